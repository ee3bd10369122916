#!/usr/bin/env bash
# `ifsfx farm filter --shards 2 --cpus-per-task=1` on a real single-node Slurm (this 2-core machine)
# against one `ifsfx filter --threads 1`, on a 1080p H.264 clip with AAC audio: the speed-up, and the
# farm's overheads measured apart — the plan (counting frames by demuxing), the seek of a shard that
# starts in the middle, the stream-copy join (MB/s) and the scheduler (what the wall time holds
# beyond the slowest shard and the join). Starts Slurm with tests/farm/start-local-slurm.sh and stops
# it at the end. Run as root.
#
#   bench/farm_bench.sh [IFSFX] [FRAMES] [SIZE]     defaults: build/release/apps/ifsfx 200 1920x1080
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ifsfx=$(realpath "${1:-build/release/apps/ifsfx}")
frames=${2:-200}
size=${3:-1920x1080}
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
"$ifsfx" filter "$work/in.mp4" -o "$work/first.mp4" --frames 0:0 --threads 1 -q
first_frame=$(since "$t")
t=$(now)
"$ifsfx" filter "$work/in.mp4" -o "$work/mid.mp4" --frames "$mid:$mid" --threads 1 -q
mid_frame=$(since "$t")
seek=$(echo "$mid_frame - $first_frame" | bc)
t=$(now)
"$ifsfx" farm join "$work/farm.mp4.farm" >/dev/null
join=$(since "$t")
shard_times=$(for i in 0 1; do
  # Each shard's log ends with the summary line of its `ifsfx filter`: "... in X s (...)".
  sed -n 's/.* in \([0-9.]*\) s .*/\1/p' "$work/farm.mp4.farm/logs/shard-000$i.log" | tail -1
done | tr '\n' ' ')

slowest=$(echo "$shard_times" | tr ' ' '\n' | sort -g | tail -1)
scheduler=$(echo "$farm - $plan - $slowest - $setup - $join" | bc)

# Join throughput on more data: the input's own H.264 cut in two at a keyframe (timestamps kept, as
# farm segments keep theirs) and joined with the input's audio by `ifsfx farm join`.
copy="$work/copy.mp4.farm"
mkdir -p "$copy/segments" "$copy/done" "$copy/logs"
printf 'ifsfx-farm 1\nkind filter\ninput %s\noutput %s\nshard 0 %s\nshard %s %s\n' \
  "$work/in.mp4" "$work/copy.mp4" $((mid - 1)) "$mid" $((frames - 1)) >"$copy/plan.txt"
ffmpeg -v error -i in.mp4 -map 0:v -c copy -f segment -segment_frames "$mid" -reset_timestamps 0 \
  "$copy/segments/segment-%04d.mp4"
touch "$copy/done/shard-0000" "$copy/done/shard-0001"
t=$(now)
"$ifsfx" farm join "$copy" >/dev/null
copy_join=$(since "$t")
copy_mb=$(mb "$work/copy.mp4")

size_mb=$(mb "$work/farm.mp4")
in_mb=$(mb "$work/in.mp4")
printf 'clip: %s frames %s, %s MB H.264+AAC; output %s MB\n' "$frames" "$size" "$in_mb" "$size_mb"
printf 'filter --threads 1:                      %6.2f s\n' "$single"
printf 'farm filter --shards 2 --cpus-per-task=1: %6.2f s   speed-up %.2fx\n' "$farm" \
  "$(echo "$single / $farm" | bc -l)"
printf '  plan (count frames by demuxing, scripts): %6.2f s (%.0f MB/s of input)\n' "$plan" \
  "$(echo "$in_mb / $plan" | bc -l)"
printf '  seek to frame %s (vs frame 0):           %6.2f s\n' "$mid" "$seek"
printf '  join by stream copy:                       %6.2f s (%.0f MB/s of output)\n' "$join" \
  "$(echo "$size_mb / $join" | bc -l)"
printf '  shard pipelines (their own timing):        %s s\n' "$shard_times"
printf '  start-up of a filter run (steal map; single run): %.2f s\n' "$setup"
printf '  left for scheduling and process start:     %6.2f s\n' "$scheduler"
printf 'join of %s MB (the input'"'"'s H.264 in 2 segments + audio): %.2f s, %.0f MB/s\n' \
  "$copy_mb" "$copy_join" "$(echo "$copy_mb / $copy_join" | bc -l)"
