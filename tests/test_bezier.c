/* SPDX-License-Identifier: MIT */
/* sw_bezier: evaluation against a long-double de Casteljau written here,
 * derivatives against finite differences, normals, the collapsed-edge normal,
 * second-derivative bounds against dense sampling, the control box. */
#include <string.h>

#include "sw_bezier.h"
#include "sw_test.h"

enum { MAXN = SW_BEZIER_MAX_ORDER };

/* Control points uniform in [-1, 1]^3; weights uniform in [0.25, 4] if rational. */
static void random_patch(double *ctrl, int n, int m, int rational, sw_bezier_patch *out)
{
    for (int k = 0; k < (n + 1) * (m + 1); k++) {
        for (int c = 0; c < 3; c++)
            ctrl[k * 4 + c] = 2 * sw_test_random() - 1;
        ctrl[k * 4 + 3] = rational ? 0.25 + 3.75 * sw_test_random() : 1.0;
    }
    sw_bezier_patch p = {n, m, rational, ctrl};
    *out = p;
}

/* Reference: de Casteljau in long double on homogeneous points, rows first. */
static void reference_point(const sw_bezier_patch *p, long double u, long double v,
                            long double out[3])
{
    long double col[MAXN][4], row[MAXN][4];
    int n = p->degree_u, m = p->degree_v;
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const double *c = p->ctrl + (j * (n + 1) + i) * 4;
            long double w = p->rational ? c[3] : 1.0L;
            row[i][0] = c[0] * w, row[i][1] = c[1] * w, row[i][2] = c[2] * w, row[i][3] = w;
        }
        for (int r = n; r > 0; r--)
            for (int i = 0; i < r; i++)
                for (int k = 0; k < 4; k++)
                    row[i][k] = (1 - u) * row[i][k] + u * row[i + 1][k];
        memcpy(col[j], row[0], sizeof row[0]);
    }
    for (int r = m; r > 0; r--)
        for (int j = 0; j < r; j++)
            for (int k = 0; k < 4; k++)
                col[j][k] = (1 - v) * col[j][k] + v * col[j + 1][k];
    for (int k = 0; k < 3; k++)
        out[k] = col[0][k] / col[0][3];
}

static double dist(sw_vec3 a, sw_vec3 b) { return sw_v3_length(sw_v3_sub(a, b)); }

static double hull_size(const sw_bezier_patch *p)
{
    sw_box b = sw_bezier_control_box(p);
    return sw_box_diagonal(&b);
}

/* |F - F_ref| <= 1e-12 * control hull diagonal, all 15 x 15 degree pairs. */
static void test_eval_matches_long_double_reference(void)
{
    double ctrl[MAXN * MAXN * 4];
    double worst = 0;
    for (int rational = 0; rational <= 1; rational++) {
        for (int n = 1; n <= SW_BEZIER_MAX_DEGREE; n++) {
            for (int m = 1; m <= SW_BEZIER_MAX_DEGREE; m++) {
                sw_bezier_patch p;
                random_patch(ctrl, n, m, rational, &p);
                double size = hull_size(&p);
                for (int s = 0; s < 8; s++) {
                    double u = s == 0 ? 0 : s == 1 ? 1 : sw_test_random();
                    double v = s == 0 ? 1 : s == 1 ? 0 : sw_test_random();
                    long double r[3];
                    sw_surface_point q;
                    reference_point(&p, u, v, r);
                    sw_bezier_eval(&p, u, v, SW_EVAL_SECOND, &q);
                    double e = dist(q.p, sw_v3((double)r[0], (double)r[1], (double)r[2])) / size;
                    worst = fmax(worst, e);
                }
            }
        }
    }
    SW_CHECK_MSG(worst <= 1e-12, "worst relative error %g", worst);
}

