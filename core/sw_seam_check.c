/* SPDX-License-Identifier: MIT */
/* sw_seam_graph_check (sw_seam_check.h): every rule of a Seam Graph, for a
 * graph built on the host and for one read from a pack (the pack reader's
 * sw_pack_validate_seam checks the SEAM header record and then calls this,
 * so there is one set of rules). It checks every index and every value the
 * runtime walks along once, so the seam selection and the trim tessellator
 * need no checks of their own: the collapse hierarchy is a forest whose
 * links only go to larger indices, so walking a vertex to its root ends;
 * every slot names an original vertex and lies in exactly one loop; slot_refs
 * are exactly the inverse of slots. It allocates nothing (the runtime calls
 * it): the inverse is checked in one pass because each vertex's references
 * are a contiguous run in vertex order and in increasing slot order.
 * Messages name the pack section, record and field ("SEAM_COLLAPSES[2].v1:
 * ..."), which are also the arrays' names in sw_seam_graph. Rules:
 * assets/PACK_FORMAT.md. */
#include "sw_seam_check.h"

#include <math.h>
#include <stdio.h>

static int finite_non_negative(float x) { return isfinite(x) && x >= 0.0f; }

static sw_status check_arrays(const sw_seam_graph *g, sw_error *err)
{
    if ((uint64_t)g->original_count + g->collapse_count != g->vertex_count)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "seam graph: vertex_count %u, expected original_count %u + "
                            "collapse_count %u", g->vertex_count, g->original_count,
                            g->collapse_count);
    if (g->vertex_count >= SW_SEAM_NONE)
        return sw_error_set(err, SW_ERR_RANGE, "seam graph: vertex_count %u too large",
                            g->vertex_count);
    if ((g->vertex_count && !g->vertices) || (g->slot_count && !g->slots) ||
        (g->loop_count && !g->loops) || (g->edge_count && !g->edges) ||
        (g->collapse_count && !g->collapses) || (g->slot_ref_count && !g->slot_refs) ||
        !g->surface_loops)
        return sw_error_set(err, SW_ERR_FORMAT, "seam graph: an array with a non-zero "
                                                "count (or surface_loops) is missing");
    if (g->slot_ref_count != g->slot_count)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM.slot_ref_count: %u, expected slot_count %u "
                            "(every slot is listed once)", (unsigned)g->slot_ref_count,
                            (unsigned)g->slot_count);
    if (!isfinite(g->tolerance) || g->tolerance < 0.0f)
        return sw_error_set(err, SW_ERR_FORMAT, "seam graph: tolerance %g, expected finite >= 0",
                            (double)g->tolerance);
    return SW_OK;
}

/* One vertex's own fields; links to other records are checked later. */
static sw_status validate_vertex(const sw_seam_graph *g, uint32_t i, sw_error *err)
{
    const sw_seam_vertex *v = &g->vertices[i];
    for (int k = 0; k < 3; k++)
        if (!isfinite(v->p[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].p.%c: %g, expected a "
                                "finite number", (unsigned)i, "xyz"[k], (double)v->p[k]);
    int original = i < g->original_count;
    /* An original vertex's error is 0 where the hierarchy starts at the
     * sewn polylines, the floor it stands for where the host cut it
     * (assets/seam/sw_seam_reroot.h). */
    if (!finite_non_negative(v->error))
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].error: %g, expected finite "
                            ">= 0", (unsigned)i, (double)v->error);
    if (v->reserved != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].reserved: %u, expected 0",
                            (unsigned)i, (unsigned)v->reserved);
    /* Children are created vertices made after i: links only go up, so the
     * hierarchy is a forest and every walk to a root ends. */
    uint32_t lowest = i + 1 > g->original_count ? i + 1 : g->original_count;
    if (v->child != SW_SEAM_NONE && (v->child < lowest || v->child >= g->vertex_count))
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_VERTICES[%u].child: %u, expected 0x%08x "
                            "(none) or a created vertex in %u..%u", (unsigned)i,
                            (unsigned)v->child, SW_SEAM_NONE, (unsigned)lowest,
                            (unsigned)g->vertex_count - 1u);
    if (!original && (v->first_slot_ref != 0 || v->slot_ref_count != 0))
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].first_slot_ref: %u with "
                            "slot_ref_count %u, expected 0 and 0 (a created vertex sits in no "
                            "slot)", (unsigned)i, (unsigned)v->first_slot_ref,
                            (unsigned)v->slot_ref_count);
    return SW_OK;
}

