/* SPDX-License-Identifier: MIT */
#include "sw_tess.h"

#include <assert.h>
#include <math.h>
#include <string.h>

/* Float Bernstein tables and sums. sw_tess_grid keeps its tables on the
 * stack, about 60 KB (u tables 32 KB, one row's columns 13 KB, control-point
 * copies 12 KB): keep it in mind for threads with small stacks. */
enum { MAXO = SW_BEZIER_MAX_ORDER, MAXV = SW_TESS_MAX_SEGMENTS + 1 };

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
    /* C(n, i) by the recurrence C(n, i + 1) = C(n, i) (n - i) / (i + 1),
     * exact in double for n <= 15. */
    double c = 1;
    for (int i = 0; i <= n; i++) {
        out[i] = (float)(c * (sp[n - i] * tp[i]));
        c = c * (n - i) / (i + 1);
    }
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
    /* Indexed [i][a], contiguous along the grid row so the column loops
     * below vectorise. */
    float bu[MAXO][MAXV];        /* B^n_i(a / nu) */
    float bud[MAXO - 1][MAXV];   /* B^(n-1)_i(a / nu): the hodograph's basis */
} tess_patch;

/* One grid row's results before packing, a float per column a. */
enum { PX, PY, PZ, UX, UY, UZ, VX, VY, VZ, W, LX, LY, LZ, COLS };
typedef struct tess_cols {
    float c[COLS][MAXV];
} tess_cols;

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
        float bv[MAXO], bd[MAXO];
        bernstein(n, a, nu, bv);
        bernstein(n - 1, a, nu, bd);
        for (int i = 0; i <= n; i++)
            tp->bu[i][a] = bv[i];
        for (int i = 0; i < n; i++)
            tp->bud[i][a] = bd[i];
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

/* Column-wise sym_sum: out[a] = sum_i b[i][a] x[i * stride] with exactly
 * sym_sum's order of operations for every a. */
static void sym_cols(const float (*b)[MAXV], const float *x, int stride, int n, uint32_t cnt,
                     float *restrict out)
{
    float x0 = x[0], xn = x[n * stride];
    const float *b0 = b[0], *bn = b[n];
    for (uint32_t a = 0; a < cnt; a++)
        out[a] = b0[a] * x0 + bn[a] * xn;
    int lo = 1, hi = n - 1;
    for (; lo < hi; lo++, hi--) {
        float xl = x[lo * stride], xh = x[hi * stride];
        const float *bl = b[lo], *bh = b[hi];
        for (uint32_t a = 0; a < cnt; a++)
            out[a] += bl[a] * xl + bh[a] * xh;
    }
    if (lo == hi) {
        float xl = x[lo * stride];
        const float *bl = b[lo];
        for (uint32_t a = 0; a < cnt; a++)
            out[a] += bl[a] * xl;
    }
}

/* Column-wise dot_sum over count terms. */
static void dot_cols(const float (*b)[MAXV], const float *x, int stride, int count, uint32_t cnt,
                     float *restrict out)
{
    for (uint32_t a = 0; a < cnt; a++)
        out[a] = 0;
    for (int i = 0; i < count; i++) {
        float xi = x[i * stride];
        const float *bi = b[i];
        for (uint32_t a = 0; a < cnt; a++)
            out[a] += bi[a] * xi;
    }
}

/* Packs one row: positions as they are, normals from du x dv. A normal is
 * degenerate when du and dv are (nearly) parallel or one is below 1e-5 of
 * the other (rounding noise at a collapsed edge); those take the double
 * evaluator's limit normal. */
static void finish_row(const tess_patch *tp, tess_cols *restrict t, uint32_t nu, uint32_t b,
                       uint32_t nv, sw_vertex *out)
{
    float *ux = t->c[UX], *uy = t->c[UY], *uz = t->c[UZ];
    float *vx = t->c[VX], *vy = t->c[VY], *vz = t->c[VZ];
    float *cx = t->c[W], *cy = t->c[LX], *cz = t->c[LY], *ok = t->c[LZ];
    for (uint32_t a = 0; a <= nu; a++) {
        float x = uy[a] * vz[a] - uz[a] * vy[a], y = uz[a] * vx[a] - ux[a] * vz[a];
        float z = ux[a] * vy[a] - uy[a] * vx[a];
        float cc = x * x + y * y + z * z;
        float uu = ux[a] * ux[a] + uy[a] * uy[a] + uz[a] * uz[a];
        float vv = vx[a] * vx[a] + vy[a] * vy[a] + vz[a] * vz[a];
        int good = cc > 1e-8f * uu * vv && uu > 1e-10f * vv && vv > 1e-10f * uu;
        cx[a] = x, cy[a] = y, cz[a] = z;
        ok[a] = good ? cc : 0.0f;
    }
    for (uint32_t a = 0; a <= nu; a++) {
        sw_vertex *o = &out[a];
        o->pos[0] = t->c[PX][a], o->pos[1] = t->c[PY][a], o->pos[2] = t->c[PZ][a];
        if (!(ok[a] > 0)) {
            fallback_normal(tp->src, (double)a / nu, (double)b / nv, o->normal);
            continue;
        }
        float inv = 1.0f / sqrtf(ok[a]);
        o->normal[0] = pack_snorm(cx[a] * inv);
        o->normal[1] = pack_snorm(cy[a] * inv);
        o->normal[2] = pack_snorm(cz[a] * inv);
        o->normal[3] = 0;
    }
}

