/* SPDX-License-Identifier: MIT */
/* Point inversion and parameter-space curve fitting (sw_pcurve.h). */
#include "sw_pcurve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the prepared surface ------------------------------------------- */

enum { GRID_PER_PIECE = 4, GRID_MAX = 97 };

static int grid_count(int pieces)
{
    long n = (long)pieces * GRID_PER_PIECE + 1;
    return n > GRID_MAX ? GRID_MAX : (int)n;
}

static sw_status fill_grid(sw_pcurve_surface *ps, sw_error *err)
{
    ps->grid_u = grid_count(ps->pieces_u);
    ps->grid_v = grid_count(ps->pieces_v);
    ps->grid = malloc((size_t)ps->grid_u * (size_t)ps->grid_v * 3 * sizeof(double));
    if (!ps->grid)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for an inversion grid");
    sw_box box = sw_box_empty();
    for (int j = 0; j < ps->grid_v; j++)
        for (int i = 0; i < ps->grid_u; i++) {
            double u = ps->domain[0] + (ps->domain[1] - ps->domain[0]) * i / (ps->grid_u - 1);
            double v = ps->domain[2] + (ps->domain[3] - ps->domain[2]) * j / (ps->grid_v - 1);
            sw_surface_point sp;
            sw_pcurve_surface_eval(ps, u, v, SW_EVAL_POINT, &sp);
            double *g = ps->grid + ((size_t)j * ps->grid_u + i) * 3;
            g[0] = sp.p.x, g[1] = sp.p.y, g[2] = sp.p.z;
            sw_box_add_point(&box, sp.p);
        }
    ps->size = sw_box_diagonal(&box);
    if (!(ps->size > 0) || !isfinite(ps->size))
        ps->size = 1.0;
    return SW_OK;
}

sw_status sw_pcurve_surface_init(sw_pcurve_surface *ps, const sw_nurbs_surface *s,
                                 sw_error *err)
{
    memset(ps, 0, sizeof *ps);
    sw_status st = sw_nurbs_surface_check(s, err);
    if (st != SW_OK)
        return st;
    sw_nurbs_bezier_sizes z = sw_nurbs_surface_bezier_sizes(s);
    ps->ctrl = malloc(z.ctrl_doubles * sizeof(double));
    ps->params = malloc(z.param_doubles * sizeof(double));
    if (!ps->ctrl || !ps->params) {
        sw_pcurve_surface_free(ps);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %zu Bezier doubles",
                            z.ctrl_doubles);
    }
    st = sw_nurbs_surface_to_bezier(s, ps->ctrl, ps->params, err);
    if (st != SW_OK) {
        sw_pcurve_surface_free(ps);
        return st;
    }
    ps->degree_u = s->degree_u, ps->degree_v = s->degree_v;
    ps->pieces_u = z.pieces_u, ps->pieces_v = z.pieces_v;
    size_t n = (size_t)s->count_u * (size_t)s->count_v;
    for (size_t i = 0; i < n; i++)
        ps->rational |= s->ctrl[i * 4 + 3] != 1.0;
    ps->domain[0] = s->knots_u[s->degree_u];
    ps->domain[1] = s->knots_u[s->count_u];
    ps->domain[2] = s->knots_v[s->degree_v];
    ps->domain[3] = s->knots_v[s->count_v];
    st = fill_grid(ps, err);
    if (st != SW_OK)
        sw_pcurve_surface_free(ps);
    return st;
}

