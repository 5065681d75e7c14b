/* SPDX-License-Identifier: MIT */
/* One seam front per instance over its prototype's shared graph
 * (sw_seam_fronts.h). */
#include "sw_seam_fronts.h"

#include <math.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_pack_move.h"
#include "sw_surface_at.h"

static uint64_t worst(uint64_t count, size_t size)
{
    return (uint64_t)sw_arena_worst_case((size_t)count * size, 8);
}

/* Prototype p's graph, renumbered from 0: counts only (no arrays). */
static sw_seam_graph part_counts(const sw_pack_prototype *p)
{
    const uint32_t *c = p->count;
    return (sw_seam_graph){
        .vertex_count = c[SW_SPACE_SEAM_ORIGINALS] + c[SW_SPACE_SEAM_COLLAPSES],
        .original_count = c[SW_SPACE_SEAM_ORIGINALS], .slot_count = c[SW_SPACE_SEAM_SLOTS],
        .loop_count = c[SW_SPACE_SEAM_LOOPS], .collapse_count = c[SW_SPACE_SEAM_COLLAPSES],
        .slot_ref_count = c[SW_SPACE_SEAM_SLOT_REFS], .surface_count = c[SW_SPACE_SURFACES] };
}

/* A copied graph's arrays (the edges left out: a front never reads them). */
static uint64_t graph_copy_bytes(const sw_seam_graph *g)
{
    return worst(g->vertex_count, sizeof(sw_seam_vertex)) +
           worst(g->slot_count, sizeof(sw_seam_slot)) +
           worst(g->loop_count, sizeof(sw_seam_loop)) +
           worst(g->collapse_count, sizeof(sw_seam_collapse)) + worst(g->slot_ref_count, 4) +
           worst((uint64_t)g->surface_count + 1, 4);
}

/* The per-instance layout's tables; largest: the most surfaces of a
 * prototype (the scaled bounds' scratch). */
static uint64_t table_bytes(uint64_t parts, uint64_t count, const uint64_t placed[SW_SPACE_COUNT],
                            uint64_t largest)
{
    return worst(parts, sizeof(sw_seam_part_graph)) + worst(count, sizeof(sw_seam_select)) +
           worst(count, 4) + worst(count, sizeof(double)) + 4 * worst(count + 1, 4) +
           worst(placed[SW_SPACE_SURFACES], 4) + worst(largest, 4) +
           worst(placed[SW_SPACE_SEAM_ORIGINALS], 4);
}

/* The most surfaces of one prototype. */
static uint32_t largest_surfaces(const sw_pack_prototype *prototypes, uint32_t prototype_count)
{
    uint32_t most = 0;
    for (uint32_t p = 0; p < prototype_count; p++)
        most = prototypes[p].count[SW_SPACE_SURFACES] > most
                   ? prototypes[p].count[SW_SPACE_SURFACES] : most;
    return most;
}

/* One select over a graph of these counts; SIZE_MAX when they do not fit. */
static uint64_t one_front_bytes(const uint64_t c[SW_SPACE_COUNT])
{
    uint64_t v = c[SW_SPACE_SEAM_ORIGINALS] + c[SW_SPACE_SEAM_COLLAPSES];
    if (v >= SW_SEAM_NONE || c[SW_SPACE_SEAM_SLOTS] >= SW_SEAM_NONE ||
        c[SW_SPACE_SURFACES] >= SW_SEAM_NONE)
        return SIZE_MAX;
    sw_seam_graph g = { .vertex_count = (uint32_t)v,
                        .original_count = (uint32_t)c[SW_SPACE_SEAM_ORIGINALS],
                        .slot_count = (uint32_t)c[SW_SPACE_SEAM_SLOTS],
                        .collapse_count = (uint32_t)c[SW_SPACE_SEAM_COLLAPSES],
                        .surface_count = (uint32_t)c[SW_SPACE_SURFACES] };
    return sw_seam_select_arena_bytes(&g);
}

