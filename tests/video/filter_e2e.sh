#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end tests of `ifsfx filter` on real files, checked with ffprobe/ffmpeg as a user would.
# Usage: filter_e2e.sh CASE IFSFX WORKDIR   (registered with CTest by tests/video/CMakeLists.txt)
set -euo pipefail
case_name=$1
ifsfx=$(realpath "$2")
work=$3/$case_name
rm -rf "$work"
mkdir -p "$work"
cd "$work"
data=/usr/share/doc/opencv-doc/examples/data

fail() { echo "FAIL: $*" >&2; exit 1; }
frames_of() { ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
probe() { ffprobe -v error -select_streams "$2" -show_entries "stream=$3" -of csv=p=0 "$1"; }
# Per-frame PSNR of two movies compared as 8-bit BGR; prints the smallest (inf → 1000).
min_psnr() {
  ffmpeg -v error -i "$1" -i "$2" -lavfi \
    "[0:v]format=bgr24,setpts=PTS-STARTPTS[a];[1:v]format=bgr24,setpts=PTS-STARTPTS[b];[a][b]psnr=stats_file=psnr.log" \
    -f null - 
  sed -e 's/.*psnr_avg:\([^ ]*\).*/\1/' -e 's/inf/1000/' psnr.log | sort -g | head -1
}
# A short real clip: the first frames of opencv-doc's vtest.avi, stream-copied (MPEG-4 v3).
real_clip() {
  [[ -f $data/vtest.avi ]] || { echo "opencv-doc sample videos not installed"; exit 77; }
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v "$1" -c copy clip.avi
}
# A small synthetic movie with a 440 Hz AAC track: WxH, seconds.
with_audio() {
  ffmpeg -v error -y -f lavfi -i "testsrc2=size=$1:rate=25" -f lavfi -i "sine=frequency=440:sample_rate=48000" \
    -t "$2" -c:v libx264 -preset ultrafast -pix_fmt yuv420p -c:a aac -b:a 96k in.mp4
}
identity=(--preset square-tiling-4 --colouring square-tiling-4 --view 0,0,1,1 --exact)
# Frame times of a movie, one per line (presentation order); relative_times_of: from the first.
times_of() { ffprobe -v error -select_streams v:0 -show_entries frame=pts_time -of csv=p=0 "$1" | sed -n 's/^\([0-9.]\+\).*/\1/p'; }
relative_times_of() { times_of "$1" | awk 'NR == 1 { t0 = $1 } { printf "%.6f\n", $1 - t0 }'; }
# The colours of the four quadrants of the first frame (TL TR BL BR: R, G, B, RGB for white, K),
# and its size: whether a picture came out the right way up.
quadrants() {
  ffmpeg -v error -i "$1" -frames:v 1 -vf "format=rgb24,scale=2:2:flags=area" -f rawvideo - |
    od -An -tu1 -v | tr -s ' ' '\n' | grep -v '^$' | paste -d, - - - |
    awk -F, '{ n = ($1 > 128 ? "R" : "") ($2 > 128 ? "G" : "") ($3 > 128 ? "B" : ""); printf "%s ", (n == "" ? "K" : n) }'
  probe "$1" v:0 width,height
}
# A variable-rate clip with AAC sound: 30 fps with frames 20-50 dropped (what `select` leaves).
dropped_frames() {
  ffmpeg -v error -y -f lavfi -i "testsrc2=size=160x120:rate=30" -f lavfi -i "sine=frequency=440:sample_rate=48000" \
    -t 4 -vf "select='not(between(n,20,50))'" -fps_mode vfr -c:v libx264 -preset ultrafast -pix_fmt yuv420p \
    -c:a aac "$1"
}

case $case_name in
real_clip)
  real_clip 30
  "$ifsfx" filter clip.avi -o out.mp4 --preset barnsley-fern --quality 8 -q
  [[ $(frames_of out.mp4) == 30 ]] || fail "frame count $(frames_of out.mp4), expected 30"
  [[ $(probe out.mp4 v:0 r_frame_rate) == "10/1" ]] || fail "rate $(probe out.mp4 v:0 r_frame_rate)"
  [[ $(probe out.mp4 v:0 width,height) == "768,576" ]] || fail "size $(probe out.mp4 v:0 width,height)"
  [[ $(probe out.mp4 v:0 codec_name) == "h264" ]] || fail "codec $(probe out.mp4 v:0 codec_name)"
  [[ -z $(probe out.mp4 a codec_name) ]] || fail "an input without audio gave audio"
  errors=$(ffmpeg -v error -i out.mp4 -f null - 2>&1)
  [[ -z $errors ]] || fail "does not decode cleanly: $errors"
  [[ -z $(ls -A | grep '^\.') ]] || fail "temporary file left behind: $(ls -A)"
  ;;
