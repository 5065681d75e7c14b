/* SPDX-License-Identifier: MIT */
/* The importer's geometry repairs, against OCCT:
 * - sw_occt::faithful_pcurve (assets/import/sw_occt_pcurve.h): a p-curve
 *   that strays from its edge is projected again from the edge's 3D curve;
 *   one that follows it, or strays by less than a ten-thousandth of the
 *   edge, is kept; one a period away, past a closed face's seam, is
 *   projected again to the ends the face had. On a cylinder made here,
 *   with its top circle's true p-curve and with copies moved off it; and
 *   on a sphere's lune, a meridian's p-curve drifting from the pole.
 * - sw_occt::converted_moving (assets/import/sw_occt_convert.h): a torus
 *   band over a whole turn that OCCT cannot convert, converted a period
 *   along, its copied edges naming the face's own.
 * - sw_occt::unrolled_over_period (assets/import/sw_occt_unroll.h): a
 *   thread's helical band a hair over one turn, put on a surface of its
 *   own range, converted with its trims within it and on its edges.
 * - the shared edges a face's loops name for the sewing
 *   (sw_occt::Loop.edges): a box's twelve, each in two faces.
 * - sw_occt::plane_over (assets/import/sw_occt_bspline.h): a plane's
 *   conversion made again over a wider box, only where it is that plane in
 *   the same parameters. */
#include "sw_occt_bspline.h"
#include "sw_occt_convert.h"
#include "sw_occt_face.h"
#include "sw_occt_pcurve.h"
#include "sw_occt_unroll.h"
#include "sw_test.h"

#include <GeomConvert.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Standard_Failure.hxx>
#include <cmath>
#include <memory>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <BRep_Tool.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <TopExp.hxx>
#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <map>

/* The cylinder's side and an edge of it that is not its seam (a circle). */
static bool side_and_circle(TopoDS_Face *face, TopoDS_Edge *edge)
{
    static TopoDS_Shape shape = BRepPrimAPI_MakeCylinder(5.0, 10.0).Shape();
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
        TopoDS_Face side = TopoDS::Face(f.Current());
        if (BRepAdaptor_Surface(side).GetType() != GeomAbs_Cylinder)
            continue;
        for (TopExp_Explorer e(side, TopAbs_EDGE); e.More(); e.Next()) {
            TopoDS_Edge circle = TopoDS::Edge(e.Current());
            if (BRep_Tool::IsClosed(circle, side))
                continue;   /* the seam */
            *face = side, *edge = circle;
            return true;
        }
    }
    return false;
}

/* The edge's own p-curve, moved by dv in v. */
static Handle(Geom2d_Curve) moved_by(const TopoDS_Edge &edge, const TopoDS_Face &face, double dv,
                                     double *first, double *last)
{
    Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, *first, *last);
    Handle(Geom2d_Curve) copy = Handle(Geom2d_Curve)::DownCast(c->Copy());
    copy->Translate(gp_Vec2d(0.0, dv));
    return copy;
}

static void test_a_true_pcurve_is_kept(void)
{
    TopoDS_Face face;
    TopoDS_Edge edge;
    SW_CHECK(side_and_circle(&face, &edge));
    double f = 0, l = 0;
    Handle(Geom2d_Curve) c = moved_by(edge, face, 0.0, &f, &l);
    bool projected = true;
    Handle(Geom2d_Curve) out = sw_occt::faithful_pcurve(edge, face, c, f, l, 1e-6, nullptr, &projected);
    SW_CHECK(!projected && out == c);
    SW_CHECK(sw_occt::pcurve_stray(edge, face, c, f, l) < 1e-9);
}

static void test_a_stray_pcurve_is_projected_again(void)
{
    TopoDS_Face face;
    TopoDS_Edge edge;
    SW_CHECK(side_and_circle(&face, &edge));
    double f = 0, l = 0;
    Handle(Geom2d_Curve) c = moved_by(edge, face, -3.0, &f, &l);
    SW_CHECK_NEAR(sw_occt::pcurve_stray(edge, face, c, f, l), 3.0, 1e-9);
    bool projected = false;
    Handle(Geom2d_Curve) out = sw_occt::faithful_pcurve(edge, face, c, f, l, 1e-6, nullptr, &projected);
    SW_CHECK(projected);
    double stray = sw_occt::pcurve_stray(edge, face, out, f, l);
    SW_CHECK_MSG(stray < 1e-6, "projected again, it strays %g", stray);
}

