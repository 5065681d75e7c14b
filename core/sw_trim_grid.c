/* SPDX-License-Identifier: MIT */
/* The trimmed tessellator's conformal tensor grid (core/sw_trim_tess.c):
 * columns are the patches' knot intervals in u, rows in v, each split into
 * sub-patch intervals (2, or 4 on rational surfaces, whose bounds tighten
 * slowly) and those into uniform grid intervals. The
 * counts come from the second-derivative bounds of every sub-patch
 * (sw_bezier_second_deriv_bounds on the exact de Casteljau sub-patch): a
 * column takes the largest count any sub-patch in it needs, a row likewise,
 * so every cell of every sub-patch meets (M_uu h_u^2 + 2 M_uv h_u h_v +
 * M_vv h_v^2) / 8 <= error and any triangle with its corners in one cell is
 * within error of the surface (Taylor with integral remainder; barycentric
 * variance <= h^2 / 4). Whole grid lines, never a local split, so no cell
 * has a T-vertex. Only sub-patches meeting the loops' box are bounded.
 * Three things keep the counts down: the counts are then lowered by
 * coordinate descent (rows as few as the columns allow, then columns),
 * every sub-patch bound is capped by the whole patch's (an exact bound the
 * piece's own proof may miss), and a knot interval merged into one grid
 * interval takes the largest of its pieces' bounds, not the whole patch's
 * (a cylinder's row the full height keeps the pieces' M_uu). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

#define SUB ((int)g->sub) /* sub-patch intervals per knot interval, per axis */

static void sift_down(double *a, uint32_t i, uint32_t n)
{
    for (;;) {
        uint32_t big = i, l = 2 * i + 1, r = l + 1;
        if (l < n && a[l] > a[big])
            big = l;
        if (r < n && a[r] > a[big])
            big = r;
        if (big == i)
            return;
        double t = a[i];
        a[i] = a[big], a[big] = t, i = big;
    }
}

/* Heap sort (libc's qsort may allocate), then repeats dropped. */
static uint32_t sort_unique(double *a, uint32_t n)
{
    for (uint32_t i = n / 2; i-- > 0;)
        sift_down(a, i, n);
    for (uint32_t end = n; end-- > 1;) {
        double t = a[0];
        a[0] = a[end], a[end] = t;
        sift_down(a, 0, end);
    }
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++)
        if (m == 0 || a[i] != a[m - 1])
            a[m++] = a[i];
    return m;
}

