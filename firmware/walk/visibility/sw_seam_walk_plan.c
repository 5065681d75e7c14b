/* The seam walk's frame split in two (sw_seam_walk.h, "Threads"): the plan,
 * made on the visibility side V after the select (the meshes the frame
 * needs made or swapped in, and every surface to draw, counted), and the
 * drawing of a plan on the GL thread P (uploads, draws, measurement), which
 * reads only the plan, the mesh bytes it points at and P's own scratch. */
#include <math.h>
#include <string.h>

#include "sw_seam_depth.h"
#include "sw_seam_measure.h"
#include "sw_seam_surface.h"
#include "sw_seam_walk_internal.h"

size_t sw_seam_walk_frame_bytes(const sw_pack *pack, uint32_t workers, int fill)
{
    uint32_t n = pack->seam.surface_count;
    sw_walk_sizes m = sw_walk_largest_surface(&pack->seam, pack->surfaces);
    size_t bytes = 2 * sw_seam_plan_bytes(n) +
                   sw_arena_worst_case(((size_t)m.patches + 1) * sizeof(sw_trim_patch), 64) +
                   sw_arena_worst_case(((size_t)n + 1) * sizeof(float), 64);
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
    w->measure_max_patches = w->largest.patches;
    w->measure_patches = sw_arena_alloc(arena, ((size_t)w->largest.patches + 1) *
                                        sizeof(sw_trim_patch), 64);
    w->measure_sew_offset = sw_arena_alloc(arena, ((size_t)n + 1) * sizeof(float), 64);
    if (!w->measure_patches || !w->measure_sew_offset)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the measurement's "
                            "scratch");
    for (uint32_t s = 0; s < n; s++)
        w->measure_sew_offset[s] = -1;
    return SW_OK;
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

static void count_behind(const sw_seam_walk *w, uint32_t s, const sw_seam_entry *e,
                         sw_seam_frame *frame)
{
    double ratio = behind_ratio(w, s, e);
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
    if (e->state == SW_SEAM_EMPTY && w->standins)
        sw_seam_walk_stand_in(w, s, plan, frame);
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
    frame->triangles += e->index_count / 3 - e->fill_triangles;
    frame->fill_triangles += e->fill_triangles;
    frame->crossings += e->crossings;
    frame->capped_surfaces += e->capped;
    frame->holes_filled += e->holes_filled;
    if (w->workers)
        count_behind(w, s, e, frame);
}

/* The vertex original o shows in a stand-in for s: where o is sewn into a
 * loop of another surface drawn this frame from a mesh of the walk's own
 * (not a stand-in), the one that mesh shows (drawn, by leaf position);
 * elsewhere its highest ancestor within the seams' share of the finest
 * border that a stand-in sewn at o was announced with (w->standin_border,
 * s's own among them). Both depend on o and the stand-ins' announcements,
 * not on s, so every stand-in sewn to o shows the same vertex there; when
 * one changes, those beside it are made again
 * (sw_seam_walk_standin_announce). So a far stand-in's border is about as
 * coarse as its bound allows; at the finest level's share for all (as
 * first made), the strips were most of the stand-ins' triangles. */
static uint32_t standin_vertex(const sw_seam_walk *w, uint32_t o, uint32_t s,
                               const uint32_t *drawn)
{
    const sw_seam_graph *g = &w->pack->seam;
    const uint32_t *at = NULL;
    uint32_t count = sw_seam_select_surfaces_at(&w->select, o, &at);
    float within = w->standin_border[s];
    for (uint32_t k = 0; k < count; k++) {
        uint32_t t = at[k];
        if (t != s && w->cache.entries[t].state == SW_SEAM_READY && !w->standin[t] &&
            w->visible[t] == 1)
            return drawn[w->select.leaf_lo[o]];
        within = fminf(within, w->standin_border[t]);
    }
    within = isfinite(within) ? (float)SW_SEAM_SHARE * within : 0.0f;
    uint32_t x = o;
    while (g->vertices[x].child != SW_SEAM_NONE &&
           g->vertices[g->vertices[x].child].error <= within)
        x = g->vertices[x].child;
    return x;
}

