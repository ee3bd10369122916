#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages ifsfx needs to build, test and run, skipping those already there.
# Run as root (or through sudo). Safe to run again.
set -euo pipefail

packages=(
  # toolchain; dpkg-dev (dpkg-shlibdeps) and file: the Debian packages' Depends, made by cpack;
  # clang and its runtime libraries (libFuzzer, sanitizers) for tools/run-fuzz.sh
  g++ cmake ninja-build pkg-config ccache clang-format dpkg-dev file clang libclang-rt-14-dev
  # the function-length check (CTest style.function_length) reads Universal Ctags' end lines
  universal-ctags
  # libraries
  libopencv-dev libopenimageio-dev libpng-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # fractal flames (flame/): the XML reader; flam3's programs and palettes (flam3-render is the
  # reference renderer of the tests and bench, flam3-palettes.xml is read at run time)
  libpugixml-dev flam3-utils flam3-palette
  # the Python module (python/): pybind11 and Python's headers; NumPy and pytest for its tests
  pybind11-dev python3-dev python3-numpy python3-pytest
  # bench/fractaldb_vs_reference.py runs the FractalDB reference generator, which draws with PIL
  python3-pil
  # runtime tools and data: ffmpeg/ffprobe (audio remux, tests), OpenCV's sample clips and images;
  # groff-base checks the man page
  ffmpeg opencv-doc openimageio-tools groff-base
  # the window of `ifsfx cam` tested under a virtual X server: Xvfb, xdotool (keys), xwd + netpbm
  xvfb xdotool x11-apps netpbm
  # the portable binary under other CPU models (qemu-x86_64 -cpu qemu64/Haswell); objdump checks it
  qemu-user binutils
  # the frei0r plugins: frei0r.h, and the hosts they are tested in (melt; GStreamer with the
  # frei0r wrapper in -bad, Matroska in -good, FFV1 in -libav)
  frei0r-plugins-dev melt gstreamer1.0-tools gstreamer1.0-plugins-base gstreamer1.0-plugins-good
  gstreamer1.0-plugins-bad gstreamer1.0-libav
  # the OBS Studio filter (plugins/obs): libobs's headers; its tests start libobs headless on
  # xvfb-run's display (xvfb, above) with Mesa's software GL (llvmpipe: EGL and the DRI driver)
  # and open the display themselves (Xlib)
  libobs-dev libegl-mesa0 libgl1-mesa-dri libx11-dev
  # `ifsfx farm` is tested against a real single-node Slurm (tests/farm/start-local-slurm.sh)
  slurmctld slurmd slurm-client munge
  # `ifsfx studio`: its HTTP server; its tests: curl, and the page in a real headless browser,
  # Debian's chromium driven by playwright-core from npm (installed by the test setup into the
  # build tree, tests/studio/studio_node_setup.sh)
  libcpp-httplib-dev curl chromium nodejs
)
# npm: Debian's package, unless a node from elsewhere (NodeSource) brings its own npm.
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