uint32_t sw_tt_interval(const double *lines, uint32_t n, double x)
{
    uint32_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (lines[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

uint32_t sw_tt_knot_patch(const tt_ctx *c, uint32_t kc, uint32_t kr)
{
    const tt_grid *g = &c->grid;
    if (kc + 1 >= g->nku || kr + 1 >= g->nkv)
        return SW_TT_NONE;
    return g->table[(size_t)kr * (g->nku - 1) + kc];
}

/* The knot lines and which patch covers which knot cell. Patches must tile
 * a grid of knot intervals (sw_pack_patch_domain), one cell each. */
static sw_status build_knots(tt_ctx *c)
{
    tt_grid *g = &c->grid;
    uint32_t n = c->patch_count;
    g->ku = sw_arena_alloc(c->arena, sizeof(double) * 2 * n, 8);
    g->kv = sw_arena_alloc(c->arena, sizeof(double) * 2 * n, 8);
    if (!g->ku || !g->kv)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for knots");
    for (uint32_t i = 0; i < n; i++) {
        const float *d = c->in_patches[i].domain;
        g->ku[2 * i] = d[0], g->ku[2 * i + 1] = d[1], g->kv[2 * i] = d[2], g->kv[2 * i + 1] = d[3];
    }
    g->nku = sort_unique(g->ku, 2 * n), g->nkv = sort_unique(g->kv, 2 * n);
    g->sub = 2;
    for (uint32_t i = 0; i < n; i++)
        if (c->in_patches[i].patch.rational)
            g->sub = SW_TT_MAX_SUB;
    uint64_t cells = (uint64_t)(g->nku - 1) * (g->nkv - 1);
    if (cells > 4 * (uint64_t)n + 16)
        return sw_error_set(c->err, SW_ERR_ARG, "trim tess: %u patches on %u x %u knot "
                            "intervals: expected a grid of knot intervals", (unsigned)n,
                            (unsigned)g->nku - 1, (unsigned)g->nkv - 1);
    g->table = sw_arena_alloc(c->arena, sizeof(uint32_t) * (size_t)cells, 4);
    g->bounded = sw_arena_alloc(c->arena, n, 1);
    g->bounds = sw_arena_alloc(c->arena, sizeof(double) * 3 * SUB * SUB * n, 8);
    g->whole = sw_arena_alloc(c->arena, sizeof(double) * 3 * n, 8);
    if (!g->table || !g->bounded || !g->bounds || !g->whole)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for knots");
    memset(g->table, 0xFF, sizeof(uint32_t) * (size_t)cells);
    memset(g->bounded, 0, n);
    for (uint32_t i = 0; i < n; i++) {
        const float *d = c->in_patches[i].domain;
        uint32_t kc = sw_tt_interval(g->ku, g->nku, d[0]), kr = sw_tt_interval(g->kv, g->nkv, d[2]);
        uint32_t *slot = &g->table[(size_t)kr * (g->nku - 1) + kc];
        if (g->ku[kc + 1] != d[1] || g->kv[kr + 1] != d[3] || *slot != SW_TT_NONE)
            return sw_error_set(c->err, SW_ERR_ARG, "trim tess: patch %u: domain [%g, %g] x "
                                "[%g, %g] spans several knot intervals or overlaps patch %u",
                                (unsigned)i, d[0], d[1], d[2], d[3],
                                *slot == SW_TT_NONE ? (unsigned)i : (unsigned)*slot);
        *slot = i;
    }
    return SW_OK;
}

/* sw_bezier_second_deriv_bounds for a polynomial patch (w = 1: the quotient
 * rule's terms vanish), the same bound with one square root per derivative
 * instead of one per difference: the largest second differences of the
 * control points translated to the hull's centre, times n (n - 1), n m,
 * m (m - 1), with the same rounding margin (equal to it within 1e-15
 * relative on random patches, well inside the 1e-12 margin). */
static void poly_bounds(const double *ctrl, int n, int m, double *out)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t row = 4 * (size_t)(n + 1);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++)
            for (int k = 0; k < 3; k++) {
                double x = ctrl[(size_t)j * row + 4 * (size_t)i + (size_t)k];
                lo[k] = x < lo[k] ? x : lo[k], hi[k] = x > hi[k] ? x : hi[k];
            }
    double c[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    double r2 = 0, uu = 0, uv = 0, vv = 0;
    for (int j = 0; j <= m; j++) {
        for (int i = 0; i <= n; i++) {
            const double *p = ctrl + (size_t)j * row + 4 * (size_t)i;
            double du2 = 0, dv2 = 0, duv = 0, pr = 0;
            for (int k = 0; k < 3; k++) {
                double x = p[k] - c[k];
                pr += x * x;
                if (i + 2 <= n) {
                    double d = (p[8 + k] - c[k]) - 2 * (p[4 + k] - c[k]) + x;
                    du2 += d * d;
                }
                if (j + 2 <= m) {
                    double d = (p[2 * row + k] - c[k]) - 2 * (p[row + k] - c[k]) + x;
                    dv2 += d * d;
                }
                if (i < n && j < m) {
                    double d = ((p[row + 4 + k] - c[k]) - (p[row + k] - c[k])) -
                               ((p[4 + k] - c[k]) - x);
                    duv += d * d;
                }
            }
            /* plain comparisons: fmax is a libm call here, and all are finite */
            r2 = pr > r2 ? pr : r2, uu = du2 > uu ? du2 : uu;
            vv = dv2 > vv ? dv2 : vv, uv = duv > uv ? duv : uv;
        }
    }
    double fn = n, fm = m, radius = sqrt(r2);
    double slack = 64 * DBL_EPSILON * radius * (n + m) * (n + m);
    out[0] = sqrt(uu) * fn * (fn - 1) * (1 + 1e-12) + (n > 1 ? slack : 0);
    out[1] = sqrt(uv) * fn * fm * (1 + 1e-12) + slack;
    out[2] = sqrt(vv) * fm * (fm - 1) * (1 + 1e-12) + (m > 1 ? slack : 0);
}

static sw_status patch_bounds(tt_ctx *c, const sw_bezier_patch *p, double *out)
{
    if (!p->rational) {
        poly_bounds(p->ctrl, p->degree_u, p->degree_v, out);
        return SW_OK;
    }
    sw_deriv_bounds b;
    sw_status s = sw_bezier_second_deriv_bounds(p, &b, c->err);
    /* an extruded patch's mixed term: 0 on a cylinder, where the general
     * bound made every cell of the cylinder four times too short */
    out[0] = b.uu, out[1] = fmin(b.uv, sw_bezier_extrusion_mixed_bound(p)), out[2] = b.vv;
    return s;
}

/* Bounds of the sub^2 sub-patches of patch p, in the sub-patch's own
 * [0,1]^2 parameters. */
/* A polynomial patch split at the middle of axis (0: u) by de Casteljau
 * (exact up to rounding): lo and hi, the same layout. */
static void split_half(const double *ctrl, int n, int m, int axis, double *lo, double *hi)
{
    size_t row = 4 * (size_t)(n + 1);
    int deg = axis ? m : n, lines = axis ? n + 1 : m + 1;
    size_t step = axis ? row : 4, across = axis ? 4 : row;
    for (int l = 0; l < lines; l++) {
        for (int k = 0; k < 4; k++) {
            double t[SW_BEZIER_MAX_ORDER];
            size_t at = (size_t)l * across + (size_t)k;
            for (int i = 0; i <= deg; i++)
                t[i] = ctrl[at + (size_t)i * step];
            for (int r = 0; r <= deg; r++) {
                lo[at + (size_t)r * step] = t[0];
                hi[at + (size_t)(deg - r) * step] = t[deg - r];
                for (int i = 0; i < deg - r; i++)
                    t[i] = 0.5 * (t[i] + t[i + 1]);
            }
        }
    }
}

/* Bounds of patch p and of its sub^2 sub-patches (in the sub-patch's
 * own [0,1]^2 parameters); tmp holds three patches. */
static sw_status bound_patch(tt_ctx *c, uint32_t p, double *tmp)
{
    tt_grid *g = &c->grid;
    if (g->bounded[p])
        return SW_OK;
    const sw_bezier_patch *src = &c->patches[p];
    sw_status st = patch_bounds(c, src, g->whole + 3 * (size_t)p);
    if (st != SW_OK)
        return st;
    size_t size = sw_tt_ctrl_doubles(src->degree_u, src->degree_v);
    double *half = tmp + size, *sub_ctrl = tmp + 2 * size;
    for (int su = 0; su < SUB; su++) {
        if (!src->rational && SUB == 2)
            split_half(src->ctrl, src->degree_u, src->degree_v, 0, su ? tmp : half,
                       su ? half : tmp);
        for (int sv = 0; sv < SUB; sv++) {
            if (!src->rational && SUB == 2) {
                if (sv == 0)
                    split_half(half, src->degree_u, src->degree_v, 1, sub_ctrl, tmp);
                else
                    memcpy(sub_ctrl, tmp, sizeof(double) * size);
            } else {
                sw_bezier_subpatch(src, (double)su / SUB, (double)(su + 1) / SUB,
                                   (double)sv / SUB, (double)(sv + 1) / SUB, sub_ctrl);
            }
            sw_bezier_patch sub = {src->degree_u, src->degree_v, src->rational, sub_ctrl};
            double *o = g->bounds + 3 * ((size_t)p * SUB * SUB + sv * SUB + su);
            if ((st = patch_bounds(c, &sub, o)) != SW_OK)
                return st;
            /* The whole patch's bounds hold on every piece of it (in the
             * piece's units, divided by SUB^2). Tighter where the piece's
             * own proof is blind: a cylinder's pieces are extrusions too,
             * but their computed weights differ in the last bit, so only the
             * whole patch gets the exact mixed bound 0. */
            for (int k = 0; k < 3; k++)
                o[k] = fmin(o[k], g->whole[3 * (size_t)p + (size_t)k] / (SUB * SUB));
        }
    }
    g->bounded[p] = 1;
    return SW_OK;
}

/* Fewest intervals along the second axis with n along the first, for
 * bounds a (first axis), b (mixed), cc (second), or 0 when none is enough. */
static double second_for(double a, double b, double cc, double r, double n)
{
    double x = 1 / n, rest = r - a * x * x;
    if (!(rest > 0))
        return 0;
    double bx = b * x, y;
    if (cc > 0)
        y = (-bx + sqrt(bx * bx + cc * rest)) / cc;
    else
        y = bx > 0 ? rest / (2 * bx) : 1;
    double k = fmax(1, ceil(1 / y));
    while ((a * x * x + 2 * b * x / k + cc / (k * k)) > r)
        k++;
    return k;
}

/* Counts (nu, nv) for a sub-patch with bounds m, about the fewest cells:
 * the continuous optimum h_u sqrt(M_uu) = h_v sqrt(M_vv) rounded and its
 * neighbours, and the slivers one or two intervals wide along either axis
 * (a bound with M_uv > 0 but M_vv = 0, as the rational cylinder's, is
 * cheapest with full-height strips). Capped at cap (then *capped). */
static void solve_counts(const double *m, double e, double cap, double *nu, double *nv,
                         int *capped)
{
    double r = 8 * e;
    *nu = *nv = 1, *capped = 0;
    if (m[0] + 2 * m[1] + m[2] <= r)
        return;
    double ideal = 1;
    if (m[0] > 0 && m[2] > 0) {
        double sa = sqrt(m[0]), sc = sqrt(m[2]);
        ideal = sa / sqrt(r / (2 + 2 * m[1] / (sa * sc)));
    }
    /* first-axis counts to try: along u (k < 5) or along v */
    const double cand[8] = {fmax(1, floor(ideal)), ceil(ideal), ceil(ideal) + 1, 1, 2, 1, 2,
                            ceil(ideal * sqrt(m[2] / fmax(m[0], 1e-300)))};
    double best = INFINITY;
    for (int k = 0; k < 8; k++) {
        int along_v = k >= 5;
        double a = fmin(cand[k], cap);
        double b = along_v ? second_for(m[2], m[1], m[0], r, a)
                           : second_for(m[0], m[1], m[2], r, a);
        if (b > 0 && a * b < best)
            best = a * b, *nu = along_v ? b : a, *nv = along_v ? a : b;
    }
    if (!isfinite(best))
        *nu = cap, *nv = cap;
    if (*nu > cap || *nv > cap || !isfinite(best))
        *capped = 1;
    *nu = fmin(*nu, cap), *nv = fmin(*nv, cap);
}

static int meets_box(const tt_grid *g, uint32_t kc, uint32_t kr, int su, int sv)
{
    double w = (g->ku[kc + 1] - g->ku[kc]) / SUB, h = (g->kv[kr + 1] - g->kv[kr]) / SUB;
    double u0 = g->ku[kc] + su * w, v0 = g->kv[kr] + sv * h;
    return u0 <= g->box[1] && u0 + w >= g->box[0] && v0 <= g->box[3] && v0 + h >= g->box[2];
}

/* Per sub-patch interval of each axis the count of grid intervals. */
static sw_status choose_counts(tt_ctx *c, double *cu, double *cv)
{
    tt_grid *g = &c->grid;
    uint32_t nkc = g->nku - 1, nkr = g->nkv - 1;
    double cap = fmin(ldexp(1.0, (int)c->max_depth), (double)c->max_vertices);
    size_t ctrl = sw_tt_ctrl_doubles(c->max_n, c->max_m);
    double *tmp = sw_arena_alloc(c->arena, 3 * sizeof(double) * ctrl, 8);
    if (!tmp)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for a patch");
    for (uint32_t i = 0; i < nkc * SUB; i++)
        cu[i] = 1;
    for (uint32_t i = 0; i < nkr * SUB; i++)
        cv[i] = 1;
    for (uint32_t kr = 0; kr < nkr; kr++) {
        for (uint32_t kc = 0; kc < nkc; kc++) {
            uint32_t p = sw_tt_knot_patch(c, kc, kr);
            if (p == SW_TT_NONE || !(g->ku[kc] <= g->box[1] && g->ku[kc + 1] >= g->box[0] &&
                                     g->kv[kr] <= g->box[3] && g->kv[kr + 1] >= g->box[2]))
                continue;
            sw_status s = bound_patch(c, p, tmp);
            if (s != SW_OK)
                return s;
            for (int sv = 0; sv < SUB; sv++) {
                for (int su = 0; su < SUB; su++) {
                    if (!meets_box(g, kc, kr, su, sv))
                        continue;
                    const double *m = g->bounds + 3 * ((size_t)p * SUB * SUB +
                                                       sv * SUB + su);
                    double nu, nv;
                    int capped;
                    solve_counts(m, c->error, cap, &nu, &nv, &capped);
                    c->res->capped_count += (uint32_t)capped;
                    cu[kc * SUB + su] = fmax(cu[kc * SUB + su], nu);
                    cv[kr * SUB + sv] = fmax(cv[kr * SUB + sv], nv);
                }
            }
        }
    }
    return SW_OK;
}

/* The fewest intervals along axis (0: u) in sub-patch interval s of knot
 * interval k that keep every bounded sub-patch there within e with the
 * other axis's counts as they are: at least 1; 0 when one cannot be met
 * (a capped count). */
static double least_count(const tt_ctx *c, const double *cu, const double *cv, int axis,
                          uint32_t k, int s)
{
    const tt_grid *g = &c->grid;
    uint32_t across = (axis ? g->nku : g->nkv) - 1;
    double most = 1;
    for (uint32_t o = 0; o < across; o++) {
        uint32_t kc = axis ? o : k, kr = axis ? k : o;
        uint32_t p = sw_tt_knot_patch(c, kc, kr);
        if (p == SW_TT_NONE || !g->bounded[p])
            continue;
        for (int t = 0; t < SUB; t++) {
            int su = axis ? t : s, sv = axis ? s : t;
            if (!meets_box(g, kc, kr, su, sv))
                continue;
            const double *m = g->bounds + 3 * ((size_t)p * SUB * SUB + sv * SUB + su);
            double need = axis ? second_for(m[0], m[1], m[2], 8 * c->error, cu[kc * SUB + su])
                               : second_for(m[2], m[1], m[0], 8 * c->error, cv[kr * SUB + sv]);
            if (!(need > 0))
                return 0;
            most = fmax(most, need);
        }
    }
    return most;
}

/* choose_counts gives each column the largest count any sub-patch in it
 * wants at that sub-patch's own best shape, and each row likewise, so
 * where sub-patches want different shapes (one tall cells, its neighbour
 * wide ones) both axes take the finer count and every cell is finer than
 * any sub-patch needs. Coordinate descent on the counts: rows as few as
 * the columns allow, then columns as few as the rows allow, until nothing
 * drops (each step keeps every sub-patch within e; counts only fall). */
static void tighten_counts(tt_ctx *c, double *cu, double *cv)
{
    const tt_grid *g = &c->grid;
    for (int round = 0; round < 8; round++) {
        int dropped = 0;
        for (int axis = 1; axis >= 0; axis--) {
            double *cnt = axis ? cv : cu;
            uint32_t nk = (axis ? g->nkv : g->nku) - 1;
            for (uint32_t k = 0; k < nk; k++)
                for (int s = 0; s < SUB; s++) {
                    double need = least_count(c, cu, cv, axis, k, s);
                    if (need > 0 && need < cnt[k * SUB + (uint32_t)s])
                        cnt[k * SUB + (uint32_t)s] = need, dropped = 1;
                }
        }
        if (!dropped)
            break;
    }
}

/* Grid lines of one axis from the counts; SW_ERR_RANGE past the cap. */
static sw_status lay_lines(tt_ctx *c, const double *knots, uint32_t nk, const double *count,
                           double **lines, uint32_t **kidx, uint8_t **sidx, uint32_t *n,
                           uint32_t *cap)
{
    const tt_grid *g = &c->grid;
    double total = 0;
    for (uint32_t i = 0; i < (nk - 1) * SUB; i++)
        total += count[i];
    if (total > (double)c->max_vertices + 4.0 * c->patch_count)
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: %.0f grid lines at error %g: "
                            "coarsen the bound", total, c->error);
    *cap = (uint32_t)total + SW_TT_MAX_INSERT;
    *lines = sw_arena_alloc(c->arena, sizeof(double) * (*cap + 1), 8);
    *kidx = sw_arena_alloc(c->arena, sizeof(uint32_t) * (*cap + 1), 4);
    *sidx = sw_arena_alloc(c->arena, *cap + 1, 1);
    if (!*lines || !*kidx || !*sidx)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the grid");
    uint32_t m = 0;
    for (uint32_t k = 0; k + 1 < nk; k++) {
        double w = knots[k + 1] - knots[k];
        int merged = count[k * SUB + 1] == 0;
        for (int s = 0; s < SUB; s++) {
            uint32_t cnt = (uint32_t)count[k * SUB + (uint32_t)s];
            for (uint32_t i = 0; i < cnt; i++) {
                double x = merged ? knots[k] : knots[k] + w * ((s + (double)i / cnt) / SUB);
                if (merged) {
                    (*lines)[m] = x, (*kidx)[m] = k, (*sidx)[m] = SW_TT_WHOLE, m++;
                    continue;
                }
                if (m > 0 && !(x > (*lines)[m - 1]))
                    return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: grid intervals "
                                        "below the double step at error %g", c->error);
                (*lines)[m] = x, (*kidx)[m] = k, (*sidx)[m] = (uint8_t)s, m++;
            }
        }
    }
    (*lines)[m] = knots[nk - 1], (*kidx)[m] = nk - 2, (*sidx)[m] = SUB - 1;
    *n = m;
    return SW_OK;
}

