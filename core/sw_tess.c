#include "sw_tess.h"

#include <math.h>
#include <string.h>

/* Float Bernstein tables and sums. Stack use of sw_tess_grid is bounded by
 * the u tables below (about 32 KB at degree 15, 7 KB bicubic) plus a few KB of
 * control-point copies: keep it in mind for threads with small stacks. */
enum { MAXO = SW_BEZIER_MAX_ORDER, MAXV = SW_TESS_MAX_SEGMENTS + 1 };

/* Binomial coefficients C(n, i) for n <= 15, exact in double. */
static double binomial(int n, int i)
{
    double c = 1;
    for (int k = 1; k <= i; k++)
        c = c * (n - i + k) / k;
    return c;
}

/* B^n_i(a / segs), i = 0..n, as C(n, i) * (s^(n-i) * t^i) with t = a / segs and
 * s = (segs - a) / segs each divided exactly: index segs - a swaps s and t,
 * so the values are bit-symmetric and a reversed edge sees the same numbers. */
static void bernstein(int n, uint32_t a, uint32_t segs, float *out)
{
    double t = (double)a / segs, s = (double)(segs - a) / segs;
    double tp[MAXO], sp[MAXO];
    tp[0] = sp[0] = 1;
    for (int k = 1; k <= n; k++) {
        tp[k] = tp[k - 1] * t;
        sp[k] = sp[k - 1] * s;
    }
    for (int i = 0; i <= n; i++)
        out[i] = (float)(binomial(n, i) * (sp[n - i] * tp[i]));
}

/* sum_i b[i] x[i * stride], i = 0..n, added in pairs from both ends inward:
 * reversing both arrays gives the same rounding, and the bicubic fast path
 * spells out exactly this order, so shared edges come out bit-identical. */
static inline float sym_sum(const float *b, const float *x, int stride, int n)
{
    float acc = b[0] * x[0] + b[n] * x[n * stride];
    int lo = 1, hi = n - 1;
    for (; lo < hi; lo++, hi--)
        acc += b[lo] * x[lo * stride] + b[hi] * x[hi * stride];
    if (lo == hi)
        acc += b[lo] * x[lo * stride];
    return acc;
}

/* Plain sum for derivatives, where only the direction of the result matters. */
static inline float dot_sum(const float *b, const float *x, int stride, int n)
{
    float acc = 0;
    for (int i = 0; i < n; i++)
        acc += b[i] * x[i * stride];
    return acc;
}

/* Per-patch data: control points as K floats each (x, y, z for polynomial;
 * w x, w y, w z, w for rational), their v differences, and for rational
 * patches a copy translated to the hull centre so derivatives do not lose
 * digits to the distance from the origin. Layout [i][j][k]: column i along v. */
typedef struct tess_patch {
    int n, m, k;
    const sw_bezier_patchf *src;
    float pts[MAXO][MAXO][4];
    float local[MAXO][MAXO][4];  /* rational only: w (P - c), w */
    float dv[MAXO][MAXO - 1][4]; /* from local (rational) or pts (polynomial) */
    float bu[MAXV][MAXO];        /* B^n_i(a / nu) */
    float bud[MAXV][MAXO - 1];   /* B^(n-1)_i(a / nu): the hodograph's basis */
} tess_patch;

/* One row of the grid (v fixed) reduced to curves along u. */
typedef struct tess_row {
    float q[MAXO][4];     /* the row's points: sum_j B_j(v) P_ij */
    float ql[MAXO][4];    /* the same from the translated copy (rational) */
    float dq[MAXO - 1][4];/* q[i + 1] - q[i] (of ql when rational): u hodograph */
    float qv[MAXO][4];    /* sum_j B'_j(v) (P_i,j+1 - P_ij): v derivative */
} tess_row;

static void prepare_patch(const sw_bezier_patchf *patch, uint32_t nu, tess_patch *tp)
{
    int n = patch->degree_u, m = patch->degree_v, r = patch->rational;
    tp->n = n, tp->m = m, tp->k = r ? 4 : 3, tp->src = patch;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const float *c = patch->ctrl + ((size_t)j * (size_t)(n + 1) + (size_t)i) * 4;
            float w = r ? c[3] : 1.0f;
            for (int k = 0; k < 3; k++) {
                tp->pts[i][j][k] = r ? c[k] * w : c[k];
                lo[k] = fminf(lo[k], c[k]), hi[k] = fmaxf(hi[k], c[k]);
            }
            tp->pts[i][j][3] = w;
        }
    }
    for (int j = 0; r && j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const float *c = patch->ctrl + ((size_t)j * (size_t)(n + 1) + (size_t)i) * 4;
            for (int k = 0; k < 3; k++)
                tp->local[i][j][k] = (c[k] - 0.5f * (lo[k] + hi[k])) * c[3];
            tp->local[i][j][3] = c[3];
        }
    }
    float(*d)[MAXO][4] = r ? tp->local : tp->pts;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j < m; j++)
            for (int k = 0; k < 4; k++)
                tp->dv[i][j][k] = d[i][j + 1][k] - d[i][j][k];
    for (uint32_t a = 0; a <= nu; a++) {
        bernstein(n, a, nu, tp->bu[a]);
        bernstein(n - 1, a, nu, tp->bud[a]);
    }
}

