/* SPDX-License-Identifier: MIT */
/* IGES surface entities as one clamped NURBS surface each: 128 rational
 * B-spline surface (periodic and unclamped knots clamped to its U/V range),
 * 114 parametric spline surface (bicubic power-form patches made Bezier),
 * 120 surface of revolution and 122 tabulated cylinder (exact rational
 * forms); each entity's 124 transform applied. The surface remembers how the
 * entity's own parameters map to ours, for the trims written in them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

int iges_is_surface(int type)
{
    return type == 114 || type == 120 || type == 122 || type == 128;
}

static sw_status check_knots(iges_reader *r, const iges_params *p, int first, int n)
{
    for (int i = first; i + 1 < first + n; i++)
        if (!(p->tok[i].num <= p->tok[i + 1].num))
            return iges_fail(r, p, i + 1, SW_ERR_FORMAT, "expected non-decreasing knots");
    return SW_OK;
}

/* 128: K1, K2, M1, M2, PROP1..5, knots S and T, weights, points, U0, U1,
 * V0, V1 (IGES 5.3, 4.24). */
static sw_status read_bspline_surface(iges_reader *r, const iges_params *p, iges_surface *s)
{
    int k1, k2, m1, m2, poly;
    sw_status st = iges_param_int(r, p, 1, "upper index K1", 1, 10000000, &k1);
    if (st == SW_OK)
        st = iges_param_int(r, p, 2, "upper index K2", 1, 10000000, &k2);
    if (st == SW_OK)
        st = iges_param_int(r, p, 3, "degree M1", 1, SW_BEZIER_MAX_DEGREE, &m1);
    if (st == SW_OK)
        st = iges_param_int(r, p, 4, "degree M2", 1, SW_BEZIER_MAX_DEGREE, &m2);
    if (st == SW_OK)
        st = iges_param_int_or(r, p, 7, "PROP3 (polynomial)", 0, 1, 0, &poly);
    if (st == SW_OK && (k1 < m1 || k2 < m2))
        st = iges_fail(r, p, 1, SW_ERR_FORMAT, "expected K1 >= M1 and K2 >= M2, found %d, %d, "
                       "%d, %d", k1, k2, m1, m2);
    if (st != SW_OK)
        return st;
    int nu = k1 + 1, nv = k2 + 1, a = k1 + m1 + 2, b = k2 + m2 + 2, base = 10;
    double npts = (double)nu * nv;
    if (npts > 1e7)
        return iges_fail(r, p, 1, SW_ERR_FORMAT, "expected fewer than 1e7 control points");
    int w0 = base + a + b, p0 = w0 + nu * nv, r0 = p0 + 3 * nu * nv;
    st = iges_param_need(r, p, base, a, "knots in u");
    if (st == SW_OK)
        st = iges_param_need(r, p, base + a, b, "knots in v");
    if (st == SW_OK)
        st = iges_param_need(r, p, w0, nu * nv, "weights");
    if (st == SW_OK)
        st = iges_param_need(r, p, p0, 3 * nu * nv, "control point coordinates");
    if (st == SW_OK)
        st = iges_param_need(r, p, r0, 4, "parameter ranges U0, U1, V0, V1");
    if (st == SW_OK)
        st = iges_surface_alloc(r, s, m1, m2, nu, nv);
    if (st == SW_OK)
        st = iges_param_reals(r, p, base, a, "knots in u", s->knots_u);
    if (st == SW_OK)
        st = iges_param_reals(r, p, base + a, b, "knots in v", s->knots_v);
    if (st == SW_OK)
        st = check_knots(r, p, base, a);
    if (st == SW_OK)
        st = check_knots(r, p, base + a, b);
    for (int i = 0; st == SW_OK && i < nu * nv; i++) {
        double w;
        st = iges_param_real(r, p, w0 + i, "weight", &w);
        if (st == SW_OK)
            st = iges_param_reals(r, p, p0 + 3 * i, 3, "control point", s->ctrl + 4 * i);
        if (st == SW_OK && !poly && !(w > 0))
            st = iges_fail(r, p, w0 + i, SW_ERR_FORMAT, "expected a positive weight, found %g",
                           w);
        s->ctrl[4 * i + 3] = poly ? 1.0 : w;
    }
    double range[4];
    if (st == SW_OK)
        st = iges_param_reals(r, p, r0, 4, "parameter ranges", range);
    if (st == SW_OK)
        st = iges_surface_clamp(r, s, range[0], range[1], range[2], range[3]);
    return st;
}

