#!/usr/bin/env bash
# Measures every curved-light family (disk, sphere, ellipsoid) beside the polygon
# family of the same distribution and method, per public set, on lavapipe, and prints
# the tables of docs/curved-lights.md (formerly README.md's "Curved lights" section): specular relL2 (Phong: specular / moment)
# at the floor each method is judged by (exact 1e-3: p95 / max of the relative
# error instead), and the count of missing or bad values over all four sets.
# Usage: scripts/curved_tables.sh [BUILD_DIR] [METHODS...]   (default build; all methods)
set -euo pipefail
cd "$(dirname "$0")/.."
A=${1:-build}/arealight
shift || true
METHODS=${*:-point lorentz pearson ellipsoid ltc exact}
V=../shared/validation
O=out/curved
mkdir -p "$O"
: >"$O/eval.log"
"$A" variants >"$O/variants.txt"

# score VARIANT SET FLOOR -> "relL2 relL2_second p95 max p95_second max_second missing bad"
score() {
  local variant=$1 set=$2 floor=$3 f
  f="$O/$(echo "$variant" | tr ',=' '._').$set"
  "$A" eval --cases "$V/$set.cases.json" --variant "$variant" --out "$f.json" 2>>"$O/eval.log"
  ../shared/tools/score "$V/$set.ref.json" "$f.json" --present --floor "$floor" --json >"$f.score.json"
  python3 - "$f.score.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
q = s["quantities"]
def get(name, key):
    x = q.get(name)
    return x.get(key) if isinstance(x, dict) and x.get(key) is not None else float("nan")
second = "moment" if "moment" in q else "ndf"
# Missing counts only for the two quantities every variant returns (point and ltc have no
# moment or ndf).
bad = sum(int(x["bad"]) for x in q.values()) + sum(int(q[k]["missing"]) for k in ("diffuse", "specular"))
print(get("specular", "relL2"), get(second, "relL2"), get("specular", "p95"), get("specular", "max"),
      max(get(second, "p95"), get("diffuse", "p95")), max(get(second, "max"), get("diffuse", "max")), bad)
EOF
}

for m in $METHODS; do
  floor=1e-2
  [ "$m" = exact ] && floor=1e-3
  echo "### docs/curved-lights.md: method=$m (floor $floor)"
  echo "| dist | set | polygon | disk | sphere | ellipsoid |"
  echo "|---|---|---|---|---|---|"
  for d in phong blinn beckmann ggx; do
    for s in typical horizon glossy stress; do
      row="| $d | $s |"
      for l in polygon disk sphere ellipsoid; do
        v="dist=$d,method=$m,light=$l"
        if ! grep -qx "$v" "$O/variants.txt"; then row+=" – |"; continue; fi
        read -r r1 r2 p95 mx p95b mxb bad < <(score "$v" "$s" "$floor")
        if [ "$m" = exact ]; then
          cell=$(printf "%.1e / %.1e; %.1e / %.1e" "$p95" "$mx" "$p95b" "$mxb")
        elif [ "$d" = phong ] && [ "$m" != ltc ] && [ "$m" != point ]; then
          cell=$(printf "%.2g / %.2g" "$r1" "$r2")
        else
          cell=$(printf "%.2g" "$r1")
        fi
        [ "$bad" != 0 ] && cell+=" (bad $bad)"
        row+=" $cell |"
      done
      echo "$row"
    done
  done
done
