/* SPDX-License-Identifier: MIT */
/* Measurement of what the seam walk (sw_seam_walk.h) drew, independent of
 * how it was made: each drawn triangle is sampled and compared with the
 * exact surface at the same (u, v), both projected to the screen, in
 * pixels; and once at start, each surface's sewing offset (how far its sewn border lies from the surface: the file's
 * own gaps, which no level of detail removes). No allocation; GL-free. */
#ifndef SW_SEAM_MEASURE_H
#define SW_SEAM_MEASURE_H

#include <stdint.h>

#include "sw_seam_graph.h"
#include "sw_stats.h"
#include "sw_tess.h"
#include "sw_trim_tess.h"

/* The frame's view (sw_view.h), which belongs to the walk's folder, whose
 * headers include this one: declared here, not included, so the includes
 * run one way. */
struct sw_view;

/* One surface's tessellation as drawn: vertices (positions, normals), their
 * (u, v), triangles of local indices. */
typedef struct sw_seam_mesh {
    const sw_vertex *verts;
    const float *uvs;
    const uint16_t *indices;
    uint32_t vertex_count, index_count;
} sw_seam_mesh;

/* The exact surface a mesh approximates, and what the walk allowed it. */
typedef struct sw_seam_exact {
    const sw_trim_patch *patches;
    uint32_t patch_count;
    double sew_offset;    /* model units, sw_seam_sewing_offset (sw_surface_at.h) */
    double depth;         /* the surface's nearest depth this frame */
    double error_px;      /* the walk's bound in pixels */
    double bound_floor;   /* the walk's smallest bound for the surface, model units */
} sw_seam_exact;

/* The frame's worst figures, over the surfaces measured. */
typedef struct sw_seam_error {
    double beyond_sewing_px;   /* the most a sample's error exceeds its surface's sewing
                                  offset, in pixels at the sample (scaled by half a pixel
                                  over the bound where the floor is coarser than that) */
    double sewing_offset_px;   /* the largest sewing offset, in pixels at its surface's
                                  nearest depth */
    double chord_px;           /* the most a seam chord lies from its surface at the same
                                  (u, v), on screen: the samples of zero-area triangles
                                  (the fill fans, sw_seam_fill.h), kept out of the rest */
} sw_seam_error;

/* Samples every triangle of mesh (vertices, centroid and edge midpoints)
 * against the exact surface, both projected to the screen (samples with a
 * point off screen are not counted), adds each sample's error in pixels to
 * stats and the worst figures to acc; a zero-area triangle's go to
 * acc->chord_px only. */
void sw_seam_measure_mesh(const sw_seam_mesh *mesh, const sw_seam_exact *exact,
                          const struct sw_view *view, sw_stats *stats, sw_seam_error *acc);


#endif
