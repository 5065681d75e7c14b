#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Boots Debian's kernel in QEMU (TCG, no KVM needed; tests/qemu/qemu_boot.sh)
# with the host's root over 9p and runs tests/qemu/uhid_guest.sh: a UHID
# gamepad (the F310's recorded descriptor) that the real hidapi backend
# enumerates, opens and reads, then loses when the device is destroyed;
# seamwalk's own code allocates nothing after init meanwhile. The issue's gpio-sim part
# is not possible with Debian 12's kernel (CONFIG_GPIO_SIM and
# CONFIG_GPIO_MOCKUP are not set); the KMS device is kms_in_qemu.sh's. Run
# after tests/test_input_walk.sh built the teaset pack.
#   run-uhid.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
. "$src/tests/qemu/qemu_boot.sh"
sw_qemu_kernel
work=$build/tests/qemu && rm -rf "$work" && mkdir -p "$work/out"
cc -O2 -I"$src/core" -I"$src/firmware/kiosk" -o "$work/uhid_pad" "$src/tests/qemu/uhid_pad.c" \
  "$src/firmware/kiosk/sw_input_timeline.c" "$src/core/sw_error.c" "$src/core/sw_hex.c" -lm
[ -f "$build/tests/input_walk/teaset.swpack" ] || { echo "run tests/test_input_walk.sh first"; exit 1; }
sw_qemu_initrd "$work"
echo "exec /bin/sh $src/tests/qemu/uhid_guest.sh $build $src" > "$work/out/guest.sh"
sw_qemu_boot "$work" "$work/out" "$work/console.log"
grep -a "QEMU-UHID" "$work/console.log" || { tail -n 30 "$work/console.log"; exit 1; }
grep -aq "QEMU-UHID: seamwalk exit 0" "$work/console.log" || { echo "FAIL: seamwalk"; exit 1; }
grep -aq "gamepad /dev/hidraw.* (046d:c216" "$work/console.log" || { echo "FAIL: no pad"; exit 1; }
grep -aq "gamepad /dev/hidraw.* unplugged" "$work/console.log" || { echo "FAIL: no unplug"; exit 1; }
grep -aq 'QEMU-UHID: "mallocs_after_init": 0' "$work/console.log" || { echo "FAIL: mallocs after init"; exit 1; }
moved=$(sed -n 's/.*QEMU-UHID: frames [0-9]* moved \([0-9.]*\).*/\1/p' "$work/console.log")
python3 -c "import sys; sys.exit(0 if float('$moved') > 0.1 else 1)" || { echo "FAIL: moved $moved"; exit 1; }
echo "ok   a UHID gamepad in QEMU drove seamwalk --navigate (moved $moved) and was unplugged"
