#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""hole_views.py INFO.json OUT.path: a camera path of still views for the
image hole test (tests/test_image_holes.sh) around a pack's box (from
`seamwalk-pack info --json`): close (0.5 model sizes from the centre, in
among the parts), mid (1 size) and far (3 sizes), two directions each, up
the pack's up axis. One key a view, one second apart: a walk of as many
frames as keys stands at each view in turn."""
import json
import math
import sys

info = json.load(open(sys.argv[1]))
lo, hi = info["box"]["min"], info["box"]["max"]
centre = [(a + b) / 2 for a, b in zip(lo, hi)]
size = max(b - a for a, b in zip(lo, hi))
axis = info.get("up_axis", "+y").lstrip("+")
sign = -1.0 if axis.startswith("-") else 1.0
up_index = "xyz".index(axis.lstrip("-"))
b_index, a_index = (up_index + 1) % 3, (up_index + 2) % 3
keys = []
for k in (0.5, 1.0, 3.0):
    for a in (0.6, 2.9):
        eye = list(centre)
        eye[a_index] += k * size * math.cos(a)
        eye[b_index] += k * size * math.sin(a)
        eye[up_index] += sign * 0.35 * k * size
        up = [0.0, 0.0, 0.0]
        up[up_index] = sign
        keys.append(tuple(eye) + tuple(centre) + tuple(up))
with open(sys.argv[2], "w") as f:
    f.writelines("%d %s\n" % (i, " ".join(repr(x) for x in key)) for i, key in enumerate(keys))
