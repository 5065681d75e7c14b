# SPDX-License-Identifier: MIT
# Every Debian package seamwalk uses, found once, exposed as imported targets.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)   # pack section checksums
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)            # headless and device displays
pkg_check_modules(GLESV2 REQUIRED IMPORTED_TARGET glesv2)      # the renderer
# The device backends, each optional (docs/building.md, "Feature options"):
# ON, a missing library stops the configuration; OFF, the runtime is built
# without it and says so when asked for it (sw_display_kind_check_built,
# sw_options.c). SW_HAVE_<NAME> is 1 or 0 in the code.
option(SW_WITH_KMS "The KMS display: libdrm and GBM" ON)
option(SW_WITH_X11 "The X11 developer window: Xlib" ON)
option(SW_WITH_WAYLAND "The Wayland developer window: wayland-client, wayland-egl, xkbcommon" ON)
option(SW_WITH_HIDAPI "Gamepads and joysticks through hidapi" ON)
option(SW_WITH_GPIOD "GPIO buttons through libgpiod" ON)
if(SW_WITH_KMS)
  pkg_check_modules(DRM REQUIRED IMPORTED_TARGET libdrm)       # KMS: connectors, modes, page flips
  pkg_check_modules(GBM REQUIRED IMPORTED_TARGET gbm)          # KMS: scan-out buffers for EGL
endif()
if(SW_WITH_X11)
  pkg_check_modules(X11 REQUIRED IMPORTED_TARGET x11)          # the X11 window
endif()
if(SW_WITH_WAYLAND)
  pkg_check_modules(WAYLAND REQUIRED IMPORTED_TARGET wayland-client wayland-egl)  # the Wayland window
  pkg_check_modules(XKBCOMMON REQUIRED IMPORTED_TARGET xkbcommon)  # Wayland keys to keysyms
  pkg_check_modules(WAYLAND_PROTOCOLS REQUIRED wayland-protocols)  # xdg-shell.xml
  pkg_get_variable(WAYLAND_PROTOCOLS_DIR wayland-protocols pkgdatadir)
  pkg_check_modules(WAYLAND_SCANNER REQUIRED wayland-scanner)
  pkg_get_variable(WAYLAND_SCANNER wayland-scanner wayland_scanner)
endif()
if(SW_WITH_HIDAPI)
  pkg_check_modules(HIDAPI REQUIRED IMPORTED_TARGET hidapi-hidraw)  # gamepads (sw_hid_hidapi.c)
endif()
if(SW_WITH_GPIOD)
  pkg_check_modules(GPIOD REQUIRED IMPORTED_TARGET libgpiod)   # GPIO buttons (sw_gpio_gpiod.c)
endif()
pkg_check_modules(SODIUM REQUIRED IMPORTED_TARGET libsodium)   # ed25519 pack signatures
pkg_check_modules(INIH REQUIRED IMPORTED_TARGET inih)          # showroom scene files, the config
if(SW_BUILD_PACK_TOOL)
  # The part levels' simplifier (host tool only); Debian ships no .pc for it.
  find_package(meshoptimizer REQUIRED CONFIG)
endif()
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
if(SW_BUILD_PACK_TOOL)
  include(SwOcct)   # OpenCASCADE for STEP import (optional, see cmake/SwOcct.cmake)
endif()
