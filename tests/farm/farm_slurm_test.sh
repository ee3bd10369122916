#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx farm` against a real single-node Slurm (munge + slurmctld + slurmd, started here with this
# folder's copy of start-local-slurm.sh, at Slurm's default DependencyParameters, and stopped at the
# end, also on failure). Checks that a sharded run equals one run (FFV1: frames, count, rate, audio
# packets; H.264: count, >= 40 dB per frame, audio duration; --animate drift and superifs), that a
# cancelled shard leaves no output and resume finishes it, that a join which can never run does not
# keep --wait waiting, that farm texture equals texture --frames, and that bad input is refused in
# one line with nothing submitted.
#   farm_slurm_test.sh IFSFX WORKDIR
set -uo pipefail
IFSFX=$1
W=$2
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[ "$(id -u)" -eq 0 ] || { echo "SKIP: starting Slurm needs root"; exit 77; }
command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null || { echo "SKIP: no ffmpeg"; exit 77; }
rm -rf "$W" && mkdir -p "$W" && cd "$W" || exit 1

cleanup() { "$HERE/stop-local-slurm.sh" >"$W/stop.log" 2>&1; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; [ -n "$(squeue -h 2>/dev/null)" ] && squeue; exit 1; }
ok() { echo "ok   $*"; }
SECONDS=0
# Slurm's own default for jobs whose dependency fails (they pend), as most clusters run it.
SLURM_LOCAL_KILL_INVALID_DEPEND=0 "$HERE/start-local-slurm.sh" >"$W/start.log" 2>&1 || { cat "$W/start.log"; fail "Slurm did not start"; }
ok "Slurm up (${SECONDS} s)"

# Clips: H.264 with B-frames and AAC audio. A: tiny, for exact checks; B: 320x240, for PSNR.
clip() { ffmpeg -v error -y -f lavfi -i "testsrc2=size=$2:rate=25" -f lavfi \
  -i sine=frequency=440:sample_rate=48000 -frames:v "$3" -shortest -c:v libx264 -bf 3 -g 12 \
  -pix_fmt yuv420p -c:a aac "$1" </dev/null || fail "ffmpeg cannot make $1"; }
clip "$W/a.mp4" 160x96 60
clip "$W/b.mp4" 320x240 50
clip "$W/c.mp4" 320x240 160

frames_of() { ffmpeg -v error -i "$1" -map 0:v -f framemd5 - | grep -v '^#' | awk -F', *' '{print $6}'; }
audio_of() { ffprobe -v error -select_streams a -show_packets -show_data_hash md5 \
  -show_entries packet=pts,dts,duration,size,data_hash -of csv "$1"; }
probe() { ffprobe -v error -select_streams "$2" -show_entries "stream=$3" -of default=nw=1:nk=1 "$1"; }
farm() { "$IFSFX" farm filter "$@" --cpus-per-task=1 --submit --wait -q; }
single() { "$IFSFX" filter "$@" -q; }

# Sharded and single FFV1 runs decode to the same frames, with the same rate and audio packets.
same_as_single() {  # NAME INPUT OUTPUT-EXT SHARDS OPTIONS...
  local name=$1 in=$2 ext=$3 k=$4; shift 4
  farm "$in" -o "$W/$name-farm.$ext" --shards "$k" "$@" >"$W/$name.farm.out" 2>&1 ||
    { cat "$W/$name.farm.out"; fail "$name: farm filter failed"; }
  single "$in" -o "$W/$name-single.$ext" "$@" || fail "$name: filter failed"
  frames_of "$W/$name-single.$ext" >"$W/$name-single.frames"
  frames_of "$W/$name-farm.$ext" >"$W/$name-farm.frames"
  [ -s "$W/$name-single.frames" ] || fail "$name: no frames"
  cmp -s "$W/$name-single.frames" "$W/$name-farm.frames" ||
    fail "$name: decoded frames differ ($(wc -l <"$W/$name-single.frames") vs $(wc -l <"$W/$name-farm.frames"))"
}

same_as_single ffv1 "$W/a.mp4" mkv 4 --codec ffv1
[ "$(probe "$W/ffv1-farm.mkv" v r_frame_rate)" = "$(probe "$W/ffv1-single.mkv" v r_frame_rate)" ] ||
  fail "ffv1: frame rates differ"
audio_of "$W/ffv1-single.mkv" >"$W/ffv1-single.audio"
audio_of "$W/ffv1-farm.mkv" >"$W/ffv1-farm.audio"
[ -s "$W/ffv1-single.audio" ] && cmp -s "$W/ffv1-single.audio" "$W/ffv1-farm.audio" ||
  fail "ffv1: audio packets differ"
