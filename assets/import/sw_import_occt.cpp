/* SPDX-License-Identifier: MIT */
/* STEP (AP203, AP214, AP242) and IGES through OpenCASCADE 7.6 behind the C
 * interface of sw_import_occt.h: reading and converting. What the file says
 * of itself is read in sw_occt_step_file.cpp, the measurement for
 * cross-checks (sw_occt_measure.h) is sw_occt_measure.cpp.
 *
 * Reading: STEP through STEPCAFControl_Reader into an XCAF document, whose
 * assembly tree gives one model part per leaf shape instance with its name and
 * location (STEPControl_Reader's roots when the document holds no shapes).
 * IGES has no assembly tree worth the name: its roots become one part named
 * after the file. OCCT scales everything to millimetres ("xstep.cascade.unit").
 *
 * Converting: each part's faces, their missing p-curves made with ShapeFix
 * first (in order: that writes into shared edges), converted on the
 * build's threads (sw_occt_face.h) and added to the model in order.
 *
 * No C++ exception crosses the C interface: every entry point catches
 * Standard_Failure, std::exception and anything else. OCCT's messages are
 * captured (not printed) while we run, so an error can quote them. */
extern "C" {
#include "sw_import_occt.h"
#include "sw_step_scan.h"
#include "sw_math.h"
#include "sw_occt_measure.h"
}
#include "sw_occt_unroll.h"
#include "sw_occt_face.h"
#include "sw_occt_internal.h"
extern "C" {
#include "sw_parts.h"
}

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Wire.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <Transfer_TransientProcess.hxx>
#include <TransferBRep.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <exception>
#include <memory>
#include <string>
#include <vector>

using namespace sw_occt;

namespace {

/* Forwards OCCT's transfer progress to options->progress, at most once per
 * percent so the callback stays cheap. */
class ProgressForward : public Message_ProgressIndicator {
public:
    ProgressForward(const sw_import_options *options, const char *stage)
        : options_(options), stage_(stage)
    {
    }

protected:
    void Show(const Message_ProgressScope &, const Standard_Boolean force) override
    {
        double position = GetPosition();
        if (!force && position - last_ < 0.01)
            return;
        last_ = position;
        options_->progress(options_->progress_user, stage_, position);
    }

private:
    const sw_import_options *options_;
    const char *stage_;
    double last_ = -1.0;
};

void report_progress(const sw_import_options *options, const char *stage, double fraction)
{
    if (options && options->progress)
        options->progress(options->progress_user, stage, fraction);
}

/* ---- small helpers ----------------------------------------------------- */

}  // namespace

namespace sw_occt {

std::string lower_extension(const char *path)
{
    const char *dot = std::strrchr(path, '.');
    const char *slash = std::strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        return std::string();
    std::string ext(dot + 1);
    for (char &c : ext)
        c = (char)std::tolower((unsigned char)c);
    return ext;
}

}  // namespace sw_occt

