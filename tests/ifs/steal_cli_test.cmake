# SPDX-License-Identifier: Apache-2.0
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
  run(2 "ifsfx: --colouring: sierpinski-triangle must have as many maps as barnsley-fern (got 3 for 4)\n"
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

elseif(CHECK STREQUAL "truncated_source")
  # Real pictures cut in half: libjpeg would paint the rest grey, libpng would complain on stderr.
  set(data /usr/share/doc/opencv-doc/examples/data)
  foreach(picture fruits.jpg pic1.png)
    file(SIZE ${data}/${picture} bytes)
    math(EXPR half "${bytes} / 2")
    execute_process(COMMAND head -c ${half} ${data}/${picture} OUTPUT_FILE ${WORK}/cut-${picture})
  endforeach()
  run(0 "" render square-tiling-4 --mode steal --source ${photo} --size 32x32 -o t.png
      --save-map t.map -q)
  set(jpeg_error "ifsfx: cut-fruits.jpg: corrupt or truncated image (JPEG error: Premature end of JPEG file)
")
  set(png_error "ifsfx: cut-pic1.png: corrupt or truncated image (cut short: ${half} bytes, ending inside its IDAT chunk)
")
  run(1 "${jpeg_error}" render barnsley-fern --mode steal --source cut-fruits.jpg --size 64x64
      -o out.png)
  run(1 "${png_error}" render barnsley-fern --mode steal --exact --source cut-pic1.png
      --size 64x64 -o out.png)
  run(1 "${jpeg_error}" apply t.map cut-fruits.jpg -o out.png)
  run(1 "${png_error}" apply t.map cut-pic1.png -o out.png)
  run(1 "${jpeg_error}" texture paper-fig4 --mode steal --source cut-fruits.jpg --size 64x64
      -o out.png)
  expect_no_file(out.png)

elseif(CHECK STREQUAL "transparent_source")
  # A half-transparent orange (200, 100, 50, alpha 127) through the identity pair: the colour
  # stays orange (not darkened by alpha), the alpha is carried where the format has it.
  execute_process(COMMAND ffmpeg -v error -y -f lavfi -i color=c=0xC86432@0.5:s=64x48,format=rgba
                          -frames:v 1 alpha.png
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ffmpeg could not make the test picture")
  endif()
  set(identity square-tiling-4 --colouring square-tiling-4 --view 0,0,1,1 --exact --size 64x48)
  run(0 "" render ${identity} --mode steal --source alpha.png -o out.png --save-map id.map -q)
  run(0 "" render ${identity} --mode steal --source alpha.png -o out.jpg -q)
  run(0 "" apply id.map alpha.png -o applied.tif)
  # pixel(file var): the centre pixel's channels as "R G B [A]" (ffmpeg decodes the file).
  function(pixel file format var)
    execute_process(COMMAND sh -c "ffmpeg -v error -i ${file} -vf format=${format},crop=1:1:32:24 -f rawvideo - | od -An -tu1 | xargs"
                    WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE value OUTPUT_STRIP_TRAILING_WHITESPACE)
    set(${var} "${value}" PARENT_SCOPE)
  endfunction()
  pixel(alpha.png rgba source)
  pixel(out.png rgba png)
  pixel(applied.tif rgba tif)
  pixel(out.jpg rgb24 jpg)
  if(NOT source STREQUAL "200 100 50 127" OR NOT png STREQUAL source OR NOT tif STREQUAL source)
    message(FATAL_ERROR "source ${source}, PNG ${png}, TIFF ${tif} (want 200 100 50 127 each)")
  endif()
  string(REPLACE " " ";" rgb "${jpg}")
  foreach(want 200 100 50)
    list(POP_FRONT rgb got)
    math(EXPR off "${got} - ${want}")
    if(off GREATER 4 OR off LESS -4)
      message(FATAL_ERROR "JPEG ${jpg}: want about 200 100 50 (darkened by alpha?)")
    endif()
  endforeach()

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
