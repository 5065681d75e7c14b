/* SPDX-License-Identifier: MIT */
/* sw_tt_cell_rings (core/sw_trim_cell.c), the tessellator's clipping of one
 * cell by the loops: a loop point the clip meets at the very end of its
 * segment is taken as it is, and may lie a rounding inside the cell rather
 * than on its side (the Bambu mount's thin strip: a point at u = -5.7e-24
 * against the side u = 0). It is ordered on the side the clip found, and
 * the cell comes out as the strip's rectangle, measured here by its area
 * and its corners. */
#include <math.h>
#include <string.h>

#include "sw_test.h"
#include "sw_trim_cell.h"

static unsigned char s_block[1 << 16];

/* The strip as the tessellator held it: counter-clockwise, region inside,
 * its top a shrink below v = 0, the point at u = 0 a rounding inside. */
static const double strip[9][2] = {
    {-1.185559389604284, -0.070710679007722613}, {-0.59277969598770142, -0.070710679007722613},
    {2.8921309791485328e-14, -0.070710679007722613}, {1.185559389604284, -0.070710679007722613},
    {1.185559389604284, -2.371118783950806e-09}, {0.4475475549697876, -2.371118783950806e-09},
    {-5.7308373033247798e-24, -2.371118783950806e-09},
    {-0.59277969598770142, -2.3711159185321544e-09},
    {-1.185559389604284, -2.3711159185321544e-09},
};

static double ring_area(const sw_tt_rings *r, uint32_t k)
{
    uint32_t first = k ? r->ring_end[k - 1] : 0, n = r->ring_end[k] - first;
    double sum = 0;
    for (uint32_t i = 0; i < n; i++) {
        const sw_tt_pv *a = &r->verts[first + i], *b = &r->verts[first + (i + 1) % n];
        sum += a->u * b->v - b->u * a->v;
    }
    return 0.5 * sum;
}

static void test_a_loop_point_a_rounding_inside_the_side(void)
{
    sw_tt_point pts[9];
    for (uint32_t i = 0; i < 9; i++)
        pts[i] = (sw_tt_point){strip[i][0], strip[i][1], i, (i + 1) % 9, 0};
    sw_tt_loop loop = {0, 9, {-1.185559389604284, 1.185559389604284, -0.070710679007722613,
                              -2.3711159185321544e-09}, 0};
    sw_tt_trims trims = {pts, &loop, 9, 1};
    const sw_tt_rect r = {-0.59277969598770142, 0, -0.0707106813788414, 2.8654186516623896e-15};
    const sw_tt_pv border[4] = {
        {r.u0, r.v0, SW_TT_GRID, 0, 0, 0, 0, 0}, {r.u1, r.v0, SW_TT_GRID, 0, 0, 0, 0, 0},
        {r.u1, r.v1, SW_TT_GRID, 0, 0, 0, 0, 0}, {r.u0, r.v1, SW_TT_GRID, 0, 0, 0, 0, 0}};
    /* The segments that meet the closed cell. */
    const uint32_t segs[5] = {0, 1, 5, 6, 7};
    uint32_t stamp[9] = {0}, skipped = 0;
    sw_arena a;
    sw_arena_init(&a, s_block, sizeof s_block);
    sw_tt_rings rings;
    int rc = sw_tt_cell_rings(&trims, &r, segs, 5, border, 4, stamp, 1, &a, &rings, &skipped);
    SW_CHECK_MSG(rc == SW_TT_CELL_OK, "cell rings: %d, expected %d", rc, SW_TT_CELL_OK);
    if (rc != SW_TT_CELL_OK)
        return;
    SW_CHECK(rings.ring_count == 1 && skipped == 0);
    /* The strip within the cell: u from the side to 0, v from the bottom
     * of the loop to its top. */
    double want = -r.u0 * (strip[7][1] - strip[1][1]);
    double got = ring_area(&rings, 0);
    SW_CHECK_MSG(fabs(got - want) < 1e-12, "ring area %.17g, expected %.17g", got, want);
    int has_point6 = 0;
    for (uint32_t i = 0; i < rings.vert_count; i++)
        has_point6 |= rings.verts[i].kind == SW_TT_SEAM && rings.verts[i].ref == 6;
    SW_CHECK(has_point6);
}

int main(void)
{
    SW_RUN(test_a_loop_point_a_rounding_inside_the_side);
    return sw_test_finish();
}
