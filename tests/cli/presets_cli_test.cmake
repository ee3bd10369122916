# SPDX-License-Identifier: Apache-2.0
# Runs `ifsfx` for one CHECK and fails (message(FATAL_ERROR)) unless the output is the known one.
#   cmake -DIFSFX=path/to/ifsfx -DCHECK=list|unknown_name|fractint_entry -DWORK=scratch -P this
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

if(CHECK STREQUAL "list")
  execute_process(COMMAND ${IFSFX} presets RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
    message(FATAL_ERROR "ifsfx presets: exit ${rc}, stderr '${err}'")
  endif()
  string(REGEX REPLACE "\n$" "" out "${out}")
  string(REPLACE ";" "," lines "${out}")  # a ';' in a description would split the CMake list
  string(REPLACE "\n" ";" lines "${lines}")
  # Every line: NAME, maps, factor, description, the columns aligned.
  set(column "")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^([a-z0-9-]+) +([0-9]+) maps  factor ([0-9.]+) +[^ ]")
      message(FATAL_ERROR "badly formed line: '${line}'")
    endif()
    string(FIND "${line}" " maps  factor " at)
    if(column STREQUAL "")
      set(column ${at})
    elseif(NOT at EQUAL column)
      message(FATAL_ERROR "columns not aligned: '${line}'")
    endif()
  endforeach()
  foreach(wanted
      "^barnsley-fern +4 maps  factor 0.8509  Barnsley's fern"
      "\nsierpinski-triangle +3 maps  factor 0.5 "
      "\nsquare-tiling-2 +2 maps  factor 1 "
      "\nsquare-tiling-9 +9 maps  factor 0.3333 "
      "\ncoral +3 maps  factor 0.749 ")
    if(NOT out MATCHES "${wanted}")
      message(FATAL_ERROR "no line matching '${wanted}' in:\n${out}")
    endif()
  endforeach()
  if(out MATCHES "super")
    message(FATAL_ERROR "superIFS presets listed among the IFS presets:\n${out}")
  endif()

elseif(CHECK STREQUAL "unknown_name")
  execute_process(COMMAND ${IFSFX} render fren -o ${WORK}/out.png RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(expected "ifsfx: unknown preset 'fren': did you mean 'fern'? (see `ifsfx presets`)\n")
  if(NOT rc EQUAL 1 OR NOT err STREQUAL expected OR EXISTS ${WORK}/out.png)
    message(FATAL_ERROR "exit ${rc} (want 1), stderr '${err}' (want '${expected}')")
  endif()

elseif(CHECK STREQUAL "fractint_entry")
  # A Fractint entry named by FILE.ifs:NAME renders from a file that also holds a 3-D entry; the
  # 3-D entry is refused by name and line, and leaves no output.
  file(WRITE ${WORK}/mine.ifs "; two entries\nhalf { .5 0 0 .5 0 0 .5 .5 0 0 .5 1 0 .5 }\n"
             "solid (3D) { 0 0 0 0 0 0 0 0 0 0 0 0 1 }\n")
  execute_process(COMMAND ${IFSFX} render ${WORK}/mine.ifs:solid -o ${WORK}/solid.png
                          --size 64x64 -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  set(expected
      "ifsfx: ${WORK}/mine.ifs:3: entry 'solid': only 2-D IFSs are supported (got a (3D) entry)\n")
  if(NOT rc EQUAL 1 OR NOT err STREQUAL expected OR EXISTS ${WORK}/solid.png)
    message(FATAL_ERROR "3-D entry: exit ${rc} (want 1), stderr '${err}' (want '${expected}')")
  endif()
  execute_process(COMMAND ${IFSFX} render ${WORK}/mine.ifs:half -o ${WORK}/half.png
                          --size 64x64 -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/half.png)
    message(FATAL_ERROR "mine.ifs:half: exit ${rc}, stderr '${err}'")
  endif()

else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
