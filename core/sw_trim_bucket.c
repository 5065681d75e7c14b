/* SPDX-License-Identifier: MIT */
/* The loops' segments by grid cell (core/sw_trim_tess.c): each segment is
 * walked column by column over the grid (its v range within the column,
 * then the rows of that range, each tested exactly with sw_tt_clip against
 * the closed cell), the (cell, segment) pairs sorted by row, then column, by
 * two counting passes. Where a cell holds a whole hole (ear clipping takes
 * rings without holes) or more than SW_TT_MAX_CELL_POINTS loop points
 * (clipping cost grows with their square, and long seams would end in fans
 * of slivers), whole grid lines are added through it and the bucketing runs
 * again: added lines only make cells smaller, so the bound still holds and
 * the grid stays conformal. */
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

/* sw_tt_interval, trying *hint and its neighbours first: consecutive loop
 * points mostly lie in one cell or the next. */
static uint32_t locate(const double *lines, uint32_t n, double x, uint32_t *hint)
{
    uint32_t h = *hint;
    if (h < n && lines[h] <= x && (x < lines[h + 1] || h + 1 == n))
        return h;
    if (h + 1 < n && lines[h + 1] <= x && (x < lines[h + 2] || h + 2 == n))
        return *hint = h + 1;
    if (h > 0 && h - 1 < n && lines[h - 1] <= x && x < lines[h])
        return *hint = h - 1;
    return *hint = sw_tt_interval(lines, n + 1, x);
}

/* The cells whose closed interval meets [lo, hi]: first and last. */
static void cell_range(const double *lines, uint32_t n, double lo, double hi, uint32_t *a,
                       uint32_t *b, uint32_t *hint)
{
    *a = locate(lines, n, lo, hint);
    if (*a > 0 && lines[*a] == lo)
        (*a)--;
    *b = lo == hi ? locate(lines, n, hi, hint) : sw_tt_interval(lines, n + 1, hi);
}

static sw_status add_pair(tt_ctx *c, uint32_t col, uint32_t row, uint32_t seg)
{
    if (c->pair_count >= c->pair_cap)
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: the loops cross more than %u "
                            "cells at error %g: coarsen the bound", (unsigned)c->pair_cap,
                            c->error);
    tt_pair *p = &c->pairs[c->pair_count++];
    p->col = col, p->row = row, p->seg = seg;
    return SW_OK;
}

static sw_status bucket_segment(tt_ctx *c, uint32_t s, uint32_t hint[2])
{
    const tt_grid *g = &c->grid;
    const sw_tt_point *a = &c->pts[s], *b = &c->pts[a->next];
    double umin = a->u < b->u ? a->u : b->u, umax = a->u < b->u ? b->u : a->u;
    double vmin = a->v < b->v ? a->v : b->v, vmax = a->v < b->v ? b->v : a->v;
    double du = b->u - a->u, dv = b->v - a->v;
    double slack = 1e-9 * (vmax - vmin) + 1e-12 * (g->gv[g->nrow] - g->gv[0]);
    uint32_t i0, i1;
    cell_range(g->gu, g->ncol, umin, umax, &i0, &i1, &hint[0]);
    for (uint32_t i = i0; i <= i1; i++) {
        double lo = vmin, hi = vmax;
        if (du != 0) {
            double ua = fmax(umin, g->gu[i]), ub = fmin(umax, g->gu[i + 1]);
            double va = a->v + (ua - a->u) / du * dv, vb = a->v + (ub - a->u) / du * dv;
            lo = fmax(vmin, fmin(va, vb) - slack), hi = fmin(vmax, fmax(va, vb) + slack);
        }
        uint32_t j0, j1;
        cell_range(g->gv, g->nrow, lo, hi, &j0, &j1, &hint[1]);
        for (uint32_t j = j0; j <= j1; j++) {
            sw_tt_rect r = {g->gu[i], g->gu[i + 1], g->gv[j], g->gv[j + 1]};
            double t0, t1;
            int s0, s1;
            if (!sw_tt_clip(&r, a, b, &t0, &s0, &t1, &s1))
                continue;
            sw_status st = add_pair(c, i, j, s);
            if (st != SW_OK)
                return st;
        }
    }
    return SW_OK;
}

/* Stable counting sort of the pairs by key (col or row) into dst; first
 * (n + 1 entries) gets each key's first index. */
static void count_sort(const tt_pair *src, tt_pair *dst, uint32_t count, int by_row, uint32_t n,
                       uint32_t *first)
{
    memset(first, 0, sizeof(uint32_t) * (n + 1));
    for (uint32_t i = 0; i < count; i++)
        first[(by_row ? src[i].row : src[i].col) + 1]++;
    for (uint32_t k = 0; k < n; k++)
        first[k + 1] += first[k];
    for (uint32_t i = 0; i < count; i++) {
        uint32_t k = by_row ? src[i].row : src[i].col;
        dst[first[k]++] = src[i];
    }
    for (uint32_t k = n; k > 0; k--)
        first[k] = first[k - 1];
    first[0] = 0;
}

