#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job on the example cases: the
# oracle, then the exact Phong polygon variant generated, compiled, validated and
# run on lavapipe and on the CPU mirror, each with its error table; then the
# error-against-cost report of every Phong polygon method (default shape); then the
# example scene rendered by the oracle, LTC, the paper's method and exact (out/render).
set -euo pipefail
cd "$(dirname "$0")/.."
# The packages this job needs (not the test suite's, the sanitizers' or the fuzzers').
bash scripts/setup.sh main
# Only what this job runs (the tests are scripts/test.sh's, which configures them back in),
# unoptimised (BUILD_TYPE=None): its time is lavapipe's, RADV's and glslang's, and our code
# runs on a few cases (the oracle on 12 in 0.1 s at -O3; the oracle's image of the example
# scene is data/render's). scripts/test.sh and the README's install build Release again.
BUILD_TYPE=None BUILD_TESTS=OFF bash scripts/build.sh arealight
# The report's GPU cost: RADV's statistics of each module, kept by chip, Mesa version and
# a hash of the module (data/gpu-cache, written by this job on the machine that
# committed it); a module this machine builds differently is compiled here.
mkdir -p out/gpu-cache
cp -n data/gpu-cache/*.json out/gpu-cache/ 2>/dev/null || true
seeded=$(ls out/gpu-cache | wc -l)
mkdir -p out
al=build/arealight
variant="dist=phong,method=exact,light=polygon"
$al reference --cases examples/cases.json --out out/examples.ref.json --table
$al generate --variant "$variant" --glsl out/phong_exact_polygon.comp --spv out/phong_exact_polygon.spv
for backend in vulkan cpu; do
  $al eval --cases examples/cases.json --variant "$variant" --backend $backend \
    --out "out/examples.$backend.json"
  $al compare --ref out/examples.ref.json --out "out/examples.$backend.json"
done
$al report --cases examples/cases.json --variants dist=phong,light=polygon,verts=8,sided=any \
  --gpu-cache out/gpu-cache --out out/report
DOCS=out/render bash scripts/render_comparison.sh
# A module not in data/gpu-cache cost this job seconds to a minute of ACO each (a stale cache
# took the report from 62 to 143 s): say how to refresh it.
computed=$(( $(ls out/gpu-cache | wc -l) - seeded ))
if [ "$computed" -gt 0 ]; then
  echo "main: $computed GPU-cost entries were not in data/gpu-cache and were computed here; to"
  echo "main: refresh it: rm -r out/gpu-cache data/gpu-cache/*.json, run this job again, then"
  echo "main: cp out/gpu-cache/*.json data/gpu-cache/"
fi
echo "main: the report is out/report/report.md (report.svg: error against GPU cost), the"
echo "main: renders and their error images out/render/ (render.md), the kernels out/*.comp"

