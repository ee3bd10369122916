#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end tests of the frei0r plugins through the hosts people use them in — FFmpeg, melt (MLT)
# and gst-launch-1.0 (GStreamer) — and through tests/plugins/frei0r_host (our own host).
# Usage: plugins_e2e.sh CASE PLUGIN_DIR IFSFX FREI0R_HOST WORKDIR  (registered by CMakeLists.txt)
set -euo pipefail
case_name=$1
plugins=$(realpath "$2")
ifsfx=$(realpath "$3")
host=$(realpath "$4")
work=$5/$case_name
rm -rf "$work"
mkdir -p "$work"
cd "$work"
export FREI0R_PATH=$plugins
data=/usr/share/doc/opencv-doc/examples/data

fail() { echo "FAIL: $*" >&2; exit 1; }
need() { command -v "$1" > /dev/null || { echo "$1 not installed"; exit 77; }; }
frames_of() { ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
rate_of() { ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 "$1"; }
# Smallest per-frame PSNR of two movies (or image sequences) compared as 8-bit RGB; inf → 1000.
min_psnr() {
  ffmpeg -v error -i "$1" -i "$2" -lavfi \
    "[0:v]format=rgb24,setpts=PTS-STARTPTS[a];[1:v]format=rgb24,setpts=PTS-STARTPTS[b];[a][b]psnr=stats_file=psnr.log" \
    -f null -
  [[ $(wc -l < psnr.log) == "${3:?frames}" ]] || fail "compared $(wc -l < psnr.log) frames of $1 and $2, expected $3"
  sed -e 's/.*psnr_avg:\([^ ]*\).*/\1/' -e 's/inf/1000/' psnr.log | sort -g | head -1
}
same_frames() {  # same_frames A B N: N frames, bit for bit the same RGB
  local p
  p=$(min_psnr "$1" "$2" "$3")
  [[ $p == 1000 ]] || fail "$1 and $2 differ (smallest PSNR $p dB)"
}
# The test clip: 30 frames of opencv-doc's vtest.avi at 320x240, 25 fps, as lossless RGB (FFV1,
# bgr0) or H.264 (yuv420p).
clip() {
  [[ -f $data/vtest.avi ]] || { echo "opencv-doc sample videos not installed"; exit 77; }
  ffmpeg -v error -y -i "$data/vtest.avi" -frames:v 30 -vf "scale=${2:-320:240},fps=25" -r 25 \
    "${@:3}" "$1"
}
# The settings both sides use: `ifsfx filter` flags and the plugin's parameters in order
# (preset|colouring|mix|background|exact|drift|speed|seed|view).
cli=(--preset maple-leaf --mix 0.25 --background "#336699" --seed 3)
params="maple-leaf||0.25|#336699|y|0|0.2|3|"

case $case_name in
exports)
  # Only the frei0r API leaves the plugins: no OpenCV, FFmpeg or ifsfx symbol to clash with the
  # host's own.
  need nm
  for so in "$plugins/ifsfx.so" "$plugins/ifsfx-texture.so"; do
    exported=$(nm -D --defined-only "$so" | awk '{ print $3 }' | sort)
    expected=$(printf '%s\n' f0r_construct f0r_deinit f0r_destruct f0r_get_param_info \
      f0r_get_param_value f0r_get_plugin_info f0r_init f0r_set_param_value f0r_update | sort)
    [[ $exported == "$expected" ]] || fail "$so exports: $(echo $exported)"
  done
  ;;
ffmpeg_lossless)
  # Lossless RGB on both sides: the plugin through FFmpeg is `ifsfx filter`, bit for bit.
  clip clip.mkv 320:240 -c:v ffv1 -pix_fmt bgr0
  "$ifsfx" filter clip.mkv -o cli.mkv --codec ffv1 "${cli[@]}" -q
  ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:$params" -c:v ffv1 -pix_fmt bgr0 ffmpeg.mkv
  [[ $(frames_of ffmpeg.mkv) == 30 ]] || fail "ffmpeg wrote $(frames_of ffmpeg.mkv) frames"
  [[ $(rate_of ffmpeg.mkv) == 25/1 ]] || fail "rate $(rate_of ffmpeg.mkv)"
  same_frames ffmpeg.mkv cli.mkv 30
  # The filter did something: the output is not the input.
  p=$(min_psnr ffmpeg.mkv clip.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p < 20) }' || fail "the output looks like the input ($p dB)"
  ;;
