#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds, and runs the whole test suite through CTest twice: in a Release
# build, and in a build with AddressSanitizer and UndefinedBehaviorSanitizer. The V4L2 tests boot a
# kernel in a software-emulated VM (label `vm`, minutes each), and the install tests install the
# build, build against it and package it (label `install`): they run in the Release pass only.
# Last, the file readers are fuzzed for a fixed budget (tools/run-fuzz.sh: clang, libFuzzer,
# ASan+UBSan, 30 s per reader, about 5 minutes with its build).
#
# The passes are independent: a failure in one (a build or a test) does not stop the others, so one
# broken case never hides what the others would find. The script ends with one line per pass and
# exits non-zero if any failed, naming them. It starts by printing the versions of the programs the
# tests run against (tools/host-versions.sh), again at the end of a red run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/host-versions.sh

jobs=$(nproc)
# suite BUILD TIMEOUT CTEST-ARGS...: the build's suite, all cores. Tests that fail are run once
# more, one at a time; the suite passes only if every one of them passes there, and their names
# are kept in build/BUILD/flaky.txt for the summary (a test that fails only beside others, under
# load, is a defect to fix, named at the end of the log, but not one that fails the whole run).
suite() {
  local build=$1 timeout=$2
  shift 2
  cd "build/$build"
  rm -f flaky.txt
  ctest --output-on-failure -j"$jobs" --timeout "$timeout" "$@" && return 0
  local failures=Testing/Temporary/LastTestsFailed.log
  [[ -s $failures ]] || return 1
  cp "$failures" first-failures.txt
  echo "=== run-tests: $build: again, one at a time: $(cut -d: -f2 first-failures.txt | tr '\n' ' ')"
  ctest --output-on-failure -j1 --timeout "$timeout" --rerun-failed || return 1
  cp first-failures.txt flaky.txt
}
release_tests() { suite release 600; }
asan_tests() {
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  suite asan 1200 -LE 'vm|install|slurm'
}

# run_pass NAME COMMAND...: runs COMMAND in a subshell with errexit and records how it ended.
results=()
failed=()
run_pass() {
  local name=$1 rc start=$SECONDS
  shift
  echo "=== run-tests: $name"
  set +e
  (set -e; "$@")
  rc=$?
  set -e
  results+=("$(printf '%-14s %s (%d s)' "$name" "$( ((rc == 0)) && echo passed || echo "FAILED (exit $rc)")" $((SECONDS - start)))")
  ((rc == 0)) || failed+=("$name")
}

run_pass release-build bash tools/build.sh release
if [[ " ${failed[*]} " != *" release-build "* ]]; then
  run_pass release-tests release_tests
else
  results+=("$(printf '%-14s %s' release-tests "not run (no build)")") && failed+=(release-tests)
fi
run_pass asan-build bash tools/build.sh asan
if [[ " ${failed[*]} " != *" asan-build "* ]]; then
  run_pass asan-tests asan_tests
else
  results+=("$(printf '%-14s %s' asan-tests "not run (no build)")") && failed+=(asan-tests)
fi
run_pass fuzz bash tools/run-fuzz.sh

echo "=== run-tests: summary"
printf '  %s\n' "${results[@]}"
# The log is long and may be read from its tail only: name the tests that failed here, at the end.
for build in release asan; do
  if [[ -s build/$build/flaky.txt ]]; then
    echo "  $build-tests: failed beside the others, passed alone:"
    sed 's/^/    /' "build/$build/flaky.txt"
  elif [[ " ${failed[*]} " == *" $build-tests "* && -s build/$build/Testing/Temporary/LastTestsFailed.log ]]; then
    echo "  $build-tests failed:"
    sed 's/^/    /' "build/$build/Testing/Temporary/LastTestsFailed.log"
  fi
done
echo "passes: $((${#results[@]} - ${#failed[@]})) passed, ${#failed[@]} failed"
if ((${#failed[@]})); then
  bash tools/host-versions.sh
  echo "run-tests: FAILED: ${failed[*]}" >&2
  exit 1
fi
echo "run-tests: every pass passed"
