/* SPDX-License-Identifier: MIT */
/* The IGES reader's owned NURBS: allocation, clamping of periodic and
 * unclamped knot vectors by knot insertion (Boehm; The NURBS Book, 5.2),
 * transforms, reversal, and the exact rational forms of lines and circular
 * arcs the analytic entities are built from. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

sw_status iges_curve_alloc(iges_reader *r, iges_curve *c, int degree, int count)
{
    memset(c, 0, sizeof *c);
    if (degree < 1 || degree > SW_BEZIER_MAX_DEGREE || count < degree + 1 || count > 10000000)
        return sw_error_set(r->err, SW_ERR_RANGE,
                            "%s: curve of degree %d with %d control points, expected degree "
                            "1..%d and more points than the degree",
                            r->file, degree, count, SW_BEZIER_MAX_DEGREE);
    c->degree = degree, c->count = count;
    c->knots = malloc((size_t)(count + degree + 1) * sizeof(double));
    c->ctrl = malloc((size_t)count * 4 * sizeof(double));
    if (!c->knots || !c->ctrl) {
        iges_curve_free(c);
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for a curve", r->file);
    }
    return SW_OK;
}

void iges_curve_free(iges_curve *c)
{
    free(c->knots);
    free(c->ctrl);
    c->knots = c->ctrl = NULL;
}

sw_status iges_curves_push(iges_reader *r, iges_curves *list, iges_curve *c)
{
    if (list->count == list->cap) {
        int cap = list->cap ? 2 * list->cap : 8;
        iges_curve *bigger = realloc(list->items, (size_t)cap * sizeof *bigger);
        if (!bigger) {
            iges_curve_free(c);
            return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for curves",
                                r->file);
        }
        list->items = bigger, list->cap = cap;
    }
    list->items[list->count++] = *c;
    memset(c, 0, sizeof *c);
    return SW_OK;
}

sw_status iges_curves_append(iges_reader *r, iges_curves *dst, iges_curves *src)
{
    sw_status st = SW_OK;
    for (int i = 0; i < src->count; i++)
        if (st == SW_OK)
            st = iges_curves_push(r, dst, &src->items[i]);
        else
            iges_curve_free(&src->items[i]);
    src->count = 0;
    return st;
}

void iges_curves_free(iges_curves *list)
{
    for (int i = 0; i < list->count; i++)
        iges_curve_free(&list->items[i]);
    free(list->items);
    memset(list, 0, sizeof *list);
}

sw_status iges_surface_alloc(iges_reader *r, iges_surface *s, int du, int dv, int cu, int cv)
{
    memset(s, 0, sizeof *s);
    s->map_u[1] = s->map_v[1] = 1.0;
    if (du < 1 || du > SW_BEZIER_MAX_DEGREE || dv < 1 || dv > SW_BEZIER_MAX_DEGREE ||
        cu < du + 1 || cv < dv + 1 || (double)cu * cv > 1e7)
        return sw_error_set(r->err, SW_ERR_RANGE,
                            "%s: surface of degree %d x %d with %d x %d control points, "
                            "expected degrees 1..%d and more points than the degree",
                            r->file, du, dv, cu, cv, SW_BEZIER_MAX_DEGREE);
    s->degree_u = du, s->degree_v = dv, s->count_u = cu, s->count_v = cv;
    s->knots_u = malloc((size_t)(cu + du + 1) * sizeof(double));
    s->knots_v = malloc((size_t)(cv + dv + 1) * sizeof(double));
    s->ctrl = malloc((size_t)cu * (size_t)cv * 4 * sizeof(double));
    if (!s->knots_u || !s->knots_v || !s->ctrl) {
        iges_surface_free(s);
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for a surface",
                            r->file);
    }
    return SW_OK;
}

void iges_surface_free(iges_surface *s)
{
    free(s->knots_u);
    free(s->knots_v);
    free(s->ctrl);
    s->knots_u = s->knots_v = s->ctrl = NULL;
}

sw_nurbs_curve iges_curve_view(const iges_curve *c)
{
    sw_nurbs_curve v = {c->degree, c->count, c->knots, c->ctrl};
    return v;
}

sw_nurbs_surface iges_surface_view(const iges_surface *s)
{
    sw_nurbs_surface v = {s->degree_u, s->degree_v, s->count_u, s->count_v,
                          s->knots_u, s->knots_v, s->ctrl};
    return v;
}

/* ---- clamping by knot insertion --------------------------------------- */

