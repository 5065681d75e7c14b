/* SPDX-License-Identifier: MIT */
/* The row sweep of the trimmed tessellator (core/sw_trim_tess.c): the grid's
 * rows inside the loops' box from bottom to top. A row's crossed cells are
 * its runs of (cell, segment) pairs; between them lie runs of cells no loop
 * touches, wholly inside or wholly outside: the even-odd count of the loop
 * crossings on the row's middle line left of the run decides. Inside cells
 * are two triangles on the grid points (vertex ids of the current and next
 * grid line only); crossed cells go through the clipping (sw_tt_cell_rings)
 * and ear clipping. Crossed cells whose bound exceeds border_error, or that
 * hold many loop points, are clipped as k x k parts; their neighbours then
 * carry the parts' corners on the shared side, so no T-vertex appears. */
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

typedef struct sweep {
    tt_ctx *c;
    uint8_t *split[3];       /* per row slot (row % 3): a crossed cell's parts (parts_of) */
    uint32_t *seg_mark, mark;
    double *xs;              /* crossings of the row's middle line, sorted */
    uint32_t nx;
    uint32_t *segs;          /* a (sub)cell's segments */
    uint8_t *group_parts;    /* per pair starting a cell's run: the cell's parts */
    int any_split[3];        /* per row slot: some cell split */
} sweep;

/* Parts of cell (col, row) along u (axis 0) or v: 1 unless crossed and
 * split. A slot holds parts_u - 1 in its low and parts_v - 1 in its high
 * nibble. */
static uint32_t parts_of(const sweep *w, uint32_t col, uint32_t row, int axis)
{
    const tt_grid *g = &w->c->grid;
    if (row >= g->nrow || col >= g->ncol)
        return 1;
    uint8_t k = w->split[row % 3][col];
    return 1u + (axis ? k >> 4 : k & 15u);
}

/* Parts of a crossed cell: the fewest parts_u x parts_v that bring its
 * bound within border_error, at least k x k where it holds k times
 * SW_TT_MAX_CELL_POINTS loop points (clipping cost grows with their
 * square), at most SW_TT_MAX_SPLIT per axis. */
static uint8_t parts_for(tt_ctx *c, uint32_t col, uint32_t row, uint32_t a, uint32_t b)
{
    const tt_grid *g = &c->grid;
    sw_tt_rect r = {g->gu[col], g->gu[col + 1], g->gv[row], g->gv[row + 1]};
    uint32_t inside = 0, ku = 1, kv = 1;
    for (uint32_t i = a; i < b; i++) {
        const sw_tt_point *q = &c->pts[c->pairs[i].seg];
        inside += sw_tt_inside(&r, q->u, q->v);
    }
    uint32_t crowd = (inside + SW_TT_MAX_CELL_POINTS - 1) / SW_TT_MAX_CELL_POINTS;
    crowd = crowd < 1 ? 1 : crowd > SW_TT_MAX_SPLIT ? SW_TT_MAX_SPLIT : crowd;
    double t[3];
    if (c->border_error < c->error && sw_tt_cell_terms(c, col, row, t) &&
        sw_tt_parts_bound(t, crowd, crowd) > c->border_error) {
        uint32_t best = SW_TT_MAX_SPLIT * SW_TT_MAX_SPLIT + 1;
        ku = kv = SW_TT_MAX_SPLIT;
        for (uint32_t i = crowd; i <= SW_TT_MAX_SPLIT; i++)
            for (uint32_t j = crowd; j <= SW_TT_MAX_SPLIT && i * j < best; j++)
                if (sw_tt_parts_bound(t, i, j) <= c->border_error)
                    best = i * j, ku = i, kv = j;
        if (best > SW_TT_MAX_SPLIT * SW_TT_MAX_SPLIT) /* capped: say so */
            c->res->error_bound = fmax(c->res->error_bound, sw_tt_parts_bound(t, ku, kv));
    } else {
        ku = kv = crowd;
    }
    return (uint8_t)((ku - 1) | (kv - 1) << 4);
}

/* Every crossed cell's parts, at the first of its pairs; returns a bound on
 * the vertices the table will hold: per segment in a cell its crossings with
 * the parts' lines, per split cell its parts' corners. */
