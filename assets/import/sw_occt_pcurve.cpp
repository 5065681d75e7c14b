/* SPDX-License-Identifier: MIT */
/* P-curves checked against their edges (sw_occt_pcurve.h). */
#include "sw_occt_pcurve.h"

#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomProjLib.hxx>
#include <Precision.hxx>
#include <ShapeConstruct_ProjectCurveOnSurface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>

namespace sw_occt {

/* Samples along the curve: enough to see a swing of a fraction of it. */
static const int kSamples = 65;

static double stray_of(const Handle(Geom2d_Curve) &c, const Handle(Geom_Surface) &s,
                       const Handle(Geom_Curve) &c3d, double first, double last)
{
    double worst = 0;
    for (int i = 0; i < kSamples; i++) {
        double t = first + (last - first) * i / (kSamples - 1);
        gp_Pnt2d uv = c->Value(t);
        worst = std::max(worst, s->Value(uv.X(), uv.Y()).Distance(c3d->Value(t)));
    }
    return worst;
}

/* The same, measured to the nearest point of the 3D curve, not the point
 * at the same parameter: a converted edge need not keep its p-curve's
 * parameters in step with its 3D curve's, and where it does not, the curve
 * may still lie on the edge. */
static double distance_off(const Handle(Geom2d_Curve) &c, const Handle(Geom_Surface) &s,
                           const Handle(Geom_Curve) &c3d, double first, double last)
{
    double worst = 0;
    for (int i = 0; i < kSamples; i++) {
        gp_Pnt2d uv = c->Value(first + (last - first) * i / (kSamples - 1));
        gp_Pnt q = s->Value(uv.X(), uv.Y());
        GeomAPI_ProjectPointOnCurve onto(q, c3d, first, last);
        double d = std::min(q.Distance(c3d->Value(first)), q.Distance(c3d->Value(last)));
        if (onto.NbPoints() > 0)
            d = std::min(d, onto.LowerDistance());
        worst = std::max(worst, d);
    }
    return worst;
}

typedef double (*PcurveMeasure)(const Handle(Geom2d_Curve) &, const Handle(Geom_Surface) &,
                                 const Handle(Geom_Curve) &, double, double);

/* measure of c on face against the edge's 3D curve; -1 without them. */
static double measured(PcurveMeasure measure, const TopoDS_Edge &edge, const TopoDS_Face &face,
                       const Handle(Geom2d_Curve) &c, double first, double last)
{
    Standard_Real f3, l3;
    Handle(Geom_Curve) c3d = BRep_Tool::Curve(edge, f3, l3);
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (c3d.IsNull() || s.IsNull() || c.IsNull())
        return -1;
    return measure(c, s, c3d, first, last);
}

double pcurve_stray(const TopoDS_Edge &edge, const TopoDS_Face &face,
                    const Handle(Geom2d_Curve) &c, double first, double last)
{
    return measured(stray_of, edge, face, c, first, last);
}

double pcurve_off(const TopoDS_Edge &edge, const TopoDS_Face &face,
                  const Handle(Geom2d_Curve) &c, double first, double last)
{
    return measured(distance_off, edge, face, c, first, last);
}

/* The edge's 3D curve projected onto s over [first, last]: OCCT's
 * projection, else shape healing's (which keeps the parameters); null when
 * both fail. */
static Handle(Geom2d_Curve) projected_curve(Handle(Geom_Curve) c3d, const Handle(Geom_Surface) &s,
                                            double first, double last, double *stray)
{
    Handle(Geom2d_Curve) best;
    *stray = HUGE_VAL;
    for (int way = 0; way < 2; way++) {
        Handle(Geom2d_Curve) c;
        try {
            if (way == 0) {
                c = GeomProjLib::Curve2d(c3d, first, last, s);
            } else {
                Handle(ShapeConstruct_ProjectCurveOnSurface) proj =
                    new ShapeConstruct_ProjectCurveOnSurface;
                proj->Init(s, Precision::Confusion());
                if (!proj->Perform(c3d, first, last, c))
                    c.Nullify();
            }
        } catch (const Standard_Failure &) {
            c.Nullify();
        }
        double d = c.IsNull() ? HUGE_VAL : distance_off(c, s, c3d, first, last);
        if (d < *stray)
            best = c, *stray = d;
    }
    return best;
}

/* Do the curves start and end at the same (u, v), within tol? A
 * projection may land a period away on a closed surface, the same points
 * in space and the wrong side of the seam. At a pole (a sphere's, a
 * cone's apex) every u is the same point: ends that differ along it, the
 * surface between them within near of their point in space, are the same
 * (the loop's gap there is closed along the pole). */
static bool same_end(const gp_Pnt2d &a, const gp_Pnt2d &b, double tol,
                     const Handle(Geom_Surface) &s, double near)
{
    if (a.Distance(b) <= tol)
        return true;
    gp_Pnt p = s->Value(a.X(), a.Y());
    for (int k = 1; k <= 4; k++) {
        gp_Pnt2d m(a.X() + (b.X() - a.X()) * k / 4, a.Y() + (b.Y() - a.Y()) * k / 4);
        if (s->Value(m.X(), m.Y()).Distance(p) > near)
            return false;
    }
    return true;
}

static bool same_ends(const Handle(Geom2d_Curve) &a, const Handle(Geom2d_Curve) &b, double first,
                      double last, double tol, const Handle(Geom_Surface) &s, double near)
{
    return same_end(a->Value(first), b->Value(first), tol, s, near) &&
           same_end(a->Value(last), b->Value(last), tol, s, near);
}

bool pcurve_ends(const TopoDS_Edge &edge, const TopoDS_Face &face, PcurveEnds *ends)
{
    Standard_Real f, l;
    Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, f, l);
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (c.IsNull() || s.IsNull())
        return false;
    ends->at[0] = c->Value(f), ends->at[1] = c->Value(l);
    ends->reach[0] = s->IsUPeriodic() ? 0.25 * s->UPeriod() : HUGE_VAL;
    ends->reach[1] = s->IsVPeriodic() ? 0.25 * s->VPeriod() : HUGE_VAL;
    return true;
}

