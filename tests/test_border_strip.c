/* SPDX-License-Identifier: MIT */
/* Border strips (core/sw_border_strip.h). The outer chain's vertices are
 * numbered 0 .. a - 1, the inner chain's a .. a + b - 1, as the chains are
 * given (not sorted). Geometry, where a test needs it: the loop is a
 * circle, t the angle in slots (period P slots round), the outer chain at
 * radius 1, the inner at radius R. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_border_strip.h"
#include "sw_test.h"

enum { MAXP = 512 };
#define P 100.0f
#define R 0.5
#define PI 3.14159265358979323846

static sw_strip_point outer[MAXP], inner[MAXP];
static uint32_t tris[3 * 2 * MAXP + 3];

/* A chain of n points at the sorted t's given, starting at index `first`
 * of them (so the wrap falls anywhere), numbered from base. */
static void chain(sw_strip_point *c, const float *t, uint32_t n, uint32_t first, uint32_t base)
{
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = (first + i) % n;
        c[i] = (sw_strip_point){ base + k, t[k] };
    }
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* n distinct random t's in [0, P), sorted. */
static void random_ts(float *t, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        t[i] = (float)(rand() % 100000) * (P / 100000.0f);
    qsort(t, n, sizeof *t, cmp_float);
}

/* How many triangles use the undirected edge x-y. */
static uint32_t edge_uses(uint32_t count, uint32_t x, uint32_t y)
{
    uint32_t uses = 0;
    for (uint32_t i = 0; i < count; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t p = tris[3 * i + k], q = tris[3 * i + (k + 1) % 3];
            uses += (p == x && q == y) || (p == y && q == x);
        }
    return uses;
}

/* The band is closed: each chain edge (consecutive in t, the last to the
 * first) is used by exactly one triangle, each triangle has two vertices on
 * one chain and one on the other, and every rung (an edge between the
 * chains) is used an even number of times: with every chain edge once,
 * that is what leaves no hole between the chains. */
static void check_band(uint32_t count, uint32_t a, uint32_t b, const float *to, const float *ti)
{
    SW_CHECK(count == a + b);
    (void)to, (void)ti;
    for (uint32_t i = 0; a > 1 && i < a; i++)
        SW_CHECK_MSG(edge_uses(count, i, (i + 1) % a) == (a == 2 ? 2u : 1u), "outer edge %u", i);
    for (uint32_t j = 0; b > 1 && j < b; j++)
        SW_CHECK_MSG(edge_uses(count, a + j, a + (j + 1) % b) == (b == 2 ? 2u : 1u),
                     "inner edge %u", j);
    for (uint32_t i = 0; i < count; i++) {
        int on_outer = (tris[3 * i] < a) + (tris[3 * i + 1] < a) + (tris[3 * i + 2] < a);
        SW_CHECK_MSG(on_outer == 1 || on_outer == 2, "triangle %u", i);
    }
    for (uint32_t i = 0; i < a; i++)
        for (uint32_t j = 0; j < b; j++)
            SW_CHECK_MSG(edge_uses(count, i, a + j) % 2 == 0, "rung %u-%u", i, a + j);
}

/* Signed area of triangle i with the outer chain on the unit circle and the
 * inner at radius R, angle t / P round. */
static double point_xy(uint32_t v, uint32_t a, const float *to, const float *ti, int axis)
{
    double r = v < a ? 1.0 : R, t = v < a ? to[v] : ti[v - a];
    double ang = 2 * PI * t / P;
    return axis == 0 ? r * cos(ang) : r * sin(ang);
}

static double signed_area(uint32_t i, uint32_t a, const float *to, const float *ti)
{
    double x[3], y[3];
    for (int k = 0; k < 3; k++) {
        x[k] = point_xy(tris[3 * i + k], a, to, ti, 0);
        y[k] = point_xy(tris[3 * i + k], a, to, ti, 1);
    }
    return 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]));
}

static double polygon_area(const float *t, uint32_t n, double r)
{
    double area = 0;
    for (uint32_t i = 0; i < n; i++) {
        double a0 = 2 * PI * t[i] / P, a1 = 2 * PI * t[(i + 1) % n] / P;
        area += 0.5 * r * r * sin(a1 - a0 < 0 ? a1 - a0 + 2 * PI : a1 - a0);
    }
    return area;
}

static void test_a_band_between_two_even_chains(void)
{
    const float to[4] = { 0, 25, 50, 75 }, ti[4] = { 10, 35, 60, 85 };
    chain(outer, to, 4, 0, 0);
    chain(inner, ti, 4, 0, 4);
    uint32_t n = sw_border_strip(outer, 4, inner, 4, P, tris);
    check_band(n, 4, 4, to, ti);
}

/* Chains that are nested give a band that does not fold: every triangle
 * turns the same way, and together they cover exactly the area between the
 * two polygons. Nested here: the inner at half the outer's radius and no
 * gap in either chain wider than 0.73 rad, so a fan from a point of one
 * chain never reaches past where the other chain's edge faces away from it
 * (acos R = 1.05 rad). A sparse chain far from a dense one can fold; the
 * next test shows the band stays closed then. Wraps anywhere, inner
 * starting before or after the outer. */
