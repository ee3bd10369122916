#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds ifsfx: tools/build.sh [release|asan|deb|native]  (default release) →
# build/<kind>/. deb: what the Debian packages hold (tools/build-deb.sh), installed under /usr,
# without the tests. native: -march=native, runs only on CPUs like this one (for
# bench/native_vs_portable.sh). Every other kind is portable, said explicitly: a tree configured
# before the portable default keeps IFSFX_NATIVE=ON in its CMake cache otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:-release}
case "$kind" in
  release) flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  native) flags=(-DCMAKE_BUILD_TYPE=Release -DIFSFX_NATIVE=ON) ;;
  # -O1 -g1: sanitizer builds compile faster and still give file:line stack traces.
  asan) flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1"
              -DIFSFX_SANITIZE=ON -DIFSFX_BUILD_BENCH=OFF) ;;
  deb) flags=(-DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DIFSFX_BUILD_TESTS=OFF
             -DIFSFX_BUILD_BENCH=OFF) ;;
  *) echo "build.sh: unknown build kind '$kind' (release, asan, deb or native)" >&2; exit 2 ;;
esac
[[ $kind == native ]] || flags+=(-DIFSFX_NATIVE=OFF)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# ccache compiles a file that uses a precompiled header again unless told that the header's
# macros and __TIME__ may be ignored (cmake/build_speed.cmake).
export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros}
cmake -S . -B "build/$kind" -G Ninja -DIFSFX_WERROR=ON "${flags[@]}" "${launcher[@]}" >/dev/null
cmake --build "build/$kind" -j"$(nproc)"
