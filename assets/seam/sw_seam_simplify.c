/* SPDX-License-Identifier: MIT */
/* sw_seam_simplify: the edge-collapse hierarchy of a sewn Seam Graph
 * (sw_seam_simplify.h; Guthe et al. 2002, 5.2-5.5).
 *
 * The stored error d. The paper keeps, per vertex, "the maximum distance
 * that was computed for any edge adjacent to it" (5.3). We keep it as a
 * bound with a proof: every point of the original polylines is attached to
 * an edge of the current graph, and d(x) bounds the distance of the points
 * attached to the edges at x. Collapsing v1 -> v2 moves the edge (v1, w) to
 * (v2, w); distance to a segment is convex, so every point of (v1, w) lies
 * within dist(v1, (v2, w)) <= epsilon of (v2, w), and the points of (v1, v2)
 * within epsilon of any (v2, w) (or of v2 itself, epsilon = |v1 v2|, when v1
 * has no other neighbour). So the points attached at v1 end up within
 * d(v1) + epsilon, and that raises d of the new vertex and of v1's other
 * neighbours (their edge to v1 moved). The same induction shows that the
 * points attached to an edge (a, b) stay within max(error(a), error(b)) of
 * it, with error the monotone vertex error stored in the graph: that is why
 * the runtime can bound a segment by its two endpoints.
 *
 * Where the paper removes and reinserts the costs of every edge in the
 * neighbourhood, the heap here holds one entry per vertex (its cheapest
 * outgoing collapse, which the paper notes is the only one that matters)
 * and updates it in place: no stale entries, and the heap stays at most the
 * vertex count.
 *
 * Costs are made exact lazily. The parameter-space term samples the
 * surface (sw_seam_runs.h), and a vertex's cost was remade after every
 * collapse next to it: 85% of a 3,000-patch showroom's simplification.
 * A collapse now gives its neighbours a lower bound (the term without the
 * surface's samples) and marks them; the heap's top is made exact when it
 * is marked, and collapsed only once its exact cost still tops the heap.
 * The heap orders by (cost, vertex), and a marked vertex's key is at most
 * its exact cost, so the vertex collapsed is the one of least exact cost
 * at that moment, with its target and epsilon. The hierarchy is not byte
 * for byte the eager one's (the teaset's pack differs in 2,510 bytes): the
 * eager heap kept a cost from the last collapse next to the vertex, stale
 * once a loop elsewhere fell under four runs, and only ever too high. */
#include "sw_seam_simplify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_math.h"
#include "sw_seam_check.h"
#include "sw_seam_runs.h"

typedef struct nbrs {
    uint32_t *v;
    uint32_t n, cap;
} nbrs;

typedef struct simp {
    sw_seam_host *g;
    nbrs *adj;        /* neighbours of each live vertex */
    sw_seam_runs runs; /* the loops' current polylines, for the parameter term */
    double *stored;   /* d (above) */
    double *cost;     /* cheapest collapse out of the vertex: epsilon + d */
    double *eps;      /* its epsilon */
    uint32_t *target; /* its kept vertex */
    uint32_t *heap, *pos, heap_n;
    uint32_t *mark, stamp;
    uint8_t *bounded; /* cost is a lower bound, target unset: made exact at the top */
    uint32_t *barred, barred_stamp; /* targets that would fold a loop (exact updates) */
    const uint8_t *pinned; /* original vertices that never collapse (may be NULL) */
} simp;

static int is_pinned(const simp *S, uint32_t v)
{
    return S->pinned && v < S->g->original_count && S->pinned[v];
}

static sw_vec3 v3f(const float p[3])
{
    return sw_v3(p[0], p[1], p[2]);
}

static double seg_dist(const float p[3], const float a[3], const float b[3])
{
    return sw_v3_segment_distance(v3f(p), v3f(a), v3f(b));
}

/* ---- the heap of vertices by their cheapest collapse ---- */

static int heap_less(const simp *S, uint32_t a, uint32_t b)
{
    return S->cost[a] < S->cost[b] || (S->cost[a] == S->cost[b] && a < b);
}

