#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The KMS display on a real DRM device: boots Debian's kernel in QEMU with a
# virtio-gpu, the host's root file system read-only over 9p and the work
# folder writable, and runs seamwalk --display kms (and auto) inside, where
# /dev/dri/card0 is virtio-gpu's and Mesa renders through GBM with its
# software rasteriser (kms_swrast). Checks from the host: the walk ran on
# KMS, its frames equal the same walk --headless at the mode's size, no
# mallocs after init, a walk stopped by SIGTERM exits 0 through the normal
# exit, and a last walk (auto, which must pick kms at the connector's
# preferred mode) opens the device again after the others' exit, restore and
# master drop. The restored CRTC itself is not inspected.
# The boot: tests/qemu/qemu_boot.sh.
#   kms_in_qemu.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
. "$src/tests/qemu/qemu_boot.sh"
sw_qemu_kernel
work=$build/tests/kms_qemu
rm -rf "$work" && mkdir -p "$work/out"
sw_qemu_initrd "$work"

"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/out/teaset.swpack" \
  > /dev/null || fail "build the teaset"
# In the guest, /run/sw is $work/out. Not /tmp: a build under the host's
# /tmp (a CI clone there) must stay visible through the host root.
cat > "$work/out/guest.sh" <<GUEST
set -u
export LIBGL_ALWAYS_SOFTWARE=1
modprobe virtio_gpu || echo "SW_QEMU: modprobe virtio_gpu failed"
for _ in \$(seq 50); do [ -e /dev/dri/card0 ] && break; sleep 0.2; done
ls -l /dev/dri
cd /run/sw
$build/firmware/seamwalk --pack teaset.swpack --orbit --frames 3 --display kms --size 640x480 \
  --png-dir kms --stats kms.json --sync-work 1 > kms.out 2>&1
echo "SW_KMS_RC=\$?"
# A service stop mid-walk: SIGTERM ends it after the frame, through the
# normal exit (restore, master dropped).
$build/firmware/seamwalk --pack teaset.swpack --orbit --frames 100000 --display kms \
  --size 640x480 > term.out 2>&1 &
walker=\$!
sleep 30
kill -TERM \$walker
wait \$walker
echo "SW_TERM_RC=\$?"
$build/firmware/seamwalk --pack teaset.swpack --orbit --frames 2 > auto.out 2>&1
echo "SW_AUTO_RC=\$?"
cat kms.out term.out auto.out
GUEST

sw_qemu_boot "$work" "$work/out" "$work/console.log" -device virtio-gpu-pci
grep -q "SW_KMS_RC=0" "$work/console.log" || fail "seamwalk --display kms: $(tail -20 "$work/console.log")"
grep -q "^seamwalk: display kms 640x480 (asked for kms)" "$work/out/kms.out" \
  || fail "the summary names kms: $(cat "$work/out/kms.out")"
grep -q "SW_TERM_RC=0" "$work/console.log" || fail "SIGTERM: $(cat "$work/out/term.out")"
grep -q "^seamwalk: display kms 640x480" "$work/out/term.out" \
  || fail "SIGTERM: no summary: $(cat "$work/out/term.out")"
grep -q "SW_AUTO_RC=0" "$work/console.log" || fail "seamwalk auto: $(cat "$work/out/auto.out")"
grep -q "^seamwalk: display kms .*(auto: /dev/dri/card\* exists and EGL offers GBM)" \
  "$work/out/auto.out" || fail "auto did not choose kms: $(cat "$work/out/auto.out")"
"$build/firmware/seamwalk" --pack "$work/out/teaset.swpack" --orbit --frames 3 \
  --headless 640x480 --png-dir "$work/headless" --sync-work 1 > /dev/null || fail "walk headless"
for f in "$work"/headless/frame_*.png; do
  "$build/tests/image_compare" "$f" "$work/out/kms/$(basename "$f")" || fail "$(basename "$f") differs"
done
python3 - "$work/out/kms.json" <<'PY' || fail "stats of the KMS walk"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["mallocs_after_init"] == 0, s["mallocs_after_init"]
assert s["viewport"] == [640, 480], s["viewport"]
PY
echo "ok: KMS on virtio-gpu in QEMU (${SW_QEMU_ACCEL:-tcg})"
