/* SPDX-License-Identifier: MIT */
#include "sw_normal_cone.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* A polynomial in "scaled Bernstein" form: coefficient (i, j) times
 * C(deg_u, i) C(deg_v, j). Products of such forms are plain convolutions
 * of their coefficients, and the scaling is positive, so the directions of
 * the final coefficients, all the cone needs, never have to be unscaled.
 * mag[k] bounds the coefficient's length plus everything that rounding can
 * have moved it by, over ROUNDING_ULPS. */
typedef struct poly {
    int nu, nv;              /* coefficients along u and v: degree + 1 */
    double *c;               /* 3 per coefficient (vectors) or 1 (scalars), j * nu + i */
    double *mag;             /* one per coefficient */
} poly;

static double binom(int n, int k)
{
    double r = 1;
    for (int i = 1; i <= k; i++)
        r = r * (n - k + i) / i;
    return r;
}

static size_t poly_doubles(int nu, int nv, int dim) { return (size_t)nu * nv * (dim + 1); }

size_t sw_normal_cone_scratch_doubles(int degree_u, int degree_v)
{
    int m = degree_u, n = degree_v;
    return poly_doubles(m + 1, n + 1, 3) + poly_doubles(m, n + 1, 3) +  /* X, X_u */
           poly_doubles(m + 1, n, 3) + poly_doubles(m + 1, n + 1, 1) + /* X_v, W */
           poly_doubles(m, n + 1, 1) + poly_doubles(m + 1, n, 1) +     /* W_u, W_v */
           poly_doubles(2 * m, 2 * n, 3) + poly_doubles(2 * m + 1, 2 * n, 3) +
           poly_doubles(2 * m, 2 * n + 1, 3) + poly_doubles(3 * m, 3 * n, 3);
}

static poly poly_take(double **scratch, int nu, int nv, int dim)
{
    poly p = { nu, nv, *scratch, *scratch + (size_t)nu * nv * dim };
    memset(*scratch, 0, poly_doubles(nu, nv, dim) * sizeof(double));
    *scratch += poly_doubles(nu, nv, dim);
    return p;
}

static double len3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* out += a (vectors) convolved with b (vectors) under the cross product. */
static void conv_cross(const poly *a, const poly *b, poly *out)
{
    for (int ja = 0; ja < a->nv; ja++)
        for (int ia = 0; ia < a->nu; ia++) {
            const double *x = a->c + 3 * (ja * a->nu + ia);
            double mx = a->mag[ja * a->nu + ia];
            for (int jb = 0; jb < b->nv; jb++)
                for (int ib = 0; ib < b->nu; ib++) {
                    const double *y = b->c + 3 * (jb * b->nu + ib);
                    int k = (ja + jb) * out->nu + ia + ib;
                    double *o = out->c + 3 * k;
                    o[0] += x[1] * y[2] - x[2] * y[1];
                    o[1] += x[2] * y[0] - x[0] * y[2];
                    o[2] += x[0] * y[1] - x[1] * y[0];
                    out->mag[k] += mx * b->mag[jb * b->nu + ib];
                }
        }
}

/* out += s (scalars) convolved with v (vectors). */
static void conv_scale(const poly *s, const poly *v, poly *out)
{
    for (int js = 0; js < s->nv; js++)
        for (int is = 0; is < s->nu; is++) {
            double w = s->c[js * s->nu + is], mw = s->mag[js * s->nu + is];
            for (int jv = 0; jv < v->nv; jv++)
                for (int iv = 0; iv < v->nu; iv++) {
                    const double *y = v->c + 3 * (jv * v->nu + iv);
                    int k = (js + jv) * out->nu + is + iv;
                    for (int d = 0; d < 3; d++)
                        out->c[3 * k + d] += w * y[d];
                    out->mag[k] += mw * v->mag[jv * v->nu + iv];
                }
        }
}

/* A control point's weighted position X = w (p - origin) and weight W. */
typedef struct homog { double x[3], w; } homog;

