/* SPDX-License-Identifier: MIT */
/* OCCT's B-splines as seamwalk's clamped NURBS (sw_occt_bspline.h). */
#include "sw_occt_bspline.h"

#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <cmath>

namespace sw_occt {

/* seamwalk's B-splines are clamped (end knots of multiplicity degree + 1).
 * OCCT's need not be: SetNotPeriodic leaves the periodic knot pattern, and
 * files may hold unclamped ones. Segmenting to the valid range clamps. */
static bool clamped(const TColStd_Array1OfReal &flat, int degree, int poles)
{
    int lo = flat.Lower();
    return flat(lo) == flat(lo + degree) && flat(lo + poles) == flat(lo + poles + degree);
}

static void clamp_curve(const Handle(Geom2d_BSplineCurve) &b)
{
    if (b->IsPeriodic())
        b->SetNotPeriodic();
    TColStd_Array1OfReal flat(1, b->NbPoles() + b->Degree() + 1);
    b->KnotSequence(flat);
    if (!clamped(flat, b->Degree(), b->NbPoles()))
        b->Segment(flat(1 + b->Degree()), flat(1 + b->NbPoles()));
}

static void clamp_surface(const Handle(Geom_BSplineSurface) &b)
{
    if (b->IsUPeriodic())
        b->SetUNotPeriodic();
    if (b->IsVPeriodic())
        b->SetVNotPeriodic();
    int du = b->UDegree(), dv = b->VDegree(), nu = b->NbUPoles(), nv = b->NbVPoles();
    TColStd_Array1OfReal ku(1, nu + du + 1), kv(1, nv + dv + 1);
    b->UKnotSequence(ku);
    b->VKnotSequence(kv);
    if (!clamped(ku, du, nu) || !clamped(kv, dv, nv))
        b->Segment(ku(1 + du), ku(1 + nu), kv(1 + dv), kv(1 + nv));
}

Handle(Geom2d_BSplineCurve) clamped_pcurve(const Handle(Geom2d_Curve) &curve, double first,
                                           double last)
{
    Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(curve);
    if (b.IsNull()) {
        Handle(Geom2d_TrimmedCurve) piece = new Geom2d_TrimmedCurve(curve, first, last);
        b = Geom2dConvert::CurveToBSplineCurve(piece);
    } else {
        b = Handle(Geom2d_BSplineCurve)::DownCast(b->Copy());
        if (std::fabs(first - b->FirstParameter()) > 1e-12 ||
            std::fabs(last - b->LastParameter()) > 1e-12)
            b->Segment(first, last);
    }
    clamp_curve(b);
    return b;
}

TrimCurve trim_curve_of(const Handle(Geom2d_BSplineCurve) &b)
{
    TrimCurve t;
    t.degree = b->Degree();
    t.count = b->NbPoles();
    TColStd_Array1OfReal flat(1, b->NbPoles() + b->Degree() + 1);
    b->KnotSequence(flat);
    t.knots.assign(flat.begin(), flat.end());
    t.ctrl.reserve((size_t)t.count * 4);
    for (int i = 1; i <= t.count; i++) {
        gp_Pnt2d p = b->Pole(i);
        t.ctrl.insert(t.ctrl.end(), {p.X(), p.Y(), 0.0, b->Weight(i)});
    }
    return t;
}

Handle(Geom_BSplineSurface) bspline_surface_of(const TopoDS_Face &face)
{
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);   /* the face's location applied */
    Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s);
    if (b.IsNull())
        b = GeomConvert::SurfaceToBSplineSurface(s);
    else
        b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
    clamp_surface(b);
    return b;
}

void fill_surface(const Handle(Geom_BSplineSurface) &b, Surface *out)
{
    int nu = b->NbUPoles(), nv = b->NbVPoles();
    TColStd_Array1OfReal ku(1, nu + b->UDegree() + 1), kv(1, nv + b->VDegree() + 1);
    b->UKnotSequence(ku);
    b->VKnotSequence(kv);
    out->knots_u.assign(ku.begin(), ku.end());
    out->knots_v.assign(kv.begin(), kv.end());
    out->ctrl.resize((size_t)nu * (size_t)nv * 4);
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            gp_Pnt p = b->Pole(i + 1, j + 1);
            double *c = &out->ctrl[((size_t)j * (size_t)nu + (size_t)i) * 4];
            c[0] = p.X();
            c[1] = p.Y();
            c[2] = p.Z();
            c[3] = b->Weight(i + 1, j + 1);
        }
    out->view.degree_u = b->UDegree();
    out->view.degree_v = b->VDegree();
    out->view.count_u = nu;
    out->view.count_v = nv;
    out->view.knots_u = out->knots_u.data();
    out->view.knots_v = out->knots_v.data();
    out->view.ctrl = out->ctrl.data();
}

Handle(Geom_Surface) basis_surface(const Handle(Geom_Surface) &s)
{
    Handle(Geom_RectangularTrimmedSurface) trimmed =
        Handle(Geom_RectangularTrimmedSurface)::DownCast(s);
    return trimmed.IsNull() ? s : trimmed->BasisSurface();
}

void trims_box(const std::vector<const TrimCurve *> &curves, double box[4])
{
    box[0] = box[2] = HUGE_VAL, box[1] = box[3] = -HUGE_VAL;
    for (const TrimCurve *c : curves)
        for (size_t i = 0; i + 3 < c->ctrl.size(); i += 4)
            for (int a = 0; a < 2; a++)
                box[2 * a] = std::fmin(box[2 * a], c->ctrl[i + a]),
                box[2 * a + 1] = std::fmax(box[2 * a + 1], c->ctrl[i + a]);
}

Handle(Geom_BSplineSurface) plane_over(const Handle(Geom_Surface) &basis,
                                       const Handle(Geom_BSplineSurface) &b, const double box[4])
{
    Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(basis);
    if (plane.IsNull() || !(box[1] > box[0]) || !(box[3] > box[2]))
        return Handle(Geom_BSplineSurface)();
    double u0, u1, v0, v1;
    b->Bounds(u0, u1, v0, v1);
    /* Same parameters: the conversion and the plane agree at its corners
     * and centre, within a billionth of its size. */
    double size = b->Value(u0, v0).Distance(b->Value(u1, v1));
    const double at[5][2] = {{u0, v0}, {u1, v0}, {u0, v1}, {u1, v1},
                             {0.5 * (u0 + u1), 0.5 * (v0 + v1)}};
    for (const auto &p : at)
        if (b->Value(p[0], p[1]).Distance(plane->Value(p[0], p[1])) > 1e-9 * size + 1e-12)
            return Handle(Geom_BSplineSurface)();
    TColgp_Array2OfPnt poles(1, 2, 1, 2);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            poles(i + 1, j + 1) = plane->Value(box[i], box[2 + j]);
    TColStd_Array1OfReal ku(1, 2), kv(1, 2);
    TColStd_Array1OfInteger mu(1, 2), mv(1, 2);
    ku(1) = box[0], ku(2) = box[1], kv(1) = box[2], kv(2) = box[3];
    mu(1) = mu(2) = mv(1) = mv(2) = 2;
    return new Geom_BSplineSurface(poles, ku, kv, mu, mv, 1, 1);
}

}  // namespace sw_occt
