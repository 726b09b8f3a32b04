#!/usr/bin/env bash
# Builds the libFuzzer targets of the readers (fuzz/, clang) into build-fuzz/ and runs each
# for FUZZ_SECONDS (default 60) from the seed corpus. Fails on any crash, leak, timeout or
# sanitizer report; the input that caused it is left in build-fuzz/findings/.
#   FUZZ_SECONDS=600 scripts/fuzz.sh        longer runs
#   FUZZ_RUNS=1000000 scripts/fuzz.sh       a fixed number of executions per target instead
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
runs="${FUZZ_RUNS:-}"
out=build-fuzz

cmake -S fuzz -B "$out" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE= >/dev/null
cmake --build "$out" -j"$(nproc)"

# Seeds: the committed hand-made ones, the examples and test data, and the shared validation
# files when this checkout has them (a clean CI clone may not), cut into one-case inputs.
seeds="$out/seeds"
rm -rf "$seeds" "$out/findings"
mkdir -p "$seeds/cases" "$seeds/results" "$out/findings"
case_files=(examples/*.json tests/data/*.json)
result_files=()
for f in ../shared/validation/*.cases.json; do [ -e "$f" ] && case_files+=("$f"); done
for f in ../shared/validation/*.ref.json; do [ -e "$f" ] && result_files+=("$f"); done
"$out/split_seeds" "$seeds/cases" 64 "${case_files[@]}"
[ ${#result_files[@]} -gt 0 ] && "$out/split_seeds" "$seeds/results" 64 "${result_files[@]}"
# Scene files are small: copied whole (libFuzzer takes folders, not files, as a corpus).
mkdir -p "$seeds/scene"
n=0
for f in examples/*scene*.json examples/*/*scene*.json; do
  [ -e "$f" ] && cp "$f" "$seeds/scene/$((n++)).json"
done

# Which seed folders and dictionary each target reads.
declare -A seed_dirs=(
  [fuzz_cases]="fuzz/corpus/cases $seeds/cases"
  [fuzz_results]="fuzz/corpus/results $seeds/results"
  [fuzz_variant]="fuzz/corpus/variant"
  [fuzz_scene]="fuzz/corpus/scene $seeds/scene"
)
declare -A dicts=([fuzz_variant]=fuzz/variant.dict)

# One target: replays its committed reproducers, then fuzzes; prints one verdict line and
# returns non-zero on any finding.
fuzz_one() {
  local target=$1
  # Inputs that once failed: each must now pass.
  if compgen -G "fuzz/crashes/$target/*" >/dev/null; then
    if ! "$out/$target" fuzz/crashes/"$target"/* >"$out/$target.replay.log" 2>&1; then
      echo "fuzz: $target FAILED on an input of fuzz/crashes/$target; log: $out/$target.replay.log"
      return 1
    fi
  fi
  local work="$out/corpus/$target"   # grows across local runs; the committed seeds stay as they are
  mkdir -p "$work"
  local limit=(-max_total_time="$seconds")
  [ -n "$runs" ] && limit=(-runs="$runs")
  # shellcheck disable=SC2086  # seed_dirs holds several folders
  if ! "$out/$target" "${limit[@]}" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
      -dict="${dicts[$target]:-fuzz/json.dict}" -print_final_stats=1 \
      -artifact_prefix="$out/findings/$target-" "$work" ${seed_dirs[$target]} \
      >"$out/$target.log" 2>&1; then
    echo "fuzz: $target FAILED; its log: $out/$target.log"
    grep -E "ERROR|SUMMARY|invariant|Test unit written" "$out/$target.log" | head -n 20 || true
    return 1
  fi
  local stats cov
  stats=$(grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added)" \
    "$out/$target.log" | sed 's/stat:://' | tr -s ' ' | tr '\n' ' ')
  cov=$(grep -E "^#[0-9]+.*(DONE|pulse|NEW|REDUCE)" "$out/$target.log" | tail -n 1 |
    grep -oE "cov: [0-9]+ ft: [0-9]+" || true)
  echo "fuzz: $target ok: $stats $cov"
}

# As many targets at once as there are cores: each fuzzer is single-threaded.
status=0
running=0
for target in fuzz_cases fuzz_results fuzz_variant fuzz_scene; do
  [ -x "$out/$target" ] || { echo "fuzz: $target not built (see fuzz/CMakeLists.txt)"; continue; }
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
