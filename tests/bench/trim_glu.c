/* SPDX-License-Identifier: MIT */
/* GLU's form of a trimmed surface, its timed and measured runs and the
 * tolerance search: see trim_glu.h. */
#include "trim_glu.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_BREAKS = 64 };

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* The distinct domain borders of the patches along axis (0 u, 1 v), sorted;
 * shared edges have equal coordinates (sw_trim_patch), so equality dedups.
 * 0 when there are more than MAX_BREAKS. */
static uint32_t breakpoints(const sw_trim_patch *patches, uint32_t count, int axis, float *out)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < count; i++)
        for (int e = 0; e < 2; e++) {
            float x = patches[i].domain[2 * axis + e];
            uint32_t k = 0;
            while (k < n && out[k] != x)
                k++;
            if (k < n)
                continue;
            if (n == MAX_BREAKS)
                return 0;
            out[n++] = x;
        }
    qsort(out, n, sizeof *out, cmp_float);
    return n;
}

static int index_of(const float *breaks, uint32_t n, float x)
{
    for (uint32_t i = 0; i < n; i++)
        if (breaks[i] == x)
            return (int)i;
    return -1;
}

/* Clamped knots over the breakpoints: the ends order times, each interior
 * one degree times, so every knot interval is one Bezier patch. */
static GLfloat *make_knots(const float *breaks, uint32_t n, int degree)
{
    GLfloat *k = malloc(sizeof *k * ((n - 1) * (uint32_t)degree + (uint32_t)degree + 2));
    if (!k)
        return NULL;
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++)
        for (int r = 0; r < (i == 0 || i + 1 == n ? degree + 1 : degree); r++)
            k[m++] = breaks[i];
    return k;
}

/* Greville abscissa of control point i: where the identity's B-spline
 * coefficient sits, so the texture map gives back (u, v) exactly. */
static GLfloat greville(const GLfloat *knots, int i, int degree)
{
    double s = 0;
    for (int r = 1; r <= degree; r++)
        s += knots[i + r];
    return (GLfloat)(s / degree);
}

static void put_patch(trim_glu_surface *g, const sw_bezier_patchf *p, int a, int b)
{
    int du = p->degree_u, dv = p->degree_v;
    for (int j = 0; j <= dv; j++)
        for (int i = 0; i <= du; i++) {
            const float *c = p->ctrl + (j * (du + 1) + i) * 4;
            int at = (b * dv + j) * g->count_u + a * du + i;
            float w = p->rational ? c[3] : 1.0f;
            GLfloat *q = g->ctrl + at * g->dims;
            q[0] = c[0] * w, q[1] = c[1] * w, q[2] = c[2] * w;
            if (g->dims == 4)
                q[3] = w;
        }
}

static int make_net(trim_glu_surface *g, const sw_trim_patch *patches, uint32_t count,
                    char *why, size_t why_size)
{
    float bu[MAX_BREAKS], bv[MAX_BREAKS];
    uint32_t nu = breakpoints(patches, count, 0, bu), nv = breakpoints(patches, count, 1, bv);
    const sw_bezier_patchf *p0 = &patches[0].patch;
    int du = p0->degree_u, dv = p0->degree_v, rational = 0;
    for (uint32_t i = 0; i < count; i++)
        rational |= patches[i].patch.rational;
    if (nu < 2 || nv < 2 || (nu - 1) * (nv - 1) != count) {
        snprintf(why, why_size, "the %u patches do not tile a grid of knot intervals", count);
        return 0;
    }
    g->order_u = du + 1, g->order_v = dv + 1;
    g->count_u = (GLint)(nu - 1) * du + 1, g->count_v = (GLint)(nv - 1) * dv + 1;
    g->dims = rational ? 4 : 3, g->type = rational ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3;
    g->knots_u = make_knots(bu, nu, du), g->knots_v = make_knots(bv, nv, dv);
    size_t points = (size_t)g->count_u * (size_t)g->count_v;
    g->ctrl = malloc(sizeof *g->ctrl * points * (size_t)g->dims);
    g->tex = malloc(sizeof *g->tex * points * 2);
    if (!g->knots_u || !g->knots_v || !g->ctrl || !g->tex) {
        snprintf(why, why_size, "out of memory");
        return 0;
    }
    for (uint32_t i = 0; i < count; i++) {
        const sw_trim_patch *p = &patches[i];
        int a = index_of(bu, nu, p->domain[0]), b = index_of(bv, nv, p->domain[2]);
        if (p->patch.degree_u != du || p->patch.degree_v != dv) {
            snprintf(why, why_size, "patch %u has another degree than patch 0", i);
            return 0;
        }
        if (index_of(bu, nu, p->domain[1]) != a + 1 || index_of(bv, nv, p->domain[3]) != b + 1) {
            snprintf(why, why_size, "patch %u spans more than one knot interval", i);
            return 0;
        }
        put_patch(g, &p->patch, a, b);
    }
    for (GLint j = 0; j < g->count_v; j++)
        for (GLint i = 0; i < g->count_u; i++) {
            g->tex[2 * (j * g->count_u + i)] = greville(g->knots_u, i, du);
            g->tex[2 * (j * g->count_u + i) + 1] = greville(g->knots_v, j, dv);
        }
    return 1;
}