/* Off by 1e-3 mm on a circle 31.4 mm long: under a ten-thousandth of it. */
static void test_a_small_stray_is_left_alone(void)
{
    TopoDS_Face face;
    TopoDS_Edge edge;
    SW_CHECK(side_and_circle(&face, &edge));
    double f = 0, l = 0;
    Handle(Geom2d_Curve) c = moved_by(edge, face, 1e-3, &f, &l);
    bool projected = true;
    Handle(Geom2d_Curve) out = sw_occt::faithful_pcurve(edge, face, c, f, l, 1e-6, nullptr, &projected);
    SW_CHECK(!projected && out == c);
}

/* A p-curve a period away, past the seam of the closed face: the same
 * points in space (it strays by nothing), and a loop that jumps across the
 * whole face to reach it. Kept when nothing says where it should be; with
 * the ends the face had before conversion, projected again to them. */
static void test_a_pcurve_a_period_away_is_projected_again(void)
{
    TopoDS_Face face;
    TopoDS_Edge edge;
    SW_CHECK(side_and_circle(&face, &edge));
    double f = 0, l = 0;
    Handle(Geom2d_Curve) c = moved_by(edge, face, 0.0, &f, &l);
    c->Translate(gp_Vec2d(2.0 * M_PI, 0.0));
    SW_CHECK(sw_occt::pcurve_stray(edge, face, c, f, l) < 1e-9);
    bool projected = true;
    SW_CHECK(sw_occt::faithful_pcurve(edge, face, c, f, l, 1e-6, nullptr, &projected) == c);
    SW_CHECK(!projected);
    sw_occt::PcurveEnds ends;
    SW_CHECK(sw_occt::pcurve_ends(edge, face, &ends));
    SW_CHECK_NEAR(ends.reach[0], 0.5 * M_PI, 1e-12);
    Handle(Geom2d_Curve) out = sw_occt::faithful_pcurve(edge, face, c, f, l, 1e-6, &ends, &projected);
    SW_CHECK(projected);
    for (int e = 0; e < 2; e++) {
        gp_Pnt2d p = out->Value(e ? l : f);
        SW_CHECK_MSG(p.Distance(ends.at[e]) < 1e-6, "end %d at (%g, %g), not (%g, %g)", e, p.X(),
                     p.Y(), ends.at[e].X(), ends.at[e].Y());
    }
    SW_CHECK(sw_occt::pcurve_stray(edge, face, out, f, l) < 1e-6);
}

/* A torus band over a whole turn in v and 1.5e-14 more, from a hair
 * under pi (a fetched hotend mount's fillets, these very numbers): OCCT's
 * conversion throws (the range, rounded, is over 2 pi); moved a period
 * along, it converts, and the conversion is the torus where its loops
 * run. */
/* A sphere's face between two meridians, and one of them (not the pole's
 * degenerate edges). */
static bool lune_and_meridian(TopoDS_Face *face, TopoDS_Edge *edge)
{
    static TopoDS_Shape shape = BRepPrimAPI_MakeSphere(60.0, 1.0).Shape();
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
        TopoDS_Face lune = TopoDS::Face(f.Current());
        if (BRepAdaptor_Surface(lune).GetType() != GeomAbs_Sphere)
            continue;
        for (TopExp_Explorer e(lune, TopAbs_EDGE); e.More(); e.Next()) {
            TopoDS_Edge meridian = TopoDS::Edge(e.Current());
            if (BRep_Tool::Degenerated(meridian) || BRep_Tool::IsClosed(meridian, lune))
                continue;
            *face = lune, *edge = meridian;
            return true;
        }
    }
    return false;
}

/* A converted p-curve from a sphere's pole (the CAx-IF head back): it
 * starts at the pole at another u, which is the same point, and drifts to
 * the meridian's u on the way, far off it. Projected again: the meridian,
 * starting at the pole at its own u (the loop's gap there lies along the
 * pole). A projection a period away off a pole is still refused
 * (test_a_pcurve_a_period_away_is_projected_again). */