# The join writes under the output policy: no temporary file (.NAME.XXXXXXXX.ifsfx-tmp) is left.
ls -A "$W" | grep -q 'ifsfx-tmp$' && fail "ffv1: temporary file left: $(ls -A "$W" | grep 'ifsfx-tmp$')"
ok "FFV1, K=4: $(wc -l <"$W/ffv1-farm.frames") frames equal, rate $(probe "$W/ffv1-farm.mkv" v r_frame_rate), $(wc -l <"$W/ffv1-farm.audio") audio packets identical (${SECONDS} s)"

# H.264 (each segment encoded on its own): same count, every frame >= 40 dB, audio in sync.
farm "$W/b.mp4" -o "$W/h264-farm.mp4" --shards 3 >"$W/h264.farm.out" 2>&1 ||
  { cat "$W/h264.farm.out"; fail "h264: farm filter failed"; }
single "$W/b.mp4" -o "$W/h264-single.mp4" || fail "h264: filter failed"
n_single=$(probe "$W/h264-single.mp4" v nb_frames)
n_farm=$(probe "$W/h264-farm.mp4" v nb_frames)
[ "$n_single" = "$n_farm" ] && [ "$n_farm" -gt 0 ] || fail "h264: $n_farm frames, single run $n_single"
ffmpeg -v error -i "$W/h264-single.mp4" -i "$W/h264-farm.mp4" \
  -lavfi "psnr=stats_file=$W/h264.psnr" -f null - || fail "h264: psnr failed"
worst=$(sed -E 's/.*psnr_avg:([^ ]+).*/\1/' "$W/h264.psnr" | sort -g | head -1)
[ "$(wc -l <"$W/h264.psnr")" = "$n_single" ] || fail "h264: psnr compared $(wc -l <"$W/h264.psnr") frames"
awk -v w="$worst" 'BEGIN { exit !(w == "inf" || w + 0 >= 40) }' || fail "h264: a frame at $worst dB"
a_single=$(probe "$W/h264-single.mp4" a duration)
a_farm=$(probe "$W/h264-farm.mp4" a duration)
awk -v a="$a_single" -v b="$a_farm" 'BEGIN { d = a - b; exit !(a > 0 && d < 0.04 && d > -0.04) }' ||
  fail "h264: audio lasts $a_farm s, single run $a_single s"
ok "H.264, K=3: $n_farm frames, worst frame $worst dB, audio $a_farm s vs $a_single s (${SECONDS} s)"

# Animations: shards that start between two keyframes build the same maps.
same_as_single drift "$W/a.mp4" mkv 3 --codec ffv1 --animate drift --keyframe-interval 7
ok "--animate drift, K=3: frames equal (${SECONDS} s)"
same_as_single superifs "$W/a.mp4" mkv 3 --codec ffv1 --animate superifs --keyframe-interval 7
ok "--animate superifs, K=3: frames equal (${SECONDS} s)"

# A shard cancelled while it runs: --wait fails naming it, the join never runs, no output; resume
# submits that shard and the join, and the result equals one run. A shard takes about a second, so
# the scancel can land just after shard 1 finished (squeue may still say RUNNING): Slurm then
# cancels the join all the same (--wait must say that every shard's frames are done and that
# resume runs the join: the case CI met once), or lets it run (the result must equal one run).
# Such a try is checked as that and the case is run again, up to four times. The cluster runs
# without kill_invalid_depend, Slurm's default: the join is ended by its own --kill-on-invalid-dep,
# not by the cluster's settings.
single "$W/c.mp4" -o "$W/cancel-single.mkv" --codec ffv1 --animate superifs --keyframe-interval 5 ||
  fail "cancel: single run failed"
