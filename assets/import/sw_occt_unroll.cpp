/* SPDX-License-Identifier: MIT */
#include "sw_occt_unroll.h"

#include "sw_occt_bspline.h"

#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <cmath>

namespace sw_occt {

namespace {

/* Rounding puts a whole turn's p-curves a hair over the period (1e-13);
 * those convert whole (sw_occt_convert.h). */
const double kOver = 1e-6;

bool over_period(const Handle(Geom_Surface) &basis, const double uv[4])
{
    return (basis->IsUPeriodic() && uv[1] - uv[0] > (1 + kOver) * basis->UPeriod()) ||
           (basis->IsVPeriodic() && uv[3] - uv[2] > (1 + kOver) * basis->VPeriod());
}

bool has_seam(const TopoDS_Face &face)
{
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
        if (BRep_Tool::IsClosed(TopoDS::Edge(ex.Current()), face))
            return true;
    return false;
}

/* The basis over uv (a millionth of the span wider each way, for p-curve
 * samples on the edge of the bounds), or null when not within tol. */
Handle(Geom_BSplineSurface) approximated(const Handle(Geom_Surface) &basis, const double uv[4],
                                         double tol)
{
    double du = 1e-6 * (uv[1] - uv[0]), dv = 1e-6 * (uv[3] - uv[2]);
    Handle(GeomAdaptor_Surface) range =
        new GeomAdaptor_Surface(basis, uv[0] - du, uv[1] + du, uv[2] - dv, uv[3] + dv);
    GeomConvert_ApproxSurface approx(range, tol, GeomAbs_C2, GeomAbs_C2, 9, 9, 1000, 1);
    if (!approx.HasResult() || !(approx.MaxError() <= tol))
        return Handle(Geom_BSplineSurface)();
    return approx.Surface();
}

}  // namespace

TopoDS_Face unrolled_over_period(const TopoDS_Face &face)
{
    try {
        TopLoc_Location loc;
        Handle(Geom_Surface) basis = basis_surface(BRep_Tool::Surface(face, loc));
        if (!basis->IsUPeriodic() && !basis->IsVPeriodic())
            return TopoDS_Face();   /* most faces: no bounds to take */
        double uv[4];
        BRepTools::UVBounds(face, uv[0], uv[1], uv[2], uv[3]);
        if (!over_period(basis, uv) || has_seam(face))
            return TopoDS_Face();
        Bnd_Box box;
        BRepBndLib::Add(face, box);
        double tol = std::max(1e-7 * std::sqrt(box.SquareExtent()), Precision::Confusion());
        Handle(Geom_BSplineSurface) b = approximated(basis, uv, tol);
        if (b.IsNull())
            return TopoDS_Face();
        BRep_Builder builder;
        TopoDS_Face unrolled;
        builder.MakeFace(unrolled, b, loc, BRep_Tool::Tolerance(face));
        for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
            const TopoDS_Edge &edge = TopoDS::Edge(ex.Current());
            Standard_Real first, last;
            Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, first, last);
            if (c.IsNull())
                return TopoDS_Face();
            builder.UpdateEdge(edge, c, b, loc, BRep_Tool::Tolerance(edge));
            builder.Range(edge, b, loc, first, last);
        }
        for (TopoDS_Iterator it(face); it.More(); it.Next())
            builder.Add(unrolled, it.Value());
        return unrolled;
    } catch (const Standard_Failure &) {
        return TopoDS_Face();
    }
}

}  // namespace sw_occt
