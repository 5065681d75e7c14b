#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages seamwalk builds and tests with, only those
# missing, so it is quiet and fast when run again. Needs root (or sudo) only
# when something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config   # compiler, build system
  ninja-build                        # the build tool of new build folders (a third faster than make)
  libegl-dev libgles-dev             # EGL and GLES2 headers and loaders (glvnd)
  libegl-mesa0 libgl1-mesa-dri       # Mesa's EGL and llvmpipe: headless rendering
  libdrm-dev libgbm-dev              # the KMS display: connectors, modes, page flips; GBM scan-out buffers
  libx11-dev                         # the X11 developer window
  libwayland-dev wayland-protocols   # the Wayland developer window (wayland-client, wayland-egl,
  libwayland-bin                     #   wayland-scanner for xdg-shell)
  libxkbcommon-dev                   # Wayland keyboard: keycodes to keysyms through the compositor's keymap
  xvfb xauth                         # the X11 window test runs EGL on a virtual X server
  weston                             # the Wayland window test: Weston's headless compositor
  libxxhash-dev                      # pack section checksums (XXH3-64)
  libstb-dev                         # stb_image_write (PNG frames), stb_image (tests)
  libinih-dev                        # showroom scene files and the unit's config (INI)
  libmeshoptimizer-dev               # the part levels' simplifier (assets/super/sw_part_levels_build.c)
  libhidapi-dev                      # gamepads and joysticks (hidapi-hidraw, platform/input/sw_hid_hidapi.c)
  libgpiod-dev                       # GPIO buttons (libgpiod v1, platform/input/sw_gpio_gpiod.c)
  libsystemd-dev                     # sd_notify for the service: READY, WATCHDOG (firmware/program/sw_notify.c)
  libevdev-dev                       # the kiosk keyboard, SYN_DROPPED resync (platform/input/sw_evdev_keys.c)
  libsodium-dev                      # ed25519 signatures of packs (seamwalk-pack sign, seamwalk-flash)
  libgl-dev libglu1-mesa-dev         # the benchmark's reference: GLU's NURBS tessellator
  python3                            # tests read the stats JSON
  dpkg-dev                           # the .deb packages' Depends: dpkg-shlibdeps (cmake/SwPackage.cmake)
  man-db                             # tests render the man pages: man --warnings -l (groff)
  systemd                            # tests verify the unit: systemd-analyze, systemd-sysusers
  gnuplot-nox                        # tests/bench/walk_bench.sh plots frame time along the path (PNG)
  clang libclang-rt-14-dev           # libFuzzer runs of the parsers (tests/fuzz)
  # OpenCASCADE 7.6: STEP import and the IGES cross-check (assets/import/sw_import_occt.cpp,
  # C++17); the build works without it (SW_WITH_OCCT, "built without STEP support")
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
  libocct-foundation-dev libocct-ocaf-dev g++
  libtbb-dev                         # OCCT's CMake targets link libtbb.so, which only -dev ships
)

# Arguments replace the list: a step that needs more than the build (the
# QEMU tests, tests/qemu/kms_deps.sh) installs its packages the same way.
[ $# -gt 0 ] && packages=("$@")

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
# --no-remove: a package that conflicts with an installed one stops the
# install instead of replacing it (arm64 libraries go in beside the amd64
# ones: tests/cross/arm64_deps.sh).
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends --no-remove "${missing[@]}" >/dev/null
