/* SPDX-License-Identifier: MIT */
/* One OpenCASCADE face made ready for the model (sw_occt_face.h). */
#include "sw_occt_face.h"

#include "sw_occt_convert.h"
#include "sw_occt_pcurve.h"

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

namespace sw_occt {
namespace {

/* A degree-1 trim from one (u, v) point to another. */
TrimCurve segment(const double *from, const double *to)
{
    TrimCurve t;
    t.degree = 1;
    t.count = 2;
    t.knots = {0.0, 0.0, 1.0, 1.0};
    t.ctrl = {from[0], from[1], 0.0, 1.0, to[0], to[1], 0.0, 1.0};
    return t;
}

/* "The same (u, v)" follows the loop's own extent in parameter space,
 * which is an angle on one surface and millimetres on the next. */
double same_uv(const Loop &loop)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const TrimCurve &c : loop.curves)
        for (size_t k = 0; k + 3 < c.ctrl.size(); k += 4)
            for (int d = 0; d < 2; d++)
                lo[d] = std::min(lo[d], c.ctrl[k + d]), hi[d] = std::max(hi[d], c.ctrl[k + d]);
    return 1e-9 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

/* Closes the loop in (u, v). NurbsConvert re-approximates p-curves, and at a
 * surface's pole (nist_mbe_pmi_4 face 186) the ends of neighbouring curves
 * drift apart in parameter space (0.09 in v there) while meeting in 3D; and
 * exporters leave micrometre gaps between trim curves that shape healing
 * covers by widening the vertex between them. Such a gap gets a straight
 * trim across it when it is within what the file allows there: both ends
 * within their vertex's tolerance (twice it apart), or within the file's
 * or the model's tolerance (floor_mm). Wider, the face is broken. */
std::string close_gaps(Loop *loop, const Handle(Geom_Surface) &surface, double floor_mm)
{
    std::vector<TrimCurve> closed;
    std::vector<int> computed;
    std::vector<double> gaps;
    std::vector<uint32_t> edges;
    size_t n = loop->curves.size();
    double same = same_uv(*loop);
    for (size_t i = 0; i < n; i++) {
        closed.push_back(std::move(loop->curves[i]));
        computed.push_back(loop->computed[i]);
        gaps.push_back(loop->gaps[i]);
        edges.push_back(loop->edges[i]);
        const TrimCurve &a = closed.back(), &b = loop->curves[(i + 1) % n];
        const double *end = &a.ctrl[a.ctrl.size() - 4];
        const double *start = i + 1 < n ? &b.ctrl[0] : &closed.front().ctrl[0];
        if (std::hypot(end[0] - start[0], end[1] - start[1]) <= same)
            continue;
        gp_Pnt p = surface->Value(end[0], end[1]), q = surface->Value(start[0], start[1]);
        double allowed = std::max(floor_mm, 2.0 * std::max(loop->reach[1][i],
                                                           loop->reach[0][(i + 1) % n]));
        if (p.Distance(q) > allowed) {
            char why[96];
            std::snprintf(why, sizeof why, "trims %.3g mm apart, over the %.3g mm allowed",
                          p.Distance(q), allowed);
            return why;
        }
        closed.push_back(segment(end, start));
        computed.push_back(1);
        gaps.push_back(p.Distance(q));
        edges.push_back(0);   /* no edge of the file's */
    }
    loop->curves = std::move(closed);
    loop->computed = std::move(computed);
    loop->gaps = std::move(gaps);
    loop->edges = std::move(edges);
    return std::string();
}

/* The edge's tolerance, widened by its vertex at the start (end = 0) or
 * the end (end = 1) of its use in the wire. */
double end_reach(const TopoDS_Edge &edge, double edge_tolerance, int end)
{
    TopoDS_Vertex v = end ? TopExp::LastVertex(edge, Standard_True)
                          : TopExp::FirstVertex(edge, Standard_True);
    return v.IsNull() ? edge_tolerance : std::max(edge_tolerance, BRep_Tool::Tolerance(v));
}

/* The file's edges, for naming a face's edges for the sewing. */
struct EdgeNames {
    const TopTools_IndexedDataMapOfShapeListOfShape *edge_faces;
    const TopTools_DataMapOfShapeShape *original_of;   /* a moved copy's edges (may be empty) */
};

/* The edge's id for the sewing (its index in edge_faces) where it bounds
 * two faces or more, or one face on both sides (a closed face's seam: left
 * unnamed, its trims were sewn onto anything near, and two solids a few
 * micrometres apart were sewn to each other through them), else 0
 * (sw_model_trim_curve.edge): a face the file does not join to others is
 * sewn by position. */
uint32_t shared_edge(const EdgeNames &names, const TopoDS_Edge &used)
{
    const TopTools_IndexedDataMapOfShapeListOfShape *edge_faces = names.edge_faces;
    const TopoDS_Edge &edge = names.original_of && names.original_of->IsBound(used)
                                  ? TopoDS::Edge(names.original_of->Find(used))
                                  : used;
    int index = edge_faces ? edge_faces->FindIndex(edge) : 0;
    if (index <= 0)
        return 0;
    const TopTools_ListOfShape &faces = edge_faces->FindFromIndex(index);
    for (TopTools_ListOfShape::Iterator it(faces); it.More(); it.Next())
        if (!it.Value().IsSame(faces.First()))
            return (uint32_t)index;
    return BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First())) ? (uint32_t)index : 0;
}

