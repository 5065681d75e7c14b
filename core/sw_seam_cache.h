/* SPDX-License-Identifier: MIT */
/* The tessellation cache of the seam walk (paper 004 section 6.4): each
 * surface keeps its last tessellation, the bound it was made for and what
 * the tessellator proved, in fixed pools carved from the arena at start: a
 * vertex pool (positions and normals as drawn, and (u, v) for measuring)
 * and an index pool, both handed out by buddy allocators (sw_buddy.h) in
 * units of SW_SEAM_CACHE_VERTEX_UNIT vertices and SW_SEAM_CACHE_INDEX_UNIT
 * indices. The GL buffers (sw_gl_pool.h) have the same layout, so a mesh's
 * place is the same in both. When a new mesh does not fit, the least
 * recently drawn surfaces that are out of view this frame are evicted.
 * No allocation after init; no GL. */
#ifndef SW_SEAM_CACHE_H
#define SW_SEAM_CACHE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_buddy.h"
#include "sw_error.h"
#include "sw_tess.h"

/* Small units: with the whole model in view every surface holds a mesh at
 * once, most of them stand-ins of a few vertices, so the pools run out of
 * blocks before they run out of vertices (64-vertex units gave a
 * 38,614-surface scene 32,768 blocks). The bookkeeping, 10 bytes a unit,
 * is about 4% of the pools. */
#define SW_SEAM_CACHE_VERTEX_UNIT 16u
#define SW_SEAM_CACHE_INDEX_UNIT 64u

enum {
    SW_SEAM_EMPTY = 0,   /* no tessellation kept */
    SW_SEAM_READY = 1,   /* a mesh in the pools */
    SW_SEAM_FAILED = 2,  /* the tessellator refused it at made_bound (not drawn) */
    SW_SEAM_GONE = 3,    /* its outer loop vanished at made_bound (not drawn) */
};

typedef struct sw_seam_entry {
    uint32_t vertex_block, index_block;  /* first units in the pools */
    uint32_t vertex_count, index_count;
    float made_bound;        /* the bound asked for, model units */
    float error_bound;       /* what the tessellator proved (> made_bound when capped) */
    uint32_t last_frame;     /* the last frame it was drawn in */
    uint32_t cracks;         /* border vertices off their seam vertex, loop points dropped;
                                a failed surface: its border points */
    uint32_t crossings;      /* border vertices on a seam segment */
    uint32_t fill_triangles; /* of index_count / 3, the fans over crossings (sw_seam_fill.h) */
    uint8_t state, capped, holes_filled;
    uint8_t untangled;       /* drawn untangled (sw_seam_surface_untangle) */
} sw_seam_entry;

typedef struct sw_seam_cache {
    sw_seam_entry *entries;      /* surface_count */
    uint32_t surface_count;
    uint32_t vertices, indices;  /* pool capacities */
    sw_buddy vertex_pool, index_pool;
    sw_vertex *verts;            /* vertices */
    float *uvs;                  /* 2 * vertices, or NULL: kept only for measuring
                                    (sw_seam_cache_keep_uvs) */
    uint16_t *index_data;        /* indices, local to their mesh */
    uint32_t evictions;          /* since init */
} sw_seam_cache;

/* Bytes sw_seam_cache_init takes, worst case (capacities rounded up to
 * whole units). */
size_t sw_seam_cache_arena_bytes(uint32_t surface_count, uint32_t vertices, uint32_t indices);
sw_status sw_seam_cache_init(sw_seam_cache *c, uint32_t surface_count, uint32_t vertices,
                             uint32_t indices, sw_arena *arena, sw_error *err);

/* The meshes' (u, v) beside their vertices, which only measuring reads
 * (the error of what is drawn, at the parameters it was made for): a walk
 * that measures keeps them, sw_seam_cache_uv_bytes(vertices) more, taken
 * from arena; without, the cache's uvs stay NULL and no one writes them. */
size_t sw_seam_cache_uv_bytes(uint32_t vertices);
sw_status sw_seam_cache_keep_uvs(sw_seam_cache *c, sw_arena *arena, sw_error *err);

/* Room for surface s's new mesh of n vertices and m indices: its old blocks
 * are given back first, then while it does not fit the least recently drawn
 * surface with evictable[t] != 0 loses its mesh (state EMPTY). 1 with the
 * entry's blocks and counts set; 0 when it cannot fit (the entry is EMPTY). */
int sw_seam_cache_place(sw_seam_cache *c, uint32_t s, uint32_t n, uint32_t m,
                        const uint8_t *evictable);

/* The least recently drawn surface with evictable[s] != 0 holding a mesh,
 * or UINT32_MAX (the threaded walk evicts through its retire ring). */
uint32_t sw_seam_cache_oldest(const sw_seam_cache *c, const uint8_t *evictable);

/* Gives surface s's blocks back (state EMPTY). */
void sw_seam_cache_drop(sw_seam_cache *c, uint32_t s);

/* Where surface s's mesh lives (valid after a successful place). */
static inline uint32_t sw_seam_cache_first_vertex(const sw_seam_cache *c, uint32_t s)
{
    return c->entries[s].vertex_block * SW_SEAM_CACHE_VERTEX_UNIT;
}
static inline uint32_t sw_seam_cache_first_index(const sw_seam_cache *c, uint32_t s)
{
    return c->entries[s].index_block * SW_SEAM_CACHE_INDEX_UNIT;
}

#endif
