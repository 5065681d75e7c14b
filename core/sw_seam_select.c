/* SPDX-License-Identifier: MIT */
/* The Seam Graph's front: init, the dependency rule, split, collapse and
 * forced split (sw_seam_select.h). The per-frame update is in
 * sw_seam_select_update.c, the polylines in sw_seam_select_loop.c.
 *
 * The dependency rule. Number the vertices as the graph does (El-Sana and
 * Varshney 1999: originals first, each created vertex after everything it
 * was made from), and let a vertex x "live" over the simplification steps
 * [x, child(x)), a root living forever. The simplifier only ever saw
 * neighbours that lived at the same time, so the front keeps the invariant
 *     I: adjacent active vertices x, y have x < child(y) and y < child(x).
 * The roots satisfy I (children are infinite), and so do the originals (every
 * child is a created vertex, larger than every original). Splitting vn into
 * v1, v2 (child vn) makes every neighbour w of vn a neighbour of v1 or v2, so
 * I needs w < vn: the split is legal when every neighbour of vn is smaller
 * than vn ("all vertices adjacent to vn are assigned a number smaller than
 * that of vn", paper 5.5). Collapsing v1, v2 into vn makes every neighbour w
 * of v1 or v2 a neighbour of vn, so I needs vn < child(w) (and w < vn, which
 * I already gives: w < child(v1) = vn): the collapse is legal when every
 * neighbour w of v1 or v2 has w < vn < child(w), which is El-Sana and
 * Varshney's rule. The paper's sentence for the collapse reads "children
 * smaller than vn" and lets any original neighbour pass; taken literally it
 * would allow a collapse next to an original w whose child d is older than
 * vn, making neighbours of vertices that never coexisted (the simplifier
 * never measured that configuration), and the collapse into d then stays
 * blocked by vn > d until vn is split again. We use the rule above,
 * which is the exact condition for keeping I. The two rules are inverse: a
 * collapse that was legal can be undone by a split at once and vice versa,
 * so every front reached is reachable back and forth. */
#include "sw_seam_select.h"

#include <stdint.h>

#include "sw_seam_check.h"
#include "sw_seam_select_internal.h"

static size_t worst(size_t count, size_t size) { return sw_arena_worst_case(count * size, 8); }

/* 1 when a graph's counts fit size_t sums (a 32-bit size_t may not). */
static int countable(const sw_seam_graph *g)
{
    uint64_t largest = g->vertex_count > g->slot_count ? g->vertex_count : g->slot_count;
    return largest <= (uint64_t)(SIZE_MAX / 64);
}

size_t sw_seam_topology_arena_bytes(const sw_seam_graph *g)
{
    if (!g)
        return 0;
    if (!countable(g))
        return SIZE_MAX;
    size_t v = g->vertex_count, o = g->original_count;
    return worst(v, 4) * 2 + worst(o, 4) + worst(o + 1, 4) + worst(g->slot_count, 4) * 3;
}

size_t sw_seam_select_front_bytes(const sw_seam_graph *g)
{
    if (!g)
        return 0;
    if (!countable(g))
        return SIZE_MAX;
    size_t v = g->vertex_count;
    return worst(v, 1) * 2 + worst(v, 4) + worst((size_t)g->collapse_count + 1, 4) +
           worst(g->surface_count, 1) + worst(g->surface_count, 4);
}

size_t sw_seam_select_shown_bytes(const sw_seam_graph *g)
{
    return !g ? 0 : !countable(g) ? SIZE_MAX : worst(g->original_count, 4);
}

size_t sw_seam_select_scratch_bytes(const sw_seam_graph *g)
{
    if (!g)
        return 0;
    if (!countable(g))
        return SIZE_MAX;
    return worst(g->vertex_count, 4) + worst(g->vertex_count, 1) +
           worst((size_t)g->collapse_count + 1, 4);
}

size_t sw_seam_select_arena_bytes(const sw_seam_graph *g)
{
    size_t t = sw_seam_topology_arena_bytes(g), f = sw_seam_select_front_bytes(g);
    size_t o = sw_seam_select_shown_bytes(g), q = sw_seam_select_scratch_bytes(g);
    return t == SIZE_MAX || f == SIZE_MAX || o == SIZE_MAX || q == SIZE_MAX ? SIZE_MAX
                                                                           : t + f + o + q;
}

