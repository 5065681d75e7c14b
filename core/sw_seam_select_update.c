/* SPDX-License-Identifier: MIT */
/* sw_seam_select_update: one frame's refinement and coarsening of the Seam
 * Graph's front (sw_seam_select.h; paper 5.5 and 6.1). */
#include <math.h>

#include "sw_seam_select.h"
#include "sw_seam_select_internal.h"

/* The work list: a binary heap of vertex indices, largest first while
 * refining (the coarsest vertices split first, and their splits free the
 * smaller ones) and smallest first while coarsening. Coarsening in rising
 * order means a collapse blocked by a finer neighbour w meets it after w's
 * own collapse (child(w) < it) was tried, so few collapses are tried twice.
 * Each vertex is in the heap at most once (queued[]): vertex_count entries
 * never overflow. */
static int before(const sw_seam_select *s, uint32_t a, uint32_t b)
{
    return s->queue_largest_first ? a > b : a < b;
}

static void push(sw_seam_select *s, uint32_t v)
{
    if (v == SW_SEAM_NONE || s->queued[v])
        return;
    s->queued[v] = 1;
    uint32_t i = s->queue_len++;
    while (i && before(s, v, s->queue[(i - 1) / 2])) {
        s->queue[i] = s->queue[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    s->queue[i] = v;
}

static uint32_t pop(sw_seam_select *s)
{
    uint32_t top = s->queue[0], v = s->queue[--s->queue_len], i = 0;
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= s->queue_len)
            break;
        if (c + 1 < s->queue_len && before(s, s->queue[c + 1], s->queue[c]))
            c++;
        if (!before(s, s->queue[c], v))
            break;
        s->queue[i] = s->queue[c];
        i = c;
    }
    if (s->queue_len)
        s->queue[i] = v;
    s->queued[top] = 0;
    return top;
}

static void drain(sw_seam_select *s)
{
    while (s->queue_len)
        pop(s);
}

static inline float smaller(float a, float b) { return b < a ? b : a; }

static int too_coarse(const sw_seam_select *s, uint32_t v)
{
    return v >= s->graph.original_count && s->graph.vertices[v].error > s->bound[v];
}

/* A collapse the coarsening tries (sw_seam_select.h, seeds). */
static void seed(sw_seam_select *s, uint32_t c)
{
    if (c == SW_SEAM_NONE || c < s->graph.original_count || s->seeded[c])
        return;
    s->seeded[c] = 1;
    s->seeds[s->seed_count++] = c;
}

/* A vertex's bound: the smallest over the surfaces of its originals' slots.
 * Those are exactly the surfaces whose loops show it while it is active
 * (a slot shows v iff its original is under v), vanished loops included, so
 * a surface that vanished far away comes back when it is approached. */
static void fold_bounds(sw_seam_select *s, const float *surface_bound)
{
    const sw_seam_graph *g = &s->graph;
    for (uint32_t o = 0; o < g->original_count; o++)
        s->bound[o] = INFINITY;
    /* loop by loop: sequential reads, and a loop's vertices are near each other */
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        float b = surface_bound[loop->surface];
        for (uint32_t i = 0; i < loop->slot_count; i++) {
            float *vb = &s->bound[g->slots[loop->first_slot + i].vertex];
            *vb = smaller(*vb, b);
        }
    }
    for (uint32_t k = 0; k < g->collapse_count; k++)
        s->bound[g->original_count + k] =
            smaller(s->bound[g->collapses[k].v1], s->bound[g->collapses[k].v2]);
}

/* Original o's bound again from the surfaces of its slots, and its
 * descendants' while theirs change: an active one that is now too coarse
 * goes into the refinement's heap, and a changed collapse whose parents
 * are both active and which meets its bound now is seeded for the
 * coarsening (one whose parents become active in the refinement is seeded
 * by its split). */
