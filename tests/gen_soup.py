#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A patch soup as CAD exporters write them, for holding seamwalk's sewing
against OpenCASCADE's: an IGES 5.3 file of independent B-spline surfaces
(type 128), sharing no topology.
  gen_soup.py OUT.igs [--cells N] [--seed S] [--gap MM] [--tolerance MM]
A courtyard of N x N square cells (500 mm), each paved whole, in two halves
or in four quarters, so a whole cell's side meets two of its neighbour's
(edge to part of edge: T-junctions); every paving stone is moved by up to
--gap (default 0.002 mm) at random, so no two sides meet exactly. On it
stand columns: rational quadratic cylinders, each one closed surface whose
two sides meet along its seam line. The global section states --tolerance
(default 0.01 mm) as the minimum resolution, in millimetres.
"""
import argparse
import math
import random


def fmt(x):
    return ("%.12g" % x).replace("e", "E") if x != 0 else "0."


class Iges:
    def __init__(self):
        self.entities = []  # (type, params text, form)

    def add(self, etype, params, form=0):
        """Adds an entity; returns its directory entry's pointer (DE)."""
        self.entities.append((etype, "%d,%s;" % (etype, ",".join(params)), form))
        return 2 * len(self.entities) - 1

    def surface_128(self, deg_u, deg_v, knots_u, knots_v, weights, points):
        nu, nv = len(knots_u) - deg_u - 1, len(knots_v) - deg_v - 1
        rational = any(abs(w - 1) > 0 for w in weights)
        params = [str(nu - 1), str(nv - 1), str(deg_u), str(deg_v), "0", "0",
                  "0" if rational else "1", "0", "0"]
        params += [fmt(k) for k in knots_u] + [fmt(k) for k in knots_v]
        params += [fmt(w) for w in weights]
        for p in points:
            params += [fmt(c) for c in p]
        params += [fmt(knots_u[deg_u]), fmt(knots_u[nu]), fmt(knots_v[deg_v]), fmt(knots_v[nv])]
        self.add(128, params)

    @staticmethod
    def lines(text, width):
        out, cur = [], ""
        for tok in text.replace(",", ",\0").replace(";", ";\0").split("\0"):
            if not tok:
                continue
            if len(cur) + len(tok) > width:
                out.append(cur)
                cur = ""
            cur += tok
        if cur:
            out.append(cur)
        return out

    def write(self, path, tolerance):
        g = ("1H,,1H;,7Hcourtyd,%dH%s,8Hseamwalk,3H1.0,32,38,6,308,15,7Hcourtyd,1.,2,2HMM,"
             "1,1.,15H20261201.000000,%s,100000.,4Htest,4Htest,11,0;"
             % (len(path.split("/")[-1]), path.split("/")[-1], fmt(tolerance)))
        s_lines = ["seamwalk patch soup (tests/gen_soup.py)"]
        g_lines = self.lines(g, 72)
        d_lines, p_lines = [], []
        for i, (etype, params, form) in enumerate(self.entities):
            de = 2 * i + 1
            body = self.lines(params, 64)
            first = len(p_lines) + 1
            for b in body:
                p_lines.append("%-64s %7d" % (b, de))
            d_lines.append("%8d%8d%8d%8d%8d%8d%8d%8d%8s" % (etype, first, 0, 0, 0, 0, 0, 0,
                                                            "00000000"))
            d_lines.append("%8d%8d%8d%8d%8d%8s%8s%8s%8d" % (etype, 0, 0, len(body), form, "", "",
                                                            "", 0))
        with open(path, "w") as f:
            for sec, lines in (("S", s_lines), ("G", g_lines), ("D", d_lines), ("P", p_lines)):
                for n, line in enumerate(lines, 1):
                    f.write("%-72s%s%7d\n" % (line[:72], sec, n))
            f.write("%-72s%s%7d\n" % ("S%7dG%7dD%7dP%7d" % (len(s_lines), len(g_lines),
                                                         len(d_lines), len(p_lines)), "T", 1))


def paving(out, rng, x0, y0, size, gap):
    kind = rng.randrange(4)
    nx, ny = {0: (1, 1), 1: (2, 1), 2: (1, 2), 3: (2, 2)}[kind]
    for i in range(nx):
        for j in range(ny):
            dx, dy, dz = (rng.uniform(-gap, gap) / math.sqrt(3) for _ in range(3))
            a, b = x0 + size * i / nx + dx, x0 + size * (i + 1) / nx + dx
            c, d = y0 + size * j / ny + dy, y0 + size * (j + 1) / ny + dy
            pts = [(a, c, dz), (b, c, dz), (a, d, dz), (b, d, dz)]
            out.surface_128(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], [1] * 4, pts)


def column(out, cx, cy, r, h):
    """A full circle of four rational quadratic arcs in u, straight in v."""
    w = math.sqrt(0.5)
    ring = [(1, 0, 1), (1, 1, w), (0, 1, 1), (-1, 1, w), (-1, 0, 1), (-1, -1, w), (0, -1, 1),
            (1, -1, w), (1, 0, 1)]
    knots_u = [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]
    weights, pts = [], []
    for z in (0.0, h):
        for (x, y, wt) in ring:
            weights.append(wt)
            pts.append((cx + r * x, cy + r * y, z))
    out.surface_128(2, 1, knots_u, [0, 0, 1, 1], weights, pts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--cells", type=int, default=30)
    ap.add_argument("--seed", type=int, default=8)
    ap.add_argument("--gap", type=float, default=0.002)
    ap.add_argument("--tolerance", type=float, default=0.01)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    out = Iges()
    size = 500.0
    for i in range(a.cells):
        for j in range(a.cells):
            paving(out, rng, i * size, j * size, size, a.gap)
    for i in range(1, a.cells, 6):
        for j in range(1, a.cells, 6):
            column(out, i * size, j * size, 120.0, 3000.0)
    out.write(a.out, a.tolerance)


if __name__ == "__main__":
    main()
