/* SPDX-License-Identifier: MIT */
#include "sw_trim_cell.h"

#include <math.h>
#include <string.h>

/* ---- segment against a cell ---------------------------------------------- */

/* One side of the Liang-Barsky clip: inside where the coordinate x(t) =
 * a + t d is on the side's inner half (lower: x >= c, else x <= c). */
static int clip_side(double a, double d, double c, int lower, int side, double *t0, int *s0,
                     double *t1, int *s1)
{
    if (d == 0)
        return lower ? a >= c : a <= c;
    double t = (c - a) / d;
    int entering = (d > 0) == (lower != 0);
    if (entering) {
        if (t >= *t0)
            *t0 = t, *s0 = side;
    } else if (t <= *t1) {
        *t1 = t, *s1 = side;
    }
    return 1;
}

int sw_tt_clip(const sw_tt_rect *r, const sw_tt_point *a, const sw_tt_point *b, double *t0,
               int *side0, double *t1, int *side1)
{
    double du = b->u - a->u, dv = b->v - a->v;
    *t0 = 0, *t1 = 1, *side0 = -1, *side1 = -1;
    if (!clip_side(a->u, du, r->u0, 1, 0, t0, side0, t1, side1) ||
        !clip_side(a->u, du, r->u1, 0, 1, t0, side0, t1, side1) ||
        !clip_side(a->v, dv, r->v0, 1, 2, t0, side0, t1, side1) ||
        !clip_side(a->v, dv, r->v1, 0, 3, t0, side0, t1, side1))
        return 0;
    if (*t0 < 0)
        *t0 = 0, *side0 = -1;
    if (*t1 > 1)
        *t1 = 1, *side1 = -1;
    return *t0 <= *t1;
}

int sw_tt_classify(const sw_tt_trims *t, double u, double v)
{
    int inside = 0;
    for (uint32_t k = 0; k < t->loop_count; k++) {
        const sw_tt_loop *l = &t->loops[k];
        if (v < l->box[2] || v > l->box[3] || u > l->box[1])
            continue;
        for (uint32_t i = l->first; i < l->first + l->count; i++) {
            const sw_tt_point *a = &t->pts[i], *b = &t->pts[a->next];
            if ((a->v > v) == (b->v > v))
                continue;
            double x = a->u + (v - a->v) / (b->v - a->v) * (b->u - a->u);
            if (x > u)
                inside ^= 1;
        }
    }
    return inside;
}

/* ---- the walk around the cell -------------------------------------------- */

/* A point of the cell's border, ordered counter-clockwise from (u0, v0):
 * bottom side by u, right by v, top by -u, left by -v. */
typedef struct border_item {
    sw_tt_pv pv;
    int side;
    double key;
    int event;        /* 0 grid point, 1 entry, 2 exit */
    int entry_first;  /* at a loop point on the border: its entry sorts before its exit */
    int hint_side;    /* an event's side as the clip found it (sw_tt_clip), -1 none */
    uint32_t chain;
} border_item;

/* A loop point the clip meets at t = 0 or 1 is taken as it is (crossing),
 * and may lie a rounding off its side, strictly inside or outside the cell:
 * it goes on the side the clip found, not by its coordinates. */
static void place_on_border(const sw_tt_rect *r, border_item *it)
{
    static const int from_clip[4] = {3, 1, 0, 2};
    double u = it->pv.u, v = it->pv.v;
    int on_a_side = u == r->u0 || u == r->u1 || v == r->v0 || v == r->v1;
    int side = !on_a_side && it->hint_side >= 0 ? from_clip[it->hint_side] : -1;
    if (side == 0 || (side < 0 && v == r->v0 && u < r->u1))
        it->side = 0, it->key = u;
    else if (side == 1 || (side < 0 && u == r->u1 && v < r->v1))
        it->side = 1, it->key = v;
    else if (side == 2 || (side < 0 && v == r->v1 && u > r->u0))
        it->side = 2, it->key = -u;
    else
        it->side = 3, it->key = -v;
}

/* Order along the border; at one place crossings come before grid points
 * (which are then dropped). A loop point on the border is both an exit (of the
 * segment ending there) and an entry (of the one starting there); which comes
 * first decides whether the walk leaving there runs along the border or
 * straight into the loop again (touch_order). */