/* The bound of a cell hu x hv (patch units) in sub-patch (su, sv) of patch
 * p; SW_TT_WHOLE for an interval not split into sub-patches (then the whole
 * patch's bounds hold). */
static void bound_terms(const tt_grid *g, uint32_t p, uint32_t su, uint32_t sv, double hu,
                        double hv, double t[3])
{
    double m[3] = {0, 0, 0};
    if (su != SW_TT_WHOLE && sv != SW_TT_WHOLE) {
        const double *b = g->bounds + 3 * ((size_t)p * SUB * SUB + sv * SUB + su);
        hu *= SUB, hv *= SUB;
        m[0] = b[0], m[1] = b[1], m[2] = b[2];
    } else {
        /* A cell across the sub-patches of a merged interval: each bound
         * over the union is the largest of the pieces' (in patch units), or
         * the whole patch's where smaller. Not the whole patch's alone: a
         * merged row of a cylinder (straight along v) would take the whole
         * arc's M_uu. */
        uint32_t a0 = su == SW_TT_WHOLE ? 0 : su, a1 = su == SW_TT_WHOLE ? g->sub : su + 1;
        uint32_t b0 = sv == SW_TT_WHOLE ? 0 : sv, b1 = sv == SW_TT_WHOLE ? g->sub : sv + 1;
        for (uint32_t b = b0; b < b1; b++)
            for (uint32_t a = a0; a < a1; a++)
                for (int k = 0; k < 3; k++)
                    m[k] = fmax(m[k], g->bounds[3 * ((size_t)p * SUB * SUB + b * SUB + a) + k] *
                                          (SUB * SUB));
        for (int k = 0; k < 3; k++)
            m[k] = fmin(m[k], g->whole[3 * (size_t)p + (size_t)k]);
    }
    t[0] = m[0] * hu * hu / 8, t[1] = 2 * m[1] * hu * hv / 8, t[2] = m[2] * hv * hv / 8;
}

