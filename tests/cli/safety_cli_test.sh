#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of issue 12 on the real binary: never lose a user's file, never hang, stop on
# a signal, refuse absurd numbers with one line naming the option. One CHECK per run.
#   safety_cli_test.sh IFSFX WORKDIR CHECK
set -euo pipefail
ifsfx=$(realpath "$1") work=$2 check=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }

# run_expect CODE "fragment" args...: exit code CODE (or "nonzero"), exactly one line on stderr
# that starts with "ifsfx:" and contains the fragment.
run_expect() {
  local code=$1 fragment=$2 rc=0
  shift 2
  "$ifsfx" "$@" >out.txt 2>err.txt || rc=$?
  if [[ $code == nonzero ]]; then
    [[ $rc -ne 0 ]] || fail "'$*' succeeded"
  else
    [[ $rc -eq $code ]] || fail "'$*' exited $rc, expected $code: $(cat err.txt)"
  fi
  [[ $(wc -l <err.txt) -eq 1 ]] || fail "'$*' printed $(wc -l <err.txt) lines on stderr: $(cat err.txt)"
  grep -q '^ifsfx: ' err.txt || fail "'$*': error does not start with 'ifsfx:': $(cat err.txt)"
  grep -qF -- "$fragment" err.txt || fail "'$*': error '$(cat err.txt)' lacks '$fragment'"
  rm -f out.txt err.txt
}

# The folder's files (hidden ones included), one per line, sorted: temporaries show up here.
listing() { ls -A | grep -v -e '^out.txt$' -e '^err.txt$' -e '^last-err.txt$' | sort; }

# same_bytes FILE SUM: the file still has the checksum it had.
same_bytes() { [[ $(md5sum <"$1") == "$2" ]] || fail "$1 was changed"; }

# stop_during SIGNAL CODE DELAY args...: starts ifsfx, sends SIGNAL after DELAY seconds (the
# command must still be in its long phase then), and checks that it exits with CODE within
# IFSFX_STOP_BOUND_MS (2 s by default: the target is 0.5 s, the bound is generous for a loaded
# machine) with one line on stderr. Prints the time it took.
stop_bound_ms=${IFSFX_STOP_BOUND_MS:-2000}