static uint32_t plan_parts(sweep *w)
{
    tt_ctx *c = w->c;
    uint64_t hashed = 64;
    for (uint32_t a = 0; a < c->pair_count;) {
        uint32_t b = a + 1, col = c->pairs[a].col, row = c->pairs[a].row;
        while (b < c->pair_count && c->pairs[b].col == col && c->pairs[b].row == row)
            b++;
        uint8_t k = parts_for(c, col, row, a, b);
        uint32_t ku = 1u + (k & 15u), kv = 1u + (k >> 4);
        w->group_parts[a] = k;
        hashed += (uint64_t)(b - a) * (ku + kv + 2) + (k ? (ku + 1) * (kv + 1) : 0);
        a = b;
    }
    return hashed > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)hashed;
}

static void mark_splits(sweep *w, uint32_t row)
{
    tt_ctx *c = w->c;
    if (row >= c->grid.nrow)
        return;
    uint8_t *s = w->split[row % 3];
    memset(s, 0, c->grid.ncol);
    w->any_split[row % 3] = 0;
    for (uint32_t a = c->row_first[row]; a < c->row_first[row + 1]; a++)
        if (a == c->row_first[row] || c->pairs[a - 1].col != c->pairs[a].col) {
            s[c->pairs[a].col] = w->group_parts[a];
            w->any_split[row % 3] |= w->group_parts[a] != 0;
        }
}

/* Even-odd count of the row's segments crossing the line v right of u. */
static int classify_in_row(sweep *w, uint32_t row, double u, double v)
{
    tt_ctx *c = w->c;
    int inside = 0;
    w->mark++;
    for (uint32_t a = c->row_first[row]; a < c->row_first[row + 1]; a++) {
        uint32_t s = c->pairs[a].seg;
        if (w->seg_mark[s] == w->mark)
            continue;
        w->seg_mark[s] = w->mark;
        const sw_tt_point *p = &c->pts[s], *q = &c->pts[p->next];
        if ((p->v > v) == (q->v > v))
            continue;
        inside ^= p->u + (v - p->v) / (q->v - p->v) * (q->u - p->u) > u;
    }
    return inside;
}

static void sort_doubles(double *a, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        double x = a[i];
        uint32_t j = i;
        for (; j > 0 && a[j - 1] > x; j--)
            a[j] = a[j - 1];
        a[j] = x;
    }
}

/* The crossings of the row's middle line, sorted. Rows hold few; a row
 * with many (a comb of a loop) sorts by insertion in O(k^2), bounded by the
 * loop points. */
static void row_crossings(sweep *w, uint32_t row)
{
    tt_ctx *c = w->c;
    double v = 0.5 * (c->grid.gv[row] + c->grid.gv[row + 1]);
    w->nx = 0;
    w->mark++;
    for (uint32_t a = c->row_first[row]; a < c->row_first[row + 1]; a++) {
        uint32_t s = c->pairs[a].seg;
        if (w->seg_mark[s] == w->mark)
            continue;
        w->seg_mark[s] = w->mark;
        const sw_tt_point *p = &c->pts[s], *q = &c->pts[p->next];
        if ((p->v > v) != (q->v > v))
            w->xs[w->nx++] = p->u + (v - p->v) / (q->v - p->v) * (q->u - p->u);
    }
    sort_doubles(w->xs, w->nx);
}

/* Vertex of a polygon point of cell (col, row): a grid corner through the
 * line arrays, anything else through the vertex table. */
static sw_status map_pv(tt_ctx *c, uint32_t p, uint32_t col, uint32_t row, const sw_tt_pv *pv,
                        uint32_t *out)
{
    const tt_grid *g = &c->grid;
    if (pv->kind == SW_TT_GRID) {
        int iu = pv->u == g->gu[col] ? 0 : pv->u == g->gu[col + 1] ? 1 : -1;
        int iv = pv->v == g->gv[row] ? 0 : pv->v == g->gv[row + 1] ? 1 : -1;
        if (iu >= 0 && iv >= 0)
            return sw_tt_grid_vertex(c, p, col + (uint32_t)iu, row + (uint32_t)iv, out);
    }
    return sw_tt_vertex_for(c, p, pv, out);
}