static sw_status bucket_all(tt_ctx *c, tt_pair *tmp, uint32_t *col_first)
{
    c->pair_count = 0;
    uint32_t hint[2] = {0, 0};
    for (uint32_t s = 0; s < c->trims.point_count; s++) {
        sw_status st = bucket_segment(c, s, hint);
        if (st != SW_OK)
            return st;
    }
    count_sort(c->pairs, tmp, c->pair_count, 0, c->grid.ncol, col_first);
    count_sort(tmp, c->pairs, c->pair_count, 1, c->grid.nrow, c->row_first);
    return SW_OK;
}

/* Lines to add, collected while the pairs' indices are valid. */
enum { MAX_ADD = 256 };
typedef struct additions {
    double at[MAX_ADD];
    int axis[MAX_ADD];
    int n;
} additions;

static void add_line(additions *ad, int axis, double at)
{
    if (ad->n < MAX_ADD)
        ad->at[ad->n] = at, ad->axis[ad->n++] = axis;
}

/* A line through the cell of pairs [a, b) when it holds too many loop
 * points: through the middle of their spread, across the axis along which
 * they spread more (relative to the cell). */
static void split_crowded(const tt_ctx *c, uint32_t a, uint32_t b, additions *ad)
{
    const tt_grid *g = &c->grid;
    const tt_pair *p = &c->pairs[a];
    sw_tt_rect r = {g->gu[p->col], g->gu[p->col + 1], g->gv[p->row], g->gv[p->row + 1]};
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    uint32_t inside = 0;
    for (uint32_t k = a; k < b; k++) {
        const sw_tt_point *q = &c->pts[c->pairs[k].seg];
        if (!sw_tt_inside(&r, q->u, q->v))
            continue;
        inside++;
        box[0] = fmin(box[0], q->u), box[1] = fmax(box[1], q->u);
        box[2] = fmin(box[2], q->v), box[3] = fmax(box[3], q->v);
    }
    if (inside <= SW_TT_MAX_CELL_POINTS * SW_TT_MAX_SPLIT)
        return;
    int axis = (box[3] - box[2]) / (r.v1 - r.v0) > (box[1] - box[0]) / (r.u1 - r.u0);
    add_line(ad, axis, 0.5 * (box[2 * axis] + box[2 * axis + 1]));
}

/* A hole inside one cell gets a line through its middle. */
static void split_holes(const tt_ctx *c, additions *ad)
{
    const tt_grid *g = &c->grid;
    for (uint32_t k = 0; k < c->trims.loop_count; k++) {
        const sw_tt_loop *l = &c->loops[k];
        if (!l->hole)
            continue;
        uint32_t i = sw_tt_interval(g->gu, g->ncol + 1, l->box[0]);
        uint32_t j = sw_tt_interval(g->gv, g->nrow + 1, l->box[2]);
        if (!(l->box[0] > g->gu[i] && l->box[1] < g->gu[i + 1] && l->box[2] > g->gv[j] &&
              l->box[3] < g->gv[j + 1]))
            continue;
        int axis = (l->box[3] - l->box[2]) / (g->gv[j + 1] - g->gv[j]) >
                   (l->box[1] - l->box[0]) / (g->gu[i + 1] - g->gu[i]);
        add_line(ad, axis, 0.5 * (l->box[2 * axis] + l->box[2 * axis + 1]));
    }
}

static sw_status refine_round(tt_ctx *c, int *added)
{
    additions ad;
    ad.n = 0;
    split_holes(c, &ad);
    for (uint32_t a = 0; a < c->pair_count;) {
        uint32_t b = a + 1;
        while (b < c->pair_count && c->pairs[b].col == c->pairs[a].col &&
               c->pairs[b].row == c->pairs[a].row)
            b++;
        if (b - a > SW_TT_MAX_CELL_POINTS * SW_TT_MAX_SPLIT)
            split_crowded(c, a, b, &ad);
        a = b;
    }
    *added = ad.n;
    for (int k = 0; k < ad.n; k++) {
        sw_status s = sw_tt_insert_line(c, ad.axis[k], ad.at[k]);
        if (s != SW_OK)
            return s;
    }
    return SW_OK;
}

sw_status sw_tt_bucket(tt_ctx *c)
{
    const tt_grid *g = &c->grid;
    c->pair_cap = 4 * c->max_vertices + 2 * c->trims.point_count + 64;
    c->pairs = sw_arena_alloc(c->arena, sizeof(tt_pair) * c->pair_cap, 4);
    tt_pair *tmp = sw_arena_alloc(c->arena, sizeof(tt_pair) * c->pair_cap, 4);
    c->row_first = sw_arena_alloc(c->arena, sizeof(uint32_t) * (g->cap_v + 2), 4);
    uint32_t *col_first = sw_arena_alloc(c->arena, sizeof(uint32_t) * (g->cap_u + 2), 4);
    if (!c->pairs || !tmp || !c->row_first || !col_first)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "loops' cells (see sw_trim_tess_scratch_bytes)");
    for (int round = 0;; round++) {
        sw_status s = bucket_all(c, tmp, col_first);
        if (s != SW_OK || round == SW_TT_REFINE_ROUNDS)
            return s;
        int added;
        if ((s = refine_round(c, &added)) != SW_OK)
            return s;
        if (!added)
            return SW_OK;
    }
}
