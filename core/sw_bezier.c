/* SPDX-License-Identifier: MIT */
#include "sw_bezier.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <string.h>

/* Derivative levels a curve evaluation returns: value, first, second. */
enum { LEVELS = 3 };

/* Homogeneous control point (w x, w y, w z, w); w = 1 for polynomial patches. */
static void homogeneous_ctrl(const sw_bezier_patch *patch, int i, int j, double out[4])
{
    const double *c = patch->ctrl + ((size_t)j * (size_t)(patch->degree_u + 1) + (size_t)i) * 4;
    double w = patch->rational ? c[3] : 1.0;
    out[0] = c[0] * w;
    out[1] = c[1] * w;
    out[2] = c[2] * w;
    out[3] = w;
}

/* De Casteljau on n + 1 four-dimensional points, stopping at the last three
 * intermediate points: they give the value and both derivatives at t without
 * the cancellation a power-basis or derivative-Bernstein sum would have for
 * high degrees. levels says how many of out[0..2] are wanted. */
static void curve_eval(double pts[][4], int n, double t, int levels, double out[LEVELS][4])
{
    double s = 1 - t;
    int stop = n >= 2 ? 2 : 1;
    for (int r = n; r > stop; r--)
        for (int i = 0; i < r; i++)
            for (int k = 0; k < 4; k++)
                pts[i][k] = s * pts[i][k] + t * pts[i + 1][k];
    memset(out, 0, sizeof(double) * LEVELS * 4);
    if (n == 1) {
        for (int k = 0; k < 4; k++) {
            out[0][k] = s * pts[0][k] + t * pts[1][k];
            out[1][k] = pts[1][k] - pts[0][k];
        }
        return;
    }
    for (int k = 0; k < 4; k++) {
        double c0 = s * pts[0][k] + t * pts[1][k];
        double c1 = s * pts[1][k] + t * pts[2][k];
        out[0][k] = s * c0 + t * c1;
        if (levels > 1)
            out[1][k] = n * (c1 - c0);
        if (levels > 2)
            out[2][k] = (double)n * (n - 1) * ((pts[2][k] - pts[1][k]) - (pts[1][k] - pts[0][k]));
    }
}

/* Homogeneous value and derivatives: h[0] = H, h[1] = H_u, h[2] = H_v,
 * h[3] = H_uu, h[4] = H_uv, h[5] = H_vv. Rows are reduced along u first,
 * then the three resulting curves along v. */
static void eval_homogeneous(const sw_bezier_patch *patch, double u, double v, int levels,
                             double h[6][4])
{
    int nu = patch->degree_u, nv = patch->degree_v;
    double rows[LEVELS][SW_BEZIER_MAX_ORDER][4];
    double pts[SW_BEZIER_MAX_ORDER][4];
    double out[LEVELS][4];
    for (int j = 0; j <= nv; j++) {
        for (int i = 0; i <= nu; i++)
            homogeneous_ctrl(patch, i, j, pts[i]);
        curve_eval(pts, nu, u, levels, out);
        for (int l = 0; l < LEVELS; l++)
            memcpy(rows[l][j], out[l], sizeof out[l]);
    }
    memset(h, 0, sizeof(double) * 6 * 4);
    curve_eval(rows[0], nv, v, levels, out);
    memcpy(h[0], out[0], sizeof out[0]);
    memcpy(h[2], out[1], sizeof out[1]);
    memcpy(h[5], out[2], sizeof out[2]);
    if (levels < 2)
        return;
    curve_eval(rows[1], nv, v, 2, out);
    memcpy(h[1], out[0], sizeof out[0]);
    memcpy(h[4], out[1], sizeof out[1]);
    if (levels < 3)
        return;
    curve_eval(rows[2], nv, v, 1, out);
    memcpy(h[3], out[0], sizeof out[0]);
}

static sw_vec3 xyz(const double h[4]) { return sw_v3(h[0], h[1], h[2]); }

/* Cross product normalised, or zero when du and dv are (nearly) parallel or
 * one of them (nearly) vanishes relative to the other: at a collapsed edge
 * the tiny derivative is rounding noise and its direction means nothing. */
static sw_vec3 normal_or_zero(sw_vec3 du, sw_vec3 dv)
{
    double a = sw_v3_length(du), b = sw_v3_length(dv);
    sw_vec3 c = sw_v3_cross(du, dv);
    double lc = sw_v3_length(c);
    if (!(lc > 1e-10 * a * b) || !(fmin(a, b) > 1e-10 * fmax(a, b)))
        return sw_v3(0, 0, 0);
    return sw_v3_scale(c, 1.0 / lc);
}

