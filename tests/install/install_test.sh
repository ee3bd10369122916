#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks of an installed ifsfx, one CHECK per run:
#   install_test.sh CHECK SOURCE_DIR BUILD_DIR WORK_DIR BUILT_IFSFX
# prefix      `cmake --install BUILD_DIR --prefix WORK_DIR/prefix` (the fixture of the next four)
# command     the installed ifsfx, run from another folder; its man page and bash completion
# consumer    examples/consumer built with find_package(ifsfx) against the prefix, run, its
#             picture compared with the installed `ifsfx render` of the same settings
# pkg_config  a program using all four libraries, compiled and linked by `pkg-config ifsfx` alone
# headers     the installed headers against the prefix alone; nothing private installed
# deb         cpack's packages: their files and fields, unpacked into a scratch root and run
set -euo pipefail
check=$1 src=$2 build=$3 work=$4 built_ifsfx=$5
built_full=$(dirname "$built_ifsfx")/ifsfx-full  # what the light ifsfx execs for other commands
prefix=$work/prefix
photo=/usr/share/doc/opencv-doc/examples/data/baboon.jpg

fail() { echo "FAIL: $*" >&2; exit 1; }

# A fresh folder under WORK_DIR for this check (checks run in parallel).
scratch() {
  rm -rf "$work/$check" && mkdir -p "$work/$check" && cd "$work/$check"
}

# expect_command IFSFX: the command of an install, run from a folder that is neither the source
# nor the build tree, lists the same presets (through the ifsfx-full it installs beside it) and
# renders the same bytes as the built one, PNG by itself and TIFF through ifsfx-full.
expect_command() {
  local ifsfx=$1
  mkdir -p elsewhere && cd elsewhere
  "$ifsfx" presets >presets.txt || fail "$ifsfx presets"
  "$built_ifsfx" presets >built-presets.txt
  grep -q '^barnsley-fern  *4 maps' presets.txt || fail "presets: $(cat presets.txt)"
  cmp -s presets.txt built-presets.txt || fail "$ifsfx presets differs from the built one"
  "$ifsfx" render maple-leaf --size 96x64 --quality 8 --seed 3 -q -o leaf.png
  "$built_ifsfx" render maple-leaf --size 96x64 --quality 8 --seed 3 -q -o built-leaf.png
  cmp -s leaf.png built-leaf.png || fail "$ifsfx render differs from the built one"
  "$ifsfx" render maple-leaf --size 96x64 --quality 8 --seed 3 -q -o leaf.tif
  "$built_ifsfx" render maple-leaf --size 96x64 --quality 8 --seed 3 -q -o built-leaf.tif
  # The pixels: a TIFF carries the second it was written (DateTime).
  [ "$(oiiotool --info --hash leaf.tif | grep SHA-1)" = \
    "$(oiiotool --info --hash built-leaf.tif | grep SHA-1)" ] ||
    fail "$ifsfx render to TIFF differs from the built one"
  cd ..
}

# expect_python DIR: the module installed in DIR imports from another folder and renders the
# array the built command's PNG holds.
expect_python() {
  local dir=$1
  mkdir -p python && cd python
  "$built_ifsfx" render maple-leaf --size 96x64 --quality 8 --seed 3 -q -o built-leaf.png
  PYTHONPATH=$dir /usr/bin/python3 -c '
import numpy as np, ifsfx
a = ifsfx.render("maple-leaf", size=(96, 64), quality=8, seed=3)
assert ifsfx.__file__.startswith("'"$dir"'"), ifsfx.__file__
assert np.array_equal(a, ifsfx.read_image("built-leaf.png")), "pixels differ"
' || fail "the Python module installed in $dir"
  cd ..
}

