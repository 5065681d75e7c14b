/* SPDX-License-Identifier: MIT */
/* Flattening (sw_seam_flatten.h): a trimmed rational bump's polylines
 * within the tolerance of its exact trims; folds: a loop whose (u, v)
 * crosses itself at a corner, by a p-curve overshooting it or a hair of a
 * closing trim, comes out not crossing itself, its corners kept; and a
 * loop starting where the last one ended keeps its start, and each its
 * segments' shared edges. */
#include <math.h>
#include <string.h>

#include "model_shapes.h"
#include "seam_polyline_check.h"
#include "sw_seam_flatten.h"
#include "sw_test.h"

/* A bicubic bump trimmed by a circle and a rational circle hole. */
static void test_trimmed_bump_polylines_within_tolerance(void)
{
    double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1}, ctrl[16 * 4];
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            double *c = ctrl + 4 * (j * 4 + i);
            c[0] = i / 3.0 * 10, c[1] = j / 3.0 * 10;
            c[2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 6 : (i + j) % 3;
            c[3] = 1 + 0.3 * ((i + 2 * j) % 3); /* rational */
        }
    sw_nurbs_surface surf = {3, 3, 4, 4, knots, knots, ctrl};
    shape_circle outer, hole;
    shape_circle_init(&outer, 0.5, 0.5, 0.45, 0);
    shape_circle_init(&hole, 0.6, 0.45, 0.1, 1);
    sw_model_loop_input loops[2] = {{&outer.curve, NULL, 1, 1, NULL, NULL},
                                    {&hole.curve, NULL, 1, 0, NULL, NULL}};
    sw_model m;
    sw_model_init(&m);
    sw_error err;
    SW_CHECK(sw_model_add_surface(&m, &surf, 0, loops, 2, &err) == SW_OK);
    check_polyline_error(&m, 1e-3, 1);
    check_polyline_error(&m, 3e-2, 1);
    sw_model_free(&m);
}

/* ---- folds ------------------------------------------------------------- */

/* The polygon pts[0 .. n) (n <= 8) as a loop of straight trims on the
 * plane [0, 2]^2, flattened at 1e-5 into pl (m holds the model). */
static void flatten_polygon(const double (*pts)[2], int n, sw_model *m, sw_seam_polylines *pl)
{
    static shape_plane plane;
    shape_plane_init(&plane, 1, 1, 1, 2, 2);
    static double knots[4] = {0, 0, 1, 1}, ctrl[8][8];
    sw_nurbs_curve curves[8];
    for (int k = 0; k < n; k++) {
        const double *a = pts[k], *b = pts[(k + 1) % n];
        double c[8] = {a[0], a[1], 0, 1, b[0], b[1], 0, 1};
        memcpy(ctrl[k], c, sizeof c);
        curves[k] = (sw_nurbs_curve){1, 2, knots, ctrl[k]};
    }
    sw_model_loop_input loop = {curves, NULL, (size_t)n, 1, NULL, NULL};
    sw_model_init(m);
    sw_error err;
    SW_CHECK(sw_model_add_surface(m, &plane.surface, 0, &loop, 1, &err) == SW_OK);
    SW_CHECK_MSG(sw_seam_flatten_model(m, 1e-5, pl, &err) == SW_OK, "%s", err.message);
}

/* A loop of the square [0.5, 1.5]^2 whose bottom curve runs 0.003 past the
 * right side and 0.001 below its start before a straight trim closes the
 * gap back to it (a p-curve overshooting a corner): flattened, the loop
 * does not cross itself (no two of its segments cross in (u, v)), and the
 * fold is gone, the corner where the two sides cross. */
static void test_a_fold_at_a_corner_is_cut_off(void)
{
    const double pts[5][2] = {{0.5, 0.5}, {1.503, 0.499}, {1.5, 0.499}, {1.5, 1.5}, {0.5, 1.5}};
    sw_model m;
    sw_seam_polylines pl;
    flatten_polygon(pts, 5, &m, &pl);
    size_t n = pl.loop_start[1] - pl.loop_start[0], crossings = 0, corner = 0;
    for (size_t i = 0; i < n; i++) {
        const double *a = pl.uv + 2 * i, *b = pl.uv + 2 * ((i + 1) % n);
        corner += fabs(a[0] - 1.5) < 1e-9 && fabs(a[1] - (0.5 - 0.001 / 1.003)) < 1e-9;
        for (size_t j = i + 2; j < n; j++) {
            if ((j + 1) % n == i)
                continue;
            const double *c = pl.uv + 2 * j, *d = pl.uv + 2 * ((j + 1) % n);
            double o1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            double o2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
            double o3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
            double o4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
            crossings += o1 * o2 < 0 && o3 * o4 < 0;
        }
    }
    SW_CHECK_MSG(crossings == 0, "%zu crossings in %zu points", crossings, n);
    SW_CHECK_MSG(corner == 1, "the corner where the sides cross: %zu", corner);
    sw_seam_polylines_free(&pl);
    sw_model_free(&m);
}

