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
foreach(key "\"format\": \"arealight-results/1\"" "\"diffuse\"" "\"specular\"" "\"moment\"" "\"ndf\"" "\"error\"")
  string(FIND "${ref}" "${key}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "results file lacks ${key}")
  endif()
endforeach()

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

# bench times variants side by side and reports deterministic instruction counts:
# SPIR-V after optimization and the x86-64 lavapipe stores in its shader cache. The
# exact variant in fp32: its fp64 default took 47 s of this test to JIT on lavapipe.
expect_exit(0 "${AREALIGHT}" bench --cases "${SOURCE}/../examples/cases.json" --variant dist=phong,method=point,light=polygon --variant dist=phong,method=exact,light=polygon,nodes=8,precision=fp32 --repeat 1 --min-cases 64)
if(NOT LAST_OUT MATCHES "method=point,light=polygon +case +[0-9]+ +[0-9.]+ +1.00 +[1-9][0-9]* +[1-9][0-9]*")
  message(FATAL_ERROR "bench printed no instruction counts for the baseline: ${LAST_OUT}")
endif()
if(NOT LAST_OUT MATCHES "method=exact,light=polygon,nodes=8,precision=fp32 +case +[0-9]+ +[0-9.]+ +[0-9.]+ +[1-9][0-9]* +[1-9][0-9]*")
  message(FATAL_ERROR "bench printed no instruction counts for the exact variant: ${LAST_OUT}")
endif()

# report: every file it promises, a Markdown row per matching variant and its
# baseline, a Pareto mark; a pattern that matches nothing is bad input and writes
# nothing.
expect_exit(0 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=lorentz --out "${WORK}/report" --repeat 1 --dispatch-ms 2)
foreach(f report.json report.md report.svg report_x86.svg)
  if(NOT EXISTS "${WORK}/report/${f}")
    message(FATAL_ERROR "report did not write ${f}")
  endif()
endforeach()
file(READ "${WORK}/report/report.md" md)
foreach(row "method=lorentz,light=polygon,sided=one,verts=4` |" "method=lorentz,light=polygon,sided=one,verts=4,fit=paper,specular=sg` |" "method=point,light=polygon,sided=one,verts=4` |")
  string(FIND "${md}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report.md lacks the row ${row}:\n${md}")
  endif()
endforeach()
if(NOT md MATCHES "●")
  message(FATAL_ERROR "report.md marks no variant on the Pareto front")
endif()
file(READ "${WORK}/report/report.svg" svg)
if(NOT svg MATCHES "<svg" OR NOT svg MATCHES "Pareto front")
  message(FATAL_ERROR "report.svg is not a plot with a front")
endif()
expect_exit(1 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants method=magic --out "${WORK}/nothing")
if(NOT LAST_ERR MATCHES "no variant matches 'method=magic'" OR EXISTS "${WORK}/nothing")
  message(FATAL_ERROR "a pattern matching nothing: ${LAST_ERR}")
endif()

# sweep: one row per variant and exponent.
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=point --exponent 10 --exponent 1000 --out "${WORK}/sweep" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep/sweep.md" md)
foreach(row "sided=one,verts=4` | 10 |" "sided=one,verts=4` | 1000 |")
  string(FIND "${md}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sweep.md lacks the row ${row}:\n${md}")
  endif()
endforeach()
foreach(f sweep.json sweep_time.svg sweep_error.svg)
  if(NOT EXISTS "${WORK}/sweep/${f}")
    message(FATAL_ERROR "sweep did not write ${f}")
  endif()
endforeach()

# report --ref: oracle values that miss a case the variants run are bad input.
file(WRITE "${WORK}/partial.ref.json" "{\"format\": \"arealight-results/1\", \"variant\": \"oracle\", \"backend\": \"cpu\", \"results\": []}")
expect_exit(1 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=point --ref "${WORK}/partial.ref.json" --out "${WORK}/noref")
if(NOT LAST_ERR MATCHES "has no value in the --ref files" OR EXISTS "${WORK}/noref")
  message(FATAL_ERROR "report with a partial --ref: ${LAST_ERR}")
endif()

# The GPU cost (RADV on a null device): a gpu object per row where RADV is installed,
# none and one warning where it is not; an unknown chip family is a usage error before
# the driver (which would abort on it) sees the name.
file(READ "${WORK}/report/report.json" js)
if(EXISTS /usr/share/vulkan/icd.d/radeon_icd.x86_64.json)
  foreach(key "\"gpu\": {" "\"family\": \"navi21\"" "\"inverse_throughput_unrolled\":" "\"gpu_device\":")
    string(FIND "${js}" "${key}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "report.json lacks ${key}")
    endif()
  endforeach()
  if(NOT EXISTS "${WORK}/report/report_time.svg")
    message(FATAL_ERROR "report with a GPU cost did not write report_time.svg")
  endif()
  expect_exit(0 "${AREALIGHT}" gpu-cost --variant dist=phong,method=point,light=polygon --gpu-family vega10)
  if(NOT LAST_OUT MATCHES "\"family\":\"vega10\"" OR NOT LAST_OUT MATCHES "\"ratio_to_point\":1.0")
    message(FATAL_ERROR "gpu-cost of a point light on vega10: ${LAST_OUT}")
  endif()
else()
  string(FIND "${js}" "\"gpu\": {" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "report without RADV has a gpu object")
  endif()
  expect_exit(3 "${AREALIGHT}" gpu-cost --variant dist=phong,method=point,light=polygon)
  if(NOT LAST_ERR MATCHES "gpu cost left out")
    message(FATAL_ERROR "gpu-cost without RADV does not say why: ${LAST_ERR}")
  endif()
endif()
expect_exit(2 "${AREALIGHT}" gpu-cost --variant dist=phong,method=point,light=polygon --gpu-family gfx1030)
if(NOT LAST_ERR MATCHES "gfx1030")
  message(FATAL_ERROR "an unknown --gpu-family is not named: ${LAST_ERR}")
endif()
expect_exit(2 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants method=point --gpu-family gfx1030 --out "${WORK}/nogpu")
if(EXISTS "${WORK}/nogpu")
  message(FATAL_ERROR "report with an unknown --gpu-family wrote ${WORK}/nogpu")
endif()

# A microfacet report: an O(1)-cost exact ggx variant and its point baseline (the
# ggx one, not phong's); the second error column is ndf.
expect_exit(0 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=ggx,light=polygon,nodes=2,precision=fp32,radial=2 --out "${WORK}/report_ggx" --repeat 1 --dispatch-ms 2)
foreach(f report.json report.md report.svg report_x86.svg)
  if(NOT EXISTS "${WORK}/report_ggx/${f}")
    message(FATAL_ERROR "microfacet report did not write ${f}")
  endif()
endforeach()
file(READ "${WORK}/report_ggx/report.md" md)
foreach(row "| ndf median / p95 / max / relL2 |" "`dist=ggx,method=exact,light=polygon,nodes=2,precision=fp32,radial=2` | 4 |" "`dist=ggx,method=point,light=polygon` | 4 |")
  string(FIND "${md}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "microfacet report.md lacks ${row}:\n${md}")
  endif()
endforeach()
if(md MATCHES "moment median")
  message(FATAL_ERROR "microfacet report.md has a moment column:\n${md}")
endif()
file(READ "${WORK}/report_ggx/report.json" js)
foreach(key "\"baseline\": \"dist=ggx,method=point,light=polygon\"" "\"ndf\": {")
  string(FIND "${js}" "${key}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "microfacet report.json lacks ${key}")
  endif()
endforeach()

# sweep --axis view and --axis param on a ggx pattern: one row per variant and
# value, the axis named in the tables and plots.
set(ggx_pattern dist=ggx,light=polygon,nodes=2,precision=fp32,radial=2)
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --axis view --value 1 --value 0.1 --out "${WORK}/sweep_view" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep_view/sweep.md" md)
foreach(row "| variant | cos θ_v | cases |" "radial=2` | 0.1 | 4 |" "`dist=ggx,method=point,light=polygon` | 1 | 4 |" "| ndf median")
  string(FIND "${md}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "view sweep.md lacks ${row}:\n${md}")
  endif()
endforeach()
file(READ "${WORK}/sweep_view/sweep_error.svg" svg)
if(NOT svg MATCHES "cos θ_v")
  message(FATAL_ERROR "view sweep_error.svg does not name its axis")
endif()
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --axis param --value 0.01 --value 0.5 --out "${WORK}/sweep_alpha" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep_alpha/sweep.md" md)
foreach(row "| variant | α | cases |" "radial=2` | 0.01 | 4 |" "`dist=ggx,method=point,light=polygon` | 0.5 | 4 |")
  string(FIND "${md}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "alpha sweep.md lacks ${row}:\n${md}")
  endif()
endforeach()
file(READ "${WORK}/sweep_alpha/sweep.json" js)
if(NOT js MATCHES "\"alpha\": 0.01" OR NOT js MATCHES "\"axis\": \"param\"")
  message(FATAL_ERROR "alpha sweep.json does not carry alpha per row")
endif()
foreach(f sweep_time.svg sweep_error.svg)
  if(NOT EXISTS "${WORK}/sweep_alpha/${f}")
    message(FATAL_ERROR "alpha sweep did not write ${f}")
  endif()
endforeach()

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
foreach(word "ndf" "ggx" "same distribution")
  string(FIND "${LAST_OUT}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report --help does not mention ${word}: ${LAST_OUT}")
  endif()
endforeach()
expect_exit(0 "${AREALIGHT}" sweep --help)
foreach(word "--axis" "alpha" "view" "ndf")
  string(FIND "${LAST_OUT}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sweep --help does not mention ${word}: ${LAST_OUT}")
  endif()
endforeach()

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
