/* SPDX-License-Identifier: MIT */
/* What a STEP or IGES file says of itself, read from OCCT's model and from
 * the file's text: the edge uses whose p-curves the file left out, its
 * units and uncertainty, the first check that makes it unreadable (with the
 * entity and line it names), and whether a file ends where it should. */
extern "C" {
#include "sw_step_scan.h"
}
#include "sw_occt_internal.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <STEPControl_Reader.hxx>
#include <StepBasic_UncertaintyMeasureWithUnit.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_Pcurve.hxx>
#include <StepGeom_Surface.hxx>
#include <StepGeom_SurfaceCurve.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <StepShape_EdgeCurve.hxx>
#include <StepShape_EdgeLoop.hxx>
#include <StepShape_FaceBound.hxx>
#include <StepShape_FaceSurface.hxx>
#include <StepShape_OrientedEdge.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopoDS_Shape.hxx>
#include <Transfer_TransientProcess.hxx>
#include <TransferBRep.hxx>
#include <XSControl_TransferReader.hxx>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

/* Edge uses of a STEP face whose edge carries no PCURVE on the face's own
 * surface: OCCT's reader projected those (the NIST files have none at all). */
int step_face_pcurve_gaps(const Handle(StepShape_FaceSurface) &face)
{
    Handle(StepGeom_Surface) surface = face->FaceGeometry();
    int gaps = 0;
    for (int b = 1; b <= face->NbBounds(); b++) {
        Handle(StepShape_EdgeLoop) loop =
            Handle(StepShape_EdgeLoop)::DownCast(face->BoundsValue(b)->Bound());
        if (loop.IsNull())
            continue;
        for (int e = 1; e <= loop->NbEdgeList(); e++) {
            Handle(StepShape_EdgeCurve) edge =
                Handle(StepShape_EdgeCurve)::DownCast(loop->EdgeListValue(e)->EdgeElement());
            Handle(StepGeom_SurfaceCurve) sc = edge.IsNull()
                ? Handle(StepGeom_SurfaceCurve)()
                : Handle(StepGeom_SurfaceCurve)::DownCast(edge->EdgeGeometry());
            bool found = false;
            for (int g = 1; !sc.IsNull() && g <= sc->NbAssociatedGeometry(); g++) {
                Handle(StepGeom_Pcurve) pc = sc->AssociatedGeometryValue(g).Pcurve();
                found = found || (!pc.IsNull() && pc->BasisSurface() == surface);
            }
            gaps += !found;
        }
    }
    return gaps;
}

/* The STEP entity (#id) that starts last at or before a line of the file
 * (0: none; line 0: the whole file). */
int step_entity_at_line(const char *path, long line)
{
    FILE *f = std::fopen(path, "rb");
    if (!f)
        return 0;
    int id = 0;
    long n = 1;
    bool line_start = true;
    for (int c; (line == 0 || n <= line) && (c = std::fgetc(f)) != EOF;) {
        if (line_start && c == '#') {
            int value = 0;
            if (std::fscanf(f, "%d", &value) == 1)
                id = value;
        }
        line_start = c == '\n';
        n += c == '\n';
    }
    std::fclose(f);
    return id;
}

/* The line number in one of OCCT's parser messages ("... Line 745: ..."). */
long message_line(const std::string &message)
{
    size_t at = message.find("Line ");
    return at == std::string::npos ? 0 : std::strtol(message.c_str() + at + 5, nullptr, 10);
}

/* Whether a failed check leaves the model unreadable where it points: a
 * geometric or topological entity with a bad parameter cannot become a
 * shape, and OCCT's transfer of one (a CARTESIAN_POINT with a string among
 * its coordinates) crashes; and text the parser could not read is data lost
 * without a trace. Fails elsewhere (units, contexts, names, presentation,
 * PMI, the IGES global section, a STEP check attached to no entity such as
 * the header's FILE_NAME or a reference to no entity) are messages: OCCT
 * reads on with its defaults and transfers every face it can, and so does
 * seamwalk; a face that cannot be made is named, and a file with no face
 * left fails for that. */
bool check_is_fatal(const Handle(Interface_InterfaceModel) &model, int number, bool step,
                    const std::string &fail)
{
    if (number <= 0 || number > model->NbEntities()) {
        if (step)
            return fail.find("Undefined Parsing") != std::string::npos;
        return fail.find("Global Section") == std::string::npos;
    }
    if (step && fail.find("not a quoted String") != std::string::npos)
        return false;  /* names carry no geometry (Rhino writes $ for them) */
    const char *type = model->Value(number)->DynamicType()->Name();
    /* A shape representation listing an item OCCT does not take there (a
     * PMI callout, as CAx-IF test files have) drops that item and
     * transfers the others. */
    if (step && std::strstr(type, "Representation") &&
        fail.find("(representation_item)") != std::string::npos)
        return false;
    static const char *const geometric[] = {"StepGeom_", "StepShape_", "IGESGeom_",
                                            "IGESSolid_"};
    for (const char *prefix : geometric)
        if (std::strncmp(type, prefix, std::strlen(prefix)) == 0)
            return true;
    return false;
}

