#!/usr/bin/env python3
"""near_far_path.py INFO.json OUT_DIR: camera paths for a walk from close to
far around a pack (its box from `seamwalk-pack info --json`), for a 320x240
headless walk at seamwalk's 45 degree field of view. OUT_DIR/near_far.path:
six views at 0.8, 1.5, 3, 10 and 40 model sizes, turning as they go, then
the far end, where the whole box spans half a pixel (the error bound: nothing
there needs drawing). OUT_DIR/far.path: the far end alone."""
import json
import math
import sys

info = json.load(open(sys.argv[1]))
lo, hi = info["box"]["min"], info["box"]["max"]
centre = [(a + b) / 2 for a, b in zip(lo, hi)]
size = max(b - a for a, b in zip(lo, hi))
px_per_unit = 240 / (2 * math.tan(math.radians(45) / 2))
dists = [0.8, 1.5, 3, 10, 40, math.dist(lo, hi) / size * px_per_unit / 0.5]
lines = []
for i, k in enumerate(dists):
    a = 0.7 + 1.1 * i
    eye = (centre[0] + k * size * math.cos(a), centre[1] + 0.4 * k * size,
           centre[2] + k * size * math.sin(a))
    lines.append("%r %r %r %r %r %r 0 1 0\n" % (eye + tuple(centre)))
with open(sys.argv[2] + "/near_far.path", "w") as f:
    f.writelines("%d %s" % (i, line) for i, line in enumerate(lines))
with open(sys.argv[2] + "/far.path", "w") as f:
    f.write("0 " + lines[-1])
