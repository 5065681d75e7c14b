/* The per-frame work of a walk: visibility (patch boxes against the frustum),
 * a tessellation level per visible patch from the screen-space error bound and
 * the patch's second-derivative bounds (paper 000 section 4.1, paper 004
 * section 6.1), then tessellation into a batch buffer and drawing. All memory
 * comes from the arena at init; the frame functions never allocate.
 * Selection is pure computation; drawing runs on the GL thread. */
#ifndef SW_WALK_H
#define SW_WALK_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_pack.h"
#include "sw_renderer.h"
#include "sw_tess.h"
#include "sw_view.h"

typedef struct sw_patch_state {
    uint8_t nu, nv;          /* grid chosen this frame */
    uint8_t visible;
    uint8_t capped;          /* the grid hit SW_TESS_MAX_SEGMENTS: bound not met */
    float min_depth;         /* eye-space depth used for the bound */
} sw_patch_state;

/* Batch capacity: one 16-bit vertex range, and indices for the largest grid. */
#define SW_BATCH_VERTICES 65536u
#define SW_BATCH_INDICES (6u * 65536u)

typedef struct sw_walk {
    const sw_pack *pack;
    sw_patch_state *state;            /* one per patch */
    sw_vertex *batch_vertices;
    uint16_t *batch_indices;
    uint32_t batch_vertex_count, batch_index_count;
    double error_px;
} sw_walk;

typedef struct sw_frame_counts {
    uint32_t visible, capped;
    uint64_t triangles;
} sw_frame_counts;

/* Arena bytes sw_walk_init takes beyond the pack's runtime_bytes, which
 * already budgets SW_RUNTIME_BYTES_PER_PATCH for each patch's state. */
size_t sw_walk_arena_bytes(void);
sw_status sw_walk_init(sw_walk *walk, const sw_pack *pack, sw_arena *arena, double error_px,
                       sw_error *err);

/* Culls and picks every patch's grid for this view. */
sw_frame_counts sw_walk_select(sw_walk *walk, const sw_view *view);

/* Tessellates the visible patches and draws them in batches, one colour per
 * part, leaving out grid cells outside a patch's trim mask. Returns the
 * triangles drawn. GL thread only. */
uint64_t sw_walk_draw(sw_walk *walk, sw_renderer *renderer);

/* Patch i's trim mask, or NULL when the whole patch is drawn. */
const sw_pack_trim_mask *sw_walk_patch_mask(const sw_walk *walk, uint32_t i);

/* The float view of patch i, as the tessellator takes it. */
sw_bezier_patchf sw_walk_patch(const sw_walk *walk, uint32_t i);
sw_box sw_walk_patch_box(const sw_walk *walk, uint32_t i);

#endif