namespace {

/* "dir/linkrods.step" -> "linkrods": the part name when the file has none. */
std::string file_stem(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    std::string name(slash ? slash + 1 : path);
    size_t dot = name.rfind('.');
    return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

sw_mat4 matrix_of(const gp_Trsf &t)
{
    sw_mat4 m = sw_mat4_identity();
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            m.m[c * 4 + r] = t.Value(r + 1, c + 1);
    return m;
}

/* ---- faces -------------------------------------------------------------- */

struct ImportContext {
    const char *path;
    const sw_import_options *options;
    sw_model *model;
    sw_import_report *report;
    sw_error *err;
    FilePcurveGaps gaps;
    FilePcurveGaps face_ids;    /* STEP: each face's #id in the file */
    size_t faces_total = 0, faces_done = 0;
};

/* Edge uses of the wire (in the original face) without a p-curve, given one
 * with ShapeFix; returns how many were missing. Planes need none stored (OCCT
 * projects on the fly), but those projections are computed all the same. */
int fix_missing_pcurves(const TopoDS_Wire &wire, const TopoDS_Face &face)
{
    int missing = 0, absent = 0;
    for (TopoDS_Iterator it(wire); it.More(); it.Next()) {
        const TopoDS_Edge &edge = TopoDS::Edge(it.Value());
        Standard_Real f, l;
        Standard_Boolean stored = Standard_False;
        Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, f, l, &stored);
        if (!stored)
            missing++;
        if (c.IsNull())
            absent++;
    }
    if (absent > 0) {
        Handle(ShapeFix_Wire) fix = new ShapeFix_Wire(wire, face, Precision::Confusion());
        fix->FixEdgeCurves();
    }
    return missing;
}

/* The widest gap between trim curves any face may close, whatever its
 * vertices say: the file's stated tolerance or the model's (an earlier
 * input's), both in millimetres. */
double gap_floor_mm(const ImportContext *ctx)
{
    return std::max(ctx->report->model_tolerance_mm, (double)ctx->model->model_tolerance);
}


/* The face's orientation, and the p-curves it lacks made. ShapeFix writes
 * them into edges the face shares with its neighbours, so this runs in
 * order, before any conversion. mirrored: the part's placement flips
 * handedness, which flips the face's normal once more. */
void prepare_face(const ImportContext *ctx, const TopoDS_Face &face, bool mirrored, FaceWork *w)
{
    w->face = face;
    w->forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    w->reversed = (face.Orientation() == TopAbs_REVERSED) != mirrored;
    if (face.Location().Transformation().IsNegative())
        w->reversed = !w->reversed;
    ctx->gaps.Find(w->forward.Located(TopLoc_Location()), w->file_gaps);
    for (TopoDS_Iterator it(w->forward); it.More(); it.Next())
        if (it.Value().ShapeType() == TopAbs_WIRE)
            w->missing += fix_missing_pcurves(TopoDS::Wire(it.Value()), w->forward);
    TopoDS_Face unrolled = unrolled_over_period(w->forward);
    if (!unrolled.IsNull())
        w->forward = unrolled, w->unrolled = true;
}

/* Adds a converted face to the current part; a face that cannot be used
 * is skipped, counted and named with its reason (an error when strict): one
 * bad face should not lose a whole assembly, nor go unnoticed. The name
 * leads with the face and the reason, so that a long part name is what the
 * report's kind cuts. */
sw_status add_face(ImportContext *ctx, const FaceWork &w, size_t index)
{
    if (w.failed != SW_OK)
        return sw_error_set(ctx->err, w.failed, "%s: out of memory", ctx->path);
    std::string why = w.why;
    if (why.empty()) {
        std::vector<std::vector<sw_nurbs_curve>> views(w.loops.size());
        std::vector<sw_model_loop_input> inputs(w.loops.size());
        for (size_t i = 0; i < w.loops.size(); i++) {
            const Loop &l = w.loops[i];
            for (const TrimCurve &t : l.curves)
                views[i].push_back({t.degree, t.count, t.knots.data(), t.ctrl.data()});
            inputs[i] = {views[i].data(), l.computed.data(), views[i].size(), l.outer,
                         l.gaps.data(), l.edges.data()};
        }
        sw_status status = sw_model_add_surface(ctx->model, &w.surface.view, w.reversed,
                                                inputs.data(), inputs.size(), ctx->err);
        if (status == SW_OK) {
            ctx->report->faces++;
            ctx->report->faces_unrolled += w.unrolled;
            ctx->report->pcurves_computed += (size_t)std::max(w.missing, w.file_gaps);
            ctx->report->pcurves_reprojected += (size_t)w.reprojected;
            ctx->report->faces_moved += w.moved;
            return SW_OK;
        }
        why = ctx->err ? ctx->err->message : sw_status_name(status);
    }
    const char *part = ctx->model->part_count ? ctx->model->parts[ctx->model->part_count - 1].name
                                              : "";
    /* STEP names the face by its entity, which a user can look up; IGES
     * faces by their place among the part's. */
    int id = 0;
    std::string face_name = ctx->face_ids.Find(w.face.Located(TopLoc_Location()), id) && id > 0
                                ? "face #" + std::to_string(id)
                                : "face " + std::to_string(index + 1);
    if (ctx->options && ctx->options->strict)
        return sw_error_set(ctx->err, SW_ERR_FORMAT, "%s: %s of part '%s': %s (--strict is set)",
                            ctx->path, face_name.c_str(), part, why.c_str());
    std::string kind = face_name + ": " + why + " (part " + part + ")";
    sw_import_report_unsupported(ctx->report, kind.c_str());
    if (ctx->err)
        ctx->err->status = SW_OK;
    return SW_OK;
}

/* Faces converted at once, then added: the progress moves, and the
 * converted surfaces waiting to be added stay few. */
const size_t FACES_AT_ONCE = 64;

struct ConvertRun {
    FaceWork *work;
    double floor_mm;
};

extern "C" void convert_part(void *arg, uint32_t i)
{
    ConvertRun *run = static_cast<ConvertRun *>(arg);
    convert_face(&run->work[i], run->floor_mm);
}

/* One part per leaf: its faces in its own frame, then the placement applied
 * through the model so the part records where it was put. */
sw_status add_part(ImportContext *ctx, const TopoDS_Shape &shape, const TopLoc_Location &placement,
                   const std::string &name)
{
    sw_status status = sw_model_begin_part(ctx->model, name.c_str(), nullptr, ctx->err);
    if (status != SW_OK)
        return status;
    size_t part = ctx->model->part_count - 1;
    TopLoc_Location total = placement * shape.Location();
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape.Located(TopLoc_Location()), TopAbs_FACE, faces);
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(shape.Located(TopLoc_Location()), TopAbs_EDGE, TopAbs_FACE,
                                  edge_faces);
    std::vector<FaceWork> work((size_t)faces.Extent());
    for (int i = 1; i <= faces.Extent(); i++) {
        prepare_face(ctx, TopoDS::Face(faces(i)), total.Transformation().IsNegative(),
                     &work[(size_t)i - 1]);
        work[(size_t)i - 1].edge_faces = &edge_faces;
    }
    /* The conversion is most of an import (a cylinder's p-curves are
     * approximated again on its B-spline); faces go in order whatever ran
     * at once, so the model is the same on any runner. */
    for (size_t first = 0; first < work.size(); first += FACES_AT_ONCE) {
        size_t n = std::min(work.size() - first, FACES_AT_ONCE);
        ConvertRun run = {&work[first], gap_floor_mm(ctx)};
        sw_parts_run(ctx->options ? ctx->options->runner : nullptr, convert_part, &run,
                     (uint32_t)n);
        for (size_t i = first; i < first + n; i++) {
            status = add_face(ctx, work[i], i);
            work[i] = FaceWork();   /* in the model now */
            if (status != SW_OK)
                return status;
        }
        ctx->faces_done += n;
        if (ctx->faces_total > 0)
            report_progress(ctx->options, "faces", (double)ctx->faces_done / (double)ctx->faces_total);
    }
    sw_mat4 m = matrix_of(total.Transformation());
    sw_model_transform_part(ctx->model, part, &m);
    return SW_OK;
}

}  // namespace


