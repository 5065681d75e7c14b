#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Small STEP files, each carrying one way real exporters' files went wrong:
    gen_step_cases.py OUT_DIR
writes into OUT_DIR:
  gap.step          one square face whose second vertex lies 5 micrometres
                    off its first edge's line: the trim curves' ends miss
                    each other by that much, and OCCT's healing widens the
                    vertex to cover it (its edges keep 1e-7 mm)
  skipped.step      a good square and one whose loop lacks an edge (a 10 mm
                    gap no tolerance covers), and a FILE_NAME with a
                    parameter short: a face to name, and a message
  empty.step        only the face whose loop lacks an edge
  header.step       one good square, FILE_NAME a parameter short: a check
                    attached to no entity
  solid_angle.step  one good square, its solid-angle unit written with
                    explicit dimensions, as Spatial InterOp writes it
  callout.step      one good square, its shape representation also listing
                    a PMI callout (an item OCCT does not take there)
  wide_gap.step     a 40 x 40 grid of 1 mm squares beside one square whose
                    edges carry a tolerance of a fifth of the model (shape
                    healing widens them to cover a vertex that far off):
                    one file-wide large gap beside many fine edges
  planes.igs        two bounded planes (IGES 108, form 1: a plane and the
                    closed curve that bounds it), a kind the native IGES
                    reader does not take and OpenCASCADE's does
  appended.step     one good square, a mesher's script appended after
                    END-ISO-10303-21; (more than the tail the trailer is
                    looked for in)
  spring.step       a wire swept along a helix of 30 turns: one B-spline
                    face whose seam, sewn at the model's tolerance, has
                    more points than one draw's 65536 vertices
  zigzag.step       a flat spring: a strip 1 mm wide with round turns
                    running up and down 20 times, 14 mm long and 2 mm
                    apart, 3 mm thick (its top and bottom planes bounded
                    by the whole outline, a side face per segment):
                    simplified freely, a turn's chord cuts across the next
                    leg in (u, v), and verify refused the top
  band.step         one cylinder face closed on itself (two circles and
                    the seam line between them, used once each way): a
                    one-face periodic band
Each file is an AP214 shell-based surface model in millimetres with a
stated uncertainty of 1e-7 mm."""
import os
import sys


def real(x):
    """A STEP REAL: a decimal point always, an upper-case exponent."""
    text = "%.9G" % x
    mantissa, e, exponent = text.partition("E")
    if "." not in mantissa:
        mantissa += "."
    return mantissa + e + exponent


class Step:
    """Entities numbered as they are added."""

    def __init__(self):
        self.lines = []

    def add(self, text):
        self.lines.append(text)
        return "#%d" % len(self.lines)

    def point(self, p):
        return self.add("CARTESIAN_POINT('',(%s));" % ",".join(real(c) for c in p))

    def direction(self, d):
        return self.add("DIRECTION('',(%s));" % ",".join(real(c) for c in d))


def line_between(s, a, b):
    d = [b[i] - a[i] for i in range(3)]
    n = sum(c * c for c in d) ** 0.5
    return s.add("LINE('',%s,%s);" % (s.point(a), s.add(
        "VECTOR('',%s,1.);" % s.direction([c / n for c in d]))))


def square(s, corners, lines=None, drop_edge=False):
    """A planar face through four corners (z = 0) bounded by lines; lines[i]
    (two points) replaces edge i's line, so that a vertex may lie off it."""
    vertices = [s.add("VERTEX_POINT('',%s);" % s.point(c)) for c in corners]
    edges = []
    for i in range(4):
        a, b = lines[i] if lines and lines[i] else (corners[i], corners[(i + 1) % 4])
        edge = s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (vertices[i], vertices[(i + 1) % 4],
                                                      line_between(s, a, b)))
        edges.append(s.add("ORIENTED_EDGE('',*,*,%s,.T.);" % edge))
    if drop_edge:
        edges = edges[:3]
    loop = s.add("EDGE_LOOP('',(%s));" % ",".join(edges))
    bound = s.add("FACE_OUTER_BOUND('',%s,.T.);" % loop)
    axes = s.add("AXIS2_PLACEMENT_3D('',%s,%s,%s);" % (
        s.point(corners[0]), s.direction((0, 0, 1)), s.direction((1, 0, 0))))
    return s.add("ADVANCED_FACE('',(%s),%s,.T.);" % (bound, s.add("PLANE('',%s);" % axes)))