case "$check" in
  prefix)
    mkdir -p "$work" && cd "$work" && rm -rf "$prefix"
    cmake --install "$build" --prefix "$prefix" >install.log 2>&1 ||
      { cat install.log; fail "cmake --install"; }
    ;;

  command)
    scratch
    expect_command "$prefix/bin/ifsfx"
    # The copies of the shipped presets are presets the command reads.
    [ -f "$prefix/share/ifsfx/presets/barnsley-fern.toml" ] || fail "no presets in share/ifsfx"
    if [ -d "$prefix/lib/python3/dist-packages" ]; then
      [ -f "$prefix/lib/python3/dist-packages/ifsfx.pyi" ] || fail "no ifsfx.pyi beside the module"
      expect_python "$prefix/lib/python3/dist-packages"
    fi
    "$prefix/bin/ifsfx" render "$prefix/share/ifsfx/presets/koch-curve.toml" --size 64x32 \
      --quality 4 -q -o koch.png || fail "render of an installed preset file"
    # The man page: every command and every option of its --help, and no roff warnings.
    man=$prefix/share/man/man1/ifsfx.1
    [ -f "$man" ] || fail "no man page"
    commands=$("$built_ifsfx" --help | sed -n '/^Subcommands:/,$p' | awk '/^  [a-z]/ { print $1 }')
    [ "$(echo "$commands" | wc -l)" -ge 7 ] || fail "ifsfx --help lists: $commands"
    for c in $commands; do
      section=$(awk -v c="$c" '$0 == ".SS " c { on = 1; next } /^\.S[SH] / { on = 0 } on' "$man")
      [ -n "$section" ] || fail "man page: no section for '$c'"
      for option in $("$built_ifsfx" "$c" --help | awk '/^  -/ { print $1 }' | tr , ' '); do
        case $option in -h | --help | --help-all) continue ;; esac
        grep -qF -- "\\fB${option//-/\\-}\\fR" <<<"$section" || fail "man page: '$c' lacks $option"
      done
    done
    # A command's own subcommands (farm filter, ...): a section each, with every option.
    for c in $commands; do
      for s in $("$built_ifsfx" "$c" --help | sed -n '/^Subcommands:/,$p' | awk '/^  [a-z]/ { print $1 }'); do
        section=$(awk -v c=".SS \"$c $s\"" '$0 == c { on = 1; next } /^\.S[SH] / { on = 0 } on' "$man")
        [ -n "$section" ] || fail "man page: no section for '$c $s'"
        for option in $("$built_ifsfx" "$c" "$s" --help | awk '/^  -/ { print $1 }' | tr , ' '); do
          case $option in -h | --help | --help-all) continue ;; esac
          grep -qF -- "\\fB${option//-/\\-}\\fR" <<<"$section" || fail "man page: '$c $s' lacks $option"
        done
      done
    done
    preconv "$man" | groff -man -ww -z 2>roff.txt
    [ ! -s roff.txt ] || fail "roff warnings: $(cat roff.txt)"
    # The bash completion: commands, options, the choices of --mode, preset names.
    completion=$prefix/share/bash-completion/completions/ifsfx
    complete_words() {
      bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
               _ifsfx; echo "${COMPREPLY[*]}"' _ "$completion" "$@"
    }
    [ "$(complete_words ifsfx ren)" = render ] || fail "completion of 'ren': $(complete_words ifsfx ren)"
    [ "$(complete_words ifsfx render --mode '')" = "attractor measure steal tops" ] ||
      fail "completion of --mode: $(complete_words ifsfx render --mode '')"
    [ "$(complete_words ifsfx render --save-m)" = --save-map ] || fail "completion of --save-m"
    [ "$(complete_words ifsfx render --save-f)" = --save-flame ] || fail "completion of --save-f"
    [ "$(complete_words ifsfx texture paper)" = paper-fig4 ] || fail "completion of a superpreset"
    [ "$(complete_words ifsfx filter --preset maple)" = maple-leaf ] || fail "completion of --preset"
    ;;

  consumer)
    scratch
    # Only the prefix: no package registry, and the package found must be the prefix's.
    cmake -S "$src/examples/consumer" -B consumer -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DCMAKE_BUILD_TYPE=Release >configure.log 2>&1 ||
      { cat configure.log; fail "configure examples/consumer"; }
    grep -q "^ifsfx_DIR:PATH=$prefix/" consumer/CMakeCache.txt ||
      fail "found $(grep '^ifsfx_DIR' consumer/CMakeCache.txt)"
    cmake --build consumer >build.log 2>&1 || { cat build.log; fail "build examples/consumer"; }
    consumer/fern_steal "$photo" fern.png 320x240 >fern.txt || fail "fern_steal"
    # The fern covers 14.3 % of a 320x240 frame; the picture is the command's, pixel for pixel.
    coverage=$(sed -n 's/.*coverage \([0-9.]*\)$/\1/p' fern.txt)
    awk -v c="$coverage" 'BEGIN { exit !(c > 0.13 && c < 0.16) }' || fail "coverage: $(cat fern.txt)"
    "$prefix/bin/ifsfx" render barnsley-fern --mode steal --exact --source "$photo" --size 320x240 \
      -q -o fern-command.ppm
    idiff fern.png fern-command.ppm >idiff.txt 2>&1 || fail "fern_steal's picture: $(cat idiff.txt)"
    oiiotool --stats fern.png | grep -q 'Constant: No' || fail "fern.png is one colour"
    ;;

  pkg_config)
    scratch
    export PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name ifsfx.pc)")
    pkg-config --exists --print-errors ifsfx || fail "pkg-config ifsfx"
    [ -f "$(pkg-config --variable=includedir ifsfx)/ifs/steal_map.h" ] || fail "includedir"
    [ -f "$(pkg-config --variable=libdir ifsfx)/libifsfx_ifs.a" ] || fail "libdir"
    # One function of each library: the link line must bring every library they use.
    cat >program.cpp <<'CPP'
