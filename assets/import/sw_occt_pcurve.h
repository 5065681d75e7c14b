/* SPDX-License-Identifier: MIT */
/* A face's parameter curve held to its edge: BRepBuilderAPI_NurbsConvert
 * re-approximates every p-curve on the converted surface, and now and then
 * the approximation strays (a fetched handle: an edge along a quarter of a
 * cylinder came back as a degree-5 curve of 166 points swinging half a turn
 * outside the surface's domain, and the face's loop crossed itself). Such a
 * curve is projected again from the edge's own 3D curve. C++ only. */
#ifndef SW_OCCT_PCURVE_H
#define SW_OCCT_PCURVE_H

#include <Geom2d_Curve.hxx>
#include <gp_Pnt2d.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

namespace sw_occt {

/* How far the image of the p-curve c on the face's surface strays from the
 * edge's 3D curve at the same parameters over [first, last] (sampled);
 * -1 when the edge has no 3D curve. */
double pcurve_stray(const TopoDS_Edge &edge, const TopoDS_Face &face,
                    const Handle(Geom2d_Curve) &c, double first, double last);

/* Where a converted p-curve must start and end: near the ends of the
 * edge's p-curve on the face before conversion. The conversion moves a
 * parameter within an arc of a circle, never by a period; a curve that
 * starts a period away (on the other side of a closed face's seam) is the
 * same points in space and a loop that jumps across the whole face. */
struct PcurveEnds {
    gp_Pnt2d at[2];     /* at first, at last */
    double reach[2];    /* in u, in v: a quarter of the surface's period there, or infinite */
};

/* How far c's image on face strays from the edge at most, measured to the
 * edge's nearest point (parameters need not be in step); -1 when the edge
 * or face has no curve or surface. */
double pcurve_off(const TopoDS_Edge &edge, const TopoDS_Face &face,
                  const Handle(Geom2d_Curve) &c, double first, double last);

/* The ends of the edge's p-curve on face (not converted), reaching a
 * quarter period where its surface is periodic; false when it has none. */
bool pcurve_ends(const TopoDS_Edge &edge, const TopoDS_Face &face, PcurveEnds *ends);

/* c when it strays at most allowed, or a ten-thousandth of the edge's
 * length, from the edge, and starts and ends within reach of ends (when
 * given); else the edge's 3D curve projected onto the face's surface over
 * [first, last] (GeomProjLib, or shape healing's projection where that
 * fails) when that strays less and ends where c does (or, c ending out of
 * reach, ends within reach), c otherwise. *projected says which. */
Handle(Geom2d_Curve) faithful_pcurve(const TopoDS_Edge &edge, const TopoDS_Face &face,
                                     const Handle(Geom2d_Curve) &c, double first, double last,
                                     double allowed, const PcurveEnds *ends, bool *projected);

}  // namespace sw_occt

#endif