/* A B-spline with points of dim homogeneous coordinates, as clamping needs
 * it (surfaces clamp one direction with whole rows as points). */
typedef struct spline {
    int p, n, dim;
    double *knots, *pts;
} spline;

/* Inserts t once (Boehm); a < knots[n + p] is guaranteed by the caller. */
static int insert_knot(spline *s, double t)
{
    int p = s->p, n = s->n, dim = s->dim, k = p;
    while (k + 1 < n + p && s->knots[k + 1] <= t)
        k++;
    double *knots = malloc((size_t)(n + p + 2) * sizeof(double));
    double *pts = malloc((size_t)(n + 1) * (size_t)dim * sizeof(double));
    if (!knots || !pts) {
        free(knots);
        free(pts);
        return 0;
    }
    memcpy(knots, s->knots, (size_t)(k + 1) * sizeof(double));
    knots[k + 1] = t;
    memcpy(knots + k + 2, s->knots + k + 1, (size_t)(n + p - k - 1 + 1) * sizeof(double));
    for (int i = 0; i <= n; i++) {
        double *q = pts + (size_t)i * dim;
        const double *a = s->pts + (size_t)(i < n ? i : n - 1) * dim;
        const double *b = s->pts + (size_t)(i > 0 ? i - 1 : 0) * dim;
        double alpha = i <= k - p ? 1.0 : i >= k + 1 ? 0.0
                     : (t - s->knots[i]) / (s->knots[i + p] - s->knots[i]);
        for (int d = 0; d < dim; d++)
            q[d] = alpha * a[d] + (1.0 - alpha) * b[d];
    }
    free(s->knots);
    free(s->pts);
    s->knots = knots, s->pts = pts, s->n = n + 1;
    return 1;
}

static int multiplicity(const spline *s, double t)
{
    int m = 0;
    for (int i = 0; i < s->n + s->p + 1; i++)
        m += s->knots[i] == t;
    return m;
}

/* Cuts s to [a, b] (inside its domain) with clamped ends: a and b raised to
 * multiplicity p, then the points outside dropped. */
static int clamp_spline(spline *s, double a, double b)
{
    int p = s->p, nk = s->n + p + 1;
    double eps = 1e-12 * (fabs(b - a) + fabs(a) + fabs(b));
    for (int i = 0; i < nk; i++) {
        if (fabs(s->knots[i] - a) <= eps)
            s->knots[i] = a;
        if (fabs(s->knots[i] - b) <= eps)
            s->knots[i] = b;
    }
    for (int m = multiplicity(s, a); m < p; m++)
        if (!insert_knot(s, a))
            return 0;
    for (int m = multiplicity(s, b); m < p; m++)
        if (!insert_knot(s, b))
            return 0;
    nk = s->n + p + 1;
    int r = 0, f = nk - 1;
    for (int i = 0; i < nk; i++)
        if (s->knots[i] == a)
            r = i;
    for (int i = nk - 1; i >= 0; i--)
        if (s->knots[i] == b)
            f = i;
    int j0 = r - p, count = f - j0;
    if (j0 < 0 || count < p + 1 || f + p - 1 >= nk)
        return 0;
    memmove(s->pts, s->pts + (size_t)j0 * s->dim, (size_t)count * s->dim * sizeof(double));
    memmove(s->knots + 1, s->knots + j0 + 1, (size_t)(f + p - 1 - j0) * sizeof(double));
    s->knots[0] = a;
    s->knots[count + p] = b;
    s->n = count;
    return 1;
}

static void to_homogeneous(double *c, size_t n)
{
    for (size_t i = 0; i < n; i++)
        c[i * 4] *= c[i * 4 + 3], c[i * 4 + 1] *= c[i * 4 + 3], c[i * 4 + 2] *= c[i * 4 + 3];
}