# Waits (up to 30 s) until process PID catches SIGINT and SIGTERM: before its handlers are in, a
# background job of a script ignores SIGINT, and a loaded machine may take seconds to get there.
wait_for_handlers() {
  local mask
  for _ in $(seq 600); do
    mask=$(sed -n 's/^SigCgt:\s*//p' "/proc/$1/status" 2>/dev/null || true)
    [[ -n $mask ]] && (((16#$mask & 16#4002) == 16#4002)) && return 0
    sleep 0.05
  done
  fail "process $1 never caught SIGINT and SIGTERM"
}
stop_during() {
  local signal=$1 code=$2 delay=$3
  shift 3
  "$ifsfx" "$@" >out.txt 2>err.txt &
  local pid=$!
  wait_for_handlers "$pid"
  sleep "$delay"
  kill -0 "$pid" 2>/dev/null || fail "'$*' ended before the signal: $(cat err.txt)"
  stop_now "$signal" "$code" "$pid" "$*"
}
# stop_now SIGNAL CODE PID WHAT: sends SIGNAL to the running PID, checks its exit code, the time it
# took and its one line (kept in last-err.txt).
stop_now() {
  local signal=$1 code=$2 pid=$3 what=$4 rc=0 start
  start=$(date +%s%N)
  kill -s "$signal" "$pid"
  wait "$pid" || rc=$?
  local ms=$((($(date +%s%N) - start) / 1000000))
  echo "$signal during '$what': exit $rc after $ms ms: $(cat err.txt)"
  [[ $rc -eq $code ]] || fail "'$what' exited $rc after $signal, expected $code: $(cat err.txt)"
  ((ms < stop_bound_ms)) || fail "'$what' took $ms ms to stop after $signal"
  [[ $(wc -l <err.txt) -eq 1 ]] || fail "'$what' printed $(wc -l <err.txt) lines: $(cat err.txt)"
  mv err.txt last-err.txt
  rm -f out.txt
}
# stop_in_phase PHASE EARLIER SIGNAL CODE OUTPUTS args...: stop_during with the delay searched
# until the signal lands in PHASE ("ifsfx: PHASE: interrupted"): twice as late while it stopped
# the EARLIER phase, halfway back when it stopped a later one or the run had ended. Which phase a
# fixed delay hits depends on the machine: an exact steal map starts with a chaos game (its
# attractor mask), which a signal at 1.5 s always hit here, and which takes over 12 s under ASan
# at 6000x6000. OUTPUTS (the files the command writes, absent before) must still be absent after
# a stop in PHASE or before it; after a later stop or an end they are removed.
stop_in_phase() {
  local phase=$1 earlier=$2 signal=$3 code=$4 outputs=$5 early=0 late=0 delay=1 pid f
  shift 5
  for _ in $(seq 12); do
    "$ifsfx" "$@" >out.txt 2>err.txt &
    pid=$!
    wait_for_handlers "$pid"
    sleep "$delay"
    if kill -0 "$pid" 2>/dev/null; then
      stop_now "$signal" "$code" "$pid" "$*"
      if grep -qx -e "ifsfx: $phase: interrupted" -e "ifsfx: $earlier: interrupted" last-err.txt; then
        for f in $outputs; do [[ ! -e $f ]] || fail "'$*' left $f after $signal"; done
        grep -qx "ifsfx: $phase: interrupted" last-err.txt && return 0
        early=$delay
      else
        late=$delay
      fi
    else
      wait "$pid" || fail "'$*' failed: $(cat err.txt)"
      echo "'$*' ended before a signal at $delay s"
      late=$delay
    fi
    # shellcheck disable=SC2086
    rm -f $outputs out.txt err.txt
    delay=$(awk -v e="$early" -v l="$late" 'BEGIN { print (l > 0 ? (e + l) / 2 : 2 * e) }')
  done
  fail "'$*': no signal landed in the $phase phase: $(cat last-err.txt)"
}

# A small photo (a white square on black, also a shape to fit), an image sequence, a movie.
photo() { "$ifsfx" render square-tiling-4 --mode attractor --size 64x64 --view -0.5,-0.5,1.5,1.5 -q -o "$1"; }
sequence() {  # sequence PREFIX COUNT FIRST: PREFIX_%04d.png from FIRST
  for ((i = $3; i < $3 + $2; ++i)); do
    ffmpeg -v error -y -f lavfi -i "testsrc=size=64x48:rate=1" -frames:v 1 "$(printf '%s_%04d.png' "$1" "$i")"
  done
}
movie() { ffmpeg -v error -y -f lavfi -i "testsrc=size=96x64:rate=25" -frames:v "$2" -c:v mpeg4 -q:v 2 "$1"; }

case "$check" in
  input_is_never_the_output)
    # Every case of the issue's "Data loss" paragraph, and more spellings of the same file: each
    # refused with exit 2 before any work, the input untouched, no file left.
    photo P.png
    photo P.tif
    "$ifsfx" render barnsley-fern --mode steal --source P.png --size 32x32 -q -o map-source.png \
      --save-map M.map
    ln P.png hard.png
    ln -s P.png soft.png
    mkdir sub
    before=$(listing)
    sum_png=$(md5sum <P.png) sum_tif=$(md5sum <P.tif) sum_map=$(md5sum <M.map)
    same="is the same file as the input"
    run_expect 2 "P.png: $same P.png" render barnsley-fern --mode steal --source P.png -o P.png
    run_expect 2 "./P.png: $same P.png" render barnsley-fern --mode steal --source P.png -o ./P.png
    run_expect 2 "hard.png: $same P.png" render barnsley-fern --mode steal --source P.png -o hard.png
    run_expect 2 "soft.png: $same P.png" render barnsley-fern --mode steal --source P.png -o soft.png
    run_expect 2 "sub/../P.png: $same P.png" render barnsley-fern --mode steal --source P.png -o sub/../P.png
    run_expect 2 "P.png: $same P.png" render barnsley-fern --mode steal --source P.png -o x.png --save-map P.png
    run_expect 2 "--save-map ./x.png: must differ from -o" render barnsley-fern --mode steal --source P.png -o x.png --save-map ./x.png
    run_expect 2 "P.tif: $same P.tif" apply M.map P.tif -o P.tif
    ln M.map map-link.png
    run_expect 2 "map-link.png: $same M.map" apply M.map P.tif -o map-link.png
    run_expect 2 "P.png: $same P.png" fit P.png -o fit.toml --preview P.png
    echo "an earlier preset" >fit.toml
    ln fit.toml fit-link.png
    run_expect 2 "--preview fit-link.png: must differ from -o" fit P.png -o fit.toml --preview fit-link.png
    printf 'name = "mine"\nmaps = [[0.5,0,0,0.5,0,0],[0.5,0,0,0.5,0.5,0],[0.5,0,0,0.5,0,0.5]]\n' >mine.toml
    sum_toml=$(md5sum <mine.toml)
    run_expect 2 "mine.toml: $same mine.toml" render mine.toml --mode steal --source P.png -o x.png --save-map mine.toml
    run_expect 2 "mine.toml: $same ./mine.toml" render barnsley-fern --mode steal --source P.png --colouring ./mine.toml -o x.png --save-map mine.toml
    same_bytes P.png "$sum_png"
    same_bytes P.tif "$sum_tif"
    same_bytes M.map "$sum_map"
    same_bytes mine.toml "$sum_toml"
    [[ $(listing) == $(printf '%s\nmine.toml\nfit.toml\nfit-link.png\nmap-link.png' "$before" | sort) ]] ||
      fail "files left: $(listing)"
    ;;
  sequence_output_over_its_input)
    # A filter from an image sequence into the same pattern, written differently, and into a
    # pattern whose later frames are inputs; texture frames over the source image.
    sequence in 5 1
    sums=$(md5sum in_*.png)
    run_expect 2 "in_0001.png: is the same file as the input in_0001.png" filter 'in_%04d.png' -o './in_%04d.png'
    run_expect 2 "is the same file as the input" filter 'in_%04d.png' -o "$PWD/in_%04d.png"
    run_expect 2 "in_0001.png: is the same file as the input in_0001.png" filter 'in_%04d.png' -o 'in_%04d.png' --frames 3:4
    ln -s . same
    run_expect 2 "is the same file as the input" filter 'in_%04d.png' -o 'same/in_%04d.png'
    cp in_0003.png src.png
    ln src.png tex_0002.png
    run_expect 2 "tex_0002.png: is the same file as the input src.png" texture paper-fig4 --size 32x32 --mode steal --source src.png --frames 3 -o 'tex_%04d.png'
    [[ $(md5sum in_*.png) == "$sums" ]] || fail "an input frame was changed"
    [[ $(listing | tr '\n' ' ') == "in_0001.png in_0002.png in_0003.png in_0004.png in_0005.png same src.png tex_0002.png " ]] ||
      fail "files left: $(listing)"
    # A sequence into another pattern works, and numbers from 0.
    "$ifsfx" filter 'in_%04d.png' -o 'out_%03d.png' --quality 4 -q
    [[ $(ls out_*.png | tr '\n' ' ') == "out_000.png out_001.png out_002.png out_003.png out_004.png " ]] ||
      fail "sequence output: $(ls out_*)"
    ;;
  unrelated_part_files_survive)
    # Fixed temporary names (OUT.part, MAP.part) are gone: files of those names are someone
    # else's and stay as they are, through every writer.
    photo P.png
    movie in.avi 10
    for f in out.png.part out.png.tmp map.part map.map.part clip.mp4.part fit.toml.tmp fit.toml.part; do
      echo "someone else's $f" >"$f"
    done
    sums=$(md5sum ./*.part ./*.tmp)
    "$ifsfx" render barnsley-fern --mode steal --source P.png --size 32x32 -q -o out.png --save-map map.map
    "$ifsfx" render barnsley-fern --mode steal --source P.png --size 32x32 -q -o out.png --save-map map
    "$ifsfx" filter in.avi -o clip.mp4 --quality 4 -q
    "$ifsfx" fit P.png --invert -n 4 --size 32 --max-evaluations 300 -o fit.toml >/dev/null
    [[ $(md5sum ./*.part ./*.tmp) == "$sums" ]] || fail "a .part or .tmp file was overwritten"
    [[ -s out.png && -s map.map && -s map && -s clip.mp4 && -s fit.toml ]] || fail "outputs missing: $(listing)"
    [[ -z $(listing | grep -e '^\.' || true) ]] || fail "temporary left: $(listing)"
    ;;
  failing_run_keeps_the_good_output)
    # A run that fails mid-stream (a truncated movie) over an existing good output: the output is
    # untouched; the frames done are a playable OUT.partial.mp4, named on stderr.
    movie whole.avi 40
    head -c $(($(stat -c %s whole.avi) / 2)) whole.avi >cut.avi
    "$ifsfx" filter whole.avi -o out.mp4 --quality 4 -q
    good=$(md5sum <out.mp4)
    echo "an earlier partial" >out.partial.mp4
    "$ifsfx" filter cut.avi -o out.mp4 --quality 4 -q 2>err.txt && fail "truncated input succeeded"
    grep -Eq '^ifsfx: cut.avi: truncated or corrupt: .*; [0-9]+ frames kept in out.partial-2.mp4$' err.txt ||
      fail "partial not named: $(cat err.txt)"
    same_bytes out.mp4 "$good"
    [[ $(cat out.partial.mp4) == "an earlier partial" ]] || fail "an existing partial was replaced"
    frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 out.partial-2.mp4)
    ((frames > 5 && frames < 40)) || fail "partial movie holds $frames frames"
    same_bytes out.mp4 "$good"
    # A still output over an existing folder: the real reason, not "(Success)".
    mkdir dir.png
    run_expect 1 "dir.png: cannot write: it is a folder" render barnsley-fern --size 16x16 -o dir.png
    # An image sequence output of a failed run leaves the existing frames as they were.
    "$ifsfx" filter whole.avi -o 'seq_%02d.png' --quality 4 --size 32x24 -q
    seqsum=$(md5sum seq_*.png)
    run_expect 1 "cut.avi" filter cut.avi -o 'seq_%02d.png' --quality 4 --size 32x24 --seed 9
    [[ $(md5sum seq_*.png) == "$seqsum" ]] || fail "a failed run changed the sequence's frames"
    [[ -z $(listing | grep -e '^\.' || true) ]] || fail "temporary left: $(listing)"
    ;;
  signals_stop_every_long_phase)
    # Real signals to the real binary during each long computation: exit 130 (SIGINT) or 143
    # (SIGTERM) within the bound, no temporary left, an existing output untouched.
    photo P.png
    movie in.avi 50
    movie long.avi 3000
    "$ifsfx" render barnsley-fern --size 16x16 -q -o out.png
    "$ifsfx" filter in.avi -o out.mp4 --quality 4 -q
    echo "good preset" >f.toml
    sums=$(md5sum out.png out.mp4 f.toml)
    before=$(listing)
    # The exact descent (and its attractor mask) of a big still.
    stop_in_phase "exact descent" "chaos game" INT 130 "phase.png phase.map" render barnsley-fern --mode steal --exact --source P.png --size 3000x3000 -o phase.png --save-map phase.map
    # The chaos game of a measure render.
    stop_during TERM 143 1.5 render barnsley-fern --size 3000x3000 --quality 20000 -o out.png
    # The chaos-game steal map of `filter` before the first frame (once ignored for minutes).
    stop_during TERM 143 1.5 filter in.avi --size 8000x8000 --quality 2000 -o out.mp4
    # The exact steal map of `filter`.
    # (A signal that lands later, while frames are written, keeps them in phase.partial.mp4: a slow
    # build, the sanitizers', can get there before the delay is bisected down.)
    stop_in_phase "exact descent" "chaos game" INT 130 "phase.mp4 phase.partial.mp4" filter in.avi --size 4000x4000 --exact -q -o phase.mp4
    # The filter's animations, through the one fractal engine: a drift keyframe built on a worker
    # thread while the first frame waits for it, and the superIFS burn-in before any frame.
    stop_during INT 130 1.5 filter in.avi --size 3000x3000 --quality 20000 --animate drift --view -3,-1,3,11 -q -o out.mp4
    stop_during TERM 143 1.5 filter in.avi --size 4096x4096 --animate superifs --buffers 6 -q -o out.mp4
    # SuperIFS burn-in, and the texture steps.
    stop_during INT 130 1.5 texture paper-fig4 --size 4096x4096 -V 6 --steps 10000 -o out.png
    stop_during TERM 143 1.5 texture carpet-lace --mode steal --source P.png --size 2048x2048 --frames 400 -o 'out_%03d.png'
    # A collage fit.
    stop_during TERM 143 1.5 fit P.png --invert -n 12 --max-seconds 0 --max-evaluations 100000000 -o f.toml --preview f.png
    # A double Ctrl-C (a second signal within the grace period) still ends cleanly: here while
    # the movie's temporary file exists, during the steal map.
    "$ifsfx" filter in.avi --size 8000x8000 --exact -o out.mp4 2>err.txt &
    pid=$!
    wait_for_handlers "$pid"
    sleep 1.5
    kill -INT "$pid"
    sleep 0.05
    kill -INT "$pid" 2>/dev/null || true
    rc=0 && wait "$pid" || rc=$?
    [[ $rc -eq 130 ]] || fail "double Ctrl-C: exit $rc: $(cat err.txt)"
    grep -q '^ifsfx: ' err.txt || fail "double Ctrl-C killed the process: $(cat err.txt)"
    rm -f err.txt
    [[ $(md5sum out.png out.mp4 f.toml) == "$sums" ]] || fail "an existing output was changed"
    [[ $(listing) == "$before" ]] || fail "files left: $(diff <(echo "$before") <(listing))"
    # While frames are written: the movie's frames kept apart as a playable partial movie.
    "$ifsfx" filter long.avi -o out.mp4 --codec mpeg4 --quality 4 --size 320x240 --threads 1 >out.txt 2>err.txt &
    pid=$!
    wait_for_handlers "$pid"
    for _ in $(seq 200); do  # until the encoder has written a few frames to its temporary file
      [[ -n $(find . -name '.out.mp4.*' -size +20k) ]] && break
      sleep 0.05
    done
    kill -INT "$pid" || fail "filter ended before the signal: $(cat err.txt)"
    rc=0 && wait "$pid" || rc=$?
    [[ $rc -eq 130 ]] || fail "filter exited $rc after SIGINT: $(cat err.txt)"
    grep -Eq '^ifsfx: interrupted: [0-9]+ frames kept in out.partial.mp4 \(out.mp4 left as it was\)$' err.txt ||
      fail "message: $(cat err.txt)"
    [[ $(md5sum out.png out.mp4 f.toml) == "$sums" ]] || fail "the output was changed by an interrupted run"
    kept=$(sed -n 's/^ifsfx: interrupted: \([0-9]*\) frames.*/\1/p' err.txt)
    [[ $(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 out.partial.mp4) == "$kept" ]] ||
      fail "partial movie does not hold the $kept frames reported"
    rm out.partial.mp4 out.txt err.txt
    [[ $(listing) == "$before" ]] || fail "files left: $(diff <(echo "$before") <(listing))"
    ;;
  absurd_ifs_terminate)
    # Every loop over IFS geometry ends: an absurd IFS is refused up front (exit 2, one line), or
    # rendered, never a hang.
    photo P.png
    ifs() {  # ifs NAME MAP...: a TOML preset
      local name=$1
      shift
      { echo "name = \"$name\""; echo "maps = ["; printf '  [%s],\n' "$@"; echo "]"; } >"$name.toml"
    }
    ifs t1e40 "0.5,0,0,0.5,0,0" "0.5,0,0,0.5,1e40,0" "0.5,0,0,0.5,0,1e40"
    ifs t4e99 "0.5,0,0,0.5,0,0" "0.5,0,0,0.5,4e99,0" "0.5,0,0,0.5,0,4e99"
    ifs t1e308 "0.5,0,0,0.5,0,0" "0.5,0,0,0.5,1e308,0" "0.5,0,0,0.5,0,1e308"
    ifs opposite "0.5,0,0,0.5,-1e308,0" "0.5,0,0,0.5,1e308,0"
    ifs slow "0.9999999,0,0,0.9999999,1e95,0" "0.5,0,0,0.5,0,0"
    ifs tiny "1e-300,0,0,1e-300,0,0" "1e-300,0,0,1e-300,1,0" "1e-300,0,0,1e-300,0,1"
    ifs tinyfar "1e-300,0,0,1e-300,1e300,0" "1e-300,0,0,1e-300,-1e300,0"
    ifs subnormal "0.5,0,0,0.5,0,0" "0.5,0,0,0.5,5e-324,0"
    ifs point "0.5,0,0,0.5,0,0" "0.3,0,0,0.3,0,0"
    ifs farpoint "0.5,0,0,0.5,5e98,5e98" "0.25,0,0,0.25,7.5e98,7.5e98"
    ifs singular "0,0,0,0,0,0" "0,0,0,0,1,0" "0,0,0,0,0,1"
    ifs rank1 "0.3,0.3,0.3,0.3,0,0" "0.3,0.3,0.3,0.3,1,0"
    ifs thin "1.1e-6,0,0,1.1e-6,0,0" "1.1e-6,0,0,1.1e-6,1,0" "1.1e-6,0,0,1.1e-6,0,1"  # det 1.2e-12
    refused="t1e308 opposite slow tinyfar"
    for name in t1e40 t4e99 t1e308 opposite slow tiny tinyfar subnormal point farpoint singular rank1 thin; do
      for mode in "--mode measure" "--mode tops --exact" "--mode steal --exact --source P.png"; do
        rc=0
        # shellcheck disable=SC2086
        timeout 60 "$ifsfx" render "$name.toml" --size 64x64 $mode -q -o out.png 2>err.txt || rc=$?
        [[ $rc -ne 124 ]] || fail "$name $mode: still running after 60 s"
        if [[ " $refused " == *" $name "* ]]; then
          [[ $rc -eq 2 ]] || fail "$name $mode: exit $rc, expected a refusal: $(cat err.txt)"
          grep -Eq "^ifsfx: $name.toml: (map [0-9]: coefficients must lie within|the attractor would reach)" err.txt ||
            fail "$name $mode: $(cat err.txt)"
        else
          [[ $rc -eq 0 ]] || fail "$name $mode: exit $rc: $(cat err.txt)"
        fi
      done
    done
    # Views the pixels of a double cannot resolve, or beyond the plane the geometry holds.
    run_expect 2 "--view: too narrow for double precision" render barnsley-fern --view 0,0,1e-300,1e-300 -o out.png
    run_expect 2 "--view: too narrow for double precision" render barnsley-fern --view 1e9,0,1.0000000000001e9,1 -o out.png
    run_expect 2 "--view: coordinates must lie within" render barnsley-fern --view -1e308,-1e308,1e308,1e308 -o out.png
    # A superIFS with huge translations, and the filter on one.
    cat >huge.super.toml <<'TOML'