/* Whether a message is about what no geometry depends on, so that
 * --strict reads past it too: a solid-angle unit, which exporters (Spatial
 * InterOp among them) write in a form OCCT reports, and which nothing in a
 * B-rep is measured in. */
bool check_is_harmless(const Handle(Interface_InterfaceModel) &model, int number, bool step)
{
    if (!step || number <= 0 || number > model->NbEntities())
        return false;
    return std::strstr(model->Value(number)->DynamicType()->Name(), "SolidAngleUnit") != nullptr;
}

}  // namespace

namespace sw_occt {

/* Names where a check points: "#172: " (STEP) or "entity at D325: " (IGES
 * directory entry). The parser's own messages name a line, which OCCT 7.6
 * counts a line or two off, so those say "near #id", except at the end of
 * the file, where the entity cut short is the last one that starts. */
std::string check_place(const Handle(Interface_InterfaceModel) &model, int number, bool step,
                        const char *path, const std::string &message)
{
    char buf[48] = "";
    Handle(StepData_StepModel) sm = Handle(StepData_StepModel)::DownCast(model);
    if (number > 0 && step && !sm.IsNull() && number <= sm->NbEntities()) {
        std::snprintf(buf, sizeof buf, "#%d: ", sm->IdentLabel(sm->Value(number)));
    } else if (number > 0 && !step) {
        std::snprintf(buf, sizeof buf, "entity at D%d: ", 2 * number - 1);
    } else if (step && message.find("end of file") != std::string::npos) {
        int id = step_entity_at_line(path, 0);
        if (id > 0)
            std::snprintf(buf, sizeof buf, "cut short in #%d: ", id);
    } else if (step && message_line(message) > 0) {
        int id = step_entity_at_line(path, message_line(message));
        if (id > 0)
            std::snprintf(buf, sizeof buf, "near #%d: ", id);
    }
    return buf;
}

/* Maps every transferred face to its p-curve gaps in the file, and to the
 * #id of its entity there (ids). */
void map_step_pcurve_gaps(const Handle(XSControl_WorkSession) &ws, FilePcurveGaps *gaps,
                          FilePcurveGaps *ids)
{
    Handle(StepData_StepModel) model = Handle(StepData_StepModel)::DownCast(ws->Model());
    Handle(Transfer_TransientProcess) tp = ws->TransferReader()->TransientProcess();
    if (tp.IsNull())
        return;
    for (int i = 1; i <= tp->NbMapped(); i++) {
        Handle(StepShape_FaceSurface) face = Handle(StepShape_FaceSurface)::DownCast(tp->Mapped(i));
        if (face.IsNull())
            continue;
        TopoDS_Shape shape = TransferBRep::ShapeResult(tp, face);
        if (shape.IsNull() || shape.ShapeType() != TopAbs_FACE)
            continue;
        gaps->Bind(shape.Located(TopLoc_Location()), step_face_pcurve_gaps(face));
        if (!model.IsNull())
            ids->Bind(shape.Located(TopLoc_Location()), model->IdentLabel(face));
    }
}

/* Millimetres per file length unit, from the names OCCT's reader reports. */
double step_units_to_mm(STEPControl_Reader &reader)
{
    TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
    reader.FileUnits(lengths, angles, solid_angles);
    if (lengths.IsEmpty())
        return 1.0;
    TCollection_AsciiString unit = lengths.First();
    unit.UpperCase();
    static const struct { const char *name; double mm; } known[] = {
        {"MM", 1.0},     {"MILLIMETRE", 1.0}, {"CM", 10.0},       {"CENTIMETRE", 10.0},
        {"M", 1000.0},   {"METRE", 1000.0},   {"KM", 1e6},        {"KILOMETRE", 1e6},
        {"UM", 1e-3},    {"MICRON", 1e-3},    {"MICROMETRE", 1e-3},
        {"INCH", 25.4},  {"IN", 25.4},        {"FT", 304.8},      {"FOOT", 304.8},
        {"MI", 1609344.0}, {"MILE", 1609344.0}, {"MIL", 0.0254},
    };
    for (const auto &k : known)
        if (unit.IsEqual(k.name))
            return k.mm;
    return 1.0;
}

/* The largest UNCERTAINTY_MEASURE_WITH_UNIT, in file units (0: none). */
double step_uncertainty(const Handle(StepData_StepModel) &model)
{
    double tolerance = 0.0;
    for (int i = 1; i <= model->NbEntities(); i++) {
        Handle(StepBasic_UncertaintyMeasureWithUnit) u =
            Handle(StepBasic_UncertaintyMeasureWithUnit)::DownCast(model->Value(i));
        if (!u.IsNull() && u->ValueComponent() > tolerance)
            tolerance = u->ValueComponent();
    }
    return tolerance;
}

/* The loaded model's first failing check that makes it unreadable, as one
 * phrase naming the entity ("" when there is none). The others are counted
 * in report (when given) by their text, the first one kept in full. */
std::string fatal_check_failure(const Handle(XSControl_WorkSession) &ws, bool step,
                                const char *path, sw_import_report *report)
{
    Interface_CheckIterator checks = ws->ModelCheckList();
    Handle(Interface_InterfaceModel) model = ws->Model();
    for (checks.Start(); checks.More(); checks.Next()) {
        const Handle(Interface_Check) &check = checks.Value();
        for (int i = 1; i <= check->NbFails(); i++) {
            std::string fail = check->CFail(i);
            std::string place = check_place(model, checks.Number(), step, path, fail);
            if (check_is_fatal(model, checks.Number(), step, fail))
                return place + fail;
            if (!report)
                continue;
            std::string kind = std::string(step ? "STEP: " : "IGES: ") + fail;
            if (check_is_harmless(model, checks.Number(), step))
                sw_import_report_harmless(report, kind.c_str());
            else
                sw_import_report_message(report, kind.c_str(), (place + fail).c_str());
        }
    }
    return std::string();
}

/* ---- truncation --------------------------------------------------------- */

/* Both formats end with a fixed trailer (STEP: END-ISO-10303-21;, IGES: the
 * T record), checked before OCCT parses anything: its IGES reader accepts a
 * file cut in the parameter section and transfers what it got, and its STEP
 * parser reports a cut as a syntax error at a line that may be off. */
bool file_tail_has(const char *path, bool step)
{
    FILE *f = std::fopen(path, "rb");
    if (!f)
        return false;
    char tail[512] = {0};
    size_t n = 0;
    if (std::fseek(f, -(long)(sizeof tail - 1), SEEK_END) != 0)
        std::rewind(f);
    n = std::fread(tail, 1, sizeof tail - 1, f);
    std::fclose(f);
    tail[n] = '\0';
    std::string text(tail, n);
    if (step)
        return text.find("END-ISO-10303-21") != std::string::npos;
    size_t end = text.find_last_not_of(" \r\n\t\x1a");
    if (end == std::string::npos)
        return false;
    size_t start = text.find_last_of('\n', end);
    std::string last = text.substr(start == std::string::npos ? 0 : start + 1,
                                   end + 1 - (start == std::string::npos ? 0 : start + 1));
    return last.size() >= 73 && last[72] == 'T';
}

/* A STEP file whose trailer is not at its end: the line where text after
 * its last END-ISO-10303-21; starts (an editor or a mesher appended a
 * script), 0 when only spaces follow it, -1 when the file has no trailer.
 * Reads the whole file: only for one whose tail lacks the trailer. */
long step_text_after_trailer(const char *path)
{
    static const char trailer[] = "END-ISO-10303-21;";
    const size_t trailer_len = sizeof trailer - 1;
    FILE *f = std::fopen(path, "rb");
    if (!f)
        return 0;
    long line = 1, after = 0;
    bool found = false;
    size_t matched = 0;  /* of the trailer, from the line's first non-space */
    bool leading = true; /* still in the line's leading spaces or the trailer */
    for (int c; (c = std::fgetc(f)) != EOF;) {
        if (c == '\n') {
            line++, matched = 0, leading = true;
            continue;
        }
        if (leading && matched < trailer_len && c == trailer[matched]) {
            if (++matched == trailer_len)
                found = true, after = 0, leading = false;
            continue;
        }
        if (leading && matched == 0 && std::isspace(c))
            continue;
        leading = false;
        if (found && after == 0 && !std::isspace(c) && matched != trailer_len)
            after = line;
    }
    std::fclose(f);
    return found ? after : -1;
}

/* The #id of the last entity whose text ends (its ';' outside a string):
 * where a truncated file was cut. 0 when none is complete. */
int last_complete_step_entity(const char *path)
{
    FILE *f = std::fopen(path, "rb");
    if (!f)
        return 0;
    int current = 0, complete = 0;
    bool line_start = true, quoted = false;
    for (int c; (c = std::fgetc(f)) != EOF;) {
        if (line_start && c == '#' && !quoted) {
            int value = 0;
            if (std::fscanf(f, "%d", &value) == 1)
                current = value;
        } else if (c == '\'') {
            quoted = !quoted;
        } else if (c == ';' && !quoted) {
            complete = current;
        }
        line_start = c == '\n';
    }
    std::fclose(f);
    return complete;
}

}  // namespace sw_occt
