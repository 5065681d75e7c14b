/* SPDX-License-Identifier: MIT */
/* A face converted to NURBS, moved a period along where that fails
 * (sw_occt_convert.h). */
#include "sw_occt_convert.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Vec2d.hxx>

namespace sw_occt {

static Handle(Geom2d_Curve) moved_copy(const TopoDS_Edge &edge, const TopoDS_Face &face,
                                       double du, double dv)
{
    Standard_Real f, l;
    Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, f, l);
    if (c.IsNull())
        return c;
    Handle(Geom2d_Curve) m = Handle(Geom2d_Curve)::DownCast(c->Copy());
    m->Translate(gp_Vec2d(du, dv));
    return m;
}

TopoDS_Face moved_face(const TopoDS_Face &face, double du, double dv,
                       TopTools_DataMapOfShapeShape *original_of)
{
    BRepBuilderAPI_Copy copier(face);
    TopoDS_Face copy = TopoDS::Face(copier.Shape());
    if (original_of) {
        TopTools_IndexedMapOfShape originals;
        TopExp::MapShapes(face, TopAbs_EDGE, originals);
        for (int i = 1; i <= originals.Extent(); i++)
            for (TopTools_ListOfShape::Iterator it(copier.Modified(originals(i))); it.More();
                 it.Next())
                original_of->Bind(it.Value(), originals(i));
    }
    BRep_Builder builder;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(copy, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); i++) {
        TopoDS_Edge e = TopoDS::Edge(edges(i));
        double tol = BRep_Tool::Tolerance(e);
        /* A seam has a p-curve for each of its two uses. */
        Handle(Geom2d_Curve) a = moved_copy(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), copy, du, dv);
        if (a.IsNull())
            continue;
        if (BRep_Tool::IsClosed(e, copy))
            builder.UpdateEdge(e, a,
                               moved_copy(TopoDS::Edge(e.Oriented(TopAbs_REVERSED)), copy, du, dv),
                               copy, tol);
        else
            builder.UpdateEdge(e, a, copy, tol);
    }
    return copy;
}

std::unique_ptr<BRepBuilderAPI_NurbsConvert> converted_moving(
    TopoDS_Face *face, bool *moved, TopTools_DataMapOfShapeShape *original_of)
{
    *moved = false;
    try {
        return std::make_unique<BRepBuilderAPI_NurbsConvert>(*face, Standard_True);
    } catch (const Standard_Failure &) {
        Handle(Geom_Surface) s = BRep_Tool::Surface(*face);
        double pu = !s.IsNull() && s->IsUPeriodic() ? s->UPeriod() : 0;
        double pv = !s.IsNull() && s->IsVPeriodic() ? s->VPeriod() : 0;
        static const int periods[4] = {1, -1, 2, -2};
        for (int k : periods)
            for (int along = 0; along < 2; along++) {
                double du = along == 0 ? k * pu : 0, dv = along == 1 ? k * pv : 0;
                if (du == 0 && dv == 0)
                    continue;
                try {
                    if (original_of)
                        original_of->Clear();
                    TopoDS_Face m = moved_face(*face, du, dv, original_of);
                    auto conv = std::make_unique<BRepBuilderAPI_NurbsConvert>(m, Standard_True);
                    *face = m, *moved = true;
                    return conv;
                } catch (const Standard_Failure &) {
                }
            }
        throw;
    }
}

}  // namespace sw_occt
