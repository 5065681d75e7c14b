/* SPDX-License-Identifier: MIT */
/* The distance from points to a mesh through its grid
 * (assets/super/sw_mesh_distance.h), against every triangle measured one
 * by one with a closest-point rule of the test's own: nearest points
 * inside, beside and far outside the mesh's box, the triangles within a
 * reach, and the sampled distance between two sheets. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_mesh_distance.h"
#include "sw_test.h"

enum { SIDE = 24, SHEET_VERTS = (SIDE + 1) * (SIDE + 1), SHEET_TRIS = SIDE * SIDE * 2,
       EXTRA = 40, VERTS = SHEET_VERTS + 3 * EXTRA, TRIS = SHEET_TRIS + EXTRA };

static float pos[3 * VERTS];
static uint32_t idx[3 * TRIS];

static uint32_t rng_state = 12345;
static double rnd(void)   /* in [0, 1) */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

/* A wavy sheet 100 wide with loose triangles of every size above and
 * through it: slivers, one across the whole box, tiny ones. */
static sw_mesh_view test_mesh(void)
{
    for (int r = 0; r <= SIDE; r++)
        for (int c = 0; c <= SIDE; c++) {
            float *p = pos + 3 * (r * (SIDE + 1) + c);
            p[0] = 100.0f * (float)c / SIDE, p[1] = 100.0f * (float)r / SIDE;
            p[2] = 8.0f * sinf(0.2f * p[0]) * cosf(0.13f * p[1]);
        }
    uint32_t *o = idx;
    for (int r = 0; r < SIDE; r++)
        for (int c = 0; c < SIDE; c++) {
            uint32_t a = (uint32_t)(r * (SIDE + 1) + c), b = a + 1, d = a + SIDE + 1, e = d + 1;
            *o++ = a, *o++ = b, *o++ = e, *o++ = a, *o++ = e, *o++ = d;
        }
    for (int t = 0; t < EXTRA; t++) {
        double size = t == 0 ? 140 : t < 10 ? 0.01 : 30 * rnd(), c[3] = { 100 * rnd(), 100 * rnd(),
                                                                          40 * rnd() - 10 };
        for (int j = 0; j < 3; j++) {
            float *p = pos + 3 * (SHEET_VERTS + 3 * t + j);
            for (int k = 0; k < 3; k++)   /* a sliver when t is odd: two corners close */
                p[k] = (float)(c[k] + size * (rnd() - 0.5) * (t % 2 && j == 2 ? 0.001 : 1));
            *o++ = (uint32_t)(SHEET_VERTS + 3 * t + j);
        }
    }
    return (sw_mesh_view){ pos, idx, VERTS, 3 * TRIS };
}

static double sub_dot(const double a[3], const double b[3], const double c[3])
{
    return (a[0] - b[0]) * c[0] + (a[1] - b[1]) * c[1] + (a[2] - b[2]) * c[2];
}

static double segment_distance(const double p[3], const double a[3], const double b[3])
{
    double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, l2 = sub_dot(b, a, ab);
    double s = l2 > 0 ? sub_dot(p, a, ab) / l2 : 0, d2 = 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    for (int k = 0; k < 3; k++)
        d2 += (p[k] - a[k] - s * ab[k]) * (p[k] - a[k] - s * ab[k]);
    return sqrt(d2);
}

/* The plane's distance when p's foot lies inside the triangle, else its
 * nearest edge's. */
static double brute_triangle(const double p[3], const sw_mesh_view *m, uint32_t t)
{
    double v[3][3];
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            v[j][k] = m->positions[3 * (size_t)m->indices[3 * t + j] + k];
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++)
        e1[k] = v[1][k] - v[0][k], e2[k] = v[2][k] - v[0][k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    double edges = fmin(segment_distance(p, v[0], v[1]),
                        fmin(segment_distance(p, v[1], v[2]), segment_distance(p, v[2], v[0])));
    if (!(nn > 1e-20))
        return edges;
    int inside = 1;
    for (int j = 0; j < 3; j++) {   /* p's side of each edge, seen along n */
        const double *a = v[j], *b = v[(j + 1) % 3];
        double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, ap[3];
        for (int k = 0; k < 3; k++)
            ap[k] = p[k] - a[k];
        double c[3] = { ab[1] * ap[2] - ab[2] * ap[1], ab[2] * ap[0] - ab[0] * ap[2],
                        ab[0] * ap[1] - ab[1] * ap[0] };
        inside &= c[0] * n[0] + c[1] * n[1] + c[2] * n[2] >= 0;
    }
    return inside ? fabs(sub_dot(p, v[0], n)) / sqrt(nn) : edges;
}