/* Power form a_kl s^k t^l (k + 4 l) on [0, du] x [0, dv] to the bicubic
 * Bezier points of the unit square: b_ij = sum a_kl C(i,k) C(j,l) /
 * (C(3,k) C(3,l)) with a_kl scaled by du^k dv^l. */
static void power_to_bezier(const double *a, double du, double dv, double b[16])
{
    static const double binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    double su[4] = {1, du, du * du, du * du * du}, sv[4] = {1, dv, dv * dv, dv * dv * dv};
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            double sum = 0;
            for (int l = 0; l <= j; l++)
                for (int k = 0; k <= i; k++)
                    sum += a[k + 4 * l] * su[k] * sv[l] * binom[i][k] * binom[j][l] /
                           (binom[3][k] * binom[3][l]);
            b[i + 4 * j] = sum;
        }
}

static void spline_knots(double *knots, const double *breaks, int segs)
{
    for (int i = 0; i < segs; i++)
        knots[1 + 3 * i] = knots[2 + 3 * i] = knots[3 + 3 * i] = breaks[i];
    knots[0] = breaks[0];
    for (int k = 0; k < 4; k++)
        knots[3 * segs + 1 + k] = breaks[segs];
}

/* 114: CTYPE, PTYPE, M, N, TU(1..M+1), TV(1..N+1), then per u segment i
 * the N patches' 48 coefficients and 48 unused ones (IGES 5.3, 4.14). */
static sw_status read_spline_surface(iges_reader *r, const iges_params *p, iges_surface *s)
{
    int m = 0, n = 0;   /* base below is computed before the checks */
    sw_status st = iges_param_int(r, p, 3, "u segment count M", 1, 3000, &m);
    if (st == SW_OK)
        st = iges_param_int(r, p, 4, "v segment count N", 1, 3000, &n);
    int base = 5 + m + 1 + n + 1;
    if (st == SW_OK)
        st = iges_param_need(r, p, 5, m + n + 2, "breakpoints");
    if (st == SW_OK)
        st = iges_param_need(r, p, base, ((m - 1) * (n + 1) + n) * 48, "patch coefficients");
    double *breaks = st == SW_OK ? malloc((size_t)(m + n + 2) * sizeof(double)) : NULL;
    if (st == SW_OK && !breaks)
        st = sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory", r->file);
    if (st == SW_OK)
        st = iges_param_reals(r, p, 5, m + n + 2, "breakpoints", breaks);
    for (int i = 0; st == SW_OK && i < m + n + 1; i++)
        if (i != m && !(breaks[i] < breaks[i + 1]))
            st = iges_fail(r, p, 6 + i, SW_ERR_FORMAT, "expected increasing breakpoints");
    if (st == SW_OK)
        st = iges_surface_alloc(r, s, 3, 3, 3 * m + 1, 3 * n + 1);
    for (int i = 0; st == SW_OK && i < m; i++)
        for (int j = 0; st == SW_OK && j < n; j++) {
            double cf[48], b[16];
            st = iges_param_reals(r, p, base + (i * (n + 1) + j) * 48, 48, "coefficients", cf);
            double du = breaks[i + 1] - breaks[i], dv = breaks[m + 2 + j] - breaks[m + 1 + j];
            for (int k = 0; st == SW_OK && k < 3; k++) {
                power_to_bezier(cf + 16 * k, du, dv, b);
                for (int jj = 0; jj < 4; jj++)
                    for (int ii = 0; ii < 4; ii++) {
                        size_t at = ((size_t)(3 * j + jj) * s->count_u + 3 * i + ii) * 4;
                        s->ctrl[at + k] = b[ii + 4 * jj];
                        s->ctrl[at + 3] = 1.0;
                    }
            }
        }
    if (st == SW_OK) {
        spline_knots(s->knots_u, breaks, m);
        spline_knots(s->knots_v, breaks + m + 1, n);
    }
    free(breaks);
    return st;
}

