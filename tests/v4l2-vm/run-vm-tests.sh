#!/bin/bash
# SPDX-License-Identifier: Apache-2.0
# run-vm-tests.sh — real V4L2 devices for tests, on a machine whose own kernel has none.
#
# Boots Debian 12's stock kernel (extracted from its .deb, never installed) in QEMU, loads the
# kernel's vivid driver (a virtual webcam: capture and output nodes) and v4l2loopback (built from
# Debian's v4l2loopback-dkms source against the matching headers), and runs COMMAND inside the
# guest ONCE, with the host's root filesystem visible read-only at the same paths (writable through
# a throw-away tmpfs overlay). One boot serves every check: software emulation costs ~20 s a boot.
#
#   tests/v4l2-vm/run-vm-tests.sh [--workdir DIR] [--cache DIR] [--timeout S] -- COMMAND [ARG...]
#
# In the guest, COMMAND runs in the caller's working directory with
#   V4L2_CAPTURE_DEV   vivid's capture node (webcam input selected)
#   V4L2_OUTPUT_DEV    vivid's output node
#   V4L2_LOOPBACK_DEV  the v4l2loopback node (/dev/video10)
#   VM_SHARE           a directory shared read-write with the host (WORKDIR/share): artefacts
# Exit status: 0 only when the guest booted, both drivers gave their nodes, vivid streamed, and
# COMMAND exited 0. Anything else — packages that cannot be installed, a kernel that cannot be
# fetched, a VM that does not boot or times out — prints FAIL with the reason and exits 1: this
# script never passes a test it could not run.
#
# Needs root when a Debian package is missing (it installs qemu-system-x86, busybox-static,
# v4l-utils, kmod, cpio, gzip, xz-utils, make, gcc and linux-headers-<kver> with apt-get).
# Knobs (environment): ACCEL=auto|kvm|tcg, CPU (QEMU CPU model under tcg, max), SMP (2),
# MEM (MiB, 1536), BOOT_TIMEOUT (s, 240), SKIP_APT=1.
set -euo pipefail

fail() { echo "FAIL: $*" >&2; exit 1; }

SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
WORKDIR=${TMPDIR:-/tmp}/ifsfx-v4l2-vm
CACHE=${XDG_CACHE_HOME:-${HOME:-/root}/.cache}/ifsfx-v4l2-vm
TIMEOUT=600
while [ $# -gt 0 ]; do
    case "$1" in
        --workdir) WORKDIR=$2; shift 2 ;;
        --cache) CACHE=$2; shift 2 ;;
        --timeout) TIMEOUT=$2; shift 2 ;;
        --) shift; break ;;
        -h|--help) sed -n '3,26p' "$0"; exit 0 ;;
        *) fail "unknown option $1 (usage: $0 [--workdir DIR] [--cache DIR] [--timeout S] -- COMMAND...)" ;;
    esac
done
[ $# -gt 0 ] || fail "no guest command given (usage: $0 [options] -- COMMAND...)"
GUEST_ARGS=("$@")
ACCEL=${ACCEL:-auto}
SMP=${SMP:-2}
MEM=${MEM:-1536}
SKIP_APT=${SKIP_APT:-0}
SHARE=$WORKDIR/share

T0=$(date +%s.%N)
stamp() { awk -v a="$T0" -v b="$(date +%s.%N)" -v m="$*" 'BEGIN{printf "[%6.1fs] %s\n", b-a, m}'; }

mkdir -p "$WORKDIR" "$CACHE"
rm -rf "$SHARE"
mkdir -p "$SHARE"
# Concurrent runs (two build folders) share the cache: one at a time fills it.
exec 9>"$CACHE/.lock"
flock 9

# ------------------------------------------------------------------------------------ packages
installed() { dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null | grep -q "ok installed"; }
apt_install() {
    [ "$SKIP_APT" != 1 ] || fail "missing Debian packages: $* (SKIP_APT=1 set)"
    [ "$(id -u)" = 0 ] || fail "missing Debian packages: $*; run as root or: apt-get install $*"
    stamp "apt-get install $*"
    local apt=(apt-get -o DPkg::Lock::Timeout=600 -o APT::Sandbox::User=root -qq)
    "${apt[@]}" update || fail "apt-get update failed"
    DEBIAN_FRONTEND=noninteractive "${apt[@]}" install -y --no-install-recommends "$@" >/dev/null \
        || fail "apt-get install $* failed"
}
missing=()
for p in qemu-system-x86 busybox-static v4l-utils kmod cpio gzip xz-utils make gcc; do
    installed "$p" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] || apt_install "${missing[@]}"
