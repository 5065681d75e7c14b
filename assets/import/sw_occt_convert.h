/* SPDX-License-Identifier: MIT */
/* A face converted to NURBS (BRepBuilderAPI_NurbsConvert), moved a period
 * along where OCCT 7.6's conversion fails at the period: a closed face
 * whose p-curves span its period and a hair more (a fetched hotend
 * mount's torus fillets: v over [pi, 3 pi] and 1e-13 more) has the range,
 * rounded, over 2 pi, and Convert_TorusToBSplineSurface throws. The same
 * face a period along rounds the other way. C++ only. */
#ifndef SW_OCCT_CONVERT_H
#define SW_OCCT_CONVERT_H

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopoDS_Face.hxx>

#include <memory>

namespace sw_occt {

/* A copy of the face with its p-curves moved by (du, dv) on its surface
 * (periods, where it is closed: the same points in space). The face's
 * own edges are shared with its neighbours and stay as they are; where
 * original_of is given, each copied edge is bound to the edge it copies
 * (the sewing names edges by the file's). */
TopoDS_Face moved_face(const TopoDS_Face &face, double du, double dv,
                       TopTools_DataMapOfShapeShape *original_of = nullptr);

/* The conversion of *face, or, where OCCT throws and the surface is
 * periodic, of the face moved one or two periods either way (then *face
 * is that copy and *moved set); OCCT's failure when no move converts. */
std::unique_ptr<BRepBuilderAPI_NurbsConvert> converted_moving(
    TopoDS_Face *face, bool *moved, TopTools_DataMapOfShapeShape *original_of = nullptr);

}  // namespace sw_occt

#endif