/* Rotation about the unit axis d through o by angle a (Rodrigues). */
static sw_vec3 rotate(sw_vec3 q, sw_vec3 o, sw_vec3 d, double a)
{
    sw_vec3 v = sw_v3_sub(q, o);
    double c = cos(a), s = sin(a);
    sw_vec3 r = sw_v3_add(sw_v3_scale(v, c), sw_v3_scale(sw_v3_cross(d, v), s));
    r = sw_v3_add(r, sw_v3_scale(d, sw_v3_dot(d, v) * (1 - c)));
    return sw_v3_add(o, r);
}

/* Surface of revolution: each generatrix point swept along the rational
 * arc (The NURBS Book, 8.5): the arc's odd points lie 1 / cos(h) out from
 * the axis, weights multiply. */
static void revolve(iges_surface *s, const iges_curve *g, sw_vec3 o, sw_vec3 d, double a0,
                    double a1)
{
    int n = iges_arc_pieces(a1 - a0), cv = 2 * n + 1;
    double step = (a1 - a0) / n, w = cos(0.5 * step);
    for (int i = 0; i < g->count; i++) {
        const double *c = g->ctrl + 4 * i;
        sw_vec3 q = sw_v3(c[0], c[1], c[2]);
        sw_vec3 foot = sw_v3_add(o, sw_v3_scale(d, sw_v3_dot(sw_v3_sub(q, o), d)));
        for (int j = 0; j < cv; j++) {
            double ang = a0 + 0.5 * step * j, scale = j % 2 ? 1.0 / w : 1.0;
            sw_vec3 pt = rotate(q, foot, d, ang);
            pt = sw_v3_add(foot, sw_v3_scale(sw_v3_sub(pt, foot), scale));
            double *out = s->ctrl + ((size_t)j * g->count + i) * 4;
            out[0] = pt.x, out[1] = pt.y, out[2] = pt.z, out[3] = c[3] * (j % 2 ? w : 1.0);
        }
    }
    memcpy(s->knots_u, g->knots, (size_t)(g->count + g->degree + 1) * sizeof(double));
    for (int k = 0; k < 3; k++)
        s->knots_v[k] = 0, s->knots_v[2 * n + 1 + k] = n;
    for (int k = 1; k < n; k++)
        s->knots_v[2 * k + 1] = s->knots_v[2 * k + 2] = k;
}

/* A curve entity as a single NURBS (pieces joined). */
static sw_status joined_curve(iges_reader *r, int entity, iges_curve *out)
{
    iges_curves pieces = {0};
    sw_status st = iges_read_curve(r, entity, &pieces);
    if (st == SW_OK)
        st = iges_curves_join(r, &pieces, out);
    iges_curves_free(&pieces);
    return st;
}

/* 120: axis line L, generatrix C, start and end angles; S(t, theta) is C(t)
 * turned by theta about L (IGES 5.3, 4.18). */
static sw_status read_revolution(iges_reader *r, const iges_params *p, iges_surface *s)
{
    int axis_e, gen_e;
    double ang[2];
    sw_status st = iges_param_entity(r, p, 1, "axis", 0, &axis_e);
    if (st == SW_OK)
        st = iges_param_entity(r, p, 2, "generatrix", 0, &gen_e);
    if (st == SW_OK)
        st = iges_param_reals(r, p, 3, 2, "start and end angles", ang);
    if (st == SW_OK && !(ang[1] > ang[0] && ang[1] - ang[0] <= 2 * SW_PI + 1e-9))
        st = iges_fail(r, p, 3, SW_ERR_FORMAT,
                       "expected 0 < end angle - start angle <= 2 pi, found %g, %g", ang[0], ang[1]);
    if (st == SW_OK && r->ents[axis_e].type != 110)
        st = iges_fail(r, p, 1, SW_ERR_FORMAT, "expected the axis to be a line (110), found %d",
                       r->ents[axis_e].type);
    iges_curve axis = {0}, gen = {0};
    if (st == SW_OK)
        st = joined_curve(r, axis_e, &axis);
    if (st == SW_OK)
        st = joined_curve(r, gen_e, &gen);
    sw_vec3 o = sw_v3(0, 0, 0), d = o;
    if (st == SW_OK) {
        o = sw_v3(axis.ctrl[0], axis.ctrl[1], axis.ctrl[2]);
        d = sw_v3_sub(sw_v3(axis.ctrl[4], axis.ctrl[5], axis.ctrl[6]), o);
        if (!(sw_v3_length(d) > 0))
            st = iges_fail(r, p, 1, SW_ERR_FORMAT, "expected an axis of non-zero length");
    }
    if (st == SW_OK)
        st = iges_surface_alloc(r, s, gen.degree, 2, gen.count, 2 * iges_arc_pieces(ang[1] - ang[0]) + 1);
    if (st == SW_OK) {
        revolve(s, &gen, o, sw_v3_normalize(d), ang[0], ang[1]);
        s->angle_v = 1, s->angle_start = ang[0], s->angle_end = ang[1];
    }
    iges_curve_free(&axis);
    iges_curve_free(&gen);
    return st;
}

