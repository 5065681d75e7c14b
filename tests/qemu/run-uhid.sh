#!/usr/bin/env bash
# Boots Debian's kernel in QEMU (TCG, no KVM needed) with the host's root
# over 9p and runs tests/qemu/guest.sh as init: a UHID gamepad (the F310's
# recorded descriptor) that the real hidapi backend enumerates, opens and
# reads, then loses when the device is destroyed. The issue's gpio-sim part
# is not possible with Debian 12's kernel (CONFIG_GPIO_SIM and
# CONFIG_GPIO_MOCKUP are not set), and no KMS device is tried (the display
# work's). Run after tests/test_input_walk.sh built the teaset pack.
#   run-uhid.sh BUILD_DIR SOURCE_DIR [KERNEL_VERSION]
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd) kver=${3:-$(ls /lib/modules | sort -V | tail -n 1)}
work=$build/tests/qemu && mkdir -p "$work"
[ -r "/boot/vmlinuz-$kver" ] || { echo "FAIL: no /boot/vmlinuz-$kver to boot (linux-image-amd64)"; exit 1; }
cc -O2 -I"$src/core" -I"$src/firmware" -o "$work/uhid_pad" "$src/tests/qemu/uhid_pad.c" \
  "$src/firmware/sw_input_timeline.c" "$src/core/sw_error.c" -lm
[ -f "$build/tests/input_walk/teaset.swpack" ] || { echo "run tests/test_input_walk.sh first"; exit 1; }

# The initramfs: busybox, the modules for 9p over virtio and UHID, an init
# that mounts the host root and hands over to guest.sh.
rd=$work/initramfs && rm -rf "$rd" && mkdir -p "$rd"/{bin,dev,proc,sys,newroot,modules}
cp /usr/bin/busybox "$rd/bin/busybox"
mods="virtio_ring virtio virtio_pci_legacy_dev virtio_pci_modern_dev virtio_pci netfs fscache"
mods="$mods 9pnet 9pnet_virtio 9p hid hid-generic uhid"
for m in $mods; do
  f=$(find "/lib/modules/$kver/kernel" -name "$m.ko*" | head -n 1)
  [ -n "$f" ] && cp "$f" "$rd/modules/"
done
cat > "$rd/init" <<INIT
#!/bin/busybox sh
/bin/busybox mount -t proc proc /proc; /bin/busybox mount -t sysfs sys /sys
for m in $mods; do /bin/busybox insmod /modules/\$m.ko || echo "insmod \$m failed"; done
/bin/busybox ls /sys/bus/virtio/devices; /bin/busybox cat /sys/bus/virtio/devices/*/mount_tag 2>/dev/null; echo
/bin/busybox mount -t 9p -o trans=virtio,version=9p2000.L,ro hostroot /newroot
exec /bin/busybox switch_root /newroot /bin/sh $src/tests/qemu/guest.sh $build $src
INIT
chmod +x "$rd/init"
(cd "$rd" && find . | cpio -o -H newc --quiet) > "$work/initramfs.cpio"

timeout 900 qemu-system-x86_64 -m 1024 -smp 2 -nographic -no-reboot \
  -kernel "/boot/vmlinuz-$kver" -initrd "$work/initramfs.cpio" \
  -append "console=ttyS0 panic=-1 quiet" \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
  > "$work/console.log" 2>&1 || true
grep -a "QEMU-UHID" "$work/console.log" || { tail -n 30 "$work/console.log"; exit 1; }
grep -aq "QEMU-UHID: seamwalk exit 0" "$work/console.log" || { echo "FAIL: seamwalk"; exit 1; }
grep -aq "gamepad /dev/hidraw.* (046d:c216" "$work/console.log" || { echo "FAIL: no pad"; exit 1; }
grep -aq "gamepad /dev/hidraw.* unplugged" "$work/console.log" || { echo "FAIL: no unplug"; exit 1; }
moved=$(sed -n 's/.*QEMU-UHID: frames [0-9]* moved \([0-9.]*\).*/\1/p' "$work/console.log")
python3 -c "import sys; sys.exit(0 if float('$moved') > 0.1 else 1)" || { echo "FAIL: moved $moved"; exit 1; }
echo "ok   a UHID gamepad in QEMU drove seamwalk --navigate (moved $moved) and was unplugged"
