/* SPDX-License-Identifier: MIT */
/* P's half of the seam walk's frame (sw_seam_walk.h, "Threads"): a plan
 * drawn on the GL thread (uploads, draws, measurement), reading only the
 * plan, the mesh bytes it points at and P's own scratch. */
#include <math.h>

#include "sw_seam_measure.h"
#include "sw_seam_walk_internal.h"

/* A drawn mesh (its bytes in the cache) against the exact surface, with
 * P's own scratch. */
static void measure_item(sw_seam_walk *w, const sw_seam_draw_item *it, const sw_view *view,
                         sw_stats *stats, sw_seam_error *acc)
{
    const sw_seam_cache *c = &w->cache;
    uint32_t s = it->surface, patch_count = 0;
    if (it->part_level)   /* its error is its level's, measured on the host */
        return;
    const sw_seam_mesh mesh = { c->verts + it->first_vertex,
                                c->uvs ? c->uvs + 2 * (size_t)it->first_vertex : NULL,
                                c->index_data + it->first_index, it->vertex_count,
                                it->index_count };
    if (it->standin) {   /* seams as drawn, yes; its error is its level's */
        if (w->drawn)
            sw_seam_drawn_add_mesh(w->drawn, s, &mesh);
        return;
    }
    if (!mesh.uvs || sw_trim_patches_placed(w->pack, s, &w->measure, &patch_count, NULL))
        return;   /* no (u, v) kept: the program keeps them when it measures */
    float offset = sw_seam_walk_sewing_offset(w, s, w->measure_sew_offset, &w->measure);
    const sw_seam_exact exact = { w->measure.patches, patch_count, offset, it->depth,
                                  w->error_px, w->floor[s] };
    sw_seam_measure_mesh(&mesh, &exact, view, stats, acc);
    if (w->drawn)
        sw_seam_drawn_add_mesh(w->drawn, s, &mesh);
}

/* Queued, not drawn: the pool merges consecutive meshes of one colour
 * into one draw call where the GL allows (sw_gl_pool_queue), their fans
 * after all the meshes. */
static void draw_item(const sw_seam_walk *w, const sw_seam_draw_item *it, sw_renderer *r,
                      sw_gl_pool *pool)
{
    const float *rgba = w->pack->parts[it->part].color;
    if (it->part_level) {   /* a whole part, from P's resident buffers */
        /* Shared with its prototype (sw_pack_expand_shared): placed by its
         * part's transform here, the camera alone again after. */
        const float *place = w->pack->level_vertices_local
                                 ? w->pack->part_transforms + 16 * (size_t)it->part : NULL;
        if (place)
            sw_renderer_set_model(r, place);
        sw_gl_pool_draw_resident(pool, r, rgba, it->first_vertex, it->first_index,
                                 it->index_count);
        if (place)
            sw_renderer_set_model(r, NULL);
        return;
    }
    const uint16_t *idx = w->cache.index_data + it->first_index;
    uint32_t v0 = it->first_vertex, i0 = it->first_index, fill = it->fill_indices;
    uint32_t mesh = it->index_count - fill;
    sw_gl_pool_queue(pool, r, SW_GL_POOL_MESHES, rgba, v0, i0, idx, mesh);
    if (fill) /* the fans, lit as the surface (sw_renderer_set_fill) */
        sw_gl_pool_queue(pool, r, SW_GL_POOL_FANS, rgba, v0, i0 + mesh, idx + mesh, fill);
}

void sw_seam_walk_draw_plan(sw_seam_walk *w, sw_renderer *r, sw_gl_pool *pool,
                            const sw_seam_plan *plan, const sw_view *view, sw_stats *stats,
                            sw_seam_frame *frame)
{
    const sw_seam_cache *c = &w->cache;
    /* Every upload before the first draw: a glBufferSubData into a buffer
     * that queued draws read makes the driver flush them first (llvmpipe:
     * 70 uploads between draws took the teaset's frame from 80 to 300 ms). */
    uint64_t before = pool->bytes_uploaded;
    for (uint32_t k = 0; k < plan->upload_count; k++) {
        const sw_seam_upload_item *u = &plan->uploads[k];
        sw_gl_pool_upload(pool, u->first_vertex, c->verts + u->first_vertex, u->vertex_count,
                          u->first_index, c->index_data + u->first_index, u->index_count);
    }
    frame->upload_bytes += pool->bytes_uploaded - before;
    frame->failed_surfaces += plan->overflow;
    sw_seam_error acc = { 0, 0, 0 }, behind = { 0, 0, 0 };
    if (stats)
        stats->measured_frames++;
    for (uint32_t k = 0; k < plan->draw_count; k++) {
        const sw_seam_draw_item *it = &plan->draws[k];
        draw_item(w, it, r, pool);
        if (!stats)
            continue;
        struct timespec t0;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        stats->route_behind = it->late;
        measure_item(w, it, view, stats, it->late ? &behind : &acc);
        stats->route_behind = 0;
        frame->measure_ms += sw_seam_walk_ms_since(&t0);
    }
    sw_gl_pool_flush(pool, r);
    frame->error_beyond_sewing_px = acc.beyond_sewing_px;
    frame->error_behind_beyond_sewing_px = behind.beyond_sewing_px;
    frame->sewing_offset_px = fmax(acc.sewing_offset_px, behind.sewing_offset_px);
    frame->seam_chord_px = fmax(acc.chord_px, behind.chord_px);
}
