/* SPDX-License-Identifier: MIT */
/* The seams as drawn (firmware/walk/gl/sw_seam_drawn.h): two unit squares side by
 * side, A over x in [0, 1] and B over [1, 2], meeting along x = 1; B's
 * side of the seam varied to make each case. */
#include <string.h>

#include "sw_seam_drawn.h"
#include "sw_test.h"

static sw_seam_drawn drawn;
static unsigned char block[1 << 20];
static const sw_box box = { { -1, -1, -1 }, { 3, 2, 1 } };

static void begin(void)
{
    sw_arena arena;
    sw_arena_init(&arena, block, sizeof block);
    SW_CHECK(sw_seam_drawn_init(&drawn, &box, 0.01, 256, 64, &arena, NULL) == SW_OK);
    sw_seam_drawn_begin(&drawn);
}

/* A fan over the corners of a convex polygon, counter-clockwise. */
static void add_polygon(uint32_t surface, const float (*xy)[2], int n)
{
    sw_vertex v[8];
    uint16_t idx[24];
    for (int i = 0; i < n; i++)
        v[i] = (sw_vertex){ { xy[i][0], xy[i][1], 0 }, { 0, 0, 127, 0 } };
    for (int i = 1; i + 1 < n; i++)
        idx[3 * (i - 1)] = 0, idx[3 * (i - 1) + 1] = (uint16_t)i, idx[3 * (i - 1) + 2] = (uint16_t)(i + 1);
    const sw_seam_mesh mesh = { v, NULL, idx, (uint32_t)n, (uint32_t)(3 * (n - 2)) };
    sw_seam_drawn_add_mesh(&drawn, surface, &mesh);
}

static const float a_square[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };

static sw_seam_drawn_result check(void)
{
    sw_seam_drawn_result r;
    sw_seam_drawn_check(&drawn, &r);
    SW_CHECK(r.checked);
    return r;
}

static void test_a_shared_edge_is_shared(void)
{
    begin();
    add_polygon(0, a_square, 4);
    const float b[4][2] = { { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 } };
    add_polygon(1, b, 4);
    sw_seam_drawn_result r = check();
    SW_CHECK(r.points == 8 && r.shared == 4 && r.free_points == 4);
    SW_CHECK(r.t_vertices == 0 && r.gaps == 0);
}

static void test_a_vertex_on_the_other_side_s_edge_is_a_t_vertex(void)
{
    begin();
    add_polygon(0, a_square, 4);
    /* B has a vertex at (1, 1/3) that A's edge (1, 0)-(1, 1) passes through */
    const float b[5][2] = { { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 1.0f / 3 } };
    add_polygon(1, b, 5);
    sw_seam_drawn_result r = check();
    SW_CHECK(r.t_vertices == 1 && r.gaps == 0);
    SW_CHECK(r.shared == 4 && r.points == 9);
}

static void test_a_side_off_the_other_within_reach_is_a_gap(void)
{
    begin();
    add_polygon(0, a_square, 4);
    const float b[4][2] = { { 1.001f, 0 }, { 2, 0 }, { 2, 1 }, { 1.001f, 1 } };
    add_polygon(1, b, 4);
    sw_seam_drawn_result r = check();
    /* both ends of both sides: 0.001 apart, within the reach of 0.01 */
    SW_CHECK(r.gaps == 4 && r.shared == 0 && r.t_vertices == 0);
}

static void test_nothing_within_reach_is_free(void)
{
    begin();
    add_polygon(0, a_square, 4);
    const float b[4][2] = { { 1.5f, 0 }, { 2, 0 }, { 2, 1 }, { 1.5f, 1 } };
    add_polygon(1, b, 4);
    sw_seam_drawn_result r = check();
    SW_CHECK(r.free_points == 8 && r.gaps == 0 && r.shared == 0);
}

static void test_more_borders_than_the_block_holds_are_not_checked(void)
{
    begin();
    for (uint32_t s = 0; s < 65; s++)
        add_polygon(s, a_square, 4);
    sw_seam_drawn_result r;
    sw_seam_drawn_check(&drawn, &r);
    SW_CHECK(!r.checked && r.points == 0);
}

int main(void)
{
    SW_RUN(test_a_shared_edge_is_shared);
    SW_RUN(test_a_vertex_on_the_other_side_s_edge_is_a_t_vertex);
    SW_RUN(test_a_side_off_the_other_within_reach_is_a_gap);
    SW_RUN(test_nothing_within_reach_is_free);
    SW_RUN(test_more_borders_than_the_block_holds_are_not_checked);
    return sw_test_finish();
}
