#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Debian 12 packages the QEMU tests (kms_in_qemu.sh, run-uhid.sh) need
# beyond cmake/install-deps.sh: QEMU, a Debian kernel to boot (its virtio-gpu,
# 9p, virtio-pci and uhid modules) and a static busybox for the initramfs.
# Only the missing ones, through install-deps.sh; needs root (or sudo) only then.
set -euo pipefail
exec bash "$(dirname "$0")/../../cmake/install-deps.sh" \
  qemu-system-x86 linux-image-amd64 busybox-static kmod cpio
