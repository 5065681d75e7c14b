/* SPDX-License-Identifier: MIT */
#include "sw_seam_make.h"

#include <math.h>
#include <string.h>

#include "sw_seam_surface.h"

static void *take(sw_arena *a, size_t bytes, int *failed)
{
    void *p = sw_arena_alloc(a, bytes + 1, 64);
    *failed |= p == NULL;
    return p;
}

/* As take: bytes + 1, 64-aligned. */
static uint64_t worst(uint64_t bytes) { return sw_arena_worst_case(bytes + 1, 64); }

uint64_t sw_seam_maker_arena_bytes(const sw_walk_sizes *m)
{
    uint64_t v = SW_WALK_VERTICES;
    return worst((m->points + 1ull) * sizeof(sw_seam_point)) +
           worst((m->points + 1ull) * sizeof(sw_trim_point)) +
           worst((m->loops + 1ull) * sizeof(uint32_t)) +
           worst((m->patches + 1ull) * sizeof(sw_trim_patch)) + worst(sw_walk_scratch_bytes(m)) +
           sw_walk_control_bytes(m) +
           2 * worst(v * 3 * sizeof(float)) + worst(v * 2 * sizeof(float)) +
           worst(v * sizeof(uint32_t)) + worst(SW_WALK_INDICES * sizeof(uint16_t));
}

sw_status sw_seam_maker_init(sw_seam_maker *k, const sw_pack *pack, const sw_seam_fronts *fronts,
                             const sw_walk_sizes *m, sw_arena *arena, sw_error *err)
{
    memset(k, 0, sizeof *k);
    k->pack = pack;
    k->fronts = fronts;
    k->max_points = m->points;
    size_t v = SW_WALK_VERTICES;
    int failed = 0;
    k->loop_points = take(arena, (m->points + 1) * sizeof(sw_seam_point), &failed);
    k->points = take(arena, (m->points + 1) * sizeof(sw_trim_point), &failed);
    k->loop_first = take(arena, (m->loops + 1) * sizeof(uint32_t), &failed);
    k->room.patches = take(arena, (m->patches + 1) * sizeof(sw_trim_patch), &failed);
    k->room.capacity = m->patches;
    size_t scratch_bytes = (size_t)sw_walk_scratch_bytes(m);
    void *scratch = take(arena, scratch_bytes, &failed);
    if (m->control) {   /* as sw_walk_control_bytes counts it */
        k->room.control = take(arena, 4 * (size_t)m->control * sizeof(float), &failed);
        k->room.control_capacity = m->control;
    }
    k->positions = take(arena, v * 3 * sizeof(float), &failed);
    k->normals = take(arena, v * 3 * sizeof(float), &failed);
    k->uvs = take(arena, v * 2 * sizeof(float), &failed);
    k->ids = take(arena, v * sizeof(uint32_t), &failed);
    k->indices = take(arena, SW_WALK_INDICES * sizeof(uint16_t), &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for a tessellation's "
                            "buffers (%llu bytes)",
                            (unsigned long long)sw_seam_maker_arena_bytes(m));
    sw_arena_init(&k->scratch, scratch, scratch_bytes);
    return SW_OK;
}

/* Tessellates surface s at bound, coarsening (x4, three times) when it
 * would need more than 65536 vertices (*capped then). */
static sw_status tessellate(sw_seam_maker *k, uint32_t s, const sw_trim_loops *loops,
                            double bound, sw_trim_tess_result *result, int *capped)
{
    uint32_t patch_count = 0;
    sw_status st = sw_trim_patches_placed(k->pack, s, &k->room, &patch_count, NULL);
    k->patch_count = st == SW_OK ? patch_count : 0;
    if (st != SW_OK)
        return st;
    sw_trim_tess_buffers out = { k->positions, k->normals, k->uvs, k->ids, k->indices,
                                 SW_WALK_VERTICES, SW_WALK_INDICES, 0, NULL, 0 };
    if (k->fill)
        out.dropped = sw_seam_fill_drop_list(k->fill, &out.dropped_capacity);
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    *capped = 0;
    for (int attempt = 0; attempt < 4; attempt++, bound *= 4.0) {
        st = sw_trim_tess(k->room.patches, patch_count, loops, bound, &opt, &k->scratch, &out,
                          result, NULL);
        if (st != SW_ERR_RANGE)
            break;
        *capped = 1;
    }
    return st;
}

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