/* A triangle whose third side ends a hair across the first one's start, a
 * straight trim 6e-10 long closing the gap (the Fly Gemini DIN mount's
 * corner face): the first and third sides cross at the start; the sliver
 * to cut is the hair, not the triangle. Flattened, its three corners
 * stay (it was cut to a point, and its three neighbours' edges were free). */
static void test_a_hair_at_a_triangle_corner_is_cut_off(void)
{
    const double pts[4][2] = {{1.0, 1.5}, {0.5, 0.5}, {1.5, 0.5}, {1.0 - 4e-10, 1.5 + 4e-10}};
    sw_model m;
    sw_seam_polylines pl;
    flatten_polygon(pts, 4, &m, &pl);
    size_t n = pl.loop_start[1] - pl.loop_start[0];
    int found[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            found[k] |= fabs(pl.uv[2 * i] - pts[k][0]) < 1e-6 && fabs(pl.uv[2 * i + 1] - pts[k][1]) < 1e-6;
    SW_CHECK_MSG(found[0] && found[1] && found[2], "corners kept: %d %d %d of %zu points", found[0],
                 found[1], found[2], n);
    sw_seam_polylines_free(&pl);
    sw_model_free(&m);
}

/* ---- loops after loops -------------------------------------------------- */

/* Two surfaces whose loops meet in (u, v): the first ends at (0, 0), where
 * the second starts. The second keeps its start, and the first its last
 * segment's edge: a point was taken for the same point twice across the
 * two loops, the second lost its start and the first took its edge (a
 * SO-100 base's two coplanar faces came out unsewn along their edge). */
static void test_a_loop_starting_where_the_last_ended_keeps_its_start(void)
{
    static shape_plane plane;
    shape_plane_init(&plane, 1, 1, 1, 2, 2);
    static const double square[2][4][2] = {{{1, 0}, {1, 1}, {0, 1}, {0, 0}},
                                           {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}};
    static double knots[4] = {0, 0, 1, 1}, ctrl[2][4][8];
    sw_nurbs_curve curves[2][4];
    uint32_t edges[2][4] = {{11, 12, 13, 14}, {21, 22, 23, 24}};
    sw_model m;
    sw_model_init(&m);
    sw_error err;
    for (int l = 0; l < 2; l++) {
        for (int k = 0; k < 4; k++) {
            const double *a = square[l][k], *b = square[l][(k + 1) % 4];
            double c[8] = {a[0], a[1], 0, 1, b[0], b[1], 0, 1};
            memcpy(ctrl[l][k], c, sizeof c);
            curves[l][k] = (sw_nurbs_curve){1, 2, knots, ctrl[l][k]};
        }
        sw_model_loop_input loop = {curves[l], NULL, 4, 1, NULL, edges[l]};
        SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, &loop, 1, &err) == SW_OK);
    }
    sw_seam_polylines pl;
    SW_CHECK_MSG(sw_seam_flatten_model(&m, 1e-5, &pl, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pl.loop_count == 2 && pl.edge);
    for (size_t l = 0; l < pl.loop_count && l < 2 && pl.edge; l++) {
        size_t first = pl.loop_start[l], n = pl.loop_start[l + 1] - first;
        SW_CHECK_MSG(n == 4, "loop %zu: %zu vertices", l, n);
        for (size_t k = 0; k < n && k < 4; k++) {
            SW_CHECK_MSG(pl.uv[2 * (first + k)] == square[l][k][0] &&
                             pl.uv[2 * (first + k) + 1] == square[l][k][1],
                         "loop %zu vertex %zu at (%g, %g)", l, k, pl.uv[2 * (first + k)],
                         pl.uv[2 * (first + k) + 1]);
            SW_CHECK_MSG(pl.edge[first + k] == edges[l][k], "loop %zu segment %zu: edge %u",
                         l, k, pl.edge[first + k]);
        }
    }
    sw_seam_polylines_free(&pl);
    sw_model_free(&m);
}

int main(void)
{
    SW_RUN(test_trimmed_bump_polylines_within_tolerance);
    SW_RUN(test_a_fold_at_a_corner_is_cut_off);
    SW_RUN(test_a_hair_at_a_triangle_corner_is_cut_off);
    SW_RUN(test_a_loop_starting_where_the_last_ended_keeps_its_start);
    return sw_test_finish();
}
