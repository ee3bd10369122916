#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx texture --loop N` and texture movies on the real binary, checked as a user would, with
# ffmpeg, ffprobe and oiiotool (docs/loops.md): frame N of a loop is frame 0 byte for byte and the
# step into it is as small as the others; a --loop 8 GIF decodes to 8 frames, the first being what
# frame 8 would be, and carries the loop-for-ever extension; animated WebP likewise; .mp4 and
# .webm hold the frames; Ctrl-C keeps a playable partial movie and the old target.
# Usage: texture_loop_cli_test.sh IFSFX WORKDIR CASE
set -euo pipefail
ifsfx=$(realpath "$1")
work=$2
case_name=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
# The mean absolute difference of two images, as a fraction of full scale.
mean_difference() { { oiiotool "$1" "$2" --diff 2>&1 || true; } | sed -n 's/.*Mean error = \([0-9.e+-]*\).*/\1/p'; }
# One frame of a movie or image as raw RGB bytes' MD5.
rgb_md5() { ffmpeg -v error -i "$1" ${2:+-vf "select=eq(n\,$2)"} -frames:v 1 -f rawvideo -pix_fmt rgb24 - | md5sum | cut -d' ' -f1; }
frames_of() { ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
common=(carpet-lace --size 96x96 --mode tops --seed 3 -q)

case $case_name in
frame_N_is_frame_0)
  # 17 frames of a loop of 8 at 2 frames a step: frames j and j + 8 are the same file, bit for bit.
  "$ifsfx" texture "${common[@]}" --loop 8 --frames 17 --crossfade 2 -o t_%02d.png
  for j in $(seq 1 9); do
    cmp -s "t_$(printf %02d "$j").png" "t_$(printf %02d $((j + 8))).png" ||
      fail "frame $((j + 7)) differs from frame $((j - 1))"
  done
  # The step from frame 7 back to frame 8 = 0 changes the picture as much as the others do (up
  # to the rounding of a crossfade, half a level).
  smallest=1 largest=0
  for j in $(seq 1 7); do
    d=$(mean_difference "t_0$j.png" "t_0$((j + 1)).png")
    smallest=$(awk -v a="$smallest" -v b="$d" 'BEGIN { print (b < a ? b : a) }')
    largest=$(awk -v a="$largest" -v b="$d" 'BEGIN { print (b > a ? b : a) }')
  done
  wrap=$(mean_difference t_08.png t_09.png)
  awk -v w="$wrap" -v lo="$smallest" -v hi="$largest" 'BEGIN { h = 0.5 / 255; exit !(w >= lo - h && w <= hi + h && lo > 0) }' ||
    fail "the step 7 -> 0 ($wrap) is outside the others' range $smallest..$largest"
  echo "steps $smallest..$largest, 7 -> 0: $wrap"
  # Without --frames, a loop writes one round of it; the same frames.
  mkdir round && "$ifsfx" texture "${common[@]}" --loop 8 --crossfade 2 -o round/t_%02d.png
  [[ $(ls round | wc -l) == 8 ]] || fail "--loop 8 alone wrote $(ls round | wc -l) frames"
  for j in $(seq 1 8); do cmp -s "round/t_0$j.png" "t_0$j.png" || fail "round: frame $j differs"; done
  ;;
gif_loops)
  "$ifsfx" texture "${common[@]}" --loop 8 --frames 9 -o t_%d.png
  "$ifsfx" texture "${common[@]}" --loop 8 -o loop.gif
  [[ $(frames_of loop.gif) == 8 ]] || fail "the GIF holds $(frames_of loop.gif) frames, not 8"
  # Frame 0 is what frame 8 would be (tops: at most 256 colours, so the GIF keeps them exactly).
  [[ $(rgb_md5 loop.gif 0) == $(rgb_md5 t_9.png) ]] || fail "GIF frame 0 is not frame 8"
  [[ $(rgb_md5 loop.gif 5) == $(rgb_md5 t_6.png) ]] || fail "GIF frame 5 is not the PNG's"
  # The NETSCAPE2.0 application extension with a loop count of 0: play for ever.
  od -An -tx1 -v loop.gif | tr -d ' \n' | grep -q '4e45545343415045322e300301000000' ||
    fail "no loop-for-ever extension in the GIF"
  # 25 fps: every frame shows 4 centiseconds (graphic control extension 21 f9 04 .. 04 00).
  delays=$(od -An -tx1 -v loop.gif | tr -d ' \n' | grep -o '21f904..0400' | wc -l)
  [[ $delays == 8 ]] || fail "$delays of 8 frames last 4/100 s"
  # One frame and no loop: a still GIF, as before movies were written.
  "$ifsfx" texture "${common[@]}" -o still.gif
  [[ $(oiiotool --info still.gif | grep -c subimages) == 0 ]] || fail "one frame made an animation"
  ;;