/* The loop of one wire: each edge's p-curve on the converted face (the face
 * itself when conv is null), in wire order, reversed where the edge runs
 * against its curve. Returns why it failed, or "". */
std::string loop_of_wire(const TopoDS_Wire &wire, const TopoDS_Face &face,
                         const BRepBuilderAPI_NurbsConvert *conv, const TopoDS_Face &converted,
                         const EdgeNames &names, int computed, double floor_mm, Loop *loop,
                         int *reprojected)
{
    int edges_in_wire = 0, explored = 0;
    for (TopoDS_Iterator it(wire); it.More(); it.Next())
        edges_in_wire++;
    for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next()) {
        const TopoDS_Edge &edge = ex.Current();
        TopoDS_Edge moved = conv ? TopoDS::Edge(conv->ModifiedShape(edge)) : edge;
        moved.Orientation(edge.Orientation());
        Standard_Real f, l;
        Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(moved, converted, f, l);
        if (c.IsNull())
            return "an edge without a parameter curve";
        /* Ten times the file's edge tolerance (not the converted edge's,
         * which the conversion widens to cover its own approximation). */
        bool projected = false;
        PcurveEnds ends;
        c = faithful_pcurve(moved, converted, c, f, l,
                            10.0 * std::max(BRep_Tool::Tolerance(edge), Precision::Confusion()),
                            pcurve_ends(edge, face, &ends) ? &ends : nullptr, &projected);
        *reprojected += projected;
        Handle(Geom2d_BSplineCurve) b = clamped_pcurve(c, f, l);
        if (edge.Orientation() == TopAbs_REVERSED)
            b->Reverse();
        loop->curves.push_back(trim_curve_of(b));
        loop->computed.push_back(computed);
        /* OCCT's edge tolerance covers how far each face's p-curve image
         * strays from the edge (shape healing widens it where the file's
         * faces do not meet): the sewing uses it as the file's own word.
         * The converted edge's tolerance covers the conversion's p-curve:
         * one projected again answers for itself. */
        double edge_tolerance =
            std::max(BRep_Tool::Tolerance(edge),
                     projected ? pcurve_off(moved, converted, c, f, l) : BRep_Tool::Tolerance(moved));
        loop->gaps.push_back(edge_tolerance);
        loop->edges.push_back(shared_edge(names, edge));
        for (int end = 0; end < 2; end++)
            loop->reach[end].push_back(
                end_reach(edge, std::max(edge_tolerance, Precision::Confusion()), end));
        explored++;
    }
    /* BRepTools_WireExplorer skips edges of wires it cannot chain; a loop
     * missing some would trim wrongly, so that is a failure, not a loop. */
    if (explored != edges_in_wire || explored == 0)
        return "a wire whose edges do not chain";
    return close_gaps(loop, BRep_Tool::Surface(converted), floor_mm);
}

/* The box (u0, u1, v0, v1) of the loops' trims (trims_box). */
void loops_box(const std::vector<Loop> &loops, double box[4])
{
    std::vector<const TrimCurve *> curves;
    for (const Loop &loop : loops)
        for (const TrimCurve &c : loop.curves)
            curves.push_back(&c);
    trims_box(curves, box);
}

/* A plane whose conversion does not hold the face's trims is made again
 * over them (plane_over), a thousandth wider each way; the trims keep
 * their parameters. */
void widen_plane(const TopoDS_Face &face, const TopoDS_Face &converted,
                 const std::vector<Loop> &loops, Surface *surface)
{
    double box[4];
    loops_box(loops, box);
    double u0 = surface->knots_u.front(), u1 = surface->knots_u.back();
    double v0 = surface->knots_v.front(), v1 = surface->knots_v.back();
    if (box[0] >= u0 && box[1] <= u1 && box[2] >= v0 && box[3] <= v1)
        return;
    double du = 1e-3 * (box[1] - box[0]), dv = 1e-3 * (box[3] - box[2]);
    const double wider[4] = {std::fmin(box[0] - du, u0), std::fmax(box[1] + du, u1),
                             std::fmin(box[2] - dv, v0), std::fmax(box[3] + dv, v1)};
    Handle(Geom_BSplineSurface) b = plane_over(BRep_Tool::Surface(face),
                                               bspline_surface_of(converted), wider);
    if (!b.IsNull())
        fill_surface(b, surface);
}

/* The u period of the face's surface (of the surface a trimmed surface
 * trims), 0 when it has none. */