static double bound_in(const tt_grid *g, uint32_t p, uint32_t su, uint32_t sv, double hu, double hv)
{
    double t[3];
    bound_terms(g, p, su, sv, hu, hv, t);
    return t[0] + t[1] + t[2];
}

/* Interval s of knot interval k with counts cnt: its sub-patch index
 * (SW_TT_WHOLE when merged) and its grid intervals' size in patch units;
 * 0 when s is merged into s = 0. */
static double interval_size(const tt_grid *g, const double *cnt, uint32_t k, uint32_t s,
                            uint32_t *sub)
{
    const double *n = cnt + (size_t)k * SUB;
    int merged = n[1] == 0;
    *sub = merged ? SW_TT_WHOLE : s;
    if (merged)
        return s == 0 ? 1.0 : 0.0;
    return 1.0 / (SUB * n[s]);
}

/* Largest bound over the cells of the bounded patches meeting the box (of
 * knot column or row `only` along axis, when axis >= 0); with check, 1 when
 * it is within e (nothing reported). */
static int grid_bound(tt_ctx *c, const double *cu, const double *cv, double e, int check,
                      int axis, uint32_t only)
{
    const tt_grid *g = &c->grid;
    uint32_t r0 = axis == 1 ? only : 0, r1 = axis == 1 ? only + 1 : g->nkv - 1;
    uint32_t c0 = axis == 0 ? only : 0, c1 = axis == 0 ? only + 1 : g->nku - 1;
    for (uint32_t kr = r0; kr < r1; kr++)
        for (uint32_t kc = c0; kc < c1; kc++) {
            uint32_t p = sw_tt_knot_patch(c, kc, kr);
            if (p == SW_TT_NONE || !g->bounded[p])
                continue;
            for (uint32_t sv = 0; sv < g->sub; sv++)
                for (uint32_t su = 0; su < g->sub; su++) {
                    uint32_t bu, bv;
                    double hu = interval_size(g, cu, kc, su, &bu);
                    double hv = interval_size(g, cv, kr, sv, &bv);
                    if (hu == 0 || hv == 0 || !meets_box(g, kc, kr, (int)su, (int)sv))
                        continue;
                    double b = bound_in(g, p, bu, bv, hu, hv);
                    if (check && b > e)
                        return 0;
                    if (!check)
                        c->res->error_bound = fmax(c->res->error_bound, b);
                }
        }
    return 1;
}