static void test_nested_chains_tile_the_band_exactly(void)
{
    srand(7);
    for (int trial = 0; trial < 300; trial++) {
        uint32_t a = 12 + (uint32_t)(rand() % 120), b = 12 + (uint32_t)(rand() % 120);
        float to[MAXP], ti[MAXP];
        /* evenly spread with jitter, so no gap spans half the circle */
        for (uint32_t i = 0; i < a; i++)
            to[i] = ((float)i + 0.4f * (float)(rand() % 100) / 100.0f) * P / (float)a;
        for (uint32_t j = 0; j < b; j++)
            ti[j] = ((float)j + 0.4f * (float)(rand() % 100) / 100.0f) * P / (float)b;
        chain(outer, to, a, (uint32_t)rand() % a, 0);
        chain(inner, ti, b, (uint32_t)rand() % b, a);
        uint32_t n = sw_border_strip(outer, a, inner, b, P, tris);
        check_band(n, a, b, to, ti);
        double sum = 0;
        int folded = 0;
        for (uint32_t i = 0; i < n; i++) {
            double s = signed_area(i, a, to, ti);
            folded += s < -1e-12;   /* t runs anticlockwise, outer to inner inwards */
            sum += s;
        }
        SW_CHECK_MSG(folded == 0, "trial %d: %d triangles folded", trial, folded);
        double band = polygon_area(to, a, 1.0) - polygon_area(ti, b, R);
        SW_CHECK_NEAR(sum, band, 1e-9 * (a + b));
    }
}

/* Random chains of any lengths, with repeated t's and points on both sides
 * of each other: the band stays closed (its edges as check_band says). */
static void test_random_chains_close(void)
{
    srand(11);
    for (int trial = 0; trial < 300; trial++) {
        uint32_t a = 1 + (uint32_t)(rand() % 60), b = 1 + (uint32_t)(rand() % 60);
        float to[MAXP], ti[MAXP];
        random_ts(to, a);
        random_ts(ti, b);
        if (trial % 3 == 0 && a > 2)
            to[1] = to[0];   /* two points at one place (a pole's corners) */
        chain(outer, to, a, (uint32_t)rand() % a, 0);
        chain(inner, ti, b, (uint32_t)rand() % b, a);
        uint32_t n = sw_border_strip(outer, a, inner, b, P, tris);
        SW_CHECK_MSG(n == a + b, "trial %d: %u of %u", trial, n, a + b);
        if (a > 2 && b > 2)
            check_band(n, a, b, to, ti);
    }
}

/* A loop that vanished at the front (one point left) is closed by a fan
 * onto the inner chain: the hole is covered. */
static void test_one_outer_point_fans_the_inner_chain(void)
{
    const float to[1] = { 40 }, ti[5] = { 0, 20, 40, 60, 80 };
    chain(outer, to, 1, 0, 0);
    chain(inner, ti, 5, 2, 1);
    uint32_t n = sw_border_strip(outer, 1, inner, 5, P, tris);
    SW_CHECK(n == 6);
    for (uint32_t j = 0; j < 5; j++)
        SW_CHECK(edge_uses(n, 1 + j, 1 + (j + 1) % 5) == 1);
}

/* The rung at the start joins points near each other: the inner chain's
 * last point at or before the outer's first, not its first point. */
static void test_the_first_rung_joins_neighbours(void)
{
    const float to[3] = { 50, 60, 70 }, ti[3] = { 5, 45, 95 };
    chain(outer, to, 3, 0, 0);
    chain(inner, ti, 3, 0, 3);
    uint32_t n = sw_border_strip(outer, 3, inner, 3, P, tris);
    SW_CHECK(n == 6);
    /* outer 0 (t 50) and inner 1 (t 45, vertex 4) share the first triangle */
    SW_CHECK(tris[0] == 0 && (tris[1] == 4 || tris[2] == 4));
    /* no triangle joins outer t 50 .. 70 to inner t 5 (vertex 3) */
    for (uint32_t i = 0; i < n; i++) {
        int has3 = tris[3 * i] == 3 || tris[3 * i + 1] == 3 || tris[3 * i + 2] == 3;
        int has1 = tris[3 * i] == 1 || tris[3 * i + 1] == 1 || tris[3 * i + 2] == 1;
        SW_CHECK(!(has3 && has1));
    }
}

static void test_invalid_chains_write_nothing(void)
{
    const float good[3] = { 0, 30, 60 };
    chain(outer, good, 3, 0, 0);
    chain(inner, good, 3, 0, 3);
    memset(tris, 0xAB, sizeof tris);
    sw_strip_point twice[4] = { { 0, 10 }, { 1, 5 }, { 2, 20 }, { 3, 1 } };   /* wraps twice */
    SW_CHECK(sw_border_strip(twice, 4, inner, 3, P, tris) == 0);
    sw_strip_point beyond[2] = { { 0, 10 }, { 1, P } };
    SW_CHECK(sw_border_strip(outer, 3, beyond, 2, P, tris) == 0);
    sw_strip_point nan_t[2] = { { 0, 10 }, { 1, NAN } };
    SW_CHECK(sw_border_strip(outer, 3, nan_t, 2, P, tris) == 0);
    sw_strip_point negative[2] = { { 0, -1 }, { 1, 3 } };
    SW_CHECK(sw_border_strip(negative, 2, inner, 3, P, tris) == 0);
    SW_CHECK(sw_border_strip(outer, 0, inner, 3, P, tris) == 0);
    SW_CHECK(sw_border_strip(outer, 3, inner, 3, 0.0f, tris) == 0);
    SW_CHECK(sw_border_strip(outer, 3, inner, 3, P, NULL) == 0);
    SW_CHECK(tris[0] == 0xABABABABu);
    SW_CHECK(sw_border_chain_valid(outer, 3, P) && !sw_border_chain_valid(twice, 4, P));
}

int main(void)
{
    SW_RUN(test_a_band_between_two_even_chains);
    SW_RUN(test_nested_chains_tile_the_band_exactly);
    SW_RUN(test_random_chains_close);
    SW_RUN(test_one_outer_point_fans_the_inner_chain);
    SW_RUN(test_the_first_rung_joins_neighbours);
    SW_RUN(test_invalid_chains_write_nothing);
    return sw_test_finish();
}
