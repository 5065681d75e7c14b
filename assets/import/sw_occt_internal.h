/* SPDX-License-Identifier: MIT */
/* What the OpenCASCADE importer's files share (C++ only, inside
 * assets/import/): OCCT's messages captured instead of printed, the
 * file's extension, what the file says of itself (sw_occt_step_file.cpp),
 * and the one place exceptions stop. The reader and converter is
 * sw_import_occt.cpp (its B-splines from sw_occt_bspline.h, its trial
 * read in a child sw_occt_read_check.cpp), the measurement for
 * cross-checks sw_occt_measure.cpp. */
#ifndef SW_OCCT_INTERNAL_H
#define SW_OCCT_INTERNAL_H

extern "C" {
#include "sw_error.h"
#include "sw_import.h"
}

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Interface_InterfaceModel.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TCollection_AsciiString.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <XSControl_WorkSession.hxx>

#include <exception>
#include <new>
#include <mutex>
#include <string>
#include <vector>

namespace sw_occt {

/* Keeps OCCT's fail and alarm messages instead of printing them: a library
 * must not write to the tool's stdout, and the first failure is the best
 * description of a malformed file we get. */
class CapturePrinter : public Message_Printer {
public:
    mutable std::vector<std::string> lines;

protected:
    /* Faces are converted on several threads, any of which may speak. */
    void send(const TCollection_AsciiString &text, const Message_Gravity gravity) const override
    {
        std::lock_guard<std::mutex> hold(lock_);
        if (gravity >= Message_Alarm && lines.size() < 16)
            lines.emplace_back(text.ToCString());
    }

private:
    mutable std::mutex lock_;
};

/* Replaces the default messenger's printers for the lifetime of one call. */
class MessageCapture {
public:
    MessageCapture() : printer_(new CapturePrinter)
    {
        const Handle(Message_Messenger) &messenger = Message::DefaultMessenger();
        saved_ = messenger->Printers();
        messenger->ChangePrinters().Clear();
        messenger->AddPrinter(printer_);
    }
    ~MessageCapture()
    {
        const Handle(Message_Messenger) &messenger = Message::DefaultMessenger();
        messenger->ChangePrinters() = saved_;
    }
    MessageCapture(const MessageCapture &) = delete;
    MessageCapture &operator=(const MessageCapture &) = delete;

    /* The first captured line, trimmed, or "" when OCCT said nothing. */
    std::string first() const
    {
        for (const std::string &line : printer_->lines) {
            size_t b = line.find_first_not_of(" \t\r\n*");
            /* "ERR StepFile : Undefined Parsing: ...": the tag is noise. */
            size_t tag = line.find(" : ", b);
            if (line.compare(b, 4, "ERR ") == 0 && tag != std::string::npos)
                b = tag + 3;
            size_t e = line.find_last_not_of(" \t\r\n*");
            if (b != std::string::npos)
                return line.substr(b, e - b + 1);
        }
        return std::string();
    }

private:
    Handle(CapturePrinter) printer_;
    Message_SequenceOfPrinters saved_;
};

/* ---- what the file says of itself (sw_occt_step_file.cpp) ---- */

/* What the file itself said about p-curves: for STEP, the number of edge uses
 * of each face (keyed by the face's TShape) whose edge carries no PCURVE on
 * that face's surface, so OCCT's reader had to project one. */
typedef TopTools_DataMapOfShapeInteger FilePcurveGaps;

/* Maps every transferred face to its p-curve gaps in the file, and to the
 * #id of its entity there (ids), which is how a user finds it. */
void map_step_pcurve_gaps(const Handle(XSControl_WorkSession) &ws, FilePcurveGaps *gaps,
                          FilePcurveGaps *ids);

/* Millimetres per file length unit, from the names OCCT's reader reports. */
double step_units_to_mm(STEPControl_Reader &reader);

/* The largest UNCERTAINTY_MEASURE_WITH_UNIT, in file units (0: none). */
double step_uncertainty(const Handle(StepData_StepModel) &model);

/* Where a check or a parser message points, as a prefix of the message:
 * "#172: " (STEP) or "entity at D325: " (IGES); "" when it names none. */
std::string check_place(const Handle(Interface_InterfaceModel) &model, int number, bool step,
                        const char *path, const std::string &message);

/* The file ends with its format's trailer (STEP: END-ISO-10303-21;, IGES:
 * the T record), checked before OCCT parses anything. */
bool file_tail_has(const char *path, bool step);

/* The line where text after a STEP file's last END-ISO-10303-21; starts, 0
 * when only spaces follow it, -1 when it has none (read whole). */
long step_text_after_trailer(const char *path);

/* The #id of the last entity whose text ends (its ';' outside a string):
 * where a truncated file was cut. 0 when none is complete. */
int last_complete_step_entity(const char *path);

/* ---- the reader's trial run (sw_occt_read_check.cpp) ---- */

/* Reads the file once in a child process: SW_OK when the reader came
 * through (whatever it thought of the file), an error naming the file when
 * it crashed or ran past the time allowed for the file's size. */
sw_status reader_survives(const char *path, bool step, sw_error *err);

/* ---- shared helpers (sw_import_occt.cpp) ---- */

/* The path's extension in lower case ("" without one). */
std::string lower_extension(const char *path);

/* The loaded model's first failing check that makes it unreadable, as one
 * phrase naming the entity ("" when there is none). The others are counted
 * in report (when given) by their text, the first one kept in full. */
std::string fatal_check_failure(const Handle(XSControl_WorkSession) &ws, bool step,
                                const char *path, sw_import_report *report);

/* The one place exceptions stop: whatever OCCT or the C++ library throws
 * becomes an error naming the file. */
template <typename Fn>
sw_status guarded(const char *path, sw_error *err, Fn fn)
{
    try {
        return fn();
    } catch (const Standard_Failure &e) {
        return sw_error_set(err, SW_ERR_FORMAT, "%s: OCCT: %s (%s)", path, e.GetMessageString(),
                            e.DynamicType()->Name());
    } catch (const std::bad_alloc &) {
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: out of memory", path);
    } catch (const std::exception &e) {
        return sw_error_set(err, SW_ERR_FORMAT, "%s: %s", path, e.what());
    } catch (...) {
        return sw_error_set(err, SW_ERR_FORMAT, "%s: unknown exception in OCCT", path);
    }
}

}  // namespace sw_occt

#endif
