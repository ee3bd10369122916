#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The light `ifsfx` (cli/light_dispatch.h): it loads neither OpenImageIO nor the video stack,
# writes the same PNG pictures and metadata as ifsfx-full, runs render to PNG itself and hands every other
# command line to ifsfx-full with the same output and exit code.
#   light_binary_test.sh IFSFX IFSFX_FULL WORKDIR
set -euo pipefail
light=$1 full=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
command -v readelf >/dev/null || { echo "SKIP: no readelf (binutils)"; exit 77; }

# What the light binary must not load, and proof the pattern finds it where it is.
heavy='OpenImageIO|libav(format|codec|util)|libswscale|opencv_(videoio|highgui|imgcodecs)'
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
needed "$full" | grep -Eq "$heavy" || fail "the pattern finds nothing in ifsfx-full: $(needed "$full")"
if needed "$light" | grep -E "$heavy"; then fail "the light ifsfx loads the libraries above"; fi
echo "light NEEDED: $(needed "$light" | tr '\n' ' ')"

# The same picture from either binary (the light one writes PNG through libpng, ifsfx-full through
# OpenImageIO), in every mode the light one runs, 8 and 16 bits and --smallest: size, channels,
# depth, the SHA-1 of the pixels and every attribute as OpenImageIO reads them back.
command -v oiiotool >/dev/null || { echo "SKIP: no oiiotool (openimageio-tools)"; exit 77; }
described() { oiiotool --info -v --hash "$1" | tail -n +2 | sed "s|^$1 *:||"; }
same() {  # NAME ARGS...
  local name=$1
  shift
  "$light" render "$@" -q -o "light-$name.png"
  "$full" render "$@" -q -o "full-$name.png"
  described "light-$name.png" >light.txt
  described "full-$name.png" >full.txt
  grep -q "SHA-1: " light.txt || fail "$name: oiiotool gave no hash: $(cat light.txt)"
  cmp -s light.txt full.txt || fail "$name: the two binaries wrote different pictures:
$(diff light.txt full.txt)"
}
same measure barnsley-fern --size 96x72 --quality 8
same measure16 sierpinski-triangle --size 96x72 --quality 8 --bits 16 --smallest
same attractor barnsley-fern --mode attractor --size 96x72 --quality 8
same tops barnsley-fern --mode tops --size 96x72 --bits 16

# Alone in a folder, without ifsfx-full, the light binary still renders to PNG — so it ran that
# itself — and says in one line, exit 1, that it cannot find ifsfx-full for everything else.
mkdir alone && cp "$light" alone/ifsfx
alone/ifsfx render barnsley-fern --size 32x32 --quality 2 -q -o alone.png
[ -s alone.png ] || fail "the light binary alone wrote no PNG"
# `dataset` runs there too.
alone/ifsfx dataset search -n 1 --rate 0.05 --points 20000 -q -o cats
alone/ifsfx dataset render cats --size 32x32 --iterations 2000 --instances 1 --weight-step 0.1 -q -o db
[ "$(find db -name '*.png' | wc -l)" -eq 100 ] || fail "the light binary alone wrote no dataset"
hands_on() {  # ARGS...: a command line the light binary gives to ifsfx-full
  local rc=0
  alone/ifsfx "$@" >out.txt 2>err.txt || rc=$?
  [ "$rc" -eq 1 ] || fail "'$*' alone: exit $rc (want 1)"
  [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^ifsfx: cannot find .*ifsfx-full" err.txt ||
    fail "'$*' alone: $(cat err.txt)"
}
hands_on --version
hands_on presets
hands_on
hands_on render barnsley-fern -o x.tif
hands_on render barnsley-fern -o x.png --mode steal --source alone.png
hands_on render barnsley-fern -o x.png --mode=STEAL --source alone.png
hands_on render barnsley-fern -o x.png --help
hands_on render barnsley-fern -qo x.png
hands_on render barnsley-fern -o x.png -o y.png

# Through the light binary, a command line gets what ifsfx-full gives it: output, message, exit.
same_run() {  # ARGS...
  local rc_light=0 rc_full=0
  "$light" "$@" >light-out.txt 2>light-err.txt || rc_light=$?
  "$full" "$@" >full-out.txt 2>full-err.txt || rc_full=$?
  [ "$rc_light" -eq "$rc_full" ] || fail "'$*': exit $rc_light through the light binary, $rc_full"
  cmp -s light-out.txt full-out.txt || fail "'$*': stdout differs: $(diff light-out.txt full-out.txt)"
  cmp -s light-err.txt full-err.txt || fail "'$*': stderr differs: $(diff light-err.txt full-err.txt)"
}
same_run --version
same_run presets
same_run bogus
same_run render no-such-preset -o x.png
same_run render barnsley-fern -o x.png --size 0x0
same_run render barnsley-fern -o x.png --mode bogus
same_run render barnsley-fern -o x.bmpx
same_run render barnsley-fern -o x.png --mode steal
same_run render barnsley-fern -o x.png --bogus
echo "PASS: the light ifsfx loads no OpenImageIO or video library, writes ifsfx-full's pictures and hands the rest on"
