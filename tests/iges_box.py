#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""An independent measure of an IGES file's bounds, for the files OpenCASCADE
reads no faces from (gpucast's teapot): its own small reader of the rational
B-spline surfaces (entity 128), sharing nothing with seamwalk's importer.

  iges_box.py FILE.igs        prints JSON:
  {"surfaces": N, "hull": {"min": [..], "max": [..]},   the control points' box
   "samples": {"min": [..], "max": [..]}}               points on the surfaces
in millimetres (the global section's unit). Each surface is sampled on a
17 x 17 grid of its parameter range by de Boor's algorithm with its weights.
The true surface box lies between the two: it holds every sample and lies
inside the hull (a rational B-spline with positive weights lies in the convex
hull of its control points). Exits 2 on what it cannot read: other surface
entities, a transformation matrix, a bad record; never guesses."""
import json, sys

UNIT_MM = {1: 25.4, 2: 1.0, 4: 304.8, 5: 1609344.0, 6: 1000.0, 7: 1e6, 8: 0.0254,
           9: 1e-3, 10: 10.0, 11: 2.54e-5}


def fail(msg):
    print("iges_box: %s" % msg, file=sys.stderr)
    sys.exit(2)


def split_params(text, pd, rd):
    """Free-format parameters; Hollerith strings (nH...) kept whole."""
    out, i, cur = [], 0, ""
    while i < len(text):
        c = text[i]
        if c in "0123456789" and cur.strip() == "":
            j = i
            while j < len(text) and text[j].isdigit():
                j += 1
            if j < len(text) and text[j] in "Hh":
                n = int(text[i:j])
                out.append(text[j + 1:j + 1 + n])
                i = j + 1 + n
                while i < len(text) and text[i] not in (pd, rd):
                    i += 1
                if i < len(text) and text[i] == rd:
                    return out
                i += 1
                cur = ""
                continue
        if c == pd or c == rd:
            out.append(cur.strip())
            cur = ""
            if c == rd:
                return out
        else:
            cur += c
        i += 1
    if cur.strip():
        out.append(cur.strip())
    return out


def read(path):
    sections = {}
    with open(path, "r", errors="replace") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\r\n")
            if len(line) < 73:
                if line.strip() == "":
                    continue
                fail("%s:%d: a line of %d columns, expected 80" % (path, n, len(line)))
            sections.setdefault(line[72], []).append(line)
    return sections


def global_unit(g, path):
    text = "".join(l[:72] for l in g)
    pd, rd = ",", ";"
    if text.startswith("1H") and len(text) > 2:
        pd = text[2]
        rest = text[4:] if text[3:4] == pd else text[3:]
        if rest.startswith("1H") and len(rest) > 2:
            rd = rest[2]
    params = split_params(text, pd, rd)
    flag = params[13] if len(params) > 13 and params[13] else "1"
    try:
        return UNIT_MM[int(float(flag))], pd, rd
    except (ValueError, KeyError):
        fail("%s: global unit flag %r not known" % (path, flag))


def entities(sections, path, pd, rd):
    d = sections.get("D", [])
    p = sections.get("P", [])
    if len(d) % 2:
        fail("%s: odd number of directory lines" % path)
    data = "".join(l[:64] for l in p)
    # Parameter records in order; the directory gives their types. Some
    # exporters number the directory wrongly (gpucast), so records are taken
    # in file order, each checked against its directory entry's type.
    records, i = [], 0
    while i < len(data):
        j = data.find(rd, i)
        if j < 0:
            break
        records.append(data[i:j + 1])
        i = j + 1
    types = [int(d[k][0:8]) for k in range(0, len(d), 2)]
    matrices = [int(d[k][48:56] or 0) for k in range(0, len(d), 2)]
    if len(records) != len(types):
        fail("%s: %d parameter records for %d directory entries" % (path, len(records), len(types)))
    for t, m, r in zip(types, matrices, records):
        params = split_params(r, pd, rd)
        if int(params[0]) != t:
            fail("%s: a parameter record of type %s under a directory entry of type %d"
                 % (path, params[0], t))
        yield t, m, params[1:]


def basis_span(knots, deg, u):
    n = len(knots) - deg - 2
    if u >= knots[n + 1]:
        return n
    lo, hi = deg, n + 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if u < knots[mid]:
            hi = mid
        else:
            lo = mid
    return lo


def de_boor(knots, deg, pts, u):
    k = basis_span(knots, deg, u)
    d = [list(pts[j + k - deg]) for j in range(deg + 1)]
    for r in range(1, deg + 1):
        for j in range(deg, r - 1, -1):
            den = knots[j + 1 + k - r] - knots[j + k - deg]
            a = 0.0 if den == 0 else (u - knots[j + k - deg]) / den
            d[j] = [(1 - a) * x + a * y for x, y in zip(d[j - 1], d[j])]
    return d[deg]


def num(x, path):
    """An IGES real: Fortran's D exponent too (1.5D0)."""
    try:
        return float(x.replace("D", "E").replace("d", "e"))
    except ValueError:
        fail("%s: %r where a number was expected in a surface (128)" % (path, x))


def surface_points(v, path):
    if len(v) < 9:
        fail("%s: a surface (128) with %d parameters" % (path, len(v)))
    k1, k2, m1, m2 = (int(num(x, path)) for x in v[0:4])
    n1, n2 = k1 + 1, k2 + 1
    at = 9
    s = [num(x, path) for x in v[at:at + k1 + m1 + 2]]; at += len(s)
    t = [num(x, path) for x in v[at:at + k2 + m2 + 2]]; at += len(t)
    w = [num(x, path) for x in v[at:at + n1 * n2]]; at += len(w)
    c = [num(x, path) for x in v[at:at + 3 * n1 * n2]]; at += len(c)
    if len(v) < at + 4:
        fail("%s: a surface (128) without its parameter range" % path)
    u0, u1, v0, v1 = (num(x, path) for x in v[at:at + 4])
    if len(w) != n1 * n2 or len(c) != 3 * n1 * n2 or min(w) <= 0:
        fail("%s: a surface (128) with missing values or non-positive weights" % path)
    ctrl = [c[3 * i:3 * i + 3] for i in range(n1 * n2)]
    hom = [[p[0] * wi, p[1] * wi, p[2] * wi, wi] for p, wi in zip(ctrl, w)]
    samples = []
    for a in range(17):
        uu = u0 + (u1 - u0) * a / 16
        # rows of fixed t index j (IGES: the s index runs fastest)
        col = [de_boor(s, m1, [hom[j * n1 + i] for i in range(n1)], uu) for j in range(n2)]
        for b in range(17):
            vv = v0 + (v1 - v0) * b / 16
            h = de_boor(t, m2, col, vv)
            samples.append([h[0] / h[3], h[1] / h[3], h[2] / h[3]])
    return ctrl, samples


def box(points):
    return {"min": [min(p[k] for p in points) for k in range(3)],
            "max": [max(p[k] for p in points) for k in range(3)]}


def main():
    if len(sys.argv) != 2:
        fail("usage: iges_box.py FILE.igs")
    path = sys.argv[1]
    sections = read(path)
    scale, pd, rd = global_unit(sections.get("G", []), path)
    hull, samples, count = [], [], 0
    for t, matrix, v in entities(sections, path, pd, rd):
        if t in (114, 118, 120, 122, 140, 143, 144, 108, 190, 192, 194, 196, 198, 510, 514):
            fail("%s: surface entity %d is not read here (only 128)" % (path, t))
        if t != 128:
            continue
        if matrix:
            fail("%s: a surface with a transformation matrix is not read here" % path)
        ctrl, pts = surface_points(v, path)
        hull += ctrl
        samples += pts
        count += 1
    if not count:
        fail("%s: no rational B-spline surface (128)" % path)
    mm = lambda b: {k: [x * scale for x in b[k]] for k in b}
    print(json.dumps({"surfaces": count, "hull": mm(box(hull)), "samples": mm(box(samples))}))


main()