static double brute_nearest(const double p[3], const sw_mesh_view *m)
{
    double best = INFINITY;
    for (uint32_t t = 0; t < m->index_count / 3; t++)
        best = fmin(best, brute_triangle(p, m, t));
    return best;
}

static void random_point(double p[3], double spread)
{
    for (int k = 0; k < 3; k++)
        p[k] = 50 + spread * (rnd() - 0.5);
}

static void test_nearest_is_the_nearest_of_all_triangles(void)
{
    sw_mesh_view m = test_mesh();
    sw_mesh_grid *g = sw_mesh_grid_make(&m);
    SW_CHECK(g != NULL);
    int wrong = 0, placed = 0;
    for (int i = 0; i < 3000 && g; i++) {
        double p[3];
        random_point(p, i < 2000 ? 120 : i < 2900 ? 400 : 40000);   /* in, beside, far */
        sw_mesh_point at;
        double d = sw_mesh_grid_nearest(g, p, &at), want = brute_nearest(p, &m);
        wrong += !(fabs(d - want) <= 1e-9 * (1 + want));
        /* the point it names lies at that distance */
        double q[3] = { 0, 0, 0 }, d2 = 0;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                q[k] += at.weights[j] * m.positions[3 * (size_t)m.indices[3 * at.triangle + j] + k];
        for (int k = 0; k < 3; k++)
            d2 += (p[k] - q[k]) * (p[k] - q[k]);
        placed += fabs(sqrt(d2) - d) <= 1e-6 * (1 + d);
        SW_CHECK_NEAR(sw_mesh_grid_distance(g, p), d, 0);
    }
    SW_CHECK_MSG(wrong == 0, "%d of 3000 points' nearest distance differs from the brute force's",
                 wrong);
    SW_CHECK_MSG(placed == 3000, "%d of 3000 nearest points at their distance", placed);
    sw_mesh_grid_free(g);
}

typedef struct seen {
    uint8_t tri[TRIS];
    int stop_after;   /* visits until one returns nonzero; 0: never */
    int visits;
} seen;

static int mark(void *ctx, const sw_mesh_point *at)
{
    seen *s = ctx;
    s->tri[at->triangle] = 1;
    return ++s->visits == s->stop_after;
}

static void test_within_visits_every_triangle_within_reach_and_no_other(void)
{
    sw_mesh_view m = test_mesh();
    sw_mesh_grid *g = sw_mesh_grid_make(&m);
    int missed = 0, extra = 0, found = 0;
    for (int i = 0; i < 300 && g; i++) {
        double p[3], r = i % 3 == 0 ? 0.5 : i % 3 == 1 ? 6 : 40;
        random_point(p, 130);
        seen s = { { 0 }, 0, 0 };
        SW_CHECK(sw_mesh_grid_within(g, p, r, mark, &s) == 0);
        for (uint32_t t = 0; t < TRIS; t++) {
            double d = brute_triangle(p, &m, t);
            /* a triangle at the reach, within rounding, may go either way */
            if (fabs(d - r) < 1e-9 * r)
                continue;
            missed += d < r && !s.tri[t];
            extra += d > r && s.tri[t];
            found += d < r;
        }
        seen stop = { { 0 }, 1, 0 };
        SW_CHECK(sw_mesh_grid_within(g, p, r, mark, &stop) == (s.visits > 0));
        SW_CHECK(stop.visits == (s.visits > 0));
    }
    SW_CHECK_MSG(missed == 0 && extra == 0, "%d within reach not visited, %d beyond it visited",
                 missed, extra);
    SW_CHECK(found > 1000);   /* the reaches held triangles to find */
    sw_mesh_grid_free(g);
}

