#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The portable ifsfx on other CPUs: run under QEMU's user-mode emulation with a baseline x86-64
# model (qemu64: SSE2, no AVX) and an AVX2 model (Haswell), it picks the scalar and the AVX2
# kernels, never dies of an illegal instruction, and renders measure, tops and steal images
# byte-identical to the native run (whatever level the host picked). A request above the CPU
# (IFSFX_CPU=avx2 on qemu64) is refused with one line. Small images: emulation is slow.
# IFSFX is the light binary (render to PNG); FULL, ifsfx-full, runs what the light one hands on
# (--version, steal), since a program it exec'd would run outside the emulator.
#   cpu_models_test.sh IFSFX FULL WORKDIR MODEL     (MODEL: qemu64 or Haswell)
set -euo pipefail
ifsfx=$1 full=$2 work=$3 model=$4
command -v qemu-x86_64 >/dev/null || { echo "SKIP: qemu-x86_64 not installed (Debian: qemu-user)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }

# run_with BINARY MODEL ARGS...: BINARY under emulation (MODEL "native": directly); QEMU's notes
# on CPU features TCG lacks are dropped from stderr. run: the light binary; run_full: ifsfx-full.
run_with() {
  local binary=$1 m=$2 rc=0
  shift 2
  if [ "$m" = native ]; then
    "$binary" "$@"
    return
  fi
  qemu-x86_64 -cpu "$m" "$binary" "$@" 2>qemu-stderr.txt || rc=$?
  grep -v "TCG doesn't support requested feature" qemu-stderr.txt >&2 || true
  return $rc
}
run() { run_with "$ifsfx" "$@"; }
run_full() { run_with "$full" "$@"; }

# The source image of the steal renders, made by ifsfx itself.
"$ifsfx" render maple-leaf --mode measure --size 80x60 --quality 16 -q -o source.png

renders() {  # MODEL: the images of every mode into MODEL-*.png
  local m=$1
  run "$m" render barnsley-fern --mode measure --size 96x72 --quality 32 --supersample 2 --seed 3 \
    --threads 2 -q -o "$m-measure.png"
  run "$m" render koch3 --mode measure --size 80x60 --quality 32 --seed 4 --threads 2 -q \
    -o "$m-measure5.png"
  run "$m" render barnsley-fern --mode tops --size 96x72 --quality 16 --seed 5 --threads 2 -q \
    -o "$m-tops.png"
  run "$m" render twin-dragon --mode tops --exact --size 64x48 --threads 2 -q -o "$m-tops-exact.png"
  run_full "$m" render barnsley-fern --mode steal --source source.png --size 96x72 --quality 16 \
    --seed 6 --threads 2 -q -o "$m-steal.png"
  run_full "$m" render maple-leaf --mode steal --exact --source source.png --size 64x48 \
    --threads 2 -q -o "$m-steal-exact.png"
}

native_level=$(run_full native --version | sed -n 's/^kernels: \([a-z0-9]*\) .*/\1/p')
echo "native: kernels $native_level"
renders native
case "$model" in
  qemu64) want=scalar ;;
  Haswell) want=avx2 ;;
  *) fail "unknown CPU model $model (qemu64 or Haswell)" ;;
esac
version=$(run_full "$model" --version) || fail "$model: ifsfx --version failed"
echo "$version" | grep -q "^kernels: $want " || fail "$model: expected the $want kernels: $version"
echo "$model: kernels $want"
renders "$model"
for native_image in native-*.png; do
  image=$model-${native_image#native-}
  cmp -s "$native_image" "$image" || fail "$model: $image differs from the native $native_image"
done

if [ "$model" = qemu64 ]; then
  # A level above the CPU is refused in one line, exit 2, not run into SIGILL.
  rc=0
  IFSFX_CPU=avx2 run qemu64 render barnsley-fern --size 32x32 -q -o refused.png 2>err.txt || rc=$?
  [ "$rc" -eq 2 ] || fail "IFSFX_CPU=avx2 on qemu64: exit $rc (want 2): $(cat err.txt)"
  [ "$(cat err.txt)" = "ifsfx: IFSFX_CPU: this CPU runs the kernel levels scalar only (got avx2)" ] ||
    fail "IFSFX_CPU=avx2 on qemu64: '$(cat err.txt)'"
  [ ! -e refused.png ] || fail "a refused render left refused.png"
fi
echo "PASS: $model ($want kernels) renders the native ($native_level) bytes in every mode"