static void prepare_row(const tess_patch *tp, uint32_t b, uint32_t nv, tess_row *row)
{
    float bv[MAXO], bvd[MAXO];
    int n = tp->n, m = tp->m, r = tp->k == 4;
    bernstein(m, b, nv, bv);
    bernstein(m - 1, b, nv, bvd);
    for (int i = 0; i <= n; i++) {
        for (int k = 0; k < tp->k; k++) {
            row->q[i][k] = sym_sum(bv, &tp->pts[i][0][k], 4, m);
            row->ql[i][k] = r ? sym_sum(bv, &tp->local[i][0][k], 4, m) : 0;
            row->qv[i][k] = dot_sum(bvd, &tp->dv[i][0][k], 4, m);
        }
    }
    const float(*d)[4] = r ? row->ql : row->q;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < tp->k; k++)
            row->dq[i][k] = d[i + 1][k] - d[i][k];
}

static inline int8_t pack_snorm(float x)
{
    /* round(x * 127), halves away from zero, as the header specifies. */
    float s = x * 127.0f;
    return (int8_t)(int)(s + (s >= 0 ? 0.5f : -0.5f));
}

/* Where du x dv vanishes (a collapsed edge) or its inputs are rounding noise,
 * the double evaluator's limit normal; rare, so the copy to double is fine. */
static __attribute__((noinline)) void fallback_normal(const sw_bezier_patchf *patch, double u,
                                                      double v, int8_t out[4])
{
    double ctrl[MAXO * MAXO * 4];
    sw_bezier_patch p = sw_bezier_patch_from_float(patch, ctrl);
    sw_surface_point q;
    sw_bezier_eval(&p, u, v, SW_EVAL_FIRST, &q);
    out[0] = pack_snorm((float)q.normal.x);
    out[1] = pack_snorm((float)q.normal.y);
    out[2] = pack_snorm((float)q.normal.z);
    out[3] = 0;
}

/* Writes the normal of du x dv; returns 0 when it is degenerate: du and dv
 * (nearly) parallel, or one of them below 1e-5 of the other (noise). */
static inline int write_normal(float ux, float uy, float uz, float vx, float vy, float vz,
                               sw_vertex *out)
{
    float cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    float cc = cx * cx + cy * cy + cz * cz;
    float uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz;
    if (!(cc > 1e-8f * uu * vv) || !(uu > 1e-10f * vv) || !(vv > 1e-10f * uu))
        return 0;
    float inv = 1.0f / sqrtf(cc);
    out->normal[0] = pack_snorm(cx * inv);
    out->normal[1] = pack_snorm(cy * inv);
    out->normal[2] = pack_snorm(cz * inv);
    out->normal[3] = 0;
    return 1;
}

/* Generic polynomial row: tensor sums with the precomputed u tables. */
static void row_polynomial(const tess_patch *tp, const tess_row *row, uint32_t nu, uint32_t b,
                           uint32_t nv, sw_vertex *out)
{
    int n = tp->n;
    for (uint32_t a = 0; a <= nu; a++) {
        const float *bu = tp->bu[a], *bud = tp->bud[a];
        sw_vertex *o = &out[a];
        o->pos[0] = sym_sum(bu, &row->q[0][0], 4, n);
        o->pos[1] = sym_sum(bu, &row->q[0][1], 4, n);
        o->pos[2] = sym_sum(bu, &row->q[0][2], 4, n);
        float ux = dot_sum(bud, &row->dq[0][0], 4, n), uy = dot_sum(bud, &row->dq[0][1], 4, n);
        float uz = dot_sum(bud, &row->dq[0][2], 4, n);
        float vx = dot_sum(bu, &row->qv[0][0], 4, n + 1);
        float vy = dot_sum(bu, &row->qv[0][1], 4, n + 1);
        float vz = dot_sum(bu, &row->qv[0][2], 4, n + 1);
        if (!write_normal(ux, uy, uz, vx, vy, vz, o))
            fallback_normal(tp->src, (double)a / nu, (double)b / nv, o->normal);
    }
}

/* Generic rational row: homogeneous sums, one division for the position and
 * the quotient rule (without the common 1/w) for the normal's direction. */
