/* SPDX-License-Identifier: MIT */
#include "sw_nurbs.h"

#include <math.h>
#include <string.h>

enum { MAXO = SW_BEZIER_MAX_ORDER };

/* ---- checks ---------------------------------------------------------- */

/* One knot vector of a clamped B-spline of degree p with count control
 * points; what names the direction in messages ("curve", "u", "v"). */
static sw_status check_knots(const char *what, int p, int count, const double *knots,
                             sw_error *err)
{
    if (p < 1 || p > SW_BEZIER_MAX_DEGREE)
        return sw_error_set(err, SW_ERR_ARG, "NURBS %s: degree %d, expected 1..%d", what, p,
                            SW_BEZIER_MAX_DEGREE);
    if (count < p + 1)
        return sw_error_set(err, SW_ERR_ARG,
                            "NURBS %s: %d control points, degree %d needs at least %d", what,
                            count, p, p + 1);
    if (!knots)
        return sw_error_set(err, SW_ERR_ARG, "NURBS %s: no knot vector", what);
    int nk = count + p + 1;
    for (int i = 0; i < nk; i++)
        if (!isfinite(knots[i]))
            return sw_error_set(err, SW_ERR_RANGE, "NURBS %s: knot %d is %g, expected finite",
                                what, i, knots[i]);
    for (int i = 0; i + 1 < nk; i++)
        if (knots[i + 1] < knots[i])
            return sw_error_set(err, SW_ERR_RANGE,
                                "NURBS %s: knot %d (%g) < knot %d (%g), expected non-decreasing",
                                what, i + 1, knots[i + 1], i, knots[i]);
    for (int i = 1; i <= p; i++)
        if (knots[i] != knots[0] || knots[nk - 1 - i] != knots[nk - 1])
            return sw_error_set(err, SW_ERR_RANGE,
                                "NURBS %s: knot vector not clamped, expected the first and last "
                                "%d knots equal",
                                what, p + 1);
    if (!(knots[p] < knots[count]))
        return sw_error_set(err, SW_ERR_RANGE, "NURBS %s: empty parameter range [%g, %g]", what,
                            knots[p], knots[count]);
    /* Multiplicity above p would break the curve (and the piece layout). */
    for (int i = p + 1, run = 1; i < count; i++) {
        run = knots[i] == knots[i - 1] ? run + 1 : 1;
        if (run > p || (i == p + 1 && knots[i] == knots[p]) ||
            (i == count - 1 && knots[i] == knots[count]))
            return sw_error_set(err, SW_ERR_RANGE,
                                "NURBS %s: knot %d (%g) has multiplicity above degree %d", what,
                                i, knots[i], p);
    }
    return SW_OK;
}

static sw_status check_point(const char *what, const double *c, int i, int j, sw_error *err)
{
    if (!c)
        return sw_error_set(err, SW_ERR_ARG, "NURBS %s: no control points", what);
    if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]))
        return sw_error_set(err, SW_ERR_RANGE,
                            "NURBS %s: control point (%d, %d) has a non-finite coordinate", what,
                            i, j);
    if (!(c[3] > 0) || !isfinite(c[3]))
        return sw_error_set(err, SW_ERR_RANGE,
                            "NURBS %s: control point (%d, %d) has weight %g, expected finite > 0",
                            what, i, j, c[3]);
    return SW_OK;
}

sw_status sw_nurbs_curve_check(const sw_nurbs_curve *curve, sw_error *err)
{
    sw_status st = check_knots("curve", curve->degree, curve->count, curve->knots, err);
    for (int i = 0; st == SW_OK && i < curve->count; i++)
        st = check_point("curve", curve->ctrl ? curve->ctrl + (size_t)i * 4 : NULL, i, 0, err);
    return st;
}

sw_status sw_nurbs_surface_check(const sw_nurbs_surface *s, sw_error *err)
{
    sw_status st = check_knots("surface u", s->degree_u, s->count_u, s->knots_u, err);
    if (st == SW_OK)
        st = check_knots("surface v", s->degree_v, s->count_v, s->knots_v, err);
    for (int j = 0; st == SW_OK && j < s->count_v; j++)
        for (int i = 0; st == SW_OK && i < s->count_u; i++)
            st = check_point("surface",
                             s->ctrl ? s->ctrl + ((size_t)j * (size_t)s->count_u + i) * 4 : NULL,
                             i, j, err);
    return st;
}

/* ---- evaluation -------------------------------------------------------- */

/* Span k with knots[k] <= t < knots[k + 1], p <= k < count; t at or past the
 * end maps to the last non-empty span, before the start to the first. */