ffmpeg_flame)
  # A fractal flame as the preset (docs/flames.md): the plugin through FFmpeg is `ifsfx filter
  # --preset FILE.flame`, bit for bit, fixed and drifting.
  cat > spiral.flame <<'XML'
<flame name="spiral" size="80 60" center="0 0" scale="20" palette="7">
  <xform weight="0.5" color="0" linear="0.8" swirl="0.2" coefs="0.6 0.2 -0.2 0.6 0.5 0"/>
  <xform weight="0.5" color="1" spherical="1" coefs="0.5 0 0 0.5 -0.5 0.2"/>
  <finalxform color="0.5" linear="1" coefs="1 0 0 1 0 0"/>
</flame>
XML
  clip clip.mkv 128:96 -c:v ffv1 -pix_fmt bgr0
  "$ifsfx" filter clip.mkv -o cli.mkv --codec ffv1 --preset spiral.flame --seed 3 -q
  ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:spiral.flame||0|black|y|0|0.2|3|" \
    -c:v ffv1 -pix_fmt bgr0 ffmpeg.mkv 2> err.txt || fail "ffmpeg: $(cat err.txt)"
  [[ $(frames_of ffmpeg.mkv) == 30 ]] || fail "ffmpeg wrote $(frames_of ffmpeg.mkv) frames"
  same_frames ffmpeg.mkv cli.mkv 30
  p=$(min_psnr ffmpeg.mkv clip.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p < 20) }' || fail "the output looks like the input ($p dB)"
  "$ifsfx" filter clip.mkv -o drift.mkv --codec ffv1 --preset spiral.flame --seed 3 \
    --animate drift --drift-amount 0.3 --drift-speed 1 -q
  p=$(min_psnr drift.mkv cli.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p < 1000) }' || fail "the drift did not move the flame"
  ;;
ffmpeg_h264)
  # A real H.264 clip: FFmpeg's YUV→RGBA conversion and ifsfx's YUV→BGR may differ in rounding.
  # (FFmpeg 5.1 hands frei0r plugins rows padded to 64 bytes as if they were contiguous, so its
  # frame widths must be multiples of 16; odd sizes are tested through GStreamer and our host.)
  clip clip.mp4 320:240 -c:v libx264 -preset ultrafast -pix_fmt yuv420p
  "$ifsfx" filter clip.mp4 -o cli.mkv --codec ffv1 "${cli[@]}" -q
  ffmpeg -v error -y -i clip.mp4 -vf "frei0r=ifsfx:$params" -c:v ffv1 -pix_fmt bgr0 ffmpeg.mkv
  [[ $(frames_of ffmpeg.mkv) == 30 ]] || fail "ffmpeg wrote $(frames_of ffmpeg.mkv) frames"
  [[ $(rate_of ffmpeg.mkv) == 25/1 ]] || fail "rate $(rate_of ffmpeg.mkv)"
  p=$(min_psnr ffmpeg.mkv cli.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "plugin vs ifsfx filter: $p dB < 40 dB"
  echo "plugin through ffmpeg vs ifsfx filter: smallest PSNR $p dB"
  ;;
ffmpeg_drift)
  # The drift animation through FFmpeg is `ifsfx filter --animate drift` at the same 25 fps, frame
  # for frame: at 256 wide FFmpeg 5.1 passes each frame's time (milliseconds, read as such); at
  # 160 wide it passes none (it copies rows that are not a multiple of 64 pixels and drops the
  # timestamp) and the plugin counts frames at 25 fps, saying so once.
  for width in 256 160; do
    clip clip$width.mkv $width:120 -c:v ffv1 -pix_fmt bgr0
    "$ifsfx" filter clip$width.mkv -o cli$width.mkv --codec ffv1 --preset sierpinski-triangle \
      --animate drift --drift-amount 0.3 --drift-speed 1 --seed 4 -q
    ffmpeg -v error -y -i clip$width.mkv -vf "frei0r=ifsfx:sierpinski-triangle||0|black|y|0.3|1|4|" \
      -c:v ffv1 -pix_fmt bgr0 ffmpeg$width.mkv 2> err$width.txt
    same_frames ffmpeg$width.mkv cli$width.mkv 30
    [[ ! -s err$width.txt ]] ||
      grep -qx "frei0r ifsfx: the host gives no frame times; animating by frame count at 25 fps" \
        err$width.txt || fail "stderr at $width wide: $(cat err$width.txt)"
    echo "${width}x120: $( [[ -s err$width.txt ]] && echo "no times from FFmpeg, frames counted" ||
      echo "FFmpeg's times")"
    # And it moves: frames 0 and 29 show different maps.
    ffmpeg -v error -y -i ffmpeg$width.mkv -vf "select=eq(n\,0)+eq(n\,29)" -vsync 0 f$width-%d.png
    [[ $(cmp -s f$width-1.png f$width-2.png; echo $?) != 0 ]] || fail "drift 0.3 left the map still"
  done
  ;;