static void row_rational(const tess_patch *tp, const tess_row *row, uint32_t nu, uint32_t b,
                         uint32_t nv, sw_vertex *out)
{
    int n = tp->n;
    for (uint32_t a = 0; a <= nu; a++) {
        const float *bu = tp->bu[a], *bud = tp->bud[a];
        sw_vertex *o = &out[a];
        float x[4], l[3], du[4], dv[4];
        for (int k = 0; k < 4; k++) {
            x[k] = sym_sum(bu, &row->q[0][k], 4, n);
            du[k] = dot_sum(bud, &row->dq[0][k], 4, n);
            dv[k] = dot_sum(bu, &row->qv[0][k], 4, n + 1);
        }
        float inv_w = 1.0f / x[3];
        for (int k = 0; k < 3; k++) {
            o->pos[k] = x[k] * inv_w;
            l[k] = dot_sum(bu, &row->ql[0][k], 4, n + 1) * inv_w;
        }
        /* F_u ~ X_u - w_u F (quotient rule without the 1/w), on the translated copy. */
        if (!write_normal(du[0] - du[3] * l[0], du[1] - du[3] * l[1], du[2] - du[3] * l[2],
                          dv[0] - dv[3] * l[0], dv[1] - dv[3] * l[1], dv[2] - dv[3] * l[2], o))
            fallback_normal(tp->src, (double)a / nu, (double)b / nv, o->normal);
    }
}

/* Bicubic polynomial row, unrolled. Positions use sym_sum's exact order. */
static void row_bicubic(const tess_patch *tp, const tess_row *row, uint32_t nu, uint32_t b,
                        uint32_t nv, sw_vertex *out)
{
    const float(*q)[4] = row->q, (*dq)[4] = row->dq, (*qv)[4] = row->qv;
    for (uint32_t a = 0; a <= nu; a++) {
        const float *bu = tp->bu[a], *bud = tp->bud[a];
        float b0 = bu[0], b1 = bu[1], b2 = bu[2], b3 = bu[3];
        float d0 = bud[0], d1 = bud[1], d2 = bud[2];
        sw_vertex *o = &out[a];
        float px = b0 * q[0][0] + b3 * q[3][0];
        float py = b0 * q[0][1] + b3 * q[3][1];
        float pz = b0 * q[0][2] + b3 * q[3][2];
        px += b1 * q[1][0] + b2 * q[2][0];
        py += b1 * q[1][1] + b2 * q[2][1];
        pz += b1 * q[1][2] + b2 * q[2][2];
        o->pos[0] = px, o->pos[1] = py, o->pos[2] = pz;
        float ux = d0 * dq[0][0] + d1 * dq[1][0] + d2 * dq[2][0];
        float uy = d0 * dq[0][1] + d1 * dq[1][1] + d2 * dq[2][1];
        float uz = d0 * dq[0][2] + d1 * dq[1][2] + d2 * dq[2][2];
        float vx = b0 * qv[0][0] + b1 * qv[1][0] + b2 * qv[2][0] + b3 * qv[3][0];
        float vy = b0 * qv[0][1] + b1 * qv[1][1] + b2 * qv[2][1] + b3 * qv[3][1];
        float vz = b0 * qv[0][2] + b1 * qv[1][2] + b2 * qv[2][2] + b3 * qv[3][2];
        if (!write_normal(ux, uy, uz, vx, vy, vz, o))
            fallback_normal(tp->src, (double)a / nu, (double)b / nv, o->normal);
    }
}

static void write_indices(uint32_t nu, uint32_t nv, uint32_t base, uint16_t *idx)
{
    uint32_t stride = nu + 1;
    for (uint32_t b = 0; b < nv; b++) {
        for (uint32_t a = 0; a < nu; a++) {
            uint32_t v00 = base + b * stride + a;
            uint32_t v10 = v00 + 1, v01 = v00 + stride, v11 = v01 + 1;
            idx[0] = (uint16_t)v00, idx[1] = (uint16_t)v10, idx[2] = (uint16_t)v11;
            idx[3] = (uint16_t)v00, idx[4] = (uint16_t)v11, idx[5] = (uint16_t)v01;
            idx += 6;
        }
    }
}

sw_tess_sizes sw_tess_grid_sizes(uint32_t nu, uint32_t nv)
{
    sw_tess_sizes s = {(nu + 1) * (nv + 1), 6 * nu * nv};
    return s;
}

