/* SPDX-License-Identifier: MIT */
/* V's half of the seam walk's frame (sw_seam_walk.h, "Threads"): the plan,
 * made after the select: the meshes the frame needs made or swapped in,
 * and every surface to draw, counted. The GL thread P draws it
 * (gl/sw_seam_walk_draw.c); stand-ins are made in sw_seam_walk_standins.c. */
#include <math.h>

#include "sw_seam_depth.h"
#include "sw_seam_walk_internal.h"

size_t sw_seam_walk_frame_bytes(const sw_pack *pack, uint32_t workers, int fill)
{
    uint32_t n = pack->seam.surface_count;
    sw_walk_sizes m = sw_walk_largest_in_pack(pack);
    size_t pieces = (size_t)pack->part_levels.piece_count + 1;
    size_t parts = (size_t)pack->meta->part_count + 1;
    size_t bytes = 2 * sw_seam_plan_bytes(n) +
                   sw_arena_worst_case(((size_t)m.patches + 1) * sizeof(sw_trim_patch), 64) +
                   (size_t)sw_walk_control_bytes(&m) +
                   sw_arena_worst_case(((size_t)n + 1) * sizeof(float), 64) +
                   2 * sw_arena_worst_case(pieces * sizeof(uint32_t), 64) +
                   sw_arena_worst_case(pieces * sizeof(double), 64) +
                   sw_arena_worst_case(parts * sizeof(uint32_t), 64);
    return workers ? bytes + sw_seam_walk_worker_bytes(pack, workers, fill) : bytes;
}

sw_status sw_seam_walk_init_frames(sw_seam_walk *w, sw_seam_plan plans[2], sw_arena *arena,
                                   sw_error *err)
{
    uint32_t n = w->pack->seam.surface_count;
    for (int k = 0; k < 2; k++) {
        sw_status st = sw_seam_plan_init(&plans[k], n, arena, err);
        if (st != SW_OK)
            return st;
    }
    const sw_walk_sizes *m = &w->largest;
    w->measure = (sw_trim_patch_room){
        sw_arena_alloc(arena, ((size_t)m->patches + 1) * sizeof(sw_trim_patch), 64), m->patches,
        m->control ? sw_arena_alloc(arena, 4 * (size_t)m->control * sizeof(float) + 1, 64) : NULL,
        m->control };
    w->measure_sew_offset = sw_arena_alloc(arena, ((size_t)n + 1) * sizeof(float), 64);
    if (!w->measure.patches || !w->measure_sew_offset || (m->control && !w->measure.control))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the measurement's "
                            "scratch");
    for (uint32_t s = 0; s < n; s++)
        w->measure_sew_offset[s] = -1;
    return sw_seam_walk_init_parts(w, arena, err);
}

void sw_seam_walk_plan_upload(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan)
{
    const sw_seam_cache *c = &w->cache;
    sw_seam_entry *e = &w->cache.entries[s];
    /* P reads the blocks to upload them, drawn or not: a mesh that came in
     * for a surface gone out of view would otherwise keep an old epoch and
     * be freed, and written over, while P still uploads it. */
    e->last_frame = w->frame;
    sw_seam_plan_upload(plan, sw_seam_cache_first_vertex(c, s), e->vertex_count,
                        sw_seam_cache_first_index(c, s), e->index_count);
}

/* How far a drawn mesh is behind the view (threaded walk): coarser than
 * the view asks, and for how many frames. */
static double behind_ratio(const sw_seam_walk *w, uint32_t s, const sw_seam_entry *e)
{
    double want = w->want[s] > 0 ? w->want[s] : e->made_bound;
    return e->made_bound / want;
}

void sw_seam_walk_count_behind(const sw_seam_walk *w, uint32_t s, double ratio,
                               sw_seam_frame *frame)
{
    if (ratio > 1) {
        frame->behind_surfaces++;
        frame->behind_ratio = fmax(frame->behind_ratio, ratio);
    }
    if (w->need_since[s] != UINT32_MAX && w->frame - 1 - w->need_since[s] > frame->frames_behind)
        frame->frames_behind = w->frame - 1 - w->need_since[s];
}