/* Everything but the fallback normal. */
static void eval_plain(const sw_bezier_patch *patch, double u, double v, sw_eval_order order,
                       sw_surface_point *out)
{
    double h[6][4];
    memset(out, 0, sizeof *out);
    eval_homogeneous(patch, u, v, (int)order + 1, h);
    double w = h[0][3], inv_w = 1.0 / w;
    sw_vec3 f = sw_v3_scale(xyz(h[0]), inv_w);
    out->p = f;
    if (order == SW_EVAL_POINT)
        return;
    /* Quotient rule on F = X / w: F_u = (X_u - w_u F) / w and so on. */
    double wu = h[1][3], wv = h[2][3];
    out->du = sw_v3_scale(sw_v3_sub(xyz(h[1]), sw_v3_scale(f, wu)), inv_w);
    out->dv = sw_v3_scale(sw_v3_sub(xyz(h[2]), sw_v3_scale(f, wv)), inv_w);
    out->normal = normal_or_zero(out->du, out->dv);
    if (order == SW_EVAL_FIRST)
        return;
    double wuu = h[3][3], wuv = h[4][3], wvv = h[5][3];
    sw_vec3 t = sw_v3_add(sw_v3_scale(out->du, 2 * wu), sw_v3_scale(f, wuu));
    out->duu = sw_v3_scale(sw_v3_sub(xyz(h[3]), t), inv_w);
    t = sw_v3_add(sw_v3_add(sw_v3_scale(out->dv, wu), sw_v3_scale(out->du, wv)),
                  sw_v3_scale(f, wuv));
    out->duv = sw_v3_scale(sw_v3_sub(xyz(h[4]), t), inv_w);
    t = sw_v3_add(sw_v3_scale(out->dv, 2 * wv), sw_v3_scale(f, wvv));
    out->dvv = sw_v3_scale(sw_v3_sub(xyz(h[5]), t), inv_w);
}

void sw_bezier_eval(const sw_bezier_patch *patch, double u, double v, sw_eval_order order,
                    sw_surface_point *out)
{
    assert(patch->degree_u >= 1 && patch->degree_u <= SW_BEZIER_MAX_DEGREE);
    assert(patch->degree_v >= 1 && patch->degree_v <= SW_BEZIER_MAX_DEGREE);
    eval_plain(patch, u, v, order, out);
    if (order == SW_EVAL_POINT || sw_v3_dot(out->normal, out->normal) > 0)
        return;
    /* Collapsed edge: the normal there is the limit of normals of nearby
     * points, so step toward the centre, growing the step until the
     * derivatives separate from rounding noise. */
    for (double eps = 1e-7; eps < 0.2; eps *= 100) {
        sw_surface_point q;
        double un = u + (u <= 0.5 ? eps : -eps), vn = v + (v <= 0.5 ? eps : -eps);
        eval_plain(patch, un, vn, SW_EVAL_FIRST, &q);
        if (sw_v3_dot(q.normal, q.normal) > 0) {
            out->normal = q.normal;
            return;
        }
    }
}

sw_bezier_patch sw_bezier_patch_from_float(const sw_bezier_patchf *patch, double *ctrl_out)
{
    size_t n = 4 * (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1);
    for (size_t i = 0; i < n; i++)
        ctrl_out[i] = patch->ctrl[i];
    sw_bezier_patch p = {patch->degree_u, patch->degree_v, patch->rational, ctrl_out};
    return p;
}

sw_box sw_bezier_control_box(const sw_bezier_patch *patch)
{
    sw_box box = sw_box_empty();
    size_t n = (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1);
    for (size_t i = 0; i < n; i++) {
        const double *c = patch->ctrl + i * 4;
        sw_box_add_point(&box, sw_v3(c[0], c[1], c[2]));
    }
    return box;
}

/* Maxima over the control net of the norms of first and second differences
 * of the homogeneous points (xyz part) and of the weights, already scaled by
 * the hodograph factors n, n(n-1), n m: each is a bound of the corresponding
 * derivative over the patch (convex hull property of the hodograph). */
typedef struct hodograph_bounds {
    double xu, xv, xuu, xuv, xvv; /* |X_u| ... of the translated homogeneous points */
    double wu, wv, wuu, wuv, wvv; /* |w_u| ... */
} hodograph_bounds;