static bool ends_within(const Handle(Geom2d_Curve) &c, double first, double last,
                        const PcurveEnds &ends)
{
    for (int e = 0; e < 2; e++) {
        gp_Pnt2d p = c->Value(e ? last : first);
        if (!(std::fabs(p.X() - ends.at[e].X()) <= ends.reach[0] &&
              std::fabs(p.Y() - ends.at[e].Y()) <= ends.reach[1]))
            return false;
    }
    return true;
}

Handle(Geom2d_Curve) faithful_pcurve(const TopoDS_Edge &edge, const TopoDS_Face &face,
                                     const Handle(Geom2d_Curve) &c, double first, double last,
                                     double allowed, const PcurveEnds *ends, bool *projected)
{
    *projected = false;
    bool astray = ends && !ends_within(c, first, last, *ends);
    double stray = pcurve_stray(edge, face, c, first, last);
    if (stray <= allowed && !astray)
        return c;
    Standard_Real f3, l3;
    Handle(Geom_Curve) c3d = BRep_Tool::Curve(edge, f3, l3);
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    /* A stray under a ten-thousandth of the edge is left alone: no one
     * sees it, and projecting costs. */
    double length = 0;
    for (int i = 1; i < kSamples; i++)
        length += c3d->Value(first + (last - first) * (i - 1) / (kSamples - 1))
                      .Distance(c3d->Value(first + (last - first) * i / (kSamples - 1)));
    double off = distance_off(c, s, c3d, first, last), enough = std::max(allowed, 1e-4 * length);
    if (off <= enough && !astray)
        return c;
    double again_off;
    Handle(Geom2d_Curve) again = projected_curve(c3d, s, first, last, &again_off);
    if (again.IsNull())
        return c;
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    double span = std::max(std::fabs(u1 - u0), std::fabs(v1 - v0));
    /* Out of reach, c's samples may all lie on the edge while it jumps
     * across the face between two of them: the projection need only be
     * as close and end within reach. */
    bool better = astray ? again_off <= std::max(off, enough) && ends_within(again, first, last, *ends)
                         : again_off < off &&
                               same_ends(c, again, first, last, 1e-4 * span, s, enough);
    if (!better)
        return c;
    *projected = true;
    return again;
}

}  // namespace sw_occt