static uint64_t per_instance_bytes(const sw_pack_prototype *prototypes, uint32_t prototype_count,
                                   const sw_pack_instance *instances, uint32_t instance_count,
                                   const uint64_t placed[SW_SPACE_COUNT])
{
    /* The largest graph: the topologies' scratch while each is built, and
     * the fronts' shared scratch. */
    sw_seam_graph largest = { 0 };
    uint64_t bytes = 0;
    for (uint32_t p = 0; p < prototype_count; p++) {
        sw_seam_graph local = part_counts(&prototypes[p]);
        bytes += graph_copy_bytes(&local) + sw_seam_topology_arena_bytes(&local);
        if (local.original_count > largest.original_count)
            largest.original_count = local.original_count;
        if (local.vertex_count > largest.vertex_count)
            largest.vertex_count = local.vertex_count;
        if (local.collapse_count > largest.collapse_count)
            largest.collapse_count = local.collapse_count;
    }
    bytes += worst(largest.original_count, 4) + sw_seam_select_scratch_bytes(&largest);
    for (uint32_t k = 0; k < instance_count; k++) {
        sw_seam_graph local = part_counts(&prototypes[instances[k].prototype]);
        bytes += sw_seam_select_front_bytes(&local);
    }
    return bytes + table_bytes(prototype_count, instance_count, placed,
                               largest_surfaces(prototypes, prototype_count));
}

size_t sw_seam_fronts_layout_bytes(const sw_pack_prototype *prototypes,
                                   uint32_t prototype_count, const sw_pack_instance *instances,
                                   uint32_t instance_count, int per_instance)
{
    uint64_t placed[SW_SPACE_COUNT];
    sw_pack_placed_counts(prototypes, instances, instance_count, placed);
    uint64_t bytes = per_instance ? per_instance_bytes(prototypes, prototype_count, instances,
                                                       instance_count, placed)
                                  : one_front_bytes(placed);
    return bytes > SIZE_MAX ? SIZE_MAX : (size_t)bytes;
}

size_t sw_seam_fronts_bytes(const sw_pack_prototype *prototypes, uint32_t prototype_count,
                            const sw_pack_instance *instances, uint32_t instance_count,
                            int *per_instance)
{
    size_t one = sw_seam_fronts_layout_bytes(prototypes, prototype_count, instances,
                                             instance_count, 0);
    size_t each = sw_seam_fronts_layout_bytes(prototypes, prototype_count, instances,
                                              instance_count, 1);
    if (per_instance)
        *per_instance = each < one;
    return each < one ? each : one;
}

size_t sw_seam_fronts_arena_bytes(const sw_pack *pack)
{
    if (!pack->seam_header)
        return 0;
    if (!pack->instances)
        return sw_seam_select_arena_bytes(&pack->seam);
    return sw_seam_fronts_bytes(pack->prototypes, pack->prototype_count, pack->instances,
                                pack->instance_count, NULL);
}

static void *take(sw_arena *arena, uint64_t count, size_t size, int *failed)
{
    void *p = sw_arena_alloc(arena, (size_t)count * size, 8);
    *failed |= p == NULL;
    return p;
}

static sw_status take_tables(sw_seam_fronts *f, const sw_pack *pack, sw_arena *arena,
                             sw_error *err)
{
    int failed = 0;
    uint64_t n = f->count;
    if (n == 1) {
        f->parts = &f->one_part, f->front = &f->one_front, f->part_of = &f->one_part_of;
        f->scale = &f->one_scale;
        f->first_surface = f->one_first[0], f->first_loop = f->one_first[1];
        f->first_original = f->one_first[2], f->first_created = f->one_first[3];
    } else {
        f->parts = take(arena, f->part_count, sizeof *f->parts, &failed);
        f->front = take(arena, n, sizeof *f->front, &failed);
        f->part_of = take(arena, n, 4, &failed);
        f->scale = take(arena, n, sizeof(double), &failed);
        f->first_surface = take(arena, n + 1, 4, &failed);
        f->first_loop = take(arena, n + 1, 4, &failed);
        f->first_original = take(arena, n + 1, 4, &failed);
        f->first_created = take(arena, n + 1, 4, &failed);
        f->instance_of = take(arena, f->placed.surface_count, 4, &failed);
        /* Instances are updated one after another: their scaled bounds
         * share one prototype's worth. */
        f->bound = take(arena, largest_surfaces(pack->prototypes, pack->prototype_count), 4,
                        &failed);
    }
    f->shown = take(arena, f->placed.original_count, 4, &failed);
    return failed ? sw_error_set(err, SW_ERR_NO_MEMORY, "seam fronts: the arena is too small "
                                 "for their tables")
                  : SW_OK;
}

