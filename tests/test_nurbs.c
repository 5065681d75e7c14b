/* SPDX-License-Identifier: MIT */
/* sw_nurbs: the Bezier pieces from knot insertion reproduce the B-spline
 * (against a Cox-de Boor basis evaluation written here in long double), piece
 * counts and parameter ranges, and check() naming each kind of bad input. */
#include <string.h>

#include "sw_nurbs.h"
#include "sw_test.h"

enum { MAXK = 64, MAXC = 40 };

/* Cox-de Boor recursion for N_{i,p}(t), half-open spans; t at the end of the
 * range is moved into the last non-empty span. */
static long double basis(const double *knots, int i, int p, long double t)
{
    if (p == 0)
        return knots[i] <= t && t < knots[i + 1] ? 1.0L : 0.0L;
    long double r = 0;
    if (knots[i + p] > knots[i])
        r += (t - knots[i]) / (knots[i + p] - knots[i]) * basis(knots, i, p - 1, t);
    if (knots[i + p + 1] > knots[i + 1])
        r += (knots[i + p + 1] - t) / (knots[i + p + 1] - knots[i + 1]) *
             basis(knots, i + 1, p - 1, t);
    return r;
}

static long double inside(const double *knots, int p, int count, long double t)
{
    long double end = knots[count];
    return t >= end ? nextafterl(end, knots[p]) : t;
}

static sw_vec3 reference_surface(const sw_nurbs_surface *s, double u, double v)
{
    long double uu = inside(s->knots_u, s->degree_u, s->count_u, u);
    long double vv = inside(s->knots_v, s->degree_v, s->count_v, v);
    long double acc[4] = {0, 0, 0, 0};
    for (int j = 0; j < s->count_v; j++) {
        long double bv = basis(s->knots_v, j, s->degree_v, vv);
        for (int i = 0; bv != 0 && i < s->count_u; i++) {
            long double b = bv * basis(s->knots_u, i, s->degree_u, uu);
            const double *c = s->ctrl + (j * s->count_u + i) * 4;
            for (int k = 0; k < 3; k++)
                acc[k] += b * c[3] * c[k];
            acc[3] += b * c[3];
        }
    }
    return sw_v3((double)(acc[0] / acc[3]), (double)(acc[1] / acc[3]), (double)(acc[2] / acc[3]));
}

/* Clamped knots on [0, 1] (or [lo, hi]) with `spans` random interior values,
 * each repeated 1..p times; returns the control point count. */
static int random_knots(int p, int spans, double lo, double hi, double *knots)
{
    int n = 0;
    for (int i = 0; i <= p; i++)
        knots[n++] = lo;
    double x = lo;
    for (int s = 1; s < spans; s++) {
        x += (hi - lo) / spans * (0.5 + sw_test_random());
        if (x >= hi)
            break;
        int mult = 1 + (int)(sw_test_random() * p);
        for (int m = 0; m < mult; m++)
            knots[n++] = x;
    }
    for (int i = 0; i <= p; i++)
        knots[n++] = hi;
    return n - p - 1;
}

static void random_ctrl(double *ctrl, int count)
{
    for (int i = 0; i < count; i++) {
        for (int k = 0; k < 3; k++)
            ctrl[i * 4 + k] = 10 * sw_test_random() - 5;
        ctrl[i * 4 + 3] = 0.3 + 2.7 * sw_test_random();
    }
}

static double ctrl_size(const double *ctrl, int count)
{
    sw_box b = sw_box_empty();
    for (int i = 0; i < count; i++)
        sw_box_add_point(&b, sw_v3(ctrl[i * 4], ctrl[i * 4 + 1], ctrl[i * 4 + 2]));
    return sw_box_diagonal(&b);
}

static double ku_buf[MAXK], kv_buf[MAXK], ctrl_buf[MAXC * MAXC * 4];
static double bez_buf[1 << 18], par_buf[512];

/* 1,000 random points per surface: piece (a, b) at the local parameters
 * equals the original within 1e-12 of the control hull's diagonal; so does
 * sw_nurbs_surface_point. */