def write(path, faces_of, file_name_params=7, solid_angle="spec", stray_item=False,
          appended=""):
    s = Step()
    faces = faces_of(s)
    shell = s.add("OPEN_SHELL('',(%s));" % ",".join(faces))
    model = s.add("SHELL_BASED_SURFACE_MODEL('',(%s));" % shell)
    origin = s.add("AXIS2_PLACEMENT_3D('',%s,%s,%s);" % (
        s.point((0, 0, 0)), s.direction((0, 0, 1)), s.direction((1, 0, 0))))
    mm = s.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));")
    rad = s.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));")
    if solid_angle == "spatial":
        dims = s.add("DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.);")
        sr = s.add("(NAMED_UNIT(%s)SOLID_ANGLE_UNIT()SI_UNIT($,.STERADIAN.));" % dims)
    else:
        sr = s.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());")
    unc = s.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),%s,"
                "'distance_accuracy_value','');" % mm)
    ctx = s.add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((%s))"
                "GLOBAL_UNIT_ASSIGNED_CONTEXT((%s,%s,%s))REPRESENTATION_CONTEXT('',''));"
                % (unc, mm, rad, sr))
    app = s.add("APPLICATION_CONTEXT('automotive design');")
    items = [model, origin] + ([s.add("LEADER_DIRECTED_CALLOUT('',(%s));" % origin)]
                               if stray_item else [])
    rep = s.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(%s),%s);" % (",".join(items), ctx))
    name = os.path.splitext(os.path.basename(path))[0]
    product = s.add("PRODUCT('%s','%s','',(%s));" % (name, name, s.add(
        "PRODUCT_CONTEXT('',%s,'mechanical');" % app)))
    definition = s.add("PRODUCT_DEFINITION('design','',%s,%s);" % (
        s.add("PRODUCT_DEFINITION_FORMATION('','',%s);" % product),
        s.add("PRODUCT_DEFINITION_CONTEXT('part definition',%s,'design');" % app)))
    s.add("SHAPE_DEFINITION_REPRESENTATION(%s,%s);" % (
        s.add("PRODUCT_DEFINITION_SHAPE('','',%s);" % definition), rep))
    file_name = ["'%s'" % name, "'2026-01-01T00:00:00'", "('')", "('')", "''", "''", "''"]
    with open(path, "w") as f:
        f.write("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n")
        f.write("FILE_NAME(%s);\n" % ",".join(file_name[:file_name_params]))
        f.write("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n")
        for i, text in enumerate(s.lines):
            f.write("#%d=%s\n" % (i + 1, text))
        f.write("ENDSEC;\nEND-ISO-10303-21;\n")
        f.write(appended)


def band(s, radius, height):
    """One cylinder face closed on itself: two circles and the seam line
    between them, used twice (once each way), as exporters write a
    periodic surface's side."""
    axes = lambda z: s.add("AXIS2_PLACEMENT_3D('',%s,%s,%s);" % (
        s.point((0, 0, z)), s.direction((0, 0, 1)), s.direction((1, 0, 0))))
    low = s.add("VERTEX_POINT('',%s);" % s.point((radius, 0, 0)))
    high = s.add("VERTEX_POINT('',%s);" % s.point((radius, 0, height)))
    circle = lambda v, z: s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (
        v, v, s.add("CIRCLE('',%s,%s);" % (axes(z), real(radius)))))
    seam = s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (
        low, high, line_between(s, (radius, 0, 0), (radius, 0, height))))
    edges = [s.add("ORIENTED_EDGE('',*,*,%s,%s);" % (e, sense))
             for e, sense in ((circle(low, 0), ".T."), (seam, ".T."),
                              (circle(high, height), ".F."), (seam, ".F."))]
    loop = s.add("EDGE_LOOP('',(%s));" % ",".join(edges))
    bound = s.add("FACE_OUTER_BOUND('',%s,.T.);" % loop)
    surface = s.add("CYLINDRICAL_SURFACE('',%s,%s);" % (axes(0), real(radius)))
    return s.add("ADVANCED_FACE('',(%s),%s,.T.);" % (bound, surface))


