# Every Debian package seamwalk uses, found once, exposed as imported targets.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)   # pack section checksums
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)            # headless and device displays
pkg_check_modules(GLESV2 REQUIRED IMPORTED_TARGET glesv2)      # the renderer
pkg_check_modules(SODIUM REQUIRED IMPORTED_TARGET libsodium)   # ed25519 pack signatures
pkg_check_modules(INIH REQUIRED IMPORTED_TARGET inih)          # showroom scene files, the config
pkg_check_modules(HIDAPI REQUIRED IMPORTED_TARGET hidapi-hidraw)  # gamepads (sw_hid_hidapi.c)
pkg_check_modules(GPIOD REQUIRED IMPORTED_TARGET libgpiod)     # GPIO buttons (sw_gpio_gpiod.c)

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
