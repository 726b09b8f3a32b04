#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job on the example cases: the
# oracle, then the exact Phong polygon variant generated, compiled, validated and
# run on lavapipe and on the CPU mirror, each with its error table; then the
# error-against-cost report of every Phong polygon method (default shape); then the
# example scene rendered by the oracle, LTC, the paper's method and exact (out/render).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh arealight   # only what this job runs: the tests are scripts/test.sh's
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
  --out out/report
DOCS=out/render bash scripts/render_comparison.sh
