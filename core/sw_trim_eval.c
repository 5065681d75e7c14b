/* SPDX-License-Identifier: MIT */
/* Exact surface evaluation for the trimmed tessellator's grid
 * (core/sw_trim_tess.c): Bernstein sums on the homogeneous control points,
 * contracted in v once per grid line and knot column (the line cache), then
 * per grid point in u: about 3 (n + 1) x 4 multiply-adds per point instead
 * of a de Casteljau pyramid per point. The normal is the quotient-rule
 * F_u x F_v; where it degenerates (a collapsed edge) sw_bezier_eval's limit
 * normal takes over. */
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

/* Bernstein values b[0..n] of degree n at t and their derivatives d: the
 * degree n - 1 values by the triangle (closed form for the bicubic's), then
 * one more step for b and the differences for d. */
static void basis(int n, double t, double *b, double *d)
{
    double lo[SW_BEZIER_MAX_ORDER], s = 1 - t;
    if (n == 3) {
        lo[0] = s * s, lo[1] = 2 * s * t, lo[2] = t * t;
    } else {
        lo[0] = 1;
        for (int k = 1; k < n; k++) {
            double carry = 0;
            for (int i = 0; i < k; i++) {
                double x = lo[i];
                lo[i] = carry + s * x;
                carry = t * x;
            }
            lo[k] = carry;
        }
    }
    b[0] = s * lo[0], d[0] = -n * lo[0];
    for (int i = 1; i < n; i++)
        b[i] = s * lo[i] + t * lo[i - 1], d[i] = n * (lo[i - 1] - lo[i]);
    b[n] = t * lo[n - 1], d[n] = n * lo[n - 1];
}

/* q[0][i] = sum_j B_j(t) H_ij, q[1][i] = sum_j B_j'(t) H_ij: the patch
 * contracted in v at t (H homogeneous: w x, w y, w z, w; w = 1 when the
 * patch is polynomial, the common case, without the multiplications). */
/* The polynomial sums with the degrees as constants (inlined for the
 * bicubic, most CAD patches: the loops unroll). */
static inline __attribute__((always_inline)) void contract_poly(const double *ctrl, int n, int m,
                                                               const double *b, const double *d,
                                                               double *q0, double *q1)
{
    size_t row = 4 * (size_t)(n + 1);
    for (int i = 0; i <= n; i++) {
        double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0, w0 = 0, w1 = 0;
        for (int j = 0; j <= m; j++) {
            const double *c = ctrl + (size_t)j * row + 4 * (size_t)i;
            x0 += b[j] * c[0], y0 += b[j] * c[1], z0 += b[j] * c[2], w0 += b[j];
            x1 += d[j] * c[0], y1 += d[j] * c[1], z1 += d[j] * c[2], w1 += d[j];
        }
        q0[4 * i] = x0, q0[4 * i + 1] = y0, q0[4 * i + 2] = z0, q0[4 * i + 3] = w0;
        q1[4 * i] = x1, q1[4 * i + 1] = y1, q1[4 * i + 2] = z1, q1[4 * i + 3] = w1;
    }
}

static void contract_v(const sw_bezier_patch *p, double t, double *q, size_t stride)
{
    double b[SW_BEZIER_MAX_ORDER], d[SW_BEZIER_MAX_ORDER];
    int n = p->degree_u, m = p->degree_v;
    size_t row = 4 * (size_t)(n + 1);
    basis(m, t, b, d);
    double *q0 = q, *q1 = q + stride;
    if (!p->rational) {
        if (n == 3 && m == 3)
            contract_poly(p->ctrl, 3, 3, b, d, q0, q1);
        else
            contract_poly(p->ctrl, n, m, b, d, q0, q1);
        return;
    }
    memset(q0, 0, sizeof(double) * row);
    memset(q1, 0, sizeof(double) * row);
    for (int j = 0; j <= m; j++) {
        const double *c = p->ctrl + (size_t)j * row;
        double bj = b[j], dj = d[j];
        for (size_t i = 0; i < row; i += 4) {
            double w = c[i + 3], h0 = c[i] * w, h1 = c[i + 1] * w, h2 = c[i + 2] * w;
            q0[i] += bj * h0, q0[i + 1] += bj * h1, q0[i + 2] += bj * h2, q0[i + 3] += bj * w;
            q1[i] += dj * h0, q1[i + 1] += dj * h1, q1[i + 2] += dj * h2, q1[i + 3] += dj * w;
        }
    }
}

/* x = sum_i B_i(s) q0_i, xu with B_i', xv = sum_i B_i(s) q1_i. */
static inline __attribute__((always_inline)) void sum_u(const double *q0, const double *q1,
                                                       const double *b, const double *d, int n,
                                                       double *x, double *xu, double *xv)
{
    for (int k = 0; k < 4; k++)
        x[k] = xu[k] = xv[k] = 0;
    for (int i = 0; i <= n; i++)
        for (int k = 0; k < 4; k++)
            x[k] += b[i] * q0[4 * i + k], xu[k] += d[i] * q0[4 * i + k],
                xv[k] += b[i] * q1[4 * i + k];
}

/* The point at s of a contracted patch. The normal is F_u x F_v
 * normalised, as sw_bezier_eval's (zero-free only where neither derivative
 * is rounding noise next to the other); where that fails, sw_bezier_eval's
 * limit normal at the patch's (s, t). */