static sw_vec3 ref_vec(const sw_bezier_patch *p, long double u, long double v)
{
    long double r[3];
    reference_point(p, u, v, r);
    return sw_v3((double)r[0], (double)r[1], (double)r[2]);
}

/* Central differences with step h = 1e-5 (truncation ~ h^2 F''' / 6):
 * |error| <= 1e-7 * (scale of the derivative), where the scale is the hull
 * size times degree (first) or degree squared (second), times the largest
 * weight ratio squared for rational patches. */
static void test_derivatives_match_finite_differences(void)
{
    double ctrl[MAXN * MAXN * 4];
    const long double h = 1e-5L;
    double worst1 = 0, worst2 = 0;
    for (int trial = 0; trial < 300; trial++) {
        int n = 1 + (int)(sw_test_random() * 15), m = 1 + (int)(sw_test_random() * 15);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        double wr = (trial & 1) ? 16.0 * 16.0 : 1.0;
        double s1 = hull_size(&p) * (n + m) * wr, s2 = s1 * (n + m);
        double u = 0.01 + 0.98 * sw_test_random(), v = 0.01 + 0.98 * sw_test_random();
        sw_surface_point q, a, b, c, d;
        sw_bezier_eval(&p, u, v, SW_EVAL_SECOND, &q);
        sw_vec3 fdu = sw_v3_scale(sw_v3_sub(ref_vec(&p, u + h, v), ref_vec(&p, u - h, v)), 0.5 / h);
        sw_vec3 fdv = sw_v3_scale(sw_v3_sub(ref_vec(&p, u, v + h), ref_vec(&p, u, v - h)), 0.5 / h);
        worst1 = fmax(worst1, fmax(dist(fdu, q.du), dist(fdv, q.dv)) / s1);
        sw_bezier_eval(&p, u + h, v, SW_EVAL_FIRST, &a);
        sw_bezier_eval(&p, u - h, v, SW_EVAL_FIRST, &b);
        sw_bezier_eval(&p, u, v + h, SW_EVAL_FIRST, &c);
        sw_bezier_eval(&p, u, v - h, SW_EVAL_FIRST, &d);
        sw_vec3 fduu = sw_v3_scale(sw_v3_sub(a.du, b.du), 0.5 / h);
        sw_vec3 fduv = sw_v3_scale(sw_v3_sub(c.du, d.du), 0.5 / h);
        sw_vec3 fdvv = sw_v3_scale(sw_v3_sub(c.dv, d.dv), 0.5 / h);
        double e2 = fmax(dist(fduu, q.duu), fmax(dist(fduv, q.duv), dist(fdvv, q.dvv)));
        worst2 = fmax(worst2, e2 / s2);
    }
    SW_CHECK_MSG(worst1 <= 1e-7, "first derivatives: worst scaled error %g", worst1);
    SW_CHECK_MSG(worst2 <= 1e-7, "second derivatives: worst scaled error %g", worst2);
}

static void test_normals_unit_and_perpendicular(void)
{
    double ctrl[MAXN * MAXN * 4];
    for (int trial = 0; trial < 200; trial++) {
        int n = 1 + (int)(sw_test_random() * 15), m = 1 + (int)(sw_test_random() * 15);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        sw_surface_point q;
        sw_bezier_eval(&p, sw_test_random(), sw_test_random(), SW_EVAL_FIRST, &q);
        SW_CHECK_NEAR(sw_v3_length(q.normal), 1, 1e-12);
        SW_CHECK(fabs(sw_v3_dot(q.normal, q.du)) <= 1e-10 * sw_v3_length(q.du));
        SW_CHECK(fabs(sw_v3_dot(q.normal, q.dv)) <= 1e-10 * sw_v3_length(q.dv));
    }
}

/* A bicubic dome whose whole v = 0 row is one point (the teapot lid's pole):
 * du vanishes there, yet the normal is the limit of the normals around it. */