/* Generic polynomial row: tensor sums with the precomputed u tables. */
static void row_polynomial(const tess_patch *tp, const tess_row *row, uint32_t nu,
                           tess_cols *t)
{
    int n = tp->n;
    for (int k = 0; k < 3; k++) {
        sym_cols(tp->bu, &row->q[0][k], 4, n, nu + 1, t->c[PX + k]);
        dot_cols(tp->bud, &row->dq[0][k], 4, n, nu + 1, t->c[UX + k]);
        dot_cols(tp->bu, &row->qv[0][k], 4, n + 1, nu + 1, t->c[VX + k]);
    }
}

/* Generic rational row: homogeneous sums, one division for the position and
 * the quotient rule F_u ~ X_u - w_u F (the common 1/w dropped, it does not
 * turn the normal) on the copy translated to the hull centre. */
static void row_rational(const tess_patch *tp, const tess_row *row, uint32_t nu, tess_cols *t)
{
    int n = tp->n;
    uint32_t cnt = nu + 1;
    float du_w[MAXV], dv_w[MAXV];
    sym_cols(tp->bu, &row->q[0][3], 4, n, cnt, t->c[W]);
    dot_cols(tp->bud, &row->dq[0][3], 4, n, cnt, du_w);
    dot_cols(tp->bu, &row->qv[0][3], 4, n + 1, cnt, dv_w);
    for (int k = 0; k < 3; k++) {
        float *p = t->c[PX + k], *l = t->c[LX + k], *u = t->c[UX + k], *v = t->c[VX + k];
        const float *w = t->c[W];
        sym_cols(tp->bu, &row->q[0][k], 4, n, cnt, p);
        dot_cols(tp->bu, &row->ql[0][k], 4, n + 1, cnt, l);
        dot_cols(tp->bud, &row->dq[0][k], 4, n, cnt, u);
        dot_cols(tp->bu, &row->qv[0][k], 4, n + 1, cnt, v);
        for (uint32_t a = 0; a < cnt; a++) {
            float inv_w = 1.0f / w[a];
            p[a] *= inv_w;
            u[a] -= du_w[a] * (l[a] * inv_w);
            v[a] -= dv_w[a] * (l[a] * inv_w);
        }
    }
}

/* Bicubic polynomial row, unrolled. Positions use sym_sum's exact order. */
static void row_bicubic(const tess_patch *tp, const tess_row *row, uint32_t nu,
                        tess_cols *restrict t)
{
    const float(*q)[4] = row->q, (*dq)[4] = row->dq, (*qv)[4] = row->qv;
    const float *b0 = tp->bu[0], *b1 = tp->bu[1], *b2 = tp->bu[2], *b3 = tp->bu[3];
    const float *d0 = tp->bud[0], *d1 = tp->bud[1], *d2 = tp->bud[2];
    for (int k = 0; k < 3; k++) {
        float q0 = q[0][k], q1 = q[1][k], q2 = q[2][k], q3 = q[3][k];
        float e0 = dq[0][k], e1 = dq[1][k], e2 = dq[2][k];
        float v0 = qv[0][k], v1 = qv[1][k], v2 = qv[2][k], v3 = qv[3][k];
        float *p = t->c[PX + k], *u = t->c[UX + k], *v = t->c[VX + k];
        for (uint32_t a = 0; a <= nu; a++) {
            float s = b0[a] * q0 + b3[a] * q3;
            p[a] = s + (b1[a] * q1 + b2[a] * q2);
            u[a] = d0[a] * e0 + d1[a] * e1 + d2[a] * e2;
            v[a] = b0[a] * v0 + b1[a] * v1 + b2[a] * v2 + b3[a] * v3;
        }
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
    assert(nu >= 1 && nu <= SW_TESS_MAX_SEGMENTS && nv >= 1 && nv <= SW_TESS_MAX_SEGMENTS);
    assert(base_vertex + (nu + 1) * (nv + 1) <= 65536u);
    assert(patch->degree_u >= 1 && patch->degree_u <= SW_BEZIER_MAX_DEGREE);
    assert(patch->degree_v >= 1 && patch->degree_v <= SW_BEZIER_MAX_DEGREE);
    tess_patch tp;
    tess_row row;
    tess_cols cols;
    prepare_patch(patch, nu, &tp);
    int bicubic = !patch->rational && patch->degree_u == 3 && patch->degree_v == 3;
    for (uint32_t b = 0; b <= nv; b++) {
        prepare_row(&tp, b, nv, &row);
        if (bicubic)
            row_bicubic(&tp, &row, nu, &cols);
        else if (patch->rational)
            row_rational(&tp, &row, nu, &cols);
        else
            row_polynomial(&tp, &row, nu, &cols);
        finish_row(&tp, &cols, nu, b, nv, verts + (size_t)b * (nu + 1));
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