/* Surface s (visible) into the plan from its cache entry, counted: drawn,
 * or why not. */
static void plan_surface(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    sw_seam_entry *e = &w->cache.entries[s];
    if (e->state == SW_SEAM_GONE) {
        frame->vanished_surfaces++;
        return;
    }
    if (e->state == SW_SEAM_EMPTY && w->standins &&
        sw_seam_walk_stand_in(w, s, plan, frame) == SW_SEAM_WALK_MET)
        return;
    if (e->state == SW_SEAM_GONE) {
        frame->vanished_surfaces++;
        return;
    }
    frame->cracks += e->cracks;
    if (e->state == SW_SEAM_EMPTY && w->workers) {
        frame->waiting_surfaces++;   /* its first mesh is not made yet */
        return;
    }
    if (e->state != SW_SEAM_READY) {
        frame->failed_surfaces++;
        return;
    }
    const sw_seam_draw_item item = {
        .surface = s, .part = w->pack->surfaces[s].part,
        .first_vertex = sw_seam_cache_first_vertex(&w->cache, s),
        .first_index = sw_seam_cache_first_index(&w->cache, s),
        .vertex_count = e->vertex_count, .index_count = e->index_count,
        .fill_indices = 3 * e->fill_triangles, .depth = w->depth[s],
        /* A mesh drawn coarser than asked while its new one is made is
         * measured apart (stats error_px_behind): error_px is then the
         * error of meshes made for their bounds. */
        .late = w->workers && behind_ratio(w, s, e) > 1,
        .standin = w->standins && w->standin[s],
    };
    frame->standins += item.standin;
    frame->standin_triangles += item.standin ? e->index_count / 3 : 0;
    sw_seam_plan_draw(plan, &item);
    e->last_frame = w->frame;   /* the epoch its blocks stay in use until (sw_handoff.h) */
    frame->drawn_surfaces++;
    frame->cache_drawn_vertices += (uint64_t)SW_SEAM_CACHE_VERTEX_UNIT *
                                   sw_buddy_block_units(&w->cache.vertex_pool, e->vertex_block);
    frame->cache_drawn_indices += (uint64_t)SW_SEAM_CACHE_INDEX_UNIT *
                                  sw_buddy_block_units(&w->cache.index_pool, e->index_block);
    frame->triangles += e->index_count / 3 - e->fill_triangles;
    frame->fill_triangles += e->fill_triangles;
    frame->crossings += e->crossings;
    frame->capped_surfaces += e->capped;
    frame->holes_filled += e->holes_filled;
    frame->untangled += e->untangled;
    if (w->workers)
        sw_seam_walk_count_behind(w, s, behind_ratio(w, s, e), frame);
}

#define SW_SQRT2 1.4142135623730951

void sw_seam_walk_pressure(sw_seam_walk *w, sw_seam_frame *frame)
{
    double vertices = (double)w->cache.vertex_pool.units * SW_SEAM_CACHE_VERTEX_UNIT;
    double indices = (double)w->cache.index_pool.units * SW_SEAM_CACHE_INDEX_UNIT;
    double drawn = fmax((double)frame->cache_drawn_vertices / vertices,
                        (double)frame->cache_drawn_indices / indices);
    double used = fmax((double)frame->cache_used_vertices / vertices,
                       (double)frame->cache_used_indices / indices);
    /* Drawn by meshes and stand-ins, not through part levels. */
    uint32_t meshes = frame->drawn_surfaces - frame->covered_surfaces;
    if (frame->waiting_surfaces > 0 && used > 15.0 / 16.0 &&
        (drawn > 0.5 || (uint64_t)frame->waiting_surfaces * 64 > meshes)) {
        w->pressure_calm = 0;
        /* A mesh's vertices go about as 1 / bound: raised by the share of
         * the view that waited, so the first frame of a view far larger
         * than the cache needs a few rises, not dozens. */
        double step = frame->standins ? (double)(frame->standins + frame->waiting_surfaces) /
                                            frame->standins
                                      : 4.0;
        step = fmin(fmax(step, SW_SQRT2), 4.0);
        if (w->pressure < SW_SEAM_PRESSURE_MAX && w->frame - w->pressure_raised >= 2) {
            w->pressure = fmin(w->pressure * step, SW_SEAM_PRESSURE_MAX);
            w->pressure_raised = w->frame;
        }
        return;
    }
    if (w->pressure > 1.0 && frame->waiting_surfaces == 0 && drawn < 1.0 / 3.0 &&
        ++w->pressure_calm >= 16) {
        w->pressure = fmax(w->pressure / SW_SQRT2, 1.0);
        w->pressure_calm = 0;
    }
    else if (frame->waiting_surfaces > 0 || drawn >= 1.0 / 3.0)
        w->pressure_calm = 0;
}

