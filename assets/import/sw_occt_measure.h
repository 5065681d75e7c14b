/* SPDX-License-Identifier: MIT */
/* What OpenCASCADE itself measures in a CAD file, for tests that cross-check
 * seamwalk's importers (native IGES, the OCCT path's NURBS conversion) against
 * it. Host only; without OCCT the function says "built without STEP support". */
#ifndef SW_OCCT_MEASURE_H
#define SW_OCCT_MEASURE_H

#include <stddef.h>

#include "sw_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sw_occt_measure {
    size_t faces;          /* distinct faces (each placed instance counts) */
    double box_min[3];     /* tight bounding box of the geometry, millimetres */
    double box_max[3];     /* (BRepBndLib::AddOptimal, no tolerance enlargement) */
    double area_mm2;       /* total face area (BRepGProp::SurfaceProperties, adaptive to 1e-9) */
} sw_occt_measure;

/* Reads path (STEP or IGES by extension) with OCCT's plain readers, in
 * millimetres, and measures the resulting shape. */
sw_status sw_occt_measure_file(const char *path, sw_occt_measure *out, sw_error *err);

/* OpenCASCADE's sewing of the file's faces as a soup: every face copied on
 * its own (sharing no edge, as seamwalk's sewing sees them), sewn by
 * BRepBuilderAPI_Sewing at tolerance_mm, and the border measured after. */
typedef struct sw_occt_sewing {
    size_t faces;
    size_t free_edges;       /* BRepBuilderAPI_Sewing::NbFreeEdges */
    double free_length_mm;   /* their total length */
    double border_length_mm; /* every edge use of every sewn face (seam edges twice) */
} sw_occt_sewing;

sw_status sw_occt_measure_sewing(const char *path, double tolerance_mm, sw_occt_sewing *out,
                                 sw_error *err);

#ifdef __cplusplus
}
#endif

#endif