/* Two flat squares of n x n cells, the second lifted by h. */
static void squares(float *p, uint32_t *ix, int n, float h)
{
    for (int s = 0; s < 2; s++)
        for (int r = 0; r <= n; r++)
            for (int c = 0; c <= n; c++) {
                float *q = p + 3 * (s * (n + 1) * (n + 1) + r * (n + 1) + c);
                q[0] = 10.0f * (float)c / (float)n, q[1] = 10.0f * (float)r / (float)n;
                q[2] = s * h;
            }
    for (int s = 0; s < 2; s++)
        for (int r = 0; r < n; r++)
            for (int c = 0; c < n; c++) {
                uint32_t a = (uint32_t)(s * (n + 1) * (n + 1) + r * (n + 1) + c), b = a + 1,
                         d = a + (uint32_t)n + 1, e = d + 1;
                *ix++ = a, *ix++ = b, *ix++ = e, *ix++ = a, *ix++ = e, *ix++ = d;
            }
}

static void test_the_distance_between_two_sheets(void)
{
    enum { N = 8, V = 2 * (N + 1) * (N + 1), I = 2 * N * N * 6 };
    float p[3 * V];
    uint32_t ix[I];
    squares(p, ix, N, 0.25f);
    sw_mesh_view low = { p, ix, V, I / 2 }, high = { p, ix + I / 2, V, I / 2 };
    sw_mesh_grid *g = sw_mesh_grid_make(&low);
    SW_CHECK_NEAR(sw_mesh_distance(&high, g, 0.1), 0.25, 1e-6);
    /* one corner of the lifted sheet raised further: found by its corner
     * sample, and by the samples inside its triangles, at any spacing */
    p[3 * (V - 1) + 2] = 2.0f;
    SW_CHECK_NEAR(sw_mesh_distance(&high, g, 0.1), 2.0, 1e-6);
    SW_CHECK_NEAR(sw_mesh_distance(&high, g, 0), 2.0, 1e-6);
    sw_mesh_grid_free(g);
    sw_mesh_view none = { p, ix, V, 0 };
    SW_CHECK(sw_mesh_grid_make(&none) == NULL);
}

/* A long triangle over a mesh with a dip between where 8 samples a side
 * would fall: found at the spacing asked (with 8 a side it measured 0). */
static void test_long_triangles_are_sampled_at_the_spacing(void)
{
    /* a: one triangle 0..100 along x; g: the same plane with a dip 5 deep
     * from x = 1.5 to 11 (between 0 and 12.5, where 8 a side sample) */
    float pa[9] = { 0, 0, 0, 100, 0, 0, 0, 1, 0 };
    uint32_t ia[3] = { 0, 1, 2 };
    float pg[] = { 0, -1, 0, 1.5f, -1, 0, 6.25f, -1, -5, 11, -1, 0, 101, -1, 0,
                   0, 2, 0, 1.5f, 2, 0, 6.25f, 2, -5, 11, 2, 0, 101, 2, 0 };
    uint32_t ig[] = { 0, 1, 6, 0, 6, 5, 1, 2, 7, 1, 7, 6, 2, 3, 8, 2, 8, 7, 3, 4, 9, 3, 9, 8 };
    sw_mesh_view a = { pa, ia, 3, 3 }, gv = { pg, ig, 10, 24 };
    sw_mesh_grid *g = sw_mesh_grid_make(&gv);
    SW_CHECK(g != NULL);
    double d = sw_mesh_distance(&a, g, 0.1);
    SW_CHECK_MSG(d > 3, "the dip under the long triangle: %g", d);
    sw_mesh_grid_free(g);
}

int main(void)
{
    SW_RUN(test_nearest_is_the_nearest_of_all_triangles);
    SW_RUN(test_within_visits_every_triangle_within_reach_and_no_other);
    SW_RUN(test_the_distance_between_two_sheets);
    SW_RUN(test_long_triangles_are_sampled_at_the_spacing);
    return sw_test_finish();
}
