/* SPDX-License-Identifier: MIT */
/* IGES curve entities as exact NURBS pieces: 100 circular arc, 102
 * composite curve, 104 conic arc, 110 line, 112 parametric spline curve, 126
 * rational B-spline curve; each entity's 124 transform applied. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

int iges_is_curve(int type)
{
    return type == 100 || type == 102 || type == 104 || type == 110 || type == 112 ||
           type == 126;
}

/* 100: centre, start, end in the plane z = ZT, counterclockwise; start ==
 * end is a full circle. */
static sw_status read_arc(iges_reader *r, const iges_params *p, iges_curves *out)
{
    double v[7];
    sw_status st = iges_param_reals(r, p, 1, 7, "arc parameters (ZT, centre, start, end)", v);
    if (st != SW_OK)
        return st;
    sw_vec3 o = sw_v3(v[1], v[2], v[0]);
    double sx = v[3] - v[1], sy = v[4] - v[2], ex = v[5] - v[1], ey = v[6] - v[2];
    double radius = hypot(sx, sy);
    if (!(radius > 0))
        return iges_fail(r, p, 4, SW_ERR_FORMAT, "expected an arc start away from its centre");
    double a0 = atan2(sy, sx), a1 = atan2(ey, ex);
    if (fabs(sx - ex) <= 1e-12 * radius && fabs(sy - ey) <= 1e-12 * radius)
        a1 = a0 + 2 * SW_PI;
    while (a1 <= a0)
        a1 += 2 * SW_PI;
    iges_curve c;
    st = iges_curve_arc(r, &c, o, sw_v3(1, 0, 0), sw_v3(0, 1, 0), radius, a0, a1);
    return st == SW_OK ? iges_curves_push(r, out, &c) : st;
}

/* A conic piece as a rational quadratic: ends, tangent crossing, weight. */
static sw_status conic_piece(iges_reader *r, iges_curves *out, sw_vec3 a, sw_vec3 m, sw_vec3 b,
                             double w)
{
    iges_curve c;
    sw_status st = iges_curve_alloc(r, &c, 2, 3);
    if (st != SW_OK)
        return st;
    double k[6] = {0, 0, 0, 1, 1, 1};
    double pts[12] = {a.x, a.y, a.z, 1, m.x, m.y, m.z, w, b.x, b.y, b.z, 1};
    memcpy(c.knots, k, sizeof k);
    memcpy(c.ctrl, pts, sizeof pts);
    return iges_curves_push(r, out, &c);
}

/* Hyperbola s*a*cosh(t), b*sinh(t) (axes swapped when the y axis is the
 * transverse one) between t0 and t1, in pieces of at most 2 in t: the
 * weight cosh(h) keeps the pieces well conditioned. */
static sw_status hyperbola(iges_reader *r, iges_curves *out, double a, double b, double s,
                           int swap, double t0, double t1, double z)
{
    int n = (int)ceil(fabs(t1 - t0) / 2.0);
    n = n < 1 ? 1 : n > 64 ? 64 : n;
    sw_status st = SW_OK;
    for (int i = 0; i < n && st == SW_OK; i++) {
        double ta = t0 + (t1 - t0) * i / n, tb = t0 + (t1 - t0) * (i + 1) / n;
        double tm = 0.5 * (ta + tb), h = 0.5 * fabs(tb - ta);
        double pt[3][2] = {{s * a * cosh(ta), b * sinh(ta)},
                           {s * a * cosh(tm) / cosh(h), b * sinh(tm) / cosh(h)},
                           {s * a * cosh(tb), b * sinh(tb)}};
        sw_vec3 q[3];
        for (int k = 0; k < 3; k++)
            q[k] = swap ? sw_v3(pt[k][1], pt[k][0], z) : sw_v3(pt[k][0], pt[k][1], z);
        st = conic_piece(r, out, q[0], q[1], q[2], cosh(h));
    }
    return st;
}

/* 104 in standard position (IGES 5.3, 4.5): A x^2 + C y^2 + F = 0 for
 * ellipses and hyperbolas, A x^2 + E y = 0 or C y^2 + D x = 0 for parabolas;
 * from start to end (counterclockwise for ellipses). */
