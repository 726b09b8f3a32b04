# `arealight render` run as a user would: exit codes, messages, untouched outputs, and
# the files a comparison writes. Invoked by ctest with -DAREALIGHT=... -DSOURCE=<tests
# dir> -DWORK=<scratch dir>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/cli_support.cmake")

expect_exit(0 "${AREALIGHT}" render --help)
if(NOT LAST_OUT MATCHES "--reference")
  message(FATAL_ERROR "render --help lacks --reference: ${LAST_OUT}")
endif()

# A bad scene: exit 1, the message names file, object and field, the PNG keeps its bytes.
file(READ "${SOURCE}/../examples/scene.json" scene)
string(REPLACE "\"material\": 2," "\"material\": 7," bad "${scene}")
file(WRITE "${WORK}/bad.json" "${bad}")
file(WRITE "${WORK}/image.png" "precious")
expect_exit(1 "${AREALIGHT}" render --scene "${WORK}/bad.json" --out "${WORK}/image.png" --backend cpu)
if(NOT LAST_ERR MATCHES "bad.json: object 2: field 'material': 7 is not an index into materials")
  message(FATAL_ERROR "message does not name file, object and field: ${LAST_ERR}")
endif()
file(READ "${WORK}/image.png" kept)
if(NOT kept STREQUAL "precious")
  message(FATAL_ERROR "output was modified on bad input")
endif()

# A render compared with its own linear image: zero error, and an error image.
set(small --scene "${SOURCE}/../examples/scene.json" --size 24 18 --backend cpu)
expect_exit(0 "${AREALIGHT}" render ${small} --out "${WORK}/a.png" --linear "${WORK}/a.pfm")
expect_exit(0 "${AREALIGHT}" render ${small} --out "${WORK}/b.png" --compare "${WORK}/a.pfm")
if(NOT LAST_OUT MATCHES "error: relL2 0.000e\\+00" OR NOT EXISTS "${WORK}/b_diff.png")
  message(FATAL_ERROR "self-comparison: ${LAST_OUT}")
endif()
# A reference of another size is bad input, and nothing is written.
expect_exit(1 "${AREALIGHT}" render --scene "${SOURCE}/../examples/scene.json" --size 12 9
            --backend cpu --out "${WORK}/c.png" --compare "${WORK}/a.pfm")
if(EXISTS "${WORK}/c.png" OR NOT LAST_ERR MATCHES "a.pfm: is 24x18, the rendering \\(--size\\) 12x9")
  message(FATAL_ERROR "size mismatch: ${LAST_ERR}")
endif()
