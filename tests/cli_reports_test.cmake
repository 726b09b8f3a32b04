# The commands that run variants over cases and write tables and plots (bench, report,
# sweep) and the GPU cost they carry, run as a user would: every file they promise, the
# rows and marks in them. Their bad-input paths are tests/cli_test.cmake's. Invoked by
# ctest with -DAREALIGHT=... -DSOURCE=<tests dir> -DWORK=<scratch dir>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/cli_support.cmake")
# The commands' private shader caches go under TMPDIR and must be gone when they exit.
file(MAKE_DIRECTORY "${WORK}/tmp")
set(ENV{TMPDIR} "${WORK}/tmp")

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
# baseline, a Pareto mark.
expect_exit(0 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=lorentz --out "${WORK}/report" --repeat 1 --dispatch-ms 2)
expect_files("${WORK}/report" "report" report.json report.md report.svg report_x86.svg)
file(READ "${WORK}/report/report.md" md)
expect_contains("${md}" "report.md" "method=lorentz,light=polygon,sided=one,verts=4` |" "method=lorentz,light=polygon,sided=one,verts=4,fit=paper,specular=sg` |" "method=point,light=polygon,sided=one,verts=4` |")
if(NOT md MATCHES "●")
  message(FATAL_ERROR "report.md marks no variant on the Pareto front")
endif()
file(READ "${WORK}/report/report.svg" svg)
if(NOT svg MATCHES "<svg" OR NOT svg MATCHES "Pareto front")
  message(FATAL_ERROR "report.svg is not a plot with a front")
endif()
# sweep: one row per variant and exponent.
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants dist=phong,light=polygon,verts=4,sided=one,method=point --exponent 10 --exponent 1000 --out "${WORK}/sweep" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep/sweep.md" md)
expect_contains("${md}" "sweep.md" "sided=one,verts=4` | 10 |" "sided=one,verts=4` | 1000 |")
expect_files("${WORK}/sweep" "sweep" sweep.json sweep_time.svg sweep_error.svg)
file(GLOB left "${WORK}/tmp/arealight-mesa-cache-*")
if(left)
  message(FATAL_ERROR "bench, report and sweep left their shader caches behind: ${left}")
endif()

# The GPU cost (RADV on a null device): a gpu object per row where RADV is installed,
# none and one warning where it is not.
file(READ "${WORK}/report/report.json" js)
if(EXISTS /usr/share/vulkan/icd.d/radeon_icd.x86_64.json)
  expect_contains("${js}" "report.json" "\"gpu\": {" "\"family\": \"navi21\"" "\"inverse_throughput_unrolled\":" "\"gpu_device\":")
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

# A microfacet report: an O(1)-cost exact ggx variant and its point baseline (the
# ggx one, not phong's); the second error column is ndf.
expect_exit(0 "${AREALIGHT}" report --cases "${SOURCE}/../examples/cases.json" --variants dist=ggx,light=polygon,nodes=2,precision=fp32,radial=2 --out "${WORK}/report_ggx" --repeat 1 --dispatch-ms 2)
expect_files("${WORK}/report_ggx" "microfacet report" report.json report.md report.svg report_x86.svg)
file(READ "${WORK}/report_ggx/report.md" md)
expect_contains("${md}" "microfacet report.md" "| ndf median / p95 / max / relL2 |" "`dist=ggx,method=exact,light=polygon,nodes=2,precision=fp32,radial=2` | 4 |" "`dist=ggx,method=point,light=polygon` | 4 |")
if(md MATCHES "moment median")
  message(FATAL_ERROR "microfacet report.md has a moment column:\n${md}")
endif()
file(READ "${WORK}/report_ggx/report.json" js)
expect_contains("${js}" "microfacet report.json" "\"baseline\": \"dist=ggx,method=point,light=polygon\"" "\"ndf\": {")

# sweep --axis view and --axis param on a ggx pattern: one row per variant and
# value, the axis named in the tables and plots.
set(ggx_pattern dist=ggx,light=polygon,nodes=2,precision=fp32,radial=2)
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --axis view --value 1 --value 0.1 --out "${WORK}/sweep_view" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep_view/sweep.md" md)
expect_contains("${md}" "view sweep.md" "| variant | cos θ_v | cases |" "radial=2` | 0.1 | 4 |" "`dist=ggx,method=point,light=polygon` | 1 | 4 |" "| ndf median")
file(READ "${WORK}/sweep_view/sweep_error.svg" svg)
if(NOT svg MATCHES "cos θ_v")
  message(FATAL_ERROR "view sweep_error.svg does not name its axis")
endif()
expect_exit(0 "${AREALIGHT}" sweep --cases "${SOURCE}/../examples/cases.json" --variants ${ggx_pattern} --axis param --value 0.01 --value 0.5 --out "${WORK}/sweep_alpha" --repeat 1 --dispatch-ms 2)
file(READ "${WORK}/sweep_alpha/sweep.md" md)
expect_contains("${md}" "alpha sweep.md" "| variant | α | cases |" "radial=2` | 0.01 | 4 |" "`dist=ggx,method=point,light=polygon` | 0.5 | 4 |")
file(READ "${WORK}/sweep_alpha/sweep.json" js)
if(NOT js MATCHES "\"alpha\": 0.01" OR NOT js MATCHES "\"axis\": \"param\"")
  message(FATAL_ERROR "alpha sweep.json does not carry alpha per row")
endif()
expect_files("${WORK}/sweep_alpha" "alpha sweep" sweep_time.svg sweep_error.svg)