static void heap_place(simp *S, uint32_t i, uint32_t v)
{
    S->heap[i] = v;
    S->pos[v] = i;
}

static void heap_up(simp *S, uint32_t i)
{
    uint32_t v = S->heap[i];
    while (i && heap_less(S, v, S->heap[(i - 1) / 2])) {
        heap_place(S, i, S->heap[(i - 1) / 2]);
        i = (i - 1) / 2;
    }
    heap_place(S, i, v);
}

static void heap_down(simp *S, uint32_t i)
{
    uint32_t v = S->heap[i];
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= S->heap_n)
            break;
        if (c + 1 < S->heap_n && heap_less(S, S->heap[c + 1], S->heap[c]))
            c++;
        if (!heap_less(S, S->heap[c], v))
            break;
        heap_place(S, i, S->heap[c]);
        i = c;
    }
    heap_place(S, i, v);
}

static void heap_remove(simp *S, uint32_t v)
{
    uint32_t i = S->pos[v];
    if (i == UINT32_MAX)
        return;
    S->pos[v] = UINT32_MAX;
    uint32_t last = S->heap[--S->heap_n];
    if (last == v)
        return;
    heap_place(S, i, last);
    heap_up(S, i);
    heap_down(S, S->pos[last]);
}

/* Recomputes v's cheapest collapse (5.3) and its place in the heap; with
 * exact 0, a lower bound of it (marked bounded: made exact at the top).
 * A pinned vertex neither collapses nor takes another's collapse.
 *
 * Beyond the paper, whose epsilon is model space only, epsilon is at least
 * the collapse's parameter-space cost (sw_seam_runs.h): a collapse free in
 * space (v on a straight line) can still bend the border in (u, v), or move
 * a point of a loop where y is not next to v by |v y|, and the tessellation
 * would follow (OCCT hammer: 7.4 px of a 0.5 px bound, the screw 2.8). */
static void choose_best(simp *S, uint32_t v)
{
    const nbrs *a = &S->adj[v];
    const sw_seam_vertex *vx = S->g->vertices;
    S->cost[v] = INFINITY;
    S->target[v] = UINT32_MAX;
    for (uint32_t i = 0; i < a->n; i++) {
        uint32_t y = a->v[i];
        if (is_pinned(S, v) || is_pinned(S, y) || S->barred[y] == S->barred_stamp)
            continue;
        double runs = sw_seam_runs_cost_to(&S->runs, S->g, v, y);
        double reach = seg_dist(vx[v].p, vx[y].p, vx[y].p);
        double e = fmax(a->n == 1 ? reach : 0.0, runs);
        /* No segment from y is farther from v than y itself, so e at reach
         * is final; and once past the best so far y cannot win (a tie still
         * can, by its index). A hub of many neighbours, whose runs elsewhere
         * already cost reach, is spared its pairs. */
        for (uint32_t j = 0; j < a->n && e < reach && e + S->stored[v] <= S->cost[v]; j++)
            if (j != i)
                e = fmax(e, seg_dist(vx[v].p, vx[y].p, vx[a->v[j]].p));
        double c = e + S->stored[v];
        if (c < S->cost[v] || (c == S->cost[v] && y < S->target[v])) {
            S->cost[v] = c;
            S->eps[v] = e;
            S->target[v] = y;
        }
    }
}

/* Targets an exact update tries before v waits for a neighbour's collapse:
 * a hub of thousands of neighbours that all fold a loop would otherwise
 * pay for every one at every update. */
enum { FOLD_TRIES = 4 };

/* Would collapsing v into y fold a loop in (u, v): pinch it (meet itself
 * at one vertex) or make it cross a loop of its surface? */
static int folds(simp *S, uint32_t v, uint32_t y)
{
    return sw_seam_runs_pinch(&S->runs, v, y) || sw_seam_runs_crosses(&S->runs, S->g, v, y);
}

