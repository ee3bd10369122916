#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzes the file readers for a fixed budget: builds the libFuzzer harnesses of tests/fuzz with
# clang under AddressSanitizer and UndefinedBehaviorSanitizer in build/fuzz (only the harnesses and
# the libraries they link), then runs each on a scratch copy of its seeds — tests/fuzz/corpus/
# <reader>, the shipped presets it reads, and tests/fuzz/regressions/<reader> (inputs that once
# broke it). Any crash, sanitizer report, uncaught non-ifsfx exception, broken property or hang
# (over 10 s on one input) fails the run; the input is kept in build/fuzz/run/<reader>/.
#   tools/run-fuzz.sh [SECONDS]   per harness; default 30 (IFSFX_FUZZ_SECONDS), 6 harnesses
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-${IFSFX_FUZZ_SECONDS:-30}}
readers=(preset_toml fractint superifs steal_map fractaldb_csv flame)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build/fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DIFSFX_FUZZ=ON -DIFSFX_NATIVE=OFF -DIFSFX_WERROR=ON \
  -DIFSFX_BUILD_TESTS=OFF -DIFSFX_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build build/fuzz -j"$(nproc)" --target "${readers[@]/%/_fuzz}"

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failed=()
for reader in "${readers[@]}"; do
  work=build/fuzz/run/$reader
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/crashes"
  seeds=(tests/fuzz/corpus/"$reader"/* tests/fuzz/regressions/"$reader"/*)
  case $reader in
    preset_toml) seeds+=(presets/*.toml) ;;
    fractint) seeds+=(presets/*.ifs) ;;
    superifs) seeds+=(presets/*.super.toml) ;;
  esac
  for seed in "${seeds[@]}"; do
    [[ -f $seed ]] || continue
    [[ $reader == preset_toml && $seed == *.super.toml ]] && continue
    cp "$seed" "$work/corpus/"
  done
  dict=()
  [[ -f tests/fuzz/$reader.dict ]] && dict=(-dict="tests/fuzz/$reader.dict")
  echo "run-fuzz: $reader for ${seconds} s on $(ls "$work/corpus" | wc -l) seeds"
  if build/fuzz/tests/fuzz/"$reader"_fuzz "$work/corpus" "${dict[@]}" -max_total_time="$seconds" \
       -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
       -artifact_prefix="$work/crashes/" > "$work/log.txt" 2>&1; then
    grep -E "^stat::number_of_executed_units|^stat::new_units_added" "$work/log.txt" | tr '\n' ' '
    echo
  else
    failed+=("$reader")
    tail -n 40 "$work/log.txt"
    echo "run-fuzz: $reader FAILED; the input is in $work/crashes/ — add it to" \
         "tests/fuzz/regressions/$reader/ with the fix"
  fi
done
if ((${#failed[@]})); then
  echo "run-fuzz: failures in ${failed[*]}" >&2
  exit 1
fi
echo "run-fuzz: no failures in ${#readers[@]} harnesses, ${seconds} s each"
