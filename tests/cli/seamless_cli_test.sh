#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of --seamless, --tiles and --tile-offset of `ifsfx render` and `ifsfx texture`
# (docs/seamless.md): one CHECK per run.
#   seamless_cli_test.sh IFSFX WORKDIR CHECK
set -euo pipefail
ifsfx=$1 work=$2 check=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
photo=/usr/share/doc/opencv-doc/examples/data/baboon.jpg

fail() { echo "FAIL: $*" >&2; exit 1; }

# same_picture A B: the same size and the same pixel values (oiiotool's --diff, no tolerance).
same_picture() {
  oiiotool "$1" "$2" --fail 0 --warn 0 --diff >diff.txt 2>&1 || fail "$1 and $2 differ: $(cat diff.txt)"
}

# expect_mosaic TILE K L PICTURE: PICTURE is the K×L repetition of TILE (one oiiotool run).
expect_mosaic() {
  local tile=$1 k=$2 l=$3 picture=$4 inputs=()
  for ((i = 0; i < k * l; ++i)); do inputs+=("$tile"); done
  oiiotool "${inputs[@]}" --mosaic "${k}x${l}" "$picture" --fail 0 --warn 0 --diff >diff.txt 2>&1 ||
    fail "$picture is not the ${k}x$l repetition of $tile: $(cat diff.txt)"
}

# mean_difference A_CUT B_CUT: oiiotool's mean absolute difference between two cuts of tile.png.
# (Identical cuts print no figures: 0.)
mean_difference() {
  oiiotool tile.png --cut "$1" tile.png --cut "$2" --diff >cuts.txt 2>&1 || true
  local mean
  mean=$(sed -n 's/^ *Mean error = //p' cuts.txt)
  echo "${mean:-0}"
}

# The seam statistic of tile.png (tests/common/seam.h): the mean absolute difference across the
# tile's edges in its 2×2 tiling over that between neighbours inside it, printed.
seam_ratio() {
  local w h
  read -r w h < <(iinfo tile.png | sed -E 's/.* : +([0-9]+) x +([0-9]+),.*/\1 \2/')
  local eh ev ih iv
  eh=$(mean_difference "1x$h+$((w - 1))+0" "1x$h+0+0")
  ev=$(mean_difference "${w}x1+0+$((h - 1))" "${w}x1+0+0")
  ih=$(mean_difference "$((w - 1))x$h+0+0" "$((w - 1))x$h+1+0")
  iv=$(mean_difference "${w}x$((h - 1))+0+0" "${w}x$((h - 1))+0+1")
  awk -v w="$w" -v h="$h" -v eh="$eh" -v ev="$ev" -v ih="$ih" -v iv="$iv" 'BEGIN {
    edge = (h * eh + w * ev) / (h + w)
    inside = ((w - 1) * h * ih + w * (h - 1) * iv) / ((w - 1) * h + w * (h - 1))
    printf "%.4f\n", (inside > 0 ? edge / inside : 0) }'
}

# expect_error "message" args...: non-zero exit, that one line on stderr, no image left behind.
expect_error() {
  local message=$1
  shift
  local rc=0
  "$ifsfx" "$@" >out.txt 2>err.txt || rc=$?
  [ "$rc" -eq 2 ] || fail "'$*' exited $rc: $(cat err.txt)"
  [ "$(cat err.txt)" = "ifsfx: $message" ] || fail "'$*': error '$(cat err.txt)', not 'ifsfx: $message'"
  [ ! -e x.png ] || fail "'$*' left x.png"
}

