/* The binary trees of the trimmed tessellator (paper 004, section 6.3):
 * each patch is split, depth first, until its cells meet the error bound
 * (proved from the cell's own sub-patch) and the trims in them are simple;
 * then the corner index that lets each kept cell find its neighbours'
 * corners on its border. Part of core/sw_trim_tess.c's call. */
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

/* (x1, x2) pairs, x1 major. */
static int pair_less(const double *a, const double *b)
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

/* Sorting without allocation (libc's qsort may call malloc). */
static void sift_down(double *a, uint32_t i, uint32_t n)
{
    for (;;) {
        uint32_t big = i, l = 2 * i + 1, r = l + 1;
        if (l < n && pair_less(a + 2 * big, a + 2 * l))
            big = l;
        if (r < n && pair_less(a + 2 * big, a + 2 * r))
            big = r;
        if (big == i)
            return;
        double t0 = a[2 * i], t1 = a[2 * i + 1];
        a[2 * i] = a[2 * big], a[2 * i + 1] = a[2 * big + 1];
        a[2 * big] = t0, a[2 * big + 1] = t1, i = big;
    }
}

static void heap_sort(double *a, uint32_t n)
{
    for (uint32_t i = n / 2; i-- > 0;)
        sift_down(a, i, n);
    for (uint32_t end = n; end-- > 1;) {
        double t0 = a[0], t1 = a[1];
        a[0] = a[2 * end], a[1] = a[2 * end + 1];
        a[2 * end] = t0, a[2 * end + 1] = t1;
        sift_down(a, 0, end);
    }
}

static void swap_pairs(double *a, uint32_t i, uint32_t j)
{
    double t0 = a[2 * i], t1 = a[2 * i + 1];
    a[2 * i] = a[2 * j], a[2 * i + 1] = a[2 * j + 1];
    a[2 * j] = t0, a[2 * j + 1] = t1;
}

/* Introsort: quicksort (median of three, recursion on the smaller part only,
 * so the stack stays O(log n)), heap sort past 2 log2 n levels, insertion
 * sort for short runs. Cache-friendlier than heap sort alone; same bound. */
static void intro_sort(double *a, uint32_t n, int depth)
{
    while (n > 16) {
        if (depth-- == 0) {
            heap_sort(a, n);
            return;
        }
        uint32_t mid = n / 2, last = n - 1;
        if (pair_less(a + 2 * mid, a))
            swap_pairs(a, mid, 0);
        if (pair_less(a + 2 * last, a))
            swap_pairs(a, last, 0);
        if (pair_less(a + 2 * last, a + 2 * mid))
            swap_pairs(a, last, mid);
        double pivot[2] = {a[2 * mid], a[2 * mid + 1]};
        uint32_t i = 0, j = last;
        for (;;) {
            while (pair_less(a + 2 * i, pivot))
                i++;
            while (pair_less(pivot, a + 2 * j))
                j--;
            if (i >= j)
                break;
            swap_pairs(a, i, j);
            i++, j--;
        }
        uint32_t left = j + 1;
        if (left < n - left) {
            intro_sort(a, left, depth);
            a += 2 * left, n -= left;
        } else {
            intro_sort(a + 2 * left, n - left, depth);
            n = left;
        }
    }
    for (uint32_t i = 1; i < n; i++)
        for (uint32_t j = i; j > 0 && pair_less(a + 2 * j, a + 2 * (j - 1)); j--)
            swap_pairs(a, j, j - 1);
}

/* Sorts and drops repeats; returns the distinct count. */
static uint32_t sort_pairs(double *a, uint32_t n)
{
    int depth = 0;
    for (uint32_t x = n; x > 1; x /= 2)
        depth += 2;
    intro_sort(a, n, depth);
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++)
        if (m == 0 || a[2 * i] != a[2 * m - 2] || a[2 * i + 1] != a[2 * m - 1])
            a[2 * m] = a[2 * i], a[2 * m + 1] = a[2 * i + 1], m++;
    return m;
}