static homog control(const sw_bezier_patchf *p, int i, int j, const double origin[3])
{
    const float *c = p->ctrl + 4 * (j * (p->degree_u + 1) + i);
    homog h;
    h.w = p->rational ? (double)c[3] : 1.0;
    for (int d = 0; d < 3; d++)
        h.x[d] = h.w * ((double)c[d] - origin[d]);
    return h;
}

/* The control points and weights in scaled form, and their first
 * differences along u (du = 1) or v (du = 0). Magnitudes are sums of the
 * operands' lengths: a difference's rounding is relative to those, not to
 * the (possibly cancelling) result. */
static void fill_points(const sw_bezier_patchf *p, const double origin[3], poly *x, poly *w)
{
    int m = p->degree_u, n = p->degree_v;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= m; i++) {
            homog h = control(p, i, j, origin);
            double s = binom(m, i) * binom(n, j);
            int k = j * (m + 1) + i;
            for (int d = 0; d < 3; d++)
                x->c[3 * k + d] = s * h.x[d];
            x->mag[k] = s * len3(h.x);
            w->c[k] = s * h.w, w->mag[k] = s * h.w;
        }
}

static void fill_differences(const sw_bezier_patchf *p, const double origin[3], int along_u,
                             poly *x, poly *w)
{
    int m = p->degree_u, n = p->degree_v;
    for (int j = 0; j < x->nv; j++)
        for (int i = 0; i < x->nu; i++) {
            homog a = control(p, i, j, origin);
            homog b = control(p, i + along_u, j + !along_u, origin);
            double s = binom(along_u ? m - 1 : m, i) * binom(along_u ? n : n - 1, j);
            int k = j * x->nu + i;
            for (int d = 0; d < 3; d++)
                x->c[3 * k + d] = s * (b.x[d] - a.x[d]);
            x->mag[k] = s * (len3(a.x) + len3(b.x));
            if (w)
                w->c[k] = s * (b.w - a.w), w->mag[k] = s * (a.w + b.w);
        }
}

/* The rounding error of a - b, exactly (Knuth's TwoSum). */
static double difference_error(double a, double b)
{
    double s = a - b, bb = s - a, aa = s - bb;
    return (a - aa) + (-b - bb);
}

/* The origin the control points are taken from: the first one, when every
 * coordinate's difference from it is exact in double (float minus float
 * nearly always is), which keeps the coefficients small; else 0. */
static void choose_origin(const sw_bezier_patchf *p, double origin[3])
{
    int count = (p->degree_u + 1) * (p->degree_v + 1);
    for (int d = 0; d < 3; d++)
        origin[d] = p->ctrl[d];
    for (int k = 0; k < count; k++)
        for (int d = 0; d < 3; d++)
            if (difference_error(p->ctrl[4 * k + d], origin[d]) != 0) {
                origin[0] = origin[1] = origin[2] = 0;
                return;
            }
}

static int all_weights_equal(const sw_bezier_patchf *p)
{
    int count = (p->degree_u + 1) * (p->degree_v + 1);
    for (int k = 1; p->rational && k < count; k++)
        if (p->ctrl[4 * k + 3] != p->ctrl[3])
            return 0;
    return 1;
}

static sw_normal_cone full_sphere(void)
{
    sw_normal_cone c = { sw_v3(0, 0, 0), 2 * SW_CONE_FULL };
    return c;
}

/* The smallest angle, with a margin for its own rounding, between axis and
 * any vector within slack of v (|v| > slack). */
static double widened_angle(sw_vec3 axis, sw_vec3 v, double length, double slack)
{
    double angle = atan2(sw_v3_length(sw_v3_cross(axis, v)), sw_v3_dot(axis, v));
    return angle + asin(slack / length) + 1e-12;
}

/* The cone of N's coefficients. rounding_ulps: how many units of rounding
 * each coefficient's magnitude may have lost (a bound on the terms summed
 * and the operations on each). */