/* Loop points the tessellator dropped and sw_seam_fill_drops gave a
 * vertex and a fan (filled), or could not (left). */
typedef struct sw_seam_drops {
    uint32_t filled, left;
} sw_seam_drops;

/* Border vertices must be their seam vertex's position bit for bit (the
 * neighbour across the seam draws the same float), and every loop point must
 * be in the mesh: each violation is a crack. With the fill, dropped points
 * are given their vertex (sw_seam_fill_drops): those it could not give one
 * are cracks. Without it, a dropped point whose triangle with its kept
 * neighbours is flat in space leaves no gap, only a T-vertex
 * (sw_trim_tess_result.dropped_flat): counted with the crossings. */
static uint32_t count_cracks(const sw_seam_maker *k, const sw_trim_tess_result *t,
                             const sw_seam_drops *drops, uint32_t *crossings)
{
    /* Dropped points given a vertex and a fan are neither. */
    uint32_t cracks = drops->filled ? drops->left : t->dropped_points - t->dropped_flat;
    *crossings += drops->filled ? 0 : t->dropped_flat;
    for (uint32_t i = 0; i < t->vertex_count; i++) {
        *crossings += k->ids[i] == SW_TRIM_CROSSING;
        if (k->ids[i] == SW_TRIM_INTERIOR || k->ids[i] == SW_TRIM_CROSSING)
            continue;
        float p[3];
        sw_seam_fronts_position(k->fronts, k->ids[i], p);
        cracks += memcmp(p, k->positions + 3 * i, 3 * sizeof(float)) != 0;
    }
    return cracks;
}

/* The maker's output into the cache's CPU pools at e's blocks. */
static void copy_out(const sw_seam_maker *k, sw_seam_cache *c, const sw_seam_entry *e)
{
    uint32_t v0 = e->vertex_block * SW_SEAM_CACHE_VERTEX_UNIT;
    uint32_t i0 = e->index_block * SW_SEAM_CACHE_INDEX_UNIT;
    for (uint32_t i = 0; i < e->vertex_count; i++) {
        sw_vertex *v = &c->verts[v0 + i];
        memcpy(v->pos, k->positions + 3 * i, sizeof v->pos);
        for (int j = 0; j < 3; j++)
            v->normal[j] = snorm8(k->normals[3 * i + j]);
        v->normal[3] = 0;
    }
    if (c->uvs)   /* kept for measuring alone */
        memcpy(c->uvs + 2 * (size_t)v0, k->uvs, 2 * sizeof(float) * e->vertex_count);
    memcpy(c->index_data + i0, k->indices, sizeof(uint16_t) * e->index_count);
}

/* One attempt at bound: tessellate (with slits cut out and touching loops
 * parted, then without the holes, when the loops cross), fans, a place in
 * the cache. SW_OK with *placed 0 when there is no room. */
