#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The depth planes fit where the model can be seen (firmware/walk/visibility/sw_seam_depth.h),
# told by pixels alone: a strip of floor that runs from behind the eye to
# 25 m ahead (its box reaches behind the eye: its nearest corner is no
# guide to the near plane) and a column 20 m ahead of the eye. The frame is
# drawn twice, back faces flat cyan and back faces hidden: the two must be
# the same picture, pixel for pixel. A near plane fitted to the floor's box
# left 24 bits too coarse 20 m away to tell the column's front from its
# back, and its back showed through in stripes.
#   test_depth_fit.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1 src=$2
work=$build/tests/depth_fit
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
python3 - "$src/tests" "$work/scene.igs" <<'PY' || fail "scene"
import math, sys
sys.path.insert(0, sys.argv[1])
from gen_soup import Iges, column
out = Iges()
for y0 in range(-25000, 25000, 10000):   # a floor strip 2 m wide in 10 m plates,
    pts = [(-1000, y0, 0), (1000, y0, 0), (-1000, y0 + 10000, 0), (1000, y0 + 10000, 0)]
    out.surface_128(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], [1] * 4, pts)   # one under the eye
column(out, 300.0, 20000.0, 120.0, 3000.0)
out.write(sys.argv[2], 0.01)
PY
"$build/assets/seamwalk-pack" build "$work/scene.igs" -o "$work/scene.swpack" --quiet \
  > "$work/build.log" 2>&1 || fail "pack build ($work/build.log)"
printf '0 0 0 1700 300 20000 1500 0 0 1\n1 0 0 1700 300 20000 1500 0 0 1\n' > "$work/view.path"
for faces in 0,255,255 hidden; do
  "$build/firmware/seamwalk" --pack "$work/scene.swpack" --path "$work/view.path" \
    --headless 640x480 --frames 1 --workers 0 --measure-every 0 --depth-bits 24 \
    --background 255,0,255 --back-faces "$faces" --png-dir "$work/$faces" \
    --stats "$work/$faces.json" > "$work/$faces.log" 2>&1 || fail "walk ($work/$faces.log)"
done
python3 - "$work/hidden.json" <<'PY' || fail "depth planes"
import json, sys
d = json.load(open(sys.argv[1]))["depth"]
print("  depth: %d bits, far over near %.1f" % (d["bits"], d["far_over_near_max"]))
assert d["bits"] == 24, d
PY
"$build/tests/image_compare" "$work/0,255,255/frame_00000.png" "$work/hidden/frame_00000.png" \
  --level 8 --max-fraction 0 || fail "back faces show through the column's front"
echo "depth fit: back faces never in front"