/* Collapse k makes vertex vn = original_count + k from two vertices that
 * existed before it, and both name vn as their child. */
static sw_status validate_collapse(const sw_seam_graph *g, uint32_t k, sw_error *err)
{
    const sw_seam_collapse *c = &g->collapses[k];
    uint32_t vn = g->original_count + k;
    if (!finite_non_negative(c->error))
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_COLLAPSES[%u].error: %g, expected finite "
                            ">= 0", (unsigned)k, (double)c->error);
    if (c->v1 >= vn || c->v2 >= vn)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_COLLAPSES[%u].%s: %u, expected a vertex "
                            "made before the one it creates (< %u)", (unsigned)k,
                            c->v1 >= vn ? "v1" : "v2", (unsigned)(c->v1 >= vn ? c->v1 : c->v2),
                            (unsigned)vn);
    if (c->v1 == c->v2)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_COLLAPSES[%u].v2: %u, the same as v1",
                            (unsigned)k, (unsigned)c->v2);
    const sw_seam_vertex *n = &g->vertices[vn], *kept = &g->vertices[c->v2];
    for (int side = 0; side < 2; side++) {
        uint32_t v = side ? c->v2 : c->v1;
        if (g->vertices[v].child != vn)
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_COLLAPSES[%u].%s: vertex %u has child "
                                "%u, expected %u (the vertex this collapse creates)", (unsigned)k,
                                side ? "v2" : "v1", (unsigned)v,
                                (unsigned)g->vertices[v].child, (unsigned)vn);
        /* Errors never drop going up, so a cut by error threshold is a
         * front of the forest; read here, with the child field. */
        if (n->error < g->vertices[v].error)
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].error: %g, below its "
                                "parent %u's %g (errors grow towards the roots)", (unsigned)vn,
                                (double)n->error, (unsigned)v, (double)g->vertices[v].error);
    }
    if (n->p[0] != kept->p[0] || n->p[1] != kept->p[1] || n->p[2] != kept->p[2])
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].p: (%g, %g, %g), expected "
                            "v2 %u's (%g, %g, %g) (made by SEAM_COLLAPSES[%u])", (unsigned)vn,
                            (double)n->p[0], (double)n->p[1], (double)n->p[2], (unsigned)c->v2,
                            (double)kept->p[0], (double)kept->p[1], (double)kept->p[2],
                            (unsigned)k);
    if (n->error < c->error)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].error: %g, below its "
                            "SEAM_COLLAPSES[%u].error %g", (unsigned)vn, (double)n->error,
                            (unsigned)k, (double)c->error);
    return SW_OK;
}

/* A vertex with a child is one of the two its child's collapse merged (so
 * every created vertex has exactly two parents). Only called to name the
 * vertex once the count in validate_hierarchy has found one. */
static sw_status check_parent(const sw_seam_graph *g, uint32_t i, sw_error *err)
{
    const sw_seam_vertex *v = &g->vertices[i];
    if (v->child == SW_SEAM_NONE)
        return SW_OK;
    uint32_t k = v->child - g->original_count;
    const sw_seam_collapse *c = &g->collapses[k];
    if (c->v1 != i && c->v2 != i)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].child: %u, but "
                            "SEAM_COLLAPSES[%u] creates it from vertices %u and %u", (unsigned)i,
                            (unsigned)v->child, (unsigned)k, (unsigned)c->v1, (unsigned)c->v2);
    return SW_OK;
}