static sw_normal_cone cone_of(const poly *nrm, double rounding_ulps)
{
    int count = nrm->nu * nrm->nv;
    sw_vec3 sum = sw_v3(0, 0, 0);
    for (int k = 0; k < count; k++) {
        sw_vec3 v = sw_v3(nrm->c[3 * k], nrm->c[3 * k + 1], nrm->c[3 * k + 2]);
        double l = sw_v3_length(v), slack = rounding_ulps * DBL_EPSILON * nrm->mag[k];
        if (l == 0 && slack == 0)
            continue; /* exactly zero: adds nothing to any normal */
        if (!(l > slack))
            return full_sphere(); /* its direction is not known */
        sum = sw_v3_add(sum, sw_v3_scale(v, 1.0 / l));
    }
    double sum_length = sw_v3_length(sum);
    if (!(sum_length > 1e-6))
        return full_sphere();
    sw_normal_cone cone = { sw_v3_scale(sum, 1.0 / sum_length), 0 };
    for (int k = 0; k < count; k++) {
        sw_vec3 v = sw_v3(nrm->c[3 * k], nrm->c[3 * k + 1], nrm->c[3 * k + 2]);
        double l = sw_v3_length(v), slack = rounding_ulps * DBL_EPSILON * nrm->mag[k];
        if (l == 0 && slack == 0)
            continue;
        cone.half_angle = fmax(cone.half_angle, widened_angle(cone.axis, v, l, slack));
    }
    return cone.half_angle < SW_CONE_FULL ? cone : full_sphere();
}

sw_normal_cone sw_normal_cone_of_patch(const sw_bezier_patchf *patch, double *scratch)
{
    int m = patch->degree_u, n = patch->degree_v;
    double origin[3];
    choose_origin(patch, origin);
    poly x = poly_take(&scratch, m + 1, n + 1, 3), w = poly_take(&scratch, m + 1, n + 1, 1);
    poly xu = poly_take(&scratch, m, n + 1, 3), wu = poly_take(&scratch, m, n + 1, 1);
    poly xv = poly_take(&scratch, m + 1, n, 3), wv = poly_take(&scratch, m + 1, n, 1);
    fill_points(patch, origin, &x, &w);
    fill_differences(patch, origin, 1, &xu, &wu);
    fill_differences(patch, origin, 0, &xv, &wv);
    /* Every coefficient sums at most this many products of at most three
     * rounded factors, each a few operations deep: a generous bound. */
    double terms = 3.0 * (m + 1) * (m + 1) * (n + 1) * (n + 1);
    double ulps = 8 * terms + 64;
    poly a = poly_take(&scratch, 2 * m, 2 * n, 3);
    conv_cross(&xu, &xv, &a);
    if (all_weights_equal(patch))
        return cone_of(&a, ulps); /* N = W^2 (P_u x P_v): the weights cancel */
    poly b = poly_take(&scratch, 2 * m + 1, 2 * n, 3), c = poly_take(&scratch, 2 * m, 2 * n + 1, 3);
    conv_cross(&xv, &x, &b);
    conv_cross(&x, &xu, &c);
    poly nrm = poly_take(&scratch, 3 * m, 3 * n, 3);
    conv_scale(&w, &a, &nrm);
    conv_scale(&wu, &b, &nrm);
    conv_scale(&wv, &c, &nrm);
    return cone_of(&nrm, ulps);
}

sw_normal_cone sw_normal_cone_empty(void)
{
    sw_normal_cone c = { sw_v3(0, 0, 0), -1 };
    return c;
}

/* The cone around unit axis holding a and b: each lies within its axis'
 * angle to axis plus its own half-angle (the triangle inequality on the
 * sphere). */
