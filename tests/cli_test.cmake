# Runs the arealight executable as a user would and checks exit codes, messages
# and that a failed run leaves its output untouched. Invoked by ctest with
# -DAREALIGHT=... -DSOURCE=<tests dir> -DWORK=<scratch dir>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/cli_support.cmake")

# A malformed case: exit 1, the message names file, case and field, and the
# existing output keeps its bytes while a new output path is never created.
file(WRITE "${WORK}/existing.json" "precious")
expect_exit(1 "${AREALIGHT}" reference --cases "${SOURCE}/data/bad_polygon.cases.json" --out "${WORK}/existing.json")
if(NOT LAST_ERR MATCHES "bad_polygon.cases.json: case 'bent-quad': field 'light.vertices")
  message(FATAL_ERROR "message does not name file, case and field: ${LAST_ERR}")
endif()
file(READ "${WORK}/existing.json" kept)
if(NOT kept STREQUAL "precious")
  message(FATAL_ERROR "output was modified on bad input: ${kept}")
endif()
expect_exit(1 "${AREALIGHT}" reference --cases "${SOURCE}/data/bad_polygon.cases.json" --out "${WORK}/new.json")
if(EXISTS "${WORK}/new.json")
  message(FATAL_ERROR "output created on bad input")
endif()

# A missing input file is bad input too.
expect_exit(1 "${AREALIGHT}" reference --cases "${WORK}/no-such-file.json" --out "${WORK}/new.json")

# Usage errors exit 2; --help on every command exits 0 and says what it does.
expect_exit(2 "${AREALIGHT}")
expect_exit(2 "${AREALIGHT}" reference --cases x.json)
expect_exit(2 "${AREALIGHT}" frobnicate)
foreach(cmd variants eval reference generate compare bench report sweep compile gpu-cost quality)
  expect_exit(0 "${AREALIGHT}" ${cmd} --help)
  if(NOT LAST_OUT MATCHES "--")
    message(FATAL_ERROR "${cmd} --help printed no options: ${LAST_OUT}")
  endif()
endforeach()

# A good run writes a complete results file with every quantity.
expect_exit(0 "${AREALIGHT}" reference --cases "${SOURCE}/../examples/cases.json" --out "${WORK}/ref.json" --threads 2)
file(READ "${WORK}/ref.json" ref)
expect_contains("${ref}" "results file" "\"format\": \"arealight-results/1\"" "\"diffuse\"" "\"specular\"" "\"moment\"" "\"ndf\"" "\"error\"")

# An unknown variant is bad input and writes nothing.
expect_exit(1 "${AREALIGHT}" eval --cases "${SOURCE}/../examples/cases.json" --variant dist=phong,method=magic,light=polygon --out "${WORK}/eval.json")
if(NOT LAST_ERR MATCHES "key 'method': unknown value 'magic'")
  message(FATAL_ERROR "unknown variant message does not name the key: ${LAST_ERR}")
endif()
if(EXISTS "${WORK}/eval.json")
  message(FATAL_ERROR "eval wrote output for an unknown variant")
endif()

# The CPU mirror runs a variant on the cases it applies to, and compare scores it.
expect_exit(0 "${AREALIGHT}" eval --cases "${SOURCE}/../examples/cases.json" --variant dist=phong,method=exact,light=polygon --backend cpu --out "${WORK}/eval.json")
expect_exit(0 "${AREALIGHT}" compare --ref "${WORK}/ref.json" --out "${WORK}/eval.json")
if(NOT LAST_OUT MATCHES "moment")
  message(FATAL_ERROR "compare printed no moment row: ${LAST_OUT}")
endif()

# A report pattern that matches nothing is bad input and writes nothing (the reports
# themselves: tests/cli_reports_test.cmake).
expect_exit(1 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants method=magic --out "${WORK}/nothing")
if(NOT LAST_ERR MATCHES "no variant matches 'method=magic'" OR EXISTS "${WORK}/nothing")
  message(FATAL_ERROR "a pattern matching nothing: ${LAST_ERR}")