/* ---- loops --------------------------------------------------------------------- */

static double signed_area(const sw_trim_point *p, uint32_t n)
{
    double a = 0;
    for (uint32_t i = 0; i < n; i++) {
        const float *s = p[i].uv, *t = p[(i + 1) % n].uv;
        a += (double)s[0] * t[1] - (double)t[0] * s[1];
    }
    return 0.5 * a;
}

static int inside(const sw_trim_point *p, uint32_t n, const float *q)
{
    int in = 0;
    for (uint32_t i = 0; i < n; i++) {
        const float *a = p[i].uv, *b = p[(i + 1) % n].uv;
        if ((a[1] > q[1]) != (b[1] > q[1]) &&
            a[0] + (q[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) > q[0])
            in ^= 1;
    }
    return in;
}

/* Loop k's points, counter-clockwise when it is inside an even number of
 * other loops (an outer border), clockwise when odd (a hole), closed. */
static void put_loop(const sw_trim_loops *loops, uint32_t k, GLfloat *out)
{
    const sw_trim_point *p = loops->points + loops->loop_first[k];
    uint32_t n = loops->loop_first[k + 1] - loops->loop_first[k];
    int depth = 0;
    for (uint32_t o = 0; o < loops->loop_count; o++)
        if (o != k)
            depth += inside(loops->points + loops->loop_first[o],
                            loops->loop_first[o + 1] - loops->loop_first[o], p[0].uv);
    int reverse = (signed_area(p, n) > 0) == (depth % 2 == 1);
    for (uint32_t i = 0; i <= n; i++) {
        uint32_t s = i % n;
        uint32_t at = reverse ? (n - s) % n : s;
        out[2 * i] = p[at].uv[0], out[2 * i + 1] = p[at].uv[1];
    }
}

static int make_trims(trim_glu_surface *g, const sw_trim_loops *loops)
{
    uint32_t total = loops->loop_first[loops->loop_count] + loops->loop_count;
    g->pwl = malloc(sizeof *g->pwl * 2 * total);
    g->loop_first = malloc(sizeof *g->loop_first * (loops->loop_count + 1));
    if (!g->pwl || !g->loop_first)
        return 0;
    g->loop_count = loops->loop_count;
    g->loop_first[0] = 0;
    for (uint32_t k = 0; k < loops->loop_count; k++) {
        uint32_t n = loops->loop_first[k + 1] - loops->loop_first[k];
        put_loop(loops, k, g->pwl + 2 * g->loop_first[k]);
        g->loop_first[k + 1] = g->loop_first[k] + n + 1;
    }
    return 1;
}

int trim_glu_make(trim_glu_surface *g, const sw_trim_patch *patches, uint32_t count,
                  const sw_trim_loops *loops, char *why, size_t why_size)
{
    memset(g, 0, sizeof *g);
    g->exact = (bench_trim_surface){patches, count};
    if (!make_net(g, patches, count, why, why_size))
        return 0;
    if (!make_trims(g, loops)) {
        snprintf(why, why_size, "out of memory");
        return 0;
    }
    return 1;
}

void trim_glu_free(trim_glu_surface *g)
{
    free(g->knots_u), free(g->knots_v), free(g->ctrl), free(g->tex);
    free(g->pwl), free(g->loop_first);
    memset(g, 0, sizeof *g);
}

/* ---- runs ---------------------------------------------------------------------- */

void trim_glu_draw(const trim_glu_surface *g, GLUnurbs *nurb, int with_tex)
{
    GLint ku = g->count_u + g->order_u, kv = g->count_v + g->order_v;
    gluBeginSurface(nurb);
    if (with_tex)
        gluNurbsSurface(nurb, ku, g->knots_u, kv, g->knots_v, 2, 2 * g->count_u, g->tex,
                        g->order_u, g->order_v, GL_MAP2_TEXTURE_COORD_2);
    gluNurbsSurface(nurb, ku, g->knots_u, kv, g->knots_v, g->dims, g->dims * g->count_u, g->ctrl,
                    g->order_u, g->order_v, g->type);
    for (uint32_t k = 0; k < g->loop_count; k++) {
        gluBeginTrim(nurb);
        gluPwlCurve(nurb, (GLint)(g->loop_first[k + 1] - g->loop_first[k]),
                    g->pwl + 2 * g->loop_first[k], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nurb);
    }
    gluEndSurface(nurb);
}

typedef struct probe {
    const bench_trim_surface *exact;
    double domain[4];
    double worst, worst_nearest, uv_area;
} probe;

static void probe_triangle(void *user, const float p[3][3], const float uv[3][2])
{
    probe *pr = user;
    pr->worst = fmax(pr->worst, bench_triangle_error(p, uv, bench_trim_surface_at, pr->exact));
    pr->worst_nearest = bench_triangle_error_nearest(p, uv, bench_trim_surface_at, pr->exact,
                                                     pr->domain, pr->worst_nearest);
    pr->uv_area += bench_uv_area(uv);
}

const char *trim_glu_run(const trim_glu_surface *g, double tolerance, int measure, int repeats,
                         double *samples, trim_glu_output *out)
{
    for (int r = 0; r < (measure ? 1 : repeats); r++) {
        probe pr = {&g->exact, {0, 0, 0, 0}, 0, 0, 0};
        bench_trim_surface_domain(&g->exact, pr.domain);
        bench_glu glu;
        if (!bench_glu_open(&glu, tolerance, measure ? probe_triangle : NULL, &pr))
            return "gluNewNurbsRenderer failed";
        double t0 = bench_now_s();
        trim_glu_draw(g, glu.nurb, measure);
        if (!measure)
            samples[r] = bench_now_s() - t0;
        const char *problem = bench_glu_problem(&glu);
        *out = (trim_glu_output){glu.triangles, glu.vertices, pr.worst, pr.worst_nearest,
                                 pr.uv_area};
        bench_glu_close(&glu);
        if (problem)
            return problem;
    }
    return NULL;
}

static const char *measure_at(const void *ctx, double tolerance, uint64_t *triangles,
                              double *error)
{
    trim_glu_output o = {0, 0, 0, 0, 0};
    const char *problem = trim_glu_run(ctx, tolerance, 1, 1, NULL, &o);
    *triangles = o.triangles, *error = o.error;
    /* At tiny tolerances GLU can give up and emit nothing: no error
     * measured is no tessellation, not a perfect one. */
    if (!problem && o.triangles == 0)
        *error = INFINITY;
    return problem;
}

const char *trim_glu_tune(const trim_glu_surface *g, double start, double target,
                          double *tolerance, trim_glu_output *out, int *tries)
{
    const char *problem = bench_glu_tune(measure_at, g, start, target, tolerance, tries);
    return problem ? problem : trim_glu_run(g, *tolerance, 1, 1, NULL, out);
}