static sw_status validate_slot(const sw_seam_graph *g, uint32_t j, sw_error *err)
{
    const sw_seam_slot *s = &g->slots[j];
    if (s->vertex >= g->original_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_SLOTS[%u].vertex: %u, expected an original "
                            "vertex (< %u)", (unsigned)j, (unsigned)s->vertex,
                            (unsigned)g->original_count);
    for (int k = 0; k < 2; k++)
        if (!isfinite(s->uv[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SLOTS[%u].uv[%d]: %g, expected a finite "
                                "number", (unsigned)j, k, (double)s->uv[k]);
    return SW_OK;
}

/* Original vertex i's references: the run right after vertex i - 1's, every
 * one a slot of i, in increasing slot order (so none repeats). *next is
 * where the run must start and becomes where the next one must. */
static sw_status check_slot_refs(const sw_seam_graph *g, uint32_t i, uint64_t *next,
                                 sw_error *err)
{
    const sw_seam_vertex *v = &g->vertices[i];
    if (v->slot_ref_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].slot_ref_count: 0, expected "
                            "at least 1 (an original vertex sits in a slot)", (unsigned)i);
    if (v->first_slot_ref != *next)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES[%u].first_slot_ref: %u, expected "
                            "%llu (the runs of slot references follow vertex order)", (unsigned)i,
                            (unsigned)v->first_slot_ref, (unsigned long long)*next);
    uint64_t end = (uint64_t)v->first_slot_ref + v->slot_ref_count;
    if (end > g->slot_ref_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_VERTICES[%u].first_slot_ref: %u + "
                            "slot_ref_count %u exceeds SEAM_SLOT_REFS count %u", (unsigned)i,
                            (unsigned)v->first_slot_ref, (unsigned)v->slot_ref_count,
                            (unsigned)g->slot_ref_count);
    for (uint32_t r = v->first_slot_ref; r < end; r++) {
        uint32_t slot = g->slot_refs[r];
        if (slot >= g->slot_count)
            return sw_error_set(err, SW_ERR_RANGE, "SEAM_SLOT_REFS[%u]: %u, but SEAM_SLOTS has "
                                "%u entries", (unsigned)r, (unsigned)slot,
                                (unsigned)g->slot_count);
        if (g->slots[slot].vertex != i)
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SLOT_REFS[%u]: slot %u holds vertex %u, "
                                "but the reference is in vertex %u's run", (unsigned)r,
                                (unsigned)slot, (unsigned)g->slots[slot].vertex, (unsigned)i);
        if (r > v->first_slot_ref && slot <= g->slot_refs[r - 1])
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SLOT_REFS[%u]: %u, expected more than "
                                "the previous %u (a vertex's slots in increasing order)",
                                (unsigned)r, (unsigned)slot, (unsigned)g->slot_refs[r - 1]);
    }
    *next = end;
    return SW_OK;
}

/* SEAM_SURFACE_LOOPS: starts at 0, never decreases, ends at the loop count. */
static sw_status validate_surface_loops(const sw_seam_graph *g, sw_error *err)
{
    const uint32_t *sl = g->surface_loops;
    uint32_t n = g->surface_count;
    if (sl[0] != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[0]: %u, expected 0",
                            (unsigned)sl[0]);
    for (uint32_t s = 1; s <= n; s++)
        if (sl[s] < sl[s - 1])
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[%u]: %u < the previous "
                                "%u, expected non-decreasing", (unsigned)s, (unsigned)sl[s],
                                (unsigned)sl[s - 1]);
    if (sl[n] != g->loop_count)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_SURFACE_LOOPS[%u]: %u, expected the "
                            "SEAM_LOOPS count %u", (unsigned)n, (unsigned)sl[n],
                            (unsigned)g->loop_count);
    return SW_OK;
}

/* Loop l: in its surface's range of SEAM_SURFACE_LOOPS, at least three slots,
 * starting where loop l - 1 ended (*next), so the loops tile SEAM_SLOTS. */
static sw_status validate_loop(const sw_seam_graph *g, uint32_t l, uint64_t *next, sw_error *err)
{
    const sw_seam_loop *loop = &g->loops[l];
    if (loop->surface >= g->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_LOOPS[%u].surface: %u, but SURFACES has %u "
                            "entries", (unsigned)l, (unsigned)loop->surface,
                            (unsigned)g->surface_count);
    const uint32_t *sl = g->surface_loops;
    if (l < sl[loop->surface] || l >= sl[loop->surface + 1])
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_LOOPS[%u].surface: %u, but "
                            "SEAM_SURFACE_LOOPS gives that surface the loops [%u, %u)",
                            (unsigned)l, (unsigned)loop->surface, (unsigned)sl[loop->surface],
                            (unsigned)sl[loop->surface + 1]);
    if (loop->flags & ~(uint32_t)SW_SEAM_LOOP_OUTER)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_LOOPS[%u].flags: 0x%x has unknown bits",
                            (unsigned)l, (unsigned)loop->flags);
    if (loop->slot_count < 3)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_LOOPS[%u].slot_count: %u, expected at "
                            "least 3", (unsigned)l, (unsigned)loop->slot_count);
    if (loop->first_slot != *next)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_LOOPS[%u].first_slot: %u, expected %llu "
                            "(the loops cover SEAM_SLOTS in order)", (unsigned)l,
                            (unsigned)loop->first_slot, (unsigned long long)*next);
    uint64_t end = (uint64_t)loop->first_slot + loop->slot_count;
    if (end > g->slot_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_LOOPS[%u].first_slot: %u + slot_count %u "
                            "exceeds SEAM_SLOTS count %u", (unsigned)l, (unsigned)loop->first_slot,
                            (unsigned)loop->slot_count, (unsigned)g->slot_count);
    *next = end;
    return SW_OK;
}