static void to_cartesian(double *c, size_t n)
{
    for (size_t i = 0; i < n; i++)
        c[i * 4] /= c[i * 4 + 3], c[i * 4 + 1] /= c[i * 4 + 3], c[i * 4 + 2] /= c[i * 4 + 3];
}

/* The domain the knots allow and [a, b] inside it, or an error. */
static sw_status clamp_range(iges_reader *r, int p, int n, const double *knots, double *a,
                             double *b)
{
    double lo = knots[p], hi = knots[n];
    if (*a < lo)
        *a = lo;
    if (*b > hi)
        *b = hi;
    if (!(*a < *b))
        return sw_error_set(r->err, SW_ERR_RANGE,
                            "%s: parameter range [%g, %g] is empty within the knots' [%g, %g]",
                            r->file, *a, *b, lo, hi);
    return SW_OK;
}

sw_status iges_curve_clamp(iges_reader *r, iges_curve *c, double a, double b)
{
    sw_status st = clamp_range(r, c->degree, c->count, c->knots, &a, &b);
    if (st != SW_OK)
        return st;
    to_homogeneous(c->ctrl, (size_t)c->count);
    spline s = {c->degree, c->count, 4, c->knots, c->ctrl};
    int ok = clamp_spline(&s, a, b);
    c->knots = s.knots, c->ctrl = s.pts, c->count = s.n;
    to_cartesian(c->ctrl, (size_t)c->count);
    if (!ok)
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: could not clamp a curve's knots",
                            r->file);
    return SW_OK;
}

/* One direction of a surface as a spline whose points are whole rows
 * (v: rows are contiguous already; u: transposed first). */
static int clamp_direction(iges_surface *s, int along_u, double a, double b)
{
    int cu = s->count_u, cv = s->count_v;
    int n = along_u ? cu : cv, other = along_u ? cv : cu;
    double *pts = s->ctrl;
    if (along_u) {
        pts = malloc((size_t)cu * cv * 4 * sizeof(double));
        if (!pts)
            return 0;
        for (int j = 0; j < cv; j++)
            for (int i = 0; i < cu; i++)
                memcpy(pts + ((size_t)i * cv + j) * 4, s->ctrl + ((size_t)j * cu + i) * 4,
                       4 * sizeof(double));
        free(s->ctrl);
        s->ctrl = NULL;
    }
    spline sp = {along_u ? s->degree_u : s->degree_v, n, 4 * other,
                 along_u ? s->knots_u : s->knots_v, pts};
    int ok = clamp_spline(&sp, a, b);
    if (along_u) {
        s->knots_u = sp.knots, s->count_u = sp.n;
        s->ctrl = malloc((size_t)sp.n * cv * 4 * sizeof(double));
        for (int j = 0; s->ctrl && j < cv; j++)
            for (int i = 0; i < sp.n; i++)
                memcpy(s->ctrl + ((size_t)j * sp.n + i) * 4, sp.pts + ((size_t)i * cv + j) * 4,
                       4 * sizeof(double));
        free(sp.pts);
        return ok && s->ctrl;
    }
    s->knots_v = sp.knots, s->count_v = sp.n, s->ctrl = sp.pts;
    return ok;
}

sw_status iges_surface_clamp(iges_reader *r, iges_surface *s, double u0, double u1, double v0,
                             double v1)
{
    sw_status st = clamp_range(r, s->degree_u, s->count_u, s->knots_u, &u0, &u1);
    if (st == SW_OK)
        st = clamp_range(r, s->degree_v, s->count_v, s->knots_v, &v0, &v1);
    if (st != SW_OK)
        return st;
    to_homogeneous(s->ctrl, (size_t)s->count_u * s->count_v);
    int ok = clamp_direction(s, 1, u0, u1) && clamp_direction(s, 0, v0, v1);
    if (!ok)
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: could not clamp a surface's knots",
                            r->file);
    to_cartesian(s->ctrl, (size_t)s->count_u * s->count_v);
    return SW_OK;
}

/* ---- transforms and reversal ---------------------------------------- */

