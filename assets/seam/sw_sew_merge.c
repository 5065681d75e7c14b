/* Sewing step 3 (sw_sew.h): the interval joins become merged vertices and
 * the host arrays of the original Seam Graph. Points are the polyline
 * vertices (ids below N) and the feet inserted into edges (ids from N); a
 * union-find whose root is always the smallest id merges them, so every
 * class's root is the first original vertex in it, whose position the class
 * takes. */
#include "sw_sew_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct inserted {
    uint32_t edge, id;
    double t;
} inserted;

typedef struct edge_use {
    uint32_t a, b, loop;
} edge_use;

static uint32_t find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

static void unite(uint32_t *parent, uint32_t x, uint32_t y)
{
    x = find(parent, x), y = find(parent, y);
    if (x < y)
        parent[y] = x;
    else if (y < x)
        parent[x] = y;
}

static int compare_inserted(const void *x, const void *y)
{
    const inserted *a = x, *b = y;
    if (a->edge != b->edge)
        return a->edge < b->edge ? -1 : 1;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

static int compare_uses(const void *x, const void *y)
{
    const edge_use *a = x, *b = y;
    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    if (a->b != b->b)
        return a->b < b->b ? -1 : 1;
    return (a->loop > b->loop) - (a->loop < b->loop);
}

static double dist2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

/* Joins into unions; feet inside edges get ids N, N + 1, ... in ins. */
static void unite_joins(const sew_state *s, uint32_t *parent, inserted *ins, size_t *ins_count)
{
    uint32_t n = (uint32_t)s->poly->vertex_count;
    for (size_t k = 0; k < s->join_count; k++) {
        const sew_join *j = &s->joins[k];
        uint32_t target;
        if (j->t == 0)
            target = j->e;
        else if (j->t == 1)
            target = sew_next(s->poly, s->vertex_loop[j->e], j->e);
        else {
            target = n + (uint32_t)*ins_count;
            ins[(*ins_count)++] = (inserted){j->e, target, j->t};
        }
        /* Union-find is transitive: a chain of merges, each within the
         * tolerance, could drag a class far from where its members are. Two
         * classes whose positions (their first original vertex) are more
         * than twice the tolerance (with their gaps) apart stay apart. */
        uint32_t ra = find(parent, j->v), rb = find(parent, target);
        double apart = ra < n && rb < n
                     ? 2 * fmax(s->tol, sew_gap(s->poly, ra) + sew_gap(s->poly, rb)) : 0;
        if (ra < n && rb < n &&
            dist2(s->poly->p + 3 * (size_t)ra, s->poly->p + 3 * (size_t)rb) > apart * apart)
            continue;
        unite(parent, ra, rb);
    }
}

/* Loop l's slots (vertex = class root for now) at out: every polyline
 * vertex, each followed by the feet inserted into its edge. A foot merged
 * into the same vertex as the slot before it or the edge's end adds nothing
 * and is left out. Repeats of original vertices stay (a side of a patch
 * collapsed to a point, sewn into one vertex): the runtime drops consecutive
 * repeats, and every original slot keeps its (u, v), so the loop's corners in
 * parameter space survive. */
static uint32_t loop_slots(const sew_state *s, uint32_t *parent, const inserted *ins,
                           size_t ins_count, size_t *cursor, uint32_t l, sw_seam_slot *out)
{
    const sw_seam_polylines *poly = s->poly;
    uint32_t count = 0;
    for (size_t v = poly->loop_start[l]; v < poly->loop_start[l + 1]; v++) {
        out[count++] = (sw_seam_slot){find(parent, (uint32_t)v),
                                      {(float)poly->uv[2 * v], (float)poly->uv[2 * v + 1]}};
        uint32_t w = sew_next(poly, l, (uint32_t)v), end = find(parent, w);
        for (; *cursor < ins_count && ins[*cursor].edge == v; (*cursor)++) {
            uint32_t c = find(parent, ins[*cursor].id);
            if (c == out[count - 1].vertex || c == end)
                continue;
            double t = ins[*cursor].t;
            double u = poly->uv[2 * v] + t * (poly->uv[2 * w] - poly->uv[2 * v]);
            double vv = poly->uv[2 * v + 1] + t * (poly->uv[2 * w + 1] - poly->uv[2 * v + 1]);
            out[count++] = (sw_seam_slot){c, {(float)u, (float)vv}};
        }
    }
    return count;
}

/* Edges from consecutive distinct slots, each once; counts by loops along it. */
static sw_status build_edges(sw_seam_host *out, sw_sew_counts *counts, sw_error *err)
{
    edge_use *uses = malloc(((size_t)out->slot_count + 1) * sizeof *uses);
    if (!uses)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory for edges");
    size_t n = 0;
    for (uint32_t l = 0; l < out->loop_count; l++) {
        const sw_seam_loop *loop = &out->loops[l];
        for (uint32_t k = 0; k < loop->slot_count; k++) {
            uint32_t a = out->slots[loop->first_slot + k].vertex;
            uint32_t b = out->slots[loop->first_slot + (k + 1) % loop->slot_count].vertex;
            if (a != b)
                uses[n++] = (edge_use){a < b ? a : b, a < b ? b : a, l};
        }
    }
    if (n > 1)
        qsort(uses, n, sizeof *uses, compare_uses);
    out->edges = malloc((n + 1) * sizeof *out->edges);
    if (!out->edges) {
        free(uses);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory for edges");
    }
    for (size_t i = 0; i < n;) {
        size_t j = i, loops = 0;
        /* uses, not distinct loops: a closed surface sewn to itself runs
         * along the edge twice in one loop, and that is a seam too */
        for (; j < n && uses[j].a == uses[i].a && uses[j].b == uses[i].b; j++)
            loops++;
        out->edges[out->edge_count++] = (sw_seam_edge){uses[i].a, uses[i].b};
        counts->seams += loops >= 2;
        counts->free_edges += loops == 1;
        counts->nonmanifold_edges += loops > 2;
        i = j;
    }
    free(uses);
    return SW_OK;
}

/* Vertices numbered by first appearance in the slots; slot_refs grouped by
 * vertex (a counting sort). */
static sw_status number_vertices(const sew_state *s, sw_seam_host *out, sw_error *err)
{
    uint32_t n = (uint32_t)s->poly->vertex_count;
    uint32_t *index = malloc(((size_t)n + 1) * sizeof *index);
    out->vertices = calloc((size_t)n + 1, sizeof *out->vertices);
    out->slot_refs = malloc(((size_t)out->slot_count + 1) * sizeof *out->slot_refs);
    if (!index || !out->vertices || !out->slot_refs) {
        free(index);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory for vertices");
    }
    memset(index, 0xFF, (size_t)n * sizeof *index);
    for (uint32_t k = 0; k < out->slot_count; k++) {
        uint32_t root = out->slots[k].vertex;
        if (index[root] == UINT32_MAX) {
            sw_seam_vertex *v = &out->vertices[out->vertex_count];
            const double *p = s->poly->p + 3 * (size_t)root;
            *v = (sw_seam_vertex){{(float)p[0], (float)p[1], (float)p[2]}, SW_SEAM_NONE, 0, 0, 0, 0};
            index[root] = out->vertex_count++;
        }
        out->slots[k].vertex = index[root];
        out->vertices[index[root]].slot_ref_count++;
    }
    free(index);
    uint32_t at = 0;
    for (uint32_t v = 0; v < out->vertex_count; v++) {
        out->vertices[v].first_slot_ref = at;
        at += out->vertices[v].slot_ref_count;
        out->vertices[v].slot_ref_count = 0;
    }
    for (uint32_t k = 0; k < out->slot_count; k++) {
        sw_seam_vertex *v = &out->vertices[out->slots[k].vertex];
        out->slot_refs[v->first_slot_ref + v->slot_ref_count++] = k;
    }
    out->original_count = out->vertex_count;
    out->slot_ref_count = out->slot_count;
    return SW_OK;
}

/* Loops and their slots, grouped by surface as the polylines are. */
static sw_status build_loops(const sew_state *s, uint32_t *parent, inserted *ins, size_t ins_count,
                             sw_seam_host *out)
{
    const sw_seam_polylines *poly = s->poly;
    out->slots = malloc((poly->vertex_count + ins_count + 1) * sizeof *out->slots);
    out->loops = malloc((poly->loop_count + 1) * sizeof *out->loops);
    out->surface_loops = malloc((poly->surface_count + 1) * sizeof *out->surface_loops);
    if (!out->slots || !out->loops || !out->surface_loops)
        return sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory for slots");
    if (ins_count > 1)
        qsort(ins, ins_count, sizeof *ins, compare_inserted);
    size_t cursor = 0;
    for (uint32_t l = 0; l < poly->loop_count; l++) {
        uint32_t count = loop_slots(s, parent, ins, ins_count, &cursor, l, out->slots + out->slot_count);
        out->loops[l] = (sw_seam_loop){poly->loop_surface[l], out->slot_count, count,
                                       poly->loop_outer[l] ? SW_SEAM_LOOP_OUTER : 0u};
        out->slot_count += count;
    }
    out->loop_count = (uint32_t)poly->loop_count;
    for (size_t k = 0; k <= poly->surface_count; k++)
        out->surface_loops[k] = (uint32_t)poly->surface_loops[k];
    out->surface_count = (uint32_t)poly->surface_count;
    out->tolerance = (float)s->tol;
    return SW_OK;
}

sw_status sew_merge(sew_state *s, sw_seam_host *out, sw_sew_counts *counts)
{
    sw_sew_counts local = {0};
    counts = counts ? counts : &local;
    size_t n = s->poly->vertex_count, total = n + s->join_count;
    uint32_t *parent = malloc((total + 1) * sizeof *parent);
    inserted *ins = malloc((s->join_count + 1) * sizeof *ins);
    sw_status st = SW_OK;
    if (!parent || !ins)
        st = sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory merging");
    size_t ins_count = 0;
    if (st == SW_OK) {
        for (size_t k = 0; k < total; k++)
            parent[k] = (uint32_t)k;
        unite_joins(s, parent, ins, &ins_count);
        counts->inserted = ins_count;
        st = build_loops(s, parent, ins, ins_count, out);
    }
    if (st == SW_OK)
        st = number_vertices(s, out, s->err);
    if (st == SW_OK)
        st = build_edges(out, counts, s->err);
    free(parent);
    free(ins);
    return st;
}