static sw_status validate_edge(const sw_seam_graph *g, uint32_t e, sw_error *err)
{
    const sw_seam_edge *edge = &g->edges[e];
    if (edge->b >= g->original_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM_EDGES[%u].b: %u, expected an original "
                            "vertex (< %u)", (unsigned)e, (unsigned)edge->b,
                            (unsigned)g->original_count);
    if (edge->a >= edge->b)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM_EDGES[%u].a: %u, expected less than b %u",
                            (unsigned)e, (unsigned)edge->a, (unsigned)edge->b);
    return SW_OK;
}

/* The check in parts (sw_parts.h), in the order of the rules: the vertices
 * in halves and the collapses in quarters, then the slots, their inverse,
 * and the loops with the edges. A part finds the first problem in its own
 * range and stops; every part reads only what check_arrays has bounded, so
 * each is safe whatever another finds. The first part in this order that
 * fails names the problem: the same one a single pass in this order would.
 * They are handed out in another order (run_order), the longest first so
 * that threads end together: on the showroom half the collapses (random
 * reads of the vertices) took 23-30 ms, the inverse 13, half the vertices
 * 10, the slots 3, the loops 1. */
enum {
    VERTEX_PARTS = 2,
    COLLAPSE_PARTS = 4,
    PART_SLOTS = VERTEX_PARTS + COLLAPSE_PARTS,
    PART_SLOT_REFS,
    PART_LOOPS,
    CHECK_PARTS
};

typedef struct check_job {
    const sw_seam_graph *g;
    sw_status status[CHECK_PARTS];
    sw_error err[CHECK_PARTS];
    uint64_t with_child[VERTEX_PARTS];
} check_job;

/* Part p of count's share of n items: [*lo, *hi). */
static void share(uint32_t n, uint32_t p, uint32_t count, uint32_t *lo, uint32_t *hi)
{
    *lo = (uint32_t)((uint64_t)n * p / count);
    *hi = (uint32_t)((uint64_t)n * (p + 1) / count);
}

static sw_status check_vertices(const sw_seam_graph *g, uint32_t p, uint64_t *with_child,
                                sw_error *err)
{
    uint32_t lo, hi;
    share(g->vertex_count, p, VERTEX_PARTS, &lo, &hi);
    sw_status s = SW_OK;
    for (uint32_t i = lo; s == SW_OK && i < hi; i++) {
        s = validate_vertex(g, i, err);
        *with_child += g->vertices[i].child != SW_SEAM_NONE;
    }
    return s;
}

static sw_status check_collapses(const sw_seam_graph *g, uint32_t p, sw_error *err)
{
    uint32_t lo, hi;
    share(g->collapse_count, p, COLLAPSE_PARTS, &lo, &hi);
    sw_status s = SW_OK;
    for (uint32_t k = lo; s == SW_OK && k < hi; k++)
        s = validate_collapse(g, k, err);
    return s;
}

static sw_status check_slots(const sw_seam_graph *g, sw_error *err)
{
    sw_status s = SW_OK;
    for (uint32_t j = 0; s == SW_OK && j < g->slot_count; j++)
        s = validate_slot(g, j, err);
    return s;
}

/* The slots' inverse: with slot_ref_count == slot_count, refs that cover
 * the array, name their run's vertex and increase within it are a
 * bijection. */
static sw_status check_inverse(const sw_seam_graph *g, sw_error *err)
{
    sw_status s = SW_OK;
    uint64_t next = 0;
    for (uint32_t i = 0; s == SW_OK && i < g->original_count; i++)
        s = check_slot_refs(g, i, &next, err);
    if (s == SW_OK && next != g->slot_ref_count)
        s = sw_error_set(err, SW_ERR_FORMAT, "SEAM_SLOT_REFS: the original vertices' runs end "
                         "at %llu, expected the count %u", (unsigned long long)next,
                         (unsigned)g->slot_ref_count);
    return s;
}