/* What s's stand-in's loops may show: its level's error or, coarser, the
 * power of two at or below its target. Not the level's error alone: a
 * surface whose coarsest level is far finer than its bound (a plane is
 * exact at every level, so it keeps one) held the loops of every stand-in
 * beside it to that fineness, and at the far end of an orbit the strips
 * were three quarters of the triangles drawn. Not the target itself:
 * it changes every frame, and each change makes the stand-ins beside s
 * again; a power of two changes once a doubling of the distance. */
static float border_step(const sw_seam_walk *w, uint32_t s, float level_error)
{
    float target = w->target[s];
    float step = target > 0 && isfinite(target) ? exp2f(floorf(log2f(target))) : 0.0f;
    return fmaxf(level_error, step);
}

/* 1 when each outer loop of s still shows three vertices or more with its
 * originals at their highest ancestors within the seams' share of border
 * (its neighbours may hold them finer, never coarser): as the select's
 * loop walk counts them, distinct. */
static int keeps_outer_loops(const sw_seam_walk *w, uint32_t s, float border)
{
    const sw_seam_graph *g = &w->pack->seam;
    float within = (float)SW_SEAM_SHARE * border;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++) {
        if (!(g->loops[l].flags & SW_SEAM_LOOP_OUTER))
            continue;
        uint32_t seen[3], distinct = 0;
        for (uint32_t k = 0; k < g->loops[l].slot_count && distinct < 3; k++) {
            uint32_t x = g->slots[g->loops[l].first_slot + k].vertex;
            while (g->vertices[x].child != SW_SEAM_NONE &&
                   g->vertices[g->vertices[x].child].error <= within)
                x = g->vertices[x].child;
            uint32_t i = 0;
            while (i < distinct && seen[i] != x)
                i++;
            if (i == distinct)
                seen[distinct++] = x;
        }
        if (distinct < 3)
            return 0;
    }
    return 1;
}

/* The border s is announced with: the step, halved while that would leave
 * an outer loop of s with fewer than three vertices (a stand-in then has
 * nothing to draw: a small surface far off, or a thin one, would be left
 * out), down to its level's own error, where the level was made. */
static float standin_border(const sw_seam_walk *w, uint32_t s, float level_error)
{
    float border = border_step(w, s, level_error);
    for (int k = 0; k < 32 && border > level_error && !keeps_outer_loops(w, s, border); k++)
        border = fmaxf(level_error, 0.5f * border);
    return border;
}

void sw_seam_walk_standin_announce(sw_seam_walk *w, uint32_t s)
{
    uint32_t level = sw_seam_standin_level(w->pack, s, w->target[s]);
    if (level == UINT32_MAX)
        return;
    float error = w->pack->levels.levels[level].error;
    float border = standin_border(w, s, error);
    if (error == w->standin_error[s] && border == w->standin_border[s])
        return;
    w->standin_error[s] = error, w->standin_border[s] = border;
    sw_seam_walk_restitch_around(w, s);
}

/* The level s stands in with: the one announced (its neighbours were
 * joined to it; a stand-in made again keeps it, so they need not be), else
 * its target's, announced now. */
static uint32_t standin_level(sw_seam_walk *w, uint32_t s)
{
    const sw_levels *lv = &w->pack->levels;
    if (s < lv->surface_count && isfinite(w->standin_error[s]))
        for (uint32_t k = lv->surface_levels[s]; k < lv->surface_levels[s + 1]; k++)
            if (lv->levels[k].error == w->standin_error[s])
                return k;
    sw_seam_walk_standin_announce(w, s);
    return sw_seam_standin_level(w->pack, s, w->target[s]);
}

/* The front a stand-in for s is joined to, as the shown vertex of each of
 * its loops' originals (in w->mixed_shown by leaf position, read only at
 * s's slots; standin_vertex). So it meets the walk's meshes beside it, as
 * they were made from the front before a batch in flight moved it, and
 * other stand-ins, whatever levels they show; not the front alone, which
 * for a surface that was out of view is as coarse as it goes, its loops
 * mostly gone. */
