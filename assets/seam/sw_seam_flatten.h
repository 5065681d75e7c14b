/* SPDX-License-Identifier: MIT */
/* A model's trimming loops as polylines with a guaranteed error in model
 * space (Guthe et al. 2002, section 4): the first half of the Seam Graph's
 * preprocessing, before sewing (sw_sew.h). Host only (malloc).
 *
 * Every surface contributes its trimming loops in order; an untrimmed
 * surface (loop_count 0, e.g. one Newell patch) contributes its domain
 * rectangle as one outer loop. Every vertex lies on its true trim curve (its
 * (u, v) is a point of the curve, not a fit) and its 3D position is the exact
 * surface point there (evaluated at (u, v) clamped to the domain: trims may
 * stray outside it by rounding).
 *
 * The promise, per edge of a loop, for a tolerance tol:
 *  (1) the true 3D trim curve between the edge's two vertices and the 3D
 *      segment between their positions are within tol of each other
 *      (Hausdorff, both ways);
 *  (2) the surface image of the (u, v) segment (what a tessellator trims
 *      along) stays within tol / 2 of the 3D segment.
 * Proved from the surface's derivative bounds (sw_seam_qtree.h) and the
 * convex hull of the trim curve's Bezier pieces, not sampled. Pieces that
 * cannot be proved after 2^-40 of a curve piece (a singular surface) are
 * accepted and counted in unproven. Every curve's start stays a vertex (the
 * loop's corners survive simplification). */
#ifndef SW_SEAM_FLATTEN_H
#define SW_SEAM_FLATTEN_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_model.h"

/* Loop l has the vertices [loop_start[l], loop_start[l + 1]), closed (the
 * last joins the first), at least 3 of them. Surface s has the loops
 * [surface_loops[s], surface_loops[s + 1]). */
typedef struct sw_seam_polylines {
    double *uv;             /* owned: 2 per vertex, in the loop's surface */
    double *p;              /* owned: 3 per vertex, model space */
    float *gap;             /* owned, may be NULL (all 0): per vertex, how far the file
                               lets its border stray from the edge it meant (the largest
                               sw_model_trim_curve.gap of the curves it stands for); the
                               sewing widens its tolerance by it */
    uint32_t *edge;         /* owned, may be NULL (all 0): per vertex, the file's shared
                               edge the segment from it to the next is a use of
                               (sw_model_trim_curve.edge, made unique in the model); 0 when
                               not known. The sewing sews a shared edge's trims only onto
                               that edge's other trims (or onto unknown ones) */
    size_t vertex_count;
    size_t *loop_start;     /* owned: loop_count + 1 */
    uint32_t *loop_surface; /* owned: per loop */
    uint8_t *loop_outer;    /* owned: per loop, 1 for an outer loop */
    size_t loop_count;
    size_t *surface_loops;  /* owned: surface_count + 1 */
    size_t surface_count;
    double tolerance;
    size_t unproven;        /* curve pieces accepted without a proof (see above) */
    size_t clamped;         /* vertices whose (u, v) lay outside the surface's domain and
                               were put on its border (the runtime refuses loops far out) */
} sw_seam_polylines;

/* Flattens every loop of every surface of the model within tolerance (> 0,
 * model units): first at tolerance / 2 by de Casteljau halving of the trim
 * curves' Bezier pieces, then simplified up to tolerance (section 4's two
 * steps). On failure out is left empty (safe to free); the message names the
 * surface, loop and curve. */
sw_status sw_seam_flatten_model(const sw_model *model, double tolerance, sw_seam_polylines *out,
                                sw_error *err);

void sw_seam_polylines_free(sw_seam_polylines *poly);

#endif