static void refold_original(sw_seam_select *s, uint32_t o, const float *surface_bound)
{
    const sw_seam_graph *g = &s->graph;
    uint32_t p = s->leaf_lo[o];
    float b = INFINITY;
    for (uint32_t e = s->leaf_slots[p]; e < s->leaf_slots[p + 1]; e++)
        b = smaller(b, surface_bound[s->slot_surface[e]]);
    if (b == s->bound[o])
        return;
    s->bound[o] = b;
    for (uint32_t c = g->vertices[o].child; c != SW_SEAM_NONE; c = g->vertices[c].child) {
        const sw_seam_collapse *k = &g->collapses[c - g->original_count];
        float nb = smaller(s->bound[k->v1], s->bound[k->v2]);
        if (nb == s->bound[c])
            return;
        s->bound[c] = nb;
        if (s->active[c] && too_coarse(s, c))
            push(s, c);
        else if (s->active[k->v1] && s->active[k->v2] && !too_coarse(s, c))
            seed(s, c);
    }
}

/* Only the surfaces whose bound changed since the last complete update:
 * their originals' bounds folded again (in a walk a few hundred surfaces a
 * frame change level, where folding every bound touched every slot and
 * every vertex of the graph). */
static void refold_changed(sw_seam_select *s, const float *surface_bound)
{
    const sw_seam_graph *g = &s->graph;
    s->queue_largest_first = 1;
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        if (surface_bound[loop->surface] == s->surface_bound[loop->surface])
            continue;
        for (uint32_t i = 0; i < loop->slot_count; i++)
            refold_original(s, g->slots[loop->first_slot + i].vertex, surface_bound);
    }
}

/* What the dependency rule reads for a collapse is who its parents'
 * active neighbours are, so a collapse it blocked can go only once one of
 * them changed: a change at x (split or collapse) is a change for the
 * collapses of x's neighbours. Those above `after` go into this pass's
 * heap (it has not reached them), the rest are the next update's seeds. */
typedef struct neighbours_of {
    sw_seam_select *s;
    uint32_t after;   /* the collapse being done (0: none, all seeded) */
} neighbours_of;

static uint32_t reconsider(void *ctx, uint32_t w)
{
    neighbours_of *n = ctx;
    uint32_t c = n->s->graph.vertices[w].child;
    if (c != SW_SEAM_NONE && n->after && c > n->after)
        push(n->s, c);
    else
        seed(n->s, c);
    return 0;
}

static void reconsider_around(sw_seam_select *s, uint32_t x, uint32_t after)
{
    neighbours_of n = { s, after };
    sw_seam_select_scan_neighbours(s, x, reconsider, &n);
}

typedef struct refining {
    sw_seam_update_result *r;
    int scan;   /* the coarsening looks at every collapse: nothing to seed */
} refining;

static void on_split(void *ctx, sw_seam_select *s, uint32_t vn, uint32_t wanted)
{
    refining *f = ctx;
    (void)wanted;
    f->r->splits++;
    if (!too_coarse(s, vn))
        f->r->forced_splits++;
    const sw_seam_collapse *c = &s->graph.collapses[vn - s->graph.original_count];
    /* its parents are active now: undoing it is a collapse to try, and
     * their neighbours' collapses see new neighbours (the scans cost a
     * third of a first update's refinement, which needs none) */
    if (!f->scan) {
        seed(s, vn);
        reconsider_around(s, c->v1, 0);
        reconsider_around(s, c->v2, 0);
    }
    if (too_coarse(s, c->v1))
        push(s, c->v1);
    if (too_coarse(s, c->v2))
        push(s, c->v2);
}

/* Splits every active vertex whose error exceeds its bound, forcing the
 * splits that block it, and its parents in turn while they still do. With
 * scan, every active vertex is looked at; without, those already in the
 * heap are all there can be (refold_changed). */
