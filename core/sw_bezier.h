/* SPDX-License-Identifier: MIT */
/* Rational tensor-product Bezier patches of degree 1..SW_BEZIER_MAX_DEGREE in u
 * and v: evaluation with first and second derivatives and the normal, bounds
 * on the second derivatives (paper 000, section 4.1, after Filip et al.), and
 * the control-hull box. Used by the pack builder, the runtime's error
 * measurement and the tessellator. Pure functions, no allocation. */
#ifndef SW_BEZIER_H
#define SW_BEZIER_H

#include "sw_error.h"
#include "sw_math.h"

#define SW_BEZIER_MAX_DEGREE 15
#define SW_BEZIER_MAX_ORDER (SW_BEZIER_MAX_DEGREE + 1)

/* Control point (i, j), i along u in 0..degree_u, j along v in 0..degree_v, is
 * ctrl[(j * (degree_u + 1) + i) * 4 + k] for k = x, y, z, w. x, y, z are
 * Cartesian (not multiplied by w). When rational is 0 every w is taken as 1.
 * Weights of a rational patch must be > 0. */
typedef struct sw_bezier_patch {
    int degree_u, degree_v;
    int rational;
    const double *ctrl;
} sw_bezier_patch;

/* The same layout with float control points: the form packs store. */
typedef struct sw_bezier_patchf {
    int degree_u, degree_v;
    int rational;
    const float *ctrl;
} sw_bezier_patchf;

typedef enum sw_eval_order {
    SW_EVAL_POINT = 0,   /* p only */
    SW_EVAL_FIRST = 1,   /* p, du, dv, normal */
    SW_EVAL_SECOND = 2,  /* everything */
} sw_eval_order;

typedef struct sw_surface_point {
    sw_vec3 p;
    sw_vec3 du, dv;
    sw_vec3 duu, duv, dvv;
    /* Unit normal, cross(du, dv) normalised; where that vanishes (a collapsed
     * edge, as at the teapot's lid) the limit normal from a point nudged toward
     * the patch centre. Zero only for a fully degenerate patch. */
    sw_vec3 normal;
} sw_surface_point;

/* Evaluates the patch at (u, v) in [0,1]^2 by de Casteljau on homogeneous
 * coordinates (stable for all degrees); fields beyond order are left zero. */
void sw_bezier_eval(const sw_bezier_patch *patch, double u, double v, sw_eval_order order,
                    sw_surface_point *out);

/* Copies a float patch's control points into ctrl_out (at least
 * 4 * (degree_u + 1) * (degree_v + 1) doubles) and returns the double view. */
sw_bezier_patch sw_bezier_patch_from_float(const sw_bezier_patchf *patch, double *ctrl_out);

/* Upper bounds of |F_uu|, |F_uv| and |F_vv| over the whole patch. Polynomial
 * patches: from the control points of the second hodographs. Rational patches:
 * from the quotient rule with the hodographs of the homogeneous points, the
 * minimum weight and the control hull's radius (a proof, not a sample).
 * SW_ERR_RANGE for a non-positive or non-finite weight. */
typedef struct sw_deriv_bounds { double uu, uv, vv; } sw_deriv_bounds;
sw_status sw_bezier_second_deriv_bounds(const sw_bezier_patch *patch, sw_deriv_bounds *out,
                                        sw_error *err);

/* A tighter bound of |F_uv| for a rational patch linear in one direction
 * with its weights constant along it (an extrusion: cylinders, extruded
 * profiles): 0 up to rounding for an exact cylinder, where
 * sw_bezier_second_deriv_bounds, blind to the structure, gives a quarter
 * cylinder 4. INFINITY for any other patch. The trimmed tessellator takes
 * the smaller of the two; the pack builder (seam flattening, the pack's
 * patch bounds) does not yet: with it the boxed sphere's trims flatten to
 * other points and its sewing leaves free edges at a sphere's pole. */
double sw_bezier_extrusion_mixed_bound(const sw_bezier_patch *patch);

/* Box of the control points (contains the patch: convex hull property). */
sw_box sw_bezier_control_box(const sw_bezier_patch *patch);

/* The same surface restricted to [u0, u1] x [v0, v1] (within [0,1]^2, u0 < u1,
 * v0 < v1), reparameterised to [0,1]^2: the control points of the sub-patch,
 * same degrees, written to ctrl_out (4 * (degree_u + 1) * (degree_v + 1)
 * doubles, Cartesian x, y, z and w; w = 1 when the patch is not rational).
 * Exact: de Casteljau subdivision on homogeneous points. */
void sw_bezier_subpatch(const sw_bezier_patch *patch, double u0, double u1, double v0, double v1,
                        double *ctrl_out);

/* The four quarters of the patch, split at u = 1/2 and v = 1/2, each as
 * sw_bezier_subpatch writes one: quarter k (0..3) is the upper half in u
 * when k & 1 and in v when k & 2. The same as sw_bezier_subpatch on each
 * quarter, but one de Casteljau pass per row and column of the patch
 * instead of two per row and column of each quarter. */
void sw_bezier_quarters(const sw_bezier_patch *patch, double *const ctrl_out[4]);

#endif