name = "huge"
[[ifs]]
maps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 1e308, 0], [0.5, 0, 0, 0.5, 0, 1e308]]
TOML
    run_expect 2 "IFS 1: map 2: coefficients must lie within ±1e+100 (got 1e+308)" texture huge.super.toml --size 32x32 -o out.png
    movie in.avi 3
    run_expect 2 "t1e308.toml: map 2: coefficients must lie within" filter in.avi --preset t1e308.toml --exact -o out.mp4
    ;;
  numbers_are_checked)
    # Every numeric option of every command against NaN, infinities, huge and negative values,
    # and output patterns: one line naming the option, exit 2, nothing written.
    photo P.png
    movie in.avi 3
    while read -r fragment args; do
      [[ -z $fragment || $fragment == \#* ]] && continue
      # shellcheck disable=SC2086
      run_expect 2 "$fragment" $args
    done <<'TABLE'
--size        render barnsley-fern -o x.png --size 0x10
--size        render barnsley-fern -o x.png --size 99999x10
--size        render barnsley-fern -o x.png --size nanxnan
--margin      render barnsley-fern -o x.png --margin nan
--margin      render barnsley-fern -o x.png --margin inf
--margin      render barnsley-fern -o x.png --margin -1
--margin      render barnsley-fern -o x.png --margin 1e300
--quality     render barnsley-fern -o x.png --quality nan
--quality     render barnsley-fern -o x.png --quality 0
--quality     render barnsley-fern -o x.png --quality -5
--quality     render barnsley-fern -o x.png --quality 1e300
--quality     render barnsley-fern -o x.png --mode steal --source P.png --quality inf
--supersample render barnsley-fern -o x.png --supersample 0
--supersample render barnsley-fern -o x.png --supersample 17
--supersample render barnsley-fern -o x.png --supersample 99999999999
--gamma       render barnsley-fern -o x.png --gamma nan
--gamma       render barnsley-fern -o x.png --gamma 0
--gamma       render barnsley-fern -o x.png --gamma 1e300
--brightness  render barnsley-fern -o x.png --brightness inf
--brightness  render barnsley-fern -o x.png --brightness 1e300
--brightness  render barnsley-fern -o x.png --brightness -1
--seed        render barnsley-fern -o x.png --seed -1
--seed        render barnsley-fern -o x.png --seed 1e300
--threads     render barnsley-fern -o x.png --threads 100000
--threads     render barnsley-fern -o x.png --threads -1
--bits        render barnsley-fern -o x.png --bits 12
--view        render barnsley-fern -o x.png --view nan,0,1,1
--view        render barnsley-fern -o x.png --view 0,0,inf,1
--threads     apply x.map P.png -o x.png --threads 100000
--bits        apply x.map P.png -o x.png --bits 0
--buffers     texture paper-fig4 -o x.png -V 0
--buffers     texture paper-fig4 -o x.png -V 99999999999
--steps       texture paper-fig4 -o x.png --steps -1
--buffer      texture paper-fig4 -o x.png --buffer 0
--frames      texture paper-fig4 -o t_%04d.png --frames 0
--frames      texture paper-fig4 -o t_%04d.png --frames -3
--crossfade   texture paper-fig4 -o t_%04d.png --frames 2 --crossfade 0
--threads     texture paper-fig4 -o x.png --threads 100000
-o            texture paper-fig4 -o t_%99999999999d.png --frames 2
-o            texture paper-fig4 -o t_%d%d.png --frames 2
-o            texture paper-fig4 -o t_%5d.png --frames 2
-o            texture paper-fig4 -o t_%04d%%.png
--fps         filter t_%04d.png -o x.mp4 --fps inf
--fps         filter t_%04d.png -o x.mp4 --fps nan
--fps         filter t_%04d.png -o x.mp4 --fps 0
--fps         filter t_%04d.png -o x.mp4 --fps 1e300
--threads     filter in.avi -o x.mp4 --threads 100000
--keyframe-interval filter in.avi -o x.mp4 --animate drift --keyframe-interval 0
--buffers     filter in.avi -o x.mp4 --animate superifs --buffers 65
--mix         filter in.avi -o x.mp4 --mix nan
--mix         filter in.avi -o x.mp4 --mix 2
--margin      filter in.avi -o x.mp4 --margin nan
--quality     filter in.avi -o x.mp4 --quality 1e300
--drift-amount filter in.avi -o x.mp4 --animate drift --drift-amount 1e300
--drift-amount filter in.avi -o x.mp4 --animate drift --drift-amount nan
--drift-amount filter in.avi -o x.mp4 --animate drift --drift-amount -1
--drift-speed filter in.avi -o x.mp4 --animate drift --drift-speed inf
--frames      filter in.avi -o x.mp4 --frames 5:2
--frames      filter in.avi -o x.mp4 --frames -1:
--frames      filter in.avi -o x.mp4 --frames 99999999999999999999:
-o            filter in.avi -o x_%99999999999d.png
-o            filter in.avi -o x_%d%d.png
-o            filter in.avi -o x_%5d.png
--fps         cam --fps inf
--fps         cam --fps nan
--fps         cam --fps 0
--buffers     cam --buffers 1
--max-frames  cam --max-frames -1
--fade-frames cam --fade-frames 0
--threads     cam --threads 100000
--mix         cam --mix nan
--drift-amount cam --drift-amount 1e300
--record      cam --record r_%d%d.mkv
--snapshot    cam --snapshot s_%5d.png
-n:           fit P.png -o f.toml -n 0
-n:           fit P.png -o f.toml -n 33
--threshold   fit P.png -o f.toml --threshold nan
--threshold   fit P.png -o f.toml --threshold 2
--max-seconds fit P.png -o f.toml --max-seconds inf
--max-seconds fit P.png -o f.toml --max-seconds nan
--max-seconds fit P.png -o f.toml --max-seconds -1
--max-evaluations fit P.png -o f.toml --max-evaluations 1
--size        fit P.png -o f.toml --size 0
--size        fit P.png -o f.toml --size 99999999999
--size        fit P.png -o f.toml --size abc
--threads     fit P.png -o f.toml --threads 100000
TABLE
    # A still image container for a movie output: FFmpeg's muxer would read patterns itself.
    run_expect 1 "x.png: a still image format; write an image sequence with a pattern such as x_%04d.png" filter in.avi -o x.png
    [[ $(listing | tr '\n' ' ') == "P.png in.avi " ]] || fail "files left: $(listing)"
    ;;
  latin1_names_and_comments)
    # Non-UTF-8 bytes in a Fractint comment and in file names: the run succeeds, and the metadata
    # holds the text read as Latin-1.
    printf 'foug\xe8re { ; Barnsley\xb4s foug\xe8re, \xe9t\xe9 1988\n' >"caf$(printf '\xe9').ifs"
    printf '  0 0 0 .16 0 0 .01\n .85 .04 -.04 .85 0 1.6 .85\n .2 -.26 .23 .22 0 1.6 .07\n -.15 .28 .26 .24 0 .44 .07\n}\n' \
      >>"caf$(printf '\xe9').ifs"
    name=$(printf 'caf\xe9')
    for ext in png tif jpg exr; do
      "$ifsfx" render "$name.ifs" --size 48x48 --quality 4 -q -o "$name.$ext" ||
        fail "render with a Latin-1 comment and name to .$ext failed"
      iinfo -v "$name.$ext" | grep -q "Barnsley´s fougère, été 1988" ||
        fail ".$ext metadata: $(iinfo -v "$name.$ext" | grep -a ifsfx)"
    done
    "$ifsfx" render "$name.ifs" --mode steal --source "$name.png" --size 48x48 -q -o "s$name.png" --save-map "$name.map"
    "$ifsfx" texture paper-fig4 --mode steal --source "$name.png" --size 32x32 -q -o "t$name.png"
    # A fit to a target with a Latin-1 name writes a preset that reads back, and valid JSON.
    "$ifsfx" render square-tiling-4 --mode attractor --size 48x48 --view -0.5,-0.5,1.5,1.5 -q -o "$name-square.png"
    "$ifsfx" fit "$name-square.png" --invert -n 4 --size 32 --max-evaluations 300 --json -o "$name.toml" >fit.json
    python3 -c 'import json,sys; r=json.load(open("fit.json")); assert r["target"] == "café-square.png", r["target"]' ||
      fail "fit --json: $(head -c 300 fit.json)"
    grep -q 'name = "café-square"' "$name.toml" || fail "fitted preset: $(head -3 "$name.toml")"
    "$ifsfx" render "$name.toml" --size 32x32 -q -o back.png || fail "the fitted preset does not read back"
    "$ifsfx" fit "$name-square.png" --invert -n 4 --size 32 --max-evaluations 300 -o "$name-fit.ifs" >/dev/null
    "$ifsfx" render "$name-fit.ifs" --size 32x32 -q -o back2.png || fail "the fitted Fractint entry does not read back"
    ;;
  *)
    fail "unknown check $check"
    ;;
esac
echo "ok: $check"