endif()

# report --ref: oracle values that miss a case the variants run are bad input.
file(WRITE "${WORK}/partial.ref.json" "{\"format\": \"arealight-results/1\", \"variant\": \"oracle\", \"backend\": \"cpu\", \"results\": []}")
expect_exit(1 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=point --ref "${WORK}/partial.ref.json" --out "${WORK}/noref")
if(NOT LAST_ERR MATCHES "has no value in the --ref files" OR EXISTS "${WORK}/noref")
  message(FATAL_ERROR "report with a partial --ref: ${LAST_ERR}")
endif()

# An unknown chip family is a usage error before the driver (which would abort on it)
# sees the name.
expect_exit(2 "${AREALIGHT}" gpu-cost --variant dist=phong,method=point,light=polygon --gpu-family gfx1030)
if(NOT LAST_ERR MATCHES "gfx1030")
  message(FATAL_ERROR "an unknown --gpu-family is not named: ${LAST_ERR}")
endif()
expect_exit(2 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants method=point --gpu-family gfx1030 --out "${WORK}/nogpu")
if(EXISTS "${WORK}/nogpu")
  message(FATAL_ERROR "report with an unknown --gpu-family wrote ${WORK}/nogpu")
endif()

set(ggx_pattern dist=ggx,light=polygon,nodes=2,precision=fp32,radial=2)
# Bad sweeps are bad input (exit 1) with a message, and write nothing: an unknown
# axis, a parameter sweep over several distributions, an exponent for ggx, a
# value out of range.
expect_exit(1 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --axis sideways --out "${WORK}/nosweep")
if(NOT LAST_ERR MATCHES "--axis 'sideways': expected param or view" OR EXISTS "${WORK}/nosweep")
  message(FATAL_ERROR "sweep with a bad axis: ${LAST_ERR}")
endif()
expect_exit(1 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants light=polygon,method=point --axis param --out "${WORK}/nosweep")
if(NOT LAST_ERR MATCHES "span several distributions" OR EXISTS "${WORK}/nosweep")
  message(FATAL_ERROR "parameter sweep over several distributions: ${LAST_ERR}")
endif()
expect_exit(1 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --exponent 10 --out "${WORK}/nosweep")
if(NOT LAST_ERR MATCHES "has no exponent" OR EXISTS "${WORK}/nosweep")
  message(FATAL_ERROR "exponent sweep of ggx: ${LAST_ERR}")
endif()
expect_exit(1 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --value 2 --out "${WORK}/nosweep")
if(NOT LAST_ERR MATCHES "alpha must lie in \\[0.001, 1\\]" OR EXISTS "${WORK}/nosweep")
  message(FATAL_ERROR "alpha out of range: ${LAST_ERR}")
endif()

# --help of report and sweep says what they cover.
expect_exit(0 "${AREALIGHT}" report --help)
expect_contains("${LAST_OUT}" "report --help" "ndf" "ggx" "same distribution")
expect_exit(0 "${AREALIGHT}" sweep --help)
expect_contains("${LAST_OUT}" "sweep --help" "--axis" "alpha" "view" "ndf")

