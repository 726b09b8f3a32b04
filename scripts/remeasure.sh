#!/usr/bin/env bash
# Regenerates every measured table under docs/ (reports and sweeps, on lavapipe,
# against the oracle) and the measured data that scene selection and the library's
# comments read (data/quality/measured.json, built into arealight). Run it after a
# change to the shader math, then rebuild. Needs ../shared/validation and a build.
set -euo pipefail
cd "$(dirname "$0")/.."
V=../shared/validation
# AREALIGHT=/path/to/a/copy lets a long run go on while build/ is rebuilt.
al=${AREALIGHT:-build/arealight}
# RADV statistics are kept per module across runs (arealight --gpu-cache).
export AREALIGHT_GPU_CACHE=${AREALIGHT_GPU_CACHE:-build/gpu-cache}
# The public sets with their independent reference values (so no report recomputes the
# oracle), the exactly degenerate views among them.
sets=()
for s in typical horizon glossy stress degenerate; do
  sets+=(--cases $V/$s.cases.json --ref $V/$s.ref.json)
done
$al report "${sets[@]}" --variants dist=phong,light=polygon --out docs/report
$al report "${sets[@]}" --variants dist=phong,light=polygon,verts=8,sided=any --out docs/report-phong
for d in blinn beckmann ggx; do
  $al report "${sets[@]}" --variants dist=$d,light=polygon --out docs/report-$d
done
$al report "${sets[@]}" --variants method=ltc,light=polygon --out docs/report-ltc
$al report "${sets[@]}" --variants method=mrp --out docs/report-mrp
for l in disk sphere ellipsoid; do
  $al report "${sets[@]}" --variants light=$l --out docs/report-$l
done
$al sweep --cases $V/typical.cases.json --variants dist=phong,light=polygon,verts=8,sided=any \
  --out docs/sweep
for axis in param view; do
  $al sweep --axis $axis --cases $V/typical.cases.json --variants dist=ggx,light=polygon \
    --out docs/sweep-ggx-$axis
done
# The spinning polygon against N and alpha (seed 000 9.2: its "brightness variation").
$al sweep --cases $V/typical.cases.json --variants dist=phong,light=disk,proxy=16 --out docs/sweep-disk
$al sweep --cases $V/typical.cases.json --variants dist=ggx,light=disk --out docs/sweep-ggx-disk
$al quality --report docs/report-phong/report.json --report docs/report-blinn/report.json \
  --report docs/report-beckmann/report.json --report docs/report-ggx/report.json \
  --report docs/report-ltc/report.json --report docs/report-mrp/report.json \
  --report docs/report-disk/report.json \
  --report docs/report-sphere/report.json --report docs/report-ellipsoid/report.json \
  --out data/quality/measured.json
# README.md's "Choosing a variant" table from the new data.
python3 scripts/choosing_table.py
