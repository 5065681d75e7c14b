/* IGES 5.3, read natively: sections S, G, D, P, T; the curve and surface
 * entities real exporters write, trimmed surfaces (144, 141/143) and the
 * B-rep route (186/502/504/508/510/514), analytic geometry made exact NURBS,
 * transformation matrices (124) applied; model-space-only trims get parameter
 * curves by point inversion and fitting. Parses from memory (for fuzzing) or a
 * file; one part per file, named after it. Errors name the file, the section
 * and line ("bearing.iges: P line 1234 (entity 57, type 126): ...").
 * Host only. */
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
