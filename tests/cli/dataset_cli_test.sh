#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of `ifsfx dataset` (docs/dataset.md): one CHECK per run.
#   dataset_cli_test.sh IFSFX WORKDIR CHECK
set -euo pipefail
ifsfx=$1 work=$2 check=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }

# Small categories found by the command's own search (fast settings), and a weight file.
make_categories() {
  "$ifsfx" dataset search -n 3 --rate 0.05 --points 20000 --seed 3 -q -o cats
  printf '1,1,1,1,1,1\n0.8,1,1,1,1,1.2\n' >w.csv
}
# A render of those into $1, extra options after.
render() {
  local out=$1
  shift
  "$ifsfx" dataset render cats --weights w.csv --size 64x48 --padding 3 --iterations 5000 \
    --instances 2 -q -o "$out" "$@"
}
# Relative paths and checksums of every file under $1.
listing() { (cd "$1" && find . -type f | sort | xargs md5sum); }

# expect_error "message fragment" CODE args...: exit CODE, one line on stderr starting with ifsfx:.
expect_error() {
  local fragment=$1 code=$2
  shift 2
  local rc=0
  "$ifsfx" "$@" >out.txt 2>err.txt || rc=$?
  [ "$rc" -eq "$code" ] || fail "'$*' exited $rc, not $code: $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*' printed $(wc -l <err.txt) lines: $(cat err.txt)"
  grep -q '^ifsfx: ' err.txt || fail "'$*': error does not start with 'ifsfx:': $(cat err.txt)"
  grep -qF -- "$fragment" err.txt || fail "'$*': error '$(cat err.txt)' lacks '$fragment'"
}

