/* SPDX-License-Identifier: MIT */
/* Normal cones: the pseudo-Gauss map of a rational Bezier patch (paper 000,
 * section 3) bounded by a cone of directions, their union over a surface,
 * and the eye-dependent back-face test of paper 004 (section 6.2) with the
 * surface's box.
 *
 * The cone is a proof, not a sample. For P = X / W (X the weighted control
 * points, W the weights), P_u x P_v = N / W^3 with the polynomial
 *     N = W (X_u x X_v) + W_u (X_v x X) + W_v (X x X_u)
 * of degree (3m - 1, 3n - 1) (for a polynomial patch simply X_u x X_v, of
 * degree (2m - 1, 2n - 1)). Its Bernstein coefficients are computed exactly
 * up to rounding, whose size is bounded alongside; N(u, v) is a combination
 * of them with non-negative weights, so a cone of half-angle below 90
 * degrees that holds every coefficient (each widened by its rounding bound)
 * holds every normal of the patch, at degenerate corners too (where N
 * vanishes, the normal is a limit of directions in the closed cone). A
 * coefficient whose rounding bound reaches its length proves nothing about
 * its direction, and then the patch gets the full sphere, as does a patch
 * whose coefficients span a half-space or more. Paper 000 takes the cone of
 * the control net's cross products, which does not bound rational patches;
 * here the weights are in the polynomial.
 *
 * Used through sw_surface_cone.h by the seam walk at load time
 * (firmware/walk/sw_seam_walk.c) and the host's clustering, and by the
 * tests. Pure functions; scratch is the caller's. */
#ifndef SW_NORMAL_CONE_H
#define SW_NORMAL_CONE_H

#include <stddef.h>

#include "sw_bezier.h"
#include "sw_math.h"

/* half_angle at or above this: no cone (the full sphere). */
#define SW_CONE_FULL 1.5707963267948966 /* pi / 2 */

typedef struct sw_normal_cone {
    sw_vec3 axis;          /* unit; zero for the full sphere */
    double half_angle;     /* radians; >= SW_CONE_FULL: every direction */
} sw_normal_cone;

/* Doubles of scratch sw_normal_cone_of_patch needs for a patch of these
 * degrees (SW_BEZIER_MAX_DEGREE both: enough for any). */
size_t sw_normal_cone_scratch_doubles(int degree_u, int degree_v);

/* The cone of cross(P_u, P_v) over the whole patch (unit (u, v) square):
 * the orientation the trimmed tessellator winds its triangles by
 * (counter-clockwise in (u, v)). scratch holds
 * sw_normal_cone_scratch_doubles(patch's degrees) doubles. Weights must be
 * > 0 (a validated pack's are). */
sw_normal_cone sw_normal_cone_of_patch(const sw_bezier_patchf *patch, double *scratch);

/* A cone holding both. */
sw_normal_cone sw_normal_cone_union(const sw_normal_cone *a, const sw_normal_cone *b);

/* The smallest cone holding both (sw_normal_cone_union keeps the bisector
 * of the axes, which is only tight for equal cones and grows a cone a
 * little with every union; clustering takes hundreds of unions in a row). */
sw_normal_cone sw_normal_cone_union_tight(const sw_normal_cone *a, const sw_normal_cone *b);

/* An empty cone: the union's identity. */
sw_normal_cone sw_normal_cone_empty(void);

/* 1 when from eye every normal in the cone at every point of box faces
 * away (dot(n, eye - p) < 0 by at least margin_rad of angle): the surface
 * shows only its back there. 0 for the full sphere, an empty cone's box, or
 * an eye in the box. */
int sw_normal_cone_back_facing(const sw_normal_cone *cone, const sw_box *box, sw_vec3 eye,
                               double margin_rad);

#endif
