# SPDX-License-Identifier: MIT
# Toolchain file for arm64 (aarch64) Linux from a Debian 12 host: Debian's
# cross compiler (gcc-aarch64-linux-gnu) and the arm64 copies of the
# libraries installed beside the host's (multiarch, `dpkg --add-architecture
# arm64`; tests/cross/arm64_deps.sh installs them).
#   cmake -S . -B build-arm64 --toolchain cmake/aarch64-linux-gnu.cmake ...
# Multiarch keeps arm64 libraries in /usr/lib/aarch64-linux-gnu (the C
# library too: libc6-dev:arm64) and shares the headers in /usr/include with
# the host. CTest runs the test programs through qemu-user
# (CMAKE_CROSSCOMPILING_EMULATOR).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(SW_CROSS_TRIPLE aarch64-linux-gnu)

set(CMAKE_C_COMPILER ${SW_CROSS_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${SW_CROSS_TRIPLE}-g++)
set(CMAKE_LIBRARY_ARCHITECTURE ${SW_CROSS_TRIPLE})

# Libraries and headers only from the arm64 side: "/" for multiarch (CMake
# looks in lib/aarch64-linux-gnu under each root, never in the host's
# lib/x86_64-linux-gnu), /usr/aarch64-linux-gnu where a C library was
# installed the older way (libc6-dev-arm64-cross). Programs (pkg-config,
# wayland-scanner) are the host's.
set(CMAKE_FIND_ROOT_PATH / /usr/${SW_CROSS_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config reads the arm64 .pc files only (and the architecture-free ones
# in /usr/share, such as wayland-protocols), never the host's.
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/${SW_CROSS_TRIPLE}/pkgconfig:/usr/share/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")

# qemu-user runs the arm64 programs CTest starts. The programs name the
# multiarch loader, /lib/ld-linux-aarch64.so.1 (libc6:arm64), which finds
# the libraries in /usr/lib/aarch64-linux-gnu; loader and C library are
# then one build. Without libc6:arm64, -L points qemu at the cross C
# library's copy instead. qemu-aarch64-static (package qemu-user-static)
# works the same.
find_program(SW_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static)
if(SW_QEMU_AARCH64 AND EXISTS /lib/ld-linux-aarch64.so.1)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${SW_QEMU_AARCH64})
elseif(SW_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${SW_QEMU_AARCH64} -L /usr/${SW_CROSS_TRIPLE})
endif()