static void test_a_pcurve_from_a_pole_is_projected_again(void)
{
    TopoDS_Face face;
    TopoDS_Edge edge;
    SW_CHECK(lune_and_meridian(&face, &edge));
    double f = 0, l = 0;
    Handle(Geom2d_Curve) own = BRep_Tool::CurveOnSurface(edge, face, f, l);
    gp_Pnt2d a = own->Value(f), b = own->Value(l);
    SW_CHECK_NEAR(std::fabs(a.Y()), 0.5 * M_PI, 1e-9);   /* it starts at a pole */
    double off = sw_occt::pcurve_off(edge, face, own, f, l);
    SW_CHECK_MSG(off >= 0 && off < 1e-6, "the edge's own p-curve strays %g", off);
    /* From the pole at u + 0.3 straight to the meridian's far end, over the
     * edge's parameters. */
    TColgp_Array1OfPnt2d poles(1, 2);
    poles(1) = gp_Pnt2d(a.X() + 0.3, a.Y()), poles(2) = b;
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = f, knots(2) = l;
    TColStd_Array1OfInteger mults(1, 2);
    mults(1) = mults(2) = 2;
    Handle(Geom2d_Curve) drift = new Geom2d_BSplineCurve(poles, knots, mults, 1);
    SW_CHECK(sw_occt::pcurve_off(edge, face, drift, f, l) > 1.0);
    bool projected = false;
    Handle(Geom2d_Curve) out =
        sw_occt::faithful_pcurve(edge, face, drift, f, l, 1e-6, nullptr, &projected);
    SW_CHECK(projected);
    off = sw_occt::pcurve_off(edge, face, out, f, l);
    SW_CHECK_MSG(off >= 0 && off < 1e-6, "projected again, it strays %g", off);
    SW_CHECK_NEAR(out->Value(f).X(), a.X(), 1e-6);
}

/* A whole turn of a torus band on a trimmed surface starting at u = pi / 2
 * (pythonocc's 11752.stp): converted, its trims lie within its surface's
 * u domain, so none is put on the border (the conversion ran the trims a
 * turn shifted against the domain and the band's seam opened). */
static void test_a_whole_turn_keeps_its_trims_in_the_domain(void)
{
    Handle(Geom_ToroidalSurface) torus = new Geom_ToroidalSurface(gp_Ax3(), 43.0, 2.0);
    Handle(Geom_RectangularTrimmedSurface) band = new Geom_RectangularTrimmedSurface(
        torus, 0.5 * M_PI, 2.5 * M_PI, 6.36769 - 2.0 * M_PI, 0.5 * M_PI);
    TopoDS_Face face = BRepBuilderAPI_MakeFace(band, 1e-7).Face();
    sw_occt::FaceWork w;
    w.face = w.forward = face;
    sw_occt::convert_face(&w, 0.1);
    SW_CHECK_MSG(w.why.empty(), "%s", w.why.c_str());
    double u0 = w.surface.knots_u.front(), u1 = w.surface.knots_u.back(), lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const sw_occt::Loop &loop : w.loops)
        for (const sw_occt::TrimCurve &c : loop.curves)
            for (int i = 0; i < c.count; i++)
                lo = std::fmin(lo, c.ctrl[4 * i]), hi = std::fmax(hi, c.ctrl[4 * i]);
    printf("  surface u [%.6f, %.6f], trims u [%.6f, %.6f]\n", u0, u1, lo, hi);
    SW_CHECK(!w.loops.empty());
    SW_CHECK_MSG(lo >= u0 - 1e-9 && hi <= u1 + 1e-9, "trims [%g, %g] past the domain [%g, %g]",
                 lo, hi, u0, u1);
}

