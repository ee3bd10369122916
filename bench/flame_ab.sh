#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Two builds of bench/flame_render on the same flames, back to back: for each flame, ROUNDS runs
# of each binary alternated (so that a change of load hits both), and the best CPU seconds
# (user + system) of the whole command of each, with the ratio. For a change to the flame
# renderer: copy the old build's flame_render aside first, e.g.
#   cp build/release/bench/flame_render /tmp/flame_render.old   # before the change
#   bench/flame_ab.sh /tmp/flame_render.old build/release/bench/flame_render A.flame B.flame
# The flames are rendered at their own size and quality: `bench/flame_vs_flam3.py --keep DIR`
# leaves each flame there as the table rendered it (DIR/NAME.flame, its size and quality).
# ARGS adds flame_render options to every run, e.g. the fixed cost after the walk at quality 1,
# or a genome at the table's size:
#   ARGS="--quality 1" bench/flame_ab.sh OLD NEW FLAME...
#   ARGS="--size 256x256" bench/flame_ab.sh OLD NEW genome.flame
# PERF=1 takes each run's task-clock from `perf stat` (a millisecond's resolution, where
# /usr/bin/time's user + system has ten: for commands of a tenth of a second).
#   ROUNDS=3 THREADS=2 bench/flame_ab.sh OLD NEW FLAME...
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: bench/flame_ab.sh OLD_flame_render NEW_flame_render FLAME..." >&2; exit 2; }
old=$1 new=$2
shift 2
rounds=${ROUNDS:-3}
threads=${THREADS:-2}
read -r -a args <<<"${ARGS:-}"
png=$(mktemp --suffix=.png)
trap 'rm -f "$png"' EXIT
cpu() {
  if [[ ${PERF:-0} == 1 ]]; then
    perf stat -x, -e task-clock "$1" "$2" -o "$png" --threads "$threads" "${args[@]}" 2>&1 \
      >/dev/null | awk -F, '/task-clock/ { print $1 / 1000 }'
  else
    /usr/bin/time -f "%U %S" "$1" "$2" -o "$png" --threads "$threads" "${args[@]}" 2>&1 \
      >/dev/null | awk 'END { print $1 + $2 }'
  fi
}
printf '%-40s %8s %8s %6s\n' flame old_s new_s ratio
for f in "$@"; do
  bo=1e9 bn=1e9
  for ((r = 0; r < rounds; ++r)); do
    bo=$(awk -v a="$(cpu "$old" "$f")" -v b="$bo" 'BEGIN { print (a < b) ? a : b }')
    bn=$(awk -v a="$(cpu "$new" "$f")" -v b="$bn" 'BEGIN { print (a < b) ? a : b }')
  done
  awk -v f="$(basename "$f")" -v o="$bo" -v n="$bn" \
    'BEGIN { printf "%-40s %8.3f %8.3f %6.2f\n", f, o, n, (n > 0) ? o / n : 0 }'
done