static void transform_points(double *c, size_t n, const sw_mat4 *m)
{
    for (size_t i = 0; i < n; i++) {
        sw_vec3 p = sw_mat4_transform_point(m, sw_v3(c[i * 4], c[i * 4 + 1], c[i * 4 + 2]));
        c[i * 4] = p.x, c[i * 4 + 1] = p.y, c[i * 4 + 2] = p.z;
    }
}

void iges_curve_transform(iges_curve *c, const sw_mat4 *m)
{
    transform_points(c->ctrl, (size_t)c->count, m);
}

static double det3(const sw_mat4 *m)
{
    const double *a = m->m;
    return a[0] * (a[5] * a[10] - a[9] * a[6]) - a[4] * (a[1] * a[10] - a[9] * a[2]) +
           a[8] * (a[1] * a[6] - a[5] * a[2]);
}

void iges_surface_transform(iges_surface *s, const sw_mat4 *m)
{
    transform_points(s->ctrl, (size_t)s->count_u * s->count_v, m);
    if (det3(m) < 0)
        s->flipped = !s->flipped;
}

void iges_curve_reverse(iges_curve *c)
{
    int n = c->count, nk = c->count + c->degree + 1;
    double a = c->knots[0], b = c->knots[nk - 1];
    for (int i = 0; i < n / 2; i++)
        for (int k = 0; k < 4; k++) {
            double t = c->ctrl[i * 4 + k];
            c->ctrl[i * 4 + k] = c->ctrl[(n - 1 - i) * 4 + k];
            c->ctrl[(n - 1 - i) * 4 + k] = t;
        }
    for (int i = 0; i < nk / 2; i++) {
        double t = c->knots[i];
        c->knots[i] = c->knots[nk - 1 - i];
        c->knots[nk - 1 - i] = t;
    }
    for (int i = 0; i < nk; i++)
        c->knots[i] = a + b - c->knots[i];
}

/* ---- exact lines and arcs ------------------------------------------- */

sw_status iges_curve_line(iges_reader *r, iges_curve *c, sw_vec3 a, sw_vec3 b, double t0,
                          double t1)
{
    sw_status st = iges_curve_alloc(r, c, 1, 2);
    if (st != SW_OK)
        return st;
    double k[4] = {t0, t0, t1, t1}, p[8] = {a.x, a.y, a.z, 1, b.x, b.y, b.z, 1};
    memcpy(c->knots, k, sizeof k);
    memcpy(c->ctrl, p, sizeof p);
    return SW_OK;
}

int iges_arc_pieces(double sweep)
{
    int n = (int)ceil(sweep / (0.5 * SW_PI) - 1e-9);
    return n < 1 ? 1 : n > 4 ? 4 : n;
}

static void put(double *c, sw_vec3 p, double w)
{
    c[0] = p.x, c[1] = p.y, c[2] = p.z, c[3] = w;
}

sw_status iges_curve_arc(iges_reader *r, iges_curve *c, sw_vec3 o, sw_vec3 x, sw_vec3 y,
                         double radius, double a0, double a1)
{
    int n = iges_arc_pieces(a1 - a0);
    sw_status st = iges_curve_alloc(r, c, 2, 2 * n + 1);
    if (st != SW_OK)
        return st;
    double step = (a1 - a0) / n, w = cos(0.5 * step);
    for (int i = 0; i < 3; i++)
        c->knots[i] = 0, c->knots[2 * n + 1 + i] = n;
    for (int i = 1; i < n; i++)
        c->knots[2 * i + 1] = c->knots[2 * i + 2] = i;
    for (int i = 0; i <= 2 * n; i++) {
        /* Even points on the circle, odd ones at the tangents' crossing. */
        double ang = a0 + 0.5 * step * i, rr = i % 2 ? radius / w : radius;
        sw_vec3 p = sw_v3_add(o, sw_v3_add(sw_v3_scale(x, rr * cos(ang)),
                                           sw_v3_scale(y, rr * sin(ang))));
        put(c->ctrl + i * 4, p, i % 2 ? w : 1.0);
    }
    return SW_OK;
}

/* On each piece the rational quadratic with weights 1, cos h, 1 over a
 * half-angle h runs with tan(phi / 2) = tan(h / 2) (2s - 1), phi measured
 * from the piece's bisector (the stereographic parameterisation). */
