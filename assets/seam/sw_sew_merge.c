/* SPDX-License-Identifier: MIT */
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

#include "sw_math.h"

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

/* Consecutive vertices of a loop within this much of the tolerance of the
 * run's first are one point. */
#define ONE_POINT_OF_TOL 0.01

/* A loop's run of vertices at one point (a pole's or an apex's degenerate
 * edge, sampled: a cone's apex came as 66 points 1e-13 apart) is one
 * vertex. Otherwise the two sides that leave the point never meet: along
 * the loop they are neighbours, and a loop is not sewn to its neighbours
 * (a cone's seam line came out free on both sides). */
static void unite_points(const sew_state *s, uint32_t *parent)
{
    const sw_seam_polylines *poly = s->poly;
    double r = ONE_POINT_OF_TOL * s->tol;
    for (size_t l = 0; l < poly->loop_count; l++) {
        uint32_t first = (uint32_t)poly->loop_start[l], end = (uint32_t)poly->loop_start[l + 1];
        uint32_t anchor = first;
        for (uint32_t v = first + 1; v < end; v++) {
            if (dist2(poly->p + 3 * (size_t)v, poly->p + 3 * (size_t)anchor) <= r * r)
                unite(parent, anchor, v);
            else
                anchor = v;
        }
        if (end - first > 2 &&
            dist2(poly->p + 3 * (size_t)(end - 1), poly->p + 3 * (size_t)first) <= r * r)
            unite(parent, first, end - 1);
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

static double segment_distance(const double *p, const double *a, const double *b)
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

/* Where p projects onto segment a-b, as a fraction in [0, 1]. */
static double segment_fraction(const double *p, const double *a, const double *b)
{
    double d = 0, t = 0;
    for (int k = 0; k < 3; k++) {
        d += (b[k] - a[k]) * (b[k] - a[k]);
        t += (p[k] - a[k]) * (b[k] - a[k]);
    }
    return d > 0 ? fmin(fmax(t / d, 0.0), 1.0) : 0.0;
}

/* Slots from .. from + runs - 1 (cyclic), moved between slots a and b (the
 * slots around their new place): their (u, v) goes onto the chord from a's
 * to b's at the fraction their vertex projects to in model space, so the
 * loop stays a simple polyline in the surface's parameters. */
static void place_on_chord(const sew_state *s, sw_seam_slot *slots, uint32_t count,
                           uint32_t from, uint32_t runs, uint32_t a, uint32_t b)
{
    const double *pos = s->poly->p;
    const sw_seam_slot *sa = &slots[a % count], *sb = &slots[b % count];
    for (uint32_t k = 0; k < runs; k++) {
        sw_seam_slot *f = &slots[(from + k) % count];
        double t = segment_fraction(pos + 3 * (size_t)f->vertex, pos + 3 * (size_t)sa->vertex,
                                    pos + 3 * (size_t)sb->vertex);
        f->uv[0] = (float)(sa->uv[0] + t * (sb->uv[0] - sa->uv[0]));
        f->uv[1] = (float)(sa->uv[1] + t * (sb->uv[1] - sa->uv[1]));
    }
}

/* Moves slot from to position to (cyclic), shifting the slots between. */
static void move_slot(sw_seam_slot *slots, uint32_t count, uint32_t from, uint32_t to)
{
    sw_seam_slot moving = slots[from % count];
    int dir = (to + count - from) % count <= count / 2 ? 1 : -1;
    for (uint32_t k = from; k % count != to % count; k += (uint32_t)(dir > 0 ? 1 : count - 1))
        slots[k % count] = slots[(k + (uint32_t)(dir > 0 ? 1 : count - 1)) % count];
    slots[to % count] = moving;
}

/* A foot inserted into an edge whose two ends were merged into one vertex
 * q comes out as q, f, q: a spike out to f (one or more slots) and back.
 * Where f belongs is on the edge before q (or after it): the other loop
 * runs p, f, q there. The spike's f slots are moved there (before the run
 * of q slots, or after it), so both loops share both edges. */
static void unspike(const sew_state *s, sw_seam_slot *slots, uint32_t count)
{
    uint32_t n = (uint32_t)s->poly->vertex_count;
    const double *pos = s->poly->p;
    for (uint32_t i = 0; count >= 4 && i < count; i++) {
        uint32_t q = slots[i].vertex, f = slots[(i + 1) % count].vertex, end = i + 1;
        while (end < i + count - 2 && slots[(end + 1) % count].vertex == f)
            end++;
        if (f == q || slots[(end + 1) % count].vertex != q || q >= n || f >= n)
            continue;
        /* The q runs around the f run: slots first .. i and end + 1 .. last
         * (offset by count, so stepping back stays unsigned). */
        uint32_t runs = end - i, first = i + count, last = end + 1 + count;
        while (first + count - 1 > last + 1 && slots[(first - 1) % count].vertex == q)
            first--;
        while (last + 1 < first + count - runs - 1 && slots[(last + 1) % count].vertex == q)
            last++;
        uint32_t before = slots[(first - 1) % count].vertex;
        uint32_t after = slots[(last + 1) % count].vertex;
        double reach = fmax(s->tol, sew_gap(s->poly, q) + sew_gap(s->poly, f));
        const double *qp = pos + 3 * (size_t)q, *fp = pos + 3 * (size_t)f;
        if (before < n && before != q &&
            segment_distance(fp, pos + 3 * (size_t)before, qp) <= reach) {
            for (uint32_t k = 0; k < runs; k++)       /* p, q.., f.., q.. -> p, f.., q.. */
                move_slot(slots, count, (i + 1 + k) % count, (first + k) % count);
            place_on_chord(s, slots, count, first, runs, first + count - 1, first + runs);
        } else if (after < n && after != q &&
                   segment_distance(fp, qp, pos + 3 * (size_t)after) <= reach) {
            for (uint32_t k = 0; k < runs; k++)       /* q.., f.., q.., r -> q.., f.., r */
                move_slot(slots, count, (end - k) % count, (last - k) % count);
            place_on_chord(s, slots, count, last + 1 - runs, runs, last - runs, last + 1);
        }
    }
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
        unspike(s, out->slots + out->slot_count, count);
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
        unite_points(s, parent);
        unite_joins(s, parent, ins, &ins_count);
        counts->inserted = ins_count;
        st = build_loops(s, parent, ins, ins_count, out);
    }
    size_t tjunctions = 0;
    if (st == SW_OK)
        st = sew_insert_tjunctions(s, out, &tjunctions);
    counts->inserted += tjunctions;
    if (st == SW_OK)
        st = number_vertices(s, out, s->err);
    if (st == SW_OK)
        st = build_edges(out, counts, s->err);
    free(parent);
    free(ins);
    return st;
}