namespace {

/* ---- reading and the assembly tree ------------------------------------- */

struct Leaf {
    TopoDS_Shape shape;
    TopLoc_Location placement;
    std::string name;
};

std::string label_name(const TDF_Label &label)
{
    Handle(TDataStd_Name) name;
    if (!label.FindAttribute(TDataStd_Name::GetID(), name))
        return std::string();
    /* With no replacement character the conversion gives UTF-8. */
    return TCollection_AsciiString(name->Get()).ToCString();
}

/* Depth-first over the assembly: every component's location composes with
 * its parents'; a shape that is not an assembly is a leaf. The depth limit
 * guards against a malformed file whose assembly refers to itself. */
void collect_leaves(const TDF_Label &label, const TopLoc_Location &placement,
                    const std::string &instance, int depth, std::vector<Leaf> *leaves)
{
    if (depth > 64)
        return;
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(label, components);
        for (const TDF_Label &component : components) {
            TDF_Label referred;
            if (XCAFDoc_ShapeTool::GetReferredShape(component, referred))
                collect_leaves(referred, placement * XCAFDoc_ShapeTool::GetLocation(component),
                               label_name(component), depth + 1, leaves);
        }
        return;
    }
    TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    if (shape.IsNull())
        return;
    std::string name = label_name(label);
    leaves->push_back({shape, placement, name.empty() ? instance : name});
}

/* A read that failed: one line naming the file and, where OCCT tells us,
 * the entity. loaded: OCCT built a model (and a check list) despite errors;
 * otherwise only its parser's messages say what went wrong. */