static void test_surface_pieces_reproduce_surface(void)
{
    double worst_piece = 0, worst_point = 0;
    for (int trial = 0; trial < 12; trial++) {
        int p = 1 + trial % 5, q = 1 + (trial * 3) % 4;
        int cu = random_knots(p, 2 + trial % 4, -1, 2, ku_buf);
        int cv = random_knots(q, 1 + trial % 5, 3, 3.5, kv_buf);
        random_ctrl(ctrl_buf, cu * cv);
        sw_nurbs_surface s = {p, q, cu, cv, ku_buf, kv_buf, ctrl_buf};
        sw_error err = {0};
        SW_CHECK(sw_nurbs_surface_check(&s, &err) == SW_OK);
        sw_nurbs_bezier_sizes z = sw_nurbs_surface_bezier_sizes(&s);
        SW_CHECK(z.ctrl_doubles <= sizeof bez_buf / sizeof bez_buf[0]);
        SW_CHECK(sw_nurbs_surface_to_bezier(&s, bez_buf, par_buf, &err) == SW_OK);
        double size = ctrl_size(ctrl_buf, cu * cv);
        for (int k = 0; k < 1000; k++) {
            double u = k == 0 ? -1 : k == 1 ? 2 : -1 + 3 * sw_test_random();
            double v = k == 0 ? 3 : k == 1 ? 3.5 : 3 + 0.5 * sw_test_random();
            int a = 0, b = 0;
            while (a + 1 < z.pieces_u && u >= par_buf[2 * a + 1])
                a++;
            while (b + 1 < z.pieces_v && v >= par_buf[2 * (z.pieces_u + b) + 1])
                b++;
            const double *ur = par_buf + 2 * a, *vr = par_buf + 2 * (z.pieces_u + b);
            sw_bezier_patch bp = {p, q, 1,
                                  bez_buf + (size_t)(b * z.pieces_u + a) * (p + 1) * (q + 1) * 4};
            sw_surface_point sp;
            sw_bezier_eval(&bp, (u - ur[0]) / (ur[1] - ur[0]), (v - vr[0]) / (vr[1] - vr[0]),
                           SW_EVAL_POINT, &sp);
            sw_vec3 ref = reference_surface(&s, u, v);
            worst_piece = fmax(worst_piece, sw_v3_length(sw_v3_sub(sp.p, ref)) / size);
            sw_vec3 db = sw_nurbs_surface_point(&s, u, v);
            worst_point = fmax(worst_point, sw_v3_length(sw_v3_sub(db, ref)) / size);
        }
    }
    SW_CHECK_MSG(worst_piece <= 1e-12, "pieces: worst relative error %g", worst_piece);
    SW_CHECK_MSG(worst_point <= 1e-12, "de Boor: worst relative error %g", worst_point);
}

static void test_curve_pieces_reproduce_curve(void)
{
    double worst = 0;
    for (int trial = 0; trial < 20; trial++) {
        int p = 1 + trial % 7;
        int count = random_knots(p, 1 + trial % 6, 0, 1, ku_buf);
        random_ctrl(ctrl_buf, count);
        sw_nurbs_curve c = {p, count, ku_buf, ctrl_buf};
        sw_nurbs_bezier_sizes z = sw_nurbs_curve_bezier_sizes(&c);
        SW_CHECK(z.pieces_v == 0 && z.param_doubles == 2 * (size_t)z.pieces_u);
        SW_CHECK(sw_nurbs_curve_to_bezier(&c, bez_buf, par_buf, NULL) == SW_OK);
        double size = ctrl_size(ctrl_buf, count);
        for (int k = 0; k < 1000; k++) {
            double t = sw_test_random();
            int a = 0;
            while (a + 1 < z.pieces_u && t >= par_buf[2 * a + 1])
                a++;
            /* A curve piece is a patch of degree p x 1 with equal rows. */
            double patch[2 * 16 * 4];
            memcpy(patch, bez_buf + (size_t)a * (p + 1) * 4, sizeof(double) * (p + 1) * 4);
            memcpy(patch + (p + 1) * 4, patch, sizeof(double) * (p + 1) * 4);
            sw_bezier_patch bp = {p, 1, 1, patch};
            sw_surface_point sp;
            sw_bezier_eval(&bp, (t - par_buf[2 * a]) / (par_buf[2 * a + 1] - par_buf[2 * a]), 0,
                           SW_EVAL_POINT, &sp);
            sw_nurbs_surface as_surface = {p, 1, count, 2, ku_buf, (double[]){0, 0, 1, 1}, NULL};
            double rows[2 * MAXC * 4];
            memcpy(rows, ctrl_buf, sizeof(double) * count * 4);
            memcpy(rows + count * 4, ctrl_buf, sizeof(double) * count * 4);
            as_surface.ctrl = rows;
            sw_vec3 ref = reference_surface(&as_surface, t, 0);
            worst = fmax(worst, sw_v3_length(sw_v3_sub(sp.p, ref)) / size);
            worst = fmax(worst, sw_v3_length(sw_v3_sub(sw_nurbs_curve_point(&c, t), ref)) / size);
        }
    }
    SW_CHECK_MSG(worst <= 1e-12, "worst relative error %g", worst);
}

