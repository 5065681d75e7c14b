/* SPDX-License-Identifier: MIT */
/* The walkthrough benchmark's baselines (tests/bench/walk_bench.sh): the
 * same pack, camera path, viewport, renderer (platform/sw_renderer.h),
 * stats file (firmware/measure/sw_stats.h) and independent measures as seamwalk
 * (error: firmware/walk/gl/sw_seam_measure.h, every drawn triangle against the
 * exact surface on screen; cracks: firmware/walk/gl/sw_seam_drawn.h, the drawn
 * borders against each other), drawn by
 *   uniform  every visible patch on one uniform grid of S x S segments, the
 *            cells outside its trim mask left out (tests/bench/sw_cell_filter.h,
 *            the first walk's way), re-tessellated every frame;
 *   glu      GLU's NURBS tessellator re-tessellating every visible surface
 *            every frame, trimmed by the Seam Graph's loops at full detail,
 *            each sampled to the pixel tolerance at its nearest depth, in
 *            model units, as seamwalk bounds it.
 * Host-side benchmark code: allocates at start, and in GLU's case GLU
 * itself allocates in every frame (that is part of what it costs). */
#ifndef WALK_BASELINE_H
#define WALK_BASELINE_H

#include <stdint.h>

#include "sw_pack.h"
#include "sw_renderer.h"
#include "sw_seam_drawn.h"
#include "sw_stats.h"
#include "sw_trim_tess.h"
#include "sw_view.h"

/* One draw batch: a 16-bit vertex range (indices are batch-relative, as
 * sw_renderer_draw takes them), with the (u, v) of every vertex for the
 * measure. */
#define WB_BATCH_VERTICES 65536u
#define WB_BATCH_INDICES (6u * 65536u)

typedef struct wb_batch {
    sw_vertex *verts;
    float *uvs;
    uint16_t *indices;
    uint32_t vertex_count, index_count;
} wb_batch;

typedef struct wb_frame {
    uint64_t triangles;
    uint32_t drawn;            /* patches (uniform) or surfaces (glu) drawn */
    uint32_t failed;           /* surfaces GLU reported an error for, or dropped output of */
} wb_frame;

typedef struct wb_walk {
    const sw_pack *pack;
    sw_renderer *renderer;
    wb_batch batch;
    sw_stats *stats;           /* measuring frames: the error samples go here */
    sw_seam_drawn *drawn;      /* measuring frames: every drawn mesh's border */
    sw_seam_error acc;
    double measure_ms;         /* this frame's time measuring (wb_measure): not frame time */
    const float *sew_offset;   /* per surface, as seamwalk measures it */
    float bound_floor;         /* seamwalk's: a tenth of the sewing tolerance */
    double error_px;           /* uniform: the bound the measure scales by; glu: its tolerance */
    sw_trim_patch *patches;    /* every patch of the pack, as sw_trim_patches_from_pack */
    uint32_t *surface_first;   /* surface s's patches start at patches + surface_first[s] */
    uint32_t segments;         /* uniform: S */
    void *glu;                 /* glu: walk_glu.c's state */
} wb_walk;

/* Draws the batch (one sw_renderer_draw) and empties it. */
void wb_batch_flush(wb_walk *w);

/* With w->stats: the batch's triangles from first_index on against the
 * exact surface (patches, count), at depth, into the stats and w->acc; their
 * border into w->drawn as mesh `id`. */
void wb_measure(wb_walk *w, uint32_t first_index, const sw_trim_patch *patches, uint32_t count,
                uint32_t surface, uint32_t id, double depth, const sw_view *view);

/* Patch i's box, and whether any of it is in view (its nearest depth). */
sw_box wb_patch_box(const sw_pack *pack, uint32_t i);
int wb_patch_visible(const sw_pack *pack, uint32_t i, const sw_view *view, double *depth);

/* One frame: culls, tessellates, draws (the caller began the frame). */
void wb_uniform_frame(wb_walk *w, const sw_view *view, wb_frame *out);

/* GLU's form of every surface, made once (outside the timed frames); a
 * message and 0 when GLU cannot be had. *skipped: surfaces whose patches
 * GLU cannot take as one NURBS surface (left out of every frame). */
int wb_glu_init(wb_walk *w, uint32_t *skipped, char *why, size_t why_size);
void wb_glu_frame(wb_walk *w, const sw_view *view, wb_frame *out);
void wb_glu_free(wb_walk *w);

#endif
