/* SPDX-License-Identifier: MIT */
/* The measurement of what was drawn (firmware/walk/gl/sw_seam_measure.h): the error
 * is the distance on screen between the flat point and the exact one, both
 * projected, and only samples on screen count. The exact surface is the
 * plane z = 0 (x, y in [-40, 40]) seen from z = 10; the meshes are single
 * triangles placed and displaced so the expected pixels follow by hand. */
#include <math.h>
#include <string.h>

#include "sw_seam_measure.h"
#include "sw_test.h"
#include "sw_view.h"

static const float plane_ctrl[16] = { -40, -40, 0, 1, 40, -40, 0, 1,
                                      -40, 40, 0, 1, 40, 40, 0, 1 };

static sw_view make_view(void)
{
    sw_camera_pose pose = { sw_v3(0, 0, 10), sw_v3(0, 0, 0), sw_v3(0, 1, 0) };
    sw_box box = { sw_v3(-40, -40, -1), sw_v3(40, 40, 1) };
    return sw_view_make(&pose, 60 * SW_PI / 180, 1280, 720, &box);
}

typedef struct measured {
    sw_stats stats;
    sw_seam_error acc;
    unsigned char block[1 << 16];
} measured;

/* Measures the triangle whose corners lie over plane points (x, y) of xy
 * and are drawn displaced by (dx, dy, dz). */
static void measure(measured *m, const double xy[3][2], sw_vec3 d, double sew_offset)
{
    sw_arena arena;
    sw_arena_init(&arena, m->block, sizeof m->block);
    SW_CHECK(sw_stats_init(&m->stats, &arena, 1, 0.5, NULL) == SW_OK);
    memset(&m->acc, 0, sizeof m->acc);
    sw_vertex verts[3];
    float uvs[6];
    for (int k = 0; k < 3; k++) {
        verts[k] = (sw_vertex){ { (float)(xy[k][0] + d.x), (float)(xy[k][1] + d.y),
                                  (float)d.z }, { 0, 0, 127, 0 } };
        uvs[2 * k] = (float)((xy[k][0] + 40) / 80), uvs[2 * k + 1] = (float)((xy[k][1] + 40) / 80);
    }
    static const uint16_t tri[3] = { 0, 1, 2 };
    const sw_seam_mesh mesh = { verts, uvs, tri, 3, 3 };
    const sw_trim_patch patch = { { 1, 1, 0, plane_ctrl }, { 0, 1, 0, 1 } };
    const sw_seam_exact exact = { &patch, 1, sew_offset, 10.0, 0.5, 0.0 };
    sw_view view = make_view();
    sw_seam_measure_mesh(&mesh, &exact, &view, &m->stats, &m->acc);
}

static measured m;

static void test_across_the_axis_is_size_over_depth(void)
{
    const double xy[3][2] = { { 0, 0 }, { 0.01, 0 }, { 0, 0.01 } };
    measure(&m, xy, sw_v3(0.002, 0, 0), 0.0);
    sw_view v = make_view();
    /* vertices, centroid and edge midpoints: seven samples, all on screen */
    SW_CHECK(m.stats.error_samples == 7);
    /* (u, v) are floats: 80 units a domain make them good to ~5e-6 */
    SW_CHECK_NEAR(m.stats.error_max_px, 0.002 * v.px_per_unit / 10.0, 1e-3);
    SW_CHECK_NEAR(m.acc.beyond_sewing_px, m.stats.error_max_px, 1e-6);
}

static void test_along_the_axis_off_centre_is_projected(void)
{
    /* Lifted 0.2 towards the eye at x = 5: distance over depth would say
     * 0.2 * ppu / 10; on screen the point moves by the change of 5 / depth. */
    const double xy[3][2] = { { 5, 0 }, { 5.001, 0 }, { 5, 0.001 } };
    measure(&m, xy, sw_v3(0, 0, 0.2), 0.0);
    sw_view v = make_view();
    double expected = v.px_per_unit * 5.0 * (1 / 9.8 - 1 / 10.0);
    SW_CHECK(m.stats.error_samples == 7);
    SW_CHECK_NEAR(m.stats.error_max_px, expected, 1e-3 * expected);
    SW_CHECK(m.stats.error_max_px < 0.2 * v.px_per_unit / 10.0 * 0.6);
}