case "$check" in
  tiles_repeat_the_tile)
    # The picture of 2×2 periods is the 2×2 repetition of the tile, byte for byte, in every mode of
    # render (exact and chaos-game tops and steal maps, supersampled measure) and of texture; with
    # an offset too, and the saved steal map colours the whole picture.
    render() { "$ifsfx" render barnsley-fern --seamless --size 48x40 -q "$@"; }
    for mode in attractor "measure --supersample 2" "tops --second-symbol" "tops --chaos" \
                "steal --source $photo" "steal --chaos --source $photo"; do
      name=$(echo "$mode" | tr -cd 'a-z-')
      # shellcheck disable=SC2086
      render --mode $mode -o "$name-1.png"
      # shellcheck disable=SC2086
      render --mode $mode --tiles 2x2 -o "$name-2.png"
      expect_mosaic "$name-1.png" 2 2 "$name-2.png"
    done
    render --mode steal --source "$photo" --tile-offset 0.25,0.5 -o shifted-1.png
    render --mode steal --source "$photo" --tile-offset 0.25,0.5 --tiles 3x2 -o shifted-32.png \
      --save-map shifted.map
    expect_mosaic shifted-1.png 3 2 shifted-32.png
    "$ifsfx" apply shifted.map "$photo" -o applied.png >/dev/null
    same_picture applied.png shifted-32.png
    for mode in attractor measure tops steal; do
      "$ifsfx" texture carpet-lace --seamless --size 54x54 --mode $mode --source "$photo" -q \
        -o "tex-$mode-1.png"
      "$ifsfx" texture carpet-lace --seamless --size 54x54 --mode $mode --source "$photo" -q \
        --tiles 2x2 -o "tex-$mode-2.png"
      expect_mosaic "tex-$mode-1.png" 2 2 "tex-$mode-2.png"
    done
    ;;
  offset_shifts_the_period)
    # --tile-offset X,Y starts the picture X·W, Y·H pixels into the period: the tile at 0,0 shifted
    # cyclically; carpet-lace's own offset is half a tile.
    "$ifsfx" render twin-dragon --seamless --size 64x48 --mode tops -q --tile-offset 0,0 -o a.png
    "$ifsfx" render twin-dragon --seamless --size 64x48 --mode tops -q --tile-offset 0.25,0.5 -o b.png
    oiiotool a.png --cshift -16-24 b.png --fail 0 --warn 0 --diff >diff.txt 2>&1 ||
      fail "b.png is not a.png shifted: $(cat diff.txt)"
    "$ifsfx" texture carpet-lace --seamless --size 60x60 -q --tile-offset 0,0 -o c.png
    "$ifsfx" texture carpet-lace --seamless --size 60x60 -q -o d.png
    oiiotool c.png --cshift -30-30 d.png --fail 0 --warn 0 --diff >diff.txt 2>&1 ||
      fail "d.png is not c.png shifted: $(cat diff.txt)"
    iinfo -v d.png >d.txt
    grep -q 'ifsfx:tile_offset: "0.5,0.5"' d.txt || fail "d.png metadata: $(cat d.txt)"
    grep -q 'ifsfx:seamless_tile: "0,0,1,1"' d.txt || fail "d.png metadata: $(cat d.txt)"
    "$ifsfx" render barnsley-fern --seamless --tiles 3x2 --size 40x30 -o e.png >summary.txt
    grep -Eq '^barnsley-fern \(measure, seamless, 120x60\): ' summary.txt || fail "summary: $(cat summary.txt)"
    iinfo -v e.png >e.txt
    grep -q 'ifsfx:tiles: "3x2"' e.txt || fail "e.png metadata: $(cat e.txt)"
    ;;
  carpet_lace_steal_has_no_seam)
    # The example at a modest size: no seam by the statistic (at most 1.15), where the
    # lace at its own view (offset 0,0) has one several times the interior's difference.
    "$ifsfx" texture carpet-lace --seamless --size 243x243 --mode steal --source "$photo" -q -o tile.png
    ratio=$(seam_ratio)
    awk -v r="$ratio" 'BEGIN { exit !(r + 0 <= 1.15 && r != "") }' || fail "seam ratio '$ratio'"
    "$ifsfx" texture carpet-lace --seamless --tile-offset 0,0 --size 243x243 --mode steal \
      --source "$photo" -q -o tile.png
    ratio=$(seam_ratio)
    awk -v r="$ratio" 'BEGIN { exit !(r > 2) }' || fail "the statistic cannot tell a seam: $ratio"
    ;;
  presets_say_which_tile)
    "$ifsfx" presets >list.txt
    grep -Eq '^barnsley-fern .* \[seamless tile\]$' list.txt || fail "fern: $(cat list.txt)"
    grep -E '^sierpinski-triangle ' list.txt | grep -vq 'seamless' || fail "sierpinski: $(cat list.txt)"
    "$ifsfx" presets --super >list.txt
    for name in carpet-lace vicsek-weave quadrant-shuffle; do
      grep -Eq "^$name .* \[seamless tile\]$" list.txt || fail "$name: $(cat list.txt)"
    done
    grep -E '^paper-fig4 ' list.txt | grep -vq 'seamless' || fail "paper-fig4: $(cat list.txt)"
    ;;
  bad_options)
    expect_error "--tiles: only with --seamless" render barnsley-fern --tiles 2x2 -o x.png
    expect_error "--tile-offset: only with --seamless" texture carpet-lace --tile-offset 0.5,0 -o x.png
    expect_error "--tiles: must be 1 to 64 periods a side (got 65x1)" \
      render barnsley-fern --seamless --tiles 65x1 -o x.png
    expect_error "--tile-offset: must be fractions of the tile in [0, 1) (got 1,0)" \
      texture carpet-lace --seamless --tile-offset 1,0 -o x.png
    expect_error "--tile-offset: must be X,Y, fractions of the tile (got '0.5')" \
      render barnsley-fern --seamless --tile-offset 0.5 -o x.png
    expect_error "--size × --tiles: each side must be 1 to 32768 pixels (got 40000x100)" \
      render barnsley-fern --seamless --size 10000x100 --tiles 4x1 -o x.png
    ;;
  *) fail "unknown check '$check'" ;;
esac