static int item_before(const border_item *a, const border_item *b)
{
    if (a->side != b->side)
        return a->side < b->side;
    if (a->key != b->key)
        return a->key < b->key;
    int ra = a->event == 0 ? 2 : (a->event == 1) == (a->entry_first != 0) ? 0 : 1;
    int rb = b->event == 0 ? 2 : (b->event == 1) == (b->entry_first != 0) ? 0 : 1;
    return ra < rb;
}

static double turn_from(double au, double av, double bu, double bv)
{
    double a = atan2(au * bv - av * bu, au * bu + av * bv);
    return a < 0 ? a + 2 * 3.14159265358979323846 : a;
}

/* For a loop point p on the border: does the border, going on counter-
 * clockwise from p, run inside the region? The region near p is the sector
 * left of the loop, from the outgoing direction counter-clockwise to the
 * reversed incoming one. If it does, the walk that leaves p follows the border
 * (entry first: the region is pinched at p into two rings); if not, it goes
 * straight back into the loop (exit first). */
static int touch_order(const sw_tt_trims *t, uint32_t p, uint32_t prev, int side)
{
    static const double dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const sw_tt_point *a = &t->pts[prev], *b = &t->pts[p], *c = &t->pts[b->next];
    double ou = c->u - b->u, ov = c->v - b->v, iu = a->u - b->u, iv = a->v - b->v;
    double e = turn_from(ou, ov, dir[side][0], dir[side][1]), back = turn_from(ou, ov, iu, iv);
    return e > 0 && e < back;
}

static void sort_items(border_item *it, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        border_item x = it[i];
        uint32_t j = i;
        for (; j > 0 && item_before(&x, &it[j - 1]); j--)
            it[j] = it[j - 1];
        it[j] = x;
    }
}

/* The crossing of segment a -> b with the border at t on side s, snapped
 * exactly onto the side's line and clamped to the cell; it takes the position
 * of the nearer end (paper 004, section 6.3). At t = 0 or 1 the loop point
 * itself lies on the border (a point on a patch edge, which no split can
 * avoid): then it is that loop point. */
static sw_tt_pv crossing(const sw_tt_rect *r, const sw_tt_trims *t, uint32_t a, double tp, int s)
{
    const sw_tt_point *pa = &t->pts[a], *pb = &t->pts[pa->next];
    if (tp == 0 || tp == 1) {
        const sw_tt_point *p = tp == 0 ? pa : pb;
        sw_tt_pv end = {p->u, p->v, SW_TT_SEAM, tp == 0 ? a : pa->next, 0, 0, 0, 0};
        return end;
    }
    sw_tt_pv pv = {pa->u + tp * (pb->u - pa->u), pa->v + tp * (pb->v - pa->v), SW_TT_CROSS,
                   tp <= 0.5 ? pa->src : pb->src, pa->src, pb->src, tp, a};
    if (s == 0 || s == 1)
        pv.u = s == 0 ? r->u0 : r->u1;
    if (s == 2 || s == 3)
        pv.v = s == 2 ? r->v0 : r->v1;
    pv.u = fmin(fmax(pv.u, r->u0), r->u1);
    pv.v = fmin(fmax(pv.v, r->v0), r->v1);
    return pv;
}

/* The point before p in its loop. */
static uint32_t prev_point(const sw_tt_trims *t, uint32_t p)
{
    const sw_tt_loop *l = &t->loops[t->pts[p].loop];
    return p == l->first ? l->first + l->count - 1 : p - 1;
}

typedef struct walk {
    const sw_tt_trims *t;
    const sw_tt_rect *r;
    border_item *items;
    uint32_t item_count;
    uint32_t *chain_entry, *chain_exit;  /* item indices (before sorting: fixed up after) */
    uint32_t *chain_first, *chain_len;   /* into seam */
    uint32_t *seam;                      /* inside points of all chains */
    uint32_t chain_count, seam_count;
} walk;