identity_ffv1)
  real_clip 12
  "$ifsfx" filter clip.avi -o out.mkv --codec ffv1 "${identity[@]}" -q
  [[ $(frames_of out.mkv) == 12 ]] || fail "frame count $(frames_of out.mkv)"
  [[ $(probe out.mkv v:0 codec_name) == "ffv1" ]] || fail "codec $(probe out.mkv v:0 codec_name)"
  p=$(min_psnr out.mkv clip.avi)
  [[ $(wc -l < psnr.log) == 12 ]] || fail "compared $(wc -l < psnr.log) frames"
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "identity PSNR $p dB < 40 dB"
  echo "identity: smallest PSNR $p dB"
  ;;
audio_kept)
  with_audio 160x120 3
  "$ifsfx" filter in.mp4 -o out.mp4 --preset sierpinski-triangle --quality 8 -q
  [[ $(probe out.mp4 a:0 codec_name) == "aac" ]] || fail "audio codec '$(probe out.mp4 a:0 codec_name)'"
  [[ $(probe out.mp4 a:0 sample_rate) == "48000" ]] || fail "sample rate changed"
  [[ $(frames_of out.mp4) == 75 ]] || fail "frame count $(frames_of out.mp4)"
  va=$(probe out.mp4 v:0 duration)
  aa=$(probe out.mp4 a:0 duration)
  ai=$(probe in.mp4 a:0 duration)
  awk -v v="$va" -v a="$aa" 'BEGIN { d = v - a; exit !(d < 0.04 && d > -0.04) }' ||
    fail "audio $aa s vs video $va s: more than one frame apart"
  awk -v o="$aa" -v i="$ai" 'BEGIN { d = o - i; exit !(d < 0.04 && d > -0.04) }' ||
    fail "audio $aa s, input's $ai s"
  # The sound itself is copied bit for bit: same packets as the input's.
  [[ $(ffmpeg -v error -i out.mp4 -map 0:a -c copy -f md5 -) == $(ffmpeg -v error -i in.mp4 -map 0:a -c copy -f md5 -) ]] ||
    fail "audio packets differ from the input's"
  ;;
frame_range)
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v 30 -vf scale=192:144 -c:v ffv1 clip.mkv
  "$ifsfx" filter clip.mkv -o full.mkv --codec ffv1 --preset barnsley-fern --quality 8 --seed 7 -q
  "$ifsfx" filter clip.mkv -o part.mkv --codec ffv1 --preset barnsley-fern --quality 8 --seed 7 --frames 10:20 -q --threads 1
  [[ $(frames_of part.mkv) == 11 ]] || fail "range gave $(frames_of part.mkv) frames"
  ffmpeg -v error -y -i full.mkv -vf "trim=start_frame=10:end_frame=21" -c:v ffv1 expected.mkv
  p=$(min_psnr part.mkv expected.mkv)
  [[ $(wc -l < psnr.log) == 11 ]] || fail "compared $(wc -l < psnr.log) frames"
  [[ $p == 1000 ]] || fail "frames 10-20 differ from the full run's (PSNR $p dB)"
  ;;