static void test_normal_at_collapsed_edge(void)
{
    double ctrl[16 * 4];
    for (int rational = 0; rational <= 1; rational++) {
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                double a = i * 0.5, r = j / 3.0;
                double *c = ctrl + (j * 4 + i) * 4;
                c[0] = r * cos(a), c[1] = r * sin(a), c[2] = 1 - r * r;
                c[3] = rational ? 1 + 0.3 * i + 0.2 * j : 1;
            }
        }
        sw_bezier_patch p = {3, 3, rational, ctrl};
        for (int s = 0; s <= 4; s++) {
            double u = s / 4.0;
            sw_surface_point q, near;
            sw_bezier_eval(&p, u, 0, SW_EVAL_SECOND, &q);
            sw_bezier_eval(&p, u, 1e-3, SW_EVAL_FIRST, &near);
            SW_CHECK(sw_v3_length(q.du) <= 1e-12);
            SW_CHECK(isfinite(q.normal.x) && isfinite(q.normal.y) && isfinite(q.normal.z));
            SW_CHECK_NEAR(sw_v3_length(q.normal), 1, 1e-12);
            SW_CHECK_MSG(sw_v3_dot(q.normal, near.normal) > 0.99, "u %g: dot %g", u,
                         sw_v3_dot(q.normal, near.normal));
        }
    }
}

/* Largest sampled |F_uu|, |F_uv|, |F_vv| on a 61 x 61 grid. */
static sw_deriv_bounds sampled_second_derivs(const sw_bezier_patch *p)
{
    sw_deriv_bounds s = {0, 0, 0};
    for (int b = 0; b <= 60; b++) {
        for (int a = 0; a <= 60; a++) {
            sw_surface_point q;
            sw_bezier_eval(p, a / 60.0, b / 60.0, SW_EVAL_SECOND, &q);
            s.uu = fmax(s.uu, sw_v3_length(q.duu));
            s.uv = fmax(s.uv, sw_v3_length(q.duv));
            s.vv = fmax(s.vv, sw_v3_length(q.dvv));
        }
    }
    return s;
}

static void test_second_deriv_bounds_hold(void)
{
    double ctrl[MAXN * MAXN * 4];
    for (int trial = 0; trial < 60; trial++) {
        int n = 1 + (int)(sw_test_random() * 8), m = 1 + (int)(sw_test_random() * 8);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        sw_deriv_bounds bound, s = sampled_second_derivs(&p);
        SW_CHECK(sw_bezier_second_deriv_bounds(&p, &bound, NULL) == SW_OK);
        SW_CHECK_MSG(bound.uu >= s.uu && bound.uv >= s.uv && bound.vv >= s.vv,
                     "degree %dx%d rational %d: bound %g %g %g sampled %g %g %g", n, m, trial & 1,
                     bound.uu, bound.uv, bound.vv, s.uu, s.uv, s.vv);
    }
}

/* For random bicubics the hodograph bound is within 10x of the sampled max. */
static void test_second_deriv_bounds_tight_for_bicubic(void)
{
    double ctrl[16 * 4];
    for (int trial = 0; trial < 20; trial++) {
        sw_bezier_patch p;
        random_patch(ctrl, 3, 3, 0, &p);
        sw_deriv_bounds bound, s = sampled_second_derivs(&p);
        SW_CHECK(sw_bezier_second_deriv_bounds(&p, &bound, NULL) == SW_OK);
        SW_CHECK_MSG(bound.uu <= 10 * s.uu && bound.uv <= 10 * s.uv && bound.vv <= 10 * s.vv,
                     "bound %g %g %g sampled %g %g %g", bound.uu, bound.uv, bound.vv, s.uu, s.uv,
                     s.vv);
    }
}

/* Degree 1 in a direction has no second derivative there: the bound is 0,
 * and a flat parallelogram has F_uv = 0 up to rounding. */
