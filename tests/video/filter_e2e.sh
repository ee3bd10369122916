#!/usr/bin/env bash
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
  kill -INT $pid
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
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: $case_name"
