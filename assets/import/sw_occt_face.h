/* SPDX-License-Identifier: MIT */
/* One OpenCASCADE face made ready for the model: converted to NURBS
 * (sw_occt_convert.h), each wire's edges as p-curves on the converted
 * surface in wire order (repaired where the conversion spoiled them:
 * sw_occt_pcurve.h), the gaps between them closed within what the file
 * allows, a plane's conversion widened over its trims. Reads the face's
 * shared shape and writes only its own FaceWork, so faces are converted at
 * the same time on the build's threads (sw_import_occt.cpp adds them in
 * order). C++ only. */
#ifndef SW_OCCT_FACE_H
#define SW_OCCT_FACE_H

extern "C" {
#include "sw_error.h"
}
#include "sw_occt_bspline.h"

#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS_Face.hxx>

#include <string>
#include <vector>

namespace sw_occt {

struct Loop {
    std::vector<TrimCurve> curves;
    std::vector<int> computed;
    std::vector<double> gaps;   /* per curve: its edge's tolerance (sw_model_trim_curve.gap) */
    std::vector<uint32_t> edges; /* per curve: its shared edge (sw_model_trim_curve.edge) */
    /* per curve: how far its start and its end may stray in 3D from the
     * vertex there (the wider of the edge's and the vertex's tolerance) */
    std::vector<double> reach[2];
    int outer = 0;
};

/* One face on its way into the model: read from the file's shape in
 * order (prepare_face), converted possibly at the same time as others
 * (convert_face), added in order (add_face). */
struct FaceWork {
    TopoDS_Face face, forward;
    /* The part's edges and the faces each bounds (TopExp::MapShapesAndAncestors):
     * an edge of two faces or more, or a seam, is named by its index here */
    const TopTools_IndexedDataMapOfShapeListOfShape *edge_faces = nullptr;
    int reversed = 0;
    int missing = 0, file_gaps = 0;   /* p-curves the file lacked (made by ShapeFix) */
    Surface surface;
    std::vector<Loop> loops;
    int reprojected = 0;
    bool moved = false;               /* converted a period along (sw_occt_convert.h) */
    bool unrolled = false;            /* put on a surface over more than a period
                                         (sw_occt_unroll.h) */
    std::string why;                  /* "" once converted */
    sw_status failed = SW_OK;         /* out of memory: the import stops */
};

/* The face as a B-spline surface and its loops into w, or why it cannot be
 * used (w->why; w->failed when out of memory): no exception leaves it.
 * floor_mm: the widest gap between trim curves any face may close. */
void convert_face(FaceWork *w, double floor_mm);

}  // namespace sw_occt

#endif