static uint32_t *standin_front(sw_seam_walk *w, uint32_t s)
{
    const uint32_t *drawn = w->batch_count > 0 ? w->drawn_shown : w->select.shown;
    const sw_seam_graph *g = &w->pack->seam;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
            uint32_t o = g->slots[g->loops[l].first_slot + k].vertex;
            w->mixed_shown[w->select.leaf_lo[o]] = standin_vertex(w, o, s, drawn);
        }
    return w->mixed_shown;
}

/* No room for a stand-in: meshes out of view go, least recently drawn
 * first, in rounds of 64, 128, 256... a frame (each round sorts the cache:
 * at most log2(surfaces / 64) + 1 of them) until none is left out of view.
 * Those drawn in frames that have finished (most of them: they went out
 * of view a while ago) free their blocks at once, so the stand-in is tried
 * again now, not a frame later, in which a turn of the eye would leave
 * hundreds of surfaces undrawn. 1 when some went. */
static int make_room(sw_seam_walk *w, sw_seam_frame *frame)
{
    if (w->standin_evicted != w->frame)
        w->standin_evicted = w->frame, w->standin_evict_rounds = 0;
    if (w->standin_evict_rounds == UINT32_MAX)
        return 0;   /* nothing left out of view this frame */
    uint32_t want = 64u << (w->standin_evict_rounds < 24 ? w->standin_evict_rounds : 24);
    uint32_t gone = sw_seam_walk_evict(w, want);
    w->standin_evict_rounds = gone < want ? UINT32_MAX : w->standin_evict_rounds + 1;
    frame->evicted += gone;
    return gone > 0;
}

int sw_seam_walk_stand_in(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    uint32_t level = standin_level(w, s);
    if (level == UINT32_MAX)
        return 0;
    sw_seam_select front = w->select;
    sw_seam_entry *e = &w->cache.entries[s];
    uint32_t last = e->last_frame;
    front.shown = standin_front(w, s);
    int made = sw_seam_standin_make(w->standins, &front, s, level, &w->cache,
                                    sw_seam_workers_place, w->workers, e);
    if (!made && make_room(w, frame))
        made = sw_seam_standin_make(w->standins, &front, s, level, &w->cache,
                                    sw_seam_workers_place, w->workers, e);
    if (!made) {
        e->last_frame = last;
        return 0;   /* it waits, undrawn and counted */
    }
    /* Gone in the loops it was made in is not gone at the surface's own
     * bound: it waits, undrawn and counted, for its mesh. */
    if (e->state != SW_SEAM_READY)
        memset(e, 0, sizeof *e);
    e->last_frame = last;
    if (e->state != SW_SEAM_READY)
        return 0;
    w->standin[s] = 1;
    frame->standins_made++;
    if (w->need_since[s] == UINT32_MAX)
        w->need_since[s] = w->frame - 1;
    sw_seam_walk_plan_upload(w, s, plan);
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
    plan->depth_known = sw_seam_depth_range(w, view, &plan->nearest, &plan->farthest);
}

/* A drawn mesh (its bytes in the cache) against the exact surface, with
 * P's own scratch. */
static void measure_item(sw_seam_walk *w, const sw_seam_draw_item *it, const sw_view *view,
                         sw_stats *stats, sw_seam_error *acc)
{
    const sw_seam_cache *c = &w->cache;
    uint32_t s = it->surface, patch_count = 0;
    const sw_seam_mesh mesh = { c->verts + it->first_vertex,
                                c->uvs + 2 * (size_t)it->first_vertex,
                                c->index_data + it->first_index, it->vertex_count,
                                it->index_count };
    if (it->standin) {   /* seams as drawn, yes; its error is its level's */
        if (w->drawn)
            sw_seam_drawn_add_mesh(w->drawn, s, &mesh);
        return;
    }
    if (sw_trim_patches_from_pack(w->pack, s, w->measure_patches, w->measure_max_patches,
                                  &patch_count, NULL))
        return;
    float offset = sw_seam_walk_sewing_offset(w, s, w->measure_sew_offset, w->measure_patches,
                                              w->measure_max_patches);
    const sw_seam_exact exact = { w->measure_patches, patch_count, offset, it->depth,
                                  w->error_px, w->bound_floor };
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