/* v's cheapest collapse into S->target[v]; exact, a target that would fold
 * a loop (folds) is passed over for the next. Only the exact update at the
 * heap's top pays for that check: the lower bounds only order the heap. A
 * pinch changes only when v or its target collapses, which updates v again;
 * a crossing also when a point in the way collapses, which v does not hear
 * of: it then keeps waiting for a collapse of its own neighbours (a
 * collapse lost, never a crossing made). */
static void update_best(simp *S, uint32_t v, int exact)
{
    S->bounded[v] = !exact;
    if (!is_pinned(S, v))
        sw_seam_runs_gather(&S->runs, S->g, v, exact);
    if (++S->barred_stamp == 0) {
        memset(S->barred, 0, (size_t)S->g->original_count * 2 * sizeof *S->barred);
        S->barred_stamp = 1;
    }
    choose_best(S, v);
    for (int tries = 0; exact && S->target[v] != UINT32_MAX &&
                        folds(S, v, S->target[v]); tries++) {
        S->barred[S->target[v]] = S->barred_stamp;
        if (tries + 1 == FOLD_TRIES) {
            S->target[v] = UINT32_MAX;   /* back in the heap when a neighbour collapses */
            break;
        }
        choose_best(S, v);
    }
    if (S->target[v] == UINT32_MAX) {
        heap_remove(S, v);
    } else if (S->pos[v] == UINT32_MAX) {
        heap_place(S, S->heap_n++, v);
        heap_up(S, S->heap_n - 1);
    } else {
        heap_up(S, S->pos[v]);
        heap_down(S, S->pos[v]);
    }
}

/* ---- adjacency from the loops, checked against graph->edges ---- */

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* The sorted distinct pairs (a < b, packed a << 32 | b) consecutive in some
 * loop; *count gets how many. NULL when malloc fails. */
static uint64_t *loop_pairs(const sw_seam_host *g, uint32_t *count)
{
    uint64_t *pairs = malloc(((size_t)g->slot_count + 1) * sizeof *pairs);
    if (!pairs)
        return NULL;
    uint32_t n = 0;
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        for (uint32_t i = 0; i < loop->slot_count; i++) {
            uint32_t a = g->slots[loop->first_slot + i].vertex;
            uint32_t b = g->slots[loop->first_slot + (i + 1) % loop->slot_count].vertex;
            if (a != b)
                pairs[n++] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
        }
    }
    qsort(pairs, n, sizeof *pairs, cmp_u64);
    uint32_t u = 0;
    for (uint32_t i = 0; i < n; i++)
        if (!u || pairs[i] != pairs[u - 1])
            pairs[u++] = pairs[i];
    *count = u;
    return pairs;
}

static sw_status check_edges(const sw_seam_host *g, const uint64_t *pairs, uint32_t count,
                             sw_error *err)
{
    uint64_t *edges = malloc(((size_t)g->edge_count + 1) * sizeof *edges);
    if (!edges)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    for (uint32_t e = 0; e < g->edge_count; e++)
        edges[e] = (uint64_t)g->edges[e].a << 32 | g->edges[e].b;
    qsort(edges, g->edge_count, sizeof *edges, cmp_u64);
    sw_status st = SW_OK;
    for (uint32_t i = 0; i < g->edge_count || i < count; i++) {
        uint64_t want = i < count ? pairs[i] : UINT64_MAX;
        uint64_t have = i < g->edge_count ? edges[i] : UINT64_MAX;
        if (want == have)
            continue;
        uint64_t bad = want < have ? want : have;
        st = sw_error_set(err, SW_ERR_FORMAT,
                          "seam simplify: vertices %u and %u are %s", (uint32_t)(bad >> 32),
                          (uint32_t)bad,
                          want < have ? "consecutive in a loop but not in edges"
                          : i > 0 && have == edges[i - 1] ? "listed twice in edges"
                                                          : "in edges but in no loop together");
        break;
    }
    free(edges);
    return st;
}

static int push_nbr(nbrs *a, uint32_t v)
{
    if (a->n == a->cap) {
        uint32_t cap = a->cap ? a->cap * 2 : 4;
        uint32_t *grown = realloc(a->v, cap * sizeof *grown);
        if (!grown)
            return -1;
        a->v = grown;
        a->cap = cap;
    }
    a->v[a->n++] = v;
    return 0;
}

