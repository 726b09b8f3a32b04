#!/usr/bin/env bash
# Sets up the machine, builds, and runs every test once: the ones scripts/plain_only_tests.txt
# lists (every variant, family or many oracle cases through one path) in the Release tree,
# every other one under ASan/UBSan (scripts/sanitize.sh); then each reader's fuzz target for
# 20 s (scripts/fuzz.sh; FUZZ_SECONDS=60 or more for a deeper run).
#   PLAIN_ALL=1 bash scripts/test.sh    the whole suite in the Release tree too
set -euo pipefail
cd "$(dirname "$0")/.."
# Seconds of each step on stderr, so that CI's log says where its time went.
#   step NAME COMMAND...
step() {
  local name=$1 t0=$SECONDS
  shift
  "$@"
  echo "test.sh: $name took $((SECONDS - t0)) s" >&2
}
# lavapipe compiles each kernel with LLVM's optimisation passes off: the tests run a kernel
# over tens of cases, so the JIT is their time (one sweep: 92 s with the passes, 39 s
# without, cold cache, the same results), and a test's lavapipe is what it validates, not
# what it times. Reports and benchmarks (scripts/main.sh, arealight bench) keep the default.
export GALLIVM_PERF="${GALLIVM_PERF:-nopt}"
# and for 4-wide (SSE) vectors instead of AVX2's 8: the JIT emits half as many lanes and
# finishes sooner (a cold ggx pearson polygon kernel: 1.7 s -> 1.1 s, blinn exact disk fp32
# 5.7 s -> 4.1 s, compile included), with bit-identical results (each lane computes alone).
export LP_NATIVE_VECTOR_WIDTH="${LP_NATIVE_VECTOR_WIDTH:-128}"
# The CPU mirror (every variant's math as C++, four shards) unoptimised, for both trees (the
# sanitized one links the Release tree's): a shard compiles in 8.5 s at -O0, 23 s at -O1 and
# more at the default -O3, and the tests run it over tens to hundreds of cases a variant, where
# it takes milliseconds at any level (ggx exact polygon over the typical set: 0.09 s at -O0,
# 0.03 s at -O3), against about half a second of lavapipe per variant.
export MIRROR_FLAGS="${MIRROR_FLAGS:--O0}"
# The Release tree's libraries and command line at -O1, the numeric ones (the oracle, the
# fitter, the renderer) at -O2: the tests spend their time in lavapipe, glslang and the
# oracle, and -O3 doubled some files' compile time (runtime/report.cpp 28.8 s -> 15.4 s at -O1).
export RELEASE_FLAGS="${RELEASE_FLAGS:--O1 -DNDEBUG}"
export NUMERIC_FLAGS="${NUMERIC_FLAGS:--O2}"
# One folder of compiled kernels for every test process of this run, both trees
# (include/arealight/spirv_cache.hpp): ctest starts a process per test case, and most of
# them compile variants an earlier one compiled (the HLSL-against-GLSL test: 147 s -> 101 s
# after the all-variant runs). Emptied here, so that its entries are this build's.
export AREALIGHT_SPIRV_CACHE="$PWD/build/spirv-cache"
rm -rf "$AREALIGHT_SPIRV_CACHE"
# The suite's own files at -O0 in the Release tree: its tests (the plain-only list) spend their
# time in the libraries, glslang and lavapipe; 24 files took 78 CPU-seconds at -O3, about half
# that at -O0 (test_library.cpp 10.4 -> 6.0 s).
export TEST_FLAGS="${TEST_FLAGS:--O0}"
step setup bash scripts/setup.sh
# The Release tree builds what its tests and the sanitized tree need (the command line, the
# suite, the CPU mirror); the other test executables are built and run under ASan only.
if [ "${PLAIN_ALL:-0}" = 1 ]; then
  step build bash scripts/build.sh
else
  step build bash scripts/build.sh arealight arealight_tests
fi
mapfile -t patterns < <(grep -v '^#' scripts/plain_only_tests.txt | grep -v '^$')
plain_only=$(IFS='|'; echo "${patterns[*]}")
# Each line must still name a test: a renamed test would otherwise leave the list silently
# and run under ASan at several times its plain cost (the LTC Fresnel test did, 25 s).
for pattern in "${patterns[@]}"; do
  if ctest --test-dir build -N -R "$pattern" | grep -q '^Total Tests: 0$'; then
    echo "test.sh: scripts/plain_only_tests.txt: '$pattern' matches no test" >&2
    exit 1
  fi
done
if [ "${PLAIN_ALL:-0}" = 1 ]; then plain_args=(); else plain_args=(-R "$plain_only"); fi
# The two all-variant runs first and alone: they compile every listed variant on lavapipe,
# whose shader cache the other tests (the HLSL-against-GLSL kernels: 218 s with a cold cache,
# 118 s with a warm one) and the sanitized run then read.
all_variants='^every listed variant compiles, validates and runs on lavapipe'
step "plain ctest (every variant)" ctest --test-dir build --output-on-failure -j"$(nproc)" -R "$all_variants"
step "plain ctest" ctest --test-dir build --output-on-failure -j"$(nproc)" "${plain_args[@]}" -E "$all_variants"
step sanitize bash scripts/sanitize.sh
FUZZ_SECONDS="${FUZZ_SECONDS:-20}" step fuzz bash scripts/fuzz.sh
