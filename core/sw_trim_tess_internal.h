/* SPDX-License-Identifier: MIT */
/* Internal to the trimmed tessellator: the state one sw_trim_tess call
 * shares between its steps (core/sw_trim_tess.c: input and output,
 * sw_trim_loops.c: the loops' orientation and region shrink, sw_trim_grid.c:
 * the conformal grid and its bounds, sw_trim_bucket.c: loop segments by
 * cell, sw_trim_sweep.c: the row sweep and crossed cells, sw_trim_eval.c:
 * the surface at grid points and loop points). Not a public API. */
#ifndef SW_TRIM_TESS_INTERNAL_H
#define SW_TRIM_TESS_INTERNAL_H

#include "sw_trim_cell.h"
#include "sw_trim_tess.h"

enum {
    SW_TT_MAX_CELL_POINTS = 32,  /* loop points per part of a crossed cell (up to 8 x 8 parts,
                                    then grid lines) */
    SW_TT_MAX_SUB = 4,           /* sub-patch intervals per knot interval, per axis (tt_grid.sub) */
    SW_TT_WHOLE = 0xFF,          /* a knot interval left whole: the patch's own bounds */
    SW_TT_MAX_SPLIT = 8,         /* crossed cells split at most 8 x 8 (border_fraction, crowding) */
    SW_TT_MAX_INSERT = 4096,     /* grid lines added for the loops, per axis */
    SW_TT_REFINE_ROUNDS = 24,
    SW_TT_BASIS_BYTES = 1 << 20, /* the column basis cache, at most */
    SW_TT_DEFAULT_DEPTH = 24,
    SW_TT_MAX_DEPTH = 40,
};
#define SW_TT_SHRINK_REL 1e-9 /* of the domain: how far loop points move into the region */
#define SW_TT_ONTO_LINE_ULPS 8 /* ulps of the domain's size: a loop point this near a side
                                  or 0 is on it */

/* A loop segment (by its start point) meeting grid cell (col, row), closed. */
typedef struct tt_pair {
    uint32_t col, row, seg;
} tt_pair;

/* The conformal tensor grid (core/sw_trim_grid.c). Knot lines are the
 * patches' domain edges; each knot interval splits into `sub` sub-patch
 * intervals, each of those into a uniform count of grid intervals. */
typedef struct tt_grid {
    double *ku, *kv;            /* knot lines, nku and nkv of them */
    uint32_t nku, nkv, sub;
    uint32_t *table;            /* patch of knot cell (kc, kr) at kr * (nku - 1) + kc, or NONE */
    double *bounds;             /* per patch and sub-patch: M_uu, M_uv, M_vv of the sub-patch */
    double *whole;              /* per patch: its own M_uu, M_uv, M_vv */
    uint8_t *bounded;           /* per patch: bounds computed */
    double *gu, *gv;            /* grid lines: ncol + 1 and nrow + 1 */
    uint32_t *col_k, *row_k;    /* knot interval of each grid column / row */
    uint8_t *col_s, *row_s;     /* sub-patch interval within it, SW_TT_WHOLE: not split */
    uint32_t ncol, nrow, cap_u, cap_v;
    uint32_t c0, c1, r0, r1;    /* columns [c0, c1) and rows [r0, r1) meeting the loops' box */
    double box[4];              /* the loops' box (moved points) */
} tt_grid;

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
    tt_grid grid;
    /* segments by cell, sorted by (row, col); row_first[r] the first of row r */
    tt_pair *pairs;
    uint32_t pair_count, pair_cap, *row_first;
    uint32_t cell_id;        /* stamp for sw_tt_cell_rings, one per (sub)cell */
    /* evaluation: per grid line slot (line & 1) and knot column, the patch
     * contracted in v at the line (core/sw_trim_eval.c) */
    double *line_q;
    uint32_t *line_stamp;
    double *col_basis;       /* per box column: degree, then B_i(s) and B_i'(s), or NULL */
    /* output */
    const sw_trim_tess_buffers *out;
    double *key_uv;
    uint8_t *key_kind;
    uint32_t *hash, hash_mask, hashed_count;
    sw_vec3 *src_normal;     /* per caller's loop point: the surface normal there, once */
    uint8_t *src_has_normal;
    uint32_t *seam_out;
    uint32_t *line_ids[2];   /* vertex of grid point (col, line), slot line & 1 */
    uint32_t vertex_count, index_count;
    sw_trim_tess_result *res;
    uint32_t *collapsed;     /* caller's loops with no area in (u, v) but some in space */
    uint32_t collapsed_count;
} tt_ctx;

static inline size_t sw_tt_ctrl_doubles(int n, int m)
{
    return (size_t)(n + 1) * (size_t)(m + 1) * 4;
}

/* How far loop points move into the region for a surface of domain dom
 * (sw_trim_tess_shrink). */
double sw_tt_shrink_of(const double dom[4]);

/* Orients every loop with the region on its left, moves its points into the
 * region (c->pts, c->loops, c->trims) and checks them against the domain. */
