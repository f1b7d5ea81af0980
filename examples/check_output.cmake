# SPDX-License-Identifier: MIT
# Runs EXE (with ARGS) and fails unless it exits 0 and its output matches every regular
# expression in EXPECTED (one per line; lines starting with '#' are comments).
execute_process(COMMAND ${EXE} ${ARGS} OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE status)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXE} exited with ${status}")
endif()
file(STRINGS ${EXPECTED} patterns)
foreach(pattern IN LISTS patterns)
  if(pattern MATCHES "^#" OR pattern STREQUAL "")
    continue()
  endif()
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "output does not match: ${pattern}")
  endif()
endforeach()
