/* SPDX-License-Identifier: MIT */
/* sw_trim: polylines within their tolerance of exact rational circles and
 * random B-splines, the even-odd rule, conservative boxes and masks against
 * analytic shapes, and trimmed areas against closed forms and a fine-grid
 * reference. */
#include <string.h>

#include "model_shapes.h"
#include "sw_test.h"
#include "sw_model_trims.h"
#include "sw_trim.h"

/* Distance from p to the polyline of n points (closed: with the edge back
 * from the last point to the first). */
static double distance_to_polyline(const double *pts, size_t n, int closed, const double p[2])
{
    double best = INFINITY;
    for (size_t k = 0; k + (closed ? 0 : 1) < n; k++) {
        const double *a = pts + 2 * k, *b = pts + 2 * ((k + 1) % n);
        double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
        double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        best = fmin(best, hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
    }
    return best;
}

/* The unit square with a circular hole of radius r at (0.5, 0.5). */
typedef struct holed_square {
    shape_rect rect;
    shape_circle hole;
    sw_model_loop_input loops[2];
} holed_square;

static void holed_square_init(holed_square *h, double r, int hole_clockwise)
{
    shape_rect_init(&h->rect, 0, 1, 0, 1);
    shape_circle_init(&h->hole, 0.5, 0.5, r, hole_clockwise);
    h->loops[0] = (sw_model_loop_input){.curves = h->rect.curves, .curve_count = 4, .outer = 1};
    h->loops[1] = (sw_model_loop_input){.curves = &h->hole.curve, .curve_count = 1};
}

/* Every sampled point of a circle lies within tolerance of its polyline,
 * every vertex lies on the circle, and the polyline is not needlessly
 * dense (a chord of sagitta tol spans 2 sqrt(2 r tol)). */
static void test_circle_polyline_within_tolerance(void)
{
    const double tols[3] = {1e-2, 1e-4, 1e-7};
    for (int k = 0; k < 3; k++) {
        shape_circle c;
        shape_circle_init(&c, 0.3, -0.2, 0.7, k == 1);
        sw_model_loop_input loop = {.curves = &c.curve, .curve_count = 1, .outer = 1};
        sw_trim_polyline poly;
        sw_error err = {0};
        SW_CHECK(sw_trim_polyline_build(&loop, 1, tols[k], 0, &poly, &err) == SW_OK);
        size_t n = poly.loop_start[1];
        double worst_vertex = 0, worst = 0;
        for (size_t i = 0; i < n; i++)
            worst_vertex = fmax(worst_vertex, fabs(hypot(poly.points[2 * i] - 0.3,
                                                         poly.points[2 * i + 1] + 0.2) - 0.7));
        for (int s = 0; s < 4000; s++) {
            sw_vec3 q = sw_nurbs_curve_point(&c.curve, sw_test_random());
            double p[2] = {q.x, q.y};
            worst = fmax(worst, distance_to_polyline(poly.points, n, 1, p));
        }
        double ideal = 2 * SW_PI * 0.7 / (2 * sqrt(2 * 0.7 * tols[k]));
        SW_CHECK_MSG(worst <= tols[k], "tol %g: a curve point is %g from the polyline", tols[k],
                     worst);
        SW_CHECK(worst_vertex < 1e-12);
        SW_CHECK_MSG((double)n < 4 * ideal + 8, "tol %g: %zu vertices, ideal %g", tols[k], n,
                     ideal);
        sw_trim_polyline_free(&poly);
    }
}

/* The same for random cubic B-splines with 6 spans and random weights. */
static void test_random_spline_polyline_within_tolerance(void)
{
    for (int trial = 0; trial < 20; trial++) {
        double knots[13] = {0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 6, 6, 6}, ctrl[9 * 4];
        for (int i = 0; i < 9; i++) {
            ctrl[4 * i] = sw_test_random(), ctrl[4 * i + 1] = sw_test_random();
            ctrl[4 * i + 2] = 0, ctrl[4 * i + 3] = 0.3 + 2 * sw_test_random();
        }
        sw_nurbs_curve curve = {3, 9, knots, ctrl};
        double tol = 1e-3 * (1 + trial), pts[2 * 4096];
        size_t count = 0;
        sw_error err = {0};
        SW_CHECK(sw_trim_flatten_curve(&curve, tol, pts, 4096, &count, &err) == SW_OK);
        SW_CHECK(count > 1 && count <= 4096);
        double worst = 0;
        for (int s = 0; s < 5000; s++) {
            sw_vec3 q = sw_nurbs_curve_point(&curve, 6 * sw_test_random());
            double p[2] = {q.x, q.y};
            worst = fmax(worst, distance_to_polyline(pts, count, 0, p));
        }
        SW_CHECK_MSG(worst <= tol, "trial %d: %g > %g", trial, worst, tol);
        SW_CHECK(pts[0] == ctrl[0] && pts[1] == ctrl[1]);
        SW_CHECK(fabs(pts[2 * count - 2] - ctrl[32]) + fabs(pts[2 * count - 1] - ctrl[33]) < 1e-14);
    }
}

/* Counting first (NULL output), a short buffer, an impossible tolerance. */
static void test_flatten_reports_sizes_and_limits(void)
{
    shape_circle c;
    shape_circle_init(&c, 0, 0, 1, 0);
    size_t need = 0, got = 0;
    sw_error err = {0};
    SW_CHECK(sw_trim_flatten_curve(&c.curve, 1e-3, NULL, 0, &need, &err) == SW_OK);
    SW_CHECK(need > 8);
    double pts[2 * 8];
    SW_CHECK(sw_trim_flatten_curve(&c.curve, 1e-3, pts, 8, &got, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK(got == need);
    SW_CHECK(sw_trim_flatten_curve(&c.curve, 1e-300, NULL, 0, &got, &err) == SW_ERR_RANGE);
    SW_CHECK(strstr(err.message, "precision") != NULL);
    SW_CHECK(sw_trim_flatten_curve(&c.curve, 0, NULL, 0, &got, &err) == SW_ERR_ARG);
}

/* Loops that do not close, loops without curves and bad curves are named. */
static void test_polyline_build_rejects_bad_loops(void)
{
    shape_rect r;
    shape_rect_init(&r, 0, 1, 0, 1);
    sw_model_loop_input open = {.curves = r.curves, .curve_count = 3, .outer = 1};
    sw_trim_polyline poly;
    sw_error err = {0};
    SW_CHECK(sw_trim_polyline_build(&open, 1, 1e-3, 1e-6, &poly, &err) == SW_ERR_FORMAT);
    SW_CHECK(strstr(err.message, "not closed") != NULL);
    SW_CHECK(poly.points == NULL && poly.loop_count == 0);
    SW_CHECK(sw_trim_polyline_build(&open, 1, 1e-3, -1, &poly, &err) == SW_OK);
    sw_trim_polyline_free(&poly);
    sw_model_loop_input empty = {.curves = r.curves, .curve_count = 0};
    SW_CHECK(sw_trim_polyline_build(&empty, 1, 1e-3, 0, &poly, &err) == SW_ERR_FORMAT);
    r.ctrl[2][3] = -1; /* a weight */
    sw_model_loop_input bad = {.curves = r.curves, .curve_count = 4, .outer = 1};
    SW_CHECK(sw_trim_polyline_build(&bad, 1, 1e-3, 0, &poly, &err) == SW_ERR_RANGE);
    SW_CHECK(strstr(err.message, "trim loop 0, curve 2") != NULL);
}

/* Even-odd: inside the square and outside the hole, whatever the loops'
 * orientations. */
static void test_point_inside_even_odd(void)
{
    for (int cw = 0; cw < 2; cw++) {
        holed_square h;
        holed_square_init(&h, 0.25, cw);
        sw_trim_polyline poly;
        sw_error err = {0};
        SW_CHECK(sw_trim_polyline_build(h.loops, 2, 1e-6, 0, &poly, &err) == SW_OK);
        int wrong = 0;
        for (int s = 0; s < 20000; s++) {
            double u = 1.4 * sw_test_random() - 0.2, v = 1.4 * sw_test_random() - 0.2;
            double rr = hypot(u - 0.5, v - 0.5);
            if (fabs(rr - 0.25) < 1e-5 || fabs(u) < 1e-5 || fabs(v) < 1e-5 ||
                fabs(u - 1) < 1e-5 || fabs(v - 1) < 1e-5)
                continue;
            int truth = u > 0 && u < 1 && v > 0 && v < 1 && rr > 0.25;
            wrong += sw_trim_point_inside(&poly, u, v) != truth;
        }
        SW_CHECK_MSG(wrong == 0, "%d points misclassified", wrong);
        sw_trim_polyline_free(&poly);
    }
}

/* Boxes: any box holding a point of the face says so; boxes wholly in the
 * hole or outside the square say no. */
static void test_box_touches_is_conservative(void)
{
    holed_square h;
    holed_square_init(&h, 0.25, 1);
    sw_trim_polyline poly;
    sw_error err = {0};
    SW_CHECK(sw_trim_polyline_build(h.loops, 2, 1e-4, 0, &poly, &err) == SW_OK);
    int missed = 0;
    for (int trial = 0; trial < 3000; trial++) {
        double u = 1.2 * sw_test_random() - 0.1, v = 1.2 * sw_test_random() - 0.1;
        double size = 0.002 + 0.05 * sw_test_random();
        double box[4] = {u, u + size, v, v + size};
        int any = 0;
        for (int s = 0; s <= 8 && !any; s++)
            for (int t = 0; t <= 8 && !any; t++) {
                double pu = u + size * s / 8, pv = v + size * t / 8;
                any = pu >= 0 && pu <= 1 && pv >= 0 && pv <= 1 &&
                      hypot(pu - 0.5, pv - 0.5) >= 0.25;
            }
        missed += any && !sw_trim_box_touches(&poly, box);
    }
    SW_CHECK_MSG(missed == 0, "%d boxes with face points said untouched", missed);
    const double in_hole[4] = {0.45, 0.55, 0.45, 0.55}, outside[4] = {1.1, 1.3, 0.2, 0.4};
    SW_CHECK(!sw_trim_box_touches(&poly, in_hole));
    SW_CHECK(!sw_trim_box_touches(&poly, outside));
    sw_trim_polyline_free(&poly);
}

/* Every face point sampled in the domain falls in a set cell; cells wholly
 * in the hole are clear; a domain inside the face is reported as such. */
static void test_mask_is_conservative_and_tight(void)
{
    holed_square h;
    holed_square_init(&h, 0.3, 0);
    sw_trim_polyline poly;
    sw_error err = {0};
    SW_CHECK(sw_trim_polyline_build(h.loops, 2, 1e-5, 0, &poly, &err) == SW_OK);
    const double domain[4] = {0.1, 0.6, 0.2, 0.9};
    uint32_t rows[32];
    SW_CHECK(sw_trim_mask(&poly, domain, rows) == SW_TRIM_PARTIAL);
    int missed = 0, clear_in_hole = 0, cells_in_hole = 0;
    for (int s = 0; s < 50000; s++) {
        double x = sw_test_random(), y = sw_test_random();
        double u = domain[0] + x * (domain[1] - domain[0]), v = domain[2] + y * (domain[3] - domain[2]);
        int i = (int)(x * 32), j = (int)(y * 32);
        if (hypot(u - 0.5, v - 0.5) > 0.3)
            missed += !(rows[j] >> i & 1u);
    }
    for (int j = 0; j < 32; j++)
        for (int i = 0; i < 32; i++) {
            double w = (domain[1] - domain[0]) / 32, hh = (domain[3] - domain[2]) / 32;
            double cu = domain[0] + (i + 0.5) * w, cv = domain[2] + (j + 0.5) * hh;
            if (hypot(cu - 0.5, cv - 0.5) + hypot(w, hh) < 0.3) {
                cells_in_hole++;
                clear_in_hole += !(rows[j] >> i & 1u);
            }
        }
    SW_CHECK_MSG(missed == 0, "%d face points in clear cells", missed);
    SW_CHECK(cells_in_hole > 100 && clear_in_hole == cells_in_hole);
    const double inside[4] = {0.02, 0.15, 0.02, 0.98}, hole[4] = {0.45, 0.55, 0.45, 0.55};
    SW_CHECK(sw_trim_mask(&poly, inside, rows) == SW_TRIM_INSIDE);
    SW_CHECK(rows[0] == 0xFFFFFFFFu && rows[31] == 0xFFFFFFFFu);
    SW_CHECK(sw_trim_mask(&poly, hole, rows) == SW_TRIM_OUTSIDE);
    SW_CHECK(rows[7] == 0);
    sw_trim_polyline_free(&poly);
}

/* Unit square with a hole of radius r: area 1 - pi r^2, on a plane split
 * into 3 x 2 and 3 x 4 bicubic patches (the hole crosses patch boundaries,
 * some vertices lie on them) and through the model's convenience call. */
static void test_area_square_with_circular_hole(void)
{
    for (int cw = 0; cw < 2; cw++) {
        holed_square h;
        holed_square_init(&h, 0.3, cw);
        shape_plane plane;
        shape_plane_init(&plane, 3, 3, 2 + 2 * cw, 1, 1); /* 2 x 4: vertices on knot lines */
        sw_trim_polyline poly;
        sw_error err = {0};
        SW_CHECK(sw_trim_polyline_build(h.loops, 2, 1e-6, 0, &poly, &err) == SW_OK);
        double area = 0, exact = 1 - SW_PI * 0.09;
        SW_CHECK(sw_trim_area(&plane.surface, &poly, 1e-9, &area, &err) == SW_OK);
        SW_CHECK_MSG(fabs(area - exact) <= 1e-5 * exact, "area %.12f, exact %.12f, rel %.3g",
                     area, exact, fabs(area - exact) / exact);
        printf("  holed square, polyline tol 1e-6 (%zu vertices): relative error %.2e\n",
               poly.loop_start[2], fabs(area - exact) / exact);
        sw_trim_polyline_free(&poly);
        sw_model model;
        sw_model_init(&model);
        SW_CHECK(sw_model_add_surface(&model, &plane.surface, cw, h.loops, 2, &err) == SW_OK);
        SW_CHECK(sw_trim_model_surface_area(&model, 0, 1e-5, &area, &err) == SW_OK);
        SW_CHECK_MSG(fabs(area - exact) <= 1e-4 * exact, "model area %.12f, rel %.3g", area,
                     fabs(area - exact) / exact);
        printf("  holed square through the model at rel_tol 1e-5: relative error %.2e\n",
               fabs(area - exact) / exact);
        sw_model_free(&model);
    }
}

/* A quarter cylinder of radius R and height H (rational quadratic in u):
 * untrimmed pi R H / 2; trimmed to u in [0, 0.5] (by symmetry half the angle)
 * pi R H / 4. */
static void test_area_rational_cylinder_quarter(void)
{
    const double R = 2.5, H = 1.5, w = sqrt(0.5);
    double ku[6] = {0, 0, 0, 1, 1, 1}, kv[4] = {0, 0, 1, 1};
    double ctrl[6 * 4] = {R, 0, 0, 1, R, R, 0, w, 0, R, 0, 1,
                          R, 0, H, 1, R, R, H, w, 0, R, H, 1};
    sw_nurbs_surface s = {2, 1, 3, 2, ku, kv, ctrl};
    double area = 0;
    sw_error err = {0};
    SW_CHECK(sw_trim_area(&s, NULL, 1e-10, &area, &err) == SW_OK);
    SW_CHECK_NEAR(area, SW_PI * R * H / 2, 1e-8 * area);
    shape_rect r;
    shape_rect_init(&r, 0, 0.5, 0, 1);
    sw_model_loop_input loop = {.curves = r.curves, .curve_count = 4, .outer = 1};
    sw_trim_polyline poly;
    SW_CHECK(sw_trim_polyline_build(&loop, 1, 1e-6, 0, &poly, &err) == SW_OK);
    SW_CHECK(sw_trim_area(&s, &poly, 1e-10, &area, &err) == SW_OK);
    SW_CHECK_NEAR(area, SW_PI * R * H / 4, 1e-8 * area);
    printf("  trimmed quarter cylinder: relative error %.2e\n",
           fabs(area - SW_PI * R * H / 4) / area);
    sw_trim_polyline_free(&poly);
}

/* Midpoint rule at n x n with Richardson extrapolation from n/2: error
 * O(n^-4), about 1e-9 relative here. */
static double grid_area(const sw_bezier_patch *p, int n)
{
    double m[2] = {0, 0};
    for (int level = 0; level < 2; level++) {
        int k = level ? n : n / 2;
        for (int j = 0; j < k; j++)
            for (int i = 0; i < k; i++) {
                sw_surface_point q;
                sw_bezier_eval(p, (i + 0.5) / k, (j + 0.5) / k, SW_EVAL_FIRST, &q);
                m[level] += sw_v3_length(sw_v3_cross(q.du, q.dv)) / ((double)k * k);
            }
    }
    return (4 * m[1] - m[0]) / 3;
}

/* Untrimmed random bicubic patches (rational and not) against the grid. */
static void test_area_random_bicubic_matches_grid(void)
{
    for (int trial = 0; trial < 4; trial++) {
        double ctrl[16 * 4], knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        for (int k = 0; k < 16; k++) {
            ctrl[4 * k] = (k % 4) + 0.4 * sw_test_random();
            ctrl[4 * k + 1] = (k / 4) + 0.4 * sw_test_random();
            ctrl[4 * k + 2] = 1.5 * sw_test_random();
            ctrl[4 * k + 3] = trial & 1 ? 0.5 + sw_test_random() : 1.0;
        }
        sw_nurbs_surface s = {3, 3, 4, 4, knots, knots, ctrl};
        sw_bezier_patch p = {3, 3, 1, ctrl};
        double area = 0, ref = grid_area(&p, 400);
        sw_error err = {0};
        SW_CHECK(sw_trim_area(&s, NULL, 1e-10, &area, &err) == SW_OK);
        SW_CHECK_MSG(fabs(area - ref) <= 1e-7 * ref, "trial %d: %.12f vs grid %.12f", trial,
                     area, ref);
        printf("  random bicubic %d: relative difference from the grid %.2e\n", trial,
               fabs(area - ref) / ref);
    }
}

/* An outer loop equal to the domain's boundary trims nothing. */
static void test_area_boundary_loop_equals_untrimmed(void)
{
    shape_plane plane;
    shape_plane_init(&plane, 2, 4, 2, 3, 2);
    plane.ctrl[4 * 7 + 2] = 0.8;     /* bend it so the area element varies */
    plane.ctrl[4 * 12 + 2] = -0.5;
    shape_rect r;
    shape_rect_init(&r, 0, 3, 0, 2);
    sw_model_loop_input loop = {.curves = r.curves, .curve_count = 4, .outer = 1};
    sw_trim_polyline poly;
    sw_error err = {0};
    SW_CHECK(sw_trim_polyline_build(&loop, 1, 1e-6, 0, &poly, &err) == SW_OK);
    double trimmed = 0, whole = 0;
    SW_CHECK(sw_trim_area(&plane.surface, &poly, 1e-10, &trimmed, &err) == SW_OK);
    SW_CHECK(sw_trim_area(&plane.surface, NULL, 1e-10, &whole, &err) == SW_OK);
    SW_CHECK(whole > 6.0);
    SW_CHECK_NEAR(trimmed, whole, 1e-9 * whole);
    sw_trim_polyline_free(&poly);
}

/* Square holes whose edges lie on knot lines (patch edges), in both
 * orientations, and one touching the domain's border: exact areas. */
static void test_area_trims_on_knot_lines(void)
{
    const double holes[3][4] = {{0.25, 0.75, 0.25, 0.75}, {0.5, 1.0, 0.0, 0.5}, {0, 0.25, 0.5, 1}};
    for (int k = 0; k < 3; k++) {
        shape_plane plane;
        shape_plane_init(&plane, 1, 4, 4, 1, 1);
        shape_rect outer, hole;
        shape_rect_init(&outer, 0, 1, 0, 1);
        shape_rect_init(&hole, holes[k][0], holes[k][1], holes[k][2], holes[k][3]);
        sw_model_loop_input loops[2] = {{.curves = outer.curves, .curve_count = 4, .outer = 1},
                                        {.curves = hole.curves, .curve_count = 4}};
        sw_trim_polyline poly;
        sw_error err = {0};
        SW_CHECK(sw_trim_polyline_build(loops, 2, 1e-6, 0, &poly, &err) == SW_OK);
        double area = 0, exact = 1 - (holes[k][1] - holes[k][0]) * (holes[k][3] - holes[k][2]);
        SW_CHECK(sw_trim_area(&plane.surface, &poly, 1e-10, &area, &err) == SW_OK);
        SW_CHECK_NEAR(area, exact, 1e-12);
        sw_trim_polyline_free(&poly);
    }
}

/* A loop along the domain's border whose right-side vertices sit an ulp
 * either side of the domain's edge, on a domain not starting at 0 (the
 * hammer's faces: their vertices round onto the patch's right side in the
 * patch's local coordinates). The side must count once: the whole area. */
static void test_area_trim_an_ulp_off_the_right_side(void)
{
    const double u0 = -6.5890918110000003, u1 = 1.421085e-14, v0 = 0, v1 = 2.82743;
    double ku[4] = {u0, u0, u1, u1}, kv[4] = {v0, v0, v1, v1};
    double ctrl[16] = {u0, v0, 0, 1, u1, v0, 0, 1, u0, v1, 0, 1, u1, v1, 0, 1};
    sw_nurbs_surface plane = {1, 1, 2, 2, ku, kv, ctrl};
    enum { SIDE = 12, N = SIDE + 4 };
    double pts[N * 4], knots[N + 2];
    int n = 0;
    const double fixed[3][2] = {{u0, v0}, {u1, v0}, {u1, v1}};
    for (int k = 0; k < 2; k++)
        pts[4 * n] = fixed[k][0], pts[4 * n + 1] = fixed[k][1], n++;
    for (int k = 1; k < SIDE; k++) {
        double off = k % 3 == 0 ? u1 : nextafter(u1, k % 3 == 1 ? INFINITY : -INFINITY);
        pts[4 * n] = off, pts[4 * n + 1] = v0 + (v1 - v0) * k / SIDE, n++;
    }
    pts[4 * n] = fixed[2][0], pts[4 * n + 1] = fixed[2][1], n++;
    pts[4 * n] = u0, pts[4 * n + 1] = v1, n++;
    pts[4 * n] = u0, pts[4 * n + 1] = v0, n++;
    for (int k = 0; k < n; k++)
        pts[4 * k + 2] = 0, pts[4 * k + 3] = 1;
    knots[0] = 0;
    for (int k = 0; k < n; k++)
        knots[k + 1] = k;
    knots[n + 1] = n - 1;
    sw_nurbs_curve curve = {1, n, knots, pts};
    sw_model_loop_input loop = {.curves = &curve, .curve_count = 1, .outer = 1};
    sw_trim_polyline poly;
    sw_error err = {0};
    SW_CHECK_MSG(sw_trim_polyline_build(&loop, 1, 1e-9, 0, &poly, &err) == SW_OK, "%s",
                 err.message);
    double area = 0, exact = (u1 - u0) * (v1 - v0);
    SW_CHECK(sw_trim_area(&plane, &poly, 1e-10, &area, &err) == SW_OK);
    SW_CHECK_MSG(fabs(area - exact) <= 1e-9 * exact, "area %.12g, exact %.12g", area, exact);
    sw_trim_polyline_free(&poly);
}

int main(void)
{
    SW_RUN(test_circle_polyline_within_tolerance);
    SW_RUN(test_random_spline_polyline_within_tolerance);
    SW_RUN(test_flatten_reports_sizes_and_limits);
    SW_RUN(test_polyline_build_rejects_bad_loops);
    SW_RUN(test_point_inside_even_odd);
    SW_RUN(test_box_touches_is_conservative);
    SW_RUN(test_mask_is_conservative_and_tight);
    SW_RUN(test_area_square_with_circular_hole);
    SW_RUN(test_area_rational_cylinder_quarter);
    SW_RUN(test_area_random_bicubic_matches_grid);
    SW_RUN(test_area_boundary_loop_equals_untrimmed);
    SW_RUN(test_area_trims_on_knot_lines);
    SW_RUN(test_area_trim_an_ulp_off_the_right_side);
    return sw_test_finish();
}