same_as_cancel_single() {  # OUTPUT WHAT
  cmp -s <(frames_of "$W/cancel-single.mkv") <(frames_of "$1") || fail "$2: frames differ from one run"
  cmp -s <(audio_of "$W/cancel-single.mkv") <(audio_of "$1") || fail "$2: audio differs from one run"
}
cancelled_while_running=""
for try in 1 2 3 4; do
  out="$W/cancel-$try.mkv"
  "$IFSFX" farm filter "$W/c.mp4" -o "$out" --shards 4 --cpus-per-task=1 --codec ffv1 \
    --animate superifs --keyframe-interval 5 --submit --wait -q >"$W/cancel.out" 2>"$W/cancel.err" &
  waiter=$!
  array=""
  for _ in $(seq 300); do
    array=$(sed -n 's/^array //p' "$out.farm/jobs.txt" 2>/dev/null)
    [ -n "$array" ] && [ "$(squeue -h -r -j "$array" -o '%i %T' 2>/dev/null | grep -c "^${array}_1 RUNNING")" = 1 ] && break
    sleep 0.1
  done
  [ -n "$array" ] || fail "cancel: no array job submitted"
  scancel "${array}_1" || fail "cancel: scancel ${array}_1 failed"
  # Bounded: a join left pending for ever would hang here.
  for _ in $(seq 600); do kill -0 "$waiter" 2>/dev/null || break; sleep 0.1; done
  kill -0 "$waiter" 2>/dev/null && { kill "$waiter"; fail "cancel: --wait still waits 60 s after the scancel: $(squeue)"; }
  wait "$waiter"
  rc=$?
  for _ in $(seq 100); do [ -z "$(squeue -h)" ] && break; sleep 0.2; done
  [ -z "$(squeue -h)" ] || fail "cancel: jobs left in the queue"
  if [ "$rc" = 0 ] && [ -e "$out.farm/done/shard-0001" ]; then
    # The scancel came after shard 1 had completed and Slurm let the join run.
    same_as_cancel_single "$out" "cancel too late"
    ok "try $try: shard 1 had finished when scancel came; the join ran, result equals one run"
    continue
  fi
  [ "$rc" != 0 ] || fail "cancel: farm filter --wait returned 0 after a shard was cancelled"
  [ -e "$out" ] && fail "cancel: $out written although a shard was cancelled"
  [ -e "$out.farm/logs/join.log" ] && fail "cancel: the join ran: $(cat "$out.farm/logs/join.log")"
  if [ -e "$out.farm/done/shard-0001" ]; then
    grep -q "^ifsfx: farm: every shard's frames are done, but the join .* was cancelled before it ran (DependencyNeverSatisfied: .*); no output; \`ifsfx farm resume $out.farm\` runs the join$" "$W/cancel.err" ||
      fail "cancel after shard 1 finished: --wait says: $(cat "$W/cancel.err")"
    "$IFSFX" farm resume "$out.farm" --wait >"$W/resume.out" 2>&1 || { cat "$W/resume.out"; fail "resume (join only) failed"; }
    grep -q "resubmitting 0 of 4 shards" "$W/resume.out" || fail "resume (join only): $(cat "$W/resume.out")"
    same_as_cancel_single "$out" "resume (join only)"
    ok "try $try: shard 1 had finished when scancel came; --wait: every shard's frames done, resume ran the join alone, result equals one run (${SECONDS} s)"
    continue
  fi
  grep -q "shard 1" "$W/cancel.err" || fail "cancel: --wait did not name shard 1: $(cat "$W/cancel.err")"
  "$IFSFX" farm status "$out.farm" >"$W/cancel.status" || fail "cancel: status failed"
  grep -q "^shard 1 .*failed, see $out.farm/logs/shard-0001.log" "$W/cancel.status" ||
    fail "cancel: status does not name shard 1's log: $(cat "$W/cancel.status")"
  ok "try $try: scancel of shard 1 (job ${array}_1): --wait rc $rc, join not run, no output; status: $(grep '^shard 1' "$W/cancel.status")"
  "$IFSFX" farm resume "$out.farm" --wait >"$W/resume.out" 2>&1 || { cat "$W/resume.out"; fail "resume failed"; }
  grep -q "resubmitting 1 of 4 shards" "$W/resume.out" || fail "resume: $(cat "$W/resume.out")"
  same_as_cancel_single "$out" "resume"
  ok "resume: 1 shard and the join resubmitted, result equals one run (${SECONDS} s)"
  cancelled_while_running=yes
  break
done
[ -n "$cancelled_while_running" ] || fail "cancel: shard 1 had finished before each of 4 scancels"

# A job folder whose join.sh lacks --kill-on-invalid-dep (planned by an older ifsfx, or edited):
# on a cluster without kill_invalid_depend its join pends for ever once a shard fails. --wait must
# still end, naming the shards, and take the join out of the queue; resume then finishes the job.
cp "$W/a.mp4" "$W/gone.mp4"
"$IFSFX" farm filter "$W/gone.mp4" -o "$W/gone.mkv" --shards 3 --cpus-per-task=1 --codec ffv1 -q \
  >"$W/gone.out" 2>&1 || { cat "$W/gone.out"; fail "pending join: planning failed"; }