/* Knot intervals whose sub-intervals all take one grid interval become one
 * grid interval where the whole patch's bound allows it (a plane stays two
 * triangles; far away a patch needs no more): columns first, then rows,
 * each kept only if every cell of the grid stays within e. */
static void merge_intervals(tt_ctx *c, double *cu, double *cv)
{
    const tt_grid *g = &c->grid;
    for (int axis = 0; axis < 2; axis++) {
        double *cnt = axis ? cv : cu;
        uint32_t nk = (axis ? g->nkv : g->nku) - 1;
        for (uint32_t k = 0; k < nk; k++) {
            double *n = cnt + (size_t)k * SUB;
            int ones = 1;
            for (int s = 0; s < SUB; s++)
                ones &= n[s] == 1;
            if (!ones)
                continue;
            for (int s = 1; s < SUB; s++)
                n[s] = 0;
            if (!grid_bound(c, cu, cv, c->error, 1, axis, k))
                for (int s = 1; s < SUB; s++)
                    n[s] = 1;
        }
    }
}

int sw_tt_cell_terms(const tt_ctx *c, uint32_t col, uint32_t row, double t[3])
{
    const tt_grid *g = &c->grid;
    uint32_t kc = g->col_k[col], kr = g->row_k[row], p = sw_tt_knot_patch(c, kc, kr);
    if (p == SW_TT_NONE || !g->bounded[p])
        return 0;
    double hu = (g->gu[col + 1] - g->gu[col]) / (g->ku[kc + 1] - g->ku[kc]);
    double hv = (g->gv[row + 1] - g->gv[row]) / (g->kv[kr + 1] - g->kv[kr]);
    bound_terms(g, p, g->col_s[col], g->row_s[row], hu, hv, t);
    return 1;
}