/* 122: directrix C and the generatrix's end L; S(u, v) = C(t) + v (L -
 * C(t0)) with u in [0, 1] spanning C's range (IGES 5.3, 4.19). */
static sw_status read_cylinder(iges_reader *r, const iges_params *p, iges_surface *s)
{
    int dir_e;
    double l[3];
    sw_status st = iges_param_entity(r, p, 1, "directrix", 0, &dir_e);
    if (st == SW_OK)
        st = iges_param_reals(r, p, 2, 3, "generatrix end point", l);
    iges_curve c = {0};
    if (st == SW_OK)
        st = joined_curve(r, dir_e, &c);
    if (st == SW_OK)
        st = iges_surface_alloc(r, s, c.degree, 1, c.count, 2);
    if (st == SW_OK) {
        sw_vec3 start = sw_v3(c.ctrl[0], c.ctrl[1], c.ctrl[2]);   /* clamped: C(t0) */
        sw_vec3 shift = sw_v3_sub(sw_v3(l[0], l[1], l[2]), start);
        for (int i = 0; i < c.count; i++) {
            double *a = s->ctrl + (size_t)i * 4, *b = s->ctrl + ((size_t)c.count + i) * 4;
            memcpy(a, c.ctrl + 4 * i, 4 * sizeof(double));
            b[0] = a[0] + shift.x, b[1] = a[1] + shift.y, b[2] = a[2] + shift.z, b[3] = a[3];
        }
        memcpy(s->knots_u, c.knots, (size_t)(c.count + c.degree + 1) * sizeof(double));
        double kv[4] = {0, 0, 1, 1};
        memcpy(s->knots_v, kv, sizeof kv);
        double t0 = c.knots[c.degree], t1 = c.knots[c.count];
        s->map_u[0] = t0, s->map_u[1] = t1 - t0;
    }
    iges_curve_free(&c);
    return st;
}

static sw_status read_surface_params(iges_reader *r, int entity, iges_surface *s)
{
    iges_params p;
    sw_status st = iges_params_read(r, entity, &p);
    if (st == SW_OK) {
        switch (p.type) {
        case 114: st = read_spline_surface(r, &p, s); break;
        case 120: st = read_revolution(r, &p, s); break;
        case 122: st = read_cylinder(r, &p, s); break;
        default: st = read_bspline_surface(r, &p, s); break;
        }
    }
    iges_params_free(&p);
    return st;
}

sw_status iges_read_surface(iges_reader *r, int entity, iges_surface *s)
{
    memset(s, 0, sizeof *s);
    s->map_u[1] = s->map_v[1] = 1.0;
    if (!iges_is_surface(r->ents[entity].type))
        return iges_unsupported(r, entity, "a surface");
    sw_status st = iges_enter(r, entity);
    if (st != SW_OK)
        return st;
    sw_mat4 m;
    st = read_surface_params(r, entity, s);
    if (st == SW_OK)
        st = iges_entity_matrix(r, entity, &m);
    if (st == SW_OK)
        iges_surface_transform(s, &m);
    if (st != SW_OK)
        iges_surface_free(s);
    iges_leave(r, entity);
    return st;
}
