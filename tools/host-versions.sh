#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Prints the versions of the programs and libraries the tests run against — the hosts of the
# plugins, the cluster, the VM, the imaging libraries — with the Debian package each comes from, so
# that a red run after a Debian point release says at once what moved. Never fails.
set -uo pipefail

# row WHAT PACKAGE COMMAND...: "WHAT  VERSION  (PACKAGE VERSION)"; "not installed" where absent.
row() {
  local what=$1 package=$2
  shift 2
  local version deb
  version=$("$@" 2>/dev/null | head -n 1)
  version=${version%% Copyright*}
  deb=$(dpkg-query -W -f='${Version}' "$package" 2>/dev/null)
  printf '  %-12s %-48s (%s %s)\n' "$what" "${version:-not installed}" "$package" "${deb:-not installed}"
}

echo "host-versions: what the tests run against"
row FFmpeg ffmpeg ffmpeg -hide_banner -version
row melt melt melt --version
row GStreamer gstreamer1.0-tools gst-launch-1.0 --version
row frei0r.h frei0r-plugins-dev pkg-config --modversion frei0r
row Slurm slurmd slurmd -V
row QEMU qemu-system-x86 qemu-system-x86_64 --version
row qemu-user qemu-user qemu-x86_64 --version
row OpenCV libopencv-dev pkg-config --modversion opencv4
row OpenImageIO libopenimageio-dev pkg-config --modversion OpenImageIO
row libavcodec libavcodec-dev pkg-config --modversion libavcodec
row GCC g++ g++ -dumpfullversion
row clang clang clang --version
row CMake cmake cmake --version
row kernel linux-libc-dev uname -r
exit 0
