# SPDX-License-Identifier: Apache-2.0
# The layers of docs/design.md §10, checked on every include of every library and door:
#   cmake -DSOURCE_DIR=<repo> -P tests/layers_check.cmake
# A folder may include its own headers and those of the layers below it, never one above or
# beside it. The core's detail/ headers are private to the core and to the products built right
# on it (superifs, collage, fractaldb); no other folder includes any detail/ but its own.
cmake_minimum_required(VERSION 3.25)
# Rank of each folder: a lower rank is a lower layer; equal ranks are siblings.
set(layers "ifs=0" "superifs=1" "collage=1" "fractaldb=1" "flame=1" "engine=2" "video=3" "farm=4"
           "run=5" "studio=6" "cli=7" "python=7" "plugins=7")
# Doors that sit on run/engine but never on the studio: python/ and plugins/ include no studio/.
set(forbidden "python>studio" "plugins>studio")
set(detail_friends superifs collage fractaldb flame)

foreach(entry IN LISTS layers)
  string(REPLACE "=" ";" pair ${entry})
  list(GET pair 0 name)
  list(GET pair 1 rank)
  set(rank_${name} ${rank})
  list(APPEND folders ${name})
endforeach()

set(problems "")
foreach(folder IN LISTS folders)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${folder}/*.h ${SOURCE_DIR}/${folder}/*.cpp
       ${SOURCE_DIR}/${folder}/*.inl)
  foreach(file IN LISTS files)
    file(STRINGS ${file} includes REGEX "^#include \"[a-z0-9_]+/")
    file(RELATIVE_PATH where ${SOURCE_DIR} ${file})
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z0-9_]+)/([^\"]*)\".*" "\\1;\\2" target "${line}")
      list(GET target 0 lib)
      list(GET target 1 rest)
      if(NOT DEFINED rank_${lib})
        continue()  # a test helper or a third-party folder
      endif()
      if(NOT lib STREQUAL folder)
        if(NOT rank_${lib} LESS rank_${folder})
          list(APPEND problems "${where}: includes ${lib}/${rest}, a layer above or beside ${folder}/")
        elseif("${folder}>${lib}" IN_LIST forbidden)
          list(APPEND problems "${where}: includes ${lib}/${rest}: ${folder}/ never reaches ${lib}/")
        elseif(rest MATCHES "^detail/" AND NOT (lib STREQUAL "ifs" AND folder IN_LIST detail_friends))
          list(APPEND problems "${where}: includes ${lib}/${rest}, private to ${lib}/")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "layers: includes against the dependency rule (docs/design.md §10):\n  ${text}")
endif()
message(STATUS "layers: every include points down")