ffmpeg_bad_preset)
  # A bad preset does not stop FFmpeg: one line on stderr, the frames pass through unchanged.
  clip clip.mkv 160:120 -c:v ffv1 -pix_fmt bgr0
  status=0
  ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:no-such-preset" -c:v ffv1 -pix_fmt bgr0 \
    out.mkv 2> err.txt || status=$?
  [[ $status == 0 ]] || fail "ffmpeg exited $status: $(cat err.txt)"
  [[ $(wc -l < err.txt) == 1 ]] || fail "expected one line, got: $(cat err.txt)"
  grep -q "^frei0r ifsfx: .*no-such-preset.*frames pass through unchanged$" err.txt ||
    fail "unclear message: $(cat err.txt)"
  echo "message: $(cat err.txt)"
  same_frames out.mkv clip.mkv 30
  ;;
ffmpeg_texture)
  # frei0r_src at 25 fps and 12.5 steps per second, crossfaded: `ifsfx texture --frames 10
  # --crossfade 2`, bit for bit.
  "$ifsfx" texture paper-fig4 --mode tops --size 160x120 -V 3 --seed 2 --frames 10 --crossfade 2 \
    -o cli_%04d.png -q
  ffmpeg -v error -y -f lavfi \
    -i "frei0r_src=size=160x120:framerate=25:filter_name=ifsfx-texture:filter_params=paper-fig4|3|tops||2|12.5|y" \
    -frames:v 10 -start_number 1 src_%04d.png
  [[ -f src_0010.png && ! -f src_0011.png ]] || fail "ffmpeg wrote $(ls src_*.png | wc -l) frames"
  same_frames src_%04d.png cli_%04d.png 10
  ;;
ffmpeg_loop)
  # The loop parameter (seconds): 0.48 s at 25 fps is `--loop 12`, frame for frame, for the drift
  # filter and the texture source; frame 12 is frame 0 again.
  clip clip.mkv 256:120 -c:v ffv1 -pix_fmt bgr0
  "$ifsfx" filter clip.mkv -o cli.mkv --codec ffv1 --preset sierpinski-triangle --animate drift \
    --drift-amount 0.3 --drift-speed 1 --seed 4 --loop 12 -q
  ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:sierpinski-triangle||0|black|y|0.3|1|4||25|0.48" \
    -c:v ffv1 -pix_fmt bgr0 ffmpeg.mkv
  same_frames ffmpeg.mkv cli.mkv 30
  "$ifsfx" texture paper-fig4 --mode tops --size 160x120 -V 3 --seed 2 --frames 30 --loop 12 \
    --crossfade 2 -o cli_%04d.png -q
  ffmpeg -v error -y -f lavfi \
    -i "frei0r_src=size=160x120:framerate=25:filter_name=ifsfx-texture:filter_params=paper-fig4|3|tops||2|12.5|y|25|0.48" \
    -frames:v 30 -start_number 1 src_%04d.png
  same_frames src_%04d.png cli_%04d.png 30
  cmp -s src_0001.png src_0013.png || fail "texture source: frame 12 is not frame 0"
  ;;