/* Knots {0,0,0,1,2,2,3,3,3}, degree 2: spans [0,1], [1,2], [2,3] (the double
 * knot at 2 adds no span). A quarter circle as a check of the rational path. */
static void test_piece_counts_and_ranges(void)
{
    const double knots[] = {0, 0, 0, 1, 2, 2, 3, 3, 3};
    double ctrl[6 * 4];
    random_ctrl(ctrl, 6);
    sw_nurbs_curve c = {2, 6, knots, ctrl};
    SW_CHECK(sw_nurbs_span_count(2, 6, knots) == 3);
    sw_nurbs_bezier_sizes z = sw_nurbs_curve_bezier_sizes(&c);
    SW_CHECK(z.pieces_u == 3 && z.ctrl_doubles == 36 && z.param_doubles == 6);
    SW_CHECK(sw_nurbs_curve_to_bezier(&c, bez_buf, par_buf, NULL) == SW_OK);
    const double expect[] = {0, 1, 1, 2, 2, 3};
    for (int i = 0; i < 6; i++)
        SW_CHECK(par_buf[i] == expect[i]);
    /* At the double knot the curve interpolates a control point (index 3),
     * which must be the last point of piece 1 and the first of piece 2. */
    SW_CHECK_NEAR(bez_buf[(1 * 3 + 2) * 4], ctrl[3 * 4], 1e-13);
    SW_CHECK_NEAR(bez_buf[(2 * 3 + 0) * 4 + 1], ctrl[3 * 4 + 1], 1e-13);

    const double kv[] = {5, 5, 6, 7, 7};
    double sctrl[6 * 3 * 4];
    random_ctrl(sctrl, 18);
    sw_nurbs_surface s = {2, 1, 6, 3, knots, kv, sctrl};
    z = sw_nurbs_surface_bezier_sizes(&s);
    SW_CHECK(z.pieces_u == 3 && z.pieces_v == 2);
    SW_CHECK(z.ctrl_doubles == 3 * 2 * 3 * 2 * 4 && z.param_doubles == 10);
    SW_CHECK(sw_nurbs_surface_to_bezier(&s, bez_buf, par_buf, NULL) == SW_OK);
    const double sexpect[] = {0, 1, 1, 2, 2, 3, 5, 6, 6, 7};
    for (int i = 0; i < 10; i++)
        SW_CHECK(par_buf[i] == sexpect[i]);
}

static void test_quarter_circle_stays_on_circle(void)
{
    const double knots[] = {0, 0, 0, 1, 1, 1};
    const double h = sqrt(0.5);
    const double ctrl[] = {1, 0, 0, 1, 1, 1, 0, h, 0, 1, 0, 1};
    sw_nurbs_curve c = {2, 3, knots, ctrl};
    SW_CHECK(sw_nurbs_curve_to_bezier(&c, bez_buf, par_buf, NULL) == SW_OK);
    for (int i = 0; i < 12; i++)
        SW_CHECK_NEAR(bez_buf[i], ctrl[i], 1e-15);
    for (int k = 0; k <= 10; k++)
        SW_CHECK_NEAR(sw_v3_length(sw_nurbs_curve_point(&c, k / 10.0)), 1, 1e-15);
}

