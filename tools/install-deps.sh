#!/usr/bin/env bash
# Installs the Debian 12 packages ifsfx needs to build, test and run, skipping those already there.
# Run as root (or through sudo). Safe to run again.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config ccache clang-format
  # libraries
  libopencv-dev libopenimageio-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # runtime tools and data: ffmpeg/ffprobe (audio remux, tests), OpenCV's sample clips and images
  ffmpeg opencv-doc openimageio-tools
  # the window of `ifsfx cam` tested under a virtual X server: Xvfb, xdotool (keys), xwd + netpbm
  xvfb xdotool x11-apps netpbm
  # the portable binary under other CPU models (qemu-x86_64 -cpu qemu64/Haswell); objdump checks it
  qemu-user binutils
)

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