drift_range)
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v 16 -vf scale=128:96 -c:v ffv1 clip.mkv
  common=(--codec ffv1 --preset sierpinski-triangle --quality 4 --animate drift --keyframe-interval 4 --seed 3 -q)
  "$ifsfx" filter clip.mkv -o full.mkv "${common[@]}"
  "$ifsfx" filter clip.mkv -o part.mkv "${common[@]}" --frames 6:13 --threads 1
  ffmpeg -v error -y -i full.mkv -vf "trim=start_frame=6:end_frame=14" -c:v ffv1 expected.mkv
  p=$(min_psnr part.mkv expected.mkv)
  [[ $(wc -l < psnr.log) == 8 ]] || fail "compared $(wc -l < psnr.log) frames"
  [[ $p == 1000 ]] || fail "drifted frames 6-13 differ from the full run's (PSNR $p dB)"
  ;;
loop)
  # A still picture for 30 frames: only the animation changes. With --loop 12 frame 12 is frame 0
  # again, bit for bit (FFV1), for the drift and the superIFS steps, and so on around the loop.
  ffmpeg -v error -y -f lavfi -i "testsrc2=size=128x96:rate=25" -frames:v 1 still.png
  ffmpeg -v error -y -loop 1 -i still.png -frames:v 30 -c:v ffv1 clip.mkv
  for animate in drift superifs; do
    "$ifsfx" filter clip.mkv -o $animate.mkv --codec ffv1 --animate $animate --loop 12 \
      --keyframe-interval 5 --drift-amount 0.2 --seed 3 -q
    ffmpeg -v error -i $animate.mkv -f framemd5 - | grep -v '^#' | awk -F', *' '{print $6}' >$animate.md5
    [[ $(wc -l <$animate.md5) == 30 ]] || fail "$animate: $(wc -l <$animate.md5) frames"
    for i in $(seq 1 18); do
      [[ $(sed -n "${i}p" $animate.md5) == $(sed -n "$((i + 12))p" $animate.md5) ]] ||
        fail "$animate: frame $((i + 11)) differs from frame $((i - 1))"
    done
    [[ $(sort -u $animate.md5 | wc -l) == 12 ]] || fail "$animate: not 12 different frames in the loop"
  done
  # --loop repeats an animation: without one it is refused in one line.
  if "$ifsfx" filter clip.mkv -o none.mkv --loop 12 -q 2>err.txt; then fail "--loop without --animate accepted"; fi
  grep -q "^ifsfx: --loop: repeats an animation; add --animate drift or --animate superifs$" err.txt ||
    fail "--loop without --animate: $(cat err.txt)"
  ;;
superifs_range)
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v 12 -vf scale=128:96 -c:v ffv1 clip.mkv
  common=(--codec ffv1 --animate superifs --superifs paper-fig4 --keyframe-interval 3 --seed 5 -q)
  "$ifsfx" filter clip.mkv -o full.mkv "${common[@]}"
  "$ifsfx" filter clip.mkv -o part.mkv "${common[@]}" --frames 4:10 --threads 1
  [[ $(frames_of full.mkv) == 12 ]] || fail "frame count $(frames_of full.mkv)"
  ffmpeg -v error -y -i full.mkv -vf "trim=start_frame=4:end_frame=11" -c:v ffv1 expected.mkv
  p=$(min_psnr part.mkv expected.mkv)
  [[ $(wc -l < psnr.log) == 7 ]] || fail "compared $(wc -l < psnr.log) frames"
  [[ $p == 1000 ]] || fail "superIFS frames 4-10 differ from the full run's (PSNR $p dB)"
  # Each keyframe is a new texture: frames 0 and 3 (keyframes 0 and 1) differ.
  ffmpeg -v error -y -i full.mkv -vf "trim=start_frame=0:end_frame=1" -c:v ffv1 k0.mkv
  ffmpeg -v error -y -i full.mkv -vf "trim=start_frame=3:end_frame=4" -c:v ffv1 k1.mkv
  p=$(min_psnr k0.mkv k1.mkv)
  [[ $p != 1000 ]] || fail "keyframes 0 and 1 are the same texture"
  ;;