def helical_sweep(s, turns, coil_radius=10.0, pitch=3.0, wire_radius=1.0, per_turn=8):
    """A wire swept along a helix, as a spring is drawn: one rational
    B-spline face, a circle (rational quadratic, nine points) around the
    wire and a cubic along the helix (per_turn spans a turn), bounded by
    the circles at its ends and the seam along the wire, used once each
    way. Not exactly a helix (the cubic runs through its control points'
    frames), which no test needs."""
    import math
    spans = turns * per_turn
    count_v = spans + 3
    h = 1.0 / math.sqrt(2.0)
    square = [(1, 0, 1), (1, 1, h), (0, 1, 1), (-1, 1, h), (-1, 0, 1), (-1, -1, h), (0, -1, 1),
              (1, -1, h), (1, 0, 1)]

    def frame(t):
        c = (coil_radius * math.cos(t), coil_radius * math.sin(t), pitch * t / (2 * math.pi))
        tangent = (-coil_radius * math.sin(t), coil_radius * math.cos(t), pitch / (2 * math.pi))
        n = math.sqrt(sum(x * x for x in tangent))
        tangent = [x / n for x in tangent]
        normal = (-math.cos(t), -math.sin(t), 0.0)
        binormal = (tangent[1] * normal[2] - tangent[2] * normal[1],
                    tangent[2] * normal[0] - tangent[0] * normal[2],
                    tangent[0] * normal[1] - tangent[1] * normal[0])
        return c, normal, binormal

    # control points' parameters along the helix: the Greville abscissae
    knots_v = [0.0] * 4 + [float(k) for k in range(1, spans)] + [float(spans)] * 4
    greville = [sum(knots_v[j + 1:j + 4]) / 3.0 for j in range(count_v)]
    grid = []
    for a, b, w in square:
        row = []
        for g in greville:
            c, n, bn = frame(2 * math.pi * turns * g / spans)
            row.append(tuple(c[i] + wire_radius * (a * n[i] + b * bn[i]) for i in range(3)))
        grid.append(row)
    ids = [[s.point(p) for p in row] for row in grid]
    weights = "(%s)" % ",".join("(%s)" % ",".join(real(w) for _ in range(count_v))
                                for _, _, w in square)
    mult_v = "(4,%s4)" % ("1," * (spans - 1))
    knots_v_text = "(%s)" % ",".join(real(k) for k in range(spans + 1))
    surface = s.add(
        "(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,3,(%s),.UNSPECIFIED.,.T.,.F.,.F.)"
        "B_SPLINE_SURFACE_WITH_KNOTS((3,2,2,2,3),%s,(0.,1.,2.,3.,4.),%s,.UNSPECIFIED.)"
        "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(%s)REPRESENTATION_ITEM('')"
        "SURFACE());" % (",".join("(%s)" % ",".join(r) for r in ids), mult_v, knots_v_text,
                         weights))

    def circle(j):
        return s.add(
            "(BOUNDED_CURVE()B_SPLINE_CURVE(2,(%s),.UNSPECIFIED.,.T.,.F.)"
            "B_SPLINE_CURVE_WITH_KNOTS((3,2,2,2,3),(0.,1.,2.,3.,4.),.UNSPECIFIED.)CURVE()"
            "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE((%s))"
            "REPRESENTATION_ITEM(''));" % (",".join(ids[i][j] for i in range(9)),
                                            ",".join(real(w) for _, _, w in square)))
    seam_curve = s.add("B_SPLINE_CURVE_WITH_KNOTS('',3,(%s),.UNSPECIFIED.,.F.,.F.,%s,%s,"
                       ".UNSPECIFIED.);" % (",".join(ids[0]), mult_v, knots_v_text))
    start = s.add("VERTEX_POINT('',%s);" % ids[0][0])
    end = s.add("VERTEX_POINT('',%s);" % ids[0][-1])
    seam = s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (start, end, seam_curve))
    low = s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (start, start, circle(0)))
    high = s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (end, end, circle(count_v - 1)))
    edges = [s.add("ORIENTED_EDGE('',*,*,%s,%s);" % (e, sense))
             for e, sense in ((low, ".T."), (seam, ".T."), (high, ".F."), (seam, ".F."))]
    loop = s.add("EDGE_LOOP('',(%s));" % ",".join(edges))
    bound = s.add("FACE_OUTER_BOUND('',%s,.T.);" % loop)
    return s.add("ADVANCED_FACE('',(%s),%s,.T.);" % (bound, surface))