double sw_tt_cell_bound(const tt_ctx *c, uint32_t col, uint32_t row, uint32_t parts_u,
                        uint32_t parts_v)
{
    double t[3];
    if (!sw_tt_cell_terms(c, col, row, t))
        return -1;
    return sw_tt_parts_bound(t, parts_u, parts_v);
}

static void find_box_range(tt_ctx *c)
{
    tt_grid *g = &c->grid;
    g->c0 = sw_tt_interval(g->gu, g->ncol + 1, g->box[0]);
    g->c1 = sw_tt_interval(g->gu, g->ncol + 1, g->box[1]) + 1;
    g->r0 = sw_tt_interval(g->gv, g->nrow + 1, g->box[2]);
    g->r1 = sw_tt_interval(g->gv, g->nrow + 1, g->box[3]) + 1;
}

sw_status sw_tt_insert_line(tt_ctx *c, int axis, double x)
{
    tt_grid *g = &c->grid;
    double *l = axis ? g->gv : g->gu;
    uint32_t *n = axis ? &g->nrow : &g->ncol, *kidx = axis ? g->row_k : g->col_k;
    uint8_t *sidx = axis ? g->row_s : g->col_s;
    uint32_t k = sw_tt_interval(l, *n + 1, x);
    if (!(x > l[k] && x < l[k + 1]))
        return SW_OK;
    if (*n >= (axis ? g->cap_v : g->cap_u))
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: more than %d grid lines added "
                            "for the loops", SW_TT_MAX_INSERT);
    memmove(l + k + 2, l + k + 1, sizeof(double) * (*n - k));
    memmove(kidx + k + 2, kidx + k + 1, sizeof(uint32_t) * (*n - k));
    memmove(sidx + k + 2, sidx + k + 1, *n - k);
    l[k + 1] = x, kidx[k + 1] = kidx[k], sidx[k + 1] = sidx[k];
    (*n)++;
    find_box_range(c);
    return SW_OK;
}