static void test_a_face_over_a_period_converts_moved_along(void)
{
    gp_Torus torus(gp_Ax3(gp::XOY()), 0.6, 0.175);
    double v0 = 3.141592653589778, v1 = 9.4247779607693793;
    TopoDS_Face face = BRepBuilderAPI_MakeFace(new Geom_ToroidalSurface(torus), 0.0, 1.5, v0, v1,
                                               1e-7);
    bool threw = false;
    try {
        BRepBuilderAPI_NurbsConvert plain(face, Standard_True);
    } catch (const Standard_Failure &) {
        threw = true;
    }
    SW_CHECK_MSG(threw, "OCCT converted it: this test no longer shows the failure it is about");
    TopoDS_Face moved = face;
    bool was_moved = false;
    std::unique_ptr<BRepBuilderAPI_NurbsConvert> conv;
    TopTools_DataMapOfShapeShape original_of;
    try {
        conv = sw_occt::converted_moving(&moved, &was_moved, &original_of);
    } catch (const Standard_Failure &e) {
        SW_CHECK_MSG(false, "not converted moved either: %s", e.GetMessageString());
        return;
    }
    SW_CHECK(was_moved && !moved.IsSame(face));
    /* The copy's edges name the face's own, for the sewing. */
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(face, TopAbs_EDGE, own);
    int named = 0, copies = 0;
    for (TopExp_Explorer e(moved, TopAbs_EDGE); e.More(); e.Next(), copies++)
        named += original_of.IsBound(e.Current()) && own.Contains(original_of.Find(e.Current()));
    SW_CHECK_MSG(copies > 0 && named == copies, "%d of %d copied edges name the face's own",
                 named, copies);
    TopoDS_Face converted = TopoDS::Face(conv->Shape());
    Handle(Geom_Surface) s = BRep_Tool::Surface(converted);
    int off = 0, samples = 0;
    for (TopExp_Explorer e(converted, TopAbs_EDGE); e.More(); e.Next()) {
        Standard_Real f, l;
        Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), converted, f, l);
        for (int i = 0; !c.IsNull() && i <= 8; i++, samples++) {
            gp_Pnt2d uv = c->Value(f + (l - f) * i / 8);
            gp_Pnt p = s->Value(uv.X(), uv.Y());
            double ru = std::hypot(p.X(), p.Y()) - 0.6;   /* off the tube's circle */
            off += std::fabs(std::hypot(ru, p.Z()) - 0.175) > 1e-6;
        }
    }
    SW_CHECK(samples > 0);
    SW_CHECK_MSG(off == 0, "%d of %d points of the loops off the torus", off, samples);
}

/* A thread's helical band on a cylinder (radius 1.4, pitch 0.5, 0.137
 * wide) over a turn and over more radians: a straight strip in (u, v). */
static TopoDS_Face helical_band(double over)
{
    const double r = 1.4, pitch = 0.5, width = 0.137;
    Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), r);
    double u0 = -M_PI, u1 = M_PI + over, rise = pitch * (u1 - u0) / (2.0 * M_PI);
    const gp_Pnt2d corners[4] = {gp_Pnt2d(u0, 0.0), gp_Pnt2d(u1, rise),
                                 gp_Pnt2d(u1, rise + width), gp_Pnt2d(u0, width)};
    BRepBuilderAPI_MakeWire wire;
    for (int i = 0; i < 4; i++)
        wire.Add(BRepBuilderAPI_MakeEdge(GCE2d_MakeSegment(corners[i], corners[(i + 1) % 4]).Value(),
                                         cylinder).Edge());
    TopoDS_Wire w = wire.Wire();
    BRepLib::BuildCurves3d(w);
    return BRepBuilderAPI_MakeFace(cylinder, w).Face();
}

/* How far the face's converted trims run past its surface's u domain, and
 * how far their points (33 a curve, on the surface) lie from the band's
 * edges in space. */
