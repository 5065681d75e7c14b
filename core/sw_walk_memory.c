/* SPDX-License-Identifier: MIT */
#include "sw_walk_memory.h"

#include "sw_arena.h"
#include "sw_cull_tree.h"
#include "sw_handoff.h"
#include "sw_normal_cone.h"
#include "sw_seam_cache.h"
#include "sw_pack_instances.h"
#include "sw_seam_fronts.h"
#include "sw_seam_select.h"
#include "sw_trim_tess.h"

sw_walk_sizes sw_walk_largest_surface(const sw_seam_graph *g, const sw_pack_surface *surfaces)
{
    sw_walk_sizes m = { 0, 0, 0, 0 };
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t points = 0, l0 = g->surface_loops[s], l1 = g->surface_loops[s + 1];
        for (uint32_t l = l0; l < l1; l++)
            points += g->loops[l].slot_count;
        m.points = points > m.points ? points : m.points;
        m.loops = l1 - l0 > m.loops ? l1 - l0 : m.loops;
        m.patches = surfaces[s].patch_count > m.patches ? surfaces[s].patch_count : m.patches;
    }
    return m;
}

uint32_t sw_walk_surface_control(const sw_pack_surface *surfaces, uint32_t surface_count,
                                 const sw_pack_patch *patches)
{
    uint64_t most = 0;
    for (uint32_t s = 0; s < surface_count; s++) {
        uint64_t points = 0;
        for (uint32_t i = 0; i < surfaces[s].patch_count; i++) {
            const sw_pack_patch *p = &patches[surfaces[s].first_patch + i];
            points += (uint64_t)(p->degree_u + 1) * (p->degree_v + 1);
        }
        most = points > most ? points : most;
    }
    return most > UINT32_MAX ? UINT32_MAX : (uint32_t)most;
}

sw_walk_sizes sw_walk_largest_in_pack(const sw_pack *pack)
{
    sw_walk_sizes m = sw_walk_largest_surface(&pack->seam, pack->surfaces);
    if (pack->control_local)
        m.control = sw_walk_surface_control(pack->surfaces, pack->seam.surface_count,
                                            pack->patches);
    return m;
}

uint64_t sw_walk_control_bytes(const sw_walk_sizes *m)
{
    return m->control ? sw_arena_worst_case(4ull * m->control * sizeof(float) + 1, 64) : 0;
}

uint32_t sw_walk_cache_vertices_for(uint64_t patches)
{
    uint64_t v = (uint64_t)SW_WALK_CACHE_PER_PATCH * patches;
    v = v < SW_WALK_CACHE_MIN ? SW_WALK_CACHE_MIN : v > SW_WALK_CACHE_MAX ? SW_WALK_CACHE_MAX : v;
    return (uint32_t)((v + 63) / 64 * 64);   /* whole units of both pools */
}

uint32_t sw_walk_cache_vertices(const sw_seam_graph *g, const sw_pack_surface *surfaces)
{
    uint64_t patches = 0;
    for (uint32_t s = 0; s < g->surface_count; s++)
        patches += surfaces[s].patch_count;
    return sw_walk_cache_vertices_for(patches);
}

uint64_t sw_walk_scratch_bytes(const sw_walk_sizes *m)
{
    return sw_trim_tess_scratch_bytes(m->patches, m->points, SW_BEZIER_MAX_DEGREE, NULL);
}

/* Each allocation as sw_seam_walk_init makes it: bytes + 1, 64-aligned. */
static uint64_t take(uint64_t bytes) { return sw_arena_worst_case(bytes + 1, 64); }

uint32_t sw_walk_retire_capacity(uint32_t surface_count, uint32_t cache_vertices)
{
    uint64_t meshes = 2ull * surface_count + 2, units = cache_vertices / SW_SEAM_CACHE_VERTEX_UNIT;
    meshes = units < meshes ? units : meshes;
    uint32_t c = 1;
    while (c < meshes)
        c *= 2;
    return c;
}

