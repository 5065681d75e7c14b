#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Debian 12 packages the arm64 cross build (tests/cross/arm64.sh) needs
# beyond cmake/install-deps.sh: the cross compiler, qemu-user to run its
# programs, and the arm64 copies of the libraries the runtime links,
# installed beside the amd64 ones (multiarch). The build is the lean one a
# kiosk image wants: KMS, hidapi and libgpiod, no X11, Wayland or host tool.
# Adds the arm64 architecture once; the packages go in through
# install-deps.sh, only the missing ones, and never in place of an installed
# package. Needs root (or sudo) only when something is missing.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)

if ! dpkg --print-foreign-architectures | grep -qx arm64; then
  echo "seamwalk: adding the arm64 architecture"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" dpkg --add-architecture arm64
fi

arm64=(
  libc6-dev                     # the C library the programs link and run with (the loader
                                #   /lib/ld-linux-aarch64.so.1 that qemu-aarch64 starts)
  libegl-dev libgles-dev        # EGL and GLES2 (glvnd); they bring Mesa's EGL and llvmpipe
  libdrm-dev libgbm-dev         # the KMS display
  libhidapi-dev libgpiod-dev    # gamepads, GPIO buttons
  libevdev-dev libsystemd-dev   # the kiosk keyboard, sd_notify
  libxxhash-dev libsodium-dev   # pack checksums, signatures
  libinih-dev libstb-dev        # the config file, PNG frames
)
# install-deps.sh runs apt-get update when something is missing, which also
# fetches the arm64 package lists the first time.
# file: arm64.sh checks that every program built is aarch64.
exec bash "$top/cmake/install-deps.sh" gcc-aarch64-linux-gnu qemu-user file "${arm64[@]/%/:arm64}"