/* First pair after (x1, x2). */
static uint32_t after(const double *a, uint32_t n, double x1, double x2)
{
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        const double *m = a + 2 * mid;
        if (m[0] < x1 || (m[0] == x1 && m[1] <= x2))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Corners on the open segment x1 = line, lo < x2 < hi, ascending. */
static uint32_t on_side(const tt_ctx *c, int by_v, double line, double lo, double hi,
                        sw_tt_pv *out, uint32_t room)
{
    const double *a = by_v ? c->by_v : c->by_u;
    uint32_t n = 0;
    for (uint32_t i = after(a, c->corner_count, line, lo); i < c->corner_count; i++) {
        const double *p = a + 2 * i;
        if (p[0] != line || p[1] >= hi)
            break;
        if (n == room)
            return SW_TT_NONE;
        sw_tt_pv pv = {by_v ? p[1] : p[0], by_v ? p[0] : p[1], SW_TT_GRID, SW_TT_NONE, 0, 0, 0};
        out[n++] = pv;
    }
    return n;
}

static void reverse_pv(sw_tt_pv *p, uint32_t n)
{
    for (uint32_t i = 0, j = n ? n - 1 : 0; i < j; i++, j--) {
        sw_tt_pv t = p[i];
        p[i] = p[j], p[j] = t;
    }
}

uint32_t sw_tt_leaf_border(const tt_ctx *c, uint32_t l, sw_tt_pv *out, uint32_t cap)
{
    const sw_tt_rect *r = &c->leaves[l].r;
    const double cu[4] = {r->u0, r->u1, r->u1, r->u0}, cv[4] = {r->v0, r->v0, r->v1, r->v1};
    uint32_t n = 0;
    for (int k = 0; k < 4; k++) {
        if (n >= cap)
            return SW_TT_NONE;
        sw_tt_pv corner = {cu[k], cv[k], SW_TT_GRID, SW_TT_NONE, 0, 0, 0};
        out[n++] = corner;
        int by_v = k == 0 || k == 2;
        double line = k == 0 ? r->v0 : k == 1 ? r->u1 : k == 2 ? r->v1 : r->u0;
        double lo = by_v ? r->u0 : r->v0, hi = by_v ? r->u1 : r->v1;
        uint32_t m = on_side(c, by_v, line, lo, hi, out + n, cap - n);
        if (m == SW_TT_NONE)
            return SW_TT_NONE;
        if (k >= 2)
            reverse_pv(out + n, m); /* top and left run backwards */
        n += m;
    }
    return n;
}

static sw_status index_corners(tt_ctx *c)
{
    uint32_t n = 4 * c->leaf_count;
    c->by_u = sw_arena_alloc(c->arena, sizeof(double) * 2 * (n + 1), 8);
    c->by_v = sw_arena_alloc(c->arena, sizeof(double) * 2 * (n + 1), 8);
    if (!c->by_u || !c->by_v)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "corner index of %u cells", (unsigned)c->leaf_count);
    for (uint32_t l = 0; l < c->leaf_count; l++) {
        const sw_tt_rect *r = &c->leaves[l].r;
        const double cu[4] = {r->u0, r->u1, r->u1, r->u0}, cv[4] = {r->v0, r->v0, r->v1, r->v1};
        for (int k = 0; k < 4; k++) {
            double *u = c->by_u + 2 * (4 * l + (uint32_t)k), *v = c->by_v + 2 * (4 * l + (uint32_t)k);
            u[0] = cu[k], u[1] = cv[k], v[0] = cv[k], v[1] = cu[k];
        }
    }
    c->corner_count = sort_pairs(c->by_u, n);
    sort_pairs(c->by_v, n);
    return SW_OK;
}

/* ---- refinement ------------------------------------------------------------ */

/* Segments of in[0..n) that meet the closed rectangle, appended to the list
 * stack; SW_TT_NONE when the stack is full. */
static uint32_t filter_segments(tt_ctx *c, const sw_tt_rect *r, const uint32_t *in, uint32_t n)
{
    uint32_t count = 0;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t s = in ? in[k] : k;
        const sw_tt_point *a = &c->pts[s], *b = &c->pts[a->next];
        double t0, t1;
        int s0, s1;
        if (fmax(a->u, b->u) < r->u0 || fmin(a->u, b->u) > r->u1 || fmax(a->v, b->v) < r->v0 ||
            fmin(a->v, b->v) > r->v1 || !sw_tt_clip(r, a, b, &t0, &s0, &t1, &s1))
            continue;
        if (c->list_top + count >= c->list_cap)
            return SW_TT_NONE;
        c->list[c->list_top + count++] = s;
    }
    c->list_top += count;
    return count;
}

/* A crossed cell splits while it holds a whole hole (a ring cannot have one)
 * or more than SW_TT_MAX_CELL_POINTS loop points. */
