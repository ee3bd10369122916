# SPDX-License-Identifier: Apache-2.0
# Helpers of the end-to-end CMake scripts (`cmake -DIFSFX=... -DWORK=... -DCHECK=... -P script`):
# a fresh scratch folder WORK, and checks of one ifsfx run. Included by tests/*/…_cli_test.cmake.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Runs ifsfx with ARGN in WORK; sets rc, out, err in the caller.
function(ifsfx)
  execute_process(COMMAND ${IFSFX} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE stdout
                  ERROR_VARIABLE stderr WORKING_DIRECTORY ${WORK})
  set(rc ${code} PARENT_SCOPE)
  set(out "${stdout}" PARENT_SCOPE)
  set(err "${stderr}" PARENT_SCOPE)
endfunction()

function(expect_success what)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: exit ${rc}\n${out}\n${err}")
  endif()
endfunction()

# Expects a failure with exit code `code` (or any non-zero when code is "nonzero") and one line
# on stderr starting with "ifsfx: " and containing `text`.
function(expect_failure what code text)
  if(rc EQUAL 0 OR (NOT code STREQUAL "nonzero" AND NOT rc EQUAL code))
    message(FATAL_ERROR "${what}: expected exit ${code}, got ${rc}\n${out}\n${err}")
  endif()
  if(NOT err MATCHES "^ifsfx: " OR NOT err MATCHES "${text}")
    message(FATAL_ERROR "${what}: expected an error line with '${text}', got:\n${err}")
  endif()
  string(REGEX MATCHALL "\n" lines "${err}")
  list(LENGTH lines count)
  if(count GREATER 1)
    message(FATAL_ERROR "${what}: expected one line on stderr, got:\n${err}")
  endif()
endfunction()