#include <cstdio>

#include "collage/distance.h"
#include "ifs/preset.h"
#include "superifs/superifs_file.h"
#include "video/file_source.h"

int main() {
  const auto fern = ifsfx::load_ifs("barnsley-fern");
  const auto fig4 = ifsfx::load_superifs("paper-fig4");
  const cv::Mat dot = cv::Mat::eye(8, 8, CV_8U) * 255;
  ifsfx::video::silence_libav_log();
  std::printf("%zu %zu %g\n", fern.ifs.size(), fig4.super.ifs.size(),
              ifsfx::collage::hausdorff(dot, dot));
}
CPP
    # shellcheck disable=SC2046
    g++ -std=c++20 program.cpp -o program $(pkg-config --cflags --libs ifsfx) >build.log 2>&1 ||
      { cat build.log; fail "compile and link with pkg-config"; }
    [ "$(./program)" = "4 2 0" ] || fail "program printed '$(./program)'"
    ;;

  headers)
    scratch
    include=$prefix/include/ifsfx
    headers=$(cd "$include" && find . -type f | sed 's|^\./||' | sort)
    [ "$(echo "$headers" | grep -c '^ifs/')" -ge 10 ] || fail "installed headers: $headers"
    # Internals stay home: detail/, the app, FFmpeg's types.
    ! echo "$headers" | grep -E '(^|/)detail/|^apps/|\.cpp$' || fail "private files installed"
    ! grep -l '#include <lib\(av\|sw\)' -r "$include" || fail "headers that include FFmpeg's"
    for h in $headers; do
      for inc in $(sed -n 's/^#include "\(.*\)"/\1/p' "$include/$h"); do
        [ -f "$include/$inc" ] || fail "$h includes $inc, which is not installed"
      done
    done
    # Against the prefix alone (no source tree on the path): each header's includes resolve by
    # themselves (the preprocessor, quick), and all of them compile in one unit with our warnings
    # as errors (the libraries' headers are system headers: OpenCV's warn in C++20). Compiling
    # every header alone would take a minute of CPU for what the first step already proves.
    export PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name ifsfx.pc)")
    others=$(pkg-config --cflags ifsfx | tr ' ' '\n' | grep -v '/include/ifsfx$' | sed 's/^-I/-isystem /')
    flags=(-std=c++20 -I"$include" $others)
    for h in $headers; do
      printf '#include "%s"\n' "$h" | g++ "${flags[@]}" -E -x c++ - -o /dev/null 2>err.txt ||
        fail "$h alone: $(cat err.txt)"
      printf '#include "%s"\n' "$h" >>all.cpp
    done
    g++ "${flags[@]}" -fsyntax-only -Wall -Wextra -Wpedantic -Werror all.cpp 2>err.txt ||
      fail "the installed headers together: $(cat err.txt)"
    ;;

  deb)
    scratch
    cpack --config "$build/CPackConfig.cmake" -B "$PWD" >cpack.log 2>&1 || { cat cpack.log; fail cpack; }
    version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$build/CPackConfig.cmake")
    arch=$(dpkg --print-architecture)
    deb=ifsfx_${version}_$arch.deb dev=ifsfx-dev_${version}_$arch.deb
    [ -f "$deb" ] && [ -f "$dev" ] || fail "packages: $(ls ./*.deb)"
    dpkg-deb -c "$deb" | awk '{ print $6 }' >deb-files.txt
    dpkg-deb -c "$dev" | awk '{ print $6 }' >dev-files.txt
    for f in ./usr/bin/ifsfx ./usr/libexec/ifsfx/ifsfx-full ./usr/share/man/man1/ifsfx.1 \
             ./usr/share/bash-completion/completions/ifsfx \
             ./usr/share/ifsfx/presets/barnsley-fern.toml ./usr/share/doc/ifsfx/README.md \
             ./usr/share/doc/ifsfx/copyright ./usr/share/doc/ifsfx/docs/design.md; do
      grep -qx -- "$f" deb-files.txt || fail "$deb lacks $f"
    done
    # The frei0r plugins (built where frei0r.h is installed) ship with the command.
    if [ -f "$build/plugins/frei0r/ifsfx.so" ]; then
      for f in ./usr/lib/frei0r-1/ifsfx.so ./usr/lib/frei0r-1/ifsfx-texture.so \
               ./usr/share/kdenlive/effects/frei0r_ifsfx.xml; do
        grep -qx -- "$f" deb-files.txt || fail "$deb lacks $f"
      done
    fi
    # The OBS filter (built where libobs-dev is installed) is a package of its own, in OBS's
    # folders, depending on libobs0; the command's package does not.
    if [ -f "$build/plugins/obs/ifsfx-obs.so" ]; then
      obs_deb=obs-ifsfx_${version}_$arch.deb
      [ -f "$obs_deb" ] || fail "packages: $(ls ./*.deb)"
      multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
      for f in ./usr/lib/$multiarch/obs-plugins/ifsfx-obs.so \
               ./usr/share/obs/obs-plugins/ifsfx-obs/locale/en-US.ini; do
        dpkg-deb -c "$obs_deb" | awk '{ print $6 }' | grep -qx -- "$f" || fail "$obs_deb lacks $f"
      done
      dpkg-deb -f "$obs_deb" Depends | grep -q libobs0 || fail "$obs_deb does not depend on libobs0"
      ! dpkg-deb -f "$deb" Depends | grep -q libobs || fail "$deb depends on libobs"
    fi
    ! grep -E '^\./usr/(include|lib)/' deb-files.txt | grep -Ev '^\./usr/lib/(frei0r-1/.*)?$' ||
      fail "$deb holds development files"
    for f in ./usr/include/ifsfx/ifs/steal_map.h 'libifsfx_ifs\.a' 'cmake/ifsfx/ifsfxConfig\.cmake' \
             'pkgconfig/ifsfx\.pc'; do
      grep -q -- "$f\$" dev-files.txt || fail "$dev lacks $f"
    done
    grep -qx -- ./usr/share/doc/ifsfx-dev/copyright dev-files.txt || fail "$dev lacks its copyright"
    ! grep -E '^\./usr/(bin|share)/' dev-files.txt | grep -Ev '^\./usr/share/(doc/(ifsfx-dev/.*)?)?$' ||
      fail "$dev holds the command's files"
    [ "$(dpkg-deb -f "$deb" Package)" = ifsfx ] && [ "$(dpkg-deb -f "$deb" Section)" = graphics ] ||
      fail "fields: $(dpkg-deb -f "$deb")"
    # No maintainer scripts of ours: the control archive holds control and md5sums, and at most
    # the postinst/postrm that CPack adds for shared objects under /usr/lib (the frei0r plugins),
    # which run ldconfig and nothing else.
    ! dpkg-deb --ctrl-tarfile "$deb" | tar -t | grep -Ev '^\./(control|md5sums|postinst|postrm)?$' ||
      fail "$deb has maintainer scripts"
    for script in postinst postrm; do
      body=$(dpkg-deb --ctrl-tarfile "$deb" | tar -xO "./$script" 2>/dev/null | grep -Ev '^(#!|set -e|if |fi|$)') || true
      [ -z "$body" ] || [ "$(echo $body)" = ldconfig ] || fail "$deb $script does more than ldconfig: $body"
    done
    # Depends, from dpkg-shlibdeps: the package of every library the two binaries link to.
    depends=$(dpkg-deb -f "$deb" Depends)
    [ -n "$depends" ] || fail "$deb has no Depends"
    multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
    for lib in $(objdump -p "$built_ifsfx" "$built_full" | awk '$1 == "NEEDED" { print $2 }' | sort -u); do
      owner=$(dpkg -S "*/$multiarch/$lib" 2>/dev/null | head -1 | sed 's/[:,].*//') || true
      [ -n "$owner" ] || fail "no installed package holds $lib"
      [[ ", $depends," == *", $owner "* || ", $depends," == *", $owner,"* ]] ||
        fail "Depends lacks $owner (for $lib): $depends"
    done
    dpkg-deb -f "$dev" Depends | grep -q 'libopencv-dev' || fail "$dev Depends: $(dpkg-deb -f "$dev")"
    # The Python module (built when pybind11 is installed) in its own package, python3-ifsfx.
    python_deb=python3-ifsfx_${version}_$arch.deb
    if ls "$build"/python/ifsfx.cpython-*.so >/dev/null 2>&1; then
      [ -f "$python_deb" ] || fail "packages: $(ls ./*.deb)"
      dpkg-deb -c "$python_deb" | awk '{ print $6 }' >python-files.txt
      grep -qx './usr/lib/python3/dist-packages/ifsfx.pyi' python-files.txt &&
        grep -q '^\./usr/lib/python3/dist-packages/ifsfx\.cpython-.*\.so$' python-files.txt ||
        fail "$python_deb: $(cat python-files.txt)"
      [ "$(dpkg-deb -f "$python_deb" Section)" = python ] || fail "fields: $(dpkg-deb -f "$python_deb")"
      dpkg-deb -f "$python_deb" Depends | grep -q 'python3-numpy' ||
        fail "$python_deb Depends: $(dpkg-deb -f "$python_deb" Depends)"
      dpkg-deb -x "$python_deb" root
      expect_python "$PWD/root/usr/lib/python3/dist-packages"
    fi
    # Unpacked into a scratch root: the command runs from there, with no library path.
    dpkg-deb -x "$deb" root && dpkg-deb -x "$dev" root
    expect_command "$PWD/root/usr/bin/ifsfx"
    # ifsfx.pc finds the package's own files wherever it lies.
    export PKG_CONFIG_PATH=$(dirname "$(find root -name ifsfx.pc)")
    [ -f "$(pkg-config --variable=libdir ifsfx)/libifsfx_video.a" ] || fail "ifsfx.pc's libdir"
    [ -f "$(pkg-config --variable=includedir ifsfx)/video/pipeline.h" ] || fail "ifsfx.pc's includedir"
    ;;

  *) fail "unknown check '$check'" ;;
esac
echo "install $check: ok"