uint64_t sw_walk_threads_bytes(uint32_t surface_count, uint32_t cache_vertices)
{
    uint64_t n = surface_count + 1ull;
    /* The walk's: this frame's bound, busy, since when, the batch, the
     * candidates (a weight and a surface). */
    uint64_t walk = 3 * take(surface_count * 4ull) + take(surface_count) +
                    take(surface_count * 8ull);
    return walk + sw_arena_worst_case(n * 2 * sizeof(float), 64) +
           sw_arena_worst_case(n * sizeof(sw_seam_entry), 64) + sw_arena_worst_case(n, 64) +
           sw_arena_worst_case(n * sizeof(sw_publish_slot), 64) +
           sw_retire_ring_arena_bytes(sw_walk_retire_capacity(surface_count, cache_vertices));
}

const char *const sw_walk_pool_names[SW_WALK_POOL_COUNT] = {
    "seam front", "surface state", "culling", "mesh maker", "surface output",
    "worker hand-over", "mesh cache" };

/* The walk over a graph of g's counts (its arrays are not read), of
 * patches patches whose culling trees hold patch_nodes nodes, whose
 * largest surface is m, pool by pool. */
static void walk_pools(const sw_seam_graph *g, uint64_t patches, uint64_t patch_nodes,
                       const sw_walk_sizes *m, uint64_t pool[SW_WALK_POOL_COUNT])
{
    uint64_t n = g->surface_count, v = SW_WALK_VERTICES;
    uint32_t cache = sw_walk_cache_vertices_for(patches);
    pool[SW_WALK_POOL_SEAM_FRONT] = sw_seam_select_arena_bytes(g);
    pool[SW_WALK_POOL_SURFACES] = 5 * take(n * sizeof(float)) + 3 * take(n); /* target, seam
        bound, offset, floor, depth; visible, evictable, dirty */
    pool[SW_WALK_POOL_CULL] = 2 * take(n * sizeof(double)) +             /* cull_near, cull_far */
                              sw_cull_tree_arena_bytes((uint32_t)n, patches, patch_nodes) +
                              take(n * sizeof(sw_normal_cone)) +         /* the cones, scratch */
                              sw_arena_worst_case(sizeof(double) * sw_normal_cone_scratch_doubles(
                                                      SW_BEZIER_MAX_DEGREE, SW_BEZIER_MAX_DEGREE),
                                                  64);
    pool[SW_WALK_POOL_MAKER] = take((m->points + 1ull) * sizeof(sw_seam_point)) +
                               take((m->points + 1ull) * sizeof(sw_trim_point)) +
                               take((m->loops + 1ull) * sizeof(uint32_t)) +
                               take((m->patches + 1ull) * sizeof(sw_trim_patch)) +
                               take(sw_walk_scratch_bytes(m)) + sw_walk_control_bytes(m);
    pool[SW_WALK_POOL_OUTPUT] = 2 * take(v * 3 * sizeof(float)) + take(v * 2 * sizeof(float)) +
                                take(v * sizeof(uint32_t)) +
                                take(SW_WALK_INDICES * sizeof(uint16_t));
    pool[SW_WALK_POOL_THREADS] = sw_walk_threads_bytes((uint32_t)n, cache);
    pool[SW_WALK_POOL_CACHE] = sw_seam_cache_arena_bytes((uint32_t)n, cache,
                                                         sw_walk_cache_indices(cache));
}

static uint64_t pool_sum(const uint64_t pool[SW_WALK_POOL_COUNT])
{
    uint64_t bytes = 0;
    for (int i = 0; i < SW_WALK_POOL_COUNT; i++)
        bytes += pool[i];
    return bytes;
}

uint64_t sw_walk_arena_bytes(const sw_seam_graph *g, const sw_pack_surface *surfaces)
{
    uint64_t pool[SW_WALK_POOL_COUNT];
    sw_walk_pools(g, surfaces, pool);
    return pool_sum(pool);
}