static void expect_rejected(const sw_nurbs_curve *c, sw_status status, const char *word)
{
    sw_error err = {0};
    SW_CHECK(sw_nurbs_curve_check(c, &err) == status);
    SW_CHECK_MSG(strstr(err.message, word) != NULL, "message '%s' lacks '%s'", err.message, word);
    SW_CHECK(sw_nurbs_curve_to_bezier(c, bez_buf, par_buf, NULL) == status);
}

static void test_check_rejects_bad_curves(void)
{
    double ctrl[6 * 4];
    random_ctrl(ctrl, 6);
    double k[8] = {0, 0, 0, 0.5, 0.7, 1, 1, 1};
    sw_nurbs_curve c = {2, 5, k, ctrl};
    SW_CHECK(sw_nurbs_curve_check(&c, NULL) == SW_OK);
    c.degree = 0;
    expect_rejected(&c, SW_ERR_ARG, "degree 0");
    c.degree = 16;
    expect_rejected(&c, SW_ERR_ARG, "degree 16");
    c.degree = 5;
    expect_rejected(&c, SW_ERR_ARG, "needs at least 6");
    c.degree = 2;
    k[3] = 0.8;
    expect_rejected(&c, SW_ERR_RANGE, "non-decreasing");
    k[3] = 0.5, k[0] = -0.1;
    expect_rejected(&c, SW_ERR_RANGE, "clamped");
    k[0] = 0, k[4] = NAN;
    expect_rejected(&c, SW_ERR_RANGE, "finite");
    k[4] = 0.5;
    const double k3[9] = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    sw_nurbs_curve m = {2, 6, k3, ctrl};
    expect_rejected(&m, SW_ERR_RANGE, "multiplicity");
    const double kz[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    sw_nurbs_curve e = {2, 5, kz, ctrl};
    expect_rejected(&e, SW_ERR_RANGE, "empty parameter range");
    ctrl[2 * 4 + 3] = 0;
    k[4] = 0.7;
    expect_rejected(&c, SW_ERR_RANGE, "weight 0");
    ctrl[2 * 4 + 3] = -1;
    expect_rejected(&c, SW_ERR_RANGE, "(2, 0) has weight -1");
    ctrl[2 * 4 + 3] = 1, ctrl[1] = INFINITY;
    expect_rejected(&c, SW_ERR_RANGE, "non-finite coordinate");
}

static void test_check_rejects_bad_surfaces(void)
{
    double ctrl[4 * 3 * 4];
    random_ctrl(ctrl, 12);
    const double ku[] = {0, 0, 0, 0.5, 1, 1, 1}, kv[] = {0, 0, 1, 2, 2};
    sw_nurbs_surface s = {2, 1, 4, 3, ku, kv, ctrl};
    sw_error err = {0};
    SW_CHECK(sw_nurbs_surface_check(&s, &err) == SW_OK);
    s.degree_v = 3;
    SW_CHECK(sw_nurbs_surface_check(&s, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(strstr(err.message, "surface v") != NULL, "%s", err.message);
    s.degree_v = 1;
    ctrl[(2 * 4 + 3) * 4 + 3] = NAN;
    SW_CHECK(sw_nurbs_surface_check(&s, &err) == SW_ERR_RANGE);
    SW_CHECK_MSG(strstr(err.message, "(3, 2)") != NULL, "%s", err.message);
    sw_nurbs_bezier_sizes z = sw_nurbs_surface_bezier_sizes(&s);
    SW_CHECK(z.pieces_u == 2 && z.pieces_v == 2);
}

int main(void)
{
    SW_RUN(test_surface_pieces_reproduce_surface);
    SW_RUN(test_curve_pieces_reproduce_curve);
    SW_RUN(test_piece_counts_and_ranges);
    SW_RUN(test_quarter_circle_stays_on_circle);
    SW_RUN(test_check_rejects_bad_curves);
    SW_RUN(test_check_rejects_bad_surfaces);
    return sw_test_finish();
}