sw_status sw_tt_build_grid(tt_ctx *c)
{
    tt_grid *g = &c->grid;
    sw_status s = build_knots(c);
    if (s != SW_OK)
        return s;
    g->box[0] = g->box[2] = INFINITY, g->box[1] = g->box[3] = -INFINITY;
    for (uint32_t k = 0; k < c->trims.loop_count; k++)
        for (int i = 0; i < 4; i++)
            g->box[i] = i % 2 ? fmax(g->box[i], c->loops[k].box[i])
                              : fmin(g->box[i], c->loops[k].box[i]);
    double *cu = sw_arena_alloc(c->arena, sizeof(double) * (g->nku - 1) * SUB, 8);
    double *cv = sw_arena_alloc(c->arena, sizeof(double) * (g->nkv - 1) * SUB, 8);
    if (!cu || !cv)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the grid");
    s = choose_counts(c, cu, cv);
    if (s != SW_OK)
        return s;
    tighten_counts(c, cu, cv);
    merge_intervals(c, cu, cv);
    grid_bound(c, cu, cv, 0, 0, -1, 0);
    if ((s = lay_lines(c, g->ku, g->nku, cu, &g->gu, &g->col_k, &g->col_s, &g->ncol,
                       &g->cap_u)) != SW_OK ||
        (s = lay_lines(c, g->kv, g->nkv, cv, &g->gv, &g->row_k, &g->row_s, &g->nrow,
                       &g->cap_v)) != SW_OK)
        return s;
    find_box_range(c);
    return SW_OK;
}
