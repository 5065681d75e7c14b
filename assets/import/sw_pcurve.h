/* SPDX-License-Identifier: MIT */
/* Parameter-space curves from model-space curves: point inversion on a NURBS
 * surface (closest point by safeguarded Newton) and least-squares B-spline
 * fitting checked against the model-space curve. Importers call it when a
 * trim has only its 3D curve (IGES 142 without a usable parameter curve, 141
 * and 508 boundaries, STEP edges without p-curves). Host only: it allocates,
 * and every *_free releases what the matching call made. */
#ifndef SW_PCURVE_H
#define SW_PCURVE_H

#include "sw_bezier.h"
#include "sw_error.h"
#include "sw_nurbs.h"

/* A surface prepared for repeated evaluation and inversion: its Bezier
 * patches (fast exact derivatives) and a coarse grid of points for start
 * values. */
typedef struct sw_pcurve_surface {
    int degree_u, degree_v, pieces_u, pieces_v, rational;
    double *ctrl;        /* patches, sw_nurbs_surface_to_bezier layout */
    double *params;      /* u ranges of the columns, then v ranges of the rows */
    double domain[4];    /* u0, u1, v0, v1 */
    int grid_u, grid_v;  /* grid samples per direction */
    double *grid;        /* grid_u * grid_v points, x, y, z */
    double size;         /* diagonal of the grid's box: scale for stopping tests */
} sw_pcurve_surface;

sw_status sw_pcurve_surface_init(sw_pcurve_surface *ps, const sw_nurbs_surface *surface,
                                 sw_error *err);
void sw_pcurve_surface_free(sw_pcurve_surface *ps);

/* The surface at (u, v) (clamped to the domain), derivatives with respect to
 * the surface's own parameters up to order. */
void sw_pcurve_surface_eval(const sw_pcurve_surface *ps, double u, double v,
                            sw_eval_order order, sw_surface_point *out);

/* Closest point of the surface to p: Newton on |S - p|^2 with clamping to
 * the domain, Gauss-Newton and gradient fallbacks and a backtracking line
 * search. start (may be NULL) is tried first; when it does not end within
 * accept of p, the best grid point is tried as well. Writes the parameters
 * and returns the distance. */
double sw_pcurve_invert(const sw_pcurve_surface *ps, sw_vec3 p, const double *start,
                        double accept, double uv[2]);

/* The model-space curve to fit, on [t0, t1]. eval writes the point at t; if
 * the caller knows the exact parameters there (a trim mapped from another
 * parameterisation) it writes uv and returns 1, else returns 0 and the
 * parameters come from inversion. */
typedef struct sw_pcurve_target {
    int (*eval)(void *user, double t, sw_vec3 *p, double uv[2]);
    void *user;
    double t0, t1;
} sw_pcurve_target;

/* A clamped B-spline in parameter space: points (u, v, 0, 1). */
typedef struct sw_pcurve_result {
    int degree, count;
    double *knots, *ctrl;
    double max_error;    /* |S(c(t)) - C(t)| beyond the curve's own distance to the surface */
    double max_gap;      /* largest distance of C(t) from the surface */
    long evals;          /* surface evaluations the fit took (also when it failed) */
} sw_pcurve_result;

/* A fit gives up with SW_ERR_RANGE after this many surface evaluations
 * (Newton steps, their backtracking, a starting grid's scan counted as one
 * per 64 points): a curve that never follows the surface would otherwise
 * try every fit up to 4,096 points, each sample searched afresh (one small
 * IGES file's curve kept the reader busy for a minute unoptimised). The cap
 * is well above what a hard but honest fit takes (test_pcurve fits a wavy
 * curve within it). */
#define SW_PCURVE_FIT_MAX_EVALS 500000L

/* Fits a parameter-space curve c on [t0, t1] such that at dense samples
 * |S(c(t)) - C(t)| <= tol + dist(C(t), S): cubic least squares with more
 * control points until it holds, then a dense polyline. SW_ERR_RANGE when
 * neither gets there (the message says how far off). */
sw_status sw_pcurve_fit(const sw_pcurve_surface *ps, const sw_pcurve_target *target, double tol,
                        sw_pcurve_result *out, sw_error *err);
void sw_pcurve_result_free(sw_pcurve_result *res);

#endif