static void test_second_deriv_bounds_of_bilinear(void)
{
    const double ctrl[16] = {0, 0, 0, 1, 2, 0, 0, 1, 1, 3, 0, 1, 3, 3, 0, 1};
    sw_bezier_patch p = {1, 1, 0, ctrl};
    sw_deriv_bounds b;
    SW_CHECK(sw_bezier_second_deriv_bounds(&p, &b, NULL) == SW_OK);
    SW_CHECK(b.uu == 0 && b.vv == 0);
    SW_CHECK(b.uv <= 1e-12);
}

/* Rational patches linear in one direction with weights constant along it
 * (extrusions): random ones keep the bound an upper bound; an exact
 * extruded quarter circle, either way round, has F_uv = 0 and its bound is
 * 0 up to rounding (the general bound gave 1.2, so the cylinder got far
 * more rows than it needs). */
static void test_second_deriv_bounds_of_extrusions(void)
{
    double ctrl[MAXN * MAXN * 4];
    for (int trial = 0; trial < 40; trial++) {
        int n = 1 + (int)(sw_test_random() * 6), along_u = trial & 1;
        sw_bezier_patch p;
        random_patch(ctrl, along_u ? 1 : n, along_u ? n : 1, 1, &p);
        for (int i = 0; i <= n; i++) { /* the second row's weights copy the first's */
            double *a = ctrl + (along_u ? (size_t)i * 2 : (size_t)i) * 4;
            a[(along_u ? 1 : (size_t)(n + 1)) * 4 + 3] = a[3];
        }
        sw_deriv_bounds bound, sampled = sampled_second_derivs(&p);
        SW_CHECK(sw_bezier_second_deriv_bounds(&p, &bound, NULL) == SW_OK);
        bound.uv = sw_bezier_extrusion_mixed_bound(&p);
        SW_CHECK_MSG(bound.uu >= sampled.uu && bound.uv >= sampled.uv && bound.vv >= sampled.vv,
                     "extrusion %d x %d: bound %g %g %g sampled %g %g %g", p.degree_u,
                     p.degree_v, bound.uu, bound.uv, bound.vv, sampled.uu, sampled.uv,
                     sampled.vv);
    }
    /* not an extrusion: curved both ways, or weights varying along the line */
    for (int trial = 0; trial < 10; trial++) {
        sw_bezier_patch p;
        random_patch(ctrl, 2, 1 + trial % 3, 1, &p);
        if (p.degree_v == 1)
            ctrl[(size_t)(p.degree_u + 1) * 4 + 3] = ctrl[3] * 1.5;
        SW_CHECK(isinf(sw_bezier_extrusion_mixed_bound(&p)));
    }
    const double h = sqrt(0.5);
    const double arc[3][4] = { { 1, 0, 0, 1 }, { 1, 1, 0, h }, { 0, 1, 0, 1 } };
    for (int along_u = 0; along_u < 2; along_u++) {
        double c[6 * 4];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 2; j++) {
                double *q = c + (along_u ? (size_t)i * 2 + j : (size_t)j * 3 + i) * 4;
                memcpy(q, arc[i], sizeof arc[i]);
                q[2] = 2.0 * j;
            }
        sw_bezier_patch p = { along_u ? 1 : 2, along_u ? 2 : 1, 1, c };
        sw_deriv_bounds bound, sampled = sampled_second_derivs(&p);
        SW_CHECK(sw_bezier_second_deriv_bounds(&p, &bound, NULL) == SW_OK);
        SW_CHECK(bound.uv > 0.5); /* the general bound: blind to the structure */
        bound.uv = sw_bezier_extrusion_mixed_bound(&p);
        SW_CHECK_MSG(bound.uv <= 1e-12 && sampled.uv <= 1e-12, "quarter cylinder: uv bound %g",
                     bound.uv);
        SW_CHECK(along_u ? bound.vv >= sampled.vv && bound.uu == 0
                         : bound.uu >= sampled.uu && bound.vv == 0);
    }
}

