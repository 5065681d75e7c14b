/* SPDX-License-Identifier: MIT */
/* Internal to the trimmed tessellator (core/sw_trim_tess.c): one cell of the
 * grid (or a part of one) cut by the trimming loops (paper 004, section 6.3) and the
 * triangulation of the resulting polygons. Parameter-space geometry only; no
 * surface evaluation, no output. Scratch from the caller's arena. */
#ifndef SW_TRIM_CELL_H
#define SW_TRIM_CELL_H

#include <stdint.h>

#include "sw_arena.h"

#define SW_TT_NONE 0xFFFFFFFFu

/* A loop point as the tessellator uses it: (u, v) moved by a tiny distance
 * into the trimmed region (see sw_trim_tess.c, "region shrink"), the index of
 * the caller's point, and the next point of its loop (region on the left). */
typedef struct sw_tt_point {
    double u, v;
    uint32_t src;
    uint32_t next;
    uint32_t loop;
} sw_tt_point;

typedef struct sw_tt_loop {
    uint32_t first, count;   /* into the sw_tt_point array */
    double box[4];           /* u0, u1, v0, v1 of the moved points */
    int hole;                /* 1: clockwise with the region on its left (a hole) */
} sw_tt_loop;

typedef struct sw_tt_rect { double u0, u1, v0, v1; } sw_tt_rect;

/* Polygon vertex kinds: a cell corner or a neighbour's corner on the cell's
 * border (exact surface), a crossing of a loop segment with the border (takes
 * the position of loop point ref), a loop point (ref). */
enum { SW_TT_GRID = 0, SW_TT_CROSS = 1, SW_TT_SEAM = 2 };
typedef struct sw_tt_pv {
    double u, v;
    uint32_t kind, ref;
    uint32_t ref_a, ref_b;   /* a crossing: its segment's loop points (sources) */
    double t;                /* and where along it, 0..1 */
    uint32_t seg;            /* a crossing: its segment's start (sw_tt_point index) */
} sw_tt_pv;

/* The loops as one read-only bundle. */
typedef struct sw_tt_trims {
    const sw_tt_point *pts;
    const sw_tt_loop *loops;
    uint32_t point_count, loop_count;
} sw_tt_trims;

/* Strictly inside the open rectangle. */
static inline int sw_tt_inside(const sw_tt_rect *r, double u, double v)
{
    return u > r->u0 && u < r->u1 && v > r->v0 && v < r->v1;
}

/* Liang-Barsky against the closed rectangle: 0 when the segment misses it,
 * else t0 <= t1 and the sides (0 u0, 1 u1, 2 v0, 3 v1, -1 none) bounding
 * them. Crossing parameters are computed as (c - a) / (b - a) for the side's
 * coordinate c alone, so two cells sharing a side find the same crossing. */
int sw_tt_clip(const sw_tt_rect *r, const sw_tt_point *a, const sw_tt_point *b, double *t0,
               int *side0, double *t1, int *side1);

/* Even-odd: is (u, v) inside the trimmed region of the moved loops? */
int sw_tt_classify(const sw_tt_trims *t, double u, double v);

/* The cell's polygons. border holds the cell's corners and the neighbours'
 * corners on its sides (any order, SW_TT_GRID); segs the loop segments
 * (start point indices) that meet the closed cell. stamp is a per-point array
 * the caller keeps across cells (cell_id unique per call). On success rings
 * holds ring_count counter-clockwise rings, ring k being
 * verts[ring_end[k - 1] .. ring_end[k]). Returns SW_TT_CELL_OK,
 * SW_TT_CELL_EMPTY (no loop meets the cell's inside: the caller classifies
 * it), SW_TT_CELL_BAD (loops cross: the walk around the border does not
 * alternate) or SW_TT_CELL_NO_MEMORY. Holes entirely inside the cell cannot
 * be expressed as rings and are counted in *skipped_holes. */
enum { SW_TT_CELL_OK = 0, SW_TT_CELL_EMPTY = 1, SW_TT_CELL_BAD = 2, SW_TT_CELL_NO_MEMORY = 3 };
typedef struct sw_tt_rings {
    sw_tt_pv *verts;
    uint32_t *ring_end;
    uint32_t ring_count, vert_count;
} sw_tt_rings;
int sw_tt_cell_rings(const sw_tt_trims *t, const sw_tt_rect *r, const uint32_t *segs,
                     uint32_t seg_count, const sw_tt_pv *border, uint32_t border_count,
                     uint32_t *stamp, uint32_t cell_id, sw_arena *arena, sw_tt_rings *out,
                     uint32_t *skipped_holes);

/* Ear clipping of one counter-clockwise ring of n vertices into at most
 * n - 2 triangles of local indices (tri[3 k + 0..2]); returns the count.
 * An ear is a convex corner with no other ring vertex in or on it (so no
 * vertex ends up inside a triangle edge); of the ears scored the best-shaped
 * is cut. When no ear exists (only for rings that cross themselves) the
 * largest convex corner is cut and *fallbacks counted. Needs 2 n uint32 of
 * scratch and n doubles of quality. */
uint32_t sw_tt_ear_clip(const sw_tt_pv *v, uint32_t n, uint32_t *scratch, double *quality,
                        uint32_t *tri, uint32_t *fallbacks);

#endif
