#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI's arm64 step: cross-builds the runtime for arm64 with Debian's cross
# compiler and multiarch libraries (cmake/aarch64-linux-gnu.cmake), checks
# that every program built is aarch64, makes the unit's .deb package, and
# runs the unit tests (CTest label unit) under qemu-user. With a host build that has seamwalk-pack and
# image_compare (the test command's build/), the arm64 seamwalk also walks
# the teaset's golden views from a pack the host built and its pictures are
# held to the references, as walk_golden holds the host's.
#   arm64.sh [BUILD_DIR [HOST_BUILD_DIR]]   (default build-arm64, build)
# The build is the lean one a kiosk image wants: KMS, hidapi and libgpiod;
# no X11 or Wayland window (a kiosk has no desktop), no seamwalk-pack (it
# runs on the host, and OpenCASCADE's arm64 copy is large). Installs what
# is missing first (tests/cross/arm64_deps.sh); safe to run again.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
dir=${1:-build-arm64}
host=${2:-build}
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
fail() { echo "arm64: FAIL: $*"; exit 1; }
step() { echo "arm64: $1 in $((SECONDS - started)) s"; started=$SECONDS; }

started=$SECONDS
bash tests/cross/arm64_deps.sh
step "packages"

cmake -S . -B "$dir" --toolchain "$top/cmake/aarch64-linux-gnu.cmake" \
  -DCMAKE_BUILD_TYPE=Release -DSW_WERROR=ON -DSW_BUILD_PACK_TOOL=OFF \
  -DSW_WITH_X11=OFF -DSW_WITH_WAYLAND=OFF >/dev/null
cmake --build "$dir" -j"$jobs"
# Every program and object file the build made is arm64: a host compiler
# or a host library picked up by mistake shows here, not on the device.
not_arm64=$(find "$dir" -type f \( -perm -u+x -o -name '*.o' \) -print0 |
            xargs -0 file | grep ELF | grep -v 'ARM aarch64' || true)
[ -z "$not_arm64" ] || fail "not arm64: $not_arm64"
file "$dir/firmware/seamwalk" "$dir/firmware/seamwalk-flash" | sed 's/, BuildID.*//'
# The unit's package, as run-package.sh makes the host's: arm64, its
# Depends read from the arm64 libraries linked, no window system.
rm -rf "$dir/packages"
cpack --config "$dir/CPackConfig.cmake" -B "$dir/packages" >/dev/null
deb=$(ls "$dir"/packages/seamwalk_*_arm64.deb) || fail "no seamwalk_*_arm64.deb"
depends=$(dpkg-deb -f "$deb" Depends)
echo "$deb: Depends: $depends"
if grep -qE 'libx11|libwayland|libxkbcommon' <<< "$depends"; then
  fail "the lean package depends on a window system"
fi
step "build and package"

# The emulator CTest runs the test programs with (the toolchain file's).
read -ra emulator < <(ctest --test-dir "$dir" -N -R '^test_math$' --show-only=json-v1 |
  python3 -c 'import json, sys; print(" ".join(json.load(sys.stdin)["tests"][0]["command"][:-1]))')
case ${emulator[*]} in *qemu-aarch64*) ;; *) fail "the tests run without qemu-aarch64" ;; esac
ctest --test-dir "$dir" --output-on-failure -j"$jobs" -L unit
step "unit tests under ${emulator[*]}"

pack_tool=$host/assets/seamwalk-pack compare=$host/tests/image_compare
if [ ! -x "$pack_tool" ] || [ ! -x "$compare" ]; then
  echo "arm64: no host build in $host: the golden views are not walked"
  exit 0
fi
work=$dir/golden
rm -rf "$work" && mkdir -p "$work"
"$pack_tool" build assets/samples/teaset.ini -o "$work/teaset.swpack" --quiet
# As walk_golden: each frame waits for its work, no part levels.
SEAMWALK_TEST_SYNC_WORK=1 "${emulator[@]}" "$dir/firmware/seamwalk" --pack "$work/teaset.swpack" \
  --headless 320x240 --path tests/golden/views.path --frames 3 --part-levels 0 \
  --png-dir "$work/png" --stats "$work/stats.json" || fail "the arm64 walk"
python3 tests/check_stats.py "$work/stats.json" 3 || fail "the arm64 walk's stats"
for i in 0 1 2; do
  "$compare" "$work/png/frame_0000$i.png" "tests/golden/teaset_view$i.png" ||
    fail "view $i, drawn on arm64, differs from its reference"
done
step "golden views walked on arm64"
