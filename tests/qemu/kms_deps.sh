#!/usr/bin/env bash
# The Debian 12 packages tests/qemu/kms_in_qemu.sh needs beyond
# cmake/install-deps.sh: QEMU, a Debian kernel to boot (its virtio-gpu, 9p and
# virtio-pci modules) and a static busybox for the initramfs. Only the missing
# ones; needs root (or sudo) only then.
set -euo pipefail
packages=(qemu-system-x86 linux-image-amd64 busybox-static kmod cpio)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "seamwalk: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
