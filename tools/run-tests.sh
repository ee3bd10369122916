#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds, and runs the whole test suite through CTest twice: in a Release
# build, and in a build with AddressSanitizer and UndefinedBehaviorSanitizer. The V4L2 tests boot a
# kernel in a software-emulated VM (label `vm`, minutes each), and the install tests install the
# build, build against it and package it (label `install`): they run in the Release pass only.
# Last, the file readers are fuzzed for a fixed budget (tools/run-fuzz.sh: clang, libFuzzer,
# ASan+UBSan, 45 s per reader, about 5 minutes with its build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh

jobs=$(nproc)
bash tools/build.sh release
(cd build/release && ctest --output-on-failure -j"$jobs" --timeout 600)

bash tools/build.sh asan
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd build/asan && ctest --output-on-failure -j"$jobs" --timeout 1200 -LE 'vm|install|slurm')

bash tools/run-fuzz.sh