if ! apt-cache show linux-image-amd64 >/dev/null 2>&1; then
    [ "$(id -u)" = 0 ] || fail "apt has no package lists (run apt-get update as root)"
    apt-get -o DPkg::Lock::Timeout=600 -qq update || fail "apt-get update failed"
fi
stamp "packages ready"

# ---------------------------------------------------------------- Debian kernel (extracted only)
KPKG=$(apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/{print $2; exit}')
[ -n "$KPKG" ] || fail "cannot resolve linux-image-amd64 to a kernel package"
KDIR=$CACHE/kernel/$KPKG
if [ ! -e "$KDIR/.done" ]; then
    stamp "fetching $KPKG"
    rm -rf "$KDIR"
    mkdir -p "$KDIR"
    (cd "$KDIR" && apt-get -o APT::Sandbox::User=root -qq download "$KPKG" && dpkg-deb -x ./*.deb root && rm -f ./*.deb) \
        || fail "cannot download or unpack $KPKG"
    depmod -b "$KDIR/root" "$(ls "$KDIR/root/lib/modules")"
    touch "$KDIR/.done"
fi
KROOT=$KDIR/root
KVER=$(ls "$KROOT/lib/modules")
KERNEL=$KROOT/boot/vmlinuz-$KVER
[ -r "$KERNEL" ] || fail "no kernel image at $KERNEL"
stamp "kernel $KVER"

# ----------------------------------------------------- v4l2loopback, built for that kernel
LBDIR=$CACHE/v4l2loopback-$KVER
if [ ! -e "$LBDIR/.done" ]; then
    installed "linux-headers-$KVER" || apt_install "linux-headers-$KVER"
    stamp "building v4l2loopback for $KVER"
    rm -rf "$LBDIR"
    mkdir -p "$LBDIR"
    (cd "$LBDIR" && apt-get -o APT::Sandbox::User=root -qq download v4l2loopback-dkms && dpkg-deb -x ./v4l2loopback-dkms_*.deb x && rm -f ./*.deb) \
        || fail "cannot download v4l2loopback-dkms"
    SRC=$(ls -d "$LBDIR"/x/usr/src/v4l2loopback-*)
    make -s -C "/usr/src/linux-headers-$KVER" M="$SRC" modules >"$LBDIR/build.log" 2>&1 \
        || { tail -20 "$LBDIR/build.log"; fail "v4l2loopback build failed"; }
    cp "$SRC/v4l2loopback.ko" "$LBDIR/"
    touch "$LBDIR/.done"
fi
flock -u 9

# ------------------------------------------------------------------------------------ initramfs
IRD=$WORKDIR/initramfs
rm -rf "$IRD"
mkdir -p "$IRD"/{bin,mods,proc,sys,dev,lower,rw,newroot}
BUSYBOX=$(command -v busybox) || fail "no busybox"
LDD_OUT=$(ldd "$BUSYBOX" 2>&1 || true)
echo "$LDD_OUT" | grep -qE "not a dynamic|statically linked" || fail "$BUSYBOX is not static (install busybox-static)"
cp "$BUSYBOX" "$IRD/bin/busybox"
: >"$IRD/modules.list"
modprobe -d "$KROOT" -S "$KVER" --show-depends -a virtio_pci 9pnet_virtio 9p overlay vivid \
    | awk '$1=="insmod"{print $2}' | awk '!seen[$0]++' >"$WORKDIR/modules.paths" \
    || fail "cannot resolve the guest kernel modules"
while read -r m; do
    b=$(basename "$m")
    case "$b" in
        *.ko.xz) xz -dc "$m" >"$IRD/mods/${b%.xz}"; b=${b%.xz} ;;
        *.ko.zst) zstd -qdc "$m" >"$IRD/mods/${b%.zst}"; b=${b%.zst} ;;
        *) cp "$m" "$IRD/mods/$b" ;;
    esac
    echo "$b" >>"$IRD/modules.list"
done <"$WORKDIR/modules.paths"
grep -q '^vivid.ko$' "$IRD/modules.list" || fail "the kernel has no vivid module"
cp "$LBDIR/v4l2loopback.ko" "$IRD/mods/"
echo v4l2loopback.ko >>"$IRD/modules.list"
# vivid: one instance with a capture and an output node, single-planar API; v4l2loopback: one
# node, /dev/video10, that both a producer (output) and readers (capture) open.
cat >"$IRD/config" <<EOF
SHARE='$SHARE'
VIVID_OPTS='n_devs=1 node_types=0x101 multiplanar=1'
LOOPBACK_OPTS='devices=1 video_nr=10 card_label=ifsfx-loopback'
EOF
cat >"$IRD/init" <<'EOF'
#!/bin/busybox sh
/bin/busybox --install -s /bin
export PATH=/bin
. /config
mount -t proc proc /proc; mount -t sysfs sysfs /sys; mount -t devtmpfs devtmpfs /dev
for m in $(cat /modules.list); do
    opts=""; [ "$m" = vivid.ko ] && opts="$VIVID_OPTS"; [ "$m" = v4l2loopback.ko ] && opts="$LOOPBACK_OPTS"
    insmod /mods/$m $opts || echo "guest-init: insmod $m FAILED"
done
mount -t 9p -o trans=virtio,version=9p2000.L,ro,msize=262144,cache=loose hostroot /lower \
    || { echo "guest-init: mount of the host root FAILED"; poweroff -f; }
mount -t tmpfs -o mode=755 tmpfs /rw; mkdir -p /rw/upper /rw/work
mount -t overlay overlay -o lowerdir=/lower,upperdir=/rw/upper,workdir=/rw/work /newroot \
    || { echo "guest-init: overlay FAILED"; poweroff -f; }
R=/newroot
mount -t proc proc $R/proc; mount -t sysfs sysfs $R/sys; mount -t devtmpfs devtmpfs $R/dev
# /tmp stays the overlay's (writable in the guest, host contents visible): a checkout or build
# folder under the host's /tmp, as a CI clone may be, must be reachable from the guest.
mount -t tmpfs tmpfs $R/run
mkdir -p $R/dev/shm $R/dev/pts; mount -t tmpfs tmpfs $R/dev/shm; mount -t devpts devpts $R/dev/pts
ln -sf /proc/self/fd $R/dev/fd; ln -sf /proc/self/fd/0 $R/dev/stdin
ln -sf /proc/self/fd/1 $R/dev/stdout; ln -sf /proc/self/fd/2 $R/dev/stderr
mkdir -p $R$SHARE
mount -t 9p -o trans=virtio,version=9p2000.L,msize=262144 share $R$SHARE \
    || { echo "guest-init: mount of the share FAILED"; poweroff -f; }
echo "guest-init: root ready at $(cut -d' ' -f1 /proc/uptime)s"
chroot $R /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root TERM=dumb /bin/bash $SHARE/guest.sh
sync; poweroff -f
EOF
chmod +x "$IRD/init"
(cd "$IRD" && find . | cpio -o -H newc 2>/dev/null | gzip -1) >"$WORKDIR/initrd.gz"
stamp "initramfs ready ($(wc -l <"$IRD/modules.list") modules)"

# ----------------------------------------------------------------------------- guest script
{
    printf 'GUEST_CWD=%q\n' "$PWD"
    printf 'GUEST_ARGS=('; printf '%q ' "${GUEST_ARGS[@]}"; printf ')\n'
    printf 'SHARE=%q\n' "$SHARE"
} >"$SHARE/guest-env.sh"
cat >"$SHARE/guest.sh" <<'EOF'
. "$(dirname "$0")/guest-env.sh"
verdict() { echo "IFSFX-VM-RESULT $1"; exit 0; }
CAP=""; OUT=""; LB=""
for n in /sys/class/video4linux/video*; do
    case "$(cat "$n/name")" in
        *vid-cap) CAP=/dev/$(basename "$n") ;;
        *vid-out) OUT=/dev/$(basename "$n") ;;
        ifsfx-loopback) LB=/dev/$(basename "$n") ;;
    esac
done
echo "guest: $(uname -r): capture=$CAP output=$OUT loopback=$LB"
[ -n "$CAP" ] && [ -n "$OUT" ] || verdict "FAIL vivid gave no capture/output node"
[ -n "$LB" ] || verdict "FAIL v4l2loopback gave no node"
# Sanity: vivid's webcam input streams at all (else every check below would fail for one reason).
v4l2-ctl -d "$CAP" -i 0 >/dev/null
v4l2-ctl -d "$CAP" --stream-mmap --stream-count=3 --stream-to=/tmp/sanity.raw >/dev/null 2>&1 \
    && [ -s /tmp/sanity.raw ] || verdict "FAIL vivid capture does not stream"
# Under software emulation AVX is emulated instruction by instruction and glibc's AVX2 string
# functions (the dynamic linker's symbol lookups above all) run slower than the SSE2 ones: keep
# glibc on SSE2. Our own code keeps whatever instruction set it was built for.
export GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-AVX_Fast_Unaligned_Load
echo "guest: running ${GUEST_ARGS[*]}"
cd "$GUEST_CWD" || verdict "FAIL no $GUEST_CWD in the guest"
V4L2_CAPTURE_DEV=$CAP V4L2_OUTPUT_DEV=$OUT V4L2_LOOPBACK_DEV=$LB VM_SHARE=$SHARE "${GUEST_ARGS[@]}"
rc=$?
[ $rc -eq 0 ] && verdict "PASS" || verdict "FAIL guest command exited $rc"
EOF

# ----------------------------------------------------------------------------------------- boot
case "$ACCEL" in
    auto) if [ -r /dev/kvm ] && [ -w /dev/kvm ] && grep -qwE 'vmx|svm' /proc/cpuinfo; then ACCEL=kvm; else ACCEL=tcg; fi ;;
esac
ACCEL_ARGS=(-accel tcg,thread=multi)
[ "$ACCEL" = kvm ] && ACCEL_ARGS=(-accel kvm -cpu host)
# TCG: any CPU model runs the default (portable) build, which picks its kernels from CPUID (scalar
# or AVX2 under QEMU, whatever the host has, AVX-512 included). A -DIFSFX_NATIVE=ON build carries
# the host's instruction set and fails here when TCG cannot emulate it (AVX-512).
[ "$ACCEL" = tcg ] && ACCEL_ARGS+=(-cpu "${CPU:-max}")
LOG=$WORKDIR/serial.log
stamp "booting QEMU ($ACCEL, $SMP cpu, $MEM MiB), log in $LOG"
: >"$LOG"
rm -f "$WORKDIR/qemu.pid" "$WORKDIR/qemu.rc"
set +e
(
    timeout "$TIMEOUT" qemu-system-x86_64 "${ACCEL_ARGS[@]}" -M pc -smp "$SMP" -m "$MEM" \
        -nodefaults -no-user-config -display none -serial stdio -no-reboot \
        -pidfile "$WORKDIR/qemu.pid" \
        -kernel "$KERNEL" -initrd "$WORKDIR/initrd.gz" \
        -append "console=ttyS0 panic=-1 quiet loglevel=3" \
        -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
        -virtfs "local,path=$SHARE,mount_tag=share,security_model=none,multidevs=remap" \
        </dev/null 2>&1 | sed -u 's/\x1b\[[0-9;?]*[a-zA-Z]//g; s/\x1bc//g' | tee -a "$LOG"
    echo "${PIPESTATUS[0]}" >"$WORKDIR/qemu.rc"
) &
RUNNER=$!
# A guest that has not reached its root filesystem by BOOT_TIMEOUT will not: stop it early.
BOOT_TIMEOUT=${BOOT_TIMEOUT:-240}
WAITED=0
while kill -0 "$RUNNER" 2>/dev/null; do
    if [ "$WAITED" -ge "$BOOT_TIMEOUT" ] && ! grep -q "guest-init: root ready" "$LOG"; then
        echo "run-vm-tests: no guest root after ${BOOT_TIMEOUT}s, stopping QEMU" >&2
        [ -s "$WORKDIR/qemu.pid" ] && kill "$(cat "$WORKDIR/qemu.pid")" 2>/dev/null
        break
    fi
    sleep 1
    WAITED=$((WAITED + 1))
done
wait "$RUNNER"
QRC=$(cat "$WORKDIR/qemu.rc" 2>/dev/null || echo "?")
set -e
stamp "QEMU exited ($QRC)"
[ "$QRC" != 124 ] || fail "the VM ran past ${TIMEOUT}s and was stopped"
grep -q "guest-init: root ready" "$LOG" || fail "the VM did not boot (see $LOG)"
RESULT=$(tr -d '\r' <"$LOG" | sed -n 's/^IFSFX-VM-RESULT //p' | tail -1)
[ -n "$RESULT" ] || fail "the guest stopped without a result (see $LOG)"
[ "$RESULT" = PASS ] || fail "${RESULT#FAIL }"
echo PASS