/* Entries and exits of every segment, appended to the items. */
static void find_events(walk *w, const uint32_t *segs, uint32_t seg_count)
{
    for (uint32_t k = 0; k < seg_count; k++) {
        const sw_tt_point *a = &w->t->pts[segs[k]], *b = &w->t->pts[a->next];
        int ain = sw_tt_inside(w->r, a->u, a->v), bin = sw_tt_inside(w->r, b->u, b->v);
        double t0, t1;
        int s0, s1;
        if ((ain && bin) || !sw_tt_clip(w->r, a, b, &t0, &s0, &t1, &s1))
            continue;
        if (!ain && (bin || t0 < t1)) {
            border_item *it = &w->items[w->item_count++];
            it->pv = crossing(w->r, w->t, segs[k], t0, s0);
            it->event = 1, it->chain = segs[k], it->entry_first = 0, it->hint_side = s0;
        }
        if (!bin && (ain || t0 < t1)) {
            border_item *it = &w->items[w->item_count++];
            it->pv = crossing(w->r, w->t, segs[k], t1, s1);
            it->event = 2, it->chain = segs[k], it->entry_first = 0, it->hint_side = s1;
        }
    }
}

/* Follows the loop from each entry to its exit through the inside points.
 * Before the call an event's chain field holds its segment; after it, the
 * chain number. Returns 0 when an exit is missing (inconsistent loops). */
static int link_chains(walk *w, uint32_t first_event, uint32_t *stamp, uint32_t cell_id)
{
    const sw_tt_point *pts = w->t->pts;
    for (uint32_t e = first_event; e < w->item_count; e++) {
        if (w->items[e].event != 1)
            continue;
        uint32_t c = w->chain_count++, s = w->items[e].chain, steps = 0;
        w->chain_entry[c] = e;
        w->chain_first[c] = w->seam_count;
        w->items[e].chain = c;
        /* The segment that leaves: walk inside points until one's successor
         * is outside (or the entry segment itself leaves). */
        while (sw_tt_inside(w->r, pts[pts[s].next].u, pts[pts[s].next].v)) {
            s = pts[s].next;
            if (stamp[s] == cell_id || ++steps > w->t->point_count)
                return 0;
            stamp[s] = cell_id;
            w->seam[w->seam_count++] = s;
        }
        uint32_t x = SW_TT_NONE;
        for (uint32_t k = first_event; k < w->item_count && x == SW_TT_NONE; k++)
            if (w->items[k].event == 2 && w->items[k].chain == s)
                x = k;
        if (x == SW_TT_NONE)
            return 0;
        w->items[x].chain = c;
        w->items[x].event = 3; /* linked; set back to 2 below */
        w->chain_exit[c] = x;
        w->chain_len[c] = w->seam_count - w->chain_first[c];
    }
    for (uint32_t k = first_event; k < w->item_count; k++) {
        if (w->items[k].event == 2)
            return 0; /* an exit without its entry */
        if (w->items[k].event == 3)
            w->items[k].event = 2;
    }
    return 1;
}

static void push_pv(sw_tt_rings *out, sw_tt_pv pv)
{
    if (out->vert_count > 0) {
        const sw_tt_pv *last = &out->verts[out->vert_count - 1];
        uint32_t first = out->ring_count ? out->ring_end[out->ring_count - 1] : 0;
        if (out->vert_count > first && last->u == pv.u && last->v == pv.v)
            return;
    }
    out->verts[out->vert_count++] = pv;
}

static void close_ring(sw_tt_rings *out)
{
    uint32_t first = out->ring_count ? out->ring_end[out->ring_count - 1] : 0;
    while (out->vert_count - first > 1 && out->verts[out->vert_count - 1].u == out->verts[first].u &&
           out->verts[out->vert_count - 1].v == out->verts[first].v)
        out->vert_count--;
    if (out->vert_count - first >= 3)
        out->ring_end[out->ring_count++] = out->vert_count;
    else
        out->vert_count = first;
}

static void append_chain(const walk *w, uint32_t c, sw_tt_rings *out)
{
    push_pv(out, w->items[w->chain_entry[c]].pv);
    for (uint32_t k = 0; k < w->chain_len[c]; k++) {
        const sw_tt_point *p = &w->t->pts[w->seam[w->chain_first[c] + k]];
        sw_tt_pv pv = {p->u, p->v, SW_TT_SEAM, w->seam[w->chain_first[c] + k], 0, 0, 0, 0};
        push_pv(out, pv);
    }
    push_pv(out, w->items[w->chain_exit[c]].pv);
}