sigint)
  with_audio 320x240 40
  "$ifsfx" filter in.mp4 -o out.mp4 --preset sierpinski-triangle --quality 4 --threads 1 2> log.txt &
  pid=$!
  for _ in $(seq 200); do  # until frames are being written (to the hidden temporary file)
    [[ -n $(find . -name '.out.mp4.*' -size +100k) ]] && break
    sleep 0.05
  done
  kill -INT $pid || fail "the filter ended before the signal came: $(cat log.txt)"
  status=0
  wait $pid || status=$?
  [[ $status == 130 ]] || fail "exit status $status, expected 130: $(cat log.txt)"
  # The output policy: the stopped run's frames are a playable movie of their own; out.mp4 is
  # never made from an unfinished run.
  done_frames=$(sed -n 's/^ifsfx: interrupted: \([0-9]*\) frames kept in out.partial.mp4 (out.mp4 left as it was)$/\1/p' log.txt)
  [[ -n $done_frames ]] || fail "no 'interrupted: N frames kept' line: $(cat log.txt)"
  [[ ! -e out.mp4 ]] || fail "an interrupted run took the output's name"
  [[ $(frames_of out.partial.mp4) == "$done_frames" ]] || fail "file holds $(frames_of out.partial.mp4) frames, reported $done_frames"
  ((done_frames > 0 && done_frames < 1000)) || fail "interrupted after $done_frames frames"
  [[ $(probe out.partial.mp4 a:0 codec_name) == "aac" ]] || fail "no audio after the interruption"
  va=$(probe out.partial.mp4 v:0 duration)
  aa=$(probe out.partial.mp4 a:0 duration)
  awk -v v="$va" -v a="$aa" 'BEGIN { d = v - a; exit !(d < 0.04 && d > -0.04) }' ||
    fail "audio $aa s vs video $va s after the interruption"
  echo "interrupted after $done_frames frames"
  ;;
bad_input)
  expect_error() {  # expect_error STATUS PATTERN ARGS...: exit status and message of a failing run
    local want=$1 pattern=$2 status=0
    shift 2
    "$ifsfx" filter "$@" -q > out.txt 2> err.txt || status=$?
    [[ $status == "$want" ]] || fail "'$*' exited $status, expected $want: $(cat err.txt)"
    grep -q -- "$pattern" err.txt || fail "'$*' said: $(cat err.txt); expected '$pattern'"
    [[ $(wc -l < err.txt) == 1 ]] || fail "'$*' printed more than one line: $(cat err.txt)"
  }
  expect_error 1 "^ifsfx: missing.mp4: no such file$" missing.mp4 -o out.mp4
  echo "not a movie" > text.mp4
  expect_error 1 "^ifsfx: text.mp4: not a movie file FFmpeg can read" text.mp4 -o out.mp4
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v 40 -vf scale=192:144 -c:v mpeg4 -q:v 2 whole.avi
  head -c $(($(stat -c %s whole.avi) / 2)) whole.avi > cut.avi
  expect_error 1 "^ifsfx: cut.avi: truncated or corrupt.*frames kept in cut.partial.mp4$" cut.avi -o cut.mp4 --quality 4
  [[ ! -e cut.mp4 ]] || fail "a failed run took the output's name"
  written=$(frames_of cut.partial.mp4)
  ((written > 5 && written < 40)) || fail "truncated input: $written frames kept"
  expect_error 1 "^ifsfx: --codec: unknown video encoder (got 'nosuchcodec'" whole.avi -o x.mp4 --codec nosuchcodec
  expect_error 1 "^ifsfx: nodir/out.mp4: cannot write" whole.avi -o nodir/out.mp4
  expect_error 1 "unknown movie container extension '.qqq'" whole.avi -o out.qqq
  expect_error 2 "^ifsfx: --frames: END must not be before START" whole.avi -o x.mp4 --frames 9:3
  [[ ! -e x.mp4 && ! -e nodir && -z $(ls -A | grep '^\.') ]] || fail "a failed run left a file behind: $(ls -A)"
  ;;
