#!/usr/bin/env bash
# Regenerates every measured table under docs/ (reports and sweeps, on lavapipe,
# against the oracle) and the measured data that scene selection and the library's
# comments read (data/quality/measured.json, built into arealight). Run it after a
# change to the shader math, then rebuild. Needs ../shared/validation and a build.
set -euo pipefail
cd "$(dirname "$0")/.."
V=../shared/validation
al=build/arealight
sets=(--cases $V/typical.cases.json --cases $V/horizon.cases.json
      --cases $V/glossy.cases.json --cases $V/stress.cases.json)
$al report "${sets[@]}" --variants dist=phong,light=polygon --out docs/report
$al report "${sets[@]}" --variants dist=phong,light=polygon,verts=8,sided=any --out docs/report-phong
for d in blinn beckmann ggx; do
  $al report "${sets[@]}" --variants dist=$d,light=polygon --out docs/report-$d
done
$al report "${sets[@]}" --variants method=ltc --out docs/report-ltc
$al sweep --cases $V/typical.cases.json --variants dist=phong,light=polygon,verts=8,sided=any \
  --out docs/sweep
for axis in param view; do
  $al sweep --axis $axis --cases $V/typical.cases.json --variants dist=ggx,light=polygon \
    --out docs/sweep-ggx-$axis
done
$al quality --report docs/report-phong/report.json --report docs/report-blinn/report.json \
  --report docs/report-beckmann/report.json --report docs/report-ggx/report.json \
  --report docs/report-ltc/report.json --out data/quality/measured.json
