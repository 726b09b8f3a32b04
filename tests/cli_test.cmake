# Runs the arealight executable as a user would and checks exit codes, messages
# and that a failed run leaves its output untouched. Invoked by ctest with
# -DAREALIGHT=... -DSOURCE=<tests dir> -DWORK=<scratch dir>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(expect_exit code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR "expected exit ${code}, got ${rc} from: ${ARGN}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(LAST_ERR "${err}" PARENT_SCOPE)
  set(LAST_OUT "${out}" PARENT_SCOPE)
endfunction()

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
foreach(cmd variants eval reference generate compare bench report sweep)
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
# SPIR-V after optimization and the x86-64 lavapipe stores in its shader cache.
expect_exit(0 "${AREALIGHT}" bench --cases "${SOURCE}/../examples/cases.json" --variant dist=phong,method=point,light=polygon --variant dist=phong,method=exact,light=polygon --repeat 1 --min-cases 64)
if(NOT LAST_OUT MATCHES "method=point,light=polygon +case +[0-9]+ +[0-9.]+ +1.00 +[1-9][0-9]* +[1-9][0-9]*")
  message(FATAL_ERROR "bench printed no instruction counts for the baseline: ${LAST_OUT}")
endif()
if(NOT LAST_OUT MATCHES "method=exact,light=polygon +case +[0-9]+ +[0-9.]+ +[0-9.]+ +[1-9][0-9]* +[1-9][0-9]*")
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
