/* SPDX-License-Identifier: MIT */
#include "sw_seam_cache.h"

#include <string.h>

static uint32_t units_of(uint32_t count, uint32_t unit) { return (count + unit - 1) / unit; }

size_t sw_seam_cache_arena_bytes(uint32_t surface_count, uint32_t vertices, uint32_t indices)
{
    uint32_t vu = units_of(vertices, SW_SEAM_CACHE_VERTEX_UNIT);
    uint32_t iu = units_of(indices, SW_SEAM_CACHE_INDEX_UNIT);
    size_t v = (size_t)vu * SW_SEAM_CACHE_VERTEX_UNIT, i = (size_t)iu * SW_SEAM_CACHE_INDEX_UNIT;
    return sw_arena_worst_case(((size_t)surface_count + 1) * sizeof(sw_seam_entry), 8) +
           sw_buddy_arena_bytes(vu) + sw_buddy_arena_bytes(iu) +
           sw_arena_worst_case(v * sizeof(sw_vertex), 64) +
           sw_arena_worst_case(i * sizeof(uint16_t), 64);
}

size_t sw_seam_cache_uv_bytes(uint32_t vertices)
{
    size_t v = (size_t)units_of(vertices, SW_SEAM_CACHE_VERTEX_UNIT) * SW_SEAM_CACHE_VERTEX_UNIT;
    return sw_arena_worst_case(v * 2 * sizeof(float), 64);
}

sw_status sw_seam_cache_keep_uvs(sw_seam_cache *c, sw_arena *arena, sw_error *err)
{
    if (c->uvs)
        return SW_OK;
    c->uvs = sw_arena_alloc(arena, (size_t)c->vertices * 2 * sizeof *c->uvs, 64);
    if (!c->uvs)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "tessellation cache: arena too small for "
                            "the (u, v) of %u vertices, which measuring reads",
                            (unsigned)c->vertices);
    return SW_OK;
}

sw_status sw_seam_cache_init(sw_seam_cache *c, uint32_t surface_count, uint32_t vertices,
                             uint32_t indices, sw_arena *arena, sw_error *err)
{
    memset(c, 0, sizeof *c);
    uint32_t vu = units_of(vertices, SW_SEAM_CACHE_VERTEX_UNIT);
    uint32_t iu = units_of(indices, SW_SEAM_CACHE_INDEX_UNIT);
    sw_status st = sw_buddy_init(&c->vertex_pool, vu, arena, err);
    if (st == SW_OK)
        st = sw_buddy_init(&c->index_pool, iu, arena, err);
    if (st != SW_OK)
        return st;
    c->surface_count = surface_count;
    c->vertices = vu * SW_SEAM_CACHE_VERTEX_UNIT;
    c->indices = iu * SW_SEAM_CACHE_INDEX_UNIT;
    c->entries = sw_arena_alloc(arena, ((size_t)surface_count + 1) * sizeof *c->entries, 8);
    c->verts = sw_arena_alloc(arena, (size_t)c->vertices * sizeof *c->verts, 64);
    c->index_data = sw_arena_alloc(arena, (size_t)c->indices * sizeof *c->index_data, 64);
    if (!c->entries || !c->verts || !c->index_data)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "tessellation cache: arena too small for "
                            "%u vertices and %u indices", (unsigned)c->vertices,
                            (unsigned)c->indices);
    memset(c->entries, 0, ((size_t)surface_count + 1) * sizeof *c->entries);
    return SW_OK;
}

void sw_seam_cache_drop(sw_seam_cache *c, uint32_t s)
{
    sw_seam_entry *e = &c->entries[s];
    if (e->state == SW_SEAM_READY) {
        sw_buddy_free(&c->vertex_pool, e->vertex_block);
        sw_buddy_free(&c->index_pool, e->index_block);
    }
    e->state = SW_SEAM_EMPTY;
    e->vertex_count = e->index_count = 0;
}

uint32_t sw_seam_cache_oldest(const sw_seam_cache *c, const uint8_t *evictable)
{
    uint32_t best = UINT32_MAX;
    for (uint32_t s = 0; s < c->surface_count; s++) {
        const sw_seam_entry *e = &c->entries[s];
        if (e->state == SW_SEAM_READY && evictable[s] &&
            (best == UINT32_MAX || e->last_frame < c->entries[best].last_frame))
            best = s;
    }
    return best;
}

int sw_seam_cache_place(sw_seam_cache *c, uint32_t s, uint32_t n, uint32_t m,
                        const uint8_t *evictable)
{
    sw_seam_cache_drop(c, s);
    uint32_t vu = units_of(n ? n : 1, SW_SEAM_CACHE_VERTEX_UNIT);
    uint32_t iu = units_of(m ? m : 1, SW_SEAM_CACHE_INDEX_UNIT);
    sw_seam_entry *e = &c->entries[s];
    for (;;) {
        uint32_t vb, ib;
        if (sw_buddy_alloc(&c->vertex_pool, vu, &vb)) {
            if (sw_buddy_alloc(&c->index_pool, iu, &ib)) {
                e->vertex_block = vb, e->index_block = ib;
                e->vertex_count = n, e->index_count = m;
                e->state = SW_SEAM_READY;
                return 1;
            }
            sw_buddy_free(&c->vertex_pool, vb);
        }
        uint32_t victim = sw_seam_cache_oldest(c, evictable);
        if (victim == UINT32_MAX || victim == s)
            return 0;
        sw_seam_cache_drop(c, victim);
        c->evictions++;
    }
}