static sw_status attempt(sw_seam_maker *k, uint32_t s, sw_trim_loops *loops, uint32_t *outer,
                         double bound, sw_seam_cache *c, sw_seam_place_fn place, void *ctx,
                         sw_seam_entry *e, sw_trim_tess_result *t, sw_seam_drops *drops,
                         int *placed)
{
    int capped = 0;
    sw_status st = tessellate(k, s, loops, bound, t, &capped);
    if (st == SW_ERR_FORMAT &&
        sw_seam_surface_untangle(loops, k->points, k->loop_first, outer,
                                 sw_trim_tess_shrink(k->room.patches, k->patch_count),
                                 &k->scratch) > 0) {
        e->untangled = 1;
        st = tessellate(k, s, loops, bound, t, &capped);
    }
    if (st == SW_ERR_FORMAT && *outer < loops->loop_count) {
        /* A hole's coarse polyline crosses another loop (both are within
         * the bound of where they belong, and so of each other): drawn
         * without its holes rather than not at all. */
        loops->loop_count = *outer;
        st = tessellate(k, s, loops, bound, t, &capped);
        e->holes_filled = st == SW_OK;
    }
    if (st != SW_OK)
        return st;
    e->fill_triangles = 0;
    *drops = (sw_seam_drops){ 0, 0 };
    /* The drops first: their list lies where the crossings' fill links the
     * border. */
    if (k->fill && t->dropped_points > 0) {
        sw_seam_fill_mesh m = { k->positions, k->normals, k->uvs, k->ids, k->indices,
                                t->vertex_count, t->index_count, SW_WALK_VERTICES,
                                SW_WALK_INDICES };
        uint32_t capacity = 0;
        uint32_t *listed = sw_seam_fill_drop_list(k->fill, &capacity);
        sw_seam_drop_list list = { listed, t->dropped_points < capacity ? t->dropped_points
                                                                        : capacity };
        e->fill_triangles += sw_seam_fill_drops(k->fill, loops, &list, &m, &drops->filled,
                                                &drops->left);
        drops->left += t->dropped_points - list.count;
        t->vertex_count = m.vertex_count, t->index_count = m.index_count;
    }
    if (k->fill) {
        uint32_t left = 0;
        e->fill_triangles += sw_seam_fill_crossings(k->fill, k->ids, t->vertex_count, k->indices,
                                                    &t->index_count, SW_WALK_INDICES, &left);
    }
    *placed = place(ctx, s, t->vertex_count, t->index_count, e);
    if (*placed) {
        e->vertex_count = t->vertex_count, e->index_count = t->index_count;
        e->state = SW_SEAM_READY;
        e->capped = (uint8_t)capped;
        copy_out(k, c, e);
    }
    return SW_OK;
}

uint64_t sw_seam_make(sw_seam_maker *k, uint32_t s, float bound, float seam_bound,
                      sw_seam_cache *c, sw_seam_place_fn place, void *place_ctx,
                      sw_seam_entry *e, int *no_room)
{
    memset(e, 0, sizeof *e);
    e->made_bound = bound;
    *no_room = 0;
    const sw_seam_surface_buffers buf = { k->loop_points, k->points, k->loop_first,
                                          k->max_points };
    sw_trim_loops loops;
    uint32_t outer = 0;
    if (!sw_seam_fronts_surface_loops(k->fronts, s, seam_bound, &buf, &loops, &outer)) {
        e->state = SW_SEAM_GONE;
        return 0;
    }
    /* When the cache cannot hold the mesh, the surface is drawn coarser
     * (the bound x4, up to three times) rather than not at all, and counted
     * as capped; its border stays the seams'. */
    for (int coarser = 0; coarser < 4; coarser++) {
        sw_trim_tess_result t;
        sw_seam_drops drops;
        int placed = 0;
        double b = bound * (double)(1u << (2 * coarser));
        if (attempt(k, s, &loops, &outer, b, c, place, place_ctx, e, &t, &drops, &placed) != SW_OK)
            break;
        if (placed) {
            e->error_bound = (float)t.error_bound;
            e->capped = (uint8_t)(e->capped || coarser > 0);
            uint32_t crossings = 0;
            e->cracks = count_cracks(k, &t, &drops, &crossings);
            e->crossings = crossings;
            *no_room = 0;   /* placed coarser: drawn, not retried */
            return t.index_count / 3 - e->fill_triangles;
        }
        *no_room = 1;
    }
    /* A visible surface left out is a hole: every point of its border has
     * nothing on this side, so each counts as a crack. */
    e->state = SW_SEAM_FAILED;
    e->cracks = loops.loop_first[loops.loop_count] - loops.loop_first[0];
    return 0;
}