static void diff_max(const double *d, double *x_max, double *w_max)
{
    *x_max = fmax(*x_max, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    *w_max = fmax(*w_max, fabs(d[3]));
}

/* net[j][i] are homogeneous control points translated to the hull centre. */
static hodograph_bounds hodographs(double net[][SW_BEZIER_MAX_ORDER][4], int n, int m)
{
    hodograph_bounds b;
    memset(&b, 0, sizeof b);
    double d[4];
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const double *p = net[j][i];
            for (int k = 0; i < n && k < 4; k++)
                d[k] = net[j][i + 1][k] - p[k];
            if (i < n)
                diff_max(d, &b.xu, &b.wu);
            for (int k = 0; j < m && k < 4; k++)
                d[k] = net[j + 1][i][k] - p[k];
            if (j < m)
                diff_max(d, &b.xv, &b.wv);
            for (int k = 0; i + 1 < n && k < 4; k++)
                d[k] = (net[j][i + 2][k] - net[j][i + 1][k]) - (net[j][i + 1][k] - p[k]);
            if (i + 1 < n)
                diff_max(d, &b.xuu, &b.wuu);
            for (int k = 0; j + 1 < m && k < 4; k++)
                d[k] = (net[j + 2][i][k] - net[j + 1][i][k]) - (net[j + 1][i][k] - p[k]);
            if (j + 1 < m)
                diff_max(d, &b.xvv, &b.wvv);
            for (int k = 0; i < n && j < m && k < 4; k++)
                d[k] = (net[j + 1][i + 1][k] - net[j + 1][i][k]) - (net[j][i + 1][k] - p[k]);
            if (i < n && j < m)
                diff_max(d, &b.xuv, &b.wuv);
        }
    }
    double fn = n, fm = m;
    b.xu *= fn, b.wu *= fn, b.xv *= fm, b.wv *= fm;
    b.xuu *= fn * (fn - 1), b.wuu *= fn * (fn - 1);
    b.xvv *= fm * (fm - 1), b.wvv *= fm * (fm - 1);
    b.xuv *= fn * fm, b.wuv *= fn * fm;
    return b;
}

static sw_status check_patch(const sw_bezier_patch *patch, sw_error *err)
{
    if (patch->degree_u < 1 || patch->degree_u > SW_BEZIER_MAX_DEGREE || patch->degree_v < 1 ||
        patch->degree_v > SW_BEZIER_MAX_DEGREE)
        return sw_error_set(err, SW_ERR_ARG, "Bezier patch degree %d x %d: expected 1..%d",
                            patch->degree_u, patch->degree_v, SW_BEZIER_MAX_DEGREE);
    for (int j = 0; j <= patch->degree_v; j++) {
        for (int i = 0; i <= patch->degree_u; i++) {
            const double *c = patch->ctrl + ((size_t)j * (size_t)(patch->degree_u + 1) + i) * 4;
            if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]))
                return sw_error_set(err, SW_ERR_RANGE,
                                    "Bezier control point (%d, %d): coordinate not finite", i, j);
            if (patch->rational && !(c[3] > 0 && isfinite(c[3])))
                return sw_error_set(err, SW_ERR_RANGE,
                                    "Bezier control point (%d, %d): weight %g, expected finite > 0",
                                    i, j, c[3]);
        }
    }
    return SW_OK;
}

/* F - c is a convex combination of the translated control points, so its
 * norm is at most R, the largest of their norms; F_u, F_uu, F_uv follow from
 * the quotient rule with w >= w_min (paper 000 section 4.1 needs only an upper
 * bound; the ordering of the terms mirrors the identities in the header). */
/* The mixed bound of a rational patch linear in one direction with weights
 * constant along it (an extrusion: cylinders, extruded profiles): there
 * S = A(s) + t B(s), B the rational curve of the rows' differences b_i with
 * the weights w_i, so S_st = B'(s) and, with c the centre of the b_i and
 * N = sum w_i (b_i - c) B_i, |B'| <= (max |N'| + max |b_i - c| max |W'|) /
 * w_min (B - c lies in the hull of the b_i - c). An exact extrusion has
 * b_i = c: 0, where the general bound, blind to the structure, gave a
 * quarter cylinder 4 (and the trimmed benchmark's cylinder 3 times the
 * triangles). Returns INFINITY when the patch is not of that kind. along_u:
 * the patch is linear in u (else in v). */
