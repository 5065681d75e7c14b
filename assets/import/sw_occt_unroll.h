/* SPDX-License-Identifier: MIT */
/* A face that runs more than its surface's period, put on a B-spline
 * surface of its own range before it is converted. A thread's helical band
 * on a cylinder can run a turn and a hair (a printer bed's M3 holes: 2 pi
 * + 0.0014 rad). OpenCASCADE's NURBS conversion makes the surface over one
 * period and re-approximates the band's helices on it: the part past the
 * period jumps across the whole domain (0.15 mm off the edge), and no
 * projection repairs a curve the domain cannot hold. (Cutting the face in
 * two with ShapeUpgrade_ShapeDivideClosed was tried: OCCT 7.6 trims the
 * piece that crosses u = 0 to [0, 0.00014].) C++ only. */
#ifndef SW_OCCT_UNROLL_H
#define SW_OCCT_UNROLL_H

#include <TopoDS_Face.hxx>

namespace sw_occt {

/* When face's (FORWARD) p-curves span more than a millionth over its
 * surface's period in u or v: a copy on a B-spline surface approximating
 * the surface over that span with its own parameters, within a ten-millionth
 * of the face's size, so the same p-curves hold on it (they are added to
 * the face's edges for the new surface). A null face when it needs none, or
 * when the face has a seam edge or the approximation falls short (then it
 * is converted as it is). */
TopoDS_Face unrolled_over_period(const TopoDS_Face &face);

}  // namespace sw_occt

#endif