static sw_status read_conic(iges_reader *r, const iges_params *p, iges_curves *out)
{
    double v[11];
    sw_status st = iges_param_reals(r, p, 1, 11, "conic parameters (A..F, ZT, start, end)", v);
    if (st != SW_OK)
        return st;
    double A = v[0], C = v[2], D = v[3], E = v[4], F = v[5], z = v[6];
    double x1 = v[7], y1 = v[8], x2 = v[9], y2 = v[10];
    if (A != 0 && C != 0 && F != 0 && -F / A > 0 && -F / C > 0) {
        double a = sqrt(-F / A), b = sqrt(-F / C);
        double t0 = atan2(y1 / b, x1 / a), t1 = atan2(y2 / b, x2 / a);
        if (fabs(t1 - t0) < 1e-14)
            t1 = t0 + 2 * SW_PI;
        while (t1 <= t0)
            t1 += 2 * SW_PI;
        iges_curve c;
        st = iges_curve_arc(r, &c, sw_v3(0, 0, z), sw_v3(a, 0, 0), sw_v3(0, b, 0), 1.0, t0, t1);
        return st == SW_OK ? iges_curves_push(r, out, &c) : st;
    }
    if (A != 0 && C != 0 && F != 0 && (-F / A > 0) != (-F / C > 0)) {
        int swap = !(-F / A > 0);   /* transverse axis along y */
        double a = sqrt(fabs(F / (swap ? C : A))), b = sqrt(fabs(F / (swap ? A : C)));
        double xs = swap ? y1 : x1, ys = swap ? x1 : y1, ye = swap ? x2 : y2;
        return hyperbola(r, out, a, b, xs < 0 ? -1.0 : 1.0, swap, asinh(ys / b), asinh(ye / b),
                         z);
    }
    if (A != 0 && E != 0 && C == 0) {
        double k = -A / E, xm = 0.5 * (x1 + x2);
        return conic_piece(r, out, sw_v3(x1, k * x1 * x1, z), sw_v3(xm, k * x1 * x2, z),
                           sw_v3(x2, k * x2 * x2, z), 1.0);
    }
    if (C != 0 && D != 0 && A == 0) {
        double k = -C / D, ym = 0.5 * (y1 + y2);
        return conic_piece(r, out, sw_v3(k * y1 * y1, y1, z), sw_v3(k * y1 * y2, ym, z),
                           sw_v3(k * y2 * y2, y2, z), 1.0);
    }
    return iges_fail(r, p, 1, SW_ERR_FORMAT,
                     "expected a conic in standard position (A x^2 + C y^2 + F = 0, "
                     "A x^2 + E y = 0 or C y^2 + D x = 0), found A=%g B=%g C=%g D=%g E=%g F=%g",
                     A, v[1], C, D, E, F);
}

static sw_status read_line(iges_reader *r, const iges_params *p, iges_curves *out)
{
    double v[6];
    sw_status st = iges_param_reals(r, p, 1, 6, "line end points", v);
    if (st != SW_OK)
        return st;
    iges_curve c;
    st = iges_curve_line(r, &c, sw_v3(v[0], v[1], v[2]), sw_v3(v[3], v[4], v[5]), 0.0, 1.0);
    return st == SW_OK ? iges_curves_push(r, out, &c) : st;
}

/* 112: N cubic segments in power form on breakpoints T(1..N+1), written
 * AX BX CX DX AY .. DZ per segment in s = t - T(i); each becomes a cubic
 * Bezier, joined on triple knots. */
static sw_status read_spline_curve(iges_reader *r, const iges_params *p, iges_curves *out)
{
    int n, ndim;
    sw_status st = iges_param_int(r, p, 3, "NDIM", 2, 3, &ndim);
    if (st == SW_OK)
        st = iges_param_int(r, p, 4, "segment count N", 1, 100000, &n);
    if (st == SW_OK)
        st = iges_param_need(r, p, 5, (n + 1) + 12 * n, "breakpoints and coefficients");
    iges_curve c;
    if (st == SW_OK)
        st = iges_curve_alloc(r, &c, 3, 3 * n + 1);
    if (st != SW_OK)
        return st;
    for (int i = 0; i <= n && st == SW_OK; i++) {
        double t0, t1, cf[12];
        st = iges_param_real(r, p, 5 + i, "breakpoint", &t0);
        if (st != SW_OK || i == n)
            break;
        st = iges_param_real(r, p, 6 + i, "breakpoint", &t1);
        if (st == SW_OK)
            st = iges_param_reals(r, p, 6 + n + 12 * i, 12, "segment coefficients", cf);
        if (st == SW_OK && !(t1 > t0))
            st = iges_fail(r, p, 6 + i, SW_ERR_FORMAT, "expected increasing breakpoints");
        double d = t1 - t0;
        for (int k = 0; st == SW_OK && k < 3; k++) {
            const double *q = cf + 4 * k;   /* a + b s + c s^2 + d s^3 */
            double *pt = c.ctrl + (size_t)3 * i * 4 + k;
            pt[0] = q[0];
            pt[4] = q[0] + q[1] * d / 3;
            pt[8] = q[0] + 2 * q[1] * d / 3 + q[2] * d * d / 3;
            pt[12] = q[0] + q[1] * d + q[2] * d * d + q[3] * d * d * d;
            if (ndim == 2 && k == 2)
                pt[0] = pt[4] = pt[8] = pt[12] = 0;
        }
        for (int k = 0; k < 4; k++)
            c.ctrl[(3 * i + k) * 4 + 3] = 1.0;
        for (int k = 0; k < 3; k++)
            c.knots[1 + 3 * i + k] = t0;
        c.knots[0] = c.knots[1];
        c.knots[3 * n + 1] = c.knots[3 * n + 2] = c.knots[3 * n + 3] = c.knots[3 * n + 4] = t1;
    }
    if (st != SW_OK) {
        iges_curve_free(&c);
        return st;
    }
    return iges_curves_push(r, out, &c);
}

