/* SPDX-License-Identifier: MIT */
/* The measurement of a file by OpenCASCADE alone, for the cross-checks of
 * sw_occt_measure.h: its faces, box and area, and how its faces sew. */
extern "C" {
#include "sw_occt_measure.h"
}
#include "sw_occt_internal.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

using namespace sw_occt;

namespace {

/* OCCT's plain reader of either kind, all roots as one shape. STEP files
 * with failed checks are refused (their transfer can crash); IGES ones are
 * transferred as OCCT would, which is what a cross-check wants to see. */
template <typename Reader>
sw_status read_one_shape(const char *path, bool step, TopoDS_Shape *shape, sw_error *err)
{
    Reader reader;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    if (reader.ReadFile(path) != IFSelect_RetDone)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: OCCT cannot read it", path);
    std::string fail = step ? fatal_check_failure(reader.WS(), true, path, nullptr) : "";
    if (!fail.empty())
        return sw_error_set(err, SW_ERR_FORMAT, "%s: %s", path, fail.c_str());
    reader.TransferRoots();
    *shape = reader.OneShape();
    return SW_OK;
}

/* The file, STEP or IGES by its extension, as one shape. */
sw_status read_file_shape(const char *path, TopoDS_Shape *shape, sw_error *err)
{
    std::string ext = lower_extension(path);
    bool step = ext == "stp" || ext == "step" || ext == "p21";
    MessageCapture messages;
    return step ? read_one_shape<STEPControl_Reader>(path, true, shape, err)
                : read_one_shape<IGESControl_Reader>(path, false, shape, err);
}

sw_status measure_file(const char *path, sw_occt_measure *out, sw_error *err)
{
    TopoDS_Shape shape;
    *out = sw_occt_measure{};
    sw_status status = read_file_shape(path, &shape, err);
    if (status != SW_OK)
        return status;
    if (shape.IsNull())
        return SW_OK;   /* an empty shape: no faces, the caller decides */
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    out->faces = (size_t)faces.Extent();
    Bnd_Box box;
    BRepBndLib::AddOptimal(shape, box, Standard_False, Standard_False);
    if (!box.IsVoid())
        box.Get(out->box_min[0], out->box_min[1], out->box_min[2], out->box_max[0],
                out->box_max[1], out->box_max[2]);
    /* The adaptive form: the plain one integrates each face at a fixed Gauss
     * order and was 0.01-0.2% short on the hammer's faces. */
    GProp_GProps props;
    BRepGProp::SurfaceProperties(shape, props, 1e-9);
    out->area_mm2 = props.Mass();
    return SW_OK;
}

double edge_length(const TopoDS_Edge &edge)
{
    if (BRep_Tool::Degenerated(edge))
        return 0.0;
    BRepAdaptor_Curve curve(edge);  /* its 3D curve, or its curve on a face (IGES) */
    return GCPnts_AbscissaPoint::Length(curve);
}

sw_status measure_sewing(const char *path, double tolerance, sw_occt_sewing *out, sw_error *err)
{
    TopoDS_Shape shape;
    *out = sw_occt_sewing{};
    sw_status status = read_file_shape(path, &shape, err);
    if (status != SW_OK || shape.IsNull())
        return status;
    BRepBuilderAPI_Sewing sewing(tolerance);
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
        BRepBuilderAPI_Copy copy(f.Current());
        sewing.Add(copy.Shape());
        out->faces++;
    }
    sewing.Perform();
    for (int i = 1; i <= sewing.NbFreeEdges(); i++)
        out->free_length_mm += edge_length(sewing.FreeEdge(i));
    out->free_edges = (size_t)sewing.NbFreeEdges();
    TopoDS_Shape sewn = sewing.SewedShape();
    for (TopExp_Explorer f(sewn, TopAbs_FACE); f.More(); f.Next())
        for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next())
            out->border_length_mm += edge_length(TopoDS::Edge(e.Current()));
    return SW_OK;
}

}  // namespace

extern "C" sw_status sw_occt_measure_sewing(const char *path, double tolerance_mm,
                                            sw_occt_sewing *out, sw_error *err)
{
    if (!path || !out || !(tolerance_mm > 0))
        return sw_error_set(err, SW_ERR_ARG, "sw_occt_measure_sewing: no path, output or "
                                             "positive tolerance");
    return guarded(path, err, [&]() { return measure_sewing(path, tolerance_mm, out, err); });
}

extern "C" sw_status sw_occt_measure_file(const char *path, sw_occt_measure *out, sw_error *err)
{
    if (!path || !out)
        return sw_error_set(err, SW_ERR_ARG, "sw_occt_measure_file: no path or output");
    return guarded(path, err, [&]() { return measure_file(path, out, err); });
}
