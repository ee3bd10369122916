#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of flame files on the command line (docs/flames.md): one CHECK per run.
#   flame_cli_test.sh IFSFX WORKDIR CHECK
set -euo pipefail
ifsfx=$1 work=$2 check=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }

case "$check" in
  save_flame)
    # --save-flame writes the IFS as a flame beside the picture; `ifsfx presets` lists it, and
    # flam3-render (where installed) renders it.
    "$ifsfx" render sierpinski-triangle --size 64x64 --quality 4 -q -o t.png --save-flame t.flame
    [ -s t.png ] || fail "no picture"
    grep -q '<flame ' t.flame || fail "no <flame> in t.flame: $(head -c 200 t.flame)"
    [ "$(grep -c '<xform ' t.flame)" -eq 3 ] || fail "not 3 xforms: $(cat t.flame)"
    "$ifsfx" presets t.flame >list.txt
    grep -Eq '^t\.flame:sierpinski-triangle +3 xforms +\(or t\.flame:0\)$' list.txt ||
      fail "presets t.flame: $(cat list.txt)"
    if command -v flam3-render >/dev/null; then
      env out=flam3.png flam3-render <t.flame >/dev/null 2>&1 || fail "flam3-render refused t.flame"
      [ -s flam3.png ] || fail "flam3-render wrote nothing"
    fi
    ;;
  render)
    # A flame of our own, rendered at its own size, then at --size; other modes are refused with
    # the reason.
    pal=$(for i in $(seq 0 255); do printf '%02X%02X%02X' "$i" 0 $((255 - i)); done)
    cat >two.flame <<XML
<flames>
<flame name="spiral" size="80 60" center="0 0" scale="20" quality="4" brightness="4" gamma="4"
       estimator_radius="0">
  <xform weight="0.5" color="0" linear="0.8" swirl="0.2" coefs="0.6 0.2 -0.2 0.6 0.5 0"/>
  <xform weight="0.5" color="1" spherical="1" coefs="0.5 0 0 0.5 -0.5 0.2"/>
  <palette count="256" format="RGB">$pal</palette>
</flame>
<flame name="other" size="40 40" scale="10">
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/>
  <palette count="256" format="RGB">$pal</palette>
</flame>
</flames>
XML
    "$ifsfx" render two.flame:spiral -o own.png >summary.txt
    grep -Eq '^spiral \(flame, 80x60\): .* -> own.png$' summary.txt || fail "summary: $(cat summary.txt)"
    file own.png | grep -q '80 x 60' || fail "own size: $(file own.png)"
    "$ifsfx" render two.flame:0 --size 64x48 --quality 2 -q -o sized.jpg
    file sized.jpg | grep -q '64x48' || fail "--size: $(file sized.jpg)"
    # The paper's modes through the chaos game (docs/flames.md), at the flame's own size.
    "$ifsfx" render two.flame:spiral --mode tops -q -o t.png
    file t.png | grep -q '80 x 60' || fail "tops size: $(file t.png)"
    "$ifsfx" render sierpinski-triangle --size 32x32 -q -o src.png
    "$ifsfx" render two.flame:spiral --mode steal --source src.png --size 40x30 -q -o s.png
    file s.png | grep -q '40 x 30' || fail "steal size: $(file s.png)"
    rc=0
    "$ifsfx" render two.flame:spiral --mode tops --exact -o t.png 2>err.txt || rc=$?
    [ "$rc" -ne 0 ] && grep -q "^ifsfx: .*exact: the exact descent follows inverse maps" err.txt ||
      fail "--exact of a flame: rc $rc, $(cat err.txt)"
    if command -v ffmpeg >/dev/null; then  # filter: a named --exact is refused, not ignored
      ffmpeg -v error -y -f lavfi -i testsrc2=size=64x48:rate=25 -frames:v 3 -c:v ffv1 clip.mkv
      rc=0
      "$ifsfx" filter clip.mkv --preset two.flame:spiral --exact -o f.mkv 2>err.txt || rc=$?
      [ "$rc" -ne 0 ] && grep -q "^ifsfx: --exact: the exact descent follows inverse maps" err.txt &&
        [ ! -e f.mkv ] || fail "filter --exact of a flame: rc $rc, $(cat err.txt)"
      "$ifsfx" filter clip.mkv --preset two.flame:spiral --chaos -q -o f.mkv || fail "filter --chaos"
    fi
    rc=0
    "$ifsfx" render two.flame:spiral --mode steal --source src.png --colouring sierpinski-triangle \
      -o s.png 2>err.txt || rc=$?
    [ "$rc" -ne 0 ] && grep -q "sierpinski-triangle must have as many maps as spiral (got 3 for 2)" err.txt ||
      fail "--colouring of 3 maps for 2 xforms: rc $rc, $(cat err.txt)"
    # --background: in place of the flame's own; transparent keeps alpha (flam3's transparency=1)
    # and needs an output that can; the paper modes' flags are refused in the flame look.
    # (python.flames checks the pixels.)
    "$ifsfx" render two.flame:spiral -q -o opaque.png
    for bg in transparent white; do
      "$ifsfx" render two.flame:spiral --background $bg -q -o $bg.png
      ! cmp -s opaque.png $bg.png || fail "--background $bg changed nothing"
    done
    for bad in "--background transparent -o clear.jpg" "--source src.png -o x.png" \
      "--chaos -o x.png"; do
      rc=0
      # shellcheck disable=SC2086
      "$ifsfx" render two.flame:spiral $bad 2>err.txt || rc=$?
      [ "$rc" -ne 0 ] && [ "$(wc -l <err.txt)" -eq 1 ] || fail "$bad: rc $rc, $(cat err.txt)"
    done
    grep -q "^ifsfx: --exact/--chaos: only with --mode" err.txt || fail "--chaos: $(cat err.txt)"
    rc=0
    "$ifsfx" render two.flame -o t.png 2>err.txt || rc=$?
    [ "$rc" -ne 0 ] && grep -q 'spiral' err.txt || fail "no pick in a file of two: rc $rc, $(cat err.txt)"
    ;;
  bad_input)
    # The flame file may not be the picture; a file that is not XML is one line naming it.
    rc=0
    "$ifsfx" render sierpinski-triangle -o same.png --save-flame same.png 2>err.txt || rc=$?
    [ "$rc" -ne 0 ] && grep -q '^ifsfx: --save-flame same.png: must differ from -o' err.txt ||
      fail "same file: rc $rc, $(cat err.txt)"
    [ ! -e same.png ] || fail "same.png written"
    echo 'not xml at all' >bad.flame
    rc=0
    "$ifsfx" presets bad.flame >out.txt 2>err.txt || rc=$?
    [ "$rc" -ne 0 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q '^ifsfx: bad.flame' err.txt ||
      fail "not XML: rc $rc, $(cat err.txt)"
    ;;
  *) fail "unknown check $check" ;;
esac
echo "PASS: $check"
