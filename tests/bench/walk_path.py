#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""walk_path.py OUT.path --box X0 Y0 Z0 X1 Y1 Z1 --up y|z [--rect A0 B0 A1 B1]
                [--eye-mm H] [--seconds S]
A closed walk for the walkthrough benchmark (tests/bench/walk_bench.sh) in
seamwalk's camera path format (firmware/kiosk/sw_camera_path.h): a person H mm
tall (default 1700) walks once round the rectangle A0..A1 x B0..B1 on the
floor (the two horizontal axes: x and z for y up, x and y for z up; by
default the middle half of the box's floor), corners rounded by the path's
splines, looking 3.5 H ahead along the way and a little down (0.4 H there), in S
seconds (default 30); H is at most a twentieth of the floor's shorter side. The last key is the first, so the path loops (the soak)."""
import argparse
import math


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--box", type=float, nargs=6, required=True)
    ap.add_argument("--up", choices=("y", "z"), required=True)
    ap.add_argument("--rect", type=float, nargs=4)
    ap.add_argument("--eye-mm", type=float, default=1700.0)
    ap.add_argument("--seconds", type=float, default=30.0)
    a = ap.parse_args()
    lo, hi = a.box[:3], a.box[3:]
    up = 1 if a.up == "y" else 2
    h0, h1 = (0, 2) if a.up == "y" else (0, 1)   # the floor's axes
    if a.rect:
        r = a.rect
    else:
        w0, w1 = hi[h0] - lo[h0], hi[h1] - lo[h1]
        r = [lo[h0] + w0 / 4, lo[h1] + w1 / 4, hi[h0] - w0 / 4, hi[h1] - w1 / 4]
    corners = [(r[0], r[1]), (r[0], r[3]), (r[2], r[3]), (r[2], r[1])]
    # Points along the sides, so the spline stays near the rectangle and
    # each side takes time in proportion to its length.
    pts = []
    for k in range(4):
        (p0, q0), (p1, q1) = corners[k], corners[(k + 1) % 4]
        for i in range(4):
            f = i / 4.0
            pts.append((p0 + (p1 - p0) * f, q0 + (q1 - q0) * f))
    pts.append(pts[0])
    lengths = [0.0]
    for i in range(1, len(pts)):
        lengths.append(lengths[-1] + math.dist(pts[i - 1], pts[i]))
    # A small scene (the --quick ones) gets a smaller walker, so the floor
    # is in view: at most a twentieth of the floor's shorter side.
    height = min(a.eye_mm, min(hi[h0] - lo[h0], hi[h1] - lo[h1]) / 20.0)
    eye_h = lo[up] + height
    look = 3.5 * height
    lines = ["# walk_path.py: a closed walk round the floor rectangle %s, eye at %g mm"
             % (" ".join("%g" % v for v in r), height)]
    for i, (p, q) in enumerate(pts):
        n = pts[(i + 1) % (len(pts) - 1)] if i < len(pts) - 1 else pts[1]
        d = (n[0] - p, n[1] - q)
        dl = math.hypot(*d) or 1.0
        d = (d[0] / dl, d[1] / dl)
        eye, target, upv = [0.0] * 3, [0.0] * 3, [0.0] * 3
        eye[h0], eye[h1], eye[up] = p, q, eye_h
        target[h0], target[h1], target[up] = p + look * d[0], q + look * d[1], eye_h - 0.4 * height
        upv[up] = 1.0
        t = a.seconds * lengths[i] / lengths[-1]
        lines.append("%.4f  %s  %s  %s" % (t, " ".join("%.3f" % v for v in eye),
                                          " ".join("%.3f" % v for v in target),
                                          " ".join("%g" % v for v in upv)))
    open(a.out, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
