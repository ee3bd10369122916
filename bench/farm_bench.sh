#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx farm filter --shards 2 --cpus-per-task=1` on a real single-node Slurm (this 2-core machine)
# against one `ifsfx filter --threads 1`, on a 1080p H.264 clip with AAC audio: the speed-up, and the
# farm's overheads measured apart — the plan (counting frames by demuxing), the seek of a shard that
# starts in the middle, the stream-copy join (MB/s) and the scheduler (what the wall time holds
# beyond the slowest shard and the join). Starts Slurm with tests/farm/start-local-slurm.sh and stops
# it at the end. Run as root.
#
#   bench/farm_bench.sh [IFSFX] [FRAMES] [SIZE] [LOOPS]
#     defaults: build/release/cli/ifsfx 200 1920x1080 50 (the large input: the clip LOOPS times)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ifsfx=$(realpath "${1:-build/release/cli/ifsfx}")
frames=${2:-200}
size=${3:-1920x1080}
loops=${4:-50}
work=$(mktemp -d /tmp/ifsfx-farm-bench.XXXXXX)
trap '"$here/../tests/farm/stop-local-slurm.sh" >/dev/null 2>&1; rm -rf "$work"' EXIT
cd "$work"
"$here/../tests/farm/start-local-slurm.sh" >/dev/null 2>&1

# The input: opencv-doc's vtest.avi scaled to $size, H.264 (B-frames, keyframe every 50) + AAC.
ffmpeg -v error -y -stream_loop -1 -i /usr/share/doc/opencv-doc/examples/data/vtest.avi \
  -f lavfi -i sine=frequency=440:sample_rate=48000 -frames:v "$frames" -shortest \
  -vf "scale=${size/x/:}" -c:v libx264 -preset fast -crf 20 -g 50 -pix_fmt yuv420p -c:a aac in.mp4

now() { date +%s.%N; }
since() { echo "$(now) - $1" | bc; }
mb() { echo "scale=1; $(stat -c %s "$1") / 1000000" | bc; }
in_mb=$(mb "$work/in.mp4")

t=$(now)
"$ifsfx" filter "$work/in.mp4" -o "$work/single.mp4" --threads 1 >single.txt 2>/dev/null
single=$(since "$t")
# Its summary line gives the pipeline's own time; the rest is start-up (the steal map).
single_pipeline=$(sed -n 's/.* in \([0-9.]*\) s .*/\1/p' single.txt)
setup=$(echo "$single - $single_pipeline" | bc)

# The whole farm run, submit to the joined file.
t=$(now)
"$ifsfx" farm filter "$work/in.mp4" -o "$work/farm.mp4" --shards 2 --cpus-per-task=1 --submit \
  --wait >/dev/null
farm=$(since "$t")

# Its parts, measured apart (the shards' own summary lines give their times).
t=$(now)
"$ifsfx" farm filter "$work/in.mp4" -o "$work/plan.mp4" --shards 2 -q >/dev/null
plan=$(since "$t")
mid=$((frames / 2))
t=$(now)
"$ifsfx" farm join "$work/farm.mp4.farm" >/dev/null
join=$(since "$t")
shard_times=$(for i in 0 1; do
  # Each shard's log ends with the summary line of its `ifsfx filter`: "... in X s (...)".
  sed -n 's/.* in \([0-9.]*\) s .*/\1/p' "$work/farm.mp4.farm/logs/shard-000$i.log" | tail -1
done | tr '\n' ' ')

slowest=$(echo "$shard_times" | tr ' ' '\n' | sort -g | tail -1)
scheduler=$(echo "$farm - $plan - $slowest - $setup - $join" | bc)

