#!/usr/bin/env bash
# The example consumer against a fresh install prefix, as a user would build it (ctest label
# `consumer`): install, configure and build examples/consumer (which generates its library and
# SPIR-V at build time), render, then check that the build regenerates exactly what changed.
#   tests/consumer_test.sh BUILD_DIR SOURCE_DIR [GENERATOR]
set -euo pipefail
build=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
generator=${3:-Ninja}

work=$(mktemp -d "${TMPDIR:-/tmp}/arealight_consumer.XXXXXX")
trap 'rm -rf "$work"' EXIT
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}

fail() { echo "consumer_test: FAIL: $*" >&2; exit 1; }
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f s", b - a }'; }
stamp() { stat -c %y "$1"; }
# Builds the consumer; the log is kept for the checks that follow.
rebuild() {
  cmake --build "$work/build" -j2 >"$work/$1.log" 2>&1 || { cat "$work/$1.log"; fail "build '$1' failed"; }
}
ran() { grep -q "arealight: $1" "$work/$2.log"; }

t=$(now)
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
[ -x "$work/prefix/bin/arealight" ] || fail "no bin/arealight in the prefix"
for f in arealightConfig.cmake arealightConfigVersion.cmake arealight_add_shaders.cmake; do
  [ -f "$work/prefix/lib/cmake/arealight/$f" ] || fail "no lib/cmake/arealight/$f in the prefix"
done
echo "consumer_test: install $(since "$t")"

# A copy, so that touching its scene leaves the source tree alone.
cp -r "$source_dir/examples/consumer" "$work/consumer"
t=$(now)
cmake -S "$work/consumer" -B "$work/build" -G "$generator" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; fail "configure failed"; }
# Nothing is generated at configure time.
lib=$work/build/gen/arealight_scene.glsl
spv=$work/build/gen/render.comp.spv
[ ! -e "$lib" ] || fail "the library exists after configuring: it must be generated at build time"
rebuild first
[ -s "$lib" ] || fail "no generated library $lib"
[ -s "$spv" ] || fail "no SPIR-V $spv"
# LANG HLSL: the scene's library in HLSL and the HLSL probe shader compiled against it.
grep -q 'Texture2D<float4>' "$work/build/gen/hlsl/arealight_scene.hlsl" \
  || fail "the HLSL library declares no Texture2D table"
[ -s "$work/build/gen/hlsl/probe.comp.hlsl.spv" ] || fail "no SPIR-V of the HLSL probe shader"
# The scene asks for no method: its GGX function is the selection's (LTC), whose tables the
# consumer must upload as the manifest says.
grep -q 'variant dist=ggx,method=ltc' "$lib" || fail "the GGX function is not LTC: $(grep -m3 variant "$lib")"
grep -q '"binding_offset"' "$work/build/gen/tables/tables.json" || fail "tables.json lists no table"
echo "consumer_test: configure + build ($generator) $(since "$t")"

t=$(now)
# The program exits 4 on an image of fewer than 64 distinct colours (a broken render).
(cd "$work" && ./build/consumer consumer.png) || fail "the consumer failed (exit $?)"
[ "$(head -c 8 "$work/consumer.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] \
  || fail "consumer.png is not a PNG"
echo "consumer_test: render $(since "$t"), $(stat -c %s "$work/consumer.png") bytes"

# The scene has every light type it may (polygon, disk, sphere) and three distributions: the
# shader calls each through the library's AREALIGHT_HAS_ macros.
for f in arealight_polygon_ggx arealight_polygon_phong arealight_disk_beckmann arealight_sphere_ggx; do
  grep -q "^ArealightShading $f(" "$lib" || fail "the library has no $f"
done
# A tables folder of another library is refused by name, not a crash: an empty one here.
mkdir -p "$work/no_tables"
printf '{"format": "arealight-tables/1", "tables": []}\n' >"$work/no_tables/tables.json"
set +e
(cd "$work" && ./build/consumer wrong.png --tables "$work/no_tables") >"$work/wrong.log" 2>&1
status=$?
set -e
[ "$status" = 1 ] || fail "a wrong tables folder gave exit $status, not 1: $(cat "$work/wrong.log")"
grep -q "samples binding" "$work/wrong.log" || fail "no message naming the binding: $(cat "$work/wrong.log")"
[ ! -e "$work/wrong.png" ] || fail "a refused render wrote its PNG"

# A no-op rebuild runs nothing of arealight's.
lib_before=$(stamp "$lib"); spv_before=$(stamp "$spv")
rebuild noop
! ran generating noop || fail "a no-op rebuild regenerated the library: $(cat "$work/noop.log")"
! ran compiling noop || fail "a no-op rebuild recompiled the shader: $(cat "$work/noop.log")"
[ "$(stamp "$lib")" = "$lib_before" ] || fail "a no-op rebuild rewrote the library"

# Touching the scene regenerates the library and recompiles the shader that includes it.
sleep 1  # a newer mtime even where the file system keeps whole seconds
touch "$work/consumer/scene.json"
rebuild scene
ran generating scene || fail "touching the scene did not regenerate: $(cat "$work/scene.log")"
ran compiling scene || fail "touching the scene did not recompile the shader"
[ "$(stamp "$lib")" != "$lib_before" ] || fail "the library's mtime did not change"
[ "$(stamp "$spv")" != "$spv_before" ] || fail "the SPIR-V's mtime did not change"

# Editing the shader recompiles it and leaves the library alone.
sleep 1
lib_before=$(stamp "$lib")
echo "// edited" >>"$work/consumer/render.comp"
rebuild shader
ran compiling shader || fail "editing render.comp did not recompile it"
! ran generating shader || fail "editing render.comp regenerated the library"

# A new arealight regenerates.
sleep 1
touch "$work/prefix/bin/arealight"
rebuild tool
ran generating tool || fail "a newer arealight did not regenerate the library"
[ "$(stamp "$lib")" != "$lib_before" ] || fail "the library's mtime did not change"
echo "consumer_test: OK (no-op, scene, shader and tool rebuilds regenerate exactly what changed)"
