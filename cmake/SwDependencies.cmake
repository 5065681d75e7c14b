# SPDX-License-Identifier: MIT
# Every Debian package seamwalk uses, found once, exposed as imported targets.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)   # pack section checksums
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)            # headless and device displays
pkg_check_modules(GLESV2 REQUIRED IMPORTED_TARGET glesv2)      # the renderer
# The device and developer displays (platform/sw_display_*.c).
pkg_check_modules(DRM REQUIRED IMPORTED_TARGET libdrm)         # KMS: connectors, modes, page flips
pkg_check_modules(GBM REQUIRED IMPORTED_TARGET gbm)            # KMS: scan-out buffers for EGL
pkg_check_modules(X11 REQUIRED IMPORTED_TARGET x11)            # the X11 window
pkg_check_modules(WAYLAND REQUIRED IMPORTED_TARGET wayland-client wayland-egl)  # the Wayland window
pkg_check_modules(XKBCOMMON REQUIRED IMPORTED_TARGET xkbcommon)  # Wayland keys to keysyms
pkg_check_modules(WAYLAND_PROTOCOLS REQUIRED wayland-protocols)  # xdg-shell.xml
pkg_get_variable(WAYLAND_PROTOCOLS_DIR wayland-protocols pkgdatadir)
pkg_check_modules(WAYLAND_SCANNER REQUIRED wayland-scanner)
pkg_get_variable(WAYLAND_SCANNER wayland-scanner wayland_scanner)
pkg_check_modules(SODIUM REQUIRED IMPORTED_TARGET libsodium)   # ed25519 pack signatures
pkg_check_modules(INIH REQUIRED IMPORTED_TARGET inih)          # showroom scene files, the config
# The part levels' simplifier (host tool only); Debian ships no .pc for it.
find_package(meshoptimizer REQUIRED CONFIG)
pkg_check_modules(HIDAPI REQUIRED IMPORTED_TARGET hidapi-hidraw)  # gamepads (sw_hid_hidapi.c)
pkg_check_modules(GPIOD REQUIRED IMPORTED_TARGET libgpiod)     # GPIO buttons (sw_gpio_gpiod.c)
pkg_check_modules(SYSTEMD REQUIRED IMPORTED_TARGET libsystemd)  # sd_notify: READY, WATCHDOG (sw_notify.c)
pkg_check_modules(EVDEV REQUIRED IMPORTED_TARGET libevdev)    # the kiosk keyboard (sw_evdev_keys.c)

# stb ships as headers (libstb-dev); we compile the implementations we use
# ourselves so that allocation can be routed into the arena.
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)
add_library(sw_stb INTERFACE)
target_include_directories(sw_stb SYSTEM INTERFACE ${STB_INCLUDE_DIR})

# Desktop GL and GLU only for the benchmark's reference tessellator.
pkg_check_modules(GLU IMPORTED_TARGET glu)
pkg_check_modules(OPENGL IMPORTED_TARGET opengl)

find_library(MATH_LIBRARY m REQUIRED)
include(SwOcct)   # OpenCASCADE for STEP import (optional, see cmake/SwOcct.cmake)