static int refine(sw_seam_select *s, int scan, uint32_t max_ops, uint32_t *used,
                  sw_seam_update_result *r)
{
    s->queue_largest_first = 1;
    refining f = { r, scan };
    for (uint32_t v = s->graph.original_count; scan && v < s->graph.vertex_count; v++)
        if (s->active[v] && too_coarse(s, v))
            push(s, v);
    while (s->queue_len) {
        uint32_t x = pop(s);
        if (!s->active[x] || !too_coarse(s, x))
            continue;
        if (max_ops && *used == max_ops)
            return 0;
        *used += sw_seam_select_force(s, x, max_ops ? max_ops - *used : 0, on_split, &f);
        if (s->active[x])
            return 0;
    }
    return 1;
}

/* Collapses wherever the new vertex meets its bound and the rule allows,
 * in rising order of the new vertex. One pass is enough: what a collapse
 * into c waits for is smaller than c (its parents; a finer neighbour w's
 * own collapse, child(w) < c), so it was settled before c came up; a
 * neighbour larger than c blocks until a split, and this phase splits
 * nothing. The new vertex's own collapse is queued after it. With scan,
 * every collapse whose parents are both active is looked at; without, the
 * seeds: those whose bound changed, those this update split, and those
 * whose parents' neighbours changed since they were last tried, which is
 * every collapse that can have become possible since (a collapse the rule
 * blocks stays blocked until one of those neighbours changes). */
static int coarsen(sw_seam_select *s, int scan, uint32_t max_ops, uint32_t *used,
                   sw_seam_update_result *r)
{
    drain(s);
    s->queue_largest_first = 0;
    const sw_seam_graph *g = &s->graph;
    for (uint32_t k = 0; scan && k < g->collapse_count; k++) {
        uint32_t c = g->original_count + k;
        if (s->active[g->collapses[k].v1] && s->active[g->collapses[k].v2] && !too_coarse(s, c))
            push(s, c);
    }
    for (uint32_t i = 0; i < s->seed_count; i++) {
        s->seeded[s->seeds[i]] = 0;
        push(s, s->seeds[i]);
    }
    s->seed_count = 0;
    while (s->queue_len) {
        uint32_t c = pop(s);
        if (s->active[c] || too_coarse(s, c))
            continue;
        const sw_seam_collapse *k = &g->collapses[c - g->original_count];
        if (!s->active[k->v1] || !s->active[k->v2])
            continue;
        if (!sw_seam_select_can_collapse(s, c))
            continue;
        if (max_ops && *used == max_ops)
            return 0;
        sw_seam_select_do_collapse(s, c);
        (*used)++;
        r->collapses++;
        push(s, s->graph.vertices[c].child);
        reconsider_around(s, c, c);
    }
    return 1;
}

void sw_seam_select_forget_bounds(sw_seam_select *s)
{
    if (s)
        s->bounds_known = 0;
}

sw_status sw_seam_select_update(sw_seam_select *s, const float *surface_bound,
                                uint32_t max_ops, sw_seam_update_result *result, sw_error *err)
{
    sw_seam_update_result r = {0};
    if (result)
        *result = r;
    if (!s || (!surface_bound && s->graph.surface_count))
        return sw_error_set(err, SW_ERR_ARG, "seam select update: no state or bounds");
    for (uint32_t i = 0; i < s->graph.surface_count; i++)
        if (!isfinite(surface_bound[i]) || surface_bound[i] < 0.0f)
            return sw_error_set(err, SW_ERR_ARG,
                                "seam select update: surface %u bound %g, expected finite >= 0",
                                i, (double)surface_bound[i]);
    int scan = !s->bounds_known;
    if (scan) {
        fold_bounds(s, surface_bound);
        for (uint32_t i = 0; i < s->seed_count; i++)
            s->seeded[s->seeds[i]] = 0;
        s->seed_count = 0;
    } else {
        refold_changed(s, surface_bound);
    }
    uint32_t used = 0;
    r.complete = refine(s, scan, max_ops, &used, &r) && coarsen(s, scan, max_ops, &used, &r);
    drain(s);
    for (uint32_t i = 0; i < s->graph.surface_count; i++)
        s->surface_bound[i] = surface_bound[i];
    /* A capped update leaves work the seeds do not hold: the next one scans. */
    s->bounds_known = r.complete;
    if (result)
        *result = r;
    return SW_OK;
}
