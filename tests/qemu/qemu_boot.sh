# SPDX-License-Identifier: MIT
# Sourced by the QEMU tests (kms_in_qemu.sh, run-uhid.sh): boots Debian's
# kernel in QEMU with the host's root file system read-only over 9p, chroots
# into it and runs a guest script from a writable work folder, which the
# guest sees at /run/sw (not under /tmp: a build under the host's /tmp, a CI
# clone there, must stay visible through the host root). The initramfs holds
# only busybox and the 9p modules with their dependencies, in the order
# modprobe would load them; every other module the guest loads with
# modprobe from the host root. Nothing is mounted over the host's /tmp (a
# CI clone there must stay visible): the guest writes under /run/sw.
#   sw_qemu_kernel                  -> $kernel, $kver (exit 77 without one)
#   sw_qemu_initrd WORK             -> WORK/initrd.gz
#   sw_qemu_boot WORK OUT LOG QEMU_ARGS...  runs OUT/guest.sh; LOG: console
# TCG by default (SW_QEMU_ACCEL=kvm where KVM works; in a nested VM it may
# hang at boot). Needs qemu-system-x86, linux-image-amd64, busybox-static
# (tests/qemu/kms_deps.sh installs them).

sw_qemu_kernel() {
  local tool
  for tool in qemu-system-x86_64 busybox cpio modprobe; do
    command -v $tool > /dev/null || { echo "SKIP: $tool is not installed"; exit 77; }
  done
  kernel=$(ls /boot/vmlinuz-*-amd64 2> /dev/null | sort -V | tail -1)
  [ -n "$kernel" ] || { echo "SKIP: no Debian kernel in /boot (linux-image-amd64)"; exit 77; }
  kver=${kernel#/boot/vmlinuz-}
}

sw_qemu_initrd() {
  local work=$1 m ko
  rm -rf "$work/initrd" && mkdir -p "$work/initrd/bin" "$work/initrd/lib/modules"
  cp "$(command -v busybox)" "$work/initrd/bin/busybox"
  for m in virtio_pci 9p 9pnet_virtio; do
    modprobe -S "$kver" --show-depends $m | awk '$1 == "insmod" {print $2}'
  done | awk '!seen[$0]++' > "$work/modules.txt"
  [ -s "$work/modules.txt" ] || { echo "FAIL: modprobe found no 9p modules for $kver"; exit 1; }
  while read -r ko; do
    cp "$ko" "$work/initrd/lib/modules/"
    echo "insmod /lib/modules/$(basename "$ko")" >> "$work/initrd/load-modules"
  done < "$work/modules.txt"
  cat > "$work/initrd/init" <<'INIT'
#!/bin/busybox sh
/bin/busybox --install -s /bin
mount -t proc proc /proc 2> /dev/null || { mkdir -p /proc && mount -t proc proc /proc; }
mkdir -p /sys /dev /host && mount -t sysfs sys /sys && mount -t devtmpfs dev /dev
sh /load-modules
mount -t 9p -o trans=virtio,version=9p2000.L,ro hostroot /host || echo "SW_QEMU: no host root"
for d in proc sys dev; do mount --bind /$d /host/$d; done
mount -t tmpfs run /host/run && mkdir -p /host/run/sw
mount -t 9p -o trans=virtio,version=9p2000.L work /host/run/sw || echo "SW_QEMU: no work"
chroot /host /bin/bash /run/sw/guest.sh
echo "SW_QEMU_DONE"
poweroff -f
INIT
  chmod +x "$work/initrd/init"
  (cd "$work/initrd" && find . | cpio -o -H newc 2> /dev/null | gzip -1) > "$work/initrd.gz"
}

sw_qemu_boot() {
  local work=$1 out=$2 log=$3
  shift 3
  timeout 900 qemu-system-x86_64 -machine q35,accel="${SW_QEMU_ACCEL:-tcg}" -m 1536 -smp 2 \
    -kernel "$kernel" -initrd "$work/initrd.gz" \
    -append "console=ttyS0 panic=-1" -nographic -no-reboot -display none \
    -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on \
    -virtfs local,path="$out",mount_tag=work,security_model=none "$@" > "$log" 2>&1
  grep -q "SW_QEMU_DONE" "$log" || { echo "FAIL: the guest did not finish: $(tail -20 "$log")"; exit 1; }
}
