/* SPDX-License-Identifier: MIT */
/* B-spline (NURBS) curves and surfaces and their conversion to rational Bezier
 * pieces by knot insertion (Boehm; every interior knot raised to multiplicity
 * degree). The pack builder calls it for every imported surface; tests compare
 * the pieces with de Boor evaluation of the original. The caller owns every
 * buffer; a *_bezier_sizes() call says how large they must be. */
#ifndef SW_NURBS_H
#define SW_NURBS_H

#include <stddef.h>

#include "sw_bezier.h"
#include "sw_error.h"

/* Clamped (open) knot vectors: knots has count + degree + 1 entries,
 * non-decreasing, first and last values repeated degree + 1 times. Control
 * points are 4 doubles each (x, y, z, w) as in sw_bezier_patch. */
typedef struct sw_nurbs_curve {
    int degree;
    int count;             /* control points */
    const double *knots;
    const double *ctrl;    /* count * 4 doubles */
} sw_nurbs_curve;

/* Control point (i, j), i along u, is ctrl[(j * count_u + i) * 4 + k]. */
typedef struct sw_nurbs_surface {
    int degree_u, degree_v;
    int count_u, count_v;
    const double *knots_u;  /* count_u + degree_u + 1 */
    const double *knots_v;  /* count_v + degree_v + 1 */
    const double *ctrl;
} sw_nurbs_surface;

/* Checks degree (1..SW_BEZIER_MAX_DEGREE), counts, clamping, monotonic and
 * finite knots, positive weights; the message names the first violation. */
sw_status sw_nurbs_curve_check(const sw_nurbs_curve *curve, sw_error *err);
sw_status sw_nurbs_surface_check(const sw_nurbs_surface *surface, sw_error *err);

/* Point on the curve / surface at a parameter in the knot range (de Boor on
 * homogeneous coordinates). Reference evaluation; not for hot loops. */
sw_vec3 sw_nurbs_curve_point(const sw_nurbs_curve *curve, double t);
sw_vec3 sw_nurbs_surface_point(const sw_nurbs_surface *surface, double u, double v);

/* Number of non-empty knot spans = Bezier pieces along one direction. */
int sw_nurbs_span_count(int degree, int count, const double *knots);

typedef struct sw_nurbs_bezier_sizes {
    int pieces_u, pieces_v;   /* pieces along each direction (curves: u only) */
    size_t ctrl_doubles;      /* doubles the ctrl output needs */
    size_t param_doubles;     /* doubles the param output needs: 2 per piece and direction */
} sw_nurbs_bezier_sizes;

sw_nurbs_bezier_sizes sw_nurbs_curve_bezier_sizes(const sw_nurbs_curve *curve);
sw_nurbs_bezier_sizes sw_nurbs_surface_bezier_sizes(const sw_nurbs_surface *surface);

/* Splits the curve into Bezier pieces of the same degree: piece p has its
 * degree + 1 control points at ctrl_out[p * (degree + 1) * 4] and covers the
 * original parameters [params_out[2p], params_out[2p + 1]]. */
sw_status sw_nurbs_curve_to_bezier(const sw_nurbs_curve *curve, double *ctrl_out,
                                   double *params_out, sw_error *err);

/* Splits the surface into pieces_u * pieces_v Bezier patches; patch (a, b)
 * (a along u) is number b * pieces_u + a, its control points at
 * ctrl_out[(b * pieces_u + a) * (degree_u + 1) * (degree_v + 1) * 4] in the
 * sw_bezier_patch layout. params_out holds the u ranges of the pieces_u
 * columns (2 each) followed by the v ranges of the pieces_v rows. */
sw_status sw_nurbs_surface_to_bezier(const sw_nurbs_surface *surface, double *ctrl_out,
                                     double *params_out, sw_error *err);

#endif
