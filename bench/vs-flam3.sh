#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# ifsfx's measure renderer against flam3's, on the same IFSs (linear variation only), the same
# size and the same samples per pixel, in the same run: points per CPU-second for each and the
# ratio. Installs Debian's flam3-utils when missing. Issue 14's target: ratio >= 13 for both IFSs,
# on 1 and 2 threads, at 64 and 200 samples per pixel.
#   bench/vs-flam3.sh [path/to/ifsfx] [samples-per-pixel] [threads]     defaults: 64 2
set -euo pipefail
cd "$(dirname "$0")/.."
ifsfx=${1:-build/release/cli/ifsfx}
spp=${2:-64}
threads=${3:-2}
width=1920 height=1080
command -v flam3-render >/dev/null || {
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq flam3-utils >/dev/null
}
[ -x "$ifsfx" ] || { echo "vs-flam3: no ifsfx binary at $ifsfx (build first)" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A flam3 genome: flam3's coefs="a c b d e f" is our x' = a x + b y + e, y' = c x + d y + f.
# center/scale frame the same plane rectangle ifsfx's auto-framing picks (read from its output).
genome() {  # name centre_x centre_y pixels_per_unit "weight a b c d e f" ...
  local name=$1 cx=$2 cy=$3 scale=$4
  shift 4
  echo "<flame name=\"$name\" size=\"$width $height\" center=\"$cx $cy\" scale=\"$scale\""
  echo "  quality=\"$spp\" oversample=\"1\" filter=\"0\" supersample=\"1\" brightness=\"4\" gamma=\"2.2\">"
  local i=0
  for map in "$@"; do
    read -r w a b c d e f <<<"$map"
    echo "  <xform weight=\"$w\" color=\"$i\" linear=\"1\" coefs=\"$a $c $b $d $e $f\"/>"
    i=$((i + 1))
  done
  for k in $(seq 0 255); do echo "  <color index=\"$k\" rgb=\"$k $((255 - k)) 128\"/>"; done
  echo "</flame>"
}

cpu_seconds() {  # command... → user+sys seconds of the whole process
  /usr/bin/time -f "%U %S" -o "$work/time" "$@" >/dev/null 2>&1
  awk '{print $1 + $2}' "$work/time"
}

run_pair() {  # name preset maps...
  local name=$1 preset=$2
  shift 2
  # ifsfx first: its metadata tells the plane rectangle it auto-framed.
  local t_ifsfx
  t_ifsfx=$(cpu_seconds "$ifsfx" render "$preset" --mode measure --size ${width}x${height} \
    --quality "$spp" --threads "$threads" --quiet -o "$work/$name-ifsfx.png")
  local view
  view=$(iinfo -v "$work/$name-ifsfx.png" 2>/dev/null | sed -n 's/.*ifsfx:view: "\(.*\)"/\1/p')
  IFS=, read -r x0 y0 x1 y1 <<<"$view"
  local cx cy scale
  cx=$(echo "($x0 + $x1) / 2" | bc -l)
  cy=$(echo "($y0 + $y1) / 2" | bc -l)
  scale=$(echo "$width / ($x1 - $x0)" | bc -l)
  genome "$name" "$cx" "$cy" "$scale" "$@" >"$work/$name.flam3"
  local t_flam3
  t_flam3=$(cpu_seconds env out="$work/$name-flam3.png" format=png nthreads="$threads" verbose=0 \
    flam3-render <"$work/$name.flam3")
  local points
  points=$(echo "$spp * $width * $height" | bc)
  awk -v n="$name" -v p="$points" -v a="$t_ifsfx" -v b="$t_flam3" 'BEGIN {
    ra = p / a / 1e6; rb = p / b / 1e6;
    printf "%-20s ifsfx %7.1f Mpts per CPU-second   flam3 %6.1f   ratio %5.1f\n", n, ra, rb, ra / rb }'
}

echo "measure mode, ${width}x${height}, $spp samples per pixel, $threads thread(s) each; whole-process CPU time"
run_pair barnsley-fern barnsley-fern \
  "0.01 0 0 0 0.16 0 0" "0.85 0.85 0.04 -0.04 0.85 0 1.6" \
  "0.07 0.2 -0.26 0.23 0.22 0 1.6" "0.07 -0.15 0.28 0.26 0.24 0 0.44"
run_pair sierpinski-triangle sierpinski-triangle \
  "1 0.5 0 0 0.5 0 0" "1 0.5 0 0 0.5 0.5 0" "1 0.5 0 0 0.5 0.25 0.4330127018922193"