static void trims_against(const sw_occt::FaceWork &w, const TopoDS_Face &band, double *past,
                          double *off)
{
    *past = 0, *off = 0;
    double u0 = w.surface.knots_u.front(), u1 = w.surface.knots_u.back();
    for (const sw_occt::Loop &loop : w.loops)
        for (const sw_occt::TrimCurve &c : loop.curves) {
            sw_nurbs_curve view = {c.degree, c.count, c.knots.data(), c.ctrl.data()};
            double t0 = c.knots[(size_t)c.degree], t1 = c.knots[(size_t)c.count];
            for (int i = 0; i <= 32; i++) {
                sw_vec3 uv = sw_nurbs_curve_point(&view, t0 + (t1 - t0) * i / 32);
                *past = std::fmax(*past, std::fmax(u0 - uv.x, uv.x - u1));
                sw_vec3 p = sw_nurbs_surface_point(&w.surface.view, uv.x, uv.y);
                double nearest = HUGE_VAL;
                for (TopExp_Explorer e(band, TopAbs_EDGE); e.More(); e.Next()) {
                    Standard_Real f, l;
                    Handle(Geom_Curve) edge = BRep_Tool::Curve(TopoDS::Edge(e.Current()), f, l);
                    GeomAPI_ProjectPointOnCurve on(gp_Pnt(p.x, p.y, p.z), edge, f, l);
                    if (on.NbPoints() > 0)
                        nearest = std::fmin(nearest, on.LowerDistance());
                }
                *off = std::fmax(*off, nearest);
            }
        }
}

/* The band 0.0014 rad over a turn, as in a printer bed's M3 holes:
 * converted as it is, its surface runs one period and the trims past it;
 * unrolled, the surface runs the band and every trim point is on an edge. */
static void test_a_band_over_a_turn_is_unrolled(void)
{
    TopoDS_Face band = helical_band(0.0014);
    sw_occt::FaceWork plain;
    plain.face = plain.forward = band;
    sw_occt::convert_face(&plain, 0.1);
    double past, off;
    trims_against(plain, band, &past, &off);
    printf("  converted as it is: trims %.3g past the domain, %.3g off the edges\n", past, off);
    SW_CHECK_MSG(past > 1e-3, "the conversion held the band: this test no longer shows the "
                              "failure it is about");
    TopoDS_Face unrolled = sw_occt::unrolled_over_period(band);
    SW_CHECK(!unrolled.IsNull());
    if (unrolled.IsNull())
        return;
    sw_occt::FaceWork w;
    w.face = band;
    w.forward = unrolled;
    w.unrolled = true;
    sw_occt::convert_face(&w, 0.1);
    SW_CHECK_MSG(w.why.empty(), "%s", w.why.c_str());
    SW_CHECK(w.loops.size() == 1);
    trims_against(w, band, &past, &off);
    printf("  unrolled: u over [%.6f, %.6f], trims %.3g past it, %.3g off the edges\n",
           w.surface.knots_u.front(), w.surface.knots_u.back(), past, off);
    SW_CHECK(w.surface.knots_u.back() - w.surface.knots_u.front() > 2.0 * M_PI + 1e-3);
    SW_CHECK_MSG(past <= 1e-9, "trims %g past the domain", past);
    /* BuildCurves3d made the edges' curves within 1e-5 of their p-curves. */
    SW_CHECK_MSG(off <= 1e-5, "trim points %g off the band's edges", off);
}

/* A whole turn and no more (a cylinder's side), or a part of one: left to
 * the conversion. */
static void test_a_turn_or_less_is_not_unrolled(void)
{
    SW_CHECK(sw_occt::unrolled_over_period(helical_band(0.0)).IsNull());
    SW_CHECK(sw_occt::unrolled_over_period(helical_band(-1.0)).IsNull());
    TopoDS_Face side, unused;
    TopoDS_Edge circle;
    SW_CHECK(side_and_circle(&side, &circle));
    SW_CHECK(sw_occt::unrolled_over_period(side).IsNull());
}

/* A box's faces, converted with its edge map: every trim names a shared
 * edge, twelve in all, each in two faces' loops. */
static void test_a_box_names_its_shared_edges(void)
{
    TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape();
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(box, TopAbs_EDGE, TopAbs_FACE, edge_faces);
    std::map<uint32_t, int> uses;
    int unnamed = 0, faces = 0;
    for (TopExp_Explorer f(box, TopAbs_FACE); f.More(); f.Next(), faces++) {
        sw_occt::FaceWork w;
        w.face = TopoDS::Face(f.Current());
        w.forward = TopoDS::Face(w.face.Oriented(TopAbs_FORWARD));
        w.edge_faces = &edge_faces;
        sw_occt::convert_face(&w, 0.1);
        SW_CHECK_MSG(w.why.empty(), "%s", w.why.c_str());
        for (const sw_occt::Loop &loop : w.loops) {
            SW_CHECK(loop.edges.size() == loop.curves.size());
            for (uint32_t e : loop.edges)
                e ? (void)uses[e]++ : (void)unnamed++;
        }
    }
    int twice = 0;
    for (const auto &u : uses)
        twice += u.second == 2;
    printf("  %d faces: %zu edges named, %d in two faces, %d trims unnamed\n", faces, uses.size(),
           twice, unnamed);
    SW_CHECK(faces == 6 && uses.size() == 12 && twice == 12 && unnamed == 0);
}