sw_status read_failure(const ImportContext *ctx, const Handle(XSControl_WorkSession) &ws,
                       bool step, bool loaded, const MessageCapture &messages)
{
    std::string why = loaded ? fatal_check_failure(ws, step, ctx->path, nullptr) : "";
    if (why.empty()) {
        why = messages.first();
        if (!why.empty())
            why = check_place(ws->Model(), 0, step, ctx->path, why) + why;
    }
    if (why.empty())
        why = step ? "not a STEP file OCCT can read" : "not an IGES file OCCT can read";
    return sw_error_set(ctx->err, SW_ERR_FORMAT, "%s: %s", ctx->path, why.c_str());
}

sw_status truncated(const ImportContext *ctx, bool step)
{
    if (step)
        return sw_error_set(ctx->err, SW_ERR_FORMAT,
                            "%s: truncated: ends after #%d without END-ISO-10303-21;", ctx->path,
                            last_complete_step_entity(ctx->path));
    return sw_error_set(ctx->err, SW_ERR_FORMAT,
                        "%s: truncated: no terminate (T) section at the end", ctx->path);
}

/* After a successful parse: fails that make the model unreadable. The
 * messages it reads on past are counted, and refused under --strict only
 * after the faces (strict_after_faces): a face that cannot be used is the
 * reason a user needs to hear first. */
sw_status check_loaded(ImportContext *ctx, const Handle(XSControl_WorkSession) &ws, bool step,
                       const MessageCapture &messages)
{
    if (!fatal_check_failure(ws, step, ctx->path, ctx->report).empty())
        return read_failure(ctx, ws, step, true, messages);
    return SW_OK;
}

/* --strict, once every face was taken: the messages about the file that
 * geometry may depend on. */
sw_status strict_after_faces(const ImportContext *ctx)
{
    size_t told = sw_import_report_strict_messages(ctx->report);
    if (!ctx->options || !ctx->options->strict || told == 0)
        return SW_OK;
    return sw_error_set(ctx->err, SW_ERR_FORMAT, "%s: %s (%zu message%s about the file, and "
                        "--strict is set)", ctx->path, ctx->report->first_message, told,
                        told > 1 ? "s" : "");
}

sw_status read_step(ImportContext *ctx, const MessageCapture &messages, std::vector<Leaf> *leaves)
{
    STEPCAFControl_Reader reader;
    reader.SetNameMode(Standard_True);
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    STEPControl_Reader &basic = reader.ChangeReader();
    report_progress(ctx->options, "read", 0.0);
    if (reader.ReadFile(ctx->path) != IFSelect_RetDone)
        return read_failure(ctx, basic.WS(), true, false, messages);
    sw_status status = check_loaded(ctx, basic.WS(), true, messages);
    if (status != SW_OK)
        return status;

    ctx->report->units_to_mm = step_units_to_mm(basic);
    ctx->report->model_tolerance_mm = step_uncertainty(basic.StepModel()) * ctx->report->units_to_mm;

    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    bool transferred;
    if (ctx->options && ctx->options->progress) {
        Handle(ProgressForward) progress = new ProgressForward(ctx->options, "transfer");
        transferred = reader.Transfer(doc, progress->Start());
    } else {
        transferred = reader.Transfer(doc);
    }
    if (transferred) {
        TDF_LabelSequence free_shapes;
        XCAFDoc_DocumentTool::ShapeTool(doc->Main())->GetFreeShapes(free_shapes);
        for (const TDF_Label &label : free_shapes)
            collect_leaves(label, TopLoc_Location(), std::string(), 0, leaves);
    }
    XCAFApp_Application::GetApplication()->Close(doc);
    /* No XDE data (or an XDE transfer that failed): the plain reader's roots. */
    if (leaves->empty() && basic.TransferRoots() > 0)
        for (int i = 1; i <= basic.NbShapes(); i++)
            leaves->push_back({basic.Shape(i), TopLoc_Location(), std::string()});
    map_step_pcurve_gaps(basic.WS(), &ctx->gaps, &ctx->face_ids);
    return SW_OK;
}

sw_status read_iges(ImportContext *ctx, const MessageCapture &messages, std::vector<Leaf> *leaves)
{
    IGESControl_Reader reader;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    report_progress(ctx->options, "read", 0.0);
    if (reader.ReadFile(ctx->path) != IFSelect_RetDone)
        return read_failure(ctx, reader.WS(), false, false, messages);
    sw_status status = check_loaded(ctx, reader.WS(), false, messages);
    if (status != SW_OK)
        return status;
    const IGESData_GlobalSection &global = reader.IGESModel()->GlobalSection();
    /* OCCT gives the file unit (flag, name and scale combined) in
     * millimetres, the unit it converts to. */
    ctx->report->units_to_mm = global.UnitValue();
    ctx->report->model_tolerance_mm = global.Resolution() * ctx->report->units_to_mm;
    report_progress(ctx->options, "transfer", 0.0);
    reader.TransferRoots();
    TopoDS_Shape shape = reader.OneShape();
    if (!shape.IsNull())
        leaves->push_back({shape, TopLoc_Location(), std::string()});
    return SW_OK;
}

