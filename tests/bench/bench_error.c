/* Measured triangulation error and timing helpers: see bench_error.h. */
#define _GNU_SOURCE /* clock_gettime */
#include "bench_error.h"

#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "sw_bezier.h"

double bench_triangle_error(const float p[3][3], const float uv[3][2], bench_surface_at_fn at,
                            const void *surface)
{
    /* Barycentric weights of the seven sample points. */
    static const double w[7][3] = {{1, 0, 0},     {0, 1, 0},     {0, 0, 1},
                                   {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5},
                                   {1.0 / 3, 1.0 / 3, 1.0 / 3}};
    double worst = 0;
    for (int s = 0; s < 7; s++) {
        double q[3] = {0, 0, 0}, t[2] = {0, 0};
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < 3; c++)
                q[c] += w[s][k] * p[k][c];
            t[0] += w[s][k] * uv[k][0], t[1] += w[s][k] * uv[k][1];
        }
        sw_vec3 e = at(surface, t[0], t[1]);
        double dx = q[0] - e.x, dy = q[1] - e.y, dz = q[2] - e.z;
        worst = fmax(worst, sqrt(dx * dx + dy * dy + dz * dz));
    }
    return worst;
}

double bench_uv_area(const float uv[3][2])
{
    double a = ((double)uv[1][0] - uv[0][0]) * ((double)uv[2][1] - uv[0][1]) -
               ((double)uv[2][0] - uv[0][0]) * ((double)uv[1][1] - uv[0][1]);
    return 0.5 * fabs(a);
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