vfr_dropped_frames)
  # Frames 20-50 dropped: every frame keeps its time (not re-timed to 89 frames at 22.25 fps), the
  # picture of each time is the input's picture of that time, and the audio ends with the video.
  dropped_frames in.mp4
  "$ifsfx" filter in.mp4 -o out.mp4 --preset sierpinski-triangle --quality 4 -q
  [[ $(times_of out.mp4) == "$(times_of in.mp4)" ]] || fail "frame times differ: $(times_of out.mp4 | head -30 | tr '\n' ' ')"
  [[ $(times_of out.mp4 | wc -l) == 89 ]] || fail "frame count $(times_of out.mp4 | wc -l)"
  va=$(probe out.mp4 v:0 duration) aa=$(probe out.mp4 a:0 duration)
  awk -v v="$va" -v a="$aa" 'BEGIN { d = v - a; exit !(d < 0.034 && d > -0.034) }' || fail "audio $aa s, video $va s"
  # The pictures, compared by time (the psnr filter pairs frames of the same time), lossless.
  ffmpeg -v error -y -i in.mp4 -c:v ffv1 -c:a copy in.mkv
  "$ifsfx" filter in.mkv -o out.mkv --codec ffv1 "${identity[@]}" -q
  [[ $(relative_times_of out.mkv) == "$(relative_times_of in.mkv)" ]] || fail "Matroska frame times differ"
  p=$(min_psnr out.mkv in.mkv)
  [[ $(wc -l < psnr.log) == 89 ]] || fail "compared $(wc -l < psnr.log) frames"
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "a frame shows another time's picture (PSNR $p dB)"
  ;;
vfr_av_sync)
  # A phone-like clip: 60 fps capture with frames missing irregularly, a white flash and a beep
  # together at 3.0 s. The flash must stay with the beep after filtering.
  ffmpeg -v error -y -f lavfi -i "color=black:size=128x96:rate=60" \
    -f lavfi -i "aevalsrc='if(between(t,3,3.05),sin(2*PI*1000*t),0)':s=48000" -t 5 \
    -vf "drawbox=t=fill:color=white:enable='between(t,3,3.049)',select='lt(mod(n,7),3)+lt(mod(n,11),2)+between(t,2.99,3.06)'" \
    -fps_mode vfr -c:v libx264 -preset ultrafast -pix_fmt yuv420p -c:a aac -b:a 64k in.mp4
  flash() {  # time of the first bright frame
    ffprobe -v error -f lavfi -i "movie=$1,signalstats" -show_entries frame=pts_time:frame_tags=lavfi.signalstats.YAVG \
      -of csv=p=0 | awk -F, '$2 > 100 { print $1; exit }'
  }
  beep() {  # time the silence ends
    ffmpeg -i "$1" -af silencedetect=n=-30dB:d=0.5 -f null - 2>&1 | sed -n 's/.*silence_end: \([0-9.]*\).*/\1/p' | head -1
  }
  "$ifsfx" filter in.mp4 -o out.mp4 "${identity[@]}" -q
  fi=$(flash in.mp4) bi=$(beep in.mp4) fo=$(flash out.mp4) bo=$(beep out.mp4)
  echo "input: flash $fi s, beep $bi s; output: flash $fo s, beep $bo s"
  [[ -n $fi && -n $bi && -n $fo && -n $bo ]] || fail "flash or beep not found"
  awk -v a="$fi" -v b="$bi" -v c="$fo" -v d="$bo" 'BEGIN { e = (c - d) - (a - b); exit !(e < 0.005 && e > -0.005) }' ||
    fail "flash and beep moved apart"
  [[ $(times_of out.mp4) == "$(times_of in.mp4)" ]] || fail "frame times differ"
  ;;
