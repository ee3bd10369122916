# One end-to-end check of `ifsfx fit`, chosen by -DCHECK=...; -DIFSFX is the binary, -DWORK a
# scratch folder. Targets are made with `ifsfx render` so that no image file is needed.
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_test.cmake)

# A white filled square on black: the attractor of the four quadrant maps.
function(make_square)
  ifsfx(render square-tiling-4 --mode attractor --size 80x80 -o square.png)
  expect_success("render the square target")
endfunction()

# A black image: the attractor rendered far outside the view.
function(make_black)
  ifsfx(render square-tiling-4 --mode attractor --size 32x32 --view 10,10,11,11 -o black.png)
  expect_success("render the black target")
endfunction()

set(quick --size 64 --max-seconds 0 --max-evaluations 3000 --threads 2)

if(CHECK STREQUAL "fit_then_render")
  make_square()
  ifsfx(fit square.png --invert -n 4 -o fitted.toml ${quick} --json --preview preview.png)
  expect_success("fit")
  string(JSON holds GET "${out}" bound_holds)
  string(JSON iou GET "${out}" iou)
  string(JSON maps LENGTH "${out}" ifs maps)
  if(NOT holds OR NOT maps EQUAL 4)
    message(FATAL_ERROR "fit: bound_holds ${holds}, ${maps} maps\n${out}")
  endif()
  if(iou LESS 0.9)
    message(FATAL_ERROR "fit: IoU ${iou} < 0.9 for a filled square\n${out}")
  endif()
  if(NOT EXISTS ${WORK}/preview.png)
    message(FATAL_ERROR "fit: --preview wrote nothing")
  endif()
  ifsfx(render fitted.toml --mode attractor --size 64x64 -o rendered.png)
  expect_success("render the fitted preset")
  # Same seed, same budget, no clock: the same preset, whatever the thread count.
  ifsfx(fit square.png --invert -n 4 -o again.toml --size 64 --max-seconds 0
        --max-evaluations 3000 --threads 1)
  expect_success("fit again")
  file(READ ${WORK}/fitted.toml first)
  file(READ ${WORK}/again.toml second)
  if(NOT first STREQUAL second)
    message(FATAL_ERROR "fit is not reproducible:\n${first}\n---\n${second}")
  endif()
elseif(CHECK STREQUAL "fractint_output")
  make_square()
  ifsfx(fit square.png --invert -n 2 -o fitted.ifs ${quick})
  expect_success("fit to .ifs")
  if(NOT out MATCHES "IoU")
    message(FATAL_ERROR "fit: no text report\n${out}")
  endif()
  ifsfx(render fitted.ifs --mode attractor --size 64x64 -o rendered.png)
  expect_success("render the fitted Fractint entry")
elseif(CHECK STREQUAL "unreadable_file")
  ifsfx(fit no-such-leaf.png -o out.toml)
  expect_failure("unreadable target" nonzero "no-such-leaf.png")
  if(EXISTS ${WORK}/out.toml)
    message(FATAL_ERROR "a failed fit left a preset behind")
  endif()
elseif(CHECK STREQUAL "empty_target")
  make_black()
  ifsfx(fit black.png --invert -o out.toml)
  expect_failure("empty target" 2 "shape is empty")
elseif(CHECK STREQUAL "full_target")
  make_black()
  ifsfx(fit black.png -o out.toml)
  expect_failure("full target" 2 "whole image")
elseif(CHECK STREQUAL "bad_map_count")
  make_square()
  ifsfx(fit square.png --invert -n 0 -o out.toml)
  expect_failure("-n 0" 2 "-n: the number of maps must be in 1..32 \\(got 0\\)")
  ifsfx(fit square.png --invert -n 100000 -o out.toml)
  expect_failure("-n 100000" 2 "got 100000")
elseif(CHECK STREQUAL "bad_output_extension")
  make_square()
  ifsfx(fit square.png --invert -o out.txt)
  expect_failure("-o out.txt" nonzero "\\.toml")
elseif(CHECK STREQUAL "interrupted")
  # Ctrl-C once a 60-second fit is running (its first progress line is out): it stops within
  # seconds, exit 130, one error line after the progress line, no preset written.
  make_square()
  execute_process(
    COMMAND bash -c [=[
      "$0" fit square.png --invert -n 4 -o out.toml --max-seconds 60 --progress 2>err.txt &
      pid=$!
      for _ in $(seq 1200); do grep -q partition err.txt 2>/dev/null && break; sleep 0.05; done
      sleep 0.5
      start=$(date +%s%N)
      kill -INT $pid
      wait $pid
      status=$?
      echo $(( ($(date +%s%N) - start) / 1000000 )) > stop-ms.txt
      exit $status
    ]=] ${IFSFX}
    RESULT_VARIABLE rc WORKING_DIRECTORY ${WORK})
  file(READ ${WORK}/err.txt err)
  file(READ ${WORK}/stop-ms.txt took)
  string(STRIP "${took}" took)
  if(NOT rc EQUAL 130 OR NOT err MATCHES "\nifsfx: fit: interrupted\n$")
    message(FATAL_ERROR "SIGINT: expected exit 130 and 'ifsfx: fit: interrupted' on a line of "
                        "its own, got exit ${rc} and:\n${err}")
  endif()
  if(took GREATER 5000)
    message(FATAL_ERROR "fit took ${took} ms to stop after SIGINT")
  endif()
  if(EXISTS ${WORK}/out.toml)
    message(FATAL_ERROR "an interrupted fit left a preset behind")
  endif()
else()
  message(FATAL_ERROR "unknown check ${CHECK}")
endif()