static void finish(const sw_bezier_patch *p, const double *q, size_t stride, const double *b,
                   const double *d, double s, double t, sw_vec3 *pos, sw_vec3 *normal)
{
    double x[4], xu[4], xv[4];
    if (p->degree_u == 3)
        sum_u(q, q + stride, b, d, 3, x, xu, xv);
    else
        sum_u(q, q + stride, b, d, p->degree_u, x, xu, xv);
    double f[3], fu[3], fv[3];
    if (!p->rational) { /* w = 1: no quotient */
        for (int k = 0; k < 3; k++)
            f[k] = x[k], fu[k] = xu[k], fv[k] = xv[k];
    } else {
        double iw = 1 / x[3];
        for (int k = 0; k < 3; k++) {
            f[k] = x[k] * iw;
            fu[k] = (xu[k] - f[k] * xu[3]) * iw, fv[k] = (xv[k] - f[k] * xv[3]) * iw;
        }
    }
    *pos = sw_v3(f[0], f[1], f[2]);
    double cx = fu[1] * fv[2] - fu[2] * fv[1], cy = fu[2] * fv[0] - fu[0] * fv[2];
    double cz = fu[0] * fv[1] - fu[1] * fv[0];
    double a2 = fu[0] * fu[0] + fu[1] * fu[1] + fu[2] * fu[2];
    double b2 = fv[0] * fv[0] + fv[1] * fv[1] + fv[2] * fv[2], l2 = cx * cx + cy * cy + cz * cz;
    if (l2 > 1e-20 * a2 * b2 && (a2 < b2 ? a2 > 1e-20 * b2 : b2 > 1e-20 * a2)) {
        double il = 1 / sqrt(l2);
        *normal = sw_v3(cx * il, cy * il, cz * il);
        return;
    }
    sw_surface_point sp;
    sw_bezier_eval(p, s, t, SW_EVAL_FIRST, &sp);
    *normal = sp.normal;
}

static double local(const float *d, int axis, double x)
{
    double lo = d[2 * axis], hi = d[2 * axis + 1], s = (x - lo) / (hi - lo);
    return s > 0 ? (s < 1 ? s : 1) : 0;
}

void sw_tt_eval_at(tt_ctx *c, uint32_t p, double u, double v, sw_vec3 *pos, sw_vec3 *normal)
{
    double q[2 * 4 * SW_BEZIER_MAX_ORDER];
    const float *dom = c->in_patches[p].domain;
    double s = local(dom, 0, u), t = local(dom, 1, v);
    double b[SW_BEZIER_MAX_ORDER], d[SW_BEZIER_MAX_ORDER];
    contract_v(&c->patches[p], t, q, 4 * SW_BEZIER_MAX_ORDER);
    basis(c->patches[p].degree_u, s, b, d);
    finish(&c->patches[p], q, 4 * SW_BEZIER_MAX_ORDER, b, d, s, t, pos, normal);
}

sw_status sw_tt_eval_init(tt_ctx *c)
{
    size_t slots = 2 * (size_t)(c->grid.nku - 1);
    c->line_q = sw_arena_alloc(c->arena, sizeof(double) * slots * 8 * (size_t)(c->max_n + 1), 8);
    c->line_stamp = sw_arena_alloc(c->arena, sizeof(uint32_t) * slots, 4);
    if (!c->line_q || !c->line_stamp)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "evaluation cache");
    memset(c->line_stamp, 0, sizeof(uint32_t) * slots);
    /* The u basis per grid column of the box, when it fits the budget. */
    size_t cols = c->grid.c1 - c->grid.c0 + 1, per = 2 * (size_t)(c->max_n + 1) + 1;
    c->col_basis = NULL;
    if (cols * per * sizeof(double) <= SW_TT_BASIS_BYTES) {
        c->col_basis = sw_arena_alloc(c->arena, sizeof(double) * cols * per, 8);
        if (!c->col_basis)
            return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                                "evaluation cache");
        for (size_t i = 0; i < cols; i++)
            c->col_basis[i * per] = -1; /* no degree yet */
    }
    return SW_OK;
}

/* Grid point (col, line) on patch p: through the cache when p is the patch
 * of the point's knot cell (the usual case), else directly. */
void sw_tt_eval_grid(tt_ctx *c, uint32_t p, uint32_t col, uint32_t line, sw_vec3 *pos,
                     sw_vec3 *normal)
{
    const tt_grid *g = &c->grid;
    double u = g->gu[col], v = g->gv[line];
    uint32_t kc = g->col_k[col], kr = g->row_k[line];
    if (sw_tt_knot_patch(c, kc, kr) != p) {
        sw_tt_eval_at(c, p, u, v, pos, normal);
        return;
    }
    size_t stride = 4 * (size_t)(c->max_n + 1), slot = (line & 1) * (g->nku - 1) + kc;
    double *q = c->line_q + slot * 2 * stride;
    const float *d = c->in_patches[p].domain;
    double t = local(d, 1, v);
    if (c->line_stamp[slot] != line + 1) {
        contract_v(&c->patches[p], t, q, stride);
        c->line_stamp[slot] = line + 1;
    }
    int n = c->patches[p].degree_u;
    double s = local(d, 0, u), bb[SW_BEZIER_MAX_ORDER], dd[SW_BEZIER_MAX_ORDER];
    const double *b = bb, *db = dd;
    if (c->col_basis) {
        size_t per = 2 * (size_t)(c->max_n + 1) + 1;
        double *e = c->col_basis + (col - g->c0) * per;
        if (e[0] != n) {
            basis(n, s, e + 1, e + 2 + c->max_n);
            e[0] = n;
        }
        b = e + 1, db = e + 2 + c->max_n;
    } else {
        basis(n, s, bb, dd);
    }
    finish(&c->patches[p], q, stride, b, db, s, t, pos, normal);
}
