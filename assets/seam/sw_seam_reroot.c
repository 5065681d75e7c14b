/* SPDX-License-Identifier: MIT */
/* The Seam Graph re-rooted at its floor (sw_seam_reroot.h). */
#include "sw_seam_reroot.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_seam_check.h"
#include "sw_seam_select.h"

typedef struct reroot {
    const sw_seam_host *g;
    uint32_t prefix;       /* the leading collapses within the floor */
    uint8_t *applied;      /* vertex_count: a created vertex applied for good */
    uint32_t *top;         /* vertex_count: the front vertex standing for it, or NONE above */
    uint32_t *renum;       /* vertex_count: its number in the new graph, NONE when gone */
    uint32_t front, applied_count;
    /* Which loops show each vertex (sorted runs in pool), and how many
     * distinct vertices each loop shows, while the prefix is applied. */
    uint32_t *set_first, *set_count, *pool, *distinct;
    size_t pool_len, pool_cap;
    uint32_t *leaf_lo;     /* original_count: the old hierarchy's leaf positions */
    sw_seam_host out;
} reroot;

static int pool_push(reroot *r, uint32_t x)
{
    if (r->pool_len == r->pool_cap) {
        size_t cap = r->pool_cap ? 2 * r->pool_cap : 1024;
        uint32_t *p = realloc(r->pool, cap * sizeof *p);
        if (!p)
            return 0;
        r->pool = p, r->pool_cap = cap;
    }
    r->pool[r->pool_len++] = x;
    return 1;
}

/* Each original's loops, sorted and unique, and each loop's distinct
 * vertices. */
static int original_sets(reroot *r)
{
    const sw_seam_host *g = r->g;
    uint32_t *slot_loop = malloc(((size_t)g->slot_count + 1) * sizeof *slot_loop);
    if (!slot_loop)
        return 0;
    for (uint32_t l = 0; l < g->loop_count; l++)
        for (uint32_t i = 0; i < g->loops[l].slot_count; i++)
            slot_loop[g->loops[l].first_slot + i] = l;
    int ok = 1;
    for (uint32_t v = 0; ok && v < g->original_count; v++) {
        const sw_seam_vertex *x = &g->vertices[v];
        r->set_first[v] = (uint32_t)r->pool_len;
        for (uint32_t k = 0; ok && k < x->slot_ref_count; k++) {
            uint32_t l = slot_loop[g->slot_refs[x->first_slot_ref + k]], *s = r->pool + r->set_first[v];
            uint32_t n = (uint32_t)(r->pool_len - r->set_first[v]), at = 0;
            while (at < n && s[at] < l)
                at++;
            if (at < n && s[at] == l)
                continue;
            ok = pool_push(r, 0);
            s = r->pool + r->set_first[v];   /* the pool may have moved */
            memmove(s + at + 1, s + at, (n - at) * sizeof *s);
            s[at] = l;
            r->distinct[l]++;
        }
        r->set_count[v] = (uint32_t)(r->pool_len - r->set_first[v]);
    }
    free(slot_loop);
    return ok;
}

/* Collapse k of the prefix, when both its vertices are there and no loop
 * showing both is down to three: vn's loops are the union of theirs. */
static int apply(reroot *r, uint32_t k)
{
    const sw_seam_host *g = r->g;
    uint32_t v1 = g->collapses[k].v1, v2 = g->collapses[k].v2, vn = g->original_count + k;
    if ((v1 >= g->original_count && !r->applied[v1]) ||
        (v2 >= g->original_count && !r->applied[v2]))
        return 1;
    uint32_t a0 = r->set_first[v1], an = r->set_count[v1], b0 = r->set_first[v2],
             bn = r->set_count[v2];
    for (uint32_t i = 0, j = 0; i < an && j < bn;) {
        uint32_t a = r->pool[a0 + i], b = r->pool[b0 + j];
        if (a == b && r->distinct[a] <= 3)
            return 1;
        i += a <= b, j += b <= a;
    }
    r->set_first[vn] = (uint32_t)r->pool_len;
    for (uint32_t i = 0, j = 0; i < an || j < bn;) {
        uint32_t a = i < an ? r->pool[a0 + i] : UINT32_MAX, b = j < bn ? r->pool[b0 + j] : UINT32_MAX;
        if (a == b)
            r->distinct[a]--;
        if (!pool_push(r, a < b ? a : b))
            return 0;
        i += a <= b, j += b <= a;
    }
    r->set_count[vn] = (uint32_t)(r->pool_len - r->set_first[vn]);
    r->applied[vn] = 1;
    r->applied_count++;
    return 1;
}