melt)
  # melt (MLT) with parameters by name: the FFmpeg result.
  need melt
  clip clip.mkv 320:240 -c:v ffv1 -pix_fmt bgr0
  ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:$params" -c:v ffv1 -pix_fmt bgr0 ffmpeg.mkv
  melt -quiet clip.mkv -filter frei0r.ifsfx preset=maple-leaf mix=0.25 background="#336699" seed=3 \
    -consumer avformat:melt.mkv vcodec=ffv1 pix_fmt=bgr0 an=1 > melt.log 2>&1 ||
    fail "melt: $(cat melt.log)"
  [[ $(frames_of melt.mkv) == 30 ]] || fail "melt wrote $(frames_of melt.mkv) frames"
  [[ $(rate_of melt.mkv) == 25/1 ]] || fail "rate $(rate_of melt.mkv)"
  p=$(min_psnr melt.mkv ffmpeg.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "melt vs ffmpeg: $p dB < 40 dB"
  echo "melt vs ffmpeg: smallest PSNR $p dB"
  ;;
melt_drift | gstreamer_drift)
  # The drift animation keyed on melt's and GStreamer's times (seconds) is `ifsfx filter --animate
  # drift`. PSNR, not bits: each host converts FFV1's BGR to the plugin's RGBA itself. A frozen or
  # wrongly timed map is far below 40 dB (11-12 dB by frame 29). GStreamer's wrapper limits number
  # properties to 0..1, so the seed is 1.
  clip clip.mkv 320:240 -c:v ffv1 -pix_fmt bgr0
  "$ifsfx" filter clip.mkv -o cli.mkv --codec ffv1 --preset sierpinski-triangle --animate drift \
    --drift-amount 0.3 --drift-speed 1 --seed 1 -q
  if [[ $case_name == melt_drift ]]; then
    need melt
    melt -quiet clip.mkv -filter frei0r.ifsfx preset=sierpinski-triangle drift=0.3 speed=1 seed=1 \
      -consumer avformat:host.mkv vcodec=ffv1 pix_fmt=bgr0 an=1 > host.log 2>&1 ||
      fail "melt: $(cat host.log)"
  else
    need gst-launch-1.0
    export GST_REGISTRY=$PWD/registry.bin
    gst-launch-1.0 -q filesrc location=clip.mkv ! matroskademux ! avdec_ffv1 ! videoconvert ! \
      frei0r-filter-ifsfx preset=sierpinski-triangle drift=0.3 speed=1 seed=1 ! videoconvert ! \
      video/x-raw,format=BGRx ! avenc_ffv1 ! matroskamux ! filesink location=host.mkv \
      > host.log 2>&1 || fail "gst-launch: $(cat host.log)"
  fi
  [[ $(frames_of host.mkv) == 30 ]] || fail "the host wrote $(frames_of host.mkv) frames"
  p=$(min_psnr host.mkv cli.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "$case_name vs ifsfx filter: $p dB < 40 dB"
  echo "$case_name vs ifsfx filter --animate drift: smallest PSNR $p dB"
  ;;
host_times)
  # What each host passes as f0r_update's time, printed by a probe plugin (tests/plugins/
  # time_probe.cpp): the facts plugins/frei0r/host_clock.h is built on. FFmpeg: milliseconds, or
  # for frames whose rows it copied (widths not a multiple of 64 in 5.1) a negative NOPTS pattern;
  # melt and GStreamer: seconds. A host that starts passing anything else fails here, naming it.
  probe=$(dirname "$host")/probe
  [[ -f $probe/ifsfx-time-probe.so ]] || fail "no probe plugin in $probe"
  # The first three times, or with `distinct` the first three different ones (melt renders frame
  # 0 twice).
  first_times() { sed -n 's/^time=//p' "$1" | { [[ ${2:-} == distinct ]] && uniq || cat; } |
    head -3 | paste -sd' '; }
  calls() { grep -c '^time=' "$1"; }
  steps_of() {  # steps_of "T0 T1 T2" STEP: the times are 0, STEP, 2 STEP
    awk -v t="$1" -v d="$2" 'BEGIN { n = split(t, a, " "); if (n != 3) exit 1
      for (k = 1; k <= 3; ++k) if ((a[k] - (k - 1) * d) ^ 2 > 1e-12) exit 1 }'
  }
  for width in 320 256 160 176; do
    clip clip$width.mkv $width:120 -c:v ffv1 -pix_fmt bgr0
    FREI0R_PATH=$probe ffmpeg -v error -y -i clip$width.mkv -vf frei0r=ifsfx-time-probe \
      -f null - 2> ffmpeg$width.txt
    t=$(first_times ffmpeg$width.txt)
    if steps_of "$t" 40; then
      echo "ffmpeg ${width}x120: $t (milliseconds; $(calls ffmpeg$width.txt) calls for 30 frames)"
    elif awk -v t="$t" 'BEGIN { n = split(t, a, " "); if (n != 3) exit 1
        for (k = 1; k <= 3; ++k) if (!(a[k] < -1e15)) exit 1 }'; then
      echo "ffmpeg ${width}x120: $t (no time: NOPTS)"
    else
      fail "ffmpeg ${width}x120 passes times host_clock.h does not expect: $t"
    fi
  done
  if command -v melt > /dev/null; then
    FREI0R_PATH=$probe melt -quiet clip320.mkv -filter frei0r.ifsfx-time-probe \
      -consumer avformat:melt.mkv vcodec=ffv1 an=1 > melt.txt 2>&1 || fail "melt: $(cat melt.txt)"
    t=$(first_times melt.txt distinct)
    steps_of "$t" 0.04 || fail "melt passes times host_clock.h does not expect: $t"
    echo "melt 320x120: $t (seconds; $(calls melt.txt) calls for 30 frames)"
  fi
  if command -v gst-launch-1.0 > /dev/null; then
    GST_REGISTRY=$PWD/registry.bin FREI0R_PATH=$probe gst-launch-1.0 -q filesrc \
      location=clip320.mkv ! matroskademux ! avdec_ffv1 ! videoconvert ! \
      frei0r-filter-ifsfx-time-probe ! fakesink > gst.txt 2>&1 || fail "gst-launch: $(cat gst.txt)"
    t=$(first_times gst.txt)
    steps_of "$t" 0.04 || fail "GStreamer passes times host_clock.h does not expect: $t"
    echo "gst-launch 320x120: $t (seconds; $(calls gst.txt) calls for 30 frames)"
  fi
  ;;