/* Units of a block holding count items of unit each, as the buddy hands
 * it out. */
static uint64_t block_units(uint64_t count, uint32_t unit)
{
    return 1ull << sw_buddy_order_of((count + unit - 1) / unit);
}

int sw_seam_walk_pressure_ahead(sw_seam_walk *w)
{
    if (!sw_seam_walk_async(w) || !w->standins || w->no_pressure ||
        w->pressure >= SW_SEAM_PRESSURE_MAX)
        return 0;
    uint64_t vertex_units = 0, index_units = 0;
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++) {
        if (w->visible[s] != 1)
            continue;
        uint32_t level = sw_seam_standin_level(w->pack, s, w->target[s], 0), n = 1, m = 1;
        if (level != UINT32_MAX)
            sw_seam_standin_estimate(w->pack, s, level, &n, &m);
        vertex_units += block_units(n, SW_SEAM_CACHE_VERTEX_UNIT);
        index_units += block_units(m, SW_SEAM_CACHE_INDEX_UNIT);
    }
    double over = fmax((double)vertex_units / w->cache.vertex_pool.units,
                       (double)index_units / w->cache.index_pool.units);
    if (over <= 0.5)
        return 0;
    double step = fmin(fmax(over / 0.375, SW_SQRT2), 4.0);
    w->pressure = fmin(w->pressure * step, SW_SEAM_PRESSURE_MAX);
    w->pressure_raised = w->frame;
    w->pressure_calm = 0;
    return 1;
}

void sw_seam_walk_plan(sw_seam_walk *w, const sw_view *view, sw_seam_plan *plan,
                       sw_seam_frame *frame)
{
    uint32_t n = w->pack->seam.surface_count;
    plan->view = *view;
    if (w->workers) {
        sw_seam_walk_commit(w, plan, frame);
        sw_seam_walk_restitch(w, plan, frame);
    }
    else
        for (uint32_t s = 0; s < n; s++)
            if (sw_seam_walk_needs_mesh(w, s))
                sw_seam_walk_refresh(w, s, plan, frame);
    for (uint32_t s = 0; s < n; s++) {
        if (w->visible[s] == SW_SEAM_WALK_TINY)
            frame->vanished_surfaces++;
        if (w->visible[s] == SW_SEAM_WALK_AWAY) /* as if drawn, for the cache's order */
            w->cache.entries[s].last_frame = w->frame;
        if (w->visible[s] == 1 && s != w->drop_surface)
            plan_surface(w, s, plan, frame);
    }
    sw_seam_walk_plan_parts(w, plan, frame);
    uint32_t vertex_units, index_units;
    if (w->workers)   /* the workers place meshes meanwhile */
        sw_seam_workers_pool_use(w->workers, &vertex_units, &index_units);
    else
        vertex_units = w->cache.vertex_pool.used_units,
        index_units = w->cache.index_pool.used_units;
    frame->cache_used_vertices = (uint64_t)SW_SEAM_CACHE_VERTEX_UNIT * vertex_units;
    frame->cache_used_indices = (uint64_t)SW_SEAM_CACHE_INDEX_UNIT * index_units;
    if (w->workers && !w->sync_work) {   /* sync_work's frames wait for their meshes */
        sw_seam_walk_keep_room(w, vertex_units, index_units, frame);
        if (!w->no_pressure)
            sw_seam_walk_pressure(w, frame);
    }
    frame->pressure = w->pressure;
    plan->depth_known = sw_seam_depth_range(w, view, &plan->nearest, &plan->farthest);
}
