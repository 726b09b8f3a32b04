# Shared by the command-line test scripts: runs a command, fails unless it exits with
# `code`, and leaves its stderr and stdout in LAST_ERR and LAST_OUT.
function(expect_exit code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR "expected exit ${code}, got ${rc} from: ${ARGN}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(LAST_ERR "${err}" PARENT_SCOPE)
  set(LAST_OUT "${out}" PARENT_SCOPE)
endfunction()

# Fails unless `text` contains every string after `what` (the file or output it is, named
# in the message with the text itself).
function(expect_contains text what)
  foreach(s IN LISTS ARGN)
    string(FIND "${text}" "${s}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${what} lacks ${s}:\n${text}")
    endif()
  endforeach()
endfunction()

# Fails unless folder `dir` holds every file named after `what` (the command that should
# have written them, named in the message).
function(expect_files dir what)
  foreach(f IN LISTS ARGN)
    if(NOT EXISTS "${dir}/${f}")
      message(FATAL_ERROR "${what} did not write ${f}")
    endif()
  endforeach()
endfunction()
