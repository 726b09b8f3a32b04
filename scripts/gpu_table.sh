#!/usr/bin/env bash
# Prints docs/gpu-cost.md's "What a GPU pays" table: `arealight gpu-cost` of each variant
# named on the command line (or one per line on stdin), as a Markdown row. RADV's figures
# are kept in build/gpu-cache between runs (AREALIGHT_GPU_CACHE).
#   scripts/gpu_table.sh dist=ggx,method=ltc,light=polygon dist=ggx,method=point,light=polygon
set -euo pipefail
cd "$(dirname "$0")/.."
al=${AREALIGHT:-build/arealight}
export AREALIGHT_GPU_CACHE=${AREALIGHT_GPU_CACHE:-build/gpu-cache}
if [ $# -gt 0 ]; then variants=("$@"); else mapfile -t variants; fi
echo "| variant | instructions | VGPRs (spilled) | waves/SIMD | as written | unrolled | cost | × point |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for v in "${variants[@]}"; do
  "$al" gpu-cost --variant "$v" | python3 -c '
import json, sys
d = json.load(sys.stdin)
g = d["gpu"]
def sp(x):
    return format(x, ",").replace(",", " ")
cells = ["`%s`" % d["variant"], sp(g["instructions"]),
         "%d (%d)" % (g["vgprs"], g["spilled_vgprs"]), str(g["waves_per_simd"]),
         sp(g["inverse_throughput"]), sp(g["inverse_throughput_unrolled"]), sp(g["cost"]),
         "%.3g" % g["ratio_to_point"]]
print("| " + " | ".join(cells) + " |")'
done
