# Runs `ifsfx` for one CHECK of the tops/steal command line and fails unless it behaves.
#   cmake -DIFSFX=path/to/ifsfx -DCHECK=name -DWORK=scratch -P this
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(photo /usr/share/doc/opencv-doc/examples/data/baboon.jpg)

# run(expected_rc expected_stderr args...): runs ifsfx; an empty expected_stderr means "none".
function(run expected_rc expected_err)
  execute_process(COMMAND ${IFSFX} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err WORKING_DIRECTORY ${WORK})
  if(NOT rc EQUAL expected_rc OR NOT err STREQUAL expected_err)
    message(FATAL_ERROR "ifsfx ${ARGN}\nexit ${rc} (want ${expected_rc})\n"
                        "stderr '${err}'\n(want '${expected_err}')\nstdout '${out}'")
  endif()
endfunction()

function(expect_file path)
  if(NOT EXISTS ${WORK}/${path})
    message(FATAL_ERROR "${path} was not written")
  endif()
endfunction()

function(expect_no_file path)
  if(EXISTS ${WORK}/${path})
    message(FATAL_ERROR "${path} was written by a failed command")
  endif()
endfunction()

if(CHECK STREQUAL "steal_save_and_apply")
  run(0 "" render barnsley-fern --mode steal --source ${photo} --size 160x120 -o fern.png
      --save-map fern.map -q)
  expect_file(fern.png)
  expect_file(fern.map)
  # 160·120 pixels of (u, v) float pairs and a coverage byte, after a 24-byte header.
  file(SIZE ${WORK}/fern.map bytes)
  if(NOT bytes EQUAL 172824)
    message(FATAL_ERROR "fern.map has ${bytes} bytes (want 172824)")
  endif()
  run(0 "" render barnsley-fern --mode steal --exact --source ${photo} --size 160x120
      -o exact.jpg --background white -q)
  expect_file(exact.jpg)
  run(0 "" apply fern.map ${photo} -o applied.tif --nearest)
  expect_file(applied.tif)

elseif(CHECK STREQUAL "tops_modes")
  run(0 "" render maple-leaf --mode tops --size 96x96 -o tops.png -q)
  run(0 "" render maple-leaf --mode tops --exact --second-symbol --size 96x96 -o tops.jpg
      --background "#336699" -q)
  expect_file(tops.png)
  expect_file(tops.jpg)

elseif(CHECK STREQUAL "colouring_count")
  run(2 "ifsfx: --colouring sierpinski-triangle: must have as many maps as barnsley-fern (got 3 for 4)\n"
      render barnsley-fern --mode steal --source ${photo} --colouring sierpinski-triangle
      --size 64x64 -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "unreadable_source")
  file(WRITE ${WORK}/broken.png "this is not a PNG")
  execute_process(COMMAND ${IFSFX} render barnsley-fern --mode steal --source broken.png
                          --size 64x64 -o out.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err WORKING_DIRECTORY ${WORK})
  if(rc EQUAL 0 OR NOT err MATCHES "^ifsfx: [^\n]*broken.png[^\n]*\n$")
    message(FATAL_ERROR "exit ${rc}, stderr '${err}' (want one line naming broken.png)")
  endif()
  run(1 "ifsfx: missing.png: no such file\n"
      render barnsley-fern --mode steal --source missing.png --size 64x64 -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "truncated_map")
  run(0 "" render square-tiling-4 --mode steal --source ${photo} --size 32x32 -o t.png
      --save-map t.map -q)
  execute_process(COMMAND head -c 100 t.map OUTPUT_FILE ${WORK}/short.map
                  WORKING_DIRECTORY ${WORK})
  run(1 "ifsfx: short.map: truncated or corrupt steal map: a 32x32 map has 9240 bytes (got 100)\n"
      apply short.map ${photo} -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "map_of_another_version")
  # A header of version 2 for a 1×1 map (CMake strings cannot hold the zero bytes: printf).
  execute_process(
    COMMAND printf "IFSFXSTM\\002\\000\\000\\000\\001\\000\\000\\000\\001\\000\\000\\000\\000\\000\\000\\000"
    OUTPUT_FILE ${WORK}/other.map)
  run(1 "ifsfx: other.map: steal map version 1 is supported (got version 2)\n"
      apply other.map ${photo} -o out.png)
  file(WRITE ${WORK}/photo.map "not a steal map")
  run(1 "ifsfx: photo.map: not an ifsfx steal map (no IFSFXSTM header)\n"
      apply photo.map ${photo} -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "option_of_another_mode")
  run(2 "ifsfx: --source: only with --mode steal (got --mode measure)\n"
      render barnsley-fern --source ${photo} -o out.png)
  run(2 "ifsfx: --source: --mode steal needs a source image\n"
      render barnsley-fern --mode steal -o out.png)
  expect_no_file(out.png)
  run(2 "ifsfx: --exact/--chaos: only with --mode tops or steal (got --mode measure)\n"
      render barnsley-fern --chaos -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "exact_by_default")
  # The steal map is the exact descent unless --chaos asks for the chaos game (issue 14 item 5).
  foreach(method "" --chaos --exact)
    execute_process(COMMAND ${IFSFX} render barnsley-fern --mode steal --source ${photo}
                            --size 96x64 -o out.png ${method}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out WORKING_DIRECTORY ${WORK})
    if(method STREQUAL "--chaos")
      set(want "steal map (chaos game)")
    else()
      set(want "steal map (exact)")
    endif()
    string(FIND "${out}" "${want}" at)
    if(NOT rc EQUAL 0 OR at EQUAL -1)
      message(FATAL_ERROR "render ${method}: exit ${rc}, stdout '${out}' (want '${want}')")
    endif()
  endforeach()

else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