/* Prototype p's graph renumbered from 0 into arena: its records moved by
 * minus its first in each space, as the expansion moves them by an
 * instance's first. */
static sw_status copy_part(const sw_pack *pack, const sw_pack_prototype *p, sw_seam_graph *out,
                           sw_arena *arena, sw_error *err)
{
    const sw_seam_graph *g = &pack->seam;
    *out = part_counts(p);
    out->tolerance = g->tolerance;
    sw_pack_move m = { .src_originals = g->original_count,
                       .dst_originals = out->original_count, .scale = 1.0 };
    const int spaces[] = { SW_SPACE_SEAM_ORIGINALS, SW_SPACE_SEAM_COLLAPSES,
                           SW_SPACE_SEAM_SLOTS,     SW_SPACE_SEAM_LOOPS,
                           SW_SPACE_SEAM_SLOT_REFS, SW_SPACE_SURFACES };
    for (size_t i = 0; i < sizeof spaces / sizeof spaces[0]; i++)
        m.shift[spaces[i]] = -(int64_t)p->first[spaces[i]];
    int failed = 0;
    sw_seam_vertex *v = take(arena, out->vertex_count, sizeof *v, &failed);
    sw_seam_slot *slots = take(arena, out->slot_count, sizeof *slots, &failed);
    sw_seam_loop *loops = take(arena, out->loop_count, sizeof *loops, &failed);
    sw_seam_collapse *c = take(arena, out->collapse_count, sizeof *c, &failed);
    uint32_t *refs = take(arena, out->slot_ref_count, 4, &failed);
    uint32_t *surface_loops = take(arena, (uint64_t)out->surface_count + 1, 4, &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam fronts: the arena is too small for "
                            "a part's graph");
    sw_pack_move_seam_vertices(&m, g->vertices + p->first[SW_SPACE_SEAM_ORIGINALS],
                               out->original_count, v);
    sw_pack_move_seam_vertices(&m, g->vertices + g->original_count +
                                       p->first[SW_SPACE_SEAM_COLLAPSES],
                               out->collapse_count, v + out->original_count);
    sw_pack_move_seam_slots(&m, g->slots + p->first[SW_SPACE_SEAM_SLOTS], out->slot_count, slots);
    sw_pack_move_seam_loops(&m, g->loops + p->first[SW_SPACE_SEAM_LOOPS], out->loop_count, loops);
    sw_pack_move_seam_collapses(&m, g->collapses + p->first[SW_SPACE_SEAM_COLLAPSES],
                                out->collapse_count, c);
    sw_pack_move_indices(&m, SW_SPACE_SEAM_SLOTS,
                         g->slot_refs + p->first[SW_SPACE_SEAM_SLOT_REFS], out->slot_ref_count,
                         refs);
    sw_pack_move_indices(&m, SW_SPACE_SEAM_LOOPS, g->surface_loops + p->first[SW_SPACE_SURFACES],
                         out->surface_count, surface_loops);
    surface_loops[out->surface_count] = out->loop_count;
    out->vertices = v, out->slots = slots, out->loops = loops, out->collapses = c;
    out->slot_refs = refs, out->surface_loops = surface_loops;
    return SW_OK;
}