static sw_status emit_ring(tt_ctx *c, uint32_t p, uint32_t col, uint32_t row,
                           const sw_tt_pv *ring, uint32_t n)
{
    uint32_t *map = sw_arena_alloc(c->arena, sizeof(uint32_t) * 6 * (size_t)n, 4);
    double *quality = sw_arena_alloc(c->arena, sizeof(double) * n, 8);
    if (!map || !quality)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for a cell");
    uint32_t *scratch = map + n, *tri = map + 3 * (size_t)n;
    for (uint32_t i = 0; i < n; i++) {
        sw_status s = map_pv(c, p, col, row, &ring[i], &map[i]);
        if (s != SW_OK)
            return s;
    }
    uint32_t count = sw_tt_ear_clip(ring, n, scratch, quality, tri, &c->res->fallback_ears);
    for (uint32_t t = 0; t < count; t++) {
        uint32_t a = map[tri[3 * t]], b = map[tri[3 * t + 1]], d = map[tri[3 * t + 2]];
        if (a != b && b != d && d != a) /* not collapsed onto a loop point */
            sw_tt_put_triangle(c, a, b, d);
    }
    return SW_OK;
}

static sw_tt_pv grid_pv(double u, double v)
{
    sw_tt_pv pv = {u, v, SW_TT_GRID, SW_TT_NONE, 0, 0, 0, 0};
    return pv;
}

/* x of the m-th of k parts of [a, b]: a + (b - a) (m / k), so that equal
 * fractions of different k give the same double (m / k is correctly rounded),
 * and exactly a and b at the ends. */
static double part(double a, double b, uint32_t m, uint32_t k)
{
    return m == 0 ? a : m == k ? b : a + (b - a) * ((double)m / k);
}

/* Points of a neighbour split in k parts on the side from fraction f0 to
 * f1 (exclusive), the side running from a to b along u (along_v 0) or v,
 * at the fixed coordinate x; in the order of the walk (reverse: from f1). */
static uint32_t side_points(double a, double b, double x, int along_v, uint32_t k, double f0,
                            double f1, int reverse, sw_tt_pv *out)
{
    uint32_t n = 0;
    for (uint32_t i = 1; i < k; i++) {
        uint32_t m = reverse ? k - i : i;
        double f = (double)m / k;
        if (!(f > f0 && f < f1))
            continue;
        double y = part(a, b, m, k);
        out[n++] = along_v ? grid_pv(x, y) : grid_pv(y, x);
    }
    return n;
}

/* The border of part (sa, sb) of ku x kv of cell (col, row), counter-
 * clockwise from its (u0, v0): its corners and, on the cell's sides, the
 * part corners of split neighbours, so no T-vertex appears. */
static uint32_t cell_border(const sweep *w, uint32_t col, uint32_t row, uint32_t ku, uint32_t kv,
                            uint32_t sa, uint32_t sb, sw_tt_pv *out)
{
    const tt_grid *g = &w->c->grid;
    double u0 = g->gu[col], u1 = g->gu[col + 1], v0 = g->gv[row], v1 = g->gv[row + 1];
    double pu0 = part(u0, u1, sa, ku), pu1 = part(u0, u1, sa + 1, ku);
    double pv0 = part(v0, v1, sb, kv), pv1 = part(v0, v1, sb + 1, kv);
    double fu0 = (double)sa / ku, fu1 = (double)(sa + 1) / ku;
    double fv0 = (double)sb / kv, fv1 = (double)(sb + 1) / kv;
    uint32_t n = 0;
    out[n++] = grid_pv(pu0, pv0);
    if (sb == 0 && row > 0)
        n += side_points(u0, u1, v0, 0, parts_of(w, col, row - 1, 0), fu0, fu1, 0, out + n);
    out[n++] = grid_pv(pu1, pv0);
    if (sa + 1 == ku)
        n += side_points(v0, v1, u1, 1, parts_of(w, col + 1, row, 1), fv0, fv1, 0, out + n);
    out[n++] = grid_pv(pu1, pv1);
    if (sb + 1 == kv)
        n += side_points(u0, u1, v1, 0, parts_of(w, col, row + 1, 0), fu0, fu1, 1, out + n);
    out[n++] = grid_pv(pu0, pv1);
    if (sa == 0 && col > 0)
        n += side_points(v0, v1, u0, 1, parts_of(w, col - 1, row, 1), fv0, fv1, 1, out + n);
    return n;
}

static sw_status emit_quad(tt_ctx *c, uint32_t p, uint32_t col, uint32_t row)
{
    uint32_t a, b, d, e;
    sw_status s;
    if ((s = sw_tt_grid_vertex(c, p, col, row, &a)) != SW_OK ||
        (s = sw_tt_grid_vertex(c, p, col + 1, row, &b)) != SW_OK ||
        (s = sw_tt_grid_vertex(c, p, col + 1, row + 1, &d)) != SW_OK ||
        (s = sw_tt_grid_vertex(c, p, col, row + 1, &e)) != SW_OK)
        return s;
    sw_tt_put_triangle(c, a, b, d);
    sw_tt_put_triangle(c, a, d, e);
    return SW_OK;
}