sw_status import_file(ImportContext *ctx)
{
    std::string ext = lower_extension(ctx->path);
    bool step = ext == "stp" || ext == "step" || ext == "p21";
    if (!step && ext != "igs" && ext != "iges")
        return sw_error_set(ctx->err, SW_ERR_ARG,
                            "%s: not a STEP (.stp, .step) or IGES (.igs, .iges) file name",
                            ctx->path);
    struct stat st;
    if (stat(ctx->path, &st) != 0)
        return sw_error_set(ctx->err, SW_ERR_IO, "%s: %s", ctx->path, std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        return sw_error_set(ctx->err, SW_ERR_IO, "%s: %s, expected a %s file", ctx->path,
                            S_ISDIR(st.st_mode) ? "a directory" : "not a regular file",
                            step ? "STEP" : "IGES");
    FILE *f = std::fopen(ctx->path, "rb");
    if (!f)
        return sw_error_set(ctx->err, SW_ERR_IO, "%s: %s", ctx->path, std::strerror(errno));
    std::fclose(f);
    if (!file_tail_has(ctx->path, step)) {
        long after = step ? step_text_after_trailer(ctx->path) : -1;
        if (after < 0)
            return truncated(ctx, step);
        /* OCCT's parser stops at the trailer; what follows is not STEP. */
        char full[96];
        std::snprintf(full, sizeof full, "line %ld: text after END-ISO-10303-21; (not read)", after);
        sw_import_report_message(ctx->report, "STEP: text after END-ISO-10303-21; (not read)", full);
    }
    /* Limits OpenCASCADE does not have: a shell listing a face many times
     * kept it busy for minutes (sw_step_scan.h). */
    sw_step_scan_result scan;
    sw_status scanned = step ? sw_step_scan_file(ctx->path, &scan, ctx->err) : SW_OK;
    if (scanned != SW_OK)
        return scanned;

    sw_status survived = reader_survives(ctx->path, step, ctx->err);
    if (survived != SW_OK)
        return survived;
    MessageCapture messages;
    std::vector<Leaf> leaves;
    sw_status status = step ? read_step(ctx, messages, &leaves) : read_iges(ctx, messages, &leaves);
    if (status != SW_OK)
        return status;
    for (const Leaf &leaf : leaves) {
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(leaf.shape, TopAbs_FACE, faces);
        ctx->faces_total += (size_t)faces.Extent();
    }
    if (ctx->faces_total == 0)
        return sw_error_set(ctx->err, SW_ERR_FORMAT, "%s: OCCT found no faces in the file",
                            ctx->path);
    for (const Leaf &leaf : leaves) {
        std::string name = leaf.name.empty() ? file_stem(ctx->path) : leaf.name;
        status = add_part(ctx, leaf.shape, leaf.placement, name);
        if (status != SW_OK)
            return status;
    }
    if (ctx->report->model_tolerance_mm > (double)ctx->model->model_tolerance)
        ctx->model->model_tolerance = (float)ctx->report->model_tolerance_mm;
    report_progress(ctx->options, "faces", 1.0);
    return strict_after_faces(ctx);
}

}  // namespace

extern "C" int sw_import_occt_available(void)
{
    return 1;
}

extern "C" sw_status sw_import_occt_file(const char *path, const sw_import_options *options,
                                         sw_model *model, sw_import_report *report, sw_error *err)
{
    if (!path || !model)
        return sw_error_set(err, SW_ERR_ARG, "sw_import_occt_file: no path or model");
    sw_import_report local_report;
    if (!report)
        report = &local_report;
    std::memset(report, 0, sizeof *report);
    report->units_to_mm = 1.0;
    return guarded(path, err, [&]() {
        ImportContext ctx{path, options, model, report, err, FilePcurveGaps(), FilePcurveGaps()};
        return import_file(&ctx);
    });
}