gstreamer | gstreamer_odd_size)
  # gst-launch-1.0 with the frei0r-filter-ifsfx element, in a registry of its own (the frei0r
  # plugin lists the FREI0R_PATH plugins when it is scanned): the FFmpeg result, or at an odd
  # size (which FFmpeg 5.1 cannot give a frei0r plugin) `ifsfx filter`'s. GStreamer's frei0r
  # wrapper limits number properties to 0..1, so the seed is 1 here.
  need gst-launch-1.0
  export GST_REGISTRY=$PWD/registry.bin
  gst-inspect-1.0 frei0r-filter-ifsfx > inspect.txt 2>&1 || fail "no frei0r-filter-ifsfx: $(cat inspect.txt)"
  if [[ $case_name == gstreamer ]]; then
    clip clip.mkv 320:240 -c:v ffv1 -pix_fmt bgr0
    ffmpeg -v error -y -i clip.mkv -vf "frei0r=ifsfx:maple-leaf||0.25|#336699|y|0|0.2|1|" \
      -c:v ffv1 -pix_fmt bgr0 expected.mkv
  else
    clip clip.mkv 321:241 -c:v ffv1 -pix_fmt bgr0
    "$ifsfx" filter clip.mkv -o expected.mkv --codec ffv1 --preset maple-leaf --mix 0.25 \
      --background "#336699" -q
  fi
  gst-launch-1.0 -q filesrc location=clip.mkv ! matroskademux ! avdec_ffv1 ! videoconvert ! \
    frei0r-filter-ifsfx preset=maple-leaf mix=0.25 background="#336699" seed=1 ! videoconvert ! \
    video/x-raw,format=BGRx ! avenc_ffv1 ! matroskamux ! filesink location=gst.mkv > gst.log 2>&1 ||
    fail "gst-launch: $(cat gst.log)"
  [[ $(frames_of gst.mkv) == 30 ]] || fail "gst-launch wrote $(frames_of gst.mkv) frames"
  p=$(min_psnr gst.mkv expected.mkv 30)
  awk -v p="$p" 'BEGIN { exit !(p >= 40) }' || fail "gstreamer vs expected: $p dB < 40 dB"
  echo "gstreamer vs expected: smallest PSNR $p dB"
  ;;
own_host_reverse_order | own_host_instances)
  # Frames are a pure function of time: drifting maps rendered backwards, or by two instances on
  # two threads taking turns, are the frames rendered in order.
  clip clip.rgba 161:121 -f rawvideo -pix_fmt rgba
  run=("$host" "$plugins/ifsfx.so" --size 161x121 --frames 30 --input clip.rgba
    --param 0=sierpinski-triangle --param 5=0.4 --param 6=2 --param 7=9)
  "${run[@]}" -o forward.rgba
  if [[ $case_name == own_host_reverse_order ]]; then
    "${run[@]}" --order reverse -o other.rgba
  else
    "${run[@]}" --instances 2 -o other.rgba
  fi
  cmp forward.rgba other.rgba || fail "frames differ"
  ! cmp -s forward.rgba clip.rgba || fail "the filter did nothing"
  ;;