/* Instance k's firsts after k - 1's, from its prototype's counts. */
static void advance(sw_seam_fronts *f, uint32_t k, const sw_seam_graph *local)
{
    f->first_surface[k + 1] = f->first_surface[k] + local->surface_count;
    f->first_loop[k + 1] = f->first_loop[k] + local->loop_count;
    f->first_original[k + 1] = f->first_original[k] + local->original_count;
    f->first_created[k + 1] = f->first_created[k] + local->collapse_count;
    for (uint32_t s = f->first_surface[k]; f->instance_of && s < f->first_surface[k + 1]; s++)
        f->instance_of[s] = k;
}

static sw_status start_front(sw_seam_fronts *f, uint32_t k, sw_arena *arena, sw_error *err)
{
    const sw_seam_part_graph *part = &f->parts[f->part_of[k]];
    advance(f, k, &part->graph);
    sw_status st = sw_seam_select_init_shared(&f->front[k], &part->topology,
                                              f->shown + f->first_original[k], &f->scratch,
                                              arena, err);
    f->active_count += f->front[k].active_count;
    return st;
}

/* The firsts' totals are the placed graph's counts. */
static sw_status check_placed(const sw_seam_fronts *f, sw_error *err)
{
    const sw_seam_graph *g = &f->placed;
    uint32_t n = f->count;
    if (f->first_surface[n] == g->surface_count && f->first_loop[n] == g->loop_count &&
        f->first_original[n] == g->original_count && f->first_created[n] == g->collapse_count)
        return SW_OK;
    return sw_error_set(err, SW_ERR_FORMAT, "seam fronts: the instances add up to %u surfaces, "
                        "%u loops, %u originals and %u collapses; the placed graph has %u, %u, "
                        "%u and %u", f->first_surface[n], f->first_loop[n], f->first_original[n],
                        f->first_created[n], g->surface_count, g->loop_count, g->original_count,
                        g->collapse_count);
}

sw_status sw_seam_fronts_init(sw_seam_fronts *f, const sw_pack *pack, const sw_seam_graph *placed,
                              sw_arena *arena, sw_error *err)
{
    int each = 0;
    if (pack->instances)
        sw_seam_fronts_bytes(pack->prototypes, pack->prototype_count, pack->instances,
                             pack->instance_count, &each);
    return sw_seam_fronts_init_layout(f, pack, placed, each, arena, err);
}

sw_status sw_seam_fronts_init_layout(sw_seam_fronts *f, const sw_pack *pack,
                                     const sw_seam_graph *placed, int each, sw_arena *arena,
                                     sw_error *err)
{
    memset(f, 0, sizeof *f);
    if (!pack->seam_header || !placed)
        return sw_error_set(err, SW_ERR_ARG, "seam fronts: the pack has no Seam Graph");
    if (each && !pack->instances)
        return sw_error_set(err, SW_ERR_ARG, "seam fronts: a front per instance of a pack "
                            "without instances");
    /* One front reads the placed graph's arrays, which the runtime's
     * expansion leaves out exactly when the fronts are per instance. */
    if (!each && placed->vertex_count > 0 && !placed->vertices)
        return sw_error_set(err, SW_ERR_ARG, "seam fronts: one front over a placed graph "
                            "without its vertices");
    f->placed = *placed;
    f->part_count = each ? pack->prototype_count : 1;
    f->count = each ? pack->instance_count : 1;
    sw_status st = take_tables(f, pack, arena, err);
    for (uint32_t p = 0; p < f->part_count && st == SW_OK; p++) {
        sw_seam_part_graph *part = &f->parts[p];
        if (each)
            st = copy_part(pack, &pack->prototypes[p], &part->graph, arena, err);
        else
            part->graph = *placed;
        if (st == SW_OK)
            st = sw_seam_topology_init(&part->topology, &part->graph, arena, err);
    }
    uint32_t vertices = 0, collapses = 0;
    for (uint32_t p = 0; p < f->part_count && st == SW_OK; p++) {
        const sw_seam_graph *pg = &f->parts[p].graph;
        vertices = pg->vertex_count > vertices ? pg->vertex_count : vertices;
        collapses = pg->collapse_count > collapses ? pg->collapse_count : collapses;
    }
    if (st == SW_OK)
        st = sw_seam_select_scratch_init(&f->scratch, vertices, collapses, arena, err);
    f->first_surface[0] = f->first_loop[0] = f->first_original[0] = f->first_created[0] = 0;
    f->instances = each ? pack->instances : NULL;
    for (uint32_t k = 0; k < f->count && st == SW_OK; k++) {
        f->part_of[k] = each ? pack->instances[k].prototype : 0;
        f->scale[k] = each ? sw_instance_scale(pack->instances[k].transform) : 1.0;
        st = start_front(f, k, arena, err);
    }
    return st == SW_OK ? check_placed(f, err) : st;
}

