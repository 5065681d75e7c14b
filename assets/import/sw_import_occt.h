/* SPDX-License-Identifier: MIT */
/* STEP (AP203, AP214, AP242) and IGES through OpenCASCADE, behind a C
 * interface (the implementation is the one C++ file, sw_import_occt.cpp).
 * Reads the file, walks the assembly tree applying locations (one model part
 * per leaf product), converts every face to NURBS
 * (BRepBuilderAPI_NurbsConvert), takes each edge's parameter-space curve
 * (built with ShapeFix where the file has none), and respects face
 * orientation. Built only when OCCT is found; otherwise the functions exist
 * and say "built without STEP support". Host only. */
#ifndef SW_IMPORT_OCCT_H
#define SW_IMPORT_OCCT_H

#include "sw_error.h"
#include "sw_import.h"
#include "sw_model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when this build links OpenCASCADE. */
int sw_import_occt_available(void);

/* Reads path as STEP (.stp, .step) or IGES (.igs, .iges) by its extension.
 * Errors name the file and, for STEP, the entity (#id) where known. */
sw_status sw_import_occt_file(const char *path, const sw_import_options *options,
                              sw_model *model, sw_import_report *report, sw_error *err);

#ifdef __cplusplus
}
#endif

#endif
