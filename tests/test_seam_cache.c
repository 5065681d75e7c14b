/* SPDX-License-Identifier: MIT */
/* The tessellation cache (core/sw_seam_cache.h) and the walk's memory
 * (core/sw_walk_memory.h):
 * - meshes get blocks that never overlap, a surface's new mesh replaces its
 *   old one, the least recently drawn evictable surface goes first, a
 *   surface marked not evictable is never evicted, and a mesh that cannot
 *   fit leaves its surface EMPTY;
 * - the pools the walk sizes for a pack hold a small mesh for every one of
 *   its surfaces at once (the whole model in view, each surface a stand-in
 *   of a few triangles): blocks are counted, not only vertices;
 * - a pack's runtime_bytes and its copy hold the loaded pack and the whole seam walk
 *   (sw_seam_walk_init), with little to spare: the figure is the memory. */
#include <stdlib.h>
#include <string.h>

#include "sw_handoff.h"
#include "sw_pack.h"
#include "sw_seam_cache.h"
#include "sw_seam_walk.h"
#include "sw_test.h"
#include "sw_walk_memory.h"

static unsigned char block[1 << 22] __attribute__((aligned(64)));

static void init(sw_seam_cache *c, sw_arena *a, uint32_t surfaces, uint32_t vertices)
{
    sw_arena_init(a, block, sizeof block);
    SW_CHECK(sw_seam_cache_init(c, surfaces, vertices, 6 * vertices, a, NULL) == SW_OK);
    SW_CHECK(a->used <= sw_seam_cache_arena_bytes(surfaces, vertices, 6 * vertices));
}

static void test_meshes_get_their_own_blocks(void)
{
    sw_arena a;
    sw_seam_cache c;
    init(&c, &a, 4, 1024);
    uint8_t evictable[4] = { 1, 1, 1, 1 };
    SW_CHECK(sw_seam_cache_place(&c, 0, 300, 900, evictable));
    SW_CHECK(sw_seam_cache_place(&c, 1, 100, 300, evictable));
    uint32_t v0 = sw_seam_cache_first_vertex(&c, 0), v1 = sw_seam_cache_first_vertex(&c, 1);
    SW_CHECK(v0 + 300 <= v1 || v1 + 100 <= v0);
    SW_CHECK(c.entries[0].state == SW_SEAM_READY && c.entries[0].vertex_count == 300);
    /* A new mesh for surface 1 gives its old blocks back first. */
    SW_CHECK(sw_seam_cache_place(&c, 1, 200, 600, evictable));
    SW_CHECK(c.evictions == 0 && c.entries[0].state == SW_SEAM_READY);
    sw_seam_cache_drop(&c, 1);
    SW_CHECK(c.entries[1].state == SW_SEAM_EMPTY);
    SW_CHECK(c.vertex_pool.used_units == 512 / SW_SEAM_CACHE_VERTEX_UNIT);
}

static void test_least_recently_drawn_goes_first(void)
{
    sw_arena a;
    sw_seam_cache c;
    init(&c, &a, 4, 1024);
    uint8_t evictable[4] = { 1, 1, 1, 1 };
    for (uint32_t s = 0; s < 4; s++) {
        SW_CHECK(sw_seam_cache_place(&c, s, 256, 256, evictable));
        c.entries[s].last_frame = 10 - s; /* 3 was drawn longest ago */
    }
    SW_CHECK(sw_seam_cache_place(&c, 0, 256 + 64, 256, evictable)); /* needs a block of 512 */
    SW_CHECK(c.evictions >= 1 && c.entries[0].state == SW_SEAM_READY);
    /* 3 and 2 are the oldest; surface 0's old block was its own */
    SW_CHECK(c.entries[3].state == SW_SEAM_EMPTY);
    SW_CHECK(c.entries[1].state == SW_SEAM_READY);
}

static void test_surfaces_in_view_are_never_evicted(void)
{
    sw_arena a;
    sw_seam_cache c;
    init(&c, &a, 3, 512);
    uint8_t all[3] = { 1, 1, 1 }, none[3] = { 0, 0, 0 };
    SW_CHECK(sw_seam_cache_place(&c, 0, 256, 256, all));
    SW_CHECK(sw_seam_cache_place(&c, 1, 256, 256, all));
    SW_CHECK(!sw_seam_cache_place(&c, 2, 256, 256, none));
    SW_CHECK(c.entries[2].state == SW_SEAM_EMPTY && c.evictions == 0);
    SW_CHECK(c.entries[0].state == SW_SEAM_READY && c.entries[1].state == SW_SEAM_READY);
    SW_CHECK(!sw_seam_cache_place(&c, 2, 5000, 256, all)); /* larger than the pool */
    SW_CHECK(c.entries[2].state == SW_SEAM_EMPTY);
}

/* 40,000 one-patch surfaces (the courtyard of walk_bench), each with a
 * mesh of 16 vertices and 16 triangles, none evictable: all fit in the
 * pools sw_walk_cache_vertices gives. With blocks of 64 vertices the pools
 * had 32,768 blocks, and at the far end of an orbit thousands of surfaces
 * in view were left undrawn. */
