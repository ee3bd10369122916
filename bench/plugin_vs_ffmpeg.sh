#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The frei0r filter inside FFmpeg, in one run on one 1080p H.264 clip (issue 13 target: ≥ 100 fps
# through FFmpeg on 2 cores, fixed map):
#   decode    ffmpeg -i clip -f null -                          (decoding alone)
#   rgba      ffmpeg -i clip -vf format=rgba -f null -          (+ the RGBA conversion FFmpeg
#                                                                 inserts before a frei0r filter)
#   plugin    ffmpeg -i clip -vf frei0r=ifsfx:PRESET -f null -  (+ the fractal filter)
#   ifsfx     ifsfx filter clip -o out.mkv --codec ffv1         (decode, filter, FFV1 encode)
# Each is also run on the first frame alone; "steady" is (N − 1) frames over the difference, which
# leaves out start-up and the steal map computed before the first frame (shown as "first frame").
# Every time is the best of REPEAT runs (a shared machine's noise only ever adds time); CPU time
# (user + sys) is shown too, and "cpu-bound" = cores / CPU time per frame, the rate on that many
# otherwise idle cores when the work spreads over them — on a loaded machine the wall times say
# more about the load than about the filter.
#
#   bench/plugin_vs_ffmpeg.sh [BUILD] [FRAMES] [SIZE] [CPUS] [REPEAT]
#   defaults: build/release 300 1920x1080 0,1 3   (CPUS: the cores to run on, taskset -c)
set -euo pipefail
build=$(realpath "${1:-build/release}")
frames=${2:-300}
size=${3:-1920x1080}
cpus=${4:-0,1}
repeat=${5:-3}
preset=barnsley-fern
export FREI0R_PATH=$build/plugins/frei0r
[[ -f $FREI0R_PATH/ifsfx.so ]] || { echo "no $FREI0R_PATH/ifsfx.so: build first" >&2; exit 1; }
taskset -cp "$cpus" $$ > /dev/null  # this script and all it runs on $cpus
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# The input: opencv-doc's vtest.avi looped, scaled to $size and encoded to H.264 as a camera would.
ffmpeg -v error -y -stream_loop -1 -i /usr/share/doc/opencv-doc/examples/data/vtest.avi \
  -frames:v "$frames" -vf "scale=${size/x/:}" -r 25 -c:v libx264 -preset fast -crf 20 \
  -pix_fmt yuv420p in.mp4

seconds() {  # seconds CMD...: "WALL CPU" of the run with the shortest wall time of $repeat
  local best=
  for ((i = 0; i < repeat; ++i)); do
    /usr/bin/time -f "%e %U %S" -o time.txt "$@" > /dev/null 2> err.txt || { cat err.txt >&2; exit 1; }
    best=$(awk -v best="$best" '{ t = $1; c = $2 + $3 }
      END { split(best, b, " "); if (best != "" && b[1] < t) { t = b[1]; c = b[2] } printf "%.3f %.3f", t, c }' time.txt)
  done
  echo "$best"
}
declare -A first all cpu1 cpu
run() {  # run NAME CMD... (the command takes its frame limit from $limit)
  local name=$1 t
  shift
  limit=1
  read -r t c < <(seconds "$@")
  first[$name]=$t cpu1[$name]=$c
  limit=$frames
  read -r t c < <(seconds "$@")
  all[$name]=$t cpu[$name]=$c
}
ff() { ffmpeg -v error -nostdin -i in.mp4 -frames:v "$limit" "$@"; }
export -f ff
export limit
run decode bash -c 'ff -f null -'
run rgba bash -c 'ff -vf format=rgba -f null -'
run plugin bash -c "ff -vf frei0r=ifsfx:$preset -f null -"
run ifsfx bash -c "\"$build/cli/ifsfx\" filter in.mp4 -o out.mkv --codec ffv1 --preset $preset --frames 0:\$((limit - 1)) -q"

echo "input: $frames frames $size H.264; cores $cpus of $(nproc); load $(cut -d' ' -f1 /proc/loadavg)"
cores=$(taskset -cp $$ | awk -F': ' '{ n = split($2, r, ","); c = 0
  for (i = 1; i <= n; ++i) { if (split(r[i], ab, "-") == 2) c += ab[2] - ab[1] + 1; else c += 1 }
  print c }')
for name in decode rgba plugin ifsfx; do
  awk -v name="$name" -v n="$frames" -v t1="${first[$name]}" -v tn="${all[$name]}" \
    -v c1="${cpu1[$name]}" -v cn="${cpu[$name]}" -v cores="$cores" 'BEGIN {
    steady = (tn > t1) ? (n - 1) / (tn - t1) : 0
    ms = (cn - c1) / (n - 1) * 1000
    printf "%-7s total %6.2f s %6.1f fps  first frame %5.2f s  steady %6.1f fps  cpu %5.2f ms/frame  cpu-bound %6.1f fps\n",
           name, tn, n / tn, t1, steady, ms, (ms > 0 ? cores * 1000 / ms : 0)
  }'
done
awk -v n="$frames" -v d="${cpu[decode]}" -v d1="${cpu1[decode]}" -v r="${cpu[rgba]}" \
  -v r1="${cpu1[rgba]}" -v p="${cpu[plugin]}" -v p1="${cpu1[plugin]}" 'BEGIN {
  printf "cpu per frame: decode %.2f ms, + RGBA conversion %.2f ms, + fractal filter %.2f ms\n",
         (d - d1) / (n - 1) * 1000, ((r - r1) - (d - d1)) / (n - 1) * 1000,
         ((p - p1) - (r - r1)) / (n - 1) * 1000
}'