/* A plane's conversion over the unit square, made again over a box that
 * reaches past it: the box is its domain and every point the plane's. */
static void test_a_plane_is_made_again_over_a_wider_box(void)
{
    Handle(Geom_Plane) plane = new Geom_Plane(gp_Ax3(gp_Pnt(1, 2, 3), gp_Dir(0, 0, 1),
                                                     gp_Dir(1, 0, 0)));
    Handle(Geom_BSplineSurface) conv = GeomConvert::SurfaceToBSplineSurface(
        new Geom_RectangularTrimmedSurface(plane, 0.0, 1.0, 0.0, 1.0));
    const double box[4] = {-2.0, 5.0, -1.0, 4.0};
    Handle(Geom_BSplineSurface) wide = sw_occt::plane_over(plane, conv, box);
    SW_CHECK(!wide.IsNull());
    if (wide.IsNull())
        return;
    double u0, u1, v0, v1;
    wide->Bounds(u0, u1, v0, v1);
    SW_CHECK(u0 == box[0] && u1 == box[1] && v0 == box[2] && v1 == box[3]);
    const double at[3][2] = {{-2.0, -1.0}, {5.0, 4.0}, {1.5, 0.3}};
    for (const auto &p : at)
        SW_CHECK(wide->Value(p[0], p[1]).Distance(plane->Value(p[0], p[1])) < 1e-12);
}

/* Not the plane in its own parameters (the same plane, its origin moved
 * along it), or not a plane: nothing made. */
static void test_other_surfaces_are_not_made_again(void)
{
    Handle(Geom_Plane) plane = new Geom_Plane(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1),
                                                     gp_Dir(1, 0, 0)));
    Handle(Geom_Plane) moved = new Geom_Plane(gp_Ax3(gp_Pnt(0.5, 0, 0), gp_Dir(0, 0, 1),
                                                     gp_Dir(1, 0, 0)));
    Handle(Geom_BSplineSurface) shifted = GeomConvert::SurfaceToBSplineSurface(
        new Geom_RectangularTrimmedSurface(moved, 0.0, 1.0, 0.0, 1.0));
    const double box[4] = {-1.0, 2.0, -1.0, 2.0};
    SW_CHECK(sw_occt::plane_over(plane, shifted, box).IsNull());
    Handle(Geom_CylindricalSurface) cylinder =
        new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 5.0);
    Handle(Geom_BSplineSurface) conv = GeomConvert::SurfaceToBSplineSurface(
        new Geom_RectangularTrimmedSurface(cylinder, 0.0, 1.0, 0.0, 1.0));
    SW_CHECK(sw_occt::plane_over(cylinder, conv, box).IsNull());
}

int main()
{
    SW_RUN(test_a_true_pcurve_is_kept);
    SW_RUN(test_a_stray_pcurve_is_projected_again);
    SW_RUN(test_a_small_stray_is_left_alone);
    SW_RUN(test_a_pcurve_a_period_away_is_projected_again);
    SW_RUN(test_a_pcurve_from_a_pole_is_projected_again);
    SW_RUN(test_a_face_over_a_period_converts_moved_along);
    SW_RUN(test_a_whole_turn_keeps_its_trims_in_the_domain);
    SW_RUN(test_a_band_over_a_turn_is_unrolled);
    SW_RUN(test_a_turn_or_less_is_not_unrolled);
    SW_RUN(test_a_box_names_its_shared_edges);
    SW_RUN(test_a_plane_is_made_again_over_a_wider_box);
    SW_RUN(test_other_surfaces_are_not_made_again);
    return sw_test_finish();
}