# compile: #include from -I folders, errors at the included file's line, nothing written on
# failure (a missing include, a stage-less extension), and a depfile listing the includes.
file(WRITE "${WORK}/compile/lib/included.glsl" "// a library\n\nfloat twice(float x) { return x + x; }\n")
file(WRITE "${WORK}/compile/bad/included.glsl" "// a library\n\nfloat twice(float x) { return undeclared_thing; }\n")
file(WRITE "${WORK}/compile/main.comp" "#version 450
layout(local_size_x = 1) in;
#include \"included.glsl\"
layout(std430, binding = 0) buffer B { float v[]; };
void main() { v[0] = twice(v[0]); }
")
expect_exit(0 "${AREALIGHT}" compile "${WORK}/compile/main.comp" -o "${WORK}/compile/main.spv"
  -I "${WORK}/compile/nowhere" -I "${WORK}/compile/lib" --depfile "${WORK}/compile/main.d")
file(READ "${WORK}/compile/main.spv" spv HEX LIMIT 4)
if(NOT spv STREQUAL "03022307")
  message(FATAL_ERROR "compile wrote no SPIR-V (first word ${spv})")
endif()
file(READ "${WORK}/compile/main.d" depfile)
if(NOT depfile MATCHES "main.spv: [^\n]*main.comp[^\n]*\n *[^\n]*lib/included.glsl")
  message(FATAL_ERROR "depfile does not list the source and the include: ${depfile}")
endif()
expect_exit(1 "${AREALIGHT}" compile "${WORK}/compile/main.comp" -o "${WORK}/compile/bad.spv" -I "${WORK}/compile/bad")
if(NOT LAST_ERR MATCHES "bad/included.glsl:3: [^\n]*undeclared_thing" OR EXISTS "${WORK}/compile/bad.spv")
  message(FATAL_ERROR "an error in an included file is not reported at its line: ${LAST_ERR}")
endif()
expect_exit(1 "${AREALIGHT}" compile "${WORK}/compile/main.comp" -o "${WORK}/compile/missing.spv" -I "${WORK}/compile/nowhere")
if(NOT LAST_ERR MATCHES "main.comp:3: [^\n]*not found \\(searched [^\n]*nowhere\\)[^\n]*included.glsl"
   OR EXISTS "${WORK}/compile/missing.spv")
  message(FATAL_ERROR "a missing include is not a clear error, or an output was written: ${LAST_ERR}")
endif()
file(WRITE "${WORK}/compile/main.glsl" "#version 450\nvoid main() {}\n")
expect_exit(2 "${AREALIGHT}" compile "${WORK}/compile/main.glsl" -o "${WORK}/compile/nostage.spv")
if(NOT LAST_ERR MATCHES "no shader stage" OR EXISTS "${WORK}/compile/nostage.spv")
  message(FATAL_ERROR "a stage-less extension: ${LAST_ERR}")
endif()
expect_exit(0 "${AREALIGHT}" compile "${WORK}/compile/main.glsl" --stage comp -o "${WORK}/compile/nostage.spv")
expect_exit(0 "${AREALIGHT}" compile --help)

# generate --scene (CONTRACT.md 7): a GGX-only scene's library has the one GGX function
# and no Phong one; a malformed scene exits 1 naming file, light and field, and writes
# nothing.
file(WRITE "${WORK}/scene/ggx.scene.json" [=[{"format": "arealight-scene/1",
  "lights": [{"type": "polygon", "vertices": [[0,0,2],[1,0,2],[1,1,2]], "two_sided": true}],
  "materials": [{"distribution": "ggx", "alpha": 0.3}]}]=])
expect_exit(0 "${AREALIGHT}" generate --scene "${WORK}/scene/ggx.scene.json" --library "${WORK}/scene/lib.glsl")
file(READ "${WORK}/scene/lib.glsl" lib)
if(NOT lib MATCHES "ArealightShading arealight_polygon_ggx\\(" OR lib MATCHES "arealight_polygon_phong")
  message(FATAL_ERROR "the GGX scene's library lacks arealight_polygon_ggx or has more: ${lib}")
endif()
file(WRITE "${WORK}/scene/bad.scene.json" [=[{"format": "arealight-scene/1",
  "lights": [{"type": "polygon", "vertices": [[0,0,2],[1,0,2]]}],
  "materials": [{"distribution": "ggx", "alpha": 0.3}]}]=])
expect_exit(1 "${AREALIGHT}" generate --scene "${WORK}/scene/bad.scene.json" --library "${WORK}/scene/bad.glsl")
if(NOT LAST_ERR MATCHES "bad.scene.json: light 0: field 'vertices'" OR EXISTS "${WORK}/scene/bad.glsl")
  message(FATAL_ERROR "a malformed scene: ${LAST_ERR}")
endif()
