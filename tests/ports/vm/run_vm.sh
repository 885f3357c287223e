#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Boots Debian's kernel under qemu-system-x86_64 (software emulation) with a
# tiny initramfs: busybox, the hid/uhid/hid-generic modules of that kernel,
# the MCP2210 model on /dev/uhid (static) and zspan-mcp2210 (dynamic, with
# hidapi-hidraw, libudev and libc copied in). The init script runs three
# phases (see init.sh) and powers off.
#
#   run_vm.sh WORKDIR MODEL_BIN CLIENT_BIN
#
# Writes WORKDIR/console.log (ttyS0: kernel, init and client output) and
# WORKDIR/ttyS1.bin (the model's picture dumps). Exit status: 0 when the VM
# ran to its end marker, 77 when something needed is missing (skip), 1 else.
# Environment: ZS_VM_KERNEL (a vmlinuz; default: the newest /boot/vmlinuz-*,
# cloud flavour first), ZS_VM_TIMEOUT (seconds, default 240), QEMU
# (default qemu-system-x86_64).
set -u

work=$1 model=$2 client=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
qemu=${QEMU:-qemu-system-x86_64}
timeout_s=${ZS_VM_TIMEOUT:-240}

skip() { echo "SKIPPED: $*"; exit 77; }

command -v "$qemu" >/dev/null 2>&1 || skip "$qemu not installed (Debian: qemu-system-x86)"
command -v cpio >/dev/null 2>&1 || skip "cpio not installed"
[ -x /bin/busybox ] && ldd /bin/busybox 2>&1 | grep -q 'not a dynamic' ||
    skip "a static /bin/busybox is needed (Debian: busybox-static)"

kernel=${ZS_VM_KERNEL:-}
if [ -z "$kernel" ]; then
    kernel=$(ls -1 /boot/vmlinuz-*-cloud-amd64 2>/dev/null | sort -V | tail -1)
    [ -n "$kernel" ] || kernel=$(ls -1 /boot/vmlinuz-* 2>/dev/null | sort -V | tail -1)
fi
[ -n "$kernel" ] && [ -r "$kernel" ] || skip "no kernel image in /boot (Debian: linux-image-cloud-amd64)"
kver=${kernel##*/vmlinuz-}
moddir=/lib/modules/$kver
[ -r "$moddir/modules.dep" ] || skip "no modules for $kver in $moddir"

rm -rf "$work/root"
mkdir -p "$work/root"/{bin,dev,proc,sys,tmp,lib/modules,etc}
root=$work/root

# Modules (and what they depend on, dependencies first). Built-in ones
# (modules.builtin) need nothing.
declare -A seen=()
order=()
add_module() {
    local name=$1 line path deps d
    if grep -q "/$name.ko" "$moddir/modules.builtin" 2>/dev/null; then return 0; fi
    line=$(grep -E "(^|/)$name\.ko[^:]*:" "$moddir/modules.dep" | head -1)
    [ -n "$line" ] || { echo "run_vm: module $name not found for $kver"; return 1; }
    path=${line%%:*}
    [ -n "${seen[$path]:-}" ] && return 0
    deps=${line#*:}
    for d in $deps; do
        d=${d##*/}
        add_module "${d%%.ko*}" || return 1
    done
    seen[$path]=1
    order+=("$path")
}
for m in hid uhid hid-generic; do
    add_module "$m" || skip "kernel $kver lacks the $m module"
done
: > "$root/modules.order"
for p in "${order[@]}"; do
    f=${p##*/}
    case "$f" in
    *.ko) cp "$moddir/$p" "$root/lib/modules/$f" ;;
    *.ko.xz) xz -dc "$moddir/$p" > "$root/lib/modules/${f%.xz}"; f=${f%.xz} ;;
    *.ko.zst) zstd -qdc "$moddir/$p" > "$root/lib/modules/${f%.zst}"; f=${f%.zst} ;;
    *.ko.gz) gzip -dc "$moddir/$p" > "$root/lib/modules/${f%.gz}"; f=${f%.gz} ;;
    esac
    echo "$f" >> "$root/modules.order"
done

cp /bin/busybox "$root/bin/busybox"
cp "$model" "$root/bin/mcp2210-uhid"
cp "$client" "$root/bin/zspan-mcp2210"
# The client's shared libraries at the same paths (and the loader).
ldd "$client" | awk '/=> \//{print $3} /^[[:space:]]*\/[^ ]+ \(/{print $1}' | while read -r lib; do
    mkdir -p "$root$(dirname "$lib")"
    cp -L "$lib" "$root$lib"
done
cp "$here/init.sh" "$root/init"
chmod 755 "$root/init" "$root/bin/"*

(cd "$root" && find . | cpio -o -H newc --quiet) > "$work/initrd.cpio" ||
    { echo "run_vm: cpio failed"; exit 1; }

rm -f "$work/console.log" "$work/ttyS1.bin"
echo "run_vm: kernel $kernel, initramfs $(du -k "$work/initrd.cpio" | cut -f1) KB, timeout ${timeout_s}s"
start=$(date +%s)
timeout -k 5 "$timeout_s" "$qemu" -machine pc -accel tcg -cpu max -m 384 -smp 1 \
    -display none -monitor none -no-reboot \
    -serial "file:$work/console.log" -serial "file:$work/ttyS1.bin" \
    -kernel "$kernel" -initrd "$work/initrd.cpio" \
    -append "console=ttyS0 panic=-1 quiet loglevel=4 rdinit=/init" </dev/null
rc=$?
echo "run_vm: qemu exited $rc after $(( $(date +%s) - start )) s"
if grep -q '^ZSVM done' "$work/console.log" 2>/dev/null; then
    exit 0
fi
echo "run_vm: the VM did not reach its end marker; console:"
tail -40 "$work/console.log" 2>/dev/null
exit 1