/* The front the applied collapses leave, and the new numbers: the front in
 * old order, then the created vertices above it in old order. */
static void number(reroot *r)
{
    const sw_seam_host *g = r->g;
    for (uint32_t v = g->vertex_count; v-- > 0;) {
        int there = v < g->original_count || r->applied[v];
        uint32_t c = g->vertices[v].child;
        int front = there && (c == SW_SEAM_NONE || !r->applied[c]);
        r->top[v] = front ? v : c == SW_SEAM_NONE || !there ? SW_SEAM_NONE : r->top[c];
    }
    uint32_t n = 0;
    for (uint32_t v = 0; v < g->vertex_count; v++)
        r->renum[v] = r->top[v] == v ? n++ : SW_SEAM_NONE;
    r->front = n;
    for (uint32_t v = g->original_count; v < g->vertex_count; v++)
        if (r->top[v] == SW_SEAM_NONE)
            r->renum[v] = n++;
}

static uint32_t shown(const reroot *r, uint32_t slot)
{
    return r->renum[r->top[r->g->slots[slot].vertex]];
}

/* Marks the slots loop l keeps: per run of slots showing one vertex, the
 * one whose (u, v) the runtime's rule took (the least old leaf position),
 * and every slot on a degenerate side. */
static uint32_t mark_loop(const reroot *r, uint32_t l, uint8_t *keep)
{
    const sw_seam_host *g = r->g;
    const sw_seam_loop *loop = &g->loops[l];
    sw_seam_graph view = sw_seam_host_view(g);
    uint32_t n = loop->slot_count, f = loop->first_slot, start = 0, kept = 0;
    while (start < n && shown(r, f + start) == shown(r, f + (start + n - 1) % n))
        start++;
    start = start == n ? 0 : start;
    for (uint32_t i = 0; i < n;) {
        uint32_t k0 = (start + i) % n, x = shown(r, f + k0), len = 1, rule = k0;
        while (i + len < n && shown(r, f + (start + i + len) % n) == x)
            len++;
        for (uint32_t j = 0; j < len; j++) {
            uint32_t k = (k0 + j) % n;
            if (r->leaf_lo[g->slots[f + k].vertex] < r->leaf_lo[g->slots[f + rule].vertex])
                rule = k;
            keep[k] = sw_seam_slot_degenerate(&view, l, k);
        }
        keep[rule] = 1;
        i += len;
    }
    for (uint32_t k = 0; k < n; k++)
        kept += keep[k];
    return kept;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* The new loops and slots, and the edges between their consecutive
 * distinct vertices. */
static int make_slots(reroot *r)
{
    const sw_seam_host *g = r->g;
    sw_seam_host *o = &r->out;
    uint8_t *keep = malloc((size_t)g->slot_count + 1);
    o->loops = malloc(((size_t)g->loop_count + 1) * sizeof *o->loops);
    o->slots = malloc(((size_t)g->slot_count + 1) * sizeof *o->slots);
    uint64_t *pairs = malloc(((size_t)g->slot_count + 1) * sizeof *pairs);
    int ok = keep && o->loops && o->slots && pairs;
    uint32_t npairs = 0;
    for (uint32_t l = 0; ok && l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        mark_loop(r, l, keep);
        o->loops[l] = (sw_seam_loop){ loop->surface, o->slot_count, 0, loop->flags };
        for (uint32_t k = 0; k < loop->slot_count; k++)
            if (keep[k]) {
                const sw_seam_slot *s = &g->slots[loop->first_slot + k];
                o->slots[o->slot_count++] = (sw_seam_slot){ shown(r, loop->first_slot + k),
                                                            { s->uv[0], s->uv[1] } };
            }
        o->loops[l].slot_count = o->slot_count - o->loops[l].first_slot;
        const sw_seam_slot *first = &o->slots[o->loops[l].first_slot];
        for (uint32_t k = 0; k < o->loops[l].slot_count; k++) {
            uint32_t a = first[k].vertex, b = first[(k + 1) % o->loops[l].slot_count].vertex;
            if (a != b)
                pairs[npairs++] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
        }
    }
    o->loop_count = g->loop_count;
    if (ok) {
        qsort(pairs, npairs, sizeof *pairs, cmp_u64);
        o->edges = malloc(((size_t)npairs + 1) * sizeof *o->edges);
        ok = o->edges != NULL;
        for (uint32_t i = 0; ok && i < npairs; i++)
            if (i == 0 || pairs[i] != pairs[i - 1])
                o->edges[o->edge_count++] = (sw_seam_edge){ (uint32_t)(pairs[i] >> 32),
                                                            (uint32_t)pairs[i] };
    }
    free(keep);
    free(pairs);
    return ok;
}

/* The vertices (slot references rebuilt) and the collapses left. */
static int make_vertices(reroot *r)
{
    const sw_seam_host *g = r->g;
    sw_seam_host *o = &r->out;
    o->original_count = r->front;
    o->collapse_count = g->collapse_count - r->applied_count;
    o->vertex_count = o->original_count + o->collapse_count;
    o->vertices = calloc((size_t)o->vertex_count + 1, sizeof *o->vertices);
    o->collapses = malloc(((size_t)o->collapse_count + 1) * sizeof *o->collapses);
    o->slot_refs = malloc(((size_t)o->slot_count + 1) * sizeof *o->slot_refs);
    if (!o->vertices || !o->collapses || !o->slot_refs)
        return 0;
    for (uint32_t v = 0; v < g->vertex_count; v++) {
        uint32_t nv = r->renum[v], c = g->vertices[v].child;
        if (nv == SW_SEAM_NONE)
            continue;
        sw_seam_vertex *x = &o->vertices[nv];
        memcpy(x->p, g->vertices[v].p, sizeof x->p);
        x->error = g->vertices[v].error;
        x->child = c == SW_SEAM_NONE ? SW_SEAM_NONE : r->renum[c];
        if (v >= g->original_count && nv >= o->original_count) {
            const sw_seam_collapse *k = &g->collapses[v - g->original_count];
            o->collapses[nv - o->original_count] =
                (sw_seam_collapse){ r->renum[k->v1], r->renum[k->v2], k->error };
        }
    }
    /* A vertex the cut made original stands for collapses, however flat:
     * its error is above 0, so it is never taken for a sewn point
     * (sw_seam_sewing_offset); errors stay monotone towards the roots. */
    for (uint32_t v = g->original_count; v < g->vertex_count; v++)
        if (r->renum[v] != SW_SEAM_NONE && r->renum[v] < o->original_count)
            o->vertices[r->renum[v]].error = fmaxf(o->vertices[r->renum[v]].error, FLT_MIN);
    for (uint32_t k = 0; k < o->collapse_count; k++) {
        sw_seam_vertex *x = &o->vertices[o->original_count + k];
        const sw_seam_collapse *c = &o->collapses[k];
        x->error = fmaxf(x->error, fmaxf(o->vertices[c->v1].error, o->vertices[c->v2].error));
    }
    for (uint32_t s = 0; s < o->slot_count; s++)
        o->vertices[o->slots[s].vertex].slot_ref_count++;
    uint32_t at = 0;
    for (uint32_t v = 0; v < o->original_count; v++) {
        o->vertices[v].first_slot_ref = at;
        at += o->vertices[v].slot_ref_count;
        o->vertices[v].slot_ref_count = 0;
    }
    for (uint32_t s = 0; s < o->slot_count; s++) {
        sw_seam_vertex *x = &o->vertices[o->slots[s].vertex];
        o->slot_refs[x->first_slot_ref + x->slot_ref_count++] = s;
    }
    o->slot_ref_count = o->slot_count;
    return 1;
}

static sw_status leaf_positions(reroot *r, sw_error *err)
{
    sw_seam_graph view = sw_seam_host_view(r->g);
    size_t bytes = sw_seam_select_arena_bytes(&view);
    void *block = bytes != SIZE_MAX ? malloc(bytes) : NULL;
    r->leaf_lo = malloc(((size_t)r->g->original_count + 1) * sizeof *r->leaf_lo);
    if (!block || !r->leaf_lo) {
        free(block);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam re-root: out of memory");
    }
    sw_arena arena;
    sw_arena_init(&arena, block, bytes);
    sw_seam_select sel;
    sw_status st = sw_seam_select_init(&sel, &view, &arena, err);
    if (st == SW_OK)
        memcpy(r->leaf_lo, sel.leaf_lo, (size_t)r->g->original_count * sizeof *r->leaf_lo);
    free(block);
    return st;
}

static void free_reroot(reroot *r)
{
    free(r->applied);
    free(r->top);
    free(r->renum);
    free(r->set_first);
    free(r->set_count);
    free(r->pool);
    free(r->distinct);
    free(r->leaf_lo);
}

static sw_status prepare(reroot *r, float floor, sw_error *err)
{
    const sw_seam_host *g = r->g;
    size_t v = (size_t)g->vertex_count + 1;
    r->applied = calloc(v, 1);
    r->top = malloc(v * sizeof *r->top);
    r->renum = malloc(v * sizeof *r->renum);
    r->set_first = malloc(v * sizeof *r->set_first);
    r->set_count = malloc(v * sizeof *r->set_count);
    r->distinct = calloc((size_t)g->loop_count + 1, sizeof *r->distinct);
    if (!r->applied || !r->top || !r->renum || !r->set_first || !r->set_count || !r->distinct)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam re-root: out of memory");
    while (r->prefix < g->collapse_count &&
           g->vertices[g->original_count + r->prefix].error <= floor)
        r->prefix++;
    if (!original_sets(r))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam re-root: out of memory");
    for (uint32_t k = 0; k < r->prefix; k++)
        if (!apply(r, k))
            return sw_error_set(err, SW_ERR_NO_MEMORY, "seam re-root: out of memory");
    return leaf_positions(r, err);
}

sw_status sw_seam_reroot(sw_seam_host *graph, float floor, sw_seam_reroot_report *report,
                         sw_error *err)
{
    sw_seam_reroot_report rep = { 0, 0, graph->original_count, graph->original_count,
                                  graph->slot_count, graph->slot_count };
    if (report)
        *report = rep;
    sw_seam_graph view = sw_seam_host_view(graph);
    sw_status st = sw_seam_graph_check(&view, err);
    if (st != SW_OK || !(floor > 0) || graph->collapse_count == 0)
        return st;
    reroot r = { .g = graph };
    st = prepare(&r, floor, err);
    if (st == SW_OK && r.applied_count > 0) {
        number(&r);
        r.out.surface_count = graph->surface_count;
        r.out.tolerance = graph->tolerance;
        r.out.surface_loops = malloc(((size_t)graph->surface_count + 1) * sizeof(uint32_t));
        if (!r.out.surface_loops || !make_slots(&r) || !make_vertices(&r))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "seam re-root: out of memory");
        else
            memcpy(r.out.surface_loops, graph->surface_loops,
                   ((size_t)graph->surface_count + 1) * sizeof(uint32_t));
        sw_seam_graph made = sw_seam_host_view(&r.out);
        if (st == SW_OK && (st = sw_seam_graph_check(&made, err)) != SW_OK)
            sw_error_prefix(err, "seam re-root made a graph the reader refuses");
    }
    if (st == SW_OK && r.applied_count > 0) {
        rep = (sw_seam_reroot_report){ r.applied_count, r.prefix - r.applied_count,
                                       graph->original_count, r.out.original_count,
                                       graph->slot_count, r.out.slot_count };
        sw_seam_host_free(graph);
        *graph = r.out;
        memset(&r.out, 0, sizeof r.out);
    } else if (st == SW_OK) {
        rep.kept = r.prefix;
    }
    sw_seam_host_free(&r.out);
    free_reroot(&r);
    if (report && st == SW_OK)
        *report = rep;
    return st;
}