static double extrusion_mixed_bound(const sw_bezier_patch *patch, int along_u)
{
    int n = patch->degree_u, m = patch->degree_v;
    int k = along_u ? m : n; /* the curved direction's degree */
    if (!patch->rational || (along_u ? n : m) != 1)
        return INFINITY;
    double b[SW_BEZIER_MAX_ORDER][3], w[SW_BEZIER_MAX_ORDER], c[3] = { 0, 0, 0 };
    for (int i = 0; i <= k; i++) {
        const double *p0 = patch->ctrl + (along_u ? (size_t)i * 2 : (size_t)i) * 4;
        const double *p1 = p0 + (along_u ? 1 : (size_t)(n + 1)) * 4;
        if (p0[3] != p1[3])
            return INFINITY;
        w[i] = p0[3];
        for (int d = 0; d < 3; d++)
            b[i][d] = p1[d] - p0[d], c[d] += b[i][d] / (k + 1);
    }
    double radius = 0, dn = 0, dw = 0, w_min = INFINITY;
    for (int i = 0; i <= k; i++) {
        double r2 = 0, e2 = 0;
        for (int d = 0; d < 3; d++) {
            r2 += (b[i][d] - c[d]) * (b[i][d] - c[d]);
            if (i < k) {
                double e = w[i + 1] * (b[i + 1][d] - c[d]) - w[i] * (b[i][d] - c[d]);
                e2 += e * e;
            }
        }
        radius = fmax(radius, sqrt(r2));
        dn = fmax(dn, k * sqrt(e2));
        dw = i < k ? fmax(dw, k * fabs(w[i + 1] - w[i])) : dw;
        w_min = fmin(w_min, w[i]);
    }
    return (dn + radius * dw) / w_min;
}

double sw_bezier_extrusion_mixed_bound(const sw_bezier_patch *patch)
{
    if (!patch->rational || check_patch(patch, NULL) != SW_OK)
        return INFINITY;
    double bound = fmin(extrusion_mixed_bound(patch, 0), extrusion_mixed_bound(patch, 1));
    if (!isfinite(bound))
        return INFINITY;
    int n = patch->degree_u, m = patch->degree_v;
    sw_box box = sw_bezier_control_box(patch);
    sw_vec3 c = sw_box_center(&box);
    double radius = 0;
    for (size_t i = 0; i < (size_t)(n + 1) * (size_t)(m + 1); i++) {
        const double *p = patch->ctrl + i * 4;
        radius = fmax(radius, sw_v3_length(sw_v3_sub(sw_v3(p[0], p[1], p[2]), c)));
    }
    /* the same margins as sw_bezier_second_deriv_bounds's */
    return bound * (1 + 1e-12) + 64 * DBL_EPSILON * radius * (n + m) * (n + m);
}

sw_status sw_bezier_second_deriv_bounds(const sw_bezier_patch *patch, sw_deriv_bounds *out,
                                        sw_error *err)
{
    sw_status st = check_patch(patch, err);
    if (st != SW_OK)
        return st;
    int n = patch->degree_u, m = patch->degree_v;
    sw_box box = sw_bezier_control_box(patch);
    sw_vec3 c = sw_box_center(&box);
    double net[SW_BEZIER_MAX_ORDER][SW_BEZIER_MAX_ORDER][4];
    double radius = 0, w_min = INFINITY;
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const double *p = patch->ctrl + ((size_t)j * (size_t)(n + 1) + (size_t)i) * 4;
            double w = patch->rational ? p[3] : 1.0;
            double x = p[0] - c.x, y = p[1] - c.y, z = p[2] - c.z;
            radius = fmax(radius, sqrt(x * x + y * y + z * z));
            w_min = fmin(w_min, w);
            net[j][i][0] = w * x, net[j][i][1] = w * y, net[j][i][2] = w * z, net[j][i][3] = w;
        }
    }
    hodograph_bounds b = hodographs(net, n, m);
    double fu = (b.xu + b.wu * radius) / w_min;
    double fv = (b.xv + b.wv * radius) / w_min;
    out->uu = (b.xuu + 2 * b.wu * fu + b.wuu * radius) / w_min;
    out->uv = (b.xuv + b.wu * fv + b.wv * fu + b.wuv * radius) / w_min;
    out->vv = (b.xvv + 2 * b.wv * fv + b.wvv * radius) / w_min;
    /* Rounding in the differences: a relative and an absolute margin keep the
     * bound an upper bound in floating point too. */
    double slack = 64 * DBL_EPSILON * radius * (n + m) * (n + m);
    out->uu = out->uu * (1 + 1e-12) + (n > 1 ? slack : 0);
    out->uv = out->uv * (1 + 1e-12) + slack;
    out->vv = out->vv * (1 + 1e-12) + (m > 1 ? slack : 0);
    return SW_OK;
}