static sw_normal_cone cover(sw_vec3 axis, const sw_normal_cone *a, const sw_normal_cone *b)
{
    sw_normal_cone u = { axis, 0 };
    for (int k = 0; k < 2; k++) {
        const sw_normal_cone *c = k ? b : a;
        double to_axis = atan2(sw_v3_length(sw_v3_cross(u.axis, c->axis)),
                               sw_v3_dot(u.axis, c->axis));
        u.half_angle = fmax(u.half_angle, to_axis + c->half_angle + 1e-12);
    }
    return u.half_angle < SW_CONE_FULL ? u : full_sphere();
}

/* 1 with *out the union when a or b is empty or the full sphere. */
static int trivial_union(const sw_normal_cone *a, const sw_normal_cone *b, sw_normal_cone *out)
{
    if (a->half_angle < 0 || b->half_angle < 0)
        *out = a->half_angle < 0 ? *b : *a;
    else if (a->half_angle >= SW_CONE_FULL || b->half_angle >= SW_CONE_FULL)
        *out = full_sphere();
    else
        return 0;
    return 1;
}

sw_normal_cone sw_normal_cone_union(const sw_normal_cone *a, const sw_normal_cone *b)
{
    sw_normal_cone u;
    if (trivial_union(a, b, &u))
        return u;
    sw_vec3 sum = sw_v3_add(a->axis, b->axis);
    double l = sw_v3_length(sum);
    if (!(l > 1e-9))
        return full_sphere();
    return cover(sw_v3_scale(sum, 1.0 / l), a, b);
}

/* The smallest cap holding two caps: its axis on the great circle through
 * theirs, its rim touching both rims, half-angle (theta + ra + rb) / 2
 * (theta the angle between the axes), unless one already holds the other.
 * The half-angle is measured again from the axis as rounded (cover), so
 * the result holds both whatever the rounding. */
sw_normal_cone sw_normal_cone_union_tight(const sw_normal_cone *a, const sw_normal_cone *b)
{
    sw_normal_cone u;
    if (trivial_union(a, b, &u))
        return u;
    double theta = atan2(sw_v3_length(sw_v3_cross(a->axis, b->axis)), sw_v3_dot(a->axis, b->axis));
    if (theta + b->half_angle <= a->half_angle)
        return *a;
    if (theta + a->half_angle <= b->half_angle)
        return *b;
    double r = 0.5 * (theta + a->half_angle + b->half_angle);
    sw_vec3 t = sw_v3_sub(b->axis, sw_v3_scale(a->axis, sw_v3_dot(a->axis, b->axis)));
    double lt = sw_v3_length(t);
    if (!(r < SW_CONE_FULL) || !(lt > 1e-12))
        return full_sphere();
    double turn = r - a->half_angle; /* from a's axis towards b's */
    sw_vec3 axis = sw_v3_add(sw_v3_scale(a->axis, cos(turn)), sw_v3_scale(t, sin(turn) / lt));
    return cover(sw_v3_scale(axis, 1.0 / sw_v3_length(axis)), a, b);
}

int sw_normal_cone_back_facing(const sw_normal_cone *cone, const sw_box *box, sw_vec3 eye,
                               double margin_rad)
{
    double widest = cone->half_angle + margin_rad;
    if (cone->half_angle < 0 || !(widest < SW_CONE_FULL) || sw_box_is_empty(box))
        return 0;
    /* Every n in the cone faces away from every d = eye - p, p in the box,
     * when the box of those d lies in the cone around -axis of half-angle
     * 90 degrees - widest; that cone is convex, so its 8 corners decide. */
    double s = sin(widest);
    for (int i = 0; i < 8; i++) {
        sw_vec3 c = sw_v3(i & 1 ? box->max.x : box->min.x, i & 2 ? box->max.y : box->min.y,
                          i & 4 ? box->max.z : box->min.z);
        sw_vec3 d = sw_v3_sub(eye, c);
        if (!(-sw_v3_dot(cone->axis, d) > sw_v3_length(d) * s * (1 + 1e-12)))
            return 0;
    }
    return 1;
}