static int trims_too_complex(const tt_ctx *c, const sw_tt_rect *r, const uint32_t *list, uint32_t n)
{
    uint32_t inside = 0;
    for (uint32_t k = 0; k < n; k++) {
        const sw_tt_point *a = &c->pts[list[k]];
        if (!sw_tt_inside(r, a->u, a->v))
            continue;
        if (++inside > SW_TT_MAX_CELL_POINTS)
            return 1;
        const sw_tt_loop *l = &c->loops[a->loop];
        if (l->hole && list[k] == l->first && l->box[0] > r->u0 && l->box[1] < r->u1 &&
            l->box[2] > r->v0 && l->box[3] < r->v1)
            return 1;
    }
    return 0;
}

static sw_vec3 eval_point(const sw_bezier_patch *p, double u, double v)
{
    sw_surface_point q;
    sw_bezier_eval(p, u, v, SW_EVAL_POINT, &q);
    return q.p;
}

/* Paper 004, 6.3: split where the surface is farthest from the bilinear
 * approximation, sampled at 5 points along the axis on the cell's middle
 * line, kept in the middle half so the tree stays shallow. */
static double split_fraction(const sw_bezier_patch *p, int axis)
{
    sw_vec3 f00 = eval_point(p, 0, 0), f10 = eval_point(p, 1, 0);
    sw_vec3 f01 = eval_point(p, 0, 1), f11 = eval_point(p, 1, 1);
    double best = -1, at = 0.5;
    for (int i = 1; i <= 5; i++) {
        double s = i / 6.0, u = axis ? 0.5 : s, v = axis ? s : 0.5;
        sw_vec3 lo = sw_v3_lerp(f00, f10, u), hi = sw_v3_lerp(f01, f11, u);
        sw_vec3 d = sw_v3_sub(eval_point(p, u, v), sw_v3_lerp(lo, hi, v));
        double dd = sw_v3_dot(d, d);
        if (dd > best)
            best = dd, at = s;
    }
    return fmin(fmax(at, 0.25), 0.75);
}

/* For a split forced by the trims: the side longer in model space. */
static int longer_axis(const sw_bezier_patch *p)
{
    int n = p->degree_u, m = p->degree_v;
    const double *c = p->ctrl;
    size_t i00 = 0, i10 = (size_t)n * 4, i01 = (size_t)m * (size_t)(n + 1) * 4,
           i11 = i01 + (size_t)n * 4;
    sw_vec3 a = sw_v3(c[i00], c[i00 + 1], c[i00 + 2]), b = sw_v3(c[i10], c[i10 + 1], c[i10 + 2]);
    sw_vec3 d = sw_v3(c[i01], c[i01 + 1], c[i01 + 2]), e = sw_v3(c[i11], c[i11 + 1], c[i11 + 2]);
    double lu = sw_v3_length(sw_v3_sub(b, a)) + sw_v3_length(sw_v3_sub(e, d));
    double lv = sw_v3_length(sw_v3_sub(d, a)) + sw_v3_length(sw_v3_sub(e, b));
    return lv > lu;
}

/* Better than the paper's nearest-neighbour rule alone: a split line through
 * a loop point meets the loop there, so that point becomes a border vertex of
 * both halves and no crossing (with its borrowed position) is needed. Of the
 * loop points in the cell's middle band (0.2 .. 0.8 along the axis) where the
 * loop passes through the line, the one nearest the wanted split x, or NAN.
 * Only points the region shrink did not move along the axis (a seam along the
 * other axis, as on the domain's border) qualify: their coordinate is the
 * caller's float, so two such lines are equal or a float step apart, never a
 * rounding error apart. */
static double split_through_point(const tt_ctx *c, const tt_frame *f, int axis, double x)
{
    double lo = axis ? f->r.v0 : f->r.u0, hi = axis ? f->r.v1 : f->r.u1, best = NAN;
    double band_lo = lo + 0.2 * (hi - lo), band_hi = hi - 0.2 * (hi - lo);
    const uint32_t *list = c->list + f->list_off;
    for (uint32_t k = 0; k < f->list_count; k++) {
        const sw_tt_point *p = &c->pts[list[k]];
        if (!sw_tt_inside(&f->r, p->u, p->v))
            continue;
        double along = axis ? p->v : p->u;
        if (along <= band_lo || along >= band_hi ||
            along != c->in_loops->points[p->src].uv[axis])
            continue;
        /* Only where the loop goes through the line, not where it turns back
         * (a tangent line would leave the point touching one half only). */
        const sw_tt_loop *l = &c->loops[p->loop];
        uint32_t i = (uint32_t)(p - c->pts), before = i == l->first ? l->first + l->count - 1 : i - 1;
        double da = (axis ? c->pts[before].v : c->pts[before].u) - along;
        double db = (axis ? c->pts[p->next].v : c->pts[p->next].u) - along;
        if (!((da < 0 && db > 0) || (da > 0 && db < 0)))
            continue;
        if (isnan(best) || fabs(along - x) < fabs(best - x))
            best = along;
    }
    return best;
}