static void test_second_deriv_bounds_reject_bad_weight(void)
{
    double ctrl[16 * 4];
    sw_bezier_patch p;
    random_patch(ctrl, 3, 3, 1, &p);
    ctrl[(2 * 4 + 1) * 4 + 3] = 0;
    sw_deriv_bounds b;
    sw_error err = {0};
    SW_CHECK(sw_bezier_second_deriv_bounds(&p, &b, &err) == SW_ERR_RANGE);
    SW_CHECK_MSG(strstr(err.message, "weight") && strstr(err.message, "(1, 2)"), "%s",
                 err.message);
    ctrl[(2 * 4 + 1) * 4 + 3] = NAN;
    SW_CHECK(sw_bezier_second_deriv_bounds(&p, &b, &err) == SW_ERR_RANGE);
    p.degree_u = 16;
    SW_CHECK(sw_bezier_second_deriv_bounds(&p, &b, &err) == SW_ERR_ARG);
}

static void test_control_box_contains_patch(void)
{
    double ctrl[MAXN * MAXN * 4];
    for (int trial = 0; trial < 40; trial++) {
        int n = 1 + (int)(sw_test_random() * 15), m = 1 + (int)(sw_test_random() * 15);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        sw_box box = sw_bezier_control_box(&p);
        double tol = 1e-12 * sw_box_diagonal(&box);
        for (int s = 0; s < 50; s++) {
            sw_surface_point q;
            sw_bezier_eval(&p, sw_test_random(), sw_test_random(), SW_EVAL_POINT, &q);
            SW_CHECK(sw_box_distance(&box, q.p) <= tol);
        }
    }
}

static void test_patch_from_float_copies(void)
{
    float f[2 * 3 * 4];
    for (int i = 0; i < 24; i++)
        f[i] = 0.5f + (float)i;
    sw_bezier_patchf pf = {1, 2, 1, f};
    double d[24];
    sw_bezier_patch p = sw_bezier_patch_from_float(&pf, d);
    SW_CHECK(p.degree_u == 1 && p.degree_v == 2 && p.rational == 1 && p.ctrl == d);
    for (int i = 0; i < 24; i++)
        SW_CHECK(d[i] == (double)f[i]);
}

static void test_eval_order_leaves_unrequested_zero(void)
{
    double ctrl[16 * 4];
    sw_bezier_patch p;
    random_patch(ctrl, 3, 3, 1, &p);
    sw_surface_point q;
    memset(&q, 0x7f, sizeof q);
    sw_bezier_eval(&p, 0.3, 0.6, SW_EVAL_POINT, &q);
    SW_CHECK(q.du.x == 0 && q.dv.y == 0 && q.normal.z == 0 && q.duu.x == 0);
    sw_bezier_eval(&p, 0.3, 0.6, SW_EVAL_FIRST, &q);
    SW_CHECK(q.duu.x == 0 && q.duv.y == 0 && q.dvv.z == 0 && q.du.x != 0);
}

/* A sub-patch is the same surface on the sub-rectangle: its point at (s, t)
 * equals the original's at (u0 + s (u1 - u0), v0 + t (v1 - v0)), for every
 * degree, rational or not, including sub-rectangles touching the border. */