/* The loops over the slots, and the edges. */
static sw_status check_loops(const sw_seam_graph *g, sw_error *err)
{
    sw_status s = validate_surface_loops(g, err);
    uint64_t next = 0;
    for (uint32_t l = 0; s == SW_OK && l < g->loop_count; l++)
        s = validate_loop(g, l, &next, err);
    if (s == SW_OK && next != g->slot_count)
        s = sw_error_set(err, SW_ERR_FORMAT, "SEAM_LOOPS: the loops end at slot %llu, expected "
                         "the SEAM_SLOTS count %u", (unsigned long long)next,
                         (unsigned)g->slot_count);
    for (uint32_t e = 0; s == SW_OK && e < g->edge_count; e++)
        s = validate_edge(g, e, err);
    return s;
}

static const uint8_t run_order[CHECK_PARTS] = {
    VERTEX_PARTS, VERTEX_PARTS + 1, VERTEX_PARTS + 2, VERTEX_PARTS + 3, PART_SLOT_REFS, 0, 1,
    PART_SLOTS, PART_LOOPS };
_Static_assert(CHECK_PARTS == 9 && COLLAPSE_PARTS == 4, "run_order lists every part once");

static void run_part(void *arg, uint32_t turn)
{
    check_job *job = arg;
    uint32_t p = run_order[turn];
    const sw_seam_graph *g = job->g;
    sw_error *err = &job->err[p];
    sw_status s;
    if (p < VERTEX_PARTS)
        s = check_vertices(g, p, &job->with_child[p], err);
    else if (p < PART_SLOTS)
        s = check_collapses(g, p - VERTEX_PARTS, err);
    else if (p == PART_SLOTS)
        s = check_slots(g, err);
    else if (p == PART_SLOT_REFS)
        s = check_inverse(g, err);
    else
        s = check_loops(g, err);
    job->status[p] = s;
}

/* Every collapse's two parents name it as their child, so no vertex is the
 * parent of two collapses and the collapses have 2 x collapse_count
 * distinct parents; then "every vertex with a child is a parent of its
 * child's collapse" is the count of vertices with a child being exactly
 * that. Counted in the vertex parts instead of a second random pass over
 * the collapses (which was a third of the pack's checks on the showroom);
 * the slow pass runs only to name the vertex. */
static sw_status check_parent_count(const sw_seam_graph *g, const check_job *job, sw_error *err)
{
    uint64_t with_child = 0;
    for (int p = 0; p < VERTEX_PARTS; p++)
        with_child += job->with_child[p];
    if (with_child == 2ull * g->collapse_count)
        return SW_OK;
    sw_status s = SW_OK;
    for (uint32_t i = 0; s == SW_OK && i < g->vertex_count; i++)
        s = check_parent(g, i, err);
    return s == SW_OK ? sw_error_set(err, SW_ERR_FORMAT, "SEAM_VERTICES: %llu vertices name a "
                                     "child, expected 2 per collapse (%llu)",
                                     (unsigned long long)with_child,
                                     2ull * g->collapse_count)
                      : s;
}

/* The first failing part in order, with the parent count after the
 * hierarchy's parts (it needs them all to have passed). */
static sw_status reduce(const sw_seam_graph *g, const check_job *job, sw_error *err)
{
    for (int p = 0; p < CHECK_PARTS; p++) {
        if (p == PART_SLOTS) {
            sw_status s = check_parent_count(g, job, err);
            if (s != SW_OK)
                return s;
        }
        if (job->status[p] != SW_OK) {
            if (err)
                *err = job->err[p];
            return job->status[p];
        }
    }
    return SW_OK;
}

sw_status sw_seam_graph_check_with(const sw_seam_graph *graph, const sw_parts_runner *runner,
                                   sw_error *err)
{
    if (!graph)
        return sw_error_set(err, SW_ERR_ARG, "seam graph: no graph");
    sw_status s = check_arrays(graph, err);
    if (s != SW_OK)
        return s;
    check_job job = {.g = graph};
    sw_parts_run(runner, run_part, &job, CHECK_PARTS);
    return reduce(graph, &job, err);
}

sw_status sw_seam_graph_check(const sw_seam_graph *graph, sw_error *err)
{
    return sw_seam_graph_check_with(graph, NULL, err);
}
