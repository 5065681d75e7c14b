/* SPDX-License-Identifier: MIT */
/* The achieved error of a triangulation, measured the same way for every
 * tessellator the benchmarks compare (tess_bench.c, trim_tess_bench.c) and
 * independently of their own claims: a triangle's sample points (vertices,
 * edge midpoints, centroid) against the exact surface at the same (u, v),
 * interpolated linearly across the triangle. That is the distance seamwalk's
 * bounds are stated for; it is never smaller than the distance to the
 * nearest surface point, which is measured too. Also the small timing helpers both benchmarks
 * share. Host-side benchmark code: no allocation. */
#ifndef BENCH_ERROR_H
#define BENCH_ERROR_H

#include <stdint.h>

#include "sw_math.h"
#include "sw_trim_tess.h"

/* The exact surface point at (u, v) of the caller's surface. */
typedef sw_vec3 (*bench_surface_at_fn)(const void *surface, double u, double v);

/* Largest distance between a sample point of the triangle (positions p,
 * parameters uv, both per vertex) and the surface at the sample's (u, v). */
double bench_triangle_error(const float p[3][3], const float uv[3][2], bench_surface_at_fn at,
                            const void *surface);

/* The same sample points' largest distance to the nearest surface point
 * instead (a local search from the sample's (u, v), within domain: u0, u1,
 * v0, v1): what the eye sees, without the parametrisation's slip. Never more
 * than bench_triangle_error; much less where a triangle's (u, v) are
 * distorted but its points lie on the surface, as at a patch's collapsed
 * edge. The search costs about fifty evaluations, so it runs only for
 * samples whose same-(u, v) distance exceeds floor (the caller's running
 * maximum: no other sample can raise it); returns at least floor. */
double bench_triangle_error_nearest(const float p[3][3], const float uv[3][2],
                                    bench_surface_at_fn at, const void *surface,
                                    const double domain[4], double floor);

/* The (u, v) area of a triangle, either orientation. */
double bench_uv_area(const float uv[3][2]);

/* A surface made of sw_trim_patch pieces (a view: nothing is copied). */
typedef struct bench_trim_surface {
    const sw_trim_patch *patches;
    uint32_t count;
} bench_trim_surface;

/* bench_surface_at_fn for a const bench_trim_surface *: the point of the
 * patch whose domain holds (u, v) (clamped onto the nearest one outside). */
sw_vec3 bench_trim_surface_at(const void *surface, double u, double v);

/* The box of the patches' domains: u0, u1, v0, v1. */
void bench_trim_surface_domain(const bench_trim_surface *s, double domain[4]);

/* bench_surface_at_fn for a const sw_bezier_patchf *, (u, v) in [0,1]^2. */
sw_vec3 bench_patchf_at(const void *patch, double u, double v);

/* Median, min and max of n samples (sorted in place). */
typedef struct bench_spread {
    double median_s, min_s, max_s;
} bench_spread;
bench_spread bench_summarise(double *samples, int n);

double bench_now_s(void);

#endif
