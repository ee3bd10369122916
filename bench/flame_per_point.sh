#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Where the flame ratio stands per command and per point: for each flame (as bench/flame_vs_flam3.py
# --keep DIR leaves it, one <flame> at its size and quality), the best of ROUNDS task-clocks
# (perf stat, milliseconds, whole command) of flam3-render and of bench/flame_render at the
# flame's quality and at quality 0.01 (the fixed cost: start, rasters, density estimation,
# filter, PNG). The command ratio is flam3's over ifsfx's at the flame's quality; the point
# ratio (flam3 − its fixed cost) / (ifsfx − its fixed cost), the chaos games alone.
#   ROUNDS=5 THREADS=2 bench/flame_per_point.sh build/release/bench/flame_render A.flame B.flame
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: bench/flame_per_point.sh FLAME_RENDER FLAME..." >&2; exit 2; }
command -v perf >/dev/null || { echo "flame_per_point: perf is needed" >&2; exit 2; }
command -v flam3-render >/dev/null || { echo "flame_per_point: flam3-render is needed" >&2; exit 2; }
bin=$1
shift
rounds=${ROUNDS:-5}
threads=${THREADS:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
clock() {  # task-clock of one command, ms
  perf stat -x, -e task-clock -o "$work/stat" "$@" >/dev/null 2>&1
  awk -F, '/task-clock/ { print $1 }' "$work/stat"
}
flam3() {
  clock env seed=1 isaac_seed=1 out="$work/f.png" format=png verbose=0 nthreads="$threads" \
    transparency=0 flam3-render <"$1"
}
ifsfx() { clock "$bin" "$1" -o "$work/i.png" --threads "$threads"; }
best() {
  local b=1e9 t
  for ((r = 0; r < rounds; ++r)); do
    t=$("$@")
    b=$(awk -v a="$t" -v b="$b" 'BEGIN { print (a < b) ? a : b }')
  done
  echo "$b"
}
printf '%-36s %9s %9s %9s %9s %7s %7s\n' flame flam3_ms fixed_ms ifsfx_ms fixed_ms command point
for f in "$@"; do
  sed -E 's/ quality="[^"]*"/ quality="0.01"/' "$f" >"$work/fixed.flame"
  a=$(best flam3 "$f") b=$(best flam3 "$work/fixed.flame")
  c=$(best ifsfx "$f") d=$(best ifsfx "$work/fixed.flame")
  awk -v f="$(basename "$f")" -v a="$a" -v b="$b" -v c="$c" -v d="$d" 'BEGIN {
    printf "%-36s %9.1f %9.1f %9.1f %9.1f %7.1f %7.1f\n", f, a, b, c, d, a / c, (a - b) / (c - d) }'
done
