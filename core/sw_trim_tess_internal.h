/* Internal to the trimmed tessellator: the state one sw_trim_tess call
 * shares between its steps (core/sw_trim_tess.c: input and output,
 * sw_trim_loops.c: the loops' orientation and region shrink, sw_trim_tree.c:
 * the binary trees and the corner index). Not a public API. */
#ifndef SW_TRIM_TESS_INTERNAL_H
#define SW_TRIM_TESS_INTERNAL_H

#include "sw_trim_cell.h"
#include "sw_trim_tess.h"

enum {
    SW_TT_MAX_CELL_POINTS = 32,  /* loop points a crossed cell may hold before it splits */
    SW_TT_MAX_BORDER = 4096,     /* grid points on one cell's border */
    SW_TT_DEFAULT_DEPTH = 24,
    SW_TT_MAX_DEPTH = 40,
};
#define SW_TT_SHRINK_REL 1e-9 /* of the domain: how far loop points move into the region */

typedef struct tt_leaf {
    sw_tt_rect r;
    uint32_t patch, seg_first, seg_count, crossed;
} tt_leaf;

typedef struct tt_frame {
    sw_tt_rect r;
    uint32_t patch, depth, list_off, list_count, inside;
} tt_frame;

typedef struct tt_ctx {
    const sw_trim_patch *in_patches;
    uint32_t patch_count;
    const sw_trim_loops *in_loops;
    double error;
    sw_arena *arena;
    sw_error *err;
    sw_bezier_patch *patches;   /* double copies of the control points */
    int max_n, max_m;
    sw_tt_trims trims;
    sw_tt_point *pts;
    sw_tt_loop *loops;
    uint32_t *stamp;
    uint32_t max_vertices, max_depth;
    int crossing_on_segment;
    double border_error;     /* error for cells a loop runs through */
    /* tree */
    tt_leaf *leaves;
    uint32_t leaf_count, leaf_cap;
    uint32_t *leaf_segs, leaf_seg_count, leaf_seg_cap;
    uint32_t *list, list_top, list_cap;
    /* corner index: the kept cells' corners, distinct, as (v, u) pairs sorted
     * (for horizontal sides) and as (u, v) pairs sorted (vertical sides) */
    double *by_v, *by_u;
    uint32_t corner_count;
    /* output */
    const sw_trim_tess_buffers *out;
    double *key_uv;
    uint8_t *key_kind;
    uint32_t *hash, hash_mask;
    uint32_t *seam_out;
    uint32_t vertex_count, index_count;
    sw_trim_tess_result *res;
} tt_ctx;

static inline size_t sw_tt_ctrl_doubles(int n, int m)
{
    return (size_t)(n + 1) * (size_t)(m + 1) * 4;
}

/* Orients every loop with the region on its left, moves its points into the
 * region (c->pts, c->loops, c->trims) and checks them against the domain. */
sw_status sw_tt_prepare_loops(tt_ctx *c, const double dom[4]);

/* Refines every patch into leaves (c->leaves, c->leaf_segs) and builds the
 * corner index (c->by_u, c->by_v). */
sw_status sw_tt_build_tree(tt_ctx *c);

/* The grid points on the border of leaf l in counter-clockwise order from
 * (u0, v0): its corners and its kept neighbours' corners. Returns the count,
 * or SW_TT_NONE when there are more than cap. */
uint32_t sw_tt_leaf_border(const tt_ctx *c, uint32_t l, sw_tt_pv *out, uint32_t cap);

#endif
