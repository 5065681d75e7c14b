#!/bin/sh
# SPDX-License-Identifier: MIT
# Inside the QEMU guest (tests/qemu/run-uhid.sh), chrooted into the host's
# root over 9p, read-only, with /run/sw writable (tests/qemu/qemu_boot.sh): a UHID
# gamepad that hidapi really opens drives seamwalk --navigate; the results
# go to the serial console.
#   uhid_guest.sh BUILD_DIR SOURCE_DIR
build=$1 src=$2
modprobe uhid || echo "QEMU-UHID: modprobe uhid failed"
modprobe hid-generic || echo "QEMU-UHID: modprobe hid-generic failed"
export HOME=/run/sw LIBGL_ALWAYS_SOFTWARE=1
w=/run/sw/w; mkdir -p $w
cat > $w/unit.ini <<INI
[display]
size = 64x48
[pack]
pack = $build/tests/input_walk/teaset.swpack
[render]
max_error_px = 4
[navigation]
walk_speed_mm_s = 1
eye_height_mm = 0.2
attract_timeout_s = 0
INI
# The pad waits until seamwalk opens it (at its first frame), then 20 s
# more, because that first frame compiles llvmpipe's shaders, which under
# TCG takes seconds; then it pushes for 5 s.
# The walk runs until the pad is gone and 3 s more (its unplug logged),
# then a service stop (SIGTERM) ends it through the normal exit: not a
# frame count, whose time depends on the machine.
$build/tests/qemu/uhid_pad $src/tests/hid/logitech_f310_dinput.hex 20 5 2> $w/pad.log &
pad=$!
(sleep 3; echo "QEMU-UHID: hidraw nodes: $(ls /sys/class/hidraw 2>&1 | tr '\n' ' ')") &
$build/firmware/seamwalk --config $w/unit.ini --navigate --frames 1000 --duration 600 \
  --pose-log $w/poses --stats $w/stats.json > /dev/null 2> $w/seamwalk.log &
walker=$!
wait $pad
sleep 3
kill -TERM $walker
wait $walker
echo "QEMU-UHID: seamwalk exit $?"
wait
sed 's/^/QEMU-UHID: /' $w/pad.log $w/seamwalk.log
sed -n '2p;$p' $w/poses | sed 's/^/QEMU-UHID: pose /'
awk '!/^#/ { if (!n++) { x = $3; z = $5 } ; lx = $3; lz = $5 }
     END { d = sqrt((lx - x)^2 + (lz - z)^2); printf "QEMU-UHID: frames %d moved %.3f\n", n, d }' $w/poses
grep -o '"mallocs_after_init": [-0-9]*' $w/stats.json | sed 's/^/QEMU-UHID: /'