cfr_by_timestamp)
  # AVI counts frames: the variable-rate clip becomes 30 fps by time, as ffmpeg -fps_mode cfr
  # makes it: the frame before the gap is repeated over it, nothing is shifted.
  dropped_frames in.mp4
  ffmpeg -v error -y -i in.mp4 -an -fps_mode cfr -r 30 -c:v ffv1 reference.avi
  "$ifsfx" filter in.mp4 -o out.avi --codec ffv1 "${identity[@]}" > summary.txt
  grep -q "(constant 30/1 fps: 31 repeated, 0 dropped)" summary.txt || fail "summary: $(cat summary.txt)"
  [[ $(frames_of out.avi) == 120 ]] || fail "frame count $(frames_of out.avi), expected 120"
  [[ $(times_of out.avi) == "$(awk 'BEGIN { for (n = 0; n < 120; ++n) printf "%.6f\n", n / 30 }')" ]] ||
    fail "frame times are not n/30 s"
  p=$(min_psnr out.avi reference.avi)
  [[ $(wc -l < psnr.log) == 120 ]] || fail "compared $(wc -l < psnr.log) frames"
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "a frame differs from ffmpeg's choice (PSNR $p dB)"
  # The same on request in Matroska; keeping times is refused where the container cannot.
  "$ifsfx" filter in.mp4 -o out.mkv --codec ffv1 "${identity[@]}" --fps-mode cfr -q
  [[ $(frames_of out.mkv) == 120 ]] || fail "--fps-mode cfr gave $(frames_of out.mkv) frames"
  status=0
  "$ifsfx" filter in.mp4 -o vfr.avi --fps-mode vfr -q 2> err.txt || status=$?
  [[ $status == 1 && $(cat err.txt) == "ifsfx: vfr.avi: the avi container cannot keep each frame's time (--fps-mode vfr); use .mkv or .mp4, or --fps-mode cfr" ]] ||
    fail "vfr into AVI: exit $status, $(cat err.txt)"
  [[ ! -e vfr.avi && ! -e vfr.avi.part ]] || fail "a refused run left a file"
  ;;
rotation)
  # A portrait picture with four coloured quarters, stored turned on its side with a display
  # matrix (as phones do): the output is upright, as ffmpeg shows it, with no matrix of its own.
  ffmpeg -v error -y -f lavfi -i "color=black:size=96x160:rate=10:duration=1" -vf \
    "drawbox=0:0:48:80:red:t=fill,drawbox=48:0:48:80:lime:t=fill,drawbox=0:80:48:80:blue:t=fill,drawbox=48:80:48:80:white:t=fill" \
    -c:v ffv1 portrait.mkv
  [[ $(quadrants portrait.mkv) == "R G B RGB 96,160" ]] || fail "test picture: $(quadrants portrait.mkv)"
  ffmpeg -v error -y -i portrait.mkv -vf transpose=cclock -c:v libx264 -pix_fmt yuv420p -qp 0 sideways.mp4
  for turn in 90 180 270; do
    ffmpeg -v error -y -i sideways.mp4 -c copy -metadata:s:v:0 rotate=$turn tagged$turn.mp4
    [[ -n $(probe tagged$turn.mp4 v:0 codec_name:stream_side_data=rotation) ]] || fail "no display matrix written"
    ffmpeg -v error -y -i tagged$turn.mp4 -frames:v 1 ffmpeg$turn.png  # ffmpeg turns it upright
    "$ifsfx" filter tagged$turn.mp4 -o out$turn.mkv --codec ffv1 "${identity[@]}" -q
    want=$(quadrants ffmpeg$turn.png) got=$(quadrants out$turn.mkv)
    echo "rotate=$turn: ffmpeg shows $want; ifsfx wrote $got"
    [[ $got == "$want" ]] || fail "rotate=$turn: $got, expected $want"
    [[ -z $(ffprobe -v error -show_entries stream_side_data -of csv=p=0 out$turn.mkv) ]] || fail "output carries a matrix"
  done
  [[ $(quadrants out90.mkv) == "RGB B G R 96,160" ]] || fail "rotate=90 is not a quarter turn"
  # A bare `rotate` tag (Matroska has no matrix) turns clockwise, as phones meant it.
  ffmpeg -v error -y -i sideways.mp4 -c copy -metadata:s:v:0 ROTATE=90 tag.mkv
  "$ifsfx" filter tag.mkv -o tag-out.mkv --codec ffv1 "${identity[@]}" -q
  [[ $(quadrants tag-out.mkv) == "R G B RGB 96,160" ]] || fail "rotate tag: $(quadrants tag-out.mkv)"
  ;;