static void *take(sw_arena *arena, size_t count, size_t size, int *failed)
{
    void *p = sw_arena_alloc(arena, count * size, 8);
    if (!p)
        *failed = 1;
    return p;
}

sw_status sw_seam_select_scratch_init(sw_seam_select_scratch *q, uint32_t vertex_count,
                                      uint32_t collapse_count, sw_arena *arena, sw_error *err)
{
    int failed = 0;
    *q = (sw_seam_select_scratch){ .vertex_count = vertex_count,
                                   .collapse_count = collapse_count };
    q->queue = take(arena, vertex_count, 4, &failed);
    q->queued = take(arena, vertex_count, 1, &failed);
    q->stack = take(arena, (size_t)collapse_count + 1, 4, &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam select: arena too small for the "
                            "scratch of %u vertices", (unsigned)vertex_count);
    for (uint32_t v = 0; v < vertex_count; v++)
        q->queued[v] = 0;
    return SW_OK;
}

static sw_status take_front(sw_seam_select *s, uint32_t *shown,
                            const sw_seam_select_scratch *scratch, sw_arena *arena,
                            sw_error *err)
{
    const sw_seam_graph *g = &s->graph;
    size_t v = g->vertex_count, o = g->original_count;
    sw_seam_select_scratch own;
    if (!scratch) {
        sw_status st = sw_seam_select_scratch_init(&own, g->vertex_count, g->collapse_count,
                                                   arena, err);
        if (st != SW_OK)
            return st;
        scratch = &own;
    } else if (scratch->vertex_count < g->vertex_count ||
               scratch->collapse_count < g->collapse_count) {
        return sw_error_set(err, SW_ERR_ARG, "seam select: scratch for %u vertices, the graph "
                            "has %u", (unsigned)scratch->vertex_count,
                            (unsigned)g->vertex_count);
    }
    s->queue = scratch->queue, s->queued = scratch->queued, s->stack = scratch->stack;
    int failed = 0;
    s->active = take(arena, v, 1, &failed);
    s->bound = take(arena, v, 4, &failed);
    s->shown = shown ? shown : take(arena, o, 4, &failed);
    s->surface_changed = take(arena, g->surface_count, 1, &failed);
    s->surface_bound = take(arena, g->surface_count, 4, &failed);
    s->seeds = take(arena, (size_t)g->collapse_count + 1, 4, &failed);
    s->seeded = take(arena, v, 1, &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "seam select: arena too small (%zu bytes free, %zu needed)",
                            arena->size - arena->used, sw_seam_select_arena_bytes(g));
    return SW_OK;
}

/* Leaf ranges: every vertex's originals contiguous in leaf_order, v2's side
 * before v1's, so the smallest position in a run is the slot whose (u, v)
 * the polyline uses (sw_seam_select_loop.c). Children are larger than their
 * parents, so a descending pass places every vertex before its parents. */
static void build_leaf_ranges(sw_seam_topology *t)
{
    const sw_seam_graph *g = &t->graph;
    for (uint32_t v = 0; v < g->vertex_count; v++)
        t->leaf_count[v] = v < g->original_count ? 1 : 0;
    for (uint32_t k = 0; k < g->collapse_count; k++)
        t->leaf_count[g->original_count + k] =
            t->leaf_count[g->collapses[k].v1] + t->leaf_count[g->collapses[k].v2];
    uint32_t next = 0;
    for (uint32_t v = 0; v < g->vertex_count; v++)
        if (g->vertices[v].child == SW_SEAM_NONE) {
            t->leaf_lo[v] = next;
            next += t->leaf_count[v];
        }
    for (uint32_t k = g->collapse_count; k-- > 0;) {
        const sw_seam_collapse *c = &g->collapses[k];
        uint32_t vn = g->original_count + k;
        t->leaf_lo[c->v2] = t->leaf_lo[vn];
        t->leaf_lo[c->v1] = t->leaf_lo[vn] + t->leaf_count[c->v2];
    }
    for (uint32_t o = 0; o < g->original_count; o++)
        t->leaf_order[t->leaf_lo[o]] = o;
}

