/* SPDX-License-Identifier: MIT */
/* Derivative bounds of a NURBS surface over boxes of its parameter domain,
 * from a quad-tree over each of its Bezier patches (Guthe et al. 2002,
 * section 4: the surface is subdivided until it is flat within a third of the
 * sewing tolerance in every leaf). The trim flattener (sw_seam_flatten.c)
 * asks it, for the box of a trim piece, how fast and how curved the surface
 * can be there. Host only (malloc).
 *
 * The tree is built lazily: a node is split only when a query reaches it and
 * it is not yet flat, so surfaces far from any trim cost nothing. */
#ifndef SW_SEAM_QTREE_H
#define SW_SEAM_QTREE_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_nurbs.h"

/* Bounds in the surface's own (u, v) units over a box: |S_u| <= lu,
 * |S_v| <= lv, |S_uu| <= uu, |S_uv| <= uv, |S_vv| <= vv everywhere in it.
 * straddles: the box crosses an interior knot line strictly, where the
 * surface may be only C0, or the domain's border (outside it the surface is
 * taken at the clamped (u, v): trims stray outside by rounding or sloppy
 * data), so second-derivative bounds say nothing about a chord across it
 * (callers then fall back to the first-derivative bound, which holds for the
 * clamped surface too). */
typedef struct sw_seam_bounds {
    double lu, lv, uu, uv, vv;
    int straddles;
} sw_seam_bounds;

typedef struct sw_seam_qnode sw_seam_qnode;

typedef struct sw_seam_qtree {
    int degree_u, degree_v, pieces_u, pieces_v;
    double *ctrl;      /* owned: the Bezier patches, sw_nurbs_surface_to_bezier layout */
    double *params;    /* owned: u ranges of the columns, then v ranges of the rows */
    double domain[4];  /* u0, u1, v0, v1 */
    double flat_tol;   /* a leaf is flat when chords in it leave the surface by at most this */
    sw_seam_qnode *nodes; /* owned: roots first (one per patch), then children in fours */
    size_t node_count, node_capacity;
} sw_seam_qtree;

/* Splits the surface into Bezier patches and makes one root per patch.
 * flat_tol > 0 (model units). On failure qt is left empty (safe to free). */
sw_status sw_seam_qtree_init(sw_seam_qtree *qt, const sw_nurbs_surface *surface, double flat_tol,
                             sw_error *err);

void sw_seam_qtree_free(sw_seam_qtree *qt);

/* The bounds over box (u0, u1, v0, v1; clamped to the domain): the maximum
 * over the leaves it touches, refining the tree where it is not yet flat.
 * SW_ERR_NO_MEMORY when a split cannot be allocated; SW_ERR_RANGE when a
 * patch's weights are unusable. */
sw_status sw_seam_qtree_bounds(sw_seam_qtree *qt, const double box[4], sw_seam_bounds *out,
                               sw_error *err);

/* The exact surface point at (u, v) (clamped to the domain), by evaluating
 * the Bezier patch that holds it. */
void sw_seam_qtree_point(const sw_seam_qtree *qt, double u, double v, double out[3]);

#endif