/* A graph of the placed counts (no arrays), for the sizes alone; 0 when
 * they do not fit one. */
static int placed_graph(const uint64_t counts[SW_SPACE_COUNT], sw_seam_graph *g)
{
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        if (counts[s] >= SW_SEAM_NONE)
            return 0;
    uint64_t originals = counts[SW_SPACE_SEAM_ORIGINALS], made = counts[SW_SPACE_SEAM_COLLAPSES];
    if (originals + made >= SW_SEAM_NONE)
        return 0;
    *g = (sw_seam_graph){
        .vertex_count = (uint32_t)(originals + made), .original_count = (uint32_t)originals,
        .slot_count = (uint32_t)counts[SW_SPACE_SEAM_SLOTS],
        .loop_count = (uint32_t)counts[SW_SPACE_SEAM_LOOPS],
        .edge_count = (uint32_t)counts[SW_SPACE_SEAM_EDGES], .collapse_count = (uint32_t)made,
        .slot_ref_count = (uint32_t)counts[SW_SPACE_SEAM_SLOT_REFS],
        .surface_count = (uint32_t)counts[SW_SPACE_SURFACES] };
    return 1;
}

void sw_walk_pools_placed(const sw_seam_graph *stored, const sw_pack_surface *surfaces,
                          const sw_walk_placed *placed, uint64_t pool[SW_WALK_POOL_COUNT])
{
    sw_seam_graph g;
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(placed->prototypes, placed->instances, placed->instance_count, counts);
    for (int i = 0; i < SW_WALK_POOL_COUNT; i++)
        pool[i] = 0;
    if (!stored || counts[SW_SPACE_SURFACES] == 0 || !placed_graph(counts, &g))
        return;
    sw_walk_sizes m = sw_walk_largest_surface(stored, surfaces);
    m.control = sw_walk_surface_control(surfaces, stored->surface_count, placed->patches);
    uint64_t nodes = 0;   /* each instance's surfaces' culling trees */
    for (uint32_t k = 0; k < placed->instance_count; k++) {
        const sw_pack_prototype *p = &placed->prototypes[placed->instances[k].prototype];
        const sw_pack_surface *own = surfaces + p->first[SW_SPACE_SURFACES];
        for (uint32_t s = 0; s < p->count[SW_SPACE_SURFACES]; s++)
            nodes += sw_cull_tree_patch_nodes(own[s].patch_count);
    }
    walk_pools(&g, counts[SW_SPACE_PATCHES], nodes, &m, pool);
    pool[SW_WALK_POOL_SEAM_FRONT] =
        sw_seam_fronts_bytes(placed->prototypes, placed->prototype_count, placed->instances,
                             placed->instance_count, NULL);
}

void sw_walk_pools(const sw_seam_graph *g, const sw_pack_surface *surfaces,
                   uint64_t pool[SW_WALK_POOL_COUNT])
{
    for (int i = 0; i < SW_WALK_POOL_COUNT; i++)
        pool[i] = 0;
    if (!g || g->surface_count == 0)
        return;
    sw_walk_sizes m = sw_walk_largest_surface(g, surfaces);
    uint64_t patches = 0, nodes = 0;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        patches += surfaces[s].patch_count;
        nodes += sw_cull_tree_patch_nodes(surfaces[s].patch_count);
    }
    walk_pools(g, patches, nodes, &m, pool);
}

uint64_t sw_walk_arena_bytes_placed(const sw_seam_graph *stored, const sw_pack_surface *surfaces,
                                    const sw_walk_placed *placed)
{
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(placed->prototypes, placed->instances, placed->instance_count, counts);
    if (!stored || counts[SW_SPACE_SURFACES] == 0)
        return 0;
    sw_seam_graph g;
    if (!placed_graph(counts, &g))
        return UINT64_MAX;
    uint64_t pool[SW_WALK_POOL_COUNT];
    sw_walk_pools_placed(stored, surfaces, placed, pool);
    return pool_sum(pool);
}