/* The slots in leaf order (leaf_slots, slot_surface, slot_prev, slot_next),
 * filled loop by loop: each original's entries in the order of its slots.
 * next_entry (original_count) holds each original's next entry. */
static void build_leaf_slots(sw_seam_topology *t, uint32_t *next_entry)
{
    const sw_seam_graph *g = &t->graph;
    t->leaf_slots[0] = 0;
    for (uint32_t p = 0; p < g->original_count; p++)
        t->leaf_slots[p + 1] = t->leaf_slots[p] + g->vertices[t->leaf_order[p]].slot_ref_count;
    for (uint32_t o = 0; o < g->original_count; o++)
        next_entry[o] = t->leaf_slots[t->leaf_lo[o]];
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        const sw_seam_slot *slots = g->slots + loop->first_slot;
        uint32_t n = loop->slot_count;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t e = next_entry[slots[i].vertex]++;
            t->slot_surface[e] = loop->surface;
            t->slot_prev[e] = t->leaf_lo[slots[i ? i - 1 : n - 1].vertex];
            t->slot_next[e] = t->leaf_lo[slots[i + 1 < n ? i + 1 : 0].vertex];
        }
    }
}

sw_status sw_seam_topology_init(sw_seam_topology *t, const sw_seam_graph *graph,
                                sw_arena *arena, sw_error *err)
{
    if (!t || !graph || !arena)
        return sw_error_set(err, SW_ERR_ARG, "seam topology: no topology, graph or arena");
    if (!countable(graph))
        return sw_error_set(err, SW_ERR_RANGE, "seam select: %u vertices, %u slots: too many",
                            graph->vertex_count, graph->slot_count);
    *t = (sw_seam_topology){.graph = *graph};
    size_t v = graph->vertex_count, o = graph->original_count;
    int failed = 0;
    t->leaf_lo = take(arena, v, 4, &failed);
    t->leaf_count = take(arena, v, 4, &failed);
    t->leaf_order = take(arena, o, 4, &failed);
    t->leaf_slots = take(arena, o + 1, 4, &failed);
    t->slot_surface = take(arena, graph->slot_count, 4, &failed);
    t->slot_prev = take(arena, graph->slot_count, 4, &failed);
    t->slot_next = take(arena, graph->slot_count, 4, &failed);
    size_t mark = sw_arena_mark(arena);
    uint32_t *next_entry = take(arena, o, 4, &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "seam select: arena too small (%zu bytes free, %zu needed)",
                            arena->size - arena->used, sw_seam_topology_arena_bytes(graph));
    build_leaf_ranges(t);
    build_leaf_slots(t, next_entry);
    sw_arena_reset_to(arena, mark);
    return SW_OK;
}

/* Marks the surfaces of the slots under v as changed and shows x in them. */
static void show(sw_seam_select *s, uint32_t v, uint32_t x)
{
    uint32_t lo = s->leaf_lo[v], hi = lo + s->leaf_count[v];
    for (uint32_t p = lo; p < hi; p++)
        s->shown[p] = x;
    for (uint32_t e = s->leaf_slots[lo]; e < s->leaf_slots[hi]; e++)
        s->surface_changed[s->slot_surface[e]] = 1;
}

sw_status sw_seam_select_init(sw_seam_select *s, const sw_seam_graph *graph, sw_arena *arena,
                              sw_error *err)
{
    if (!s || !arena)
        return sw_error_set(err, SW_ERR_ARG, "seam select: no state or arena");
    sw_status st = sw_seam_graph_check(graph, err);
    return st != SW_OK ? st : sw_seam_select_init_checked(s, graph, arena, err);
}

sw_status sw_seam_select_init_shared(sw_seam_select *s, const sw_seam_topology *t,
                                     uint32_t *shown, const sw_seam_select_scratch *scratch,
                                     sw_arena *arena, sw_error *err)
{
    if (!s || !t || !arena)
        return sw_error_set(err, SW_ERR_ARG, "seam select: no state, topology or arena");
    *s = (sw_seam_select){.graph = t->graph, .leaf_lo = t->leaf_lo,
                          .leaf_count = t->leaf_count, .leaf_order = t->leaf_order,
                          .leaf_slots = t->leaf_slots, .slot_surface = t->slot_surface,
                          .slot_prev = t->slot_prev, .slot_next = t->slot_next};
    sw_status st = take_front(s, shown, scratch, arena, err);
    if (st != SW_OK)
        return st;
    const sw_seam_graph *g = &s->graph;
    for (uint32_t v = 0; v < g->vertex_count; v++) {
        s->seeded[v] = 0;
        s->active[v] = g->vertices[v].child == SW_SEAM_NONE;
        if (s->active[v]) {
            s->active_count++;
            show(s, v, v);
        }
    }
    sw_seam_select_clear_changed(s);
    return SW_OK;
}

