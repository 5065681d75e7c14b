/* SPDX-License-Identifier: MIT */
/* The flattening's promises checked against the exact trims, for tests:
 * check_polyline_error(model, tol, require_tight). Static functions, one
 * copy per test program. */
#ifndef SEAM_POLYLINE_CHECK_H
#define SEAM_POLYLINE_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_shapes.h"
#include "sw_math.h"
#include "sw_seam_flatten.h"
#include "sw_test.h"

/* Distance from p to segment a-b. */
static double seg_dist(const double p[3], const double a[3], const double b[3])
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

static double loop_dist(const sw_seam_polylines *pl, size_t l, const double q[3])
{
    double best = INFINITY;
    size_t s = pl->loop_start[l], e = pl->loop_start[l + 1];
    for (size_t k = s; k < e; k++)
        best = fmin(best, seg_dist(q, pl->p + 3 * k, pl->p + 3 * (k + 1 < e ? k + 1 : s)));
    return best;
}

/* The model's curves of loop l of surface s, or its domain rectangle. */
static size_t loop_curves(const sw_model *m, size_t s, size_t l, shape_rect *rect,
                          sw_nurbs_curve *out)
{
    const sw_model_surface *surf = &m->surfaces[s];
    if (surf->loop_count == 0) {
        shape_rect_init(rect, surf->domain[0], surf->domain[1], surf->domain[2], surf->domain[3]);
        memcpy(out, rect->curves, sizeof rect->curves);
        return 4;
    }
    const sw_model_loop *ml = &m->loops[surf->first_loop + l];
    for (size_t k = 0; k < ml->curve_count && k < 16; k++)
        out[k] = sw_model_curve_view(&m->curves[ml->first_curve + k]);
    return ml->curve_count;
}

/* Promise (1) one way, exactly sampled: every sample of the true trim curve
 * mapped through the surface lies within tol of the 3D polyline; promise (2):
 * the surface image of every (u, v) edge within tol / 2 of its 3D edge; and
 * every vertex's position is the surface point at its (u, v). */
static void check_polyline_error(const sw_model *m, double tol, int require_tight)
{
    sw_seam_polylines pl;
    sw_error err;
    SW_CHECK(sw_seam_flatten_model(m, tol, &pl, &err) == SW_OK);
    double worst_curve = 0, worst_chord = 0, worst_vertex = 0;
    for (size_t s = 0; s < m->surface_count; s++) {
        sw_nurbs_surface sv = sw_model_surface_view(&m->surfaces[s]);
        const double *d = m->surfaces[s].domain;
        for (size_t l = pl.surface_loops[s]; l < pl.surface_loops[s + 1]; l++) {
            shape_rect rect;
            sw_nurbs_curve curves[16];
            size_t n = loop_curves(m, s, l - pl.surface_loops[s], &rect, curves);
            for (size_t c = 0; c < n && c < 16; c++) {
                const sw_nurbs_curve *cv = &curves[c];
                double t0 = cv->knots[cv->degree], t1 = cv->knots[cv->count];
                for (int i = 0; i <= 400; i++) {
                    sw_vec3 uv = sw_nurbs_curve_point(cv, t0 + (t1 - t0) * i / 400);
                    sw_vec3 q = sw_nurbs_surface_point(&sv, fmin(fmax(uv.x, d[0]), d[1]),
                                                       fmin(fmax(uv.y, d[2]), d[3]));
                    double dd = loop_dist(&pl, l, (double[3]){q.x, q.y, q.z});
                    if (dd > tol && getenv("SEAM_DEBUG"))
                        fprintf(stderr, "surface %zu loop %zu curve %zu sample %d uv %g %g dist %g domain %g %g %g %g deg %d count %d\n", s, l, c, i, uv.x, uv.y, dd, d[0], d[1], d[2], d[3], cv->degree, cv->count);
                    worst_curve = fmax(worst_curve, dd);
                }
            }
            size_t a = pl.loop_start[l], e = pl.loop_start[l + 1];
            for (size_t k = a; k < e; k++) {
                size_t k1 = k + 1 < e ? k + 1 : a;
                const double *uv0 = pl.uv + 2 * k, *uv1 = pl.uv + 2 * k1;
                sw_vec3 q = sw_nurbs_surface_point(&sv, fmin(fmax(uv0[0], d[0]), d[1]),
                                                   fmin(fmax(uv0[1], d[2]), d[3]));
                double dq[3] = {q.x - pl.p[3 * k], q.y - pl.p[3 * k + 1], q.z - pl.p[3 * k + 2]};
                worst_vertex = fmax(worst_vertex, sqrt(dq[0] * dq[0] + dq[1] * dq[1] + dq[2] * dq[2]));
                for (int i = 1; i < 32; i++) {
                    double t = i / 32.0;
                    sw_vec3 x = sw_nurbs_surface_point(
                        &sv, fmin(fmax(uv0[0] + t * (uv1[0] - uv0[0]), d[0]), d[1]),
                        fmin(fmax(uv0[1] + t * (uv1[1] - uv0[1]), d[2]), d[3]));
                    worst_chord = fmax(worst_chord, seg_dist((double[3]){x.x, x.y, x.z},
                                                             pl.p + 3 * k, pl.p + 3 * k1));
                }
            }
        }
    }
    SW_CHECK_MSG(worst_curve <= tol, "curve %g > tol %g", worst_curve, tol);
    SW_CHECK_MSG(worst_chord <= tol / 2, "chord %g > tol/2 %g", worst_chord, tol / 2);
    SW_CHECK_MSG(worst_vertex <= 1e-9 * (1 + tol), "vertex %g", worst_vertex);
    /* Not trivially met: the polylines are not much finer than needed. */
    if (require_tight)
        SW_CHECK_MSG(worst_curve > tol / 20, "curve %g: suspiciously fine for %g", worst_curve, tol);
    sw_seam_polylines_free(&pl);
}

#endif