sw_status sw_seam_fronts_update(sw_seam_fronts *f, const float *surface_bound,
                                sw_seam_update_result *result, sw_error *err)
{
    sw_seam_update_result sum = { 0, 0, 0, 1 };
    f->active_count = 0;
    for (uint32_t k = 0; k < f->count; k++) {
        uint32_t a = f->first_surface[k], b = f->first_surface[k + 1];
        const float *bound = surface_bound + a;
        if (f->scale[k] != 1.0) {
            for (uint32_t s = a; s < b; s++)
                f->bound[s - a] = (float)(surface_bound[s] / f->scale[k]);
            bound = f->bound;
        }
        sw_seam_update_result r;
        sw_status st = sw_seam_select_update(&f->front[k], bound, 0, &r, err);
        if (st != SW_OK)
            return st;
        sum.splits += r.splits, sum.forced_splits += r.forced_splits;
        sum.collapses += r.collapses, sum.complete &= r.complete;
        f->active_count += f->front[k].active_count;
    }
    if (result)
        *result = sum;
    return SW_OK;
}

uint32_t sw_seam_fronts_instance_of(const sw_seam_fronts *f, uint32_t s)
{
    return f->instance_of ? f->instance_of[s] : 0;
}

int sw_seam_fronts_surface_changed(const sw_seam_fronts *f, uint32_t s)
{
    uint32_t k = sw_seam_fronts_instance_of(f, s);
    return sw_seam_select_surface_changed(&f->front[k], s - f->first_surface[k]);
}

void sw_seam_fronts_clear_changed(sw_seam_fronts *f)
{
    for (uint32_t k = 0; k < f->count; k++)
        sw_seam_select_clear_changed(&f->front[k]);
}

/* The k whose run [first[k], first[k + 1]) holds x (instances with an
 * empty run are passed over). */