static int find_span(int p, int count, const double *knots, double t)
{
    if (t >= knots[count]) {
        int k = count - 1;
        while (k > p && knots[k] == knots[k + 1])
            k--;
        return k;
    }
    if (t <= knots[p])
        return p;
    int lo = p, hi = count;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (t < knots[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

static void homogeneous(const double *c, double out[4])
{
    out[0] = c[0] * c[3], out[1] = c[1] * c[3], out[2] = c[2] * c[3], out[3] = c[3];
}

/* De Boor's triangle on the p + 1 homogeneous points d of span k, with
 * argument args[r - 1] at level r. All arguments equal t gives the point at t;
 * args = (a^(p-r), b^r) over the span [a, b] gives the blossom value that is
 * the r-th Bezier point of the span: exactly the point Boehm insertion of a
 * and b to multiplicity p produces (Ramshaw's blossoming), computed locally. */
static void de_boor(const double *knots, int p, int k, double d[][4], const double *args)
{
    for (int r = 1; r <= p; r++) {
        for (int j = p; j >= r; j--) {
            int i = k - p + j;
            double alpha = (args[r - 1] - knots[i]) / (knots[i + p - r + 1] - knots[i]);
            for (int c = 0; c < 4; c++)
                d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
        }
    }
}

static sw_vec3 cartesian(const double h[4]) { return sw_v3(h[0] / h[3], h[1] / h[3], h[2] / h[3]); }

/* Homogeneous point at t of the span-k local points of a strided point row. */
static void row_point(const double *knots, int p, int k, const double *ctrl, size_t stride,
                      double t, double out[4])
{
    double d[MAXO][4], args[MAXO];
    for (int j = 0; j <= p; j++) {
        homogeneous(ctrl + (size_t)(k - p + j) * stride, d[j]);
        args[j] = t;
    }
    de_boor(knots, p, k, d, args);
    memcpy(out, d[p], sizeof d[p]);
}

sw_vec3 sw_nurbs_curve_point(const sw_nurbs_curve *curve, double t)
{
    int k = find_span(curve->degree, curve->count, curve->knots, t);
    double h[4];
    row_point(curve->knots, curve->degree, k, curve->ctrl, 4, t, h);
    return cartesian(h);
}

sw_vec3 sw_nurbs_surface_point(const sw_nurbs_surface *s, double u, double v)
{
    int p = s->degree_u, q = s->degree_v;
    int ku = find_span(p, s->count_u, s->knots_u, u);
    int kv = find_span(q, s->count_v, s->knots_v, v);
    double d[MAXO][4], args[MAXO];
    for (int j = 0; j <= q; j++) {
        const double *row = s->ctrl + (size_t)(kv - q + j) * (size_t)s->count_u * 4;
        double h[4];
        row_point(s->knots_u, p, ku, row, 4, u, h);
        memcpy(d[j], h, sizeof h);
        args[j] = v;
    }
    de_boor(s->knots_v, q, kv, d, args);
    return cartesian(d[q]);
}

/* ---- decomposition ----------------------------------------------------- */

int sw_nurbs_span_count(int degree, int count, const double *knots)
{
    int spans = 0;
    for (int i = degree; i < count; i++)
        spans += knots[i] < knots[i + 1];
    return spans;
}

sw_nurbs_bezier_sizes sw_nurbs_curve_bezier_sizes(const sw_nurbs_curve *curve)
{
    sw_nurbs_bezier_sizes z = {0, 0, 0, 0};
    if (curve->degree < 1 || curve->degree > SW_BEZIER_MAX_DEGREE || curve->count <= curve->degree)
        return z;
    z.pieces_u = sw_nurbs_span_count(curve->degree, curve->count, curve->knots);
    z.ctrl_doubles = (size_t)z.pieces_u * (size_t)(curve->degree + 1) * 4;
    z.param_doubles = 2 * (size_t)z.pieces_u;
    return z;
}

sw_nurbs_bezier_sizes sw_nurbs_surface_bezier_sizes(const sw_nurbs_surface *s)
{
    sw_nurbs_bezier_sizes z = {0, 0, 0, 0};
    if (s->degree_u < 1 || s->degree_u > SW_BEZIER_MAX_DEGREE || s->count_u <= s->degree_u ||
        s->degree_v < 1 || s->degree_v > SW_BEZIER_MAX_DEGREE || s->count_v <= s->degree_v)
        return z;
    z.pieces_u = sw_nurbs_span_count(s->degree_u, s->count_u, s->knots_u);
    z.pieces_v = sw_nurbs_span_count(s->degree_v, s->count_v, s->knots_v);
    z.ctrl_doubles = (size_t)z.pieces_u * (size_t)z.pieces_v * (size_t)(s->degree_u + 1) *
                     (size_t)(s->degree_v + 1) * 4;
    z.param_doubles = 2 * ((size_t)z.pieces_u + (size_t)z.pieces_v);
    return z;
}

/* The p + 1 homogeneous Bezier points of span k, from the span's p + 1
 * homogeneous de Boor points local[0..p] (control points k - p .. k). */
static void span_to_bezier(const double *knots, int p, int k, const double local[][4],
                           double out[][4])
{
    double a = knots[k], b = knots[k + 1];
    for (int r = 0; r <= p; r++) {
        double d[MAXO][4], args[MAXO];
        for (int j = 0; j <= p; j++)
            args[j] = j < p - r ? a : b;
        memcpy(d, local, sizeof(double) * 4 * (size_t)(p + 1));
        de_boor(knots, p, k, d, args);
        memcpy(out[r], d[p], sizeof d[p]);
    }
}

/* Homogeneous to the Cartesian + w layout of sw_bezier_patch. */
static void store_point(const double h[4], double *out)
{
    out[0] = h[0] / h[3], out[1] = h[1] / h[3], out[2] = h[2] / h[3], out[3] = h[3];
}

sw_status sw_nurbs_curve_to_bezier(const sw_nurbs_curve *curve, double *ctrl_out,
                                   double *params_out, sw_error *err)
{
    sw_status st = sw_nurbs_curve_check(curve, err);
    if (st != SW_OK)
        return st;
    int p = curve->degree, piece = 0;
    for (int k = p; k < curve->count; k++) {
        if (!(curve->knots[k] < curve->knots[k + 1]))
            continue;
        double local[MAXO][4], bez[MAXO][4];
        for (int j = 0; j <= p; j++)
            homogeneous(curve->ctrl + (size_t)(k - p + j) * 4, local[j]);
        span_to_bezier(curve->knots, p, k, local, bez);
        for (int r = 0; r <= p; r++)
            store_point(bez[r], ctrl_out + ((size_t)piece * (size_t)(p + 1) + (size_t)r) * 4);
        params_out[2 * piece] = curve->knots[k];
        params_out[2 * piece + 1] = curve->knots[k + 1];
        piece++;
    }
    return SW_OK;
}

/* Patch for spans (ku, kv): each of the q + 1 local rows split along u, then
 * each resulting column along v, all in homogeneous coordinates. */
static void patch_to_bezier(const sw_nurbs_surface *s, int ku, int kv, double *out)
{
    int p = s->degree_u, q = s->degree_v;
    double rows[MAXO][MAXO][4]; /* [local row j][Bezier column r] */
    for (int j = 0; j <= q; j++) {
        double local[MAXO][4];
        const double *row = s->ctrl + (size_t)(kv - q + j) * (size_t)s->count_u * 4;
        for (int i = 0; i <= p; i++)
            homogeneous(row + (size_t)(ku - p + i) * 4, local[i]);
        span_to_bezier(s->knots_u, p, ku, local, rows[j]);
    }
    for (int r = 0; r <= p; r++) {
        double col[MAXO][4], h[MAXO][4];
        for (int j = 0; j <= q; j++)
            memcpy(col[j], rows[j][r], sizeof col[j]);
        span_to_bezier(s->knots_v, q, kv, col, h);
        for (int c = 0; c <= q; c++)
            store_point(h[c], out + ((size_t)c * (size_t)(p + 1) + (size_t)r) * 4);
    }
}

sw_status sw_nurbs_surface_to_bezier(const sw_nurbs_surface *s, double *ctrl_out,
                                     double *params_out, sw_error *err)
{
    sw_status st = sw_nurbs_surface_check(s, err);
    if (st != SW_OK)
        return st;
    int p = s->degree_u, q = s->degree_v;
    int pieces_u = sw_nurbs_span_count(p, s->count_u, s->knots_u);
    size_t patch_doubles = (size_t)(p + 1) * (size_t)(q + 1) * 4;
    int b = 0;
    for (int kv = q; kv < s->count_v; kv++) {
        if (!(s->knots_v[kv] < s->knots_v[kv + 1]))
            continue;
        int a = 0;
        for (int ku = p; ku < s->count_u; ku++) {
            if (!(s->knots_u[ku] < s->knots_u[ku + 1]))
                continue;
            patch_to_bezier(s, ku, kv, ctrl_out + ((size_t)b * pieces_u + a) * patch_doubles);
            params_out[2 * a] = s->knots_u[ku];
            params_out[2 * a + 1] = s->knots_u[ku + 1];
            a++;
        }
        params_out[2 * (pieces_u + b)] = s->knots_v[kv];
        params_out[2 * (pieces_u + b) + 1] = s->knots_v[kv + 1];
        b++;
    }
    return SW_OK;
}