/* Control points of the piece [t0, t1] of a Bezier curve of degree n given by
 * homogeneous points pts (overwritten): split at t0 and keep the right part
 * (b_i^(n-i) of the de Casteljau triangle), then split that at the rescaled
 * t1 and keep the left part (b_0^r). */
static void curve_segment(double pts[][4], int n, double t0, double t1)
{
    double tail[SW_BEZIER_MAX_ORDER][4];
    for (int r = 0; r <= n; r++) {
        memcpy(tail[n - r], pts[n - r], sizeof tail[0]);
        for (int i = 0; i < n - r; i++)
            for (int k = 0; k < 4; k++)
                pts[i][k] = (1 - t0) * pts[i][k] + t0 * pts[i + 1][k];
    }
    double s = t0 < 1 ? (t1 - t0) / (1 - t0) : 0;
    for (int r = 0; r <= n; r++) {
        memcpy(pts[r], tail[0], sizeof tail[0]);
        for (int i = 0; i < n - r; i++)
            for (int k = 0; k < 4; k++)
                tail[i][k] = (1 - s) * tail[i][k] + s * tail[i + 1][k];
    }
}

void sw_bezier_subpatch(const sw_bezier_patch *patch, double u0, double u1, double v0, double v1,
                        double *ctrl_out)
{
    assert(patch && ctrl_out && u0 < u1 && v0 < v1);
    int n = patch->degree_u, m = patch->degree_v;
    double net[SW_BEZIER_MAX_ORDER][SW_BEZIER_MAX_ORDER][4]; /* [j][i] */
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++)
            homogeneous_ctrl(patch, i, j, net[j][i]);
        curve_segment(net[j], n, u0, u1);
    }
    double col[SW_BEZIER_MAX_ORDER][4];
    for (int i = 0; i <= n; i++) {
        for (int j = 0; j <= m; j++)
            memcpy(col[j], net[j][i], sizeof col[j]);
        curve_segment(col, m, v0, v1);
        for (int j = 0; j <= m; j++) {
            double *c = ctrl_out + ((size_t)j * (size_t)(n + 1) + (size_t)i) * 4;
            c[0] = col[j][0] / col[j][3];
            c[1] = col[j][1] / col[j][3];
            c[2] = col[j][2] / col[j][3];
            c[3] = patch->rational ? col[j][3] : 1.0;
        }
    }
}

/* Both halves of a curve at t = 1/2: left[r] and right[n - r] are the ends
 * of the r-th row of the de Casteljau triangle. */
static void curve_halves(double pts[][4], int n, double left[][4], double right[][4])
{
    for (int r = 0; r <= n; r++) {
        memcpy(left[r], pts[0], sizeof left[r]);
        memcpy(right[n - r], pts[n - r], sizeof right[n - r]);
        for (int i = 0; i < n - r; i++)
            for (int k = 0; k < 4; k++)
                pts[i][k] = 0.5 * (pts[i][k] + pts[i + 1][k]);
    }
}

void sw_bezier_quarters(const sw_bezier_patch *patch, double *const ctrl_out[4])
{
    assert(patch && ctrl_out);
    int n = patch->degree_u, m = patch->degree_v;
    double half[2][SW_BEZIER_MAX_ORDER][SW_BEZIER_MAX_ORDER][4]; /* [u half][j][i] */
    for (int j = 0; j <= m; j++) {
        double row[SW_BEZIER_MAX_ORDER][4];
        for (int i = 0; i <= n; i++)
            homogeneous_ctrl(patch, i, j, row[i]);
        curve_halves(row, n, half[0][j], half[1][j]);
    }
    for (int a = 0; a < 2; a++) {   /* the u half; its v halves are quarters a and a + 2 */
        for (int i = 0; i <= n; i++) {
            double col[SW_BEZIER_MAX_ORDER][4], low[SW_BEZIER_MAX_ORDER][4];
            double high[SW_BEZIER_MAX_ORDER][4];
            for (int j = 0; j <= m; j++)
                memcpy(col[j], half[a][j][i], sizeof col[j]);
            curve_halves(col, m, low, high);
            for (int j = 0; j <= m; j++) {
                for (int b = 0; b < 2; b++) {
                    const double *h = b ? high[j] : low[j];
                    double *c = ctrl_out[a + 2 * b] +
                                ((size_t)j * (size_t)(n + 1) + (size_t)i) * 4;
                    c[0] = h[0] / h[3], c[1] = h[1] / h[3], c[2] = h[2] / h[3];
                    c[3] = patch->rational ? h[3] : 1.0;
                }
            }
        }
    }
}