double iges_arc_param(double a0, double a1, double a)
{
    int n = iges_arc_pieces(a1 - a0);
    double step = (a1 - a0) / n;
    int k = (int)floor((a - a0) / step);
    k = k < 0 ? 0 : k >= n ? n - 1 : k;
    double phi = a - (a0 + (k + 0.5) * step), h = 0.5 * step;
    double s = 0.5 * (1.0 + tan(0.5 * phi) / tan(0.5 * h));
    return k + s;
}

/* ---- joining pieces ----------------------------------------------------- */

/* Raises a homogeneous Bezier segment of degree d to d + 1 in place
 * (room for d + 2 points). */
static void elevate(double *h, int d)
{
    double prev[4], cur[4];
    memcpy(prev, h, sizeof prev);
    for (int i = 1; i <= d; i++) {
        double a = (double)i / (d + 1);
        memcpy(cur, h + i * 4, sizeof cur);
        for (int k = 0; k < 4; k++)
            h[i * 4 + k] = a * prev[k] + (1 - a) * cur[k];
        memcpy(prev, cur, sizeof prev);
    }
    memcpy(h + (d + 1) * 4, prev, sizeof prev);
}

static int join_segments(const iges_curves *list, int p, iges_curve *out, double *seg,
                         double *params)
{
    int at = 0;
    double t = list->items[0].knots[list->items[0].degree];
    for (int c = 0; c < list->count; c++) {
        const iges_curve *in = &list->items[c];
        sw_nurbs_curve v = iges_curve_view(in);
        sw_nurbs_bezier_sizes z = sw_nurbs_curve_bezier_sizes(&v);
        if (sw_nurbs_curve_to_bezier(&v, seg, params, NULL) != SW_OK)
            return 0;
        for (int k = 0; k < z.pieces_u; k++) {
            double h[SW_BEZIER_MAX_ORDER * 4];
            memcpy(h, seg + (size_t)k * (in->degree + 1) * 4,
                   (size_t)(in->degree + 1) * 4 * sizeof(double));
            to_homogeneous(h, (size_t)in->degree + 1);
            for (int d = in->degree; d < p; d++)
                elevate(h, d);
            to_cartesian(h, (size_t)p + 1);
            memcpy(out->ctrl + (size_t)at * p * 4, h, (size_t)(p + 1) * 4 * sizeof(double));
            double t1 = t + (params[2 * k + 1] - params[2 * k]);
            for (int m = 0; m < p; m++)
                out->knots[1 + at * p + m] = t;
            t = t1;
            at++;
        }
    }
    out->knots[0] = out->knots[1];
    for (int m = 0; m <= p; m++)
        out->knots[at * p + 1 + m] = t;
    return 1;
}

sw_status iges_curves_join(iges_reader *r, const iges_curves *list, iges_curve *out)
{
    memset(out, 0, sizeof *out);
    if (list->count == 0)
        return sw_error_set(r->err, SW_ERR_FORMAT, "%s: expected a curve, found none", r->file);
    int p = 1, segs = 0;
    size_t seg_doubles = 0, param_doubles = 0;
    for (int c = 0; c < list->count; c++) {
        sw_nurbs_curve v = iges_curve_view(&list->items[c]);
        sw_status st = sw_nurbs_curve_check(&v, r->err);
        if (st != SW_OK)
            return st;
        sw_nurbs_bezier_sizes z = sw_nurbs_curve_bezier_sizes(&v);
        p = v.degree > p ? v.degree : p;
        segs += z.pieces_u;
        seg_doubles = z.ctrl_doubles > seg_doubles ? z.ctrl_doubles : seg_doubles;
        param_doubles = z.param_doubles > param_doubles ? z.param_doubles : param_doubles;
    }
    sw_status st = iges_curve_alloc(r, out, p, segs * p + 1);
    if (st != SW_OK)
        return st;
    double *seg = malloc((seg_doubles + param_doubles) * sizeof(double));
    int ok = seg && join_segments(list, p, out, seg, seg + seg_doubles);
    free(seg);
    if (!ok) {
        iges_curve_free(out);
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory joining curves",
                            r->file);
    }
    return SW_OK;
}