/* The split coordinate: through a loop point when the cell holds one (above),
 * else snapped to a lattice of 2^-22 of the patch and rounded to a float, so
 * splits computed along different paths of the tree (2/3 of 1/3, 1/2 of 4/9)
 * land on one line instead of two lines an ulp apart (output (u, v) are
 * floats). A loop point may lie exactly on the line: the clipping makes such a
 * point a border vertex of both cells (sw_trim_cell.c, crossing()). 0 when the
 * cell is too narrow to split. */
static int place_split(const tt_ctx *c, const tt_frame *f, int axis, double s, double *at)
{
    const float *d = c->in_patches[f->patch].domain;
    double lo = axis ? f->r.v0 : f->r.u0, hi = axis ? f->r.v1 : f->r.u1;
    double p0 = axis ? d[2] : d[0], w = (axis ? d[3] : d[1]) - p0, steps = 4194304.0;
    double x = lo + s * (hi - lo), q = nearbyint((x - p0) / w * steps);
    double through = f->list_count ? split_through_point(c, f, axis, x) : NAN;
    *at = isnan(through) ? (float)(p0 + q * (w / steps)) : through;
    return lo < *at && *at < hi;
}

static sw_status add_leaf(tt_ctx *c, const tt_frame *f)
{
    if (c->leaf_count == c->leaf_cap || c->leaf_seg_count + f->list_count > c->leaf_seg_cap)
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: more than %u cells (or their loop "
                            "lists) at error %g: coarsen the bound", (unsigned)c->leaf_cap,
                            c->error);
    tt_leaf *l = &c->leaves[c->leaf_count++];
    l->r = f->r, l->patch = f->patch, l->crossed = f->list_count > 0;
    l->seg_first = c->leaf_seg_count, l->seg_count = f->list_count;
    memcpy(c->leaf_segs + c->leaf_seg_count, c->list + f->list_off,
           sizeof(uint32_t) * f->list_count);
    c->leaf_seg_count += f->list_count;
    return SW_OK;
}

typedef struct tt_stack {
    tt_frame *frames;
    double *ctrl, *tmp;   /* ctrl: one slot per frame; tmp: the parent while splitting */
    size_t stride;
} tt_stack;

/* Replaces the popped frame f (slot top) by its two halves in slots top
 * (the upper half, processed last) and top + 1. */
static sw_status push_halves(tt_ctx *c, tt_stack *st, uint32_t top, const tt_frame *f,
                             int axis, double at)
{
    const sw_bezier_patch *src = &c->patches[f->patch];
    memcpy(st->tmp, st->ctrl + top * st->stride, sizeof(double) * st->stride);
    sw_bezier_patch parent = {src->degree_u, src->degree_v, src->rational, st->tmp};
    double lo = axis ? f->r.v0 : f->r.u0, hi = axis ? f->r.v1 : f->r.u1;
    double s = (at - lo) / (hi - lo);
    tt_frame parts[2] = {*f, *f};
    for (int h = 0; h < 2; h++) {
        tt_frame *p = &parts[h];
        double s0 = h ? 0 : s, s1 = h ? s : 1;  /* h = 0: the upper half */
        if (axis)
            p->r.v0 = h ? f->r.v0 : at, p->r.v1 = h ? at : f->r.v1;
        else
            p->r.u0 = h ? f->r.u0 : at, p->r.u1 = h ? at : f->r.u1;
        p->depth = f->depth + 1;
        sw_bezier_subpatch(&parent, axis ? 0 : s0, axis ? 1 : s1, axis ? s0 : 0, axis ? s1 : 1,
                           st->ctrl + (top + (uint32_t)h) * st->stride);
        p->list_off = c->list_top;
        p->list_count = filter_segments(c, &p->r, c->list + f->list_off, f->list_count);
        if (p->list_count == SW_TT_NONE)
            return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                                "cells' loop lists");
        st->frames[top + (uint32_t)h] = *p;
    }
    return SW_OK;
}