static sw_status build_adjacency(simp *S, sw_error *err)
{
    uint32_t count = 0;
    uint64_t *pairs = loop_pairs(S->g, &count);
    if (!pairs)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    sw_status st = check_edges(S->g, pairs, count, err);
    for (uint32_t i = 0; st == SW_OK && i < count; i++) {
        uint32_t a = (uint32_t)(pairs[i] >> 32), b = (uint32_t)pairs[i];
        if (push_nbr(&S->adj[a], b) || push_nbr(&S->adj[b], a))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    }
    free(pairs);
    return st;
}

/* ---- one step (5.4) ---- */

static void remove_nbr(nbrs *a, uint32_t v)
{
    for (uint32_t i = 0; i < a->n; i++)
        if (a->v[i] == v) {
            a->v[i] = a->v[--a->n];
            return;
        }
}

/* Collapses v1 into S->target[v1]. Returns -1 when malloc fails. */
static int collapse(simp *S, uint32_t v1)
{
    sw_seam_host *g = S->g;
    uint32_t v2 = S->target[v1], vn = g->vertex_count;
    double eps = S->eps[v1], step = eps + S->stored[v1];
    sw_seam_vertex *vx = g->vertices;
    float e = fmaxf((float)step, fmaxf(vx[v1].error, vx[v2].error));
    vx[vn] = (sw_seam_vertex){{vx[v2].p[0], vx[v2].p[1], vx[v2].p[2]}, SW_SEAM_NONE, e, 0, 0, 0};
    vx[v1].child = vx[v2].child = vn;
    g->collapses[g->collapse_count++] = (sw_seam_collapse){v1, v2, (float)step};
    g->vertex_count++;
    S->stored[vn] = fmax(S->stored[v2], S->stored[v1] + eps);
    S->pos[vn] = UINT32_MAX;
    heap_remove(S, v1);
    heap_remove(S, v2);

    uint32_t stamp = ++S->stamp;
    S->mark[v1] = S->mark[v2] = stamp;
    nbrs merged = {0};
    for (int side = 0; side < 2; side++) {
        nbrs *a = &S->adj[side ? v2 : v1];
        for (uint32_t i = 0; i < a->n; i++) {
            uint32_t w = a->v[i];
            if (!side && w != v2)
                S->stored[w] = fmax(S->stored[w], S->stored[v1] + eps);
            if (S->mark[w] == stamp)
                continue;
            S->mark[w] = stamp;
            if (push_nbr(&merged, w))
                return -1;
        }
    }
    free(S->adj[v1].v);
    free(S->adj[v2].v);
    S->adj[v1] = S->adj[v2] = (nbrs){0};
    S->adj[vn] = merged;
    sw_seam_runs_collapse(&S->runs, v1, v2, vn);
    for (uint32_t i = 0; i < merged.n; i++) {
        nbrs *a = &S->adj[merged.v[i]];
        remove_nbr(a, v1);
        remove_nbr(a, v2);
        if (push_nbr(a, vn))
            return -1;
    }
    update_best(S, vn, 0);
    for (uint32_t i = 0; i < merged.n; i++)
        update_best(S, merged.v[i], 0);
    return 0;
}

/* ---- driver ---- */

static sw_status check_original(const sw_seam_host *g, sw_error *err)
{
    sw_seam_graph view = sw_seam_host_view(g);
    sw_status st = sw_seam_graph_check(&view, err);
    if (st != SW_OK) {
        sw_error_prefix(err, "seam simplify");
        return st;
    }
    if (g->collapse_count)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "seam simplify: graph already has %u collapses, expected 0",
                            g->collapse_count);
    if (g->original_count > UINT32_MAX / 2)
        return sw_error_set(err, SW_ERR_RANGE, "seam simplify: %u vertices, too many",
                            g->original_count);
    return SW_OK;
}