double u_period(const TopoDS_Face &face)
{
    Handle(Geom_Surface) basis = basis_surface(BRep_Tool::Surface(face));
    return basis->IsUPeriodic() ? basis->UPeriod() : 0;
}

/* A face over a whole turn (a torus band on a trimmed surface) whose
 * converted trims run the turn shifted against the converted surface's
 * domain: OpenCASCADE's conversion started the surface 0.04 rad past the
 * seam the trims start at, and the strip between lay outside the domain
 * (its trim points were put on the border, and the band's seam opened 1.6
 * mm). The surface is made periodic, its origin moved to where the trims
 * start (a knot inserted there), and made open and clamped again over
 * [start, start + period]: the same points, the trims inside. */
void wrap_turn(const TopoDS_Face &face, const TopoDS_Face &converted,
               const std::vector<Loop> &loops, Surface *surface)
{
    double period = u_period(face);
    double u0 = surface->knots_u.front(), u1 = surface->knots_u.back();
    if (!(period > 0) || std::fabs(u1 - u0 - period) > 1e-9 * period)
        return;
    double box[4], eps = 1e-9 * period;
    loops_box(loops, box);
    if ((box[0] >= u0 - eps && box[1] <= u1 + eps) || box[1] - box[0] > period + eps)
        return;
    double start = box[0] < u0 - eps ? box[0] : box[1] - period;
    double origin = start < u0 ? start + period : start;
    try {
        Handle(Geom_BSplineSurface) b = bspline_surface_of(converted);
        if (!b->IsUClosed())
            return;
        /* A knot a hair from the origin is taken for it: a new one there
         * would leave a span too short for floats (the Bambu mount). */
        for (int k = 1; k <= b->NbUKnots(); k++)
            if (std::fabs(b->UKnot(k) - origin) <= 1e-6 * period)
                origin = b->UKnot(k);
        b->InsertUKnot(origin, 1, Precision::PConfusion());
        b->SetUPeriodic();
        int at = 0;
        for (int k = 1; k <= b->NbUKnots() && at == 0; k++)
            at = std::fabs(b->UKnot(k) - origin) <= Precision::PConfusion() ? k : 0;
        if (at == 0)
            return;
        b->SetUOrigin(at);
        b->SetUNotPeriodic();
        double a0, a1, b0, b1;
        b->Bounds(a0, a1, b0, b1);
        b->Segment(a0, a1, b0, b1);   /* clamped, as the model takes it */
        Surface wrapped;
        fill_surface(b, &wrapped);
        double shift = start - wrapped.knots_u.front();
        for (double &k : wrapped.knots_u)
            k += shift;
        *surface = std::move(wrapped);
    } catch (const Standard_Failure &) {
        /* left as it was: the trims past its domain are put on its border */
    }
}

}  // namespace

/* The face as a B-spline surface and its loops, or why it cannot be used.
 * It reads the shared shape and writes only w: faces are converted at the
 * same time on the build's threads. */
static void convert_face_unguarded(FaceWork *w, double floor_mm)
{
    int computed = w->missing > 0 || w->file_gaps > 0;
    TopoDS_Face face = w->forward;   /* or its copy a period along */
    bool moved = false;
    /* An unrolled face is on its B-spline already, with its own p-curves:
     * the conversion would approximate them again. */
    std::unique_ptr<BRepBuilderAPI_NurbsConvert> conv;
    TopTools_DataMapOfShapeShape original_of;   /* a moved copy's edges: the file's */
    if (!w->unrolled)
        conv = converted_moving(&face, &moved, &original_of);
    w->moved = moved;
    TopoDS_Face converted = conv ? TopoDS::Face(conv->Shape().Oriented(TopAbs_FORWARD)) : face;
    fill_surface(bspline_surface_of(converted), &w->surface);
    TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
        if (it.Value().ShapeType() != TopAbs_WIRE)
            continue;
        Loop loop;
        const TopoDS_Wire &wire = TopoDS::Wire(it.Value());
        loop.outer = wire.IsSame(outer);
        w->why = loop_of_wire(wire, face, conv.get(), converted,
                              {w->edge_faces, &original_of}, computed,
                              floor_mm, &loop, &w->reprojected);
        if (!w->why.empty())
            return;
        w->loops.push_back(std::move(loop));
    }
    widen_plane(face, converted, w->loops, &w->surface);
    wrap_turn(face, converted, w->loops, &w->surface);
}

/* No exception leaves a thread: each becomes the face's reason, or a stop. */
void convert_face(FaceWork *w, double floor_mm)
{
    try {
        convert_face_unguarded(w, floor_mm);
    } catch (const Standard_Failure &e) {
        w->why = std::string("OCCT: ") + e.GetMessageString();
    } catch (const std::bad_alloc &) {
        w->failed = SW_ERR_NO_MEMORY;
    } catch (const std::exception &e) {
        w->why = e.what();
    } catch (...) {
        w->why = "unknown exception in OCCT";
    }
}

}  // namespace sw_occt
