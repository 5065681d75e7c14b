/* SPDX-License-Identifier: MIT */
/* Measured triangulation error and timing helpers: see bench_error.h. */
#define _GNU_SOURCE /* clock_gettime */
#include "bench_error.h"

#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "sw_bezier.h"

double bench_uv_area(const float uv[3][2])
{
    double a = ((double)uv[1][0] - uv[0][0]) * ((double)uv[2][1] - uv[0][1]) -
               ((double)uv[2][0] - uv[0][0]) * ((double)uv[1][1] - uv[0][1]);
    return 0.5 * fabs(a);
}

/* Barycentric weights of the seven sample points. */
static const double sample_w[7][3] = {{1, 0, 0},     {0, 1, 0},     {0, 0, 1},
                                      {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5},
                                      {1.0 / 3, 1.0 / 3, 1.0 / 3}};

static void sample(const float p[3][3], const float uv[3][2], int s, sw_vec3 *q, double t[2])
{
    double x[3] = {0, 0, 0};
    t[0] = t[1] = 0;
    for (int k = 0; k < 3; k++) {
        for (int c = 0; c < 3; c++)
            x[c] += sample_w[s][k] * p[k][c];
        t[0] += sample_w[s][k] * uv[k][0], t[1] += sample_w[s][k] * uv[k][1];
    }
    *q = (sw_vec3){x[0], x[1], x[2]};
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* The central difference along (hu, hv) at t. */
static sw_vec3 derivative(bench_surface_at_fn at, const void *surface, const double t[2],
                          double hu, double hv)
{
    sw_vec3 d = sw_v3_sub(at(surface, t[0] + hu, t[1] + hv), at(surface, t[0] - hu, t[1] - hv));
    return sw_v3_scale(d, 0.5 / (hu + hv));
}

/* Damped Gauss-Newton on |S(u, v) - q|^2 from t, derivatives by central
 * differences (the callback gives points only), steps clamped into the
 * domain and halved until they help: the smallest distance met. */
static double nearest_from(sw_vec3 q, double t[2], bench_surface_at_fn at, const void *surface,
                           const double d[4])
{
    double best = sw_v3_length(sw_v3_sub(at(surface, t[0], t[1]), q));
    double h = 1e-6 * fmax(d[1] - d[0], d[3] - d[2]);
    for (int it = 0; it < 8 && best > 0; it++) {
        sw_vec3 r = sw_v3_sub(at(surface, t[0], t[1]), q);
        sw_vec3 su = derivative(at, surface, t, h, 0), sv = derivative(at, surface, t, 0, h);
        double a = sw_v3_dot(su, su), b = sw_v3_dot(su, sv), c = sw_v3_dot(sv, sv);
        double damp = 1e-9 * (a + c) + 1e-300;
        a += damp, c += damp;
        double gu = -sw_v3_dot(su, r), gv = -sw_v3_dot(sv, r), det = a * c - b * b;
        if (!(det > 0))
            break;
        double du = (c * gu - b * gv) / det, dv = (a * gv - b * gu) / det;
        int improved = 0;
        for (int half = 0; half < 4 && !improved; half++, du *= 0.5, dv *= 0.5) {
            double nu = clamp(t[0] + du, d[0], d[1]), nv = clamp(t[1] + dv, d[2], d[3]);
            double e = sw_v3_length(sw_v3_sub(at(surface, nu, nv), q));
            if (e < best)
                best = e, t[0] = nu, t[1] = nv, improved = 1;
        }
        if (!improved)
            break;
    }
    return best;
}

double bench_triangle_error_nearest(const float p[3][3], const float uv[3][2],
                                    bench_surface_at_fn at, const void *surface,
                                    const double domain[4], double floor)
{
    double worst = floor;
    for (int s = 0; s < 7; s++) {
        sw_vec3 q;
        double t[2];
        sample(p, uv, s, &q, t);
        /* The search starts at the same-(u, v) point and only gets nearer. */
        if (sw_v3_length(sw_v3_sub(at(surface, t[0], t[1]), q)) > worst)
            worst = fmax(worst, nearest_from(q, t, at, surface, domain));
    }
    return worst;
}

double bench_triangle_error(const float p[3][3], const float uv[3][2], bench_surface_at_fn at,
                            const void *surface)
{
    double worst = 0;
    for (int s = 0; s < 7; s++) {
        sw_vec3 q;
        double t[2];
        sample(p, uv, s, &q, t);
        worst = fmax(worst, sw_v3_length(sw_v3_sub(at(surface, t[0], t[1]), q)));
    }
    return worst;
}

sw_vec3 bench_patchf_at(const void *patch, double u, double v)
{
    const sw_bezier_patchf *pf = patch;
    double ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    sw_bezier_patch d = sw_bezier_patch_from_float(pf, ctrl);
    sw_surface_point q;
    sw_bezier_eval(&d, fmin(fmax(u, 0), 1), fmin(fmax(v, 0), 1), SW_EVAL_POINT, &q);
    return q.p;
}

/* Squared distance from (u, v) to the patch's domain rectangle. */
static double domain_gap(const float *d, double u, double v)
{
    double du = u < d[0] ? d[0] - u : u > d[1] ? u - d[1] : 0;
    double dv = v < d[2] ? d[2] - v : v > d[3] ? v - d[3] : 0;
    return du * du + dv * dv;
}

sw_vec3 bench_trim_surface_at(const void *surface, double u, double v)
{
    const bench_trim_surface *s = surface;
    const sw_trim_patch *p = &s->patches[0];
    double best = INFINITY;
    for (uint32_t i = 0; i < s->count && best > 0; i++) {
        double g = domain_gap(s->patches[i].domain, u, v);
        if (g < best)
            best = g, p = &s->patches[i];
    }
    const float *d = p->domain;
    return bench_patchf_at(&p->patch, (u - d[0]) / (d[1] - d[0]), (v - d[2]) / (d[3] - d[2]));
}

void bench_trim_surface_domain(const bench_trim_surface *s, double domain[4])
{
    domain[0] = domain[2] = INFINITY, domain[1] = domain[3] = -INFINITY;
    for (uint32_t i = 0; i < s->count; i++) {
        const float *d = s->patches[i].domain;
        domain[0] = fmin(domain[0], d[0]), domain[1] = fmax(domain[1], d[1]);
        domain[2] = fmin(domain[2], d[2]), domain[3] = fmax(domain[3], d[3]);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

bench_spread bench_summarise(double *s, int n)
{
    qsort(s, (size_t)n, sizeof *s, cmp_double);
    bench_spread t = {n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]), s[0], s[n - 1]};
    return t;
}

double bench_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
