# arealight_prebuilt_library(TARGET VAR [PROPERTY VALUE]...): TARGET as an imported static
# library of the file that the cache variable VAR names, a library another build tree of the
# same sources made (scripts/sanitize.sh links the Release tree's CPU mirror and Catch2
# runner), with the given target properties. A missing file is a configure error naming VAR.
function(arealight_prebuilt_library target var)
  if(NOT EXISTS "${${var}}")
    message(FATAL_ERROR "${var}: no file ${${var}}")
  endif()
  add_library(${target} STATIC IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${${var}}" ${ARGN})
endfunction()