sed -i '/--kill-on-invalid-dep/d' "$W/gone.mkv.farm/join.sh"
mv "$W/gone.mp4" "$W/gone-away.mp4"
timeout 60 "$IFSFX" farm resume "$W/gone.mkv.farm" --wait >"$W/gone.out" 2>"$W/gone.err"
rc=$?
[ "$rc" = 124 ] && fail "pending join: --wait did not end in 60 s: $(squeue)"
[ "$rc" != 0 ] || fail "pending join: --wait returned 0 although every shard failed"
grep -q "^ifsfx: farm: shard 0 (.*), shard 1 (.*), shard 2 (.*) failed; the join did not run, no output" "$W/gone.err" ||
  fail "pending join: --wait says: $(cat "$W/gone.err")"
[ -z "$(squeue -h)" ] || fail "pending join: left in the queue: $(squeue)"
# Without --wait the join stays behind, pending for ever; the next resume takes it out first.
"$IFSFX" farm resume "$W/gone.mkv.farm" >"$W/gone.out" 2>&1 || { cat "$W/gone.out"; fail "pending join: resume failed"; }
for _ in $(seq 150); do squeue -h -o '%j %r' | grep -q "^ifsfx-join DependencyNeverSatisfied$" && break; sleep 0.2; done
squeue -h -o '%j %r' | grep -q "^ifsfx-join DependencyNeverSatisfied$" || fail "pending join: not pending: $(squeue)"
"$IFSFX" farm status "$W/gone.mkv.farm" | grep -q "; join PENDING, never to run (\`ifsfx farm resume\` cancels it); output not written$" ||
  fail "pending join: status says: $("$IFSFX" farm status "$W/gone.mkv.farm")"
mv "$W/gone-away.mp4" "$W/gone.mp4"
"$IFSFX" farm resume "$W/gone.mkv.farm" --wait >"$W/gone.out" 2>&1 || { cat "$W/gone.out"; fail "pending join: resume failed"; }
[ -z "$(squeue -h)" ] || fail "pending join: the old join is still in the queue: $(squeue)"
single "$W/gone.mp4" -o "$W/gone-single.mkv" --codec ffv1 || fail "pending join: single run failed"
cmp -s <(frames_of "$W/gone-single.mkv") <(frames_of "$W/gone.mkv") || fail "pending join: frames differ from one run"
ok "a join pending for ever (no --kill-on-invalid-dep): --wait rc $rc names the 3 shards and cancels it; resume cancels one left behind and finishes (${SECONDS} s)"

# farm texture: the same files as texture --frames.
mkdir -p "$W/tex-farm" "$W/tex-single"
"$IFSFX" farm texture paper-fig4 --frames 7 -o "$W/tex-farm/t_%03d.png" --shards 3 --size 64x64 \
  --crossfade 2 --cpus-per-task=1 --submit --wait >"$W/tex.out" 2>&1 || { cat "$W/tex.out"; fail "farm texture failed"; }
"$IFSFX" texture paper-fig4 --frames 7 -o "$W/tex-single/t_%03d.png" --size 64x64 --crossfade 2 -q ||
  fail "texture failed"
(cd "$W/tex-single" && md5sum t_*.png) >"$W/tex-single.md5"
(cd "$W/tex-farm" && md5sum t_*.png) >"$W/tex-farm.md5"
[ "$(wc -l <"$W/tex-single.md5")" = 7 ] && cmp -s "$W/tex-single.md5" "$W/tex-farm.md5" ||
  fail "farm texture files differ from texture --frames"
ok "farm texture, K=3: 7 files identical (${SECONDS} s)"

# farm texture of a seamless loop (docs/loops.md, docs/seamless.md): every shard closes the same
# loop on the same torus, so the files are the single run's (two periods across each), and frame 8
# is frame 0 again.
mkdir -p "$W/loop-farm" "$W/loop-single"
loop=(--frames 9 --loop 8 --size 48x48 --crossfade 2 --mode tops --seed 5 --seamless --tiles 2x1)
"$IFSFX" farm texture carpet-lace "${loop[@]}" -o "$W/loop-farm/t_%03d.png" --shards 2 \
  --cpus-per-task=1 --submit --wait >"$W/loop.out" 2>&1 || { cat "$W/loop.out"; fail "farm texture --loop failed"; }
"$IFSFX" texture carpet-lace "${loop[@]}" -o "$W/loop-single/t_%03d.png" -q || fail "texture --loop failed"
(cd "$W/loop-single" && md5sum t_*.png) >"$W/loop-single.md5"
(cd "$W/loop-farm" && md5sum t_*.png) >"$W/loop-farm.md5"
[ "$(wc -l <"$W/loop-single.md5")" = 9 ] && cmp -s "$W/loop-single.md5" "$W/loop-farm.md5" ||
  fail "farm texture --loop files differ from texture --loop"
