# arealight_add_shaders(<target>
#   OUTPUT <file.glsl>                      # the shading library (CONTRACT.md section 5)
#   VARIANTS <name>... | SCENE <scene.json>
#   [LANG GLSL|HLSL]                        # the library's language (GLSL by default)
#   [SPIRV <shader source>...]              # compiled to <name>.spv beside OUTPUT
#   [TABLES <dir>])                         # `arealight generate --tables <dir>`
#
# Everything runs at build time (custom commands), never at configure time. The library is
# regenerated when arealight::arealight, the scene file or the arguments (variant list, scene
# path, tables folder) change: the arguments are kept in a file rewritten only when they
# change, which both Ninja and Makefiles see as an input. A SPIRV source `dir/x.comp` becomes
# `x.comp.spv` in OUTPUT's folder, compiled by `arealight compile` with that folder on the
# include path; it depends on the source, the library, and (depfile) every file it includes.
# An HLSL source is named for its stage, `x.frag.hlsl`, and starts at main().
#
# If <target> exists it is made to depend on the outputs; otherwise it is created as a custom
# target (in ALL) that builds them. Relative OUTPUT and TABLES are in the current binary
# folder, relative SCENE and SPIRV sources in the current source folder.
include_guard(GLOBAL)

cmake_policy(PUSH)
# DEPFILE paths relative to the binary folder and rewritten for Ninja (CMake 3.20).
if(POLICY CMP0116)
  cmake_policy(SET CMP0116 NEW)
endif()

function(arealight_add_shaders target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "OUTPUT;SCENE;TABLES;LANG" "VARIANTS;SPIRV")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "arealight_add_shaders(${target}): unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_OUTPUT)
    message(FATAL_ERROR "arealight_add_shaders(${target}): OUTPUT <file.glsl> is required")
  endif()
  if((arg_VARIANTS AND arg_SCENE) OR (NOT arg_VARIANTS AND NOT arg_SCENE))
    message(FATAL_ERROR "arealight_add_shaders(${target}): give either VARIANTS <name>... or SCENE <file>")
  endif()
  if(arg_LANG AND NOT arg_LANG MATCHES "^(GLSL|HLSL)$")
    message(FATAL_ERROR "arealight_add_shaders(${target}): LANG is GLSL or HLSL, not ${arg_LANG}")
  endif()
  if(NOT TARGET arealight::arealight)
    message(FATAL_ERROR "arealight_add_shaders(${target}): arealight::arealight is not defined (find_package(arealight))")
  endif()

  get_filename_component(output "${arg_OUTPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  get_filename_component(out_dir "${output}" DIRECTORY)
  set(work_dir "${CMAKE_CURRENT_BINARY_DIR}/arealight/${target}")

  set(generate_args)
  if(arg_LANG STREQUAL "HLSL")
    list(APPEND generate_args --lang hlsl)
  endif()
  set(inputs)
  if(arg_SCENE)
    get_filename_component(scene "${arg_SCENE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND generate_args --scene "${scene}")
    list(APPEND inputs "${scene}")
  else()
    foreach(variant IN LISTS arg_VARIANTS)
      list(APPEND generate_args --variant "${variant}")
    endforeach()
  endif()
  set(outputs "${output}")
  if(arg_TABLES)
    get_filename_component(tables "${arg_TABLES}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    list(APPEND generate_args --tables "${tables}")
    list(APPEND outputs "${tables}/tables.json")
  endif()

  # The arguments as a file: written only when they change, so that a changed variant list
  # regenerates under Makefiles too (which, unlike Ninja, do not track command lines).
  set(arguments_file "${work_dir}/generate.args")
  string(REPLACE ";" "\n" arguments_text "${generate_args}")
  file(CONFIGURE OUTPUT "${arguments_file}" CONTENT "${arguments_text}\n" @ONLY)

  add_custom_command(OUTPUT ${outputs}
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${out_dir}"
    COMMAND arealight::arealight generate ${generate_args} --library "${output}"
    DEPENDS "$<TARGET_FILE:arealight::arealight>" "${arguments_file}" ${inputs}
    COMMENT "arealight: generating ${output}"
    VERBATIM)

  set(spirv_outputs)
  foreach(source IN LISTS arg_SPIRV)
    get_filename_component(source "${source}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${source}" NAME)
    set(spv "${out_dir}/${name}.spv")
    if(spv IN_LIST spirv_outputs)
      message(FATAL_ERROR "arealight_add_shaders(${target}): two SPIRV sources named ${name} would both write ${spv}")
    endif()
    set(depfile_args)
    set(compile_args)
    # DEPFILE reaches Makefiles in CMake 3.20; other generators get the explicit inputs only.
    if(CMAKE_GENERATOR MATCHES "Ninja|Makefiles" AND NOT CMAKE_VERSION VERSION_LESS 3.20)
      set(depfile "${work_dir}/${name}.d")
      set(depfile_args DEPFILE "${depfile}")
      set(compile_args --depfile "${depfile}")
    endif()
    add_custom_command(OUTPUT "${spv}"
      COMMAND arealight::arealight compile "${source}" -o "${spv}" -I "${out_dir}" ${compile_args}
      DEPENDS "$<TARGET_FILE:arealight::arealight>" "${source}" "${output}"
      ${depfile_args}
      COMMENT "arealight: compiling ${spv}"
      VERBATIM)
    list(APPEND spirv_outputs "${spv}")
  endforeach()

  if(TARGET ${target})
    add_custom_target(${target}_arealight DEPENDS ${outputs} ${spirv_outputs})
    add_dependencies(${target} ${target}_arealight)
  else()
    add_custom_target(${target} ALL DEPENDS ${outputs} ${spirv_outputs})
  endif()
endfunction()

cmake_policy(POP)