sw_status sw_tt_prepare_loops(tt_ctx *c, const double dom[4]);

/* The knot grid, the sub-patch bounds and the grid lines meeting the
 * loops' box (core/sw_trim_grid.c). */
sw_status sw_tt_build_grid(tt_ctx *c);

/* Inserts a grid line at x (axis 0: u, 1: v) if none is there. */
sw_status sw_tt_insert_line(tt_ctx *c, int axis, double x);

/* Index k of the interval lines[k] <= x < lines[k + 1] (clamped into
 * 0 .. n - 2 for n lines). */
uint32_t sw_tt_interval(const double *lines, uint32_t n, double x);

/* The patch of knot cell (kc, kr), or SW_TT_NONE. */
uint32_t sw_tt_knot_patch(const tt_ctx *c, uint32_t kc, uint32_t kr);

/* The bound (M_uu h_u^2 + 2 M_uv h_u h_v + M_vv h_v^2) / 8 of grid cell
 * (col, row) cut into parts_u x parts_v parts; -1 when not known. */
double sw_tt_cell_bound(const tt_ctx *c, uint32_t col, uint32_t row, uint32_t parts_u,
                        uint32_t parts_v);

/* The three terms of that bound for the whole cell, into t (0 when not
 * known): a cell cut into i x j parts has t[0] / i^2 + t[1] / (i j) +
 * t[2] / j^2, so a search over parts costs no bounds lookup. */
int sw_tt_cell_terms(const tt_ctx *c, uint32_t col, uint32_t row, double t[3]);

static inline double sw_tt_parts_bound(const double t[3], uint32_t i, uint32_t j)
{
    return t[0] / ((double)i * i) + t[1] / ((double)i * j) + t[2] / ((double)j * j);
}

/* Segments into cells (c->pairs, c->row_first), refining the grid where a
 * cell holds a whole hole or too many loop points (core/sw_trim_bucket.c). */
sw_status sw_tt_bucket(tt_ctx *c);

/* The row sweep: every cell inside or crossed, triangulated and written
 * (core/sw_trim_sweep.c). */
sw_status sw_tt_sweep(tt_ctx *c);

/* Exact evaluation (core/sw_trim_eval.c): position and unit normal of patch
 * p at the surface's (u, v); grid point (col, line) through the line cache. */
void sw_tt_eval_at(tt_ctx *c, uint32_t p, double u, double v, sw_vec3 *pos, sw_vec3 *normal);
void sw_tt_eval_grid(tt_ctx *c, uint32_t p, uint32_t col, uint32_t line, sw_vec3 *pos,
                     sw_vec3 *normal);
sw_status sw_tt_eval_init(tt_ctx *c);

/* Vertex output (core/sw_trim_tess.c). */
sw_status sw_tt_vertex_for(tt_ctx *c, uint32_t patch, const sw_tt_pv *pv, uint32_t *out);
sw_status sw_tt_new_grid_vertex(tt_ctx *c, uint32_t patch, uint32_t col, uint32_t line,
                                uint32_t *out);

/* The vertex of grid point (col, line), evaluated on patch the first time. */
static inline sw_status sw_tt_grid_vertex(tt_ctx *c, uint32_t patch, uint32_t col, uint32_t line,
                                          uint32_t *out)
{
    uint32_t id = c->line_ids[line & 1][col];
    if (id == SW_TT_NONE)
        return sw_tt_new_grid_vertex(c, patch, col, line, out);
    *out = id;
    return SW_OK;
}

/* Writes a triangle where the caller's buffer holds it, counts it always. */
static inline void sw_tt_put_triangle(tt_ctx *c, uint32_t a, uint32_t b, uint32_t d)
{
    const sw_trim_tess_buffers *o = c->out;
    const uint32_t v[3] = {a, b, d};
    for (uint32_t k = 0; o && k < 3; k++)
        if (c->index_count + k < o->index_capacity)
            o->indices[c->index_count + k] = (uint16_t)(o->base_vertex + v[k]);
    c->index_count += 3;
}
/* A new output vertex at the caller's loop point src: its position, the
 * surface's normal at its (u, v) (also into *normal), its id. Needs no grid
 * (core/sw_trim_tess.c). */
sw_status sw_tt_new_loop_vertex(tt_ctx *c, uint32_t src, sw_vec3 *normal, uint32_t *out);

/* Collapsed loops (core/sw_trim_fan.c): does caller's loop k span area in
 * space (its points off one line by more than float rounding)? */
int sw_tt_loop_spans_space(const sw_trim_loops *l, uint32_t k);

/* Each collapsed loop as a fan over its points' positions, turned with the
 * surface's normal. */
sw_status sw_tt_fan_collapsed(tt_ctx *c);

/* The vertex table for at most `hashed` crossings and part corners. */
sw_status sw_tt_init_vertices(tt_ctx *c, uint32_t hashed);
uint32_t sw_tt_patch_at(const tt_ctx *c, double u, double v);

#endif