# Throughputs, from two sizes so that the fixed costs (process start, probing) drop out: the input
# and the input LOOPS times over (stream copy). Planning counts frames by demuxing the whole file;
# seeking to the middle demuxes half of it; the join copies segments cut at a keyframe (timestamps
# kept, as farm segments keep theirs) and the audio.
ffmpeg -v error -stream_loop $((loops - 1)) -i in.mp4 -c copy big.mp4
join_of() {  # join_of NAME INPUT FRAMES: prints the seconds `ifsfx farm join` takes
  local dir="$work/$1.mp4.farm" half=$(($3 / 2))
  mkdir -p "$dir/segments" "$dir/done" "$dir/logs"
  printf 'ifsfx-farm 1\nkind filter\ninput %s\noutput %s\nshard 0 %s\nshard %s %s\n' \
    "$2" "$work/$1.mp4" $((half - 1)) "$half" $(($3 - 1)) >"$dir/plan.txt"
  ffmpeg -v error -i "$2" -map 0:v -c copy -f segment -segment_frames "$half" \
    -reset_timestamps 0 "$dir/segments/segment-%04d.mp4"
  touch "$dir/done/shard-0000" "$dir/done/shard-0001"
  local t0; t0=$(now)
  "$ifsfx" farm join "$dir" >/dev/null
  since "$t0"
}
plan_of() {
  local t0; t0=$(now)
  "$ifsfx" farm filter "$1" -o "$work/plan-$2.mp4" --shards 2 -q >/dev/null
  since "$t0"
}
# Seconds to filter frame $2 minus frame 0, the best of three: a tiny output (--size 64x36) so that
# the steal map costs nothing and what differs is the seek (demuxing to the frame, decoding its GOP).
seek_of() {
  local best="" t0 t1 d
  for _ in 1 2 3; do
    t0=$(now)
    "$ifsfx" filter "$1" -o "$work/f0.mp4" --frames 0:0 --size 64x36 --threads 1 -q
    t1=$(now)
    "$ifsfx" filter "$1" -o "$work/f1.mp4" --frames "$2:$2" --size 64x36 --threads 1 -q
    d=$(echo "$(now) - $t1 - ($t1 - $t0)" | bc)
    if [ -z "$best" ] || [ "$(echo "$d < $best" | bc)" = 1 ]; then best=$d; fi
  done
  echo "$best"
}
big_frames=$((frames * loops))
small_mb=$in_mb
big_mb=$(mb "$work/big.mp4")
join_small=$(join_of js "$work/in.mp4" "$frames")
join_big=$(join_of jb "$work/big.mp4" "$big_frames")
plan_big=$(plan_of "$work/big.mp4" big)
seek=$(seek_of "$work/in.mp4" "$mid")
seek_big=$(seek_of "$work/big.mp4" $((big_frames / 2)))
rate() { echo "($3 - $1) / ($4 - $2)" | bc -l; }  # MB/s from (MB, s) at two sizes

size_mb=$(mb "$work/farm.mp4")
printf 'clip: %s frames %s, %s MB H.264+AAC; output %s MB\n' "$frames" "$size" "$in_mb" "$size_mb"
printf 'filter --threads 1:                      %6.2f s\n' "$single"
printf 'farm filter --shards 2 --cpus-per-task=1: %6.2f s   speed-up %.2fx\n' "$farm" \
  "$(echo "$single / $farm" | bc -l)"
printf '  plan (count frames by demuxing, scripts): %6.2f s (%.0f MB/s of input)\n' "$plan" \
  "$(echo "$in_mb / $plan" | bc -l)"
printf '  join of its %s MB by stream copy:          %6.2f s (mostly fixed costs)\n' "$size_mb" "$join"
printf '  shard pipelines (their own timing):        %s s\n' "$shard_times"
printf '  start-up of a filter run (steal map; single run): %.2f s\n' "$setup"
printf '  left for scheduling and process start:     %6.2f s\n' "$scheduler"
printf 'throughput (from %s MB and %s MB inputs; fixed costs excluded):\n' "$small_mb" "$big_mb"
printf '  plan, frames counted by demuxing:  %.0f MB/s  (%.2f s for %s MB)\n' \
  "$(rate "$small_mb" "$plan" "$big_mb" "$plan_big")" "$plan_big" "$big_mb"
printf '  seek to the middle (demux half):   %.2f s at %s MB, %.2f s at %s MB\n' "$seek" \
  "$small_mb" "$seek_big" "$big_mb"
printf '  join by stream copy (+ audio):     %.0f MB/s  (%.2f s for %s MB, %.2f s for %s MB)\n' \
  "$(rate "$small_mb" "$join_small" "$big_mb" "$join_big")" "$join_small" "$small_mb" \
  "$join_big" "$big_mb"