/* One cell: dropped (outside), kept (a leaf) or split. *pushed says how many
 * frames it left on the stack. */
static sw_status visit(tt_ctx *c, tt_stack *st, uint32_t top, int *pushed)
{
    tt_frame f = st->frames[top];
    *pushed = 0;
    if (f.list_count == 0 && !f.inside) {
        if (!sw_tt_classify(&c->trims, 0.5 * (f.r.u0 + f.r.u1), 0.5 * (f.r.v0 + f.r.v1)))
            return SW_OK;
        f.inside = 1;
    }
    const sw_bezier_patch *src = &c->patches[f.patch];
    sw_bezier_patch cell = {src->degree_u, src->degree_v, src->rational,
                            st->ctrl + top * st->stride};
    sw_deriv_bounds b;
    sw_status s = sw_bezier_second_deriv_bounds(&cell, &b, c->err);
    if (s != SW_OK)
        return s;
    double e = (b.uu + 2 * b.uv + b.vv) / 8;
    double target = f.list_count > 0 ? c->border_error : c->error;
    int forced = f.list_count > 0 && trims_too_complex(c, &f.r, c->list + f.list_off,
                                                       f.list_count);
    int axis = 0;
    double at = 0;
    int split = (e > target || forced) && f.depth < c->max_depth;
    if (split) {
        axis = e > target ? b.vv > b.uu : longer_axis(&cell);
        split = place_split(c, &f, axis, e > target ? split_fraction(&cell, axis) : 0.5, &at);
    }
    if (!split) {
        c->res->capped_count += e > target;
        c->res->error_bound = fmax(c->res->error_bound, e);
        return add_leaf(c, &f);
    }
    st->frames[top] = f;
    *pushed = 2;
    return push_halves(c, st, top, &f, axis, at);
}

static sw_status refine_patch(tt_ctx *c, tt_stack *st, uint32_t p)
{
    const float *d = c->in_patches[p].domain;
    tt_frame root = {{d[0], d[1], d[2], d[3]}, p, 0, 0, 0, 0};
    c->list_top = 0;
    root.list_count = filter_segments(c, &root.r, NULL, c->trims.point_count);
    if (root.list_count == SW_TT_NONE)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "cells' loop lists");
    memcpy(st->ctrl, c->patches[p].ctrl, sizeof(double) *
           sw_tt_ctrl_doubles(c->patches[p].degree_u, c->patches[p].degree_v));
    st->frames[0] = root;
    uint32_t top = 1;
    while (top > 0) {
        top--;
        c->list_top = st->frames[top].list_off + st->frames[top].list_count;
        int pushed;
        sw_status s = visit(c, st, top, &pushed);
        if (s != SW_OK)
            return s;
        top += (uint32_t)pushed;
    }
    return SW_OK;
}

sw_status sw_tt_build_tree(tt_ctx *c)
{
    uint32_t slots = 2 * c->max_depth + 4, n = c->trims.point_count;
    tt_stack st;
    st.stride = sw_tt_ctrl_doubles(c->max_n, c->max_m);
    st.frames = sw_arena_alloc(c->arena, sizeof *st.frames * slots, 8);
    st.ctrl = sw_arena_alloc(c->arena, sizeof(double) * st.stride * (slots + 1), 8);
    /* Each level of the depth-first stack holds two lists of at most n. */
    c->list_cap = (2 * c->max_depth + 4) * n + 64;
    c->list = sw_arena_alloc(c->arena, sizeof(uint32_t) * c->list_cap, 4);
    c->leaf_cap = c->max_vertices;
    c->leaves = sw_arena_alloc(c->arena, sizeof *c->leaves * (c->leaf_cap + 1), 8);
    c->leaf_seg_cap = 4 * c->max_vertices + 2 * n;
    c->leaf_segs = sw_arena_alloc(c->arena, sizeof(uint32_t) * (c->leaf_seg_cap + 1), 4);
    if (!st.frames || !st.ctrl || !c->list || !c->leaves || !c->leaf_segs)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the trees "
                            "(see sw_trim_tess_scratch_bytes)");
    st.tmp = st.ctrl + st.stride * slots;
    for (uint32_t p = 0; p < c->patch_count; p++) {
        sw_status s = refine_patch(c, &st, p);
        if (s != SW_OK)
            return s;
    }
    return index_corners(c);
}