sw_status sw_seam_select_init_checked(sw_seam_select *s, const sw_seam_graph *graph,
                                      sw_arena *arena, sw_error *err)
{
    if (!s || !arena)
        return sw_error_set(err, SW_ERR_ARG, "seam select: no state or arena");
    if (sw_seam_select_arena_bytes(graph) == SIZE_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "seam select: %u vertices, %u slots: too many",
                            graph->vertex_count, graph->slot_count);
    /* The topology lives in the same arena, before the front, and only
     * this state points at it. */
    sw_seam_topology t;
    sw_status st = sw_seam_topology_init(&t, graph, arena, err);
    return st != SW_OK ? st : sw_seam_select_init_shared(s, &t, NULL, NULL, arena, err);
}

/* Every run of x in a polyline is bounded by slots next to slots of x's
 * originals, so looking one slot each way from each of them finds all
 * neighbours in O(slots under x). A neighbour slot whose original is a
 * leaf of x (its leaf position in x's range) shows x itself: skipped
 * without a lookup. */
uint32_t sw_seam_select_scan_neighbours(const sw_seam_select *s, uint32_t x,
                                        uint32_t (*visit)(void *ctx, uint32_t w), void *ctx)
{
    uint32_t lo = s->leaf_lo[x], n = s->leaf_count[x];
    for (uint32_t e = s->leaf_slots[lo]; e < s->leaf_slots[lo + n]; e++) {
        uint32_t q[2] = {s->slot_prev[e], s->slot_next[e]};
        for (int k = 0; k < 2; k++) {
            if (q[k] - lo < n)   /* unsigned: lo <= q < lo + n */
                continue;
            uint32_t stop = visit(ctx, s->shown[q[k]]);
            if (stop)
                return stop;
        }
    }
    return 0;
}

typedef struct limits {
    const sw_seam_select *s;
    uint32_t vn, v1, v2;
} limits;

/* Split test: a neighbour >= vn blocks; returns it (+1, so 0 means none). */
static uint32_t blocks_split(void *ctx, uint32_t w)
{
    const limits *lim = ctx;
    return w > lim->vn ? w + 1 : 0;
}

/* Collapse test: a neighbour w of v1 or v2 blocks unless w < vn < child(w). */
static uint32_t blocks_collapse(void *ctx, uint32_t w)
{
    const limits *lim = ctx;
    if (w == lim->v1 || w == lim->v2)
        return 0;
    uint32_t child = lim->s->graph.vertices[w].child;
    return (w < lim->vn && (child == SW_SEAM_NONE || child > lim->vn)) ? 0 : w + 1;
}

static int is_created(const sw_seam_select *s, uint32_t v)
{
    return v >= s->graph.original_count && v < s->graph.vertex_count;
}

/* The first neighbour of active vn larger than vn, or SW_SEAM_NONE. */
static uint32_t split_blocker(const sw_seam_select *s, uint32_t vn)
{
    limits lim = {s, vn, SW_SEAM_NONE, SW_SEAM_NONE};
    uint32_t w = sw_seam_select_scan_neighbours(s, vn, blocks_split, &lim);
    return w ? w - 1 : SW_SEAM_NONE;
}

int sw_seam_select_can_split(const sw_seam_select *s, uint32_t vn)
{
    if (!s || !is_created(s, vn) || !s->active[vn])
        return 0;
    return split_blocker(s, vn) == SW_SEAM_NONE;
}

