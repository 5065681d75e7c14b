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

/* Bernstein values b[0..n] of degree n at t and their derivatives d. */
static void basis(int n, double t, double *b, double *d)
{
    double lower[SW_BEZIER_MAX_ORDER], s = 1 - t;
    b[0] = 1;
    for (int k = 1; k <= n; k++) {
        if (k == n)
            memcpy(lower, b, sizeof(double) * (size_t)n);
        double carry = 0;
        for (int i = 0; i < k; i++) {
            double x = b[i];
            b[i] = carry + s * x;
            carry = t * x;
        }
        b[k] = carry;
    }
    for (int i = 0; i <= n; i++)
        d[i] = n * ((i > 0 ? lower[i - 1] : 0) - (i < n ? lower[i] : 0));
}

/* q[0][i] = sum_j B_j(t) H_ij, q[1][i] = sum_j B_j'(t) H_ij: the patch
 * contracted in v at t (H homogeneous: w x, w y, w z, w). */
static void contract_v(const sw_bezier_patch *p, double t, double *q, size_t stride)
{
    double b[SW_BEZIER_MAX_ORDER], d[SW_BEZIER_MAX_ORDER];
    int n = p->degree_u, m = p->degree_v;
    basis(m, t, b, d);
    double *q0 = q, *q1 = q + stride;
    memset(q0, 0, sizeof(double) * 4 * (size_t)(n + 1));
    memset(q1, 0, sizeof(double) * 4 * (size_t)(n + 1));
    for (int j = 0; j <= m; j++) {
        const double *row = p->ctrl + (size_t)j * (size_t)(n + 1) * 4;
        for (int i = 0; i <= n; i++) {
            const double *c = row + 4 * i;
            double w = p->rational ? c[3] : 1;
            double h[4] = {c[0] * w, c[1] * w, c[2] * w, w};
            for (int k = 0; k < 4; k++)
                q0[4 * i + k] += b[j] * h[k], q1[4 * i + k] += d[j] * h[k];
        }
    }
}

static int normal_of(sw_vec3 du, sw_vec3 dv, sw_vec3 *n)
{
    double a = sw_v3_length(du), b = sw_v3_length(dv);
    sw_vec3 x = sw_v3_cross(du, dv);
    double l = sw_v3_length(x);
    if (!(l > 1e-10 * a * b) || !(fmin(a, b) > 1e-10 * fmax(a, b)))
        return 0;
    *n = sw_v3_scale(x, 1.0 / l);
    return 1;
}

/* The point at s of a contracted patch; *normal from sw_bezier_eval at the
 * patch's (s, t) where the quotient-rule normal degenerates. */
static void finish(const sw_bezier_patch *p, const double *q, size_t stride, double s, double t,
                   sw_vec3 *pos, sw_vec3 *normal)
{
    double b[SW_BEZIER_MAX_ORDER], d[SW_BEZIER_MAX_ORDER];
    double x[4] = {0, 0, 0, 0}, xu[4] = {0, 0, 0, 0}, xv[4] = {0, 0, 0, 0};
    int n = p->degree_u;
    basis(n, s, b, d);
    const double *q1 = q + stride;
    for (int i = 0; i <= n; i++)
        for (int k = 0; k < 4; k++)
            x[k] += b[i] * q[4 * i + k], xu[k] += d[i] * q[4 * i + k], xv[k] += b[i] * q1[4 * i + k];
    double iw = 1 / x[3];
    sw_vec3 f = sw_v3(x[0] * iw, x[1] * iw, x[2] * iw);
    sw_vec3 fu = sw_v3_scale(sw_v3_sub(sw_v3(xu[0], xu[1], xu[2]), sw_v3_scale(f, xu[3])), iw);
    sw_vec3 fv = sw_v3_scale(sw_v3_sub(sw_v3(xv[0], xv[1], xv[2]), sw_v3_scale(f, xv[3])), iw);
    *pos = f;
    if (!normal_of(fu, fv, normal)) {
        sw_surface_point sp;
        sw_bezier_eval(p, s, t, SW_EVAL_FIRST, &sp);
        *normal = sp.normal;
    }
}

static double local(const float *d, int axis, double x)
{
    double lo = d[2 * axis], hi = d[2 * axis + 1];
    return fmin(fmax((x - lo) / (hi - lo), 0), 1);
}

void sw_tt_eval_at(tt_ctx *c, uint32_t p, double u, double v, sw_vec3 *pos, sw_vec3 *normal)
{
    double q[2 * 4 * SW_BEZIER_MAX_ORDER];
    const float *d = c->in_patches[p].domain;
    double s = local(d, 0, u), t = local(d, 1, v);
    contract_v(&c->patches[p], t, q, 4 * SW_BEZIER_MAX_ORDER);
    finish(&c->patches[p], q, 4 * SW_BEZIER_MAX_ORDER, s, t, pos, normal);
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
    finish(&c->patches[p], q, stride, local(d, 0, u), t, pos, normal);
}