odd_size)
  ffmpeg -v error -y -f lavfi -i "testsrc=size=161x121:rate=25" -t 0.4 -pix_fmt bgr0 -c:v ffv1 odd.mkv
  "$ifsfx" filter odd.mkv -o out.mp4 --quality 4 -q 2> err.txt
  [[ $(probe out.mp4 v:0 width,height) == "160,120" ]] || fail "size $(probe out.mp4 v:0 width,height)"
  [[ $(cat err.txt) == "ifsfx: note: out.mp4: writing 160x120, not 161x121: libx264 codes colour at half resolution and needs even sides" ]] ||
    fail "note: $(cat err.txt)"
  [[ $(frames_of out.mp4) == 10 ]] || fail "frame count $(frames_of out.mp4)"
  "$ifsfx" filter odd.mkv -o sized.mp4 --size 99x77 --quality 4 -q 2> err.txt
  [[ $(probe sized.mp4 v:0 width,height) == "98,76" ]] || fail "--size 99x77 gave $(probe sized.mp4 v:0 width,height)"
  grep -q "writing 98x76, not 99x77" err.txt || fail "no note for --size: $(cat err.txt)"
  # Encoders without chroma subsampling take odd sides as they are, without a note.
  "$ifsfx" filter odd.mkv -o same.mkv --codec ffv1 --quality 4 -q 2> err.txt
  [[ $(probe same.mkv v:0 width,height) == "161,121" && ! -s err.txt ]] || fail "FFV1: $(probe same.mkv v:0 width,height) $(cat err.txt)"
  ;;
sequence_gap)
  mkdir seq
  ffmpeg -v error -y -f lavfi -i "testsrc2=size=64x48:rate=25" -frames:v 6 -start_number 1 seq/frame_%04d.png
  rm seq/frame_0004.png
  status=0
  "$ifsfx" filter seq/frame_%04d.png -o out.mkv --codec ffv1 -q 2> err.txt || status=$?
  [[ $status == 1 ]] || fail "a gap exited $status"
  [[ $(cat err.txt) == "ifsfx: seq/frame_0004.png: missing from the sequence seq/frame_%04d.png (1 file missing between frame_0001.png and frame_0006.png; --skip-gaps goes on without it)" ]] ||
    fail "message: $(cat err.txt)"
  [[ ! -e out.mkv && ! -e out.mkv.part ]] || fail "a refused run left a file"
  # --skip-gaps: five frames, the third held for the missing one's time (0.12 s to 0.20 s).
  "$ifsfx" filter seq/frame_%04d.png -o out.mkv --codec ffv1 --skip-gaps -q
  [[ $(times_of out.mkv | tr '\n' ' ') == "0.000000 0.040000 0.080000 0.160000 0.200000 " ]] ||
    fail "times $(times_of out.mkv | tr '\n' ' ')"
  "$ifsfx" filter seq/frame_%04d.png -o cfr.avi --codec ffv1 --skip-gaps -q
  [[ $(frames_of cfr.avi) == 6 ]] || fail "constant rate over the gap: $(frames_of cfr.avi) frames"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: $case_name"