def serpentine_outline(legs, length=10.0, width=1.0, gap=1.0):
    """The border of a strip width wide running up and down legs times,
    legs length long and gap apart, its turns half circles: the centre
    line offset by half the width to either side, closed by a line at each
    end. Segments ('line', p, q) or ('arc', centre, radius, p, q, ccw)."""
    pitch, h = width + gap, width / 2
    left, right = [], []
    for k in range(legs):
        x, up = k * pitch, k % 2 == 0
        y0, y1 = (0.0, length) if up else (length, 0.0)
        side = -h if up else h          # the walker's left on this leg
        left.append(("line", (x + side, y0), (x + side, y1)))
        right.append(("line", (x - side, y0), (x - side, y1)))
        if k + 1 < legs:
            c = (x + pitch / 2, y1)
            outer, inner = pitch / 2 + h, pitch / 2 - h
            # at the top the strip turns clockwise (its left side outer), at
            # the bottom anticlockwise (its left side inner)
            rl, rr = (outer, inner) if up else (inner, outer)
            left.append(("arc", c, rl, (c[0] - rl, c[1]), (c[0] + rl, c[1]), not up))
            right.append(("arc", c, rr, (c[0] - rr, c[1]), (c[0] + rr, c[1]), not up))

    def reverse(g):
        return ("line", g[2], g[1]) if g[0] == "line" else ("arc", g[1], g[2], g[4], g[3], not g[5])

    segments = left + [("line", left[-1][2], right[-1][2])]
    segments += [reverse(g) for g in reversed(right)]
    return segments + [("line", right[0][1], left[0][1])]


def slab(s, segments, thickness):
    """The solid the outline sweeps from z = 0 to z = thickness, as its
    faces: bottom, top, and a side face per segment (planes, cylinders),
    each edge written once and used by both its faces."""
    ends = lambda g: (g[1], g[2]) if g[0] == "line" else (g[3], g[4])
    vertices = {}

    def vertex(p, z):
        key = (round(p[0], 9), round(p[1], 9), z)
        if key not in vertices:
            vertices[key] = s.add("VERTEX_POINT('',%s);" % s.point((p[0], p[1], z)))
        return vertices[key]

    def placement(origin, axis, ref):
        return s.add("AXIS2_PLACEMENT_3D('',%s,%s,%s);" % (
            s.point(origin), s.direction(axis), s.direction(ref)))

    def edge_at(g, z):
        a, b = ends(g)
        if g[0] == "line":
            curve, sense = line_between(s, (a[0], a[1], z), (b[0], b[1], z)), ".T."
        else:
            c, r, ccw = g[1], g[2], g[5]
            curve = s.add("CIRCLE('',%s,%s);" % (placement((c[0], c[1], z), (0, 0, 1),
                                                             (1, 0, 0)), real(r)))
            sense = ".T." if ccw else ".F."
        return s.add("EDGE_CURVE('',%s,%s,%s,%s);" % (vertex(a, z), vertex(b, z), curve, sense))

    bottom = [edge_at(g, 0.0) for g in segments]
    top = [edge_at(g, thickness) for g in segments]
    uprights = [s.add("EDGE_CURVE('',%s,%s,%s,.T.);" % (
        vertex(ends(g)[0], 0.0), vertex(ends(g)[0], thickness),
        line_between(s, (ends(g)[0][0], ends(g)[0][1], 0.0),
                     (ends(g)[0][0], ends(g)[0][1], thickness)))) for g in segments]
    used = lambda e, sense: s.add("ORIENTED_EDGE('',*,*,%s,%s);" % (e, sense))

    def face(edges, surface):
        loop = s.add("EDGE_LOOP('',(%s));" % ",".join(edges))
        bound = s.add("FACE_OUTER_BOUND('',%s,.T.);" % loop)
        return s.add("ADVANCED_FACE('',(%s),%s,.T.);" % (bound, surface))

    faces = [face([used(e, ".F.") for e in reversed(bottom)],
                  s.add("PLANE('',%s);" % placement((0, 0, 0), (0, 0, -1), (1, 0, 0)))),
             face([used(e, ".T.") for e in top],
                  s.add("PLANE('',%s);" % placement((0, 0, thickness), (0, 0, 1), (1, 0, 0))))]
    n = len(segments)
    for i, g in enumerate(segments):
        a, b = ends(g)
        if g[0] == "line":
            d = (b[0] - a[0], b[1] - a[1])
            length = (d[0] ** 2 + d[1] ** 2) ** 0.5
            surface = s.add("PLANE('',%s);" % placement(
                (a[0], a[1], 0.0), (d[1] / length, -d[0] / length, 0), (d[0] / length, d[1] / length, 0)))
        else:
            surface = s.add("CYLINDRICAL_SURFACE('',%s,%s);" % (
                placement((g[1][0], g[1][1], 0.0), (0, 0, 1), (1, 0, 0)), real(g[2])))
        faces.append(face([used(bottom[i], ".T."), used(uprights[(i + 1) % n], ".T."),
                           used(top[i], ".F."), used(uprights[i], ".F.")], surface))
    return faces


