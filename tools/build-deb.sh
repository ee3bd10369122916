#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds ifsfx for /usr (Release, tools/build.sh deb) and packs it with
# CPack into build/deb/:
#   ifsfx_VERSION_ARCH.deb      the command, its man page, bash completion and the presets
#   ifsfx-dev_VERSION_ARCH.deb  headers, static libraries, CMake package and pkg-config file
#   python3-ifsfx_VERSION_ARCH.deb  the Python module (when pybind11-dev is installed; docs/python.md)
#   obs-ifsfx_VERSION_ARCH.deb  the OBS Studio filter (when libobs-dev is installed; docs/obs.md)
# Then, as root:  apt install ./build/deb/ifsfx_*.deb   (and ./build/deb/ifsfx-dev_*.deb)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh deb
rm -f build/deb/*.deb
(cd build/deb && cpack -G DEB >/dev/null)
ls build/deb/*.deb
