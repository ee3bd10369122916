# SPDX-License-Identifier: Apache-2.0
# What keeps the build quick (CI builds the project twice and more on two cores). Measured on
# tests/ifs/chaos_game_test.cpp, a typical test file: 5.7 s of CPU as it was, 4.2 s with the
# precompiled headers below, 2.3 s with them and the test code at -O1.
#
# Precompiled headers: most of the compile time went into parsing the same third-party headers
# again in every translation unit: OpenCV's core and imgproc, {fmt} and the standard library in
# nearly all of them, GoogleTest in every test, cpp-httplib in the studio's, pybind11 in the
# module's. Not CLI11: its cost is not the parsing but the validators it defines at namespace
# scope, compiled again in every file that includes it (a precompiled CLI11 made a 1 s file of
# the command line's take 10 s). Each target that takes the project's options
# (ifsfx_options) precompiles the ones it uses once, and its sources include that first. Off with
# -DIFSFX_PCH=OFF: the fuzz build (clang refuses a header precompiled for other flags), and any
# build that wants to check that each file includes what it uses.
#
# Test code at -O1 in the optimised builds: the tests check the libraries, which keep their -O3;
# the test files themselves need no more than -O1, at less than half the compile time. Floating
# point is the same at every level (SSE2, -ffp-contract=off), so no answer changes.
set(ifsfx_pch_default ON)
if(IFSFX_FUZZ)
  set(ifsfx_pch_default OFF)
endif()
option(IFSFX_PCH
       "Precompile the third-party headers every target parses (OpenCV, fmt, GoogleTest, cpp-httplib, pybind11)"
       ${ifsfx_pch_default})

# The targets defined in DIR and below it.
function(ifsfx_targets_below dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    ifsfx_targets_below(${sub} below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# Whether TARGET reaches OpenCV through what it links, directly or through the project's
# libraries (some targets, the kernels' checks, are built without it on purpose).
function(ifsfx_reaches_opencv target out)
  set(todo ${target})
  set(seen "")
  while(todo)
    list(POP_FRONT todo t)
    if(t IN_LIST seen OR NOT TARGET ${t})
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(imported ${t} IMPORTED)
    if(imported)
      continue()
    endif()
    get_target_property(links ${t} LINK_LIBRARIES)
    get_target_property(interface ${t} INTERFACE_LINK_LIBRARIES)
    foreach(link IN LISTS links interface)
      string(REGEX REPLACE "^\\$<[A-Z_]+:(.*)>$" "\\1" link "${link}")
      if(link MATCHES "^opencv_|^OpenCV")
        set(${out} TRUE PARENT_SCOPE)
        return()
      endif()
      list(APPEND todo ${link})
    endforeach()
  endwhile()
  set(${out} FALSE PARENT_SCOPE)
endfunction()

# The headers TARGET should precompile, from what it links (LINKS).
function(ifsfx_pch_headers target links out)
  set(headers <algorithm> <cstdint> <functional> <map> <memory> <optional> <string> <vector>
              <fmt/format.h>)
  ifsfx_reaches_opencv(${target} opencv)
  if(opencv)
    list(APPEND headers <opencv2/core.hpp> <opencv2/imgproc.hpp>)
  endif()
  if(links MATCHES "GTest::")
    list(APPEND headers <gtest/gtest.h>)
  endif()
  if(links MATCHES "PkgConfig::HTTPLIB")
    list(APPEND headers <httplib.h>)
  endif()
  if(links MATCHES "pybind11::")
    list(APPEND headers <pybind11/pybind11.h> <pybind11/numpy.h>)
  endif()
  set(${out} ${headers} PARENT_SCOPE)
endfunction()

# A file compiled for another instruction set (a SIMD kernel's -march=) cannot use the header
# precompiled for the target: GCC would refuse it (-Winvalid-pch, an error with -Werror).
function(ifsfx_skip_pch_for_other_cpus target)
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    if(source MATCHES "^\\$<")
      continue()
    endif()
    get_source_file_property(options ${source} TARGET_DIRECTORY ${target} COMPILE_OPTIONS)
    if(options MATCHES "-march=")
      set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES
                                  SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
endfunction()

# Applies both to every compiled target of the project that links ifsfx_options (a target can
# refuse the headers with DISABLE_PRECOMPILE_HEADERS, as the chaos-game kernels do).
function(ifsfx_speed_up_build)
  ifsfx_targets_below(${PROJECT_SOURCE_DIR} targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(links ${target} LINK_LIBRARIES)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$"
       OR NOT links MATCHES "ifsfx_options")
      continue()
    endif()
    if(links MATCHES "GTest::")
      target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo>:-O1>)
    endif()
    # A header precompiled costs about three files' parsing: not worth it for one or two files.
    get_target_property(sources ${target} SOURCES)
    list(FILTER sources INCLUDE REGEX "\\.cpp$")
    list(LENGTH sources files)
    if(IFSFX_PCH AND files GREATER 2)
      ifsfx_pch_headers(${target} "${links}" headers)
      target_precompile_headers(${target} PRIVATE ${headers})
      ifsfx_skip_pch_for_other_cpus(${target})
    endif()
  endforeach()
endfunction()