def bounded_planes(path):
    """Two squares as IGES 108 bounded planes, each bounded by a composite
    curve (102) of four lines (110)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from gen_soup import Iges, fmt
    out = Iges()
    for x0 in (0.0, 20.0):
        c = corners(x0, 0, 10)
        lines = [out.add(110, [fmt(v) for v in c[i] + c[(i + 1) % 4]]) for i in range(4)]
        boundary = out.add(102, ["4"] + [str(d) for d in lines])
        out.add(108, ["0.", "0.", "1.", "0.", str(boundary), fmt(x0 + 5), "5.", "0.", "1."], 1)
    out.write(path, 1e-4)


def corners(x, y, size):
    return [(x, y, 0), (x + size, y, 0), (x + size, y + size, 0), (x, y + size, 0)]


def off_vertex(s, x, y, size, off):
    """A square whose second vertex lies off from its first edge's line."""
    c = corners(x, y, size)
    moved = list(c)
    moved[1] = (x + size, y + off, 0)
    lines = [(c[0], c[1]), ((x + size, y + off, 0), c[2]), None, None]
    return square(s, moved, lines)


def grid(s, n, size):
    return [square(s, corners(i * size, j * size, size)) for i in range(n) for j in range(n)]


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "gap.step"), lambda s: [off_vertex(s, 0, 0, 10, 0.005)])
    write(os.path.join(out, "skipped.step"), lambda s: [
        square(s, corners(0, 0, 10)), square(s, corners(20, 0, 10), drop_edge=True)],
        file_name_params=6)
    write(os.path.join(out, "empty.step"),
          lambda s: [square(s, corners(0, 0, 10), drop_edge=True)])
    write(os.path.join(out, "header.step"), lambda s: [square(s, corners(0, 0, 10))],
          file_name_params=6)
    write(os.path.join(out, "solid_angle.step"), lambda s: [square(s, corners(0, 0, 10))],
          solid_angle="spatial")
    write(os.path.join(out, "callout.step"), lambda s: [square(s, corners(0, 0, 10))],
          stray_item=True)
    write(os.path.join(out, "wide_gap.step"),
          lambda s: grid(s, 40, 1.0) + [off_vertex(s, 50, 0, 10, 8.0)])
    write(os.path.join(out, "appended.step"), lambda s: [square(s, corners(0, 0, 10))],
          appended="".join("//+\nPhysical Surface(%d) = {%d};\n" % (i, i) for i in range(40)))
    write(os.path.join(out, "band.step"), lambda s: [band(s, 10.0, 4.0)])
    bounded_planes(os.path.join(out, "planes.igs"))
    write(os.path.join(out, "spring.step"), lambda s: [helical_sweep(s, 30)])
    write(os.path.join(out, "zigzag.step"),
          lambda s: slab(s, serpentine_outline(20, length=14.0, gap=2.0), 3.0))


if __name__ == "__main__":
    main()
