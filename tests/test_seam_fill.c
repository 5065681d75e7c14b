/* SPDX-License-Identifier: MIT */
/* Fill fans over seam crossings (firmware/walk/workers/sw_seam_fill.h). The mesh is a
 * strip of three quads over a seam: its bottom border runs from seam vertex
 * a through two crossings to seam vertex b, so the neighbour's straight
 * edge a-b would meet it in two T-junctions. */
#include <string.h>

#include "sw_seam_fill.h"
#include "sw_test.h"
#include "sw_trim_tess.h"

enum { V = 8, STRIP = 18, CAP = 64 };

static sw_seam_fill fill;
static unsigned char block[1 << 16];

/* Bottom 0 (a), 1, 2 (crossings), 3 (b); top 4..7, seam vertices. */
static const uint32_t ids[V] = { 10, SW_TRIM_CROSSING, SW_TRIM_CROSSING, 11, 12, 13, 14, 15 };

static uint32_t make_strip(uint16_t *idx)
{
    uint32_t n = 0;
    for (uint16_t i = 0; i < 3; i++) {
        const uint16_t t[6] = { i, (uint16_t)(i + 1), (uint16_t)(5 + i),
                                i, (uint16_t)(5 + i), (uint16_t)(4 + i) };
        memcpy(idx + n, t, sizeof t);
        n += 6;
    }
    return n;
}

/* How many triangles use edge a-b. */
static int uses(const uint16_t *idx, uint32_t n, uint16_t a, uint16_t b)
{
    int count = 0;
    for (uint32_t t = 0; t + 2 < n; t += 3)
        for (int k = 0; k < 3; k++) {
            uint16_t p = idx[t + k], q = idx[t + (k + 1) % 3];
            count += (p == a && q == b) || (p == b && q == a);
        }
    return count;
}

static void init(void)
{
    sw_arena arena;
    sw_arena_init(&arena, block, sizeof block);
    SW_CHECK(sw_seam_fill_init(&fill, V, CAP, &arena, NULL) == SW_OK);
}

static void test_the_fan_closes_the_border_onto_the_seam_edge(void)
{
    init();
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 99;
    SW_CHECK(sw_seam_fill_crossings(&fill, ids, V, idx, &n, CAP, &left) == 2);
    SW_CHECK(n == STRIP + 6 && left == 0);
    /* the fan is (a, c1, c2), (a, c2, b): no vertex added */
    const uint16_t fan[6] = { 0, 1, 2, 0, 2, 3 };
    SW_CHECK(memcmp(idx + STRIP, fan, sizeof fan) == 0);
    /* the border now runs a-b: every edge at a crossing has two triangles */
    SW_CHECK(uses(idx, n, 0, 1) == 2 && uses(idx, n, 1, 2) == 2 && uses(idx, n, 2, 3) == 2);
    SW_CHECK(uses(idx, n, 0, 3) == 1);
    /* the rest of the border is as it was */
    SW_CHECK(uses(idx, n, 3, 7) == 1 && uses(idx, n, 4, 0) == 1 && uses(idx, n, 5, 6) == 1);
}

static void test_no_crossings_nothing_added(void)
{
    init();
    uint32_t plain[V];
    memcpy(plain, ids, sizeof plain);
    plain[1] = 20, plain[2] = 21;
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 99;
    SW_CHECK(sw_seam_fill_crossings(&fill, plain, V, idx, &n, CAP, &left) == 0);
    SW_CHECK(n == STRIP && left == 0);
}

static void test_a_run_that_does_not_fit_is_left_whole(void)
{
    init();
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 0;
    SW_CHECK(sw_seam_fill_crossings(&fill, ids, V, idx, &n, STRIP + 3, &left) == 0);
    SW_CHECK(n == STRIP && left == 2);
}

int main(void)
{
    SW_RUN(test_the_fan_closes_the_border_onto_the_seam_edge);
    SW_RUN(test_no_crossings_nothing_added);
    SW_RUN(test_a_run_that_does_not_fit_is_left_whole);
    return sw_test_finish();
}
