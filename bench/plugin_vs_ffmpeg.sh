#!/usr/bin/env bash
# The frei0r filter inside FFmpeg, in one run on one 1080p H.264 clip (issue 13 target: ≥ 100 fps
# through FFmpeg on 2 cores, fixed map):
#   decode    ffmpeg -i clip -f null -                          (decoding alone)
#   rgba      ffmpeg -i clip -vf format=rgba -f null -          (+ the RGBA conversion FFmpeg
#                                                                 inserts before a frei0r filter)
#   plugin    ffmpeg -i clip -vf frei0r=ifsfx:PRESET -f null -  (+ the fractal filter)
#   ifsfx     ifsfx filter clip -o out.mkv --codec ffv1         (decode, filter, FFV1 encode)
# Each is also run on the first frame alone; "steady" is (N − 1) frames over the difference, which
# leaves out start-up and the steal map computed before the first frame (shown as "first frame").
# Every time is the best of REPEAT runs (a shared machine's noise only ever adds time).
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

seconds() {  # seconds CMD...: the shortest wall time of CMD in $repeat runs
  local t0 t1 best=
  for ((i = 0; i < repeat; ++i)); do
    t0=$(date +%s.%N)
    "$@" > /dev/null 2> err.txt || { cat err.txt >&2; exit 1; }
    t1=$(date +%s.%N)
    best=$(awk -v a="$t0" -v b="$t1" -v best="$best" \
      'BEGIN { t = b - a; if (best != "" && best < t) t = best; printf "%.3f", t }')
  done
  echo "$best"
}
declare -A first all
run() {  # run NAME CMD... (the command takes its frame limit from $limit)
  local name=$1
  shift
  limit=1
  first[$name]=$(seconds "$@")
  limit=$frames
  all[$name]=$(seconds "$@")
}
ff() { ffmpeg -v error -nostdin -i in.mp4 -frames:v "$limit" "$@"; }
run decode ff -f null -
run rgba ff -vf format=rgba -f null -
run plugin ff -vf "frei0r=ifsfx:$preset" -f null -
ifsfx_run() { "$build/apps/ifsfx" filter in.mp4 -o out.mkv --codec ffv1 --preset "$preset" \
  --frames "0:$((limit - 1))" -q; }
run ifsfx ifsfx_run

echo "input: $frames frames $size H.264; cores $cpus of $(nproc); load $(cut -d' ' -f1 /proc/loadavg)"
for name in decode rgba plugin ifsfx; do
  awk -v name="$name" -v n="$frames" -v t1="${first[$name]}" -v tn="${all[$name]}" 'BEGIN {
    steady = (tn > t1) ? (n - 1) / (tn - t1) : 0
    printf "%-7s total %6.2f s %7.1f fps   first frame %5.2f s   steady %7.1f fps\n",
           name, tn, n / tn, t1, steady
  }'
done
awk -v n="$frames" -v d="${all[decode]}" -v d1="${first[decode]}" -v r="${all[rgba]}" \
  -v r1="${first[rgba]}" -v p="${all[plugin]}" -v p1="${first[plugin]}" 'BEGIN {
  conv = ((r - r1) - (d - d1)) / (n - 1) * 1000
  filt = ((p - p1) - (r - r1)) / (n - 1) * 1000
  printf "per frame: RGBA conversion %.2f ms, fractal filter %.2f ms; plugin steady %.1f fps (target >= 100)\n",
         conv, filt, (n - 1) / (p - p1)
}'