static void test_on_the_axis_a_lift_does_not_move_the_pixel(void)
{
    /* 0.5 towards the eye, 0.001 off the axis: 0.001 * ppu * (1/9.5 - 1/10),
     * 0.0033 px, where distance over depth says 31 px */
    const double xy[3][2] = { { 0, 0 }, { 0.001, 0 }, { 0, 0.001 } };
    measure(&m, xy, sw_v3(0, 0, 0.5), 0.0);
    SW_CHECK(m.stats.error_samples == 7);
    SW_CHECK(m.stats.error_max_px < 0.004);
}

static void test_a_zero_area_triangle_measures_a_chord_apart(void)
{
    /* corners on one line, as the crossing fans' (sw_seam_fill.h) are */
    const double xy[3][2] = { { 0, 0 }, { 0.01, 0 }, { 0.02, 0 } };
    measure(&m, xy, sw_v3(0, 0.002, 0), 0.0);
    sw_view v = make_view();
    SW_CHECK(m.stats.error_samples == 0 && m.stats.error_max_px == 0);
    SW_CHECK_NEAR(m.acc.chord_px, 0.002 * v.px_per_unit / 10.0, 1e-3);
}

static void test_samples_behind_the_eye_are_not_counted(void)
{
    /* Drawn 15 units up, behind the eye at z = 10: nothing on screen. */
    const double xy[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
    measure(&m, xy, sw_v3(0, 0, 15.0), 0.0);
    SW_CHECK(m.stats.error_samples == 0);
    SW_CHECK(m.stats.error_max_px == 0 && m.acc.beyond_sewing_px == 0);
}

static void test_samples_outside_the_viewport_are_not_counted(void)
{
    /* Depth 10 and 60 degrees high: the view ends at |y| = 5.77. */
    const double xy[3][2] = { { 0, 20 }, { 1, 20 }, { 0, 21 } };
    measure(&m, xy, sw_v3(0.5, 0, 0), 0.0);
    SW_CHECK(m.stats.error_samples == 0);
    /* Half in: the corner at y = 5 and the samples near it count, the rest not. */
    const double half[3][2] = { { 0, 5 }, { 1, 7 }, { -1, 7 } };
    measure(&m, half, sw_v3(0.001, 0, 0), 0.0);
    SW_CHECK(m.stats.error_samples > 0 && m.stats.error_samples < 7);
}

static void test_within_the_sewing_offset_nothing_is_beyond(void)
{
    const double xy[3][2] = { { 0, 0 }, { 0.01, 0 }, { 0, 0.01 } };
    measure(&m, xy, sw_v3(0.002, 0, 0), 0.003);
    SW_CHECK(m.stats.error_max_px > 0.05);
    SW_CHECK(m.acc.beyond_sewing_px == 0);
    measure(&m, xy, sw_v3(0.002, 0, 0), 0.001);
    SW_CHECK_NEAR(m.acc.beyond_sewing_px, 0.5 * m.stats.error_max_px, 1e-3);
}

int main(void)
{
    SW_RUN(test_across_the_axis_is_size_over_depth);
    SW_RUN(test_along_the_axis_off_centre_is_projected);
    SW_RUN(test_on_the_axis_a_lift_does_not_move_the_pixel);
    SW_RUN(test_a_zero_area_triangle_measures_a_chord_apart);
    SW_RUN(test_samples_behind_the_eye_are_not_counted);
    SW_RUN(test_samples_outside_the_viewport_are_not_counted);
    SW_RUN(test_within_the_sewing_offset_nothing_is_beyond);
    return sw_test_finish();
}