/* From each unused chain: the chain, then the border counter-clockwise up
 * to the next entry, its chain, and so on until the first chain comes back. */
static int walk_rings(walk *w, uint8_t *done, sw_tt_rings *out)
{
    for (uint32_t start = 0; start < w->chain_count; start++) {
        if (done[start])
            continue;
        uint32_t c = start, guard = 0;
        for (;;) {
            done[c] = 1;
            append_chain(w, c, out);
            uint32_t j = w->chain_exit[c];
            do {
                j = (j + 1) % w->item_count;
                if (w->items[j].event == 0)
                    push_pv(out, w->items[j].pv);
            } while (w->items[j].event == 0 && ++guard <= w->item_count);
            if (w->items[j].event != 1)
                return 0;
            c = w->items[j].chain;
            if (c == start)
                break;
            if (done[c] || ++guard > 2 * w->item_count + w->chain_count)
                return 0;
        }
        close_ring(out);
    }
    return 1;
}

/* Sorts the items, drops grid points where a crossing sits and renumbers the
 * chains' entry and exit items. */
static void order_border(walk *w)
{
    sort_items(w->items, w->item_count);
    uint32_t n = 0;
    for (uint32_t i = 0; i < w->item_count; i++) {
        border_item *it = &w->items[i];
        if (it->event == 0 && n > 0 && w->items[n - 1].event != 0 &&
            w->items[n - 1].pv.u == it->pv.u && w->items[n - 1].pv.v == it->pv.v)
            continue;
        if (it->event == 0 && i + 1 < w->item_count && w->items[i + 1].event != 0 &&
            w->items[i + 1].pv.u == it->pv.u && w->items[i + 1].pv.v == it->pv.v)
            continue;
        w->items[n++] = *it;
    }
    w->item_count = n;
    for (uint32_t i = 0; i < n; i++) {
        if (w->items[i].event == 1)
            w->chain_entry[w->items[i].chain] = i;
        else if (w->items[i].event == 2)
            w->chain_exit[w->items[i].chain] = i;
    }
}

/* Loops entirely inside the cell: islands become rings, holes are counted. */
static void closed_loops(const walk *w, const uint32_t *segs, uint32_t seg_count, uint32_t *stamp,
                         uint32_t cell_id, sw_tt_rings *out, uint32_t *skipped_holes)
{
    const sw_tt_point *pts = w->t->pts;
    for (uint32_t k = 0; k < seg_count; k++) {
        uint32_t s = segs[k];
        if (stamp[s] == cell_id || !sw_tt_inside(w->r, pts[s].u, pts[s].v))
            continue;
        const sw_tt_loop *l = &w->t->loops[pts[s].loop];
        for (uint32_t i = l->first; i < l->first + l->count; i++)
            stamp[i] = cell_id;
        if (l->hole) {
            (*skipped_holes)++;
            continue;
        }
        for (uint32_t i = l->first; i < l->first + l->count; i++) {
            sw_tt_pv pv = {pts[i].u, pts[i].v, SW_TT_SEAM, i, 0, 0, 0, 0};
            push_pv(out, pv);
        }
        close_ring(out);
    }
}