void sw_pcurve_surface_free(sw_pcurve_surface *ps)
{
    free(ps->ctrl);
    free(ps->params);
    free(ps->grid);
    memset(ps, 0, sizeof *ps);
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

/* The piece whose range holds x (ranges are 2 doubles each, ascending). */
static int find_piece(const double *ranges, int pieces, double x)
{
    int lo = 0, hi = pieces - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (x >= ranges[2 * mid])
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

void sw_pcurve_surface_eval(const sw_pcurve_surface *ps, double u, double v,
                            sw_eval_order order, sw_surface_point *out)
{
    u = clampd(u, ps->domain[0], ps->domain[1]);
    v = clampd(v, ps->domain[2], ps->domain[3]);
    int a = find_piece(ps->params, ps->pieces_u, u);
    int b = find_piece(ps->params + 2 * ps->pieces_u, ps->pieces_v, v);
    const double *ru = ps->params + 2 * a, *rv = ps->params + 2 * ps->pieces_u + 2 * b;
    double su = 1.0 / (ru[1] - ru[0]), sv = 1.0 / (rv[1] - rv[0]);
    size_t patch = (size_t)(ps->degree_u + 1) * (size_t)(ps->degree_v + 1) * 4;
    sw_bezier_patch bp = {ps->degree_u, ps->degree_v, ps->rational,
                          ps->ctrl + ((size_t)b * ps->pieces_u + a) * patch};
    sw_bezier_eval(&bp, clampd((u - ru[0]) * su, 0, 1), clampd((v - rv[0]) * sv, 0, 1), order,
                   out);
    out->du = sw_v3_scale(out->du, su);
    out->dv = sw_v3_scale(out->dv, sv);
    out->duu = sw_v3_scale(out->duu, su * su);
    out->duv = sw_v3_scale(out->duv, su * sv);
    out->dvv = sw_v3_scale(out->dvv, sv * sv);
}

/* ---- point inversion -------------------------------------------------- */

static double dist_at(const sw_pcurve_surface *ps, sw_vec3 p, const double uv[2])
{
    sw_surface_point sp;
    sw_pcurve_surface_eval(ps, uv[0], uv[1], SW_EVAL_POINT, &sp);
    return sw_v3_length(sw_v3_sub(sp.p, p));
}

/* The Newton step for min |S - p|^2, or Gauss-Newton when the full Hessian
 * is not positive definite (far from the surface, on concave sides), or a
 * scaled gradient step when even that is singular (poles). */
static void newton_step(const sw_surface_point *sp, sw_vec3 r, double step[2])
{
    double g0 = sw_v3_dot(sp->du, r), g1 = sw_v3_dot(sp->dv, r);
    double a = sw_v3_dot(sp->du, sp->du), b = sw_v3_dot(sp->du, sp->dv);
    double c = sw_v3_dot(sp->dv, sp->dv);
    double h00 = a + sw_v3_dot(sp->duu, r), h01 = b + sw_v3_dot(sp->duv, r);
    double h11 = c + sw_v3_dot(sp->dvv, r);
    double det = h00 * h11 - h01 * h01;
    if (!(h00 > 0 && det > 1e-14 * (a * c + 1e-300))) {
        h00 = a, h01 = b, h11 = c;
        det = a * c - b * b;
    }
    if (det > 1e-14 * (a * c + 1e-300)) {
        step[0] = -(h11 * g0 - h01 * g1) / det;
        step[1] = -(h00 * g1 - h01 * g0) / det;
        return;
    }
    step[0] = a > 0 ? -g0 / a : 0;
    step[1] = c > 0 ? -g1 / c : 0;
}

/* Projected Newton: a parameter on the domain's edge whose step points out
 * stays there, and the other one takes the 1D Newton step along the edge
 * (closest points on boundaries, where a clamped 2D step would stall). */
static void bound_step(const sw_surface_point *sp, sw_vec3 r, const double uv[2],
                       const double *d, double step[2])
{
    int stuck_u = (uv[0] <= d[0] && step[0] < 0) || (uv[0] >= d[1] && step[0] > 0);
    int stuck_v = (uv[1] <= d[2] && step[1] < 0) || (uv[1] >= d[3] && step[1] > 0);
    if (stuck_u == stuck_v)
        return;
    int k = stuck_u ? 1 : 0;
    sw_vec3 t = k ? sp->dv : sp->du, tt = k ? sp->dvv : sp->duu;
    double g = sw_v3_dot(t, r), h = sw_v3_dot(t, t) + sw_v3_dot(tt, r), a = sw_v3_dot(t, t);
    step[1 - k] = 0;
    step[k] = h > 0 ? -g / h : a > 0 ? -g / a : 0;
}

/* Surface evaluations spent so far, counted against a fit's limit
 * (SW_PCURVE_FIT_MAX_EVALS); NULL counts nothing. */
static void spend(long *evals, long n)
{
    if (evals)
        *evals += n;
}

static double newton(const sw_pcurve_surface *ps, sw_vec3 p, double uv[2], long *evals)
{
    const double *d = ps->domain;
    sw_surface_point sp;
    sw_pcurve_surface_eval(ps, uv[0], uv[1], SW_EVAL_SECOND, &sp);
    spend(evals, 1);
    double best = sw_v3_length(sw_v3_sub(sp.p, p));
    for (int it = 0; it < 40 && best > 1e-15 * ps->size; it++) {
        double step[2];
        newton_step(&sp, sw_v3_sub(sp.p, p), step);
        bound_step(&sp, sw_v3_sub(sp.p, p), uv, d, step);
        /* Backtracking: a full step that makes things worse is halved. */
        double lambda = 1.0, trial[2], dist = best;
        int improved = 0;
        for (int k = 0; k < 12 && !improved; k++, lambda *= 0.5) {
            trial[0] = clampd(uv[0] + lambda * step[0], d[0], d[1]);
            trial[1] = clampd(uv[1] + lambda * step[1], d[2], d[3]);
            dist = dist_at(ps, p, trial);
            spend(evals, 1);
            improved = dist < best;
        }
        if (!improved)
            break;
        double moved = fabs(trial[0] - uv[0]) * sw_v3_length(sp.du) +
                       fabs(trial[1] - uv[1]) * sw_v3_length(sp.dv);
        uv[0] = trial[0], uv[1] = trial[1];
        best = dist;
        if (moved < 1e-14 * ps->size)
            break;
        sw_pcurve_surface_eval(ps, uv[0], uv[1], SW_EVAL_SECOND, &sp);
        spend(evals, 1);
    }
    return best;
}

static void grid_start(const sw_pcurve_surface *ps, sw_vec3 p, double uv[2])
{
    double best = INFINITY;
    int bi = 0, bj = 0;
    for (int j = 0; j < ps->grid_v; j++)
        for (int i = 0; i < ps->grid_u; i++) {
            const double *g = ps->grid + ((size_t)j * ps->grid_u + i) * 3;
            double dx = g[0] - p.x, dy = g[1] - p.y, dz = g[2] - p.z;
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < best)
                best = d2, bi = i, bj = j;
        }
    uv[0] = ps->domain[0] + (ps->domain[1] - ps->domain[0]) * bi / (ps->grid_u - 1);
    uv[1] = ps->domain[2] + (ps->domain[3] - ps->domain[2]) * bj / (ps->grid_v - 1);
}

/* sw_pcurve_invert, its evaluations counted (the grid's scan as one
 * evaluation per 64 grid points: about what it costs). */
static double invert(const sw_pcurve_surface *ps, sw_vec3 p, const double *start, double accept,
                     double uv[2], long *evals)
{
    double best = INFINITY;
    if (start) {
        uv[0] = clampd(start[0], ps->domain[0], ps->domain[1]);
        uv[1] = clampd(start[1], ps->domain[2], ps->domain[3]);
        best = newton(ps, p, uv, evals);
        if (best <= accept)
            return best;
    }
    double alt[2];
    grid_start(ps, p, alt);
    spend(evals, 1 + ps->grid_u * ps->grid_v / 64);
    double d = newton(ps, p, alt, evals);
    if (d < best) {
        uv[0] = alt[0], uv[1] = alt[1];
        best = d;
    }
    return best;
}

double sw_pcurve_invert(const sw_pcurve_surface *ps, sw_vec3 p, const double *start,
                        double accept, double uv[2])
{
    return invert(ps, p, start, accept, uv, NULL);
}

/* ---- fitting ---------------------------------------------------------- */

enum { FIT_MAX_CTRL = 256, POLY_MAX_POINTS = 4096 };

/* Parameters on the surface for the target's point at t, and the distance
 * of that point from the surface. warm carries the previous answer along the
 * curve so neighbouring samples stay on the same side of a seam. */
static double sample_uv(const sw_pcurve_surface *ps, const sw_pcurve_target *tg, double t,
                        double tol, double warm[2], int *have_warm, sw_vec3 *p, double uv[2],
                        long *evals)
{
    if (tg->eval(tg->user, t, p, uv)) {
        warm[0] = uv[0], warm[1] = uv[1], *have_warm = 1;
        return 0.0;
    }
    double gap = invert(ps, *p, *have_warm ? warm : NULL, 0.01 * tol, uv, evals);
    warm[0] = uv[0], warm[1] = uv[1], *have_warm = 1;
    return gap;
}

/* Cox-de Boor: the degree + 1 non-zero basis functions at t in span k. */
static void basis(const double *knots, int p, int k, double t, double *n)
{
    double left[SW_BEZIER_MAX_ORDER], right[SW_BEZIER_MAX_ORDER];
    n[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = t - knots[k + 1 - j];
        right[j] = knots[k + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            double den = right[r + 1] + left[j - r];
            double tmp = den != 0 ? n[r] / den : 0.0;
            n[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        n[j] = saved;
    }
}

static int span_of(const double *knots, int p, int count, double t)
{
    if (t >= knots[count])
        return count - 1;
    int k = p;
    while (k < count - 1 && t >= knots[k + 1])
        k++;
    return k;
}

static sw_vec3 curve_uv(const sw_pcurve_result *c, double t)
{
    sw_nurbs_curve nc = {c->degree, c->count, c->knots, c->ctrl};
    return sw_nurbs_curve_point(&nc, t);
}

/* Dense Cholesky solve of the n x n system a x = b for two right-hand sides
 * (u and v). a is symmetric positive definite (normal equations). */
static int cholesky_solve(double *a, int n, double *bu, double *bv)
{
    for (int j = 0; j < n; j++) {
        double s = a[j * n + j];
        for (int k = 0; k < j; k++)
            s -= a[j * n + k] * a[j * n + k];
        if (!(s > 0))
            return 0;
        a[j * n + j] = sqrt(s);
        for (int i = j + 1; i < n; i++) {
            double x = a[i * n + j];
            for (int k = 0; k < j; k++)
                x -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = x / a[j * n + j];
        }
    }
    double *rhs[2] = {bu, bv};
    for (int c = 0; c < 2; c++) {
        double *b = rhs[c];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < i; k++)
                b[i] -= a[i * n + k] * b[k];
            b[i] /= a[i * n + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            for (int k = i + 1; k < n; k++)
                b[i] -= a[k * n + i] * b[k];
            b[i] /= a[i * n + i];
        }
    }
    return 1;
}

static sw_status result_alloc(sw_pcurve_result *c, int degree, int count, sw_error *err)
{
    c->degree = degree, c->count = count;
    c->knots = malloc((size_t)(count + degree + 1) * sizeof(double));
    c->ctrl = calloc((size_t)count * 4, sizeof(double));
    if (!c->knots || !c->ctrl) {
        sw_pcurve_result_free(c);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for a %d-point pcurve", count);
    }
    for (int i = 0; i < count; i++)
        c->ctrl[i * 4 + 3] = 1.0;
    return SW_OK;
}

/* Cubic least squares with n control points on uniform knots, the ends
 * interpolated; the samples are (t[i], uv[2i..]). */
static sw_status lsq_cubic(int n, int ns, const double *t, const double *uv, double t0,
                           double t1, sw_pcurve_result *c, sw_error *err)
{
    sw_status st = result_alloc(c, 3, n, err);
    if (st != SW_OK)
        return st;
    for (int i = 0; i <= n + 3; i++)
        c->knots[i] = i <= 3 ? t0 : i >= n ? t1 : t0 + (t1 - t0) * (i - 3) / (n - 3);
    int m = n - 2;   /* unknown interior points */
    double *a = calloc((size_t)m * m + 2 * (size_t)m, sizeof(double));
    if (!a) {
        sw_pcurve_result_free(c);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for a pcurve fit");
    }
    double *bu = a + (size_t)m * m, *bv = bu + m;
    const double *first = uv, *last = uv + 2 * (ns - 1);
    for (int s = 0; s < ns; s++) {
        double nb[4];
        int k = span_of(c->knots, 3, n, t[s]);
        basis(c->knots, 3, k, t[s], nb);
        double ru = uv[2 * s], rv = uv[2 * s + 1];
        for (int r = 0; r < 4; r++) {
            int j = k - 3 + r;
            if (j == 0)
                ru -= nb[r] * first[0], rv -= nb[r] * first[1];
            if (j == n - 1)
                ru -= nb[r] * last[0], rv -= nb[r] * last[1];
        }
        for (int r = 0; r < 4; r++) {
            int j = k - 3 + r - 1;
            if (j < 0 || j >= m)
                continue;
            bu[j] += nb[r] * ru, bv[j] += nb[r] * rv;
            for (int q = 0; q < 4; q++) {
                int l = k - 3 + q - 1;
                if (l >= 0 && l < m)
                    a[j * m + l] += nb[r] * nb[q];
            }
        }
    }
    int ok = cholesky_solve(a, m, bu, bv);
    for (int j = 0; ok && j < m; j++)
        c->ctrl[(j + 1) * 4] = bu[j], c->ctrl[(j + 1) * 4 + 1] = bv[j];
    free(a);
    c->ctrl[0] = first[0], c->ctrl[1] = first[1];
    c->ctrl[(n - 1) * 4] = last[0], c->ctrl[(n - 1) * 4 + 1] = last[1];
    if (!ok) {
        sw_pcurve_result_free(c);
        return sw_error_set(err, SW_ERR_RANGE, "pcurve fit: singular system with %d points", n);
    }
    return SW_OK;
}

static sw_status polyline(int ns, const double *t, const double *uv, sw_pcurve_result *c,
                          sw_error *err)
{
    sw_status st = result_alloc(c, 1, ns, err);
    if (st != SW_OK)
        return st;
    c->knots[0] = t[0];
    for (int i = 0; i < ns; i++) {
        c->knots[i + 1] = t[i];
        c->ctrl[i * 4] = uv[2 * i], c->ctrl[i * 4 + 1] = uv[2 * i + 1];
    }
    c->knots[ns + 1] = t[ns - 1];
    return SW_OK;
}

typedef struct fit_samples {
    int n;
    double *t, *uv;
    double max_gap;
    long evals;          /* surface evaluations spent on this fit */
} fit_samples;

static sw_status over_budget(const fit_samples *s, sw_error *err)
{
    return sw_error_set(err, SW_ERR_RANGE,
                        "pcurve fit: gave up after %ld surface evaluations (the limit is %ld): "
                        "the curve does not follow the surface closely enough to fit",
                        s->evals, (long)SW_PCURVE_FIT_MAX_EVALS);
}

static sw_status take_samples(const sw_pcurve_surface *ps, const sw_pcurve_target *tg,
                              double tol, int n, fit_samples *s, sw_error *err)
{
    free(s->t);
    s->t = malloc((size_t)n * 3 * sizeof(double));
    if (!s->t)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for %d pcurve samples", n);
    s->uv = s->t + n;
    s->n = n;
    double warm[2] = {0, 0};
    int have_warm = 0;
    for (int i = 0; i < n; i++) {
        if (s->evals > SW_PCURVE_FIT_MAX_EVALS)
            return over_budget(s, err);
        sw_vec3 p;
        s->t[i] = i == n - 1 ? tg->t1 : tg->t0 + (tg->t1 - tg->t0) * i / (n - 1);
        double gap = sample_uv(ps, tg, s->t[i], tol, warm, &have_warm, &p, s->uv + 2 * i,
                               &s->evals);
        if (gap > s->max_gap)
            s->max_gap = gap;
    }
    return SW_OK;
}

/* The worst excess of |S(c(t)) - C(t)| over C's own distance from the
 * surface, at checks points spread evenly over [t0, t1]. */
static double fit_error(const sw_pcurve_surface *ps, const sw_pcurve_target *tg, double tol,
                        const sw_pcurve_result *c, int checks, fit_samples *s)
{
    double worst = 0.0;
    for (int i = 0; i < checks && s->evals <= SW_PCURVE_FIT_MAX_EVALS; i++) {
        double t = tg->t0 + (tg->t1 - tg->t0) * i / (checks - 1);
        sw_vec3 fuv = curve_uv(c, t), p;
        double warm[2] = {fuv.x, fuv.y}, uv[2];
        int have_warm = 1;
        double gap = sample_uv(ps, tg, t, tol, warm, &have_warm, &p, uv, &s->evals);
        sw_surface_point on;
        sw_pcurve_surface_eval(ps, fuv.x, fuv.y, SW_EVAL_POINT, &on);
        double e = sw_v3_length(sw_v3_sub(on.p, p)) - gap;
        if (!(e <= worst))
            worst = e;   /* NaN counts as the worst */
        if (gap > s->max_gap)
            s->max_gap = gap;
    }
    return worst;
}

static sw_status try_fits(const sw_pcurve_surface *ps, const sw_pcurve_target *tg, double tol,
                          fit_samples *s, sw_pcurve_result *out, double *worst, sw_error *err)
{
    for (int n = 4; n <= FIT_MAX_CTRL; n *= 2) {
        sw_status st = take_samples(ps, tg, tol, 8 * n + 1, s, err);
        if (st == SW_OK)
            st = lsq_cubic(n, s->n, s->t, s->uv, tg->t0, tg->t1, out, err);
        if (st != SW_OK)
            return st;
        *worst = fit_error(ps, tg, tol, out, 4 * s->n + 1, s);
        if (s->evals > SW_PCURVE_FIT_MAX_EVALS) {
            sw_pcurve_result_free(out);
            return over_budget(s, err);
        }
        if (*worst <= tol)
            return SW_OK;
        sw_pcurve_result_free(out);
    }
    for (int n = 4 * FIT_MAX_CTRL; n <= POLY_MAX_POINTS; n *= 2) {
        sw_status st = take_samples(ps, tg, tol, n, s, err);
        if (st == SW_OK)
            st = polyline(s->n, s->t, s->uv, out, err);
        if (st != SW_OK)
            return st;
        *worst = fit_error(ps, tg, tol, out, 2 * s->n + 1, s);
        if (s->evals > SW_PCURVE_FIT_MAX_EVALS) {
            sw_pcurve_result_free(out);
            return over_budget(s, err);
        }
        if (*worst <= tol)
            return SW_OK;
        sw_pcurve_result_free(out);
    }
    return sw_error_set(err, SW_ERR_RANGE,
                        "no parameter curve within %g of the model-space curve (best %g off "
                        "beyond its own distance %g from the surface)",
                        tol, *worst, s->max_gap);
}

sw_status sw_pcurve_fit(const sw_pcurve_surface *ps, const sw_pcurve_target *tg, double tol,
                        sw_pcurve_result *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(tg->t0 < tg->t1) || !isfinite(tg->t0) || !isfinite(tg->t1))
        return sw_error_set(err, SW_ERR_RANGE, "pcurve fit: empty curve range [%g, %g]", tg->t0,
                            tg->t1);
    if (!(tol > 0))
        return sw_error_set(err, SW_ERR_ARG, "pcurve fit: tolerance %g, expected > 0", tol);
    fit_samples s = {0, NULL, NULL, 0.0, 0};
    double worst = INFINITY;
    sw_status st = try_fits(ps, tg, tol, &s, out, &worst, err);
    free(s.t);
    out->evals = s.evals;
    if (st == SW_OK)
        out->max_error = worst > 0 ? worst : 0, out->max_gap = s.max_gap;
    return st;
}

void sw_pcurve_result_free(sw_pcurve_result *res)
{
    free(res->knots);
    free(res->ctrl);
    res->knots = res->ctrl = NULL;
    res->count = 0;
}