webp_loops)
  "$ifsfx" texture "${common[@]}" --loop 8 --crossfade 2 -o loop.webp
  info=$(oiiotool --info -v loop.webp)
  grep -q "8 subimages" <<<"$info" || fail "the WebP is not 8 frames: $info"
  # The ANIM chunk: background colour, then a loop count of 0 (for ever).
  od -An -tx1 -v loop.webp | tr -d ' \n' | grep -q '414e494d06000000........0000' ||
    fail "the WebP does not loop for ever"
  ;;
mp4_and_webm)
  "$ifsfx" texture "${common[@]}" --loop 12 --crossfade 3 --fps 30 -o loop.mp4
  "$ifsfx" texture "${common[@]}" --loop 12 --crossfade 3 -o loop.webm
  "$ifsfx" texture "${common[@]}" --loop 12 --crossfade 3 --codec ffv1 -o loop.mkv
  "$ifsfx" texture "${common[@]}" --loop 12 --crossfade 3 -o t_%02d.png
  for f in loop.mp4 loop.webm loop.mkv; do
    [[ $(frames_of $f) == 12 ]] || fail "$f holds $(frames_of $f) frames"
    errors=$(ffmpeg -v error -i $f -f null - 2>&1)
    [[ -z $errors ]] || fail "$f does not decode cleanly: $errors"
  done
  [[ $(ffprobe -v error -show_entries stream=codec_name,r_frame_rate -of csv=p=0 loop.mp4) == "h264,30/1" ]] ||
    fail "loop.mp4: $(ffprobe -v error -show_entries stream=codec_name,r_frame_rate -of csv=p=0 loop.mp4)"
  [[ $(ffprobe -v error -show_entries stream=codec_name -of csv=p=0 loop.webm) == vp9 ]] || fail "loop.webm is not VP9"
  # FFV1 is lossless: the movie's frames are the PNG frames.
  for j in 0 5 11; do
    [[ $(rgb_md5 loop.mkv $j) == $(rgb_md5 "t_$(printf %02d $((j + 1))).png") ]] || fail "FFV1 frame $j differs"
  done
  [[ -z $(ls -A | grep '^\.') ]] || fail "temporary file left behind: $(ls -A)"
  ;;
sigint_keeps_partial)
  printf 'old' >loop.mp4
  "$ifsfx" texture carpet-lace --size 256x256 --mode tops --frames 2000 -o loop.mp4 2>err.txt &
  pid=$!
  for _ in $(seq 600); do
    [[ -n $(ls -A | grep '^\.loop.*tmp$' || true) ]] && break
    sleep 0.05
  done
  sleep 1.5
  kill -INT $pid
  rc=0
  wait $pid || rc=$?
  [[ $rc == 130 ]] || fail "exit $rc after Ctrl-C: $(cat err.txt)"
  [[ $(cat loop.mp4) == old ]] || fail "the old loop.mp4 was replaced"
  grep -q "^ifsfx: interrupted: [0-9]* frames kept in loop.partial.mp4 (loop.mp4 left as it was)$" err.txt ||
    fail "stderr: $(cat err.txt)"
  n=$(frames_of loop.partial.mp4)
  [[ $n -ge 1 ]] || fail "the partial movie holds no frame"
  [[ -z $(ls -A | grep '^\.') ]] || fail "temporary file left behind: $(ls -A)"
  echo "stopped: $n frames kept"
  ;;
bad_input)
  expect() {  # MESSAGE ARGS...
    local want=$1
    shift
    if "$ifsfx" texture "$@" 2>err.txt; then fail "accepted: $*"; fi
    [[ $(wc -l <err.txt) == 1 ]] && grep -q "^ifsfx: .*$want" err.txt || fail "$*: $(cat err.txt)"
  }
  expect "--bits: a movie has 8 bits per channel (got 16 for loop.mp4)" "${common[@]}" --loop 4 --bits 16 -o loop.mp4
  expect "-o: --frames needs a numbered pattern like tex_%04d.png or a movie" "${common[@]}" --frames 3 -o out.png
  expect "--loop: Value -1 not in range" "${common[@]}" --loop -1 -o out.gif
  [[ -z $(ls -A | grep -v err.txt) ]] || fail "files written: $(ls -A)"
  # A movie never replaces an input: here the GIF colours are stolen from.
  "$ifsfx" render barnsley-fern --mode tops --size 64x64 -o source.gif -q
  before=$(md5sum <source.gif)
  expect "source.gif: is the same file as the input" carpet-lace --size 64x64 --mode steal \
    --source source.gif --loop 4 -o source.gif
  [[ $(md5sum <source.gif) == "$before" ]] || fail "the source was replaced"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok $case_name"
