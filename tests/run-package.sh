#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The packaging command: installs what is missing, configures and builds
# the Release build as the test command does (build/), and makes the .deb
# packages seamwalk (the runtime) and seamwalk-pack (the host tool) in
# build/packages with cpack (cmake/SwPackage.cmake). Safe to run again.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
bash cmake/install-deps.sh
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSW_WERROR=ON >/dev/null
cmake --build build -j"$(nproc 2>/dev/null || echo 2)"
rm -f build/packages/*.deb
cpack --config build/CPackConfig.cmake -B build/packages
ls -l build/packages/*.deb
