#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End to end: `ifsfx filter` (decode, fractal filter, encode to H.264) against a plain ffmpeg
# transcode of the same 1080p H.264 file with the same encoder settings ifsfx uses by default
# (libx264, preset medium, CRF 23, yuv420p), measured in the same run. Issue 5 target: ifsfx at
# ≥ 0.9× ffmpeg's speed, i.e. the fractal filter costs under 10% on top of decoding and encoding.
#
# Reports wall time and CPU time (user + sys) of each; the steal map is computed once before the
# first frame (a fixed cost shown apart: "pipeline" is ifsfx's own timing of decode→encode).
#
#   bench/filter_vs_ffmpeg.sh [IFSFX] [FRAMES] [SIZE]     defaults: build/cli/ifsfx 150 1920x1080
set -euo pipefail
ifsfx=$(realpath "${1:-build/cli/ifsfx}")
frames=${2:-150}
size=${3:-1920x1080}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# The input: opencv-doc's vtest.avi scaled to $size and encoded to H.264, as a camera file would be.
ffmpeg -v error -y -stream_loop -1 -i /usr/share/doc/opencv-doc/examples/data/vtest.avi \
  -frames:v "$frames" -vf "scale=${size/x/:}" -c:v libx264 -preset fast -crf 20 -pix_fmt yuv420p in.mp4

measure() {  # measure NAME CMD...: prints "NAME wall_s cpu_s" to fd 3
  local name=$1
  shift
  /usr/bin/time -f "$name %e %U %S" -o time.txt "$@" > "$name.log" 2>&1
  awk '{ printf "%s %.2f %.2f\n", $1, $2, $3 + $4 }' time.txt >&3
}
exec 3> results.txt
measure ffmpeg ffmpeg -v error -y -i in.mp4 -an -c:v libx264 -preset medium -crf 23 -pix_fmt yuv420p ffmpeg.mp4
measure ifsfx "$ifsfx" filter in.mp4 -o ifsfx.mp4 --preset barnsley-fern
exec 3>&-
pipeline=$(sed -n 's/.* in \([0-9.]*\) s (.*/\1/p' ifsfx.log)

read -r _ fw fc < <(grep '^ffmpeg' results.txt)
read -r _ iw ic < <(grep '^ifsfx' results.txt)
echo "input: $frames frames $size H.264; $(nproc) cores; load $(cut -d' ' -f1 /proc/loadavg)"
awk -v n="$frames" -v fw="$fw" -v fc="$fc" -v iw="$iw" -v ic="$ic" -v p="$pipeline" 'BEGIN {
  printf "ffmpeg  transcode         wall %6.2f s  cpu %6.2f s  %6.1f fps\n", fw, fc, n / fw
  printf "ifsfx   filter (total)    wall %6.2f s  cpu %6.2f s  %6.1f fps\n", iw, ic, n / iw
  printf "ifsfx   pipeline only     wall %6.2f s                %6.1f fps\n", p, n / p
  printf "speed ifsfx/ffmpeg: pipeline %.2f, total %.2f (target >= 0.90); cpu ffmpeg/ifsfx %.2f\n",
         fw / p, fw / iw, fc / ic
}'