static void free_simp(simp *S, uint32_t vertices)
{
    if (S->adj)
        for (uint32_t v = 0; v < vertices; v++)
            free(S->adj[v].v);
    free(S->adj);
    sw_seam_runs_free(&S->runs);
    free(S->stored);
    free(S->cost);
    free(S->eps);
    free(S->target);
    free(S->heap);
    free(S->pos);
    free(S->mark);
    free(S->bounded);
    free(S->barred);
}

static sw_status grow_host(sw_seam_host *g, size_t cap, sw_error *err)
{
    sw_seam_vertex *v = realloc(g->vertices, cap * sizeof *v);
    if (!v)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    g->vertices = v;
    sw_seam_collapse *c = malloc(cap * sizeof *c);
    if (!c)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    free(g->collapses);
    g->collapses = c;
    return SW_OK;
}

static void restore(sw_seam_host *g, uint32_t original)
{
    for (uint32_t v = 0; v < original; v++)
        g->vertices[v].child = SW_SEAM_NONE;
    g->vertex_count = original;
    g->collapse_count = 0;
}

sw_status sw_seam_simplify(sw_seam_host *g, sw_error *err)
{
    return sw_seam_simplify_on(g, NULL, err);
}

sw_status sw_seam_simplify_on(sw_seam_host *g, const sw_seam_surface_eval *eval, sw_error *err)
{
    return sw_seam_simplify_pinned(g, eval, NULL, err);
}

sw_status sw_seam_simplify_pinned(sw_seam_host *g, const sw_seam_surface_eval *eval,
                                  const uint8_t *pinned, sw_error *err)
{
    if (!g)
        return sw_error_set(err, SW_ERR_ARG, "seam simplify: no graph");
    if (pinned && g->collapse_count)
        restore(g, g->original_count);
    sw_status st = check_original(g, err);
    if (st != SW_OK || !g->original_count)
        return st;
    size_t cap = (size_t)g->original_count * 2;
    simp S = {.g = g, .pinned = pinned};
    S.adj = calloc(cap, sizeof *S.adj);
    S.stored = calloc(cap, sizeof *S.stored);
    S.cost = malloc(cap * sizeof *S.cost);
    S.eps = malloc(cap * sizeof *S.eps);
    S.target = malloc(cap * sizeof *S.target);
    S.heap = malloc(cap * sizeof *S.heap);
    S.pos = malloc(cap * sizeof *S.pos);
    S.mark = calloc(cap, sizeof *S.mark);
    S.bounded = calloc(cap, sizeof *S.bounded);
    S.barred = calloc(cap, sizeof *S.barred);
    if (!S.adj || !S.stored || !S.cost || !S.eps || !S.target || !S.heap || !S.pos || !S.mark ||
        !S.bounded || !S.barred)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    if (st == SW_OK)
        st = build_adjacency(&S, err);
    if (st == SW_OK)
        st = sw_seam_runs_init(&S.runs, g, (uint32_t)cap, err);
    S.runs.eval = eval;
    if (st == SW_OK)
        st = grow_host(g, cap, err);
    uint32_t original = g->original_count;
    if (st == SW_OK) {
        memset(S.pos, 0xFF, cap * sizeof *S.pos);
        for (uint32_t v = 0; v < original; v++)
            update_best(&S, v, 0);
        while (S.heap_n && st == SW_OK) {
            uint32_t top = S.heap[0];
            if (S.bounded[top])
                update_best(&S, top, 1);   /* exact now; the heap's top may change */
            else if (collapse(&S, top))
                st = sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
        }
        if (st != SW_OK)
            restore(g, original);
    }
    free_simp(&S, (uint32_t)cap);
    return st;
}

uint32_t sw_seam_pin_surfaces(const sw_seam_host *g, const uint8_t *surfaces, uint8_t *pinned)
{
    uint32_t newly = 0;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        if (!surfaces[s])
            continue;
        int changed = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            for (uint32_t i = 0; i < g->loops[l].slot_count; i++) {
                uint32_t v = g->slots[g->loops[l].first_slot + i].vertex;
                changed |= !pinned[v];
                pinned[v] = 1;
            }
        newly += (uint32_t)changed;
    }
    return newly;
}
