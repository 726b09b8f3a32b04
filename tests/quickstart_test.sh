#!/usr/bin/env bash
# README.md's Quick start, run verbatim (ctest label `docs`): the shell block between the
# quickstart markers runs in a scratch folder with the built arealight first on PATH; then its
# image is held to relative L2 <= 2e-2 (luminance) against the oracle's render of the same
# scene at the same size (arealight render --reference), as `arealight render --compare`
# measures it.
#   tests/quickstart_test.sh AREALIGHT_BINARY SOURCE_DIR
set -euo pipefail
arealight=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source_dir=$(cd "$2" && pwd)
readme=$source_dir/README.md
bound=2e-2

fail() { echo "quickstart_test: FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/arealight_quickstart.XXXXXX")
trap 'rm -rf "$work"' EXIT
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}

# The block: the lines between the markers, without the fence lines.
awk '/<!-- quickstart:begin/ { on = 1; next } /<!-- quickstart:end/ { on = 0 } on' "$readme" \
  | sed -e '/^```/d' >"$work/quickstart.sh"
[ -s "$work/quickstart.sh" ] || fail "no quickstart block between the markers in $readme"
grep -q 'arealight generate --scene' "$work/quickstart.sh" || fail "the block generates no library"

# Run it as written, in its own folder, with the built arealight as `arealight`.
mkdir "$work/run" "$work/bin"
ln -s "$arealight" "$work/bin/arealight"
(cd "$work/run" && PATH="$work/bin:$PATH" bash -euo pipefail "$work/quickstart.sh") \
  >"$work/run.log" 2>&1 || { cat "$work/run.log"; fail "the quick start failed"; }
cd "$work/run"
for f in scene.json arealight_scene.glsl tables/tables.json scene.png scene.pfm; do
  [ -s "$f" ] || { cat "$work/run.log"; fail "the quick start wrote no $f"; }
done
grep -q '^ArealightShading arealight_polygon_ggx(' arealight_scene.glsl \
  || fail "the library has no arealight_polygon_ggx"

# The oracle at the block's image size.
size=$(grep -o -- '--size [0-9]* [0-9]*' "$work/quickstart.sh" | head -1 | cut -d' ' -f2-)
[ -n "$size" ] || fail "the block's render has no --size W H"
# shellcheck disable=SC2086  # W H are two arguments
"$arealight" render --scene scene.json --size $size --reference --out ref.png --linear ref.pfm \
  >"$work/ref.log" 2>&1 || { cat "$work/ref.log"; fail "the oracle's render failed"; }
# The same render again, measured against the oracle; it must be the quick start's image.
# shellcheck disable=SC2086
"$arealight" render --scene scene.json --size $size --out check.png --linear check.pfm \
  --compare ref.pfm >"$work/check.log" 2>&1 || { cat "$work/check.log"; fail "the check render failed"; }
cmp -s check.pfm scene.pfm || fail "rendering the scene again gave another image than the quick start's"
line=$(grep '^error: relL2' "$work/check.log") || { cat "$work/check.log"; fail "no error line"; }
rel=$(echo "$line" | sed -e 's/^error: relL2 \([^,]*\),.*/\1/')
echo "quickstart_test: $line"
awk -v r="$rel" -v b="$bound" 'BEGIN { exit !(r + 0 <= b + 0) }' \
  || fail "the quick start's image is $rel from the oracle's (relative L2), more than $bound"
echo "quickstart_test: OK (relL2 $rel <= $bound against the oracle at $size)"