static void test_every_surface_fits_at_once(void)
{
    enum { SURFACES = 40000 };
    sw_pack_surface *surfaces = calloc(SURFACES, sizeof *surfaces);
    uint8_t *none = calloc(SURFACES, 1);
    sw_seam_graph g = { .surface_count = SURFACES };
    for (uint32_t s = 0; surfaces && s < SURFACES; s++)
        surfaces[s].patch_count = 1;
    uint32_t v = surfaces ? sw_walk_cache_vertices(&g, surfaces) : 0;
    size_t bytes = sw_seam_cache_arena_bytes(SURFACES, v, sw_walk_cache_indices(v));
    void *mem = malloc(bytes);
    SW_CHECK(surfaces && none && mem);
    if (surfaces && none && mem) {
        sw_arena a;
        sw_seam_cache c;
        sw_arena_init(&a, mem, bytes);
        SW_CHECK(sw_seam_cache_init(&c, SURFACES, v, sw_walk_cache_indices(v), &a, NULL) == SW_OK);
        uint32_t placed = 0;
        for (uint32_t s = 0; s < SURFACES; s++)
            placed += (uint32_t)sw_seam_cache_place(&c, s, 16, 48, none);
        SW_CHECK_MSG(placed == SURFACES, "%u of %u surfaces placed in %u vertices", placed,
                     (unsigned)SURFACES, v);
        SW_CHECK(c.evictions == 0);
    }
    free(mem);
    free(none);
    free(surfaces);
}

/* The pools' size: 32 vertices a patch within 2^19 .. 2^21, whole units of
 * both pools, six indices a vertex. */
static void test_cache_size_follows_the_patches(void)
{
    const uint64_t patches[5] = { 0, 1000, 40000, 40066, 400000 };
    const uint32_t want[5] = { 1u << 19, 1u << 19, 1280000, 1282112, 1u << 21 };
    for (int i = 0; i < 5; i++) {
        uint32_t v = sw_walk_cache_vertices_for(patches[i]);
        SW_CHECK_MSG(v == want[i], "%llu patches: %u vertices, expected %u",
                     (unsigned long long)patches[i], v, want[i]);
        SW_CHECK(v % SW_SEAM_CACHE_VERTEX_UNIT == 0 &&
                 sw_walk_cache_indices(v) % SW_SEAM_CACHE_INDEX_UNIT == 0);
    }
}

/* The retire ring holds every mesh that can wait in it: with more
 * surfaces than the vertex pool has units, as many as it has units (each
 * waiting mesh keeps its block), the smallest meshes all retired at once. */
static void test_retire_ring_holds_every_block(void)
{
    sw_seam_cache c;
    sw_arena a;
    uint32_t surfaces = 1000, vertices = 1024;
    init(&c, &a, surfaces, vertices);
    uint32_t capacity = sw_walk_retire_capacity(surfaces, vertices);
    SW_CHECK_MSG(capacity == vertices / SW_SEAM_CACHE_VERTEX_UNIT, "capacity %u", capacity);
    SW_CHECK(sw_walk_retire_capacity(10, vertices) == 32);   /* two a surface, and 2 */
    sw_retire_ring r;
    SW_CHECK(sw_retire_ring_init(&r, capacity, &a, NULL) == SW_OK);
    uint32_t vb, ib, meshes = 0, refused = 0;
    while (sw_buddy_alloc(&c.vertex_pool, 1, &vb)) {
        SW_CHECK(sw_buddy_alloc(&c.index_pool, 1, &ib));
        refused += !sw_retire_ring_put(&r, (sw_retired){ vb, ib, 1 });
        meshes++;
    }
    SW_CHECK_MSG(meshes == capacity && refused == 0, "%u meshes, %u refused", meshes, refused);
}

/* The fuzz seed with a Seam Graph: copied into an arena of exactly its
 * runtime_bytes and the copy's sw_pack_arena_bytes, and walked there. */
static void test_runtime_bytes_hold_pack_and_walk(const char *seed)
{
    sw_pack_header h;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_read_header(seed, &h, &err) == SW_OK, "%s", err.message);
    size_t size = (size_t)(h.runtime_bytes + sw_pack_arena_bytes(h.total_size));
    unsigned char *mem = malloc(size);
    SW_CHECK(mem != NULL);
    if (!mem)
        return;
    sw_arena a;
    sw_arena_init(&a, mem, size);
    sw_pack pack;
    SW_CHECK_MSG(sw_pack_load(seed, &a, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.seam_header != NULL);
    sw_seam_walk w;
    SW_CHECK_MSG(sw_seam_walk_init(&w, &pack, &pack, &a, 0.5, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(sw_seam_walk_enable_cones(&w, &a, &err) == SW_OK, "%s", err.message);
    uint64_t walk = sw_walk_arena_bytes(&pack.seam, pack.surfaces);
    /* Against the high-water mark, cones made: the walk gives back its
     * start-up scratch (the culling tree's surface list, the normal
     * cones'), which the arena must still have held. */
    SW_CHECK(a.peak <= size);
    SW_CHECK_MSG(size - a.peak < 16384 && walk > (uint64_t)SW_WALK_CACHE_MIN * 16,
                 "arena %zu, peak %zu, walk %llu", size, a.peak, (unsigned long long)walk);
    free(mem);
}

int main(int argc, char **argv)
{
    SW_RUN(test_meshes_get_their_own_blocks);
    SW_RUN(test_least_recently_drawn_goes_first);
    SW_RUN(test_surfaces_in_view_are_never_evicted);
    SW_RUN(test_every_surface_fits_at_once);
    SW_RUN(test_cache_size_follows_the_patches);
    SW_RUN(test_retire_ring_holds_every_block);
    if (argc == 2)
        test_runtime_bytes_hold_pack_and_walk(argv[1]);
    else
        SW_CHECK_MSG(0, "usage: test_seam_cache SEED_WITH_SEAM_GRAPH");
    return sw_test_finish();
}