/* A cell no loop touches, inside the loops. */
static sw_status emit_inside(sweep *w, uint32_t col, uint32_t row)
{
    tt_ctx *c = w->c;
    const tt_grid *g = &c->grid;
    uint32_t p = sw_tt_knot_patch(c, g->col_k[col], g->row_k[row]);
    if (p == SW_TT_NONE)
        return SW_OK;
    c->res->leaf_count++;
    if (!w->any_split[row % 3] && !w->any_split[(row + 1) % 3] &&
        (row == 0 || !w->any_split[(row + 2) % 3]))
        return emit_quad(c, p, col, row);
    if ((row == 0 || parts_of(w, col, row - 1, 0) == 1) && parts_of(w, col, row + 1, 0) == 1 &&
        (col == 0 || parts_of(w, col - 1, row, 1) == 1) && parts_of(w, col + 1, row, 1) == 1)
        return emit_quad(c, p, col, row);
    sw_tt_pv border[4 * SW_TT_MAX_SPLIT + 4];
    size_t mark = sw_arena_mark(c->arena);
    sw_status s = emit_ring(c, p, col, row, border, cell_border(w, col, row, 1, 1, 0, 0, border));
    sw_arena_reset_to(c->arena, mark);
    return s;
}

/* The segments of pairs [a, b) meeting the closed rectangle r (all of
 * them for the whole cell: the bucketing tested them). */
static uint32_t segs_in(const sweep *w, const sw_tt_rect *r, uint32_t a, uint32_t b, int whole)
{
    uint32_t n = 0;
    for (uint32_t k = a; k < b; k++) {
        uint32_t s = w->c->pairs[k].seg;
        if (whole) {
            w->segs[n++] = s;
            continue;
        }
        const sw_tt_point *p = &w->c->pts[s], *q = &w->c->pts[p->next];
        double t0, t1;
        int s0, s1;
        if (sw_tt_clip(r, p, q, &t0, &s0, &t1, &s1))
            w->segs[n++] = s;
    }
    return n;
}

/* One clipped (sub)cell r of grid cell (col, row) with its border. */
static sw_status clip_cell(sweep *w, uint32_t p, uint32_t col, uint32_t row, const sw_tt_rect *r,
                           uint32_t nsegs, const sw_tt_pv *border, uint32_t nb)
{
    tt_ctx *c = w->c;
    sw_tt_rings rings;
    int rc = sw_tt_cell_rings(&c->trims, r, w->segs, nsegs, border, nb, c->stamp, ++c->cell_id,
                              c->arena, &rings, &c->res->skipped_loops);
    if (rc == SW_TT_CELL_NO_MEMORY)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for a cell");
    if (rc == SW_TT_CELL_BAD)
        return sw_error_set(c->err, SW_ERR_FORMAT, "trim tess: loops cross each other or "
                            "themselves near (%g, %g)", 0.5 * (r->u0 + r->u1),
                            0.5 * (r->v0 + r->v1));
    if (rc == SW_TT_CELL_EMPTY) {
        if (!classify_in_row(w, row, 0.5 * (r->u0 + r->u1), 0.5 * (r->v0 + r->v1)))
            return SW_OK;
        return emit_ring(c, p, col, row, border, nb);
    }
    for (uint32_t k = 0; k < rings.ring_count; k++) {
        uint32_t first = k ? rings.ring_end[k - 1] : 0;
        sw_status s = emit_ring(c, p, col, row, rings.verts + first, rings.ring_end[k] - first);
        if (s != SW_OK)
            return s;
    }
    return SW_OK;
}

