#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of `ifsfx render` (attractor and measure modes): one CHECK per run.
#   render_cli_test.sh IFSFX WORKDIR CHECK
set -euo pipefail
ifsfx=$1 work=$2 check=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_error "message fragment" args...: exit code non-zero, exactly one line on stderr that
# starts with "ifsfx:" and contains the fragment, and no image left behind.
expect_error() {
  local fragment=$1
  shift
  local rc=0
  "$ifsfx" "$@" >out.txt 2>err.txt || rc=$?
  [ "$rc" -ne 0 ] || fail "'$*' succeeded"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*' printed $(wc -l <err.txt) lines on stderr: $(cat err.txt)"
  grep -q '^ifsfx: ' err.txt || fail "'$*': error does not start with 'ifsfx:': $(cat err.txt)"
  grep -qF -- "$fragment" err.txt || fail "'$*': error '$(cat err.txt)' lacks '$fragment'"
  [ -z "$(ls -A | grep -v -e '^out.txt$' -e '^err.txt$' -e '^bad' -e '^ro$' || true)" ] ||
    fail "'$*' left files: $(ls -A)"
}

case "$check" in
  formats)
    # PNG 8 and 16 bit, TIFF, OpenEXR float: each written, of the right size and depth, with the
    # preset and seed in its metadata.
    "$ifsfx" render barnsley-fern --size 96x64 --quality 8 --seed 5 -o a.png >summary.txt
    grep -Eq '^barnsley-fern \(measure, 96x64\): [0-9.]+ M points in [0-9.]+ s \([0-9]+ Mpts/s\), coverage [0-9.]+% -> a.png$' summary.txt ||
      fail "summary line: $(cat summary.txt)"
    # The chaos-game tops say how many points they plotted; the exact descent (the default) says
    # it was exact.
    "$ifsfx" render barnsley-fern --size 96x64 --quality 8 --mode tops --chaos -o t.png >summary.txt
    grep -Eq '^barnsley-fern \(tops, 96x64\): [0-9.]+ M points in [0-9.]+ s \([0-9]+ Mpts/s\), coverage [0-9.]+% -> t.png$' summary.txt ||
      fail "tops summary line: $(cat summary.txt)"
    "$ifsfx" render barnsley-fern --size 96x64 --mode tops -o t.png >summary.txt
    grep -Eq '^barnsley-fern \(tops, 96x64\): exact descent in [0-9.]+ s, coverage [0-9.]+% -> t.png$' summary.txt ||
      fail "exact tops summary line: $(cat summary.txt)"
    "$ifsfx" render barnsley-fern --size 96x64 --quality 8 --bits 16 -q -o b.png
    "$ifsfx" render barnsley-fern --size 96x64 --quality 8 --mode attractor -q -o c.tif
    "$ifsfx" render barnsley-fern --size 96x64 --quality 8 -q -o d.exr
    iinfo -v a.png | grep -q '96 x   64, 3 channel, uint8' || fail "a.png: $(iinfo a.png)"
    iinfo -v b.png | grep -q '96 x   64, 3 channel, uint16' || fail "b.png: $(iinfo b.png)"
    iinfo -v c.tif | grep -q '96 x   64, 1 channel, uint8' || fail "c.tif: $(iinfo c.tif)"
    iinfo -v d.exr | grep -Eq '96 x   64, 3 channel, (float|half)' || fail "d.exr: $(iinfo d.exr)"
    iinfo -v a.png | grep -q 'ifsfx:seed: "5"' || fail "a.png metadata: $(iinfo -v a.png)"
    iinfo -v d.exr | grep -q 'ifsfx:preset: "# Barnsley' || fail "d.exr metadata: $(iinfo -v d.exr)"
    [ "$(ls -A | wc -l)" -eq 6 ] || fail "stray files: $(ls -A)"
    ;;
  same_seed_same_bytes)
    # 640x480 at 64 points per pixel spans five chunks of the chaos game: with 2 or 3 threads a
    # worker runs several of them.
    for preset in barnsley-fern maple-leaf; do
      for threads in 1 2 3; do
        "$ifsfx" render $preset --mode measure --size 640x480 --seed 7 --threads $threads -q \
          -o $preset-$threads.png
      done
      cmp -s $preset-1.png $preset-2.png || fail "$preset: 2 threads changed the image"
      cmp -s $preset-1.png $preset-3.png || fail "$preset: 3 threads changed the image"
    done
    "$ifsfx" render maple-leaf --mode measure --size 640x480 --seed 8 --threads 2 -q -o other.png
    ! cmp -s maple-leaf-2.png other.png || fail "the seed does not matter"
    ;;
  bad_inputs)
    expect_error "unknown preset 'fren'" render fren -o x.png
    expect_error "nope.toml" render ./nope.toml -o x.png
    printf 'name = "bad"\nmaps = [\n  [0.5, 0, 0, 0.5, 0],\n]\n' >bad-count.toml
    expect_error "bad-count.toml:3" render ./bad-count.toml -o x.png
    printf 'name = "big"\nmaps = [[1.2, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 1, 0]]\n' >bad-expansive.toml
    expect_error "contraction factor must be < 1" render ./bad-expansive.toml -o x.png
    printf 'name = "neg"\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\nprobabilities = [-1]\n' >bad-prob.toml
    expect_error "probabilit" render ./bad-prob.toml -o x.png
    printf 'name = "zero"\nmaps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 1, 0]]\nprobabilities = [0, 0]\n' >bad-zero.toml
    expect_error "must not all be zero" render ./bad-zero.toml -o x.png
    printf 'name = "nan"\nmaps = [[nan, 0, 0, 0.5, 0, 0]]\n' >bad-nan.toml
    expect_error "finite" render ./bad-nan.toml -o x.png
    expect_error "each side must be 1 to 32768 pixels (got 0x10)" render barnsley-fern --size 0x10 -o x.png
    expect_error "(got 40000x10)" render barnsley-fern --size 40000x10 -o x.png
    # The command line checks its flags first; where the library checks (its own parameter
    # names), the command line reports the flags typed (--size × --supersample).
    expect_error "ifsfx: --quality: must be a number in (0, 1e+06] (got 0)" \
      render barnsley-fern --quality 0 -o x.png
    expect_error "ifsfx: --supersample: Value 0 not in range 1 to 16" render barnsley-fern --supersample 0 -o x.png
    expect_error "ifsfx: --size × --supersample: each side must be 1 to 32768 pixels (got 40000x40000)" \
      render barnsley-fern --size 20000x20000 --supersample 2 -o x.png
    expect_error "ifsfx: --gamma: must be a number in (0, 100] (got -1)" render barnsley-fern --gamma -1 -o x.png
    expect_error "ifsfx: --threads: Value -2 not in range 0 to 256" \
      render barnsley-fern --threads -2 -o x.png
    expect_error "ifsfx: --view: needs x1 > x0 and y1 > y0 (got '1,0,0,1')" \
      render barnsley-fern --view 1,0,0,1 -o x.png
    expect_error "no image writer for extension '.xyz'" render barnsley-fern -o x.xyz
    expect_error "does not exist" render barnsley-fern -o missing/x.png
    mkdir ro && chmod 555 ro
    if [ "$(id -u)" -ne 0 ]; then expect_error "not writable" render barnsley-fern -o ro/x.png; fi
    ;;
  allow_expansive)
    # One map of factor 1.2, but contracting on average: refused, then accepted with the flag.
    printf 'name = "avg"\nmaps = [[1.2, 0, 0, 1.2, 0, 0], [0.3, 0, 0, 0.3, 1, 0]]\nprobabilities = [0.2, 0.8]\n' >bad-avg.toml
    expect_error "--allow-expansive" render ./bad-avg.toml -o x.png
    "$ifsfx" render ./bad-avg.toml --allow-expansive --size 64x64 --quality 4 -q -o bad-avg.png
    [ -s bad-avg.png ] || fail "no image with --allow-expansive"
    # Expanding on average too: refused even with the flag.
    printf 'name = "grow"\nmaps = [[1.5, 0, 0, 1.5, 0, 0], [0.9, 0, 0, 0.9, 1, 0]]\n' >bad-grow.toml
    expect_error "contract on average" render ./bad-grow.toml --allow-expansive -o x.png
    # The file itself may opt in.
    printf 'name = "avg"\nallow_expansive = true\nmaps = [[1.2, 0, 0, 1.2, 0, 0], [0.3, 0, 0, 0.3, 1, 0]]\nprobabilities = [0.2, 0.8]\n' >avg-opted-in.toml
    "$ifsfx" render ./avg-opted-in.toml --size 64x64 --quality 4 -q -o opted-in.png 2>err.txt
    [ -s opted-in.png ] && [ ! -s err.txt ] || fail "allow_expansive = true: $(cat err.txt)"
    # A Fractint entry with a point reflection (factor 1) that contracts on average renders as
    # Fractint renders it, with exactly one warning line; with the flag, without a word.
    printf 'reflect {\n -1 0 0 -1 0 10 .55\n .5 0 0 .5 0 0 .15\n .5 0 0 .5 0 5 .15\n .5 0 0 .5 5 0 .15\n}\n' >designer.ifs
    "$ifsfx" render ./designer.ifs:reflect --size 64x64 --quality 4 -q -o reflect.png 2>err.txt
    [ -s reflect.png ] || fail "the Fractint entry did not render: $(cat err.txt)"
    [ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one warning line: $(cat err.txt)"
    grep -q '^ifsfx: warning: ./designer.ifs:reflect: map 1 does not contract (factor 1); accepted as Fractint renders it' err.txt ||
      fail "warning: $(cat err.txt)"
    "$ifsfx" render ./designer.ifs:reflect --allow-expansive --size 64x64 --quality 4 -q -o reflect2.png 2>err.txt
    [ ! -s err.txt ] || fail "a warning with --allow-expansive: $(cat err.txt)"
    rm -f reflect.png reflect2.png opted-in.png
    ;;
  super_presets)
    # `ifsfx presets --super`: one line per shipped superIFS preset, the paper's among them.
    "$ifsfx" presets --super >list.txt
    grep -Eq '^paper-fig4 +Paper Fig. 4' list.txt || fail "no paper-fig4 line: $(cat list.txt)"
    [ "$(wc -l <list.txt)" -ge 4 ] || fail "fewer than 4 superIFS presets: $(cat list.txt)"
    ! grep -q barnsley-fern list.txt || fail "IFS presets among the superIFS ones"
    ;;
  file_presets)
    # `ifsfx presets FILE...`: every entry of a Fractint file, the unusable ones with the reason
    # (an artist's notes entry first, as in Tony Hanmer's files), and a .toml file's preset.
    printf '_README { ; notes\n1 1 1 1 1 1 1 ; of the artist\n}\nhalves { ; two halves\n.5 0 0 .5 0 0 .5\n.5 0 0 .5 1 0 .5\n}\nodd { .5 0 0 .5 0 0 1 1 }\n' >artist.ifs
    "$ifsfx" presets ./artist.ifs barnsley-fern.toml >list.txt 2>err.txt || fail "presets FILE: $(cat err.txt)"
    [ "$(wc -l <list.txt)" -eq 4 ] || fail "expected 4 lines: $(cat list.txt)"
    grep -Eq '^_README +not usable: \./artist\.ifs:_README: the IFS must contract on average' list.txt ||
      fail "no _README line: $(cat list.txt)"
    grep -Eq '^halves +2 maps +factor 0\.5 +two halves$' list.txt || fail "no halves line: $(cat list.txt)"
    grep -Eq "^odd +not usable: \./artist\.ifs:8: entry 'odd': needs 7 numbers per map" list.txt ||
      fail "no odd line: $(cat list.txt)"
    grep -Eq '^barnsley-fern +4 maps +factor 0\.8509 ' list.txt || fail "no fern line: $(cat list.txt)"
    # Rendered without an entry, the file's message names one that can be used.
    "$ifsfx" render ./artist.ifs -q -o x.png 2>err.txt && fail "the notes entry rendered"
    grep -q "(the first of the file's 3 entries; name one as FILE.ifs:NAME, e.g. ./artist.ifs:halves)$" err.txt ||
      fail "render of the file: $(cat err.txt)"
    "$ifsfx" presets ./missing.ifs 2>err.txt && fail "a missing file listed"
    grep -qx 'ifsfx: ./missing.ifs: no such file' err.txt || fail "missing file: $(cat err.txt)"
    ;;
  *) fail "unknown check '$check'" ;;
esac
echo "PASS: $check"
