/* SPDX-License-Identifier: MIT */
/* What the runtime's walk through a pack's Seam Graph takes from its arena
 * (firmware/walk/sw_seam_walk.h): the selection's front, per-surface state, the
 * tessellation cache's pools, the trimmed tessellator's scratch and one
 * surface's output. A function of the pack alone, so the pack writer puts it
 * into the header's runtime_bytes (PACK_FORMAT.md, "runtime_bytes"), the
 * reader checks it there, and the runtime sizes its one arena from the
 * header before loading anything. No allocation. */
#ifndef SW_WALK_MEMORY_H
#define SW_WALK_MEMORY_H

#include <stdint.h>

#include "sw_pack.h"
#include "sw_seam_graph.h"

/* One surface's tessellation at most: 16-bit indices (GLES2). */
#define SW_WALK_VERTICES 65536u
#define SW_WALK_INDICES (6u * 65536u)

/* The cache's pools: vertices (16 bytes as drawn; 8 more of (u, v) in a
 * walk that measures, counted with its options: sw_seam_cache_keep_uvs)
 * and six indices a vertex (12 bytes), the same again in GL buffers. They hold the
 * meshes a frame draws, beside them the batch replacing them (a move of
 * the seam front remakes most of what is in view), stand-ins, and meshes
 * out of view kept until the room is needed: 32 vertices a patch, from
 * 2^19 (below it a courtyard's close views refused surfaces) to 2^21, a
 * multiple of 64 (whole units of both pools; the pools need not be powers
 * of two, only their blocks are). About three times the blocks the busiest
 * frames of the generated showrooms draw; at half that, surfaces coming
 * into view waited undrawn (docs/perf/2026-12-07-cache.md). The walk's
 * stats give each pool's fill (cache.pool in docs/stats.md). */
#define SW_WALK_CACHE_MIN (1u << 19)
#define SW_WALK_CACHE_MAX (1u << 21)
#define SW_WALK_CACHE_PER_PATCH 32u
uint32_t sw_walk_cache_vertices(const sw_seam_graph *g, const sw_pack_surface *surfaces);
uint32_t sw_walk_cache_vertices_for(uint64_t patches);
static inline uint32_t sw_walk_cache_indices(uint32_t vertices) { return 6u * vertices; }

/* The largest surface in loop points (slots), loops and patches, each on
 * its own: the walk's per-surface buffers hold any surface. control: the
 * most control points a surface's patches hold together where they are
 * placed as they are read (a placed pack's: sw_pack_patch_control), else
 * 0 (no room is taken for them). */
typedef struct sw_walk_sizes {
    uint32_t points, loops, patches, control;
} sw_walk_sizes;

/* g and surfaces must be validated (their indices are followed); control 0. */
sw_walk_sizes sw_walk_largest_surface(const sw_seam_graph *g, const sw_pack_surface *surfaces);

/* The most control points of one surface's patches, over surface_count
 * surfaces (validated, with their patches). */
uint32_t sw_walk_surface_control(const sw_pack_surface *surfaces, uint32_t surface_count,
                                 const sw_pack_patch *patches);

/* The largest surface of a validated pack with a Seam Graph as the walk
 * reads it: with control where its points are placed as they are read. */
sw_walk_sizes sw_walk_largest_in_pack(const sw_pack *pack);

/* Bytes of a room for m->control placed control points: 0 without. */
uint64_t sw_walk_control_bytes(const sw_walk_sizes *m);

/* Bytes of the walk, worst case (every alignment included); 0 for no graph. */
uint64_t sw_walk_arena_bytes(const sw_seam_graph *g, const sw_pack_surface *surfaces);

/* The same for the placed scene of an instanced pack (sw_pack_instances.h):
 * its prototypes placed by its instances (which must index them), whose
 * stored graph and surfaces give the largest surface; the seam front as
 * sw_seam_fronts_bytes counts it. UINT64_MAX when the placed counts do not
 * fit a graph. */
typedef struct sw_walk_placed {
    const sw_pack_prototype *prototypes;
    uint32_t prototype_count;
    const sw_pack_instance *instances;
    uint32_t instance_count;
    const sw_pack_patch *patches;     /* the prototypes' (the stored pack's) */
} sw_walk_placed;
uint64_t sw_walk_arena_bytes_placed(const sw_seam_graph *stored, const sw_pack_surface *surfaces,
                                    const sw_walk_placed *placed);

/* The same, pool by pool (each of the walk's allocations in one of them):
 * the selection's front over the Seam Graph (sw_seam_fronts.h), the
 * per-surface state, culling (the tree, the cones), the maker's buffers
 * for one surface, one surface's output, the workers' shared hand-over
 * (sw_walk_threads_bytes) and the tessellation cache's pools. */
enum { SW_WALK_POOL_SEAM_FRONT, SW_WALK_POOL_SURFACES, SW_WALK_POOL_CULL, SW_WALK_POOL_MAKER,
       SW_WALK_POOL_OUTPUT, SW_WALK_POOL_THREADS, SW_WALK_POOL_CACHE, SW_WALK_POOL_COUNT };
extern const char *const sw_walk_pool_names[SW_WALK_POOL_COUNT];
void sw_walk_pools(const sw_seam_graph *g, const sw_pack_surface *surfaces,
                   uint64_t pool[SW_WALK_POOL_COUNT]);
void sw_walk_pools_placed(const sw_seam_graph *stored, const sw_pack_surface *surfaces,
                          const sw_walk_placed *placed, uint64_t pool[SW_WALK_POOL_COUNT]);

/* Of those, the state the tessellation workers share (sw_seam_workers.h),
 * whatever their number: per surface a job (two floats), the worker's
 * result entry, its no-room flag and a publish slot (one atomic pointer),
 * and the ring of retired meshes (sw_walk_retire_capacity), over a cache
 * of cache_vertices vertices. Each worker's own buffers depend on the
 * option --workers and are counted by the runtime on top. */
uint64_t sw_walk_threads_bytes(uint32_t surface_count, uint32_t cache_vertices);

/* The ring of retired meshes: a power of two no smaller than the meshes
 * that can wait in it, two per surface at most (the drawn one and the one
 * replacing it) and no more than the vertex pool's units (a retired mesh
 * keeps its block, of a unit at least, until it is freed). */
uint32_t sw_walk_retire_capacity(uint32_t surface_count, uint32_t cache_vertices);

/* Of those: the tessellator's scratch, for its own sub-arena. */
uint64_t sw_walk_scratch_bytes(const sw_walk_sizes *m);

#endif
