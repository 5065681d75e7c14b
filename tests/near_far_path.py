#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""near_far_path.py INFO.json OUT_DIR: camera paths for a walk from close to
far around a pack (its box from `seamwalk-pack info --json`), for a 320x240
headless walk at seamwalk's 45 degree field of view. OUT_DIR/near_far.path:
six views at 0.8, 1.5, 3, 10 and 40 model sizes, turning as they go, then
the far end, where the whole box spans half a pixel (the error bound: nothing
there needs drawing), circling the pack's up axis (its "up_axis", +y when
absent) with that axis as the camera's up. OUT_DIR/far.path: the far end
alone."""
import json
import math
import sys

info = json.load(open(sys.argv[1]))
lo, hi = info["box"]["min"], info["box"]["max"]
centre = [(a + b) / 2 for a, b in zip(lo, hi)]
size = max(b - a for a, b in zip(lo, hi))
px_per_unit = 240 / (2 * math.tan(math.radians(45) / 2))
dists = [0.8, 1.5, 3, 10, 40, math.dist(lo, hi) / size * px_per_unit / 0.5]
axis = info.get("up_axis", "+y").lstrip("+")
sign = -1.0 if axis.startswith("-") else 1.0
up_index = "xyz".index(axis.lstrip("-"))
# The two other axes in cyclic order after the up one (for +y: z, x), so
# the y-up paths are the ones this script always wrote.
b_index, a_index = (up_index + 1) % 3, (up_index + 2) % 3
lines = []
for i, k in enumerate(dists):
    a = 0.7 + 1.1 * i
    eye = list(centre)
    eye[a_index] += k * size * math.cos(a)
    eye[b_index] += k * size * math.sin(a)
    eye[up_index] += sign * 0.4 * k * size
    up = [0.0, 0.0, 0.0]
    up[up_index] = sign
    lines.append("%r %r %r %r %r %r %r %r %r\n" % (tuple(eye) + tuple(centre) + tuple(up)))
with open(sys.argv[2] + "/near_far.path", "w") as f:
    f.writelines("%d %s" % (i, line) for i, line in enumerate(lines))
with open(sys.argv[2] + "/far.path", "w") as f:
    f.write("0 " + lines[-1])
