#!/usr/bin/env bash
# The portable build (baseline x86-64, kernels chosen at run time) against a build for this
# machine's CPU (-DIFSFX_NATIVE=ON, -march=native), in one run: chaos_game_bench, steal_bench and
# bench/vs-flam3.sh of each, the two builds alternating round by round so that the load of a
# shared machine falls on both alike; the best of the rounds is kept. Prints per benchmark both
# figures and the portable build's speed relative to the native one (1.00 = as fast; the issue
# allows no kernel to lose more than 5%, i.e. no ratio below 0.95).
#   cmake -S . -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release -DIFSFX_NATIVE=ON
#   cmake --build build/native --target chaos_game_bench steal_bench ifsfx
#   bench/native_vs_portable.sh [PORTABLE_BUILD] [NATIVE_BUILD] [ROUNDS]
# (defaults build/release, build/native, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
portable=${1:-build/release} native=${2:-build/native} rounds=${3:-3}
for dir in "$portable" "$native"; do
  for program in bench/chaos_game_bench bench/steal_bench apps/ifsfx; do
    [ -x "$dir/$program" ] || { echo "native_vs_portable: no $dir/$program (build it first)" >&2; exit 2; }
  done
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flam3=0
command -v flam3-render >/dev/null && flam3=1

# Lines "KIND NAME VALUE UNIT": a time (ms, lower is better) or a rate (Mpts/s, higher is better).
for round in $(seq "$rounds"); do
  for kind in portable native; do
    dir=$portable
    [ "$kind" = native ] && dir=$native
    for program in chaos_game_bench steal_bench; do
      # CSV: name,iterations,real_time,cpu_time,time_unit,...
      "$dir/bench/$program" --benchmark_format=csv 2>/dev/null |
        awk -F, -v kind="$kind" '$1 ~ /^"/ { gsub(/"/, "", $1); print kind, $1, $3, $5 }' \
          >>"$work/results"
    done
    if ((flam3)); then
      bash bench/vs-flam3.sh "$dir/apps/ifsfx" |
        awk -v kind="$kind" '/Mpts per CPU-second/ { print kind, "vs-flam3:" $1, $3, "Mpts/CPU-s" }' \
          >>"$work/results"
    fi
    echo "round $round: $kind done" >&2
  done
done

awk '
  { key = $2; unit[key] = $4; if (!(key in order)) { order[key] = ++n; names[n] = key }
    better = ($4 ~ /Mpts/) ? ($3 > best[$1, key]) : (!(($1, key) in best) || $3 < best[$1, key])
    if (!(($1, key) in best) || better) best[$1, key] = $3 }
  END {
    printf "%-44s %12s %12s %8s\n", "benchmark (best of the rounds)", "portable", "native",
           "speed"
    for (i = 1; i <= n; i++) {
      k = names[i]; p = best["portable", k]; q = best["native", k]
      speed = (unit[k] ~ /Mpts/) ? p / q : q / p
      printf "%-44s %9.1f %-2s %9.1f %-2s %8.3f\n", k, p, unit[k] ~ /Mpts/ ? "M" : unit[k], q,
             unit[k] ~ /Mpts/ ? "M" : unit[k], speed
    }
    print "speed: portable relative to native (> 1: the portable build is faster); times in " \
          "ms, M = Mpts per CPU-second"
  }' "$work/results"
