/* SPDX-License-Identifier: MIT */
/* A sheet's rim corners held for the simplifier (assets/super/sw_part_rim.h):
 * found where the rim turns and nowhere else, held through meshoptimizer
 * down to the fewest triangles it can make, and mapped back. */
#include <meshoptimizer.h>
#include <string.h>

#include "sw_part_rim.h"
#include "sw_test.h"

enum { COLS = 40, ROWS = 6, VERTS = (COLS + 1) * (ROWS + 1), INDICES = COLS * ROWS * 6 };

/* A wall COLS x ROWS cells, x along, y up, its foot a wave in z: the
 * rail's side, where meshoptimizer cut the corners off. */
static void wall(float *pos, uint32_t *idx)
{
    for (int r = 0; r <= ROWS; r++)
        for (int c = 0; c <= COLS; c++) {
            float *p = pos + 3 * (r * (COLS + 1) + c);
            p[0] = 30.0f * (float)c, p[1] = 20.0f * (float)r;
            p[2] = 60.0f * sinf(6.2831853f * (float)c / COLS);
        }
    uint32_t *o = idx;
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLS; c++) {
            uint32_t a = (uint32_t)(r * (COLS + 1) + c), b = a + 1, d = a + COLS + 1, e = d + 1;
            *o++ = a, *o++ = b, *o++ = e, *o++ = a, *o++ = e, *o++ = d;
        }
}

static int has_position(const float *pos, const uint32_t *idx, size_t n, const float *p)
{
    for (size_t i = 0; i < n; i++)
        if (memcmp(pos + 3 * (size_t)idx[i], p, 3 * sizeof *p) == 0)
            return 1;
    return 0;
}

static void test_the_four_corners_of_a_wall_are_held(void)
{
    static float pos[3 * VERTS];
    static uint32_t idx[INDICES], dest[INDICES];
    wall(pos, idx);
    sw_part_tris t = { pos, idx, VERTS, INDICES };
    sw_part_rim r = { 0 };
    SW_CHECK(sw_part_rim_hold_corners(&r, &t, 0.70710678));
    SW_CHECK_MSG(r.copies == 4, "%u corners held", r.copies);
    size_t n = meshopt_simplify(dest, r.idx, INDICES, r.pos, r.vertex_count, 3 * sizeof(float),
                                6, 1e30f, 0, NULL);
    sw_part_rim_unmap(&r, VERTS, dest, n);
    for (size_t i = 0; i < n; i++)
        SW_CHECK(dest[i] < VERTS);
    const int corners[4] = { 0, COLS, ROWS * (COLS + 1), VERTS - 1 };
    for (int k = 0; k < 4; k++)
        SW_CHECK_MSG(has_position(pos, dest, n, pos + 3 * corners[k]),
                     "corner %d lost in %zu indices", corners[k], n);
    sw_part_rim_free(&r);
}

static void test_a_closed_surface_has_no_rim(void)
{
    /* A tetrahedron, every edge run both ways. */
    static const float pos[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    static const uint32_t idx[12] = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
    sw_part_tris t = { pos, idx, 4, 12 };
    sw_part_rim r = { 0 };
    SW_CHECK(sw_part_rim_hold_corners(&r, &t, 0.70710678));
    SW_CHECK(r.copies == 0 && r.vertex_count == 4);
    SW_CHECK(memcmp(r.idx, idx, sizeof idx) == 0);
    sw_part_rim_free(&r);
}

static void test_a_straight_rim_is_not_held(void)
{
    /* The wall's long sides turn by a few degrees a cell: no corner there,
     * and none held at a turn under the angle asked. */
    static float pos[3 * VERTS];
    static uint32_t idx[INDICES];
    wall(pos, idx);
    sw_part_tris t = { pos, idx, VERTS, INDICES };
    sw_part_rim r = { 0 };
    SW_CHECK(sw_part_rim_hold_corners(&r, &t, -0.5));   /* only turns past 120 degrees */
    SW_CHECK_MSG(r.copies == 0, "%u held", r.copies);
    sw_part_rim_free(&r);
}

int main(void)
{
    test_the_four_corners_of_a_wall_are_held();
    test_a_closed_surface_has_no_rim();
    test_a_straight_rim_is_not_held();
    return sw_test_finish();
}
