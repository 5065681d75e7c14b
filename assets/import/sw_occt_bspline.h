/* SPDX-License-Identifier: MIT */
/* OpenCASCADE's B-spline curves and surfaces as seamwalk's clamped NURBS
 * (C++ only, inside assets/import/): clamped where OCCT's are periodic or
 * unclamped, and copied into flat arrays the C model takes. The importer's
 * faces and loops (sw_import_occt.cpp) are made of these. */
#ifndef SW_OCCT_BSPLINE_H
#define SW_OCCT_BSPLINE_H

extern "C" {
#include "sw_nurbs.h"
}

#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>

#include <vector>

namespace sw_occt {

/* A 2D curve's points as (u, v, 0, w) and its flat knot vector. */
struct TrimCurve {
    int degree = 0, count = 0;
    std::vector<double> knots, ctrl;
};

/* A surface's knots and points, and the C model's view of them. */
struct Surface {
    std::vector<double> knots_u, knots_v, ctrl;
    sw_nurbs_surface view{};
};

/* The p-curve's used range [first, last] as a clamped B-spline. A periodic
 * one is cut first: its range may cross the period's start. */
Handle(Geom2d_BSplineCurve) clamped_pcurve(const Handle(Geom2d_Curve) &curve, double first,
                                           double last);
TrimCurve trim_curve_of(const Handle(Geom2d_BSplineCurve) &b);

/* The surface a rectangular trimmed surface trims, or s itself: where its
 * periods are told. */
Handle(Geom_Surface) basis_surface(const Handle(Geom_Surface) &s);

/* The face's surface (its location applied) as a clamped B-spline copy. */
Handle(Geom_BSplineSurface) bspline_surface_of(const TopoDS_Face &face);
void fill_surface(const Handle(Geom_BSplineSurface) &b, Surface *out);

/* The box (u0, u1, v0, v1) of the loops' control points: it holds the
 * curves (convex hull, positive weights). */
void trims_box(const std::vector<const TrimCurve *> &curves, double box[4]);

/* The face's plane as a bilinear B-spline over box, when b (the face's
 * conversion) is that plane in the same parameters; null otherwise (not a
 * plane, or parameterised otherwise). A plane's conversion covers the
 * face's own bounds, which need not hold its trims (a fetched lock body:
 * trims 2 mm past a 16 mm plate's conversion, drawn clamped to its border
 * and left unsewn). */
Handle(Geom_BSplineSurface) plane_over(const Handle(Geom_Surface) &basis,
                                       const Handle(Geom_BSplineSurface) &b, const double box[4]);

}  // namespace sw_occt

#endif
