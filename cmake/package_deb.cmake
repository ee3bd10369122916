# SPDX-License-Identifier: Apache-2.0
# The Debian packages, made by `cpack -G DEB` in a build tree (tools/build-deb.sh):
#   ifsfx_<version>_amd64.deb      component runtime: the command, man page, completion, presets
#   ifsfx-dev_<version>_amd64.deb  component dev: headers, static libraries, CMake package, ifsfx.pc
#   python3-ifsfx_<version>_amd64.deb  component python: the Python module and its stubs in
#                                  /usr/lib/python3/dist-packages (when built: IFSFX_BUILD_PYTHON)
#   obs-ifsfx_<version>_amd64.deb  component obs: the OBS Studio filter in OBS's plugin folders
#                                  (when built: libobs-dev installed)
# Two packages, as Debian splits a tool from its development files: whoever wants the command
# gets only the shared libraries it runs on (OpenCV, OpenImageIO, FFmpeg's, ...), its Depends read
# from the binary by dpkg-shlibdeps; whoever builds against the libraries gets the -dev packages
# their headers and link lines need. Those are written here: static archives have no NEEDED
# entries for dpkg-shlibdeps to read. The list follows find_dependency() in ifsfxConfig.cmake.in
# and Requires in ifsfx.pc.in. What goes into which package: cmake/install.cmake.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ifsfx)
set(CPACK_PACKAGE_VENDOR "ifsfx developers")
set(CPACK_PACKAGE_CONTACT "ifsfx developers <dev@ifsfx.local>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # the command; static archives are never stripped by install()
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # NAME_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME ifsfx)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# A description's first line is the package's summary (CPACK_PACKAGE_DESCRIPTION_SUMMARY is
# left unset: CPack would put it before both).
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
    "turn images and video into fractals
ifsfx renders iterated function systems (IFS) by the chaos game, their
invariant measures and fractal tops, colours them by colour stealing (each
pixel takes its colour from an image through a second IFS), and builds
V-variable superfractals: stills, texture sequences, a movie filter and a
live webcam filter (V4L2, virtual webcams through v4l2loopback).")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME ifsfx-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "libopencv-dev, libopenimageio-dev, libfmt-dev, libtomlplusplus-dev, zlib1g-dev, libavformat-dev, \
libavcodec-dev, libswscale-dev, libavutil-dev, pkg-config")
set(CPACK_COMPONENT_DEV_DESCRIPTION
    "static libraries and headers of ifsfx (fractals from images and video)
The C++20 libraries of ifsfx: IFS and colour stealing (ifs), V-variable
superfractals (superifs), collage fitting (collage) and the video filter
(video), as static libraries with their headers, a CMake package
(find_package(ifsfx CONFIG): targets ifsfx::ifs, ...) and a pkg-config
file (ifsfx).")

# The Python module, as Debian packages one: python3-NAME, section python, for the interpreter
# version it was built against (its file name carries the ABI tag), NumPy at run time.
if(TARGET ifsfx_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-ifsfx)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS ON)
  set(python_next ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR})
  math(EXPR python_next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= ${python_next}~), python3 (<< ${Python3_VERSION_MAJOR}.${python_next_minor}), \
python3-numpy")
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION
      "turn images and video into fractals (Python 3 module)
The ifsfx engine on NumPy arrays: IFS rendering by the chaos game (attractor,
invariant measure), fractal tops, colour stealing through steal maps and
V-variable superfractal textures, with the results of the ifsfx command.
Long computations release the GIL and stop on Ctrl-C.")
endif()

# The OBS Studio filter, named as Debian names OBS plugins (obs-shaderfilter, obs-move-transition):
# its Depends (libobs0, ...) from the module by dpkg-shlibdeps, OBS itself recommended.
if(TARGET ifsfx-obs)
  list(APPEND CPACK_COMPONENTS_ALL obs)
  set(CPACK_DEBIAN_OBS_PACKAGE_NAME obs-ifsfx)
  set(CPACK_DEBIAN_OBS_PACKAGE_SECTION video)
  set(CPACK_DEBIAN_OBS_PACKAGE_SHLIBDEPS ON)
  set(CPACK_DEBIAN_OBS_PACKAGE_RECOMMENDS obs-studio)
  set(CPACK_COMPONENT_OBS_DESCRIPTION
      "fractal kaleidoscope filter for OBS Studio (ifsfx)
The fractal filter of ifsfx inside OBS Studio: add the filter named
ifsfx fractal to a webcam or media source and every frame is coloured
through the steal map of an IFS (colour stealing), optionally drifting or
stepping through a V-variable superfractal, computed off OBS's video thread.")
endif()

include(CPack)
