#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx render PRESET --save-flame F`: a flame file beside the picture (docs/flames.md), refused
# when it would overwrite another output, and rendered by flam3-render when flam3-utils is there.
#   save_flame_test.sh IFSFX WORKDIR
set -euo pipefail
ifsfx=$1
work=$2
fail() { echo "save_flame_test: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"

"$ifsfx" render barnsley-fern -o fern.png --size 96x128 --quality 20 --save-flame fern.flame -q
[ -s fern.png ] || fail "no picture"
grep -q '<flame version="ifsfx" name="barnsley-fern" size="96 128"' fern.flame ||
  fail "not the fern's flame: $(head -c 300 fern.flame)"
[ "$(grep -c '<xform ' fern.flame)" -eq 4 ] || fail "the fern has 4 maps"

if "$ifsfx" render barnsley-fern -o same.png --size 16x16 --save-flame same.png 2> err.txt; then
  fail "--save-flame onto -o was accepted"
fi
grep -q '^ifsfx: --save-flame same.png: must differ from the other outputs' err.txt ||
  fail "unexpected message: $(cat err.txt)"
[ ! -e same.png ] || fail "a refused command left same.png"

if command -v flam3-render > /dev/null; then
  env out=flam3.png flam3-render < fern.flame > /dev/null 2>&1 || fail "flam3-render refused it"
  [ -s flam3.png ] || fail "flam3-render wrote nothing"
fi
echo "save_flame_test: ok"