int sw_seam_select_can_collapse(const sw_seam_select *s, uint32_t vn)
{
    if (!s || !is_created(s, vn))
        return 0;
    const sw_seam_collapse *c = &s->graph.collapses[vn - s->graph.original_count];
    if (!s->active[c->v1] || !s->active[c->v2])
        return 0;
    limits lim = {s, vn, c->v1, c->v2};
    return !sw_seam_select_scan_neighbours(s, c->v1, blocks_collapse, &lim) &&
           !sw_seam_select_scan_neighbours(s, c->v2, blocks_collapse, &lim);
}

/* The steps themselves, for callers that checked the rule. */
static void do_split(sw_seam_select *s, uint32_t vn)
{
    const sw_seam_collapse *c = &s->graph.collapses[vn - s->graph.original_count];
    s->active[vn] = 0;
    s->active[c->v1] = s->active[c->v2] = 1;
    s->active_count++;
    show(s, c->v1, c->v1);
    show(s, c->v2, c->v2);
}

void sw_seam_select_do_collapse(sw_seam_select *s, uint32_t vn)
{
    const sw_seam_collapse *c = &s->graph.collapses[vn - s->graph.original_count];
    s->active[vn] = 1;
    s->active[c->v1] = s->active[c->v2] = 0;
    s->active_count--;
    show(s, vn, vn);
}

sw_status sw_seam_select_split(sw_seam_select *s, uint32_t vn, sw_error *err)
{
    if (!sw_seam_select_can_split(s, vn))
        return sw_error_set(err, SW_ERR_ARG, "seam select: split of vertex %u not allowed", vn);
    s->bounds_known = 0;   /* the next update cannot go from the last one's */
    do_split(s, vn);
    return SW_OK;
}

sw_status sw_seam_select_collapse(sw_seam_select *s, uint32_t vn, sw_error *err)
{
    if (!sw_seam_select_can_collapse(s, vn))
        return sw_error_set(err, SW_ERR_ARG, "seam select: collapse into vertex %u not allowed",
                            vn);
    s->bounds_known = 0;
    sw_seam_select_do_collapse(s, vn);
    return SW_OK;
}

/* A blocker is larger than the vertex it blocks, so the stack rises
 * strictly and never holds more than the created vertices. */
uint32_t sw_seam_select_force(sw_seam_select *s, uint32_t v, uint32_t max_ops,
                              sw_seam_on_split on_split, void *ctx)
{
    uint32_t depth = 0, splits = 0;
    s->stack[depth++] = v;
    while (depth) {
        uint32_t t = s->stack[depth - 1];
        if (!s->active[t]) {
            depth--;
            continue;
        }
        uint32_t w = split_blocker(s, t);
        if (w != SW_SEAM_NONE) {
            s->stack[depth++] = w;
            continue;
        }
        if (max_ops && splits == max_ops)
            break;
        do_split(s, t);
        splits++;
        if (on_split)
            on_split(ctx, s, t, v);
        depth--;
    }
    return splits;
}

sw_status sw_seam_select_force_split(sw_seam_select *s, uint32_t v, uint32_t max_ops,
                                     uint32_t *splits, sw_error *err)
{
    if (splits)
        *splits = 0;
    if (!s || !is_created(s, v) || !s->active[v])
        return sw_error_set(err, SW_ERR_ARG,
                            "seam select: vertex %u is not an active created vertex", v);
    s->bounds_known = 0;
    uint32_t n = sw_seam_select_force(s, v, max_ops, NULL, NULL);
    if (splits)
        *splits = n;
    return SW_OK;
}

uint32_t sw_seam_select_surfaces_at(const sw_seam_select *s, uint32_t o,
                                    const uint32_t **surfaces)
{
    if (o >= s->graph.original_count) {
        *surfaces = NULL;
        return 0;
    }
    uint32_t p = s->leaf_lo[o];
    *surfaces = s->slot_surface + s->leaf_slots[p];
    return s->leaf_slots[p + 1] - s->leaf_slots[p];
}

int sw_seam_select_is_active(const sw_seam_select *s, uint32_t v)
{
    return s && v < s->graph.vertex_count && s->active[v];
}

int sw_seam_select_surface_changed(const sw_seam_select *s, uint32_t surface)
{
    return s && surface < s->graph.surface_count && s->surface_changed[surface];
}

void sw_seam_select_clear_changed(sw_seam_select *s)
{
    for (uint32_t i = 0; i < s->graph.surface_count; i++)
        s->surface_changed[i] = 0;
}