static void test_subpatch_matches_original_on_subrect(void)
{
    double ctrl[MAXN * MAXN * 4], sub[MAXN * MAXN * 4];
    for (int trial = 0; trial < 200; trial++) {
        int n = 1 + (int)(sw_test_random() * 15), m = 1 + (int)(sw_test_random() * 15);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        double a = sw_test_random(), b = sw_test_random();
        double u0 = trial % 5 == 0 ? 0 : fmin(a, b) * 0.9, u1 = trial % 7 == 0 ? 1 : fmax(a, b);
        double v0 = 0.3 * sw_test_random(), v1 = v0 + 0.05 + 0.65 * sw_test_random();
        if (u1 - u0 < 0.01)
            u1 = u0 + 0.01;
        sw_bezier_subpatch(&p, u0, u1, v0, v1, sub);
        sw_bezier_patch q = {n, m, p.rational, sub};
        double worst = 0;
        for (int s = 0; s < 8; s++) {
            double su = s < 2 ? s : sw_test_random(), tv = s < 2 ? 1 - s : sw_test_random();
            long double r[3];
            sw_surface_point e;
            reference_point(&p, u0 + su * (u1 - u0), v0 + tv * (v1 - v0), r);
            sw_bezier_eval(&q, su, tv, SW_EVAL_POINT, &e);
            worst = fmax(worst, fabs((double)(r[0] - e.p.x)) + fabs((double)(r[1] - e.p.y)) +
                                    fabs((double)(r[2] - e.p.z)));
        }
        SW_CHECK_MSG(worst < 1e-9, "degree %d x %d rational %d: off by %g", n, m, p.rational,
                     worst);
        if (!p.rational)
            SW_CHECK(sub[3] == 1.0 && sub[4 * ((n + 1) * (m + 1)) - 1] == 1.0);
    }
}

/* Each quarter (u upper half when k & 1, v when k & 2) against the
 * sub-patch of the same quarter: the same control points up to rounding,
 * and (a check that can fail) not those of another quarter. */
static void test_quarters_match_subpatches(void)
{
    double ctrl[MAXN * MAXN * 4], sub[MAXN * MAXN * 4], quarter[4][MAXN * MAXN * 4];
    double *const out[4] = {quarter[0], quarter[1], quarter[2], quarter[3]};
    for (int trial = 0; trial < 100; trial++) {
        int n = 1 + (int)(sw_test_random() * 15), m = 1 + (int)(sw_test_random() * 15);
        sw_bezier_patch p;
        random_patch(ctrl, n, m, trial & 1, &p);
        sw_bezier_quarters(&p, out);
        size_t doubles = 4 * (size_t)(n + 1) * (size_t)(m + 1);
        for (int k = 0; k < 4; k++) {
            double u0 = (k & 1) ? 0.5 : 0, v0 = (k & 2) ? 0.5 : 0;
            sw_bezier_subpatch(&p, u0, u0 + 0.5, v0, v0 + 0.5, sub);
            double same = 0, other = 0;
            for (size_t i = 0; i < doubles; i++) {
                same = fmax(same, fabs(sub[i] - quarter[k][i]) / fmax(1, fabs(sub[i])));
                other = fmax(other, fabs(sub[i] - quarter[k ^ 3][i]));
            }
            SW_CHECK_MSG(same < 1e-12, "degree %d x %d rational %d quarter %d: off by %g", n, m,
                         p.rational, k, same);
            SW_CHECK_MSG(other > 1e-9, "degree %d x %d: quarters %d and %d alike", n, m, k, k ^ 3);
        }
    }
}

int main(void)
{
    SW_RUN(test_eval_matches_long_double_reference);
    SW_RUN(test_derivatives_match_finite_differences);
    SW_RUN(test_normals_unit_and_perpendicular);
    SW_RUN(test_normal_at_collapsed_edge);
    SW_RUN(test_second_deriv_bounds_hold);
    SW_RUN(test_second_deriv_bounds_tight_for_bicubic);
    SW_RUN(test_second_deriv_bounds_of_bilinear);
    SW_RUN(test_second_deriv_bounds_of_extrusions);
    SW_RUN(test_second_deriv_bounds_reject_bad_weight);
    SW_RUN(test_control_box_contains_patch);
    SW_RUN(test_patch_from_float_copies);
    SW_RUN(test_eval_order_leaves_unrequested_zero);
    SW_RUN(test_subpatch_matches_original_on_subrect);
    SW_RUN(test_quarters_match_subpatches);
    return sw_test_finish();
}
