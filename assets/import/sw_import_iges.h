/* SPDX-License-Identifier: MIT */
/* IGES 5.3, read natively: sections S, G, D, P, T; the curve and surface
 * entities real exporters write, trimmed surfaces (144, 141/143) and the
 * B-rep route (186/502/504/508/510/514), analytic geometry made exact NURBS,
 * transformation matrices (124) applied; model-space-only trims get parameter
 * curves by point inversion and fitting. Parses from memory (for fuzzing) or a
 * file. Errors name the file, the section and line ("bearing.iges: P line
 * 1234 (entity D 57, type 126): ..."); positions are physical records within
 * the section (sequence numbers in columns 74-80 are not trusted).
 *
 * Parts: the caller (scene loader, seamwalk-pack) begins the part, named
 * after the file, before calling; the importer only adds surfaces to the
 * current part (sw_model_add_surface starts an unnamed one if there is none).
 * Faces: independent 186/514/510/144/143 entities and bare surfaces; an
 * entity marked physically dependent is reached through its parent, unless
 * no parent used it (gpucast_teapot.igs marks its 32 surfaces dependent with
 * no parent). A face needing an unsupported entity, and every independent
 * entity of an unsupported type, is skipped and counted in the report
 * ("IGES 402"); options->strict makes that an error.
 * Units: coordinates become millimetres (G units flag and model space scale);
 * the file's minimum resolution (G 19) is the model tolerance, raised into
 * model->model_tolerance; parameter curves computed by point inversion are
 * fitted within options->tolerance_mm, else the file's, else 0.01 mm.
 * Failure: the whole file is read and checked before anything is added, so
 * a malformed file leaves the model unchanged; only a failure inside
 * sw_model_add_surface itself (out of memory, trims enclosing nothing) can
 * leave the faces added before it, and callers discard the model on error.
 * The report is cleared at the start. Host only. */
#ifndef SW_IMPORT_IGES_H
#define SW_IMPORT_IGES_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_import.h"
#include "sw_model.h"

sw_status sw_import_iges_memory(const char *text, size_t size, const char *file_name,
                                const sw_import_options *options, sw_model *model,
                                sw_import_report *report, sw_error *err);

sw_status sw_import_iges_file(const char *path, const sw_import_options *options,
                              sw_model *model, sw_import_report *report, sw_error *err);

#endif
