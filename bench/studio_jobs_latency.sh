#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Does a long render job freeze `ifsfx studio`'s editor? The editor's render (POST /api/render,
# tops 512x512, the exact descent and the PNG) timed N times with the server idle, then N times
# while a movie-filter job runs (960x720, drift, on the job threads at nice 5), then N times
# while a 4096x4096 measure still runs. Prints p50 and p95 of each (curl's total time); asserts
# nothing.
# Usage: bench/studio_jobs_latency.sh [IFSFX] [N]   (default build/release/cli/ifsfx, 20)
set -euo pipefail
ifsfx=$(realpath "${1:-build/release/cli/ifsfx}")
n=${2:-20}
work=$(mktemp -d)
trap 'kill -INT "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; rm -rf "$work"' EXIT
mkdir "$work/folder"
ffmpeg -v error -y -f lavfi -i "testsrc2=size=320x240:rate=25" -frames:v 2000 -c:v mpeg4 -q:v 5 \
  "$work/folder/clip.mp4"
"$ifsfx" studio barnsley-fern --folder "$work/folder" >"$work/out" 2>/dev/null &
pid=$!
for _ in $(seq 100); do grep -q token "$work/out" && break; sleep 0.1; done
url=$(sed -n 's/^ifsfx studio: //p' "$work/out")
base=${url%%/\?token=*}
auth=(-H "X-Ifsfx-Token: ${url##*token=}")
preset=$(curl -s "${auth[@]}" "$base/api/preset?name=barnsley-fern")
with() { printf '%s' "${preset/#\{/\{$1,}"; }

# times LABEL: N renders, one after the other; prints p50 and p95 in ms
times() {
  local label=$1
  for _ in $(seq "$n"); do
    curl -s -o /dev/null -w '%{time_total}\n' "${auth[@]}" -X POST "$base/api/render" \
      --data "$(with '"mode": "tops", "size": "512x512"')"
  done | sort -n | awk -v label="$label" '{ t[NR] = $1 * 1000 }
    END { k = int(NR * 0.95); if (k < 1) k = 1
          printf "%-34s p50 %6.1f ms  p95 %6.1f ms  (%d renders)\n", label,
          t[int(NR * 0.5) + 1], t[k], NR }'
}
job() {  # job REQUEST: starts it, prints its number
  curl -s "${auth[@]}" -X POST "$base/api/jobs" --data "$(with "$1")" |
    sed -n 's/.*"id":\([0-9]*\).*/\1/p'
}
cancel() { curl -s -o /dev/null "${auth[@]}" -X POST "$base/api/jobs/$1/cancel" --data ''; }

echo "load average $(cut -d' ' -f1 /proc/loadavg) on $(nproc) cores"
times "editor render, server idle"
id=$(job '"kind": "filter", "movie": "clip.mp4", "file": "out.mp4", "size": "960x720", "animate": "drift"')
sleep 1
times "editor render, movie filter job"
cancel "$id"
id=$(job '"kind": "still", "file": "big.png", "mode": "measure", "size": "4096x4096", "quality": 2000')
sleep 1
times "editor render, 4096x4096 still job"
cancel "$id"