cmp -s "$W/loop-farm/t_001.png" "$W/loop-farm/t_009.png" || fail "farm texture --loop: frame 8 is not frame 0"
oiiotool --info "$W/loop-farm/t_001.png" | grep -q " 96 x   48," || fail "farm texture --seamless --tiles 2x1: not 96x48"
ok "farm texture --seamless --tiles 2x1 --loop 8, K=2: 9 files identical, frame 8 = frame 0 (${SECONDS} s)"

# Bad input: one line on stderr, a non-zero exit, no job folder, nothing in the queue.
refused() {  # EXPECTED-TEXT ARGS...
  local want=$1; shift
  rm -rf "$W/bad.mkv.farm"
  "$IFSFX" farm filter "$@" --submit >"$W/bad.out" 2>"$W/bad.err"
  local rc=$?
  [ "$rc" != 0 ] || fail "bad input accepted: $*"
  [ "$(wc -l <"$W/bad.err")" = 1 ] && grep -q "^ifsfx: .*$want" "$W/bad.err" ||
    fail "bad input '$*': expected one line with '$want', got: $(cat "$W/bad.err")"
  [ -z "$(squeue -h)" ] || fail "bad input '$*': something was submitted"
  [ -e "$W/bad.mkv.farm" ] && fail "bad input '$*': a job folder was written"
  ok "refused ($rc): $(cat "$W/bad.err")"
}
refused "no such file" "$W/missing.mp4" -o "$W/bad.mkv" --shards 2
refused "must be an absolute path" "$W/a.mp4" -o bad.mkv --shards 2
refused "must be an absolute path" a.mp4 -o "$W/bad.mkv" --shards 2
refused "at least 1" "$W/a.mp4" -o "$W/bad.mkv" --shards 0
refused "more shards than frames" "$W/a.mp4" -o "$W/bad.mkv" --shards 61
# The output policy, before anything is planned: OUTPUT is never the input (here through a link).
ln -sf "$W/a.mp4" "$W/bad.mkv"
refused "is the same file as the input" "$W/a.mp4" -o "$W/bad.mkv" --shards 2
rm -f "$W/bad.mkv"
# farm texture's count is read whole, as each shard's `texture --frames` will read it.
for count in 7x 1e3; do
  rm -rf "$W/badtex_.farm"
  if "$IFSFX" farm texture paper-fig4 --frames $count -o "$W/badtex_%04d.png" --shards 2 --submit \
    >"$W/bad.out" 2>"$W/bad.err"; then fail "farm texture --frames $count accepted"; fi
  grep -q "^ifsfx: --frames: the number of textures, at least 1 (got '$count')$" "$W/bad.err" ||
    fail "farm texture --frames $count: $(cat "$W/bad.err")"
  [ -z "$(squeue -h)" ] && [ ! -e "$W/badtex_.farm" ] || fail "farm texture --frames $count: submitted"
  ok "refused: $(cat "$W/bad.err")"
done
# The texture options handed on to every shard are checked as `ifsfx texture` checks them, before
# anything is planned or submitted (they used to fail in every shard, after submitting).
printf 'not an image' >"$W/not-an-image.png"
tex_refused() {  # expected-message options...
  local want=$1
  shift
  rm -rf "$W/badtex_.farm"
  if "$IFSFX" farm texture paper-fig4 --frames 4 -o "$W/badtex_%04d.png" --shards 2 --submit "$@" \
    >"$W/bad.out" 2>"$W/bad.err"; then fail "farm texture $* accepted"; fi
  [ "$(wc -l <"$W/bad.err")" = 1 ] && grep -q "^ifsfx: .*$want" "$W/bad.err" ||
    fail "farm texture $*: expected one line with '$want', got: $(cat "$W/bad.err")"
  [ -z "$(squeue -h)" ] && [ ! -e "$W/badtex_.farm" ] || fail "farm texture $*: submitted"
  ok "refused: $(cat "$W/bad.err")"
}
tex_refused "--size: expected WxH (got '10x')" --size 10x
tex_refused "--mode: must be one of" --mode sepia
tex_refused "--buffer: must be 1..3 for V = 3 (got 4)" --buffer 4
tex_refused "--source: steal mode needs a source image" --mode steal
tex_refused "--source: must be an absolute path" --mode steal --source photo.png
tex_refused "no such file" --mode steal --source "$W/missing.png"
tex_refused "cannot read as an image" --mode steal --source "$W/not-an-image.png"
tex_refused "not expected" --sparkle 3
echo "ALL OK (${SECONDS} s)"