own_host_no_times)
  # A host that gives no frame times (FFmpeg 5.1's NOPTS pattern): the plugin counts frames at its
  # `rate` (25 by default), and the frames are those of a host that gives k / rate seconds; it says
  # so once. A still filter (drift 0) has nothing to say.
  clip clip.rgba 161:121 -f rawvideo -pix_fmt rgba
  run=("$host" "$plugins/ifsfx.so" --size 161x121 --frames 30 --input clip.rgba
    --param 0=sierpinski-triangle --param 5=0.4 --param 6=2 --param 7=9)
  message="frei0r ifsfx: the host gives no frame times; animating by frame count at"
  "${run[@]}" -o timed.rgba 2> timed.txt
  "${run[@]}" --times none -o counted.rgba 2> counted.txt
  cmp timed.rgba counted.rgba || fail "frames counted at 25 fps differ from frames at k/25 s"
  [[ ! -s timed.txt ]] || fail "a host with times got: $(cat timed.txt)"
  [[ $(cat counted.txt) == "$message 25 fps" ]] || fail "message: $(cat counted.txt)"
  "${run[@]}" --fps 30 -o timed30.rgba
  "${run[@]}" --times none --param 9=30 -o counted30.rgba 2> counted30.txt
  cmp timed30.rgba counted30.rgba || fail "frames counted at rate 30 differ from frames at k/30 s"
  [[ $(cat counted30.txt) == "$message 30 fps" ]] || fail "message: $(cat counted30.txt)"
  ! cmp -s timed.rgba timed30.rgba || fail "25 and 30 fps gave the same frames"
  "$host" "$plugins/ifsfx.so" --size 161x121 --frames 5 --input clip.rgba --times none \
    -o still.rgba 2> still.txt
  [[ ! -s still.txt ]] || fail "a still filter said: $(cat still.txt)"
  "$host" "$plugins/ifsfx.so" --size 161x121 --frames 5 --input clip.rgba --times none \
    --param 5=0.4 --param 9=0 -o bad_rate.rgba 2> bad_rate.txt
  grep -q "^frei0r ifsfx: rate: must be in (0, 1000\] frames per second (got 0)" bad_rate.txt ||
    fail "rate 0: $(cat bad_rate.txt)"
  # The texture source too (speed 6 steps per second).
  tex=("$host" "$plugins/ifsfx-texture.so" --size 97x65 --frames 12 --param 5=6)
  "${tex[@]}" -o tex_timed.rgba
  "${tex[@]}" --times none -o tex_counted.rgba 2> tex.txt
  cmp tex_timed.rgba tex_counted.rgba || fail "texture frames counted differ from timed ones"
  [[ $(cat tex.txt) == "frei0r ifsfx-texture: the host gives no frame times; animating by frame count at 25 fps" ]] ||
    fail "texture message: $(cat tex.txt)"
  ;;
own_host_parameter_changes)
  # Parameters changed mid-stream, a bad one among them: frames 10-14 pass through unchanged, the
  # others are filtered; the message comes once.
  clip clip.rgba 161:121 -f rawvideo -pix_fmt rgba
  frame=$((161 * 121 * 4))
  "$host" "$plugins/ifsfx.so" --size 161x121 --frames 30 --input clip.rgba --param 5=0.2 \
    --set 5:0=maple-leaf --set 8:2=0.5 --set 10:0=no-such-preset --set 12:2=0.7 \
    --set 15:0=sierpinski-triangle --set 18:5=0 --set 20:3=original --set 22:8=0,0,1,1 \
    --set 25:4=y -o out.rgba 2> err.txt
  [[ $(grep -c "^frei0r ifsfx: .*no-such-preset" err.txt) == 1 ]] || fail "messages: $(cat err.txt)"
  for j in 10 14; do
    cmp -s <(dd if=out.rgba bs=$frame skip=$j count=1 status=none) \
      <(dd if=clip.rgba bs=$frame skip=$j count=1 status=none) || fail "frame $j was filtered"
  done
  for j in 0 9 15 29; do
    ! cmp -s <(dd if=out.rgba bs=$frame skip=$j count=1 status=none) \
      <(dd if=clip.rgba bs=$frame skip=$j count=1 status=none) || fail "frame $j passed through"
  done
  # The texture source too, with a change of mode and a bad V.
  "$host" "$plugins/ifsfx-texture.so" --size 97x65 --frames 12 --param 5=6 \
    --set 4:2=attractor --set 6:1=0 --set 8:1=2 -o tex.rgba 2> tex_err.txt
  [[ $(grep -c "^frei0r ifsfx-texture: buffers: must be a whole number" tex_err.txt) == 1 ]] ||
    fail "texture messages: $(cat tex_err.txt)"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: $case_name"