int sw_tt_cell_rings(const sw_tt_trims *t, const sw_tt_rect *r, const uint32_t *segs,
                     uint32_t seg_count, const sw_tt_pv *border, uint32_t border_count,
                     uint32_t *stamp, uint32_t cell_id, sw_arena *arena, sw_tt_rings *out,
                     uint32_t *skipped_holes)
{
    /* Bounds: two events per segment; a segment's start is at most one
     * inside point; a ring vertex is a border item or an inside point. */
    uint32_t max_items = border_count + 2 * seg_count, max_chains = seg_count + 1;
    walk w = {t, r, NULL, 0, NULL, NULL, NULL, NULL, NULL, 0, 0};
    w.items = sw_arena_alloc(arena, sizeof *w.items * max_items, 8);
    w.chain_entry = sw_arena_alloc(arena, sizeof(uint32_t) * 4 * max_chains, 4);
    w.seam = sw_arena_alloc(arena, sizeof(uint32_t) * (seg_count + 1), 4);
    uint8_t *done = sw_arena_alloc(arena, max_chains, 1);
    out->verts = sw_arena_alloc(arena, sizeof *out->verts * (max_items + seg_count + 1), 8);
    out->ring_end = sw_arena_alloc(arena, sizeof(uint32_t) * (max_items + seg_count + 1), 4);
    out->ring_count = out->vert_count = 0;
    if (!w.items || !w.chain_entry || !w.seam || !done || !out->verts || !out->ring_end)
        return SW_TT_CELL_NO_MEMORY;
    w.chain_exit = w.chain_entry + max_chains;
    w.chain_first = w.chain_exit + max_chains;
    w.chain_len = w.chain_first + max_chains;
    memset(done, 0, max_chains);
    for (uint32_t i = 0; i < border_count; i++) {
        border_item *it = &w.items[w.item_count++];
        it->pv = border[i], it->event = 0, it->chain = SW_TT_NONE, it->entry_first = 0;
        it->hint_side = -1;
    }
    find_events(&w, segs, seg_count);
    if (!link_chains(&w, border_count, stamp, cell_id))
        return SW_TT_CELL_BAD;
    for (uint32_t i = 0; i < w.item_count; i++) {
        border_item *it = &w.items[i];
        place_on_border(r, it);
        if (it->event && it->pv.kind == SW_TT_SEAM)
            it->entry_first = touch_order(t, it->pv.ref, prev_point(t, it->pv.ref), it->side);
    }
    if (w.chain_count > 0) {
        order_border(&w);
        if (!walk_rings(&w, done, out))
            return SW_TT_CELL_BAD;
    }
    closed_loops(&w, segs, seg_count, stamp, cell_id, out, skipped_holes);
    return w.chain_count == 0 && out->ring_count == 0 ? SW_TT_CELL_EMPTY : SW_TT_CELL_OK;
}

/* ---- ear clipping --------------------------------------------------------- */

static double orient(const sw_tt_pv *a, const sw_tt_pv *b, const sw_tt_pv *c)
{
    return (b->u - a->u) * (c->v - a->v) - (b->v - a->v) * (c->u - a->u);
}

static int same(const sw_tt_pv *a, const sw_tt_pv *b) { return a->u == b->u && a->v == b->v; }

/* Is any other ring vertex in or on triangle (a, b, c)? Vertices at the
 * same place as a corner do not count (a ring may touch itself there). */
static int blocked(const sw_tt_pv *v, const uint32_t *prev, const uint32_t *next, uint32_t a,
                   uint32_t b, uint32_t c)
{
    for (uint32_t p = next[c]; p != a; p = next[p]) {
        const sw_tt_pv *q = &v[p];
        /* Only a reflex or flat vertex can be the first inside an ear (the
         * one farthest from its diagonal is reflex): convex ones are skipped. */
        if (orient(&v[prev[p]], q, &v[next[p]]) > 0)
            continue;
        if (same(q, &v[a]) || same(q, &v[b]) || same(q, &v[c]))
            continue;
        if (orient(&v[a], &v[b], q) >= 0 && orient(&v[b], &v[c], q) >= 0 &&
            orient(&v[c], &v[a], q) >= 0)
            return 1;
    }
    return 0;
}

/* Shape of an ear: area over the sum of squared sides (equilateral best). */
static double ear_quality(const sw_tt_pv *a, const sw_tt_pv *b, const sw_tt_pv *c)
{
    double s = (b->u - a->u) * (b->u - a->u) + (b->v - a->v) * (b->v - a->v) +
               (c->u - b->u) * (c->u - b->u) + (c->v - b->v) * (c->v - b->v) +
               (a->u - c->u) * (a->u - c->u) + (a->v - c->v) * (a->v - c->v);
    return s > 0 ? orient(a, b, c) / s : 0;
}