/* A cell the loops cross: pairs [a, b). */
static sw_status emit_crossed(sweep *w, uint32_t col, uint32_t row, uint32_t a, uint32_t b)
{
    tt_ctx *c = w->c;
    const tt_grid *g = &c->grid;
    uint32_t p = sw_tt_knot_patch(c, g->col_k[col], g->row_k[row]);
    if (p == SW_TT_NONE)
        return SW_OK;
    c->res->leaf_count++, c->res->crossed_count++;
    double u0 = g->gu[col], u1 = g->gu[col + 1], v0 = g->gv[row], v1 = g->gv[row + 1];
    uint32_t ku = parts_of(w, col, row, 0), kv = parts_of(w, col, row, 1);
    sw_tt_pv border[4 * SW_TT_MAX_SPLIT + 4];
    for (uint32_t sb = 0; sb < kv; sb++) {
        for (uint32_t sa = 0; sa < ku; sa++) {
            sw_tt_rect r = {part(u0, u1, sa, ku), part(u0, u1, sa + 1, ku), part(v0, v1, sb, kv),
                            part(v0, v1, sb + 1, kv)};
            uint32_t nb = cell_border(w, col, row, ku, kv, sa, sb, border);
            size_t mark = sw_arena_mark(c->arena);
            uint32_t nsegs = segs_in(w, &r, a, b, ku * kv == 1);
            sw_status s = clip_cell(w, p, col, row, &r, nsegs, border, nb);
            sw_arena_reset_to(c->arena, mark);
            if (s != SW_OK)
                return s;
        }
    }
    return SW_OK;
}

/* Cells [a, b) of the row, none touched by a loop: inside when an odd
 * number of crossings of the middle line lies left of them. */
static sw_status emit_run(sweep *w, uint32_t row, uint32_t a, uint32_t b, uint32_t *x)
{
    if (a >= b)
        return SW_OK;
    const tt_grid *g = &w->c->grid;
    double mid = 0.5 * (g->gu[a] + g->gu[a + 1]);
    while (*x < w->nx && w->xs[*x] < mid)
        (*x)++;
    if (*x % 2 == 0)
        return SW_OK;
    for (uint32_t col = a; col < b; col++) {
        sw_status s = emit_inside(w, col, row);
        if (s != SW_OK)
            return s;
    }
    return SW_OK;
}

static sw_status sweep_row(sweep *w, uint32_t row)
{
    tt_ctx *c = w->c;
    const tt_grid *g = &c->grid;
    mark_splits(w, row + 1);
    uint32_t *next = c->line_ids[(row + 1) & 1];
    for (uint32_t i = g->c0; i <= g->c1; i++)
        next[i] = SW_TT_NONE;
    row_crossings(w, row);
    uint32_t col = g->c0, x = 0, end = c->row_first[row + 1];
    for (uint32_t a = c->row_first[row]; a < end;) {
        uint32_t b = a + 1, cc = c->pairs[a].col;
        while (b < end && c->pairs[b].col == cc)
            b++;
        sw_status s = emit_run(w, row, col, cc, &x);
        if (s == SW_OK)
            s = emit_crossed(w, cc, row, a, b);
        if (s != SW_OK)
            return s;
        col = cc + 1, a = b;
    }
    return emit_run(w, row, col, g->c1, &x);
}

sw_status sw_tt_sweep(tt_ctx *c)
{
    const tt_grid *g = &c->grid;
    sweep w;
    memset(&w, 0, sizeof w);
    w.c = c;
    uint32_t n = c->trims.point_count;
    w.seg_mark = sw_arena_alloc(c->arena, sizeof(uint32_t) * (n + 1), 4);
    w.xs = sw_arena_alloc(c->arena, sizeof(double) * (n + 1), 8);
    w.segs = sw_arena_alloc(c->arena, sizeof(uint32_t) * (n + 1), 4);
    w.group_parts = sw_arena_alloc(c->arena, c->pair_count + 1, 1);
    for (int k = 0; k < 3; k++)
        w.split[k] = sw_arena_alloc(c->arena, g->ncol + 1, 1);
    for (int k = 0; k < 2; k++)
        c->line_ids[k] = sw_arena_alloc(c->arena, sizeof(uint32_t) * (g->ncol + 2), 4);
    if (!w.seg_mark || !w.xs || !w.segs || !w.group_parts || !w.split[0] || !w.split[1] ||
        !w.split[2] || !c->line_ids[0] || !c->line_ids[1])
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "sweep (see sw_trim_tess_scratch_bytes)");
    memset(w.seg_mark, 0, sizeof(uint32_t) * (n + 1));
    sw_status s = sw_tt_eval_init(c);
    if (s == SW_OK)
        s = sw_tt_init_vertices(c, plan_parts(&w));
    if (s != SW_OK)
        return s;
    if (g->r0 > 0)
        mark_splits(&w, g->r0 - 1);
    mark_splits(&w, g->r0);
    for (uint32_t i = g->c0; i <= g->c1; i++)
        c->line_ids[g->r0 & 1][i] = SW_TT_NONE;
    for (uint32_t row = g->r0; row < g->r1; row++)
        if ((s = sweep_row(&w, row)) != SW_OK)
            return s;
    return SW_OK;
}
