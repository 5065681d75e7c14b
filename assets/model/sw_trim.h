/* SPDX-License-Identifier: MIT */
/* Trim geometry on the host: a face's trimming loops flattened into closed
 * polylines in the surface's (u, v) parameter space with a guaranteed
 * tolerance, the even-odd point-in-face test, conservative box and 32 x 32
 * cell classification (the pack's trim masks), and the trimmed area of a
 * surface in model space. The model (sw_model.c) restricts Bezier patches to
 * the trimmed region with it; sw_model_trims.h applies it to a model's
 * stored faces. Below the model: it knows loops, not models.
 *
 * Tolerance: every point of every trimming curve lies within `tolerance` of
 * the polyline, and every polyline vertex lies on the curve. It is proved
 * from the convex hull of each flattened Bezier piece's control points, not
 * sampled. So a point farther than `tolerance` from the polyline is inside the
 * true face exactly when the polyline says so.
 *
 * Host only: sw_trim_polyline_build allocates and sw_trim_polyline_free
 * releases; the rest takes caller-owned buffers. */
#ifndef SW_TRIM_H
#define SW_TRIM_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_nurbs.h"
#include "sw_trim_loop.h"

/* Flattens one trimming curve (points u, v, 0, w) into a polyline from its
 * start to its end within tolerance (> 0): its Bezier pieces are halved by de
 * Casteljau until every control point is within tolerance of the chord. Writes
 * up to capacity (u, v) pairs to points_out (may be NULL to count) and the
 * number the whole polyline needs to *count_out; the first and last points
 * are the curve's ends. SW_ERR_NO_MEMORY when capacity is short (points_out
 * then holds the first capacity points), SW_ERR_RANGE when the tolerance is
 * below what double precision resolves at the curve's coordinates. */
sw_status sw_trim_flatten_curve(const sw_nurbs_curve *curve, double tolerance, double *points_out,
                                size_t capacity, size_t *count_out, sw_error *err);

/* A face's loops as closed polylines: loop l has the vertices
 * points[2 * loop_start[l] ...] up to loop_start[l + 1] (the closing edge
 * from the last vertex back to the first is implied). */
/* A run of at most SW_TRIM_CHUNK_EDGES consecutive edges of one loop and the
 * box of their vertices: queries skip whole runs whose box cannot matter, so
 * a point or box test costs about sqrt(n) edge tests on a smooth loop rather
 * than n (fine tolerances give loops of many thousand vertices). */
enum { SW_TRIM_CHUNK_EDGES = 32 };
typedef struct sw_trim_chunk {
    size_t first, end;           /* edges first..end-1: edge k runs from vertex k to k + 1 */
    size_t loop_first, loop_end; /* the loop's vertices: the last edge closes to loop_first */
    double box[4];               /* u0, u1, v0, v1 of the edges' end points */
} sw_trim_chunk;

typedef struct sw_trim_polyline {
    double *points;       /* owned: u, v per vertex */
    size_t *loop_start;   /* owned: loop_count + 1 entries */
    size_t loop_count;
    sw_trim_chunk *chunks; /* owned: every edge in exactly one chunk, in loop order */
    size_t chunk_count;
    double tolerance;     /* as promised above */
    double box[4];        /* u0, u1, v0, v1 of the vertices, grown by tolerance: holds every trim */
} sw_trim_polyline;

/* Flattens every curve of every loop (checked with sw_nurbs_curve_check) into
 * out. Loops must close: the end of each curve must meet the start of the next
 * (and the last the first) within gap (>= 0); SW_ERR_FORMAT naming the loop
 * and curve otherwise. On failure out is left empty (safe to free). */
sw_status sw_trim_polyline_build(const sw_model_loop_input *loops, size_t loop_count,
                                 double tolerance, double gap, sw_trim_polyline *out,
                                 sw_error *err);

void sw_trim_polyline_free(sw_trim_polyline *poly);

/* Even-odd rule over all loops (orientation does not matter). Points on the
 * polyline itself follow the half-open crossing rule: exact answers are only
 * promised farther than tolerance from it. */
int sw_trim_point_inside(const sw_trim_polyline *poly, double u, double v);

typedef enum sw_trim_coverage {
    SW_TRIM_OUTSIDE = 0,  /* no cell touches the face: mask all zero */
    SW_TRIM_PARTIAL = 1,  /* some cells set */
    SW_TRIM_INSIDE = 2,   /* the whole domain is inside and no trim comes near it */
} sw_trim_coverage;

/* Conservative class of the box [u0, u1] x [v0, v1] (box[4] as u0, u1, v0,
 * v1): OUTSIDE only when no point of it is in the true trimmed face, INSIDE
 * only when every point is, PARTIAL when the polyline's tolerance band
 * crosses it. */
sw_trim_coverage sw_trim_box_classify(const sw_trim_polyline *poly, const double box[4]);

/* sw_trim_box_classify(poly, box) != SW_TRIM_OUTSIDE. */
int sw_trim_box_touches(const sw_trim_polyline *poly, const double box[4]);

/* The 32 x 32 cell mask of a patch domain (u0, u1, v0, v1): bit i of rows[j]
 * is cell i along u, row j along v, set when the cell may touch the true face
 * (crossed by the tolerance band of the polyline, or inside). Same layout as
 * sw_pack_trim_mask. */
sw_trim_coverage sw_trim_mask(const sw_trim_polyline *poly, const double domain[4],
                              uint32_t rows[32]);

/* Area in model space of the surface's trimmed region (poly NULL: the whole
 * domain): the integral of |S_u x S_v| over the face. The polyline is taken as
 * the boundary (Green's theorem per Bezier patch: the area integral becomes a
 * boundary integral of F(u, v) = int_{u_patch}^{u} |S_u x S_v| du', both by
 * adaptive Gauss-Legendre), so build it with a tolerance well below the
 * wanted accuracy: the chords cut off about 2/3 tolerance x perimeter of
 * parameter area. rel_tol (e.g. 1e-7) drives the quadrature. */
sw_status sw_trim_area(const sw_nurbs_surface *surface, const sw_trim_polyline *poly,
                       double rel_tol, double *area_out, sw_error *err);

#endif