case "$check" in
  layout)
    # make_fractaldb.py's layout: FOLDER/NAME/NAME_WW_count_I_flipT.png, PNGs of the size asked.
    make_categories
    [[ $(ls cats) == $'00000.csv\n00001.csv\n00002.csv' ]] || fail "search wrote: $(ls cats)"
    "$ifsfx" dataset render cats --weights w.csv --size 64x48 --padding 3 --iterations 5000 \
      --instances 2 -o db >summary.txt 2>progress.txt
    grep -Eq '^3 categories x 2 weights x 2 instances x 4 flips \(patch_gray, 64x48\): 48 images written, 0 already there -> db$' summary.txt ||
      fail "summary: $(cat summary.txt)"
    [[ $(find db -type f | wc -l) -eq 48 ]] || fail "$(find db -type f | wc -l) files"
    [[ $(ls db) == $'00000\n00001\n00002' ]] || fail "folders: $(ls db)"
    for f in 00001/00001_00_count_0_flip0.png 00002/00002_01_count_1_flip3.png; do
      [[ -f db/$f ]] || fail "no db/$f"
    done
    iinfo db/00000/00000_01_count_1_flip2.png | grep -q '64 x   48' ||
      fail "$(iinfo db/00000/00000_01_count_1_flip2.png)"
    grep -q '48/48 images' progress.txt || fail "progress: $(cat progress.txt)"
    # Point types draw one picture per category and weight; --rgb-png the reference's format.
    render points --draw point_color --rgb-png
    [[ $(find points -type f | wc -l) -eq 24 ]] || fail "points: $(find points -type f | wc -l)"
    iinfo -v points/00000/00000_00_count_0_flip0.png | grep -q '3 channel, uint8' || fail "rgb png"
    ;;
  same_bytes)
    # Any thread count, and a second run into a fresh folder: the same files.
    make_categories
    render one --threads 1
    render two --threads 2
    render again
    [[ $(listing one) == "$(listing two)" ]] || fail "2 threads changed the files"
    [[ $(listing one) == "$(listing again)" ]] || fail "a second run changed the files"
    render seeded --seed 9
    [[ $(listing one) != "$(listing seeded)" ]] || fail "--seed changed nothing"
    ;;
  resume)
    make_categories
    render full
    cp -r full db
    rm db/00001/00001_01_count_0_flip2.png db/00002/00002_00_count_1_flip0.png
    "$ifsfx" dataset render cats --weights w.csv --size 64x48 --padding 3 --iterations 5000 \
      --instances 2 -o db 2>/dev/null >summary.txt
    grep -q ': 2 images written, 46 already there -> db$' summary.txt || fail "$(cat summary.txt)"
    [[ $(listing full) == "$(listing db)" ]] || fail "the resumed dataset differs"
    ;;
  interrupted)
    # Ctrl-C mid-run: exit 130, whole files only (each the full run's), no temporary left; the
    # same command again completes the dataset.
    make_categories
    args=(dataset render cats --weights w.csv --size 128x128 --iterations 200000 --instances 50
      --threads 1 -q)
    "$ifsfx" "${args[@]}" -o full
    "$ifsfx" "${args[@]}" -o db 2>err.txt &
    pid=$!
    for _ in $(seq 400); do
      [[ $(find db -name '*.png' 2>/dev/null | wc -l) -ge 20 ]] && break
      sleep 0.025
    done
    kill -INT "$pid" || fail "the render ended before the signal"
    rc=0 && wait "$pid" || rc=$?
    [[ $rc -eq 130 ]] || fail "exit $rc after SIGINT: $(cat err.txt)"
    grep -q '^ifsfx: interrupted: the images written are whole; run the same command again' err.txt ||
      fail "message: $(cat err.txt)"
    [[ -z $(find db -name '*.ifsfx-tmp') ]] || fail "temporaries left: $(find db -name '*.ifsfx-tmp')"
    written=$(find db -type f | wc -l)
    ((written >= 20 && written < 1200)) || fail "$written files after the stop"
    listing full | sort >full.txt
    listing db | sort >db.txt
    [[ -z $(comm -23 db.txt full.txt) ]] || fail "files differ from the full run's: $(comm -23 db.txt full.txt | head -3)"
    "$ifsfx" "${args[@]}" -o db
    [[ $(listing full) == "$(listing db)" ]] || fail "the resumed dataset differs"
    ;;
  bad_input)
    make_categories
    printf '0.5,0,0,0.5,0,0,0.5\n0.5,0,0,0.5,0.5,0\n' >bad.csv
    expect_error "bad.csv:2: a category row a,b,c,d,e,f,p is 7 numbers separated by commas (got 6)" 2 \
      dataset render bad.csv -o db
    printf '1.3,0,0,0.2,0,0,1\n' >grows.csv
    expect_error "grows.csv: the maps do not contract on average" 2 dataset render grows.csv -o db
    printf '1,1,1\n' >w3.csv
    expect_error "w3.csv:1: a weight row wa,wb,wc,wd,we,wf is 6 numbers" 2 \
      dataset render cats --weights w3.csv -o db
    expect_error "--weights: give a weight file or --weight-step, not both" 2 \
      dataset render cats --weights w.csv --weight-step 0.2 -o db
    expect_error "--draw: must be one of point_gray, point_color, patch_gray, patch_color (got 'dots')" 2 \
      dataset render cats --draw dots -o db
    expect_error "--padding: must be" 2 dataset render cats --padding 300 --size 512 -o db
    expect_error "missing: no such file" 1 dataset render missing -o db
    expect_error "--rate: 0.5 cannot be reached with 100000 points" 2 dataset search --rate 0.5 -o s
    [[ ! -e db ]] || fail "a refused run made db"
    ;;
  search)
    # A rerun keeps what is there; another search's files are not overwritten.
    make_categories
    cp -r cats first
    "$ifsfx" dataset search -n 3 --rate 0.05 --points 20000 --seed 3 -o cats >summary.txt 2>/dev/null
    grep -Eq '^3 categories of filling rate >= 0.05 from [0-9]+ candidates: 0 written, 3 already there -> cats$' summary.txt ||
      fail "summary: $(cat summary.txt)"
    [[ $(listing first) == "$(listing cats)" ]] || fail "the rerun changed the files"
    expect_error "00000.csv: holds another category than this search finds" 2 \
      dataset search -n 3 --rate 0.05 --points 20000 --seed 4 -o cats
    ;;
  *) fail "unknown check '$check'" ;;
esac