/* Does the ring turn strictly left at every vertex and wind once? Then it
 * is strictly convex (the common crossed cell: a rectangle cut by a seam),
 * no vertex lies in or on any ear, and it stays so as ears are cut (a flat
 * vertex could lie on an ear's diagonal: such rings take the checks).
 * Winding once: the edge direction, turning counter-clockwise only, passes
 * +u at most once. */
static int convex_ring(const sw_tt_pv *v, uint32_t n)
{
    uint32_t passes = 0;
    for (uint32_t i = 0; i < n; i++) {
        const sw_tt_pv *a = &v[(i + n - 1) % n], *b = &v[i], *c = &v[(i + 1) % n];
        if (!(orient(a, b, c) > 0))
            return 0;
        double d0 = b->v - a->v, d1 = c->v - b->v;
        passes += d0 < 0 && d1 >= 0 && c->u - b->u > 0;
    }
    return passes <= 1;
}

/* The quality of the ear at i, 0 when there is none (not convex, or
 * blocked). */
static double ear_at(const sw_tt_pv *v, const uint32_t *prev, const uint32_t *next, uint32_t i,
                     int convex)
{
    double q = ear_quality(&v[prev[i]], &v[i], &v[next[i]]);
    return q > 0 && (convex || !blocked(v, prev, next, prev[i], i, next[i])) ? q : 0;
}

/* The best cached ear from start on, or SW_TT_NONE. */
static uint32_t best_ear(const uint32_t *next, const double *quality, uint32_t start)
{
    uint32_t best = SW_TT_NONE, i = start;
    double best_q = 0;
    do {
        if (quality[i] > best_q)
            best = i, best_q = quality[i];
        i = next[i];
    } while (i != start);
    return best;
}

/* The largest convex corner, blocked or not (rings that cross themselves). */
static uint32_t any_corner(const sw_tt_pv *v, const uint32_t *prev, const uint32_t *next,
                           uint32_t start)
{
    uint32_t best = SW_TT_NONE, i = start;
    double best_q = 0;
    do {
        double q = ear_quality(&v[prev[i]], &v[i], &v[next[i]]);
        if (q > best_q)
            best = i, best_q = q;
        i = next[i];
    } while (i != start);
    return best;
}

/* Ears are scored once and rescored only at the two corners a cut changes:
 * cutting never blocks another ear (its triangle and the other vertices stay
 * or go), so a scored ear stays valid; an ear a removed vertex unblocked is
 * found by rescoring all when no scored ear is left. O(n^2) for most rings
 * instead of O(n^3). */
uint32_t sw_tt_ear_clip(const sw_tt_pv *v, uint32_t n, uint32_t *scratch, double *quality,
                        uint32_t *tri, uint32_t *fallbacks)
{
    if (n < 3)
        return 0;
    uint32_t *prev = scratch, *next = scratch + n, count = 0, start = 0;
    for (uint32_t i = 0; i < n; i++)
        prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    int convex = convex_ring(v, n);
    for (uint32_t i = 0; i < n; i++)
        quality[i] = ear_at(v, prev, next, i, convex);
    for (uint32_t left = n; left > 3; left--) {
        uint32_t e = best_ear(next, quality, start);
        if (e == SW_TT_NONE) {
            uint32_t i = start;
            do {
                quality[i] = ear_at(v, prev, next, i, convex);
                i = next[i];
            } while (i != start);
            e = best_ear(next, quality, start);
        }
        if (e == SW_TT_NONE) {
            (*fallbacks)++;
            e = any_corner(v, prev, next, start);
        }
        if (e == SW_TT_NONE) {
            /* Only flat corners left: what remains has no area. */
            return count;
        }
        tri[3 * count] = prev[e], tri[3 * count + 1] = e, tri[3 * count + 2] = next[e];
        count++;
        next[prev[e]] = next[e], prev[next[e]] = prev[e];
        start = next[e];
        quality[prev[e]] = ear_at(v, prev, next, prev[e], convex);
        quality[next[e]] = ear_at(v, prev, next, next[e], convex);
    }
    if (orient(&v[prev[start]], &v[start], &v[next[start]]) > 0) {
        tri[3 * count] = prev[start], tri[3 * count + 1] = start, tri[3 * count + 2] = next[start];
        count++;
    }
    return count;
}