void sw_tess_grid(const sw_bezier_patchf *patch, uint32_t nu, uint32_t nv, uint32_t base_vertex,
                  sw_vertex *verts, uint16_t *indices)
{
    tess_patch tp;
    tess_row row;
    prepare_patch(patch, nu, &tp);
    int bicubic = !patch->rational && patch->degree_u == 3 && patch->degree_v == 3;
    for (uint32_t b = 0; b <= nv; b++) {
        sw_vertex *out = verts + (size_t)b * (nu + 1);
        prepare_row(&tp, b, nv, &row);
        if (bicubic)
            row_bicubic(&tp, &row, nu, b, nv, out);
        else if (patch->rational)
            row_rational(&tp, &row, nu, b, nv, out);
        else
            row_polynomial(&tp, &row, nu, b, nv, out);
    }
    write_indices(nu, nv, base_vertex, indices);
}

/* Paper 000 section 4.1 (after Filip et al.): a triangle with parameter legs
 * l1, l2 deviates by at most (l1^2 M_uu + 2 l1 l2 M_uv + l2^2 M_vv) / 8. */
double sw_tess_grid_error_bound(const sw_deriv_bounds *bounds, uint32_t nu, uint32_t nv)
{
    double l1 = 1.0 / nu, l2 = 1.0 / nv;
    return (l1 * l1 * bounds->uu + 2 * l1 * l2 * bounds->uv + l2 * l2 * bounds->vv) / 8;
}

/* Smallest nv meeting the bound for this nu, 0 if none up to the cap. The
 * bound is a quadratic in x = 1 / nv: M_vv x^2 + 2 M_uv l1 x + M_uu l1^2 <= 8 e;
 * its root is the estimate, corrected by direct checks against rounding. */
static uint32_t min_nv(const sw_deriv_bounds *bd, double err, uint32_t nu)
{
    double l1 = 1.0 / nu, c0 = bd->uu * l1 * l1 - 8 * err, half_b = bd->uv * l1;
    if (c0 > 0)
        return 0;
    double x;
    if (bd->vv > 0)
        x = (-half_b + sqrt(half_b * half_b - bd->vv * c0)) / bd->vv;
    else
        x = half_b > 0 ? -c0 / (2 * half_b) : INFINITY;
    double est = x > 0 ? ceil(1 / x) : INFINITY;
    uint32_t nv = est < 1 ? 1 : est > SW_TESS_MAX_SEGMENTS ? SW_TESS_MAX_SEGMENTS : (uint32_t)est;
    while (nv > 1 && sw_tess_grid_error_bound(bd, nu, nv - 1) <= err)
        nv--;
    while (nv <= SW_TESS_MAX_SEGMENTS && sw_tess_grid_error_bound(bd, nu, nv) > err)
        nv++;
    return nv <= SW_TESS_MAX_SEGMENTS ? nv : 0;
}

static uint32_t lower_bound_segments(double m, double err)
{
    /* Even with the other direction infinitely fine, m l^2 / 8 <= err. */
    double s = floor(sqrt(m / (8 * err)));
    return s < 1 ? 1 : s > SW_TESS_MAX_SEGMENTS ? SW_TESS_MAX_SEGMENTS : (uint32_t)s;
}

/* error_world <= 0 (or NaN) cannot be met by any grid and is treated as
 * capped, as are non-finite bounds. */
int sw_tess_segments_for_error(const sw_deriv_bounds *bounds, double error_world, uint32_t *nu,
                               uint32_t *nv)
{
    const sw_deriv_bounds *b = bounds;
    int finite = isfinite(b->uu) && isfinite(b->uv) && isfinite(b->vv);
    if (!(error_world > 0) || !finite) {
        *nu = !finite || b->uu > 0 || b->uv > 0 ? SW_TESS_MAX_SEGMENTS : 1;
        *nv = !finite || b->vv > 0 || b->uv > 0 ? SW_TESS_MAX_SEGMENTS : 1;
        return 0;
    }
    uint32_t lo_u = lower_bound_segments(b->uu, error_world);
    uint32_t lo_v = lower_bound_segments(b->vv, error_world);
    uint32_t best_u = 0, best_v = 0;
    uint64_t best = UINT64_MAX;
    for (uint32_t u = lo_u; u <= SW_TESS_MAX_SEGMENTS; u++) {
        if ((uint64_t)u * lo_v > best)
            break;
        uint32_t v = min_nv(b, error_world, u);
        if (v == 0)
            continue;
        uint64_t prod = (uint64_t)u * v;
        if (prod < best || (prod == best && sw_tess_grid_error_bound(b, u, v) <
                                                sw_tess_grid_error_bound(b, best_u, best_v))) {
            best = prod, best_u = u, best_v = v;
        }
    }
    if (best_u == 0) {
        *nu = b->uu > 0 || b->uv > 0 ? SW_TESS_MAX_SEGMENTS : 1;
        *nv = b->vv > 0 || b->uv > 0 ? SW_TESS_MAX_SEGMENTS : 1;
        return 0;
    }
    *nu = best_u, *nv = best_v;
    return 1;
}
