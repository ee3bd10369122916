# SPDX-License-Identifier: Apache-2.0
# No function over 80 lines (docs/style.md rule 13), measured as Universal Ctags measures it: from
# the line of the function's name to the line of its closing brace, both included.
#   cmake -DSOURCE_DIR=<repo> -P tests/function_length_check.cmake
# Reads every .h, .cpp and .inl of every library and door. Without Universal Ctags (Debian's
# universal-ctags; Exuberant Ctags knows no end lines) it says "function_length: skipped", which
# CTest reports as a skipped test.
cmake_minimum_required(VERSION 3.25)
set(limit 80)
set(folders ifs superifs collage fractaldb flame engine video farm run studio cli python plugins)
# For ever: the SIMD kernels (written out lane by lane, docs/style.md rule 9) and the CMA-ES loop
# (one published algorithm, Hansen's, kept in the order of its pseudocode).
set(exempt_files "_avx2\\.cpp$" "_avx512\\.cpp$")
set(exempt "ifs/detail/walk_quads.inl:walk_quads" "collage/optimise.cpp:minimise_cmaes")

find_program(CTAGS NAMES ctags-universal universal-ctags ctags)
if(CTAGS)
  execute_process(COMMAND ${CTAGS} --version OUTPUT_VARIABLE version ERROR_QUIET)
endif()
if(NOT CTAGS OR NOT version MATCHES "Universal Ctags")
  message(STATUS "function_length: skipped: Universal Ctags not found (apt-get install "
                 "universal-ctags)")
  return()
endif()

set(files "")
foreach(folder IN LISTS folders)
  file(GLOB_RECURSE found RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${folder}/*.h
       ${SOURCE_DIR}/${folder}/*.cpp ${SOURCE_DIR}/${folder}/*.inl)
  list(APPEND files ${found})
endforeach()
list(SORT files)
execute_process(
  COMMAND ${CTAGS} --map-C++=+.inl --languages=C++ --kinds-C++=f --fields=+ne -x
          "--_xformat=%{end} %{line} %N %F" ${files}
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE tags
  RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "function_length: ctags failed (${failed})")
endif()

string(REPLACE "\n" ";" tags "${tags}")
set(problems "")
set(longest 0)
foreach(tag IN LISTS tags)
  if(NOT tag MATCHES "^([0-9]+) ([0-9]+) ([^ ]+) (.+)$")
    continue()  # no end line known
  endif()
  set(end ${CMAKE_MATCH_1})
  set(line ${CMAKE_MATCH_2})
  set(name ${CMAKE_MATCH_3})
  set(file ${CMAKE_MATCH_4})
  math(EXPR length "${end} - ${line} + 1")
  if(length GREATER longest)
    set(longest ${length})
  endif()
  if(NOT length GREATER limit OR "${file}:${name}" IN_LIST exempt)
    continue()
  endif()
  set(skip OFF)
  foreach(pattern IN LISTS exempt_files)
    if(file MATCHES "${pattern}")
      set(skip ON)
    endif()
  endforeach()
  if(NOT skip)
    if(name MATCHES "^__anon")
      set(name "a lambda")
    endif()
    list(APPEND problems "${file}:${line}: ${name} is ${length} lines")
  endif()
endforeach()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "function_length: functions over ${limit} lines (split them into pieces a "
                      "reader would name):\n  ${text}")
endif()
list(LENGTH files count)
message(STATUS "function_length: no function over ${limit} lines in ${count} files")
