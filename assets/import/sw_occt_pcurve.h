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
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

namespace sw_occt {

/* How far the image of the p-curve c on the face's surface strays from the
 * edge's 3D curve at the same parameters over [first, last] (sampled);
 * -1 when the edge has no 3D curve. */
double pcurve_stray(const TopoDS_Edge &edge, const TopoDS_Face &face,
                    const Handle(Geom2d_Curve) &c, double first, double last);

/* c when it strays at most allowed, or a ten-thousandth of the edge's
 * length, from the edge; else the edge's 3D curve projected onto the face's
 * surface over [first, last] (GeomProjLib, or shape healing's projection
 * where that fails) when that strays less, c otherwise. *projected says
 * which. */
Handle(Geom2d_Curve) faithful_pcurve(const TopoDS_Edge &edge, const TopoDS_Face &face,
                                     const Handle(Geom2d_Curve) &c, double first, double last,
                                     double allowed, bool *projected);

}  // namespace sw_occt

#endif