/* 126: K, M, PROP1..4, knots, weights, points, V(0), V(1), normal. */
static sw_status read_bspline_curve(iges_reader *r, const iges_params *p, iges_curves *out)
{
    int k = 0, m = 0, poly = 0;   /* read only on success, but n and nk below are computed first */
    sw_status st = iges_param_int(r, p, 1, "upper index K", 1, 10000000, &k);
    if (st == SW_OK)
        st = iges_param_int(r, p, 2, "degree M", 1, SW_BEZIER_MAX_DEGREE, &m);
    if (st == SW_OK)
        st = iges_param_int_or(r, p, 5, "PROP3 (polynomial)", 0, 1, 0, &poly);
    if (st == SW_OK && k < m)
        st = iges_fail(r, p, 1, SW_ERR_FORMAT, "expected K >= M (%d), found %d", m, k);
    int n = k + 1, nk = k + m + 2, base = 7;
    if (st == SW_OK)
        st = iges_param_need(r, p, base, nk, "knots");
    if (st == SW_OK)
        st = iges_param_need(r, p, base + nk, n, "weights");
    if (st == SW_OK)
        st = iges_param_need(r, p, base + nk + n, 3 * n, "control point coordinates");
    if (st == SW_OK)
        st = iges_param_need(r, p, base + nk + 4 * n, 2, "parameter range V(0), V(1)");
    iges_curve c;
    if (st == SW_OK)
        st = iges_curve_alloc(r, &c, m, n);
    if (st != SW_OK)
        return st;
    st = iges_param_reals(r, p, base, nk, "knots", c.knots);
    for (int i = 0; st == SW_OK && i < n; i++) {
        double w;
        st = iges_param_real(r, p, base + nk + i, "weight", &w);
        if (st == SW_OK)
            st = iges_param_reals(r, p, base + nk + n + 3 * i, 3, "control point", c.ctrl + 4 * i);
        if (st == SW_OK && !poly && !(w > 0))
            st = iges_fail(r, p, base + nk + i, SW_ERR_FORMAT, "expected a positive weight, found %g",
                           w);
        c.ctrl[4 * i + 3] = poly ? 1.0 : w;
    }
    for (int i = 0; st == SW_OK && i + 1 < nk; i++)
        if (!(c.knots[i] <= c.knots[i + 1]))
            st = iges_fail(r, p, base + i + 1, SW_ERR_FORMAT, "expected non-decreasing knots");
    double range[2];
    if (st == SW_OK)
        st = iges_param_reals(r, p, base + nk + 4 * n, 2, "parameter range", range);
    if (st == SW_OK)
        st = iges_curve_clamp(r, &c, range[0], range[1]);
    if (st != SW_OK) {
        iges_curve_free(&c);
        return st;
    }
    return iges_curves_push(r, out, &c);
}

/* 102: its curves in order, head to tail; points (116) in it are skipped. */
static sw_status read_composite(iges_reader *r, const iges_params *p, iges_curves *out)
{
    int n;
    sw_status st = iges_param_int(r, p, 1, "curve count N", 0, 1000000, &n);
    if (st == SW_OK)
        st = iges_param_need(r, p, 2, n, "curve pointers");
    for (int i = 0; st == SW_OK && i < n; i++) {
        int e;
        st = iges_param_entity(r, p, 2 + i, "curve", 0, &e);
        if (st == SW_OK && r->ents[e].type != 116)
            st = iges_read_curve(r, e, out);
    }
    return st;
}

static sw_status read_curve_params(iges_reader *r, int entity, iges_curves *out)
{
    iges_params p;
    sw_status st = iges_params_read(r, entity, &p);
    if (st == SW_OK) {
        switch (p.type) {
        case 100: st = read_arc(r, &p, out); break;
        case 102: st = read_composite(r, &p, out); break;
        case 104: st = read_conic(r, &p, out); break;
        case 110: st = read_line(r, &p, out); break;
        case 112: st = read_spline_curve(r, &p, out); break;
        default: st = read_bspline_curve(r, &p, out); break;
        }
    }
    iges_params_free(&p);
    return st;
}

sw_status iges_read_curve(iges_reader *r, int entity, iges_curves *out)
{
    if (!iges_is_curve(r->ents[entity].type))
        return iges_unsupported(r, entity, "a curve");
    sw_status st = iges_enter(r, entity);
    if (st != SW_OK)
        return st;
    iges_curves mine = {0};
    sw_mat4 m;
    st = read_curve_params(r, entity, &mine);
    if (st == SW_OK)
        st = iges_entity_matrix(r, entity, &m);
    for (int i = 0; st == SW_OK && i < mine.count; i++)
        iges_curve_transform(&mine.items[i], &m);
    if (st == SW_OK)
        st = iges_curves_append(r, out, &mine);
    iges_curves_free(&mine);
    iges_leave(r, entity);
    return st;
}