static uint32_t run_of(const uint32_t *first, uint32_t count, uint32_t x)
{
    uint32_t lo = 0, hi = count;   /* first[lo] <= x < first[hi] */
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (first[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

uint32_t sw_seam_fronts_instance_at(const sw_seam_fronts *f, uint32_t v)
{
    if (v < f->placed.original_count)
        return run_of(f->first_original, f->count, v);
    return run_of(f->first_created, f->count, v - f->placed.original_count);
}

uint32_t sw_seam_fronts_placed(const sw_seam_fronts *f, uint32_t k, uint32_t local)
{
    uint32_t originals = f->front[k].graph.original_count;
    if (local < originals)
        return f->first_original[k] + local;
    return f->placed.original_count + f->first_created[k] + (local - originals);
}

uint32_t sw_seam_fronts_local(const sw_seam_fronts *f, uint32_t k, uint32_t placed)
{
    if (placed < f->placed.original_count)
        return placed - f->first_original[k];
    return f->front[k].graph.original_count +
           (placed - f->placed.original_count - f->first_created[k]);
}

/* Point p of instance k's prototype where the instance places it, as the
 * expansion places it (a transform that moves nothing copies). */
static void place(const sw_seam_fronts *f, uint32_t k, const float p[3], float out[3])
{
    const float *t = f->instances[k].transform;
    if (sw_instance_moves(t))
        sw_instance_place(t, p, out);
    else
        memcpy(out, p, 3 * sizeof(float));
}

int sw_seam_fronts_surface_loops(const sw_seam_fronts *f, uint32_t s, float pin,
                                 const sw_seam_surface_buffers *buf, sw_trim_loops *loops,
                                 uint32_t *outer)
{
    uint32_t k = sw_seam_fronts_instance_of(f, s);
    float local_pin = f->scale[k] != 1.0 ? (float)(pin / f->scale[k]) : pin;
    if (!sw_seam_surface_loops(&f->front[k], s - f->first_surface[k], local_pin, buf, loops,
                               outer))
        return 0;
    for (uint32_t i = 0; f->instances && i < loops->loop_first[loops->loop_count]; i++) {
        sw_trim_point *tp = &buf->points[i];
        float p[3] = { tp->p[0], tp->p[1], tp->p[2] };
        tp->id = sw_seam_fronts_placed(f, k, tp->id);
        place(f, k, p, tp->p);
    }
    return 1;
}

uint32_t sw_seam_fronts_surfaces_at(const sw_seam_fronts *f, uint32_t o,
                                    const uint32_t **surfaces, uint32_t *first)
{
    uint32_t k = sw_seam_fronts_instance_at(f, o);
    *first = f->first_surface[k];
    return sw_seam_select_surfaces_at(&f->front[k], o - f->first_original[k], surfaces);
}

uint32_t sw_seam_fronts_shown(const sw_seam_fronts *f, const uint32_t *shown, uint32_t o)
{
    uint32_t k = sw_seam_fronts_instance_at(f, o);
    const sw_seam_select *front = &f->front[k];
    uint32_t leaf = f->first_original[k] + front->leaf_lo[o - f->first_original[k]];
    return sw_seam_fronts_placed(f, k, (shown ? shown : f->shown)[leaf]);
}

void sw_seam_fronts_set_shown(const sw_seam_fronts *f, uint32_t *shown, uint32_t o, uint32_t v)
{
    uint32_t k = sw_seam_fronts_instance_at(f, o);
    uint32_t first = f->first_original[k];
    shown[first + f->front[k].leaf_lo[o - first]] = sw_seam_fronts_local(f, k, v);
}

sw_status sw_seam_fronts_loop_slots(const sw_seam_fronts *f, const uint32_t *shown, uint32_t l,
                                    float pin, sw_seam_point *points, uint32_t *slots,
                                    uint32_t capacity, uint32_t *count, int *vanished,
                                    sw_error *err)
{
    if (l >= f->placed.loop_count || !f->placed.loops)
        return sw_error_set(err, SW_ERR_RANGE, "seam fronts: loop %u of %u", (unsigned)l,
                            (unsigned)f->placed.loop_count);
    uint32_t k = sw_seam_fronts_instance_of(f, f->placed.loops[l].surface);
    sw_seam_select front = f->front[k];
    if (shown)   /* the copy's, laid out as f->shown */
        front.shown = (uint32_t *)shown + f->first_original[k];
    float local_pin = f->scale[k] != 1.0 ? (float)(pin / f->scale[k]) : pin;
    sw_status st = sw_seam_select_loop_slots(&front, l - f->first_loop[k], local_pin, points,
                                             slots, capacity, count, vanished, err);
    for (uint32_t i = 0; st == SW_OK && i < *count; i++)
        points[i].vertex = sw_seam_fronts_placed(f, k, points[i].vertex);
    return st;
}

/* Placed vertex v's instance and its vertex in the prototype's graph. */
static const sw_seam_vertex *local_vertex(const sw_seam_fronts *f, uint32_t v, uint32_t *k)
{
    *k = sw_seam_fronts_instance_at(f, v);
    const sw_seam_graph *g = &f->parts[f->part_of[*k]].graph;
    return &g->vertices[sw_seam_fronts_local(f, *k, v)];
}

void sw_seam_fronts_position(const sw_seam_fronts *f, uint32_t v, float out[3])
{
    if (!f->instances) {
        memcpy(out, f->placed.vertices[v].p, 3 * sizeof(float));
        return;
    }
    uint32_t k;
    const sw_seam_vertex *local = local_vertex(f, v, &k);
    place(f, k, local->p, out);
}

float sw_seam_fronts_error(const sw_seam_fronts *f, uint32_t v)
{
    if (!f->instances)
        return f->placed.vertices[v].error;
    uint32_t k;
    float e = local_vertex(f, v, &k)->error;
    return (float)(e * f->scale[k]);
}

uint32_t sw_seam_fronts_ancestor_within(const sw_seam_fronts *f, uint32_t v, float within)
{
    if (!f->instances) {
        const sw_seam_vertex *g = f->placed.vertices;
        while (g[v].child != SW_SEAM_NONE && g[g[v].child].error <= within)
            v = g[v].child;
        return v;
    }
    uint32_t k = sw_seam_fronts_instance_at(f, v), x = sw_seam_fronts_local(f, k, v);
    const sw_seam_vertex *g = f->parts[f->part_of[k]].graph.vertices;
    while (g[x].child != SW_SEAM_NONE && (float)(g[g[x].child].error * f->scale[k]) <= within)
        x = g[x].child;
    return sw_seam_fronts_placed(f, k, x);
}

float sw_seam_fronts_loop_error(const sw_seam_fronts *f, uint32_t s)
{
    uint32_t k = sw_seam_fronts_instance_of(f, s);
    const sw_seam_graph *g = f->instances ? &f->parts[f->part_of[k]].graph : &f->placed;
    uint32_t local = f->instances ? s - f->first_surface[k] : s;
    float worst = 0;
    for (uint32_t l = g->surface_loops[local]; l < g->surface_loops[local + 1]; l++)
        for (uint32_t i = 0; i < g->loops[l].slot_count; i++) {
            float e = g->vertices[g->slots[g->loops[l].first_slot + i].vertex].error;
            e = f->instances ? (float)(e * f->scale[k]) : e;
            worst = e > worst ? e : worst;
        }
    return worst;
}

uint32_t sw_seam_fronts_slot_vertex(const sw_seam_fronts *f, uint32_t l, uint32_t i)
{
    const sw_seam_loop *loop = &f->placed.loops[l];
    if (!f->instances)
        return f->placed.slots[loop->first_slot + i].vertex;
    uint32_t k = sw_seam_fronts_instance_of(f, loop->surface);
    const sw_seam_graph *g = &f->parts[f->part_of[k]].graph;
    const sw_seam_loop *local = &g->loops[l - f->first_loop[k]];
    return sw_seam_fronts_placed(f, k, g->slots[local->first_slot + i].vertex);
}

typedef struct placed_loop {
    const sw_seam_fronts *f;
    uint32_t k;
    const sw_seam_graph *g;
    const sw_seam_loop *loop;
} placed_loop;

/* Slot i of a prototype's loop as instance k places it. */
static void placed_point(const void *ctx, uint32_t i, sw_sewn_point *out)
{
    const placed_loop *pl = ctx;
    const sw_seam_slot *slot = &pl->g->slots[pl->loop->first_slot + i];
    const sw_seam_vertex *v = &pl->g->vertices[slot->vertex];
    place(pl->f, pl->k, v->p, out->p);
    memcpy(out->uv, slot->uv, sizeof out->uv);
    out->error = (float)(v->error * pl->f->scale[pl->k]);
}

double sw_seam_fronts_sewing_offset(const sw_seam_fronts *f, uint32_t s,
                                    const sw_trim_patch *patches, uint32_t patch_count)
{
    const sw_seam_graph *placed = &f->placed;
    double worst = 0;
    uint32_t k = sw_seam_fronts_instance_of(f, s);
    for (uint32_t l = placed->surface_loops[s]; l < placed->surface_loops[s + 1]; l++) {
        if (!f->instances) {
            worst = fmax(worst, sw_seam_sewing_offset(placed, &placed->loops[l], patches,
                                                      patch_count));
            continue;
        }
        const sw_seam_graph *g = &f->parts[f->part_of[k]].graph;
        const placed_loop pl = { f, k, g, &g->loops[l - f->first_loop[k]] };
        worst = fmax(worst, sw_seam_sewing_offset_of(pl.loop->slot_count, placed_point, &pl,
                                                     patches, patch_count));
    }
    return worst;
}
