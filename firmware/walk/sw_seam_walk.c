/* SPDX-License-Identifier: MIT */
#include "sw_seam_walk.h"

#include <float.h>
#include <math.h>
#include <string.h>
#include <time.h>

#include "sw_pack_instances.h"
#include "sw_seam_measure.h"
#include "sw_seam_surface.h"
#include "sw_seam_walk_internal.h"
#include "sw_surface_at.h"
#include "sw_surface_cone.h"

size_t sw_seam_walk_arena_bytes(const sw_pack *stored)
{
    sw_runtime_pools pools;
    sw_pack_runtime_pools(stored, &pools);
    uint64_t bytes = 0;
    for (int i = 0; i < SW_WALK_POOL_COUNT; i++)
        bytes += pools.walk[i];
    return (size_t)bytes;
}

static void *take(sw_arena *a, size_t bytes, int *failed)
{
    void *p = sw_arena_alloc(a, bytes + 1, 64);
    *failed |= p == NULL;
    return p;
}

/* Surface s's sewing offset, worked out the first time a thread asks for
 * it and kept in its own array (known: V's for cone culling, P's for
 * measuring; neither thread writes the other's). Done for all surfaces at
 * init it took 40% of the 40,000-patch showroom's start. room: the asking
 * thread's for s's patches; 0 when they do not fit it (they always do: it
 * is sized for the largest surface). */
float sw_seam_walk_sewing_offset(const sw_seam_walk *w, uint32_t s, float *known,
                                 const sw_trim_patch_room *room)
{
    if (known[s] >= 0)
        return known[s];
    uint32_t count = 0;
    if (sw_trim_patches_placed(w->pack, s, room, &count, NULL))
        return 0;
    return known[s] = (float)sw_seam_fronts_sewing_offset(&w->fronts, s, room->patches, count);
}

/* The per-surface state of the threaded walk (counted with the rest in
 * sw_walk_threads_bytes, taken whether or not workers start). */
static int take_thread_state(sw_seam_walk *w, sw_arena *arena, size_t n)
{
    int failed = 0;
    w->want = take(arena, n * sizeof(float), &failed);
    w->busy = take(arena, n, &failed);
    w->need_since = take(arena, n * sizeof(uint32_t), &failed);
    w->batch = take(arena, n * sizeof(uint32_t), &failed);
    w->candidates = take(arena, n * sizeof(sw_seam_candidate), &failed);
    if (failed)
        return 0;
    memset(w->busy, 0, n);
    for (size_t k = 0; k < n; k++)
        w->need_since[k] = UINT32_MAX, w->want[k] = 0;
    return 1;
}

/* Every surface's normal cone, the union of its patches' (scratch from the
 * arena, given back; placed control points in V's maker's room). */
static sw_status make_cones(sw_seam_walk *w, sw_arena *arena, sw_error *err)
{
    size_t mark = sw_arena_mark(arena);
    size_t doubles = sw_normal_cone_scratch_doubles(SW_BEZIER_MAX_DEGREE, SW_BEZIER_MAX_DEGREE);
    double *scratch = sw_arena_alloc(arena, doubles * sizeof(double), 64);
    if (!scratch)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the normal cones' "
                            "scratch (%zu bytes)", doubles * sizeof(double));
    const sw_pack *pack = w->pack;
    for (uint32_t s = 0; s < pack->seam.surface_count; s++)
        w->cones[s] = sw_surface_normal_cone(pack, s, 0, w->maker.room.control, scratch);
    sw_arena_reset_to(arena, mark);
    return SW_OK;
}

/* Each surface's floor: the largest error of the vertices its loops start
 * at, no finer than the walk's. */
static void set_floors(sw_seam_walk *w)
{
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++)
        w->floor[s] = fmaxf(w->bound_floor, sw_seam_fronts_loop_error(&w->fronts, s));
}

sw_status sw_seam_walk_init(sw_seam_walk *w, const sw_pack *pack, const sw_pack *stored,
                            sw_arena *arena, double error_px, sw_error *err)
{
    memset(w, 0, sizeof *w);
    if (!pack->seam_header)
        return sw_error_set(err, SW_ERR_ARG, "the pack has no Seam Graph (build it again with "
                            "this seamwalk-pack)");
    w->pack = pack;
    w->error_px = error_px;
    w->pressure = 1.0;
    w->pressure_raised = UINT32_MAX - 1;   /* as if two frames before the first */
    w->bound_floor = 0.1f * pack->seam.tolerance;
    w->drop_surface = UINT32_MAX;
    w->standin_silhouettes = 1;
    sw_status st = sw_seam_fronts_init(&w->fronts, stored, &pack->seam, arena, err);
    if (st != SW_OK)
        return st;
    w->largest = sw_walk_largest_in_pack(pack);
    size_t n = pack->seam.surface_count;
    int failed = 0;
    w->target = take(arena, n * sizeof(float), &failed);
    w->seam_bound = take(arena, n * sizeof(float), &failed);
    w->visible = take(arena, n, &failed);
    w->evictable = take(arena, n, &failed);
    w->dirty = take(arena, n, &failed);
    w->sew_offset = take(arena, n * sizeof(float), &failed);
    w->floor = take(arena, n * sizeof(float), &failed);
    w->depth = take(arena, n * sizeof(float), &failed);
    w->cull_near = take(arena, n * sizeof(double), &failed);
    w->cull_far = take(arena, n * sizeof(double), &failed);
    w->cones = take(arena, n * sizeof(sw_normal_cone), &failed);
    if (failed || sw_seam_maker_init(&w->maker, pack, &w->fronts, &w->largest, arena, err) ||
        !take_thread_state(w, arena, n))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the seam walk "
                            "(needs %zu bytes)", sw_seam_walk_arena_bytes(stored));
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    st = sw_cull_tree_build(&w->cull_tree, pack->surfaces, (uint32_t)n, pack->patches, arena, err);
    if (st != SW_OK)
        return st;
    w->cull_tree_ms = sw_seam_walk_ms_since(&t0);
    set_floors(w);
    for (size_t k = 0; k < n; k++)
        w->target[k] = SW_SEAM_INVISIBLE_BOUND, w->seam_bound[k] = 0, w->sew_offset[k] = -1,
        w->depth[k] = INFINITY;
    memset(w->dirty, 0, n);
    uint32_t cache = sw_walk_cache_vertices(&pack->seam, pack->surfaces);
    return sw_seam_cache_init(&w->cache, (uint32_t)n, cache, sw_walk_cache_indices(cache), arena,
                              err);
}

/* Pool b cut to units, at least 1 and at most what it has. */
static void cut(sw_buddy *b, uint64_t units)
{
    sw_buddy_shrink(b, (uint32_t)(units == 0 ? 1 : units < b->units ? units : b->units));
}

void sw_seam_walk_shrink_cache(sw_seam_walk *w, uint32_t vertices)
{
    uint64_t indices = (uint64_t)vertices * 6;
    cut(&w->cache.vertex_pool, (vertices + SW_SEAM_CACHE_VERTEX_UNIT - 1ull) /
                                   SW_SEAM_CACHE_VERTEX_UNIT);
    cut(&w->cache.index_pool, (indices + SW_SEAM_CACHE_INDEX_UNIT - 1) / SW_SEAM_CACHE_INDEX_UNIT);
}

sw_status sw_seam_walk_enable_cones(sw_seam_walk *w, sw_arena *arena, sw_error *err)
{
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    sw_status st = make_cones(w, arena, err);
    w->cones_ms = sw_seam_walk_ms_since(&t0);
    w->cone_cull = st == SW_OK;
    return st;
}

/* The level a tessellation is made for: the bound rounded down to a power
 * of sqrt 2, so it meets the bound and neighbours share levels. */
float sw_seam_walk_level_of(double bound)
{
    double k = floor(2.0 * log2(bound));
    return (float)exp2(0.5 * k);
}

/* A kept tessellation made for t still serves bound b when t <= b <= KEEP t
 * (never coarser than asked, at most KEEP times as fine). */
static int still_valid(const sw_seam_entry *e, float t, double b)
{
    return e->state != SW_SEAM_EMPTY && t <= b && b <= SW_SEAM_KEEP * t;
}

/* Surface s's target for this frame's bound (0 out of view) and its seams'
 * share; 1 when that share changed. The threaded walk's first frame asks
 * for SW_SEAM_FIRST_COARSER times the bound (the coarsest start). ahead
 * (<= bound) is the bound a few frames on (ahead_bound): a kept mesh that
 * will not serve it is made again now, for it. */
static int choose_target(sw_seam_walk *w, uint32_t s, double bound, double ahead)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (w->visible[s] == 1) {
        bound = fmax(bound, (double)w->floor[s]);
        ahead = fmin(fmax(ahead, (double)w->floor[s]), bound);
        w->want[s] = (float)bound;
        if (sw_seam_walk_coarse_start(w, 0))
            bound *= SW_SEAM_FIRST_COARSER, ahead = bound;
        if (w->no_cache)
            w->target[s] = (float)bound;
        else if (!still_valid(e, w->target[s], bound) || w->target[s] > ahead)
            w->target[s] = sw_seam_walk_level_of(ahead);
    } else if (e->state != SW_SEAM_READY && !w->busy[s]) {
        w->target[s] = SW_SEAM_INVISIBLE_BOUND;
    }
    if (sw_seam_walk_async(w))
        return 0;   /* the schedule moves the seams (sw_seam_walk_threads.c) */
    float seam = w->target[s] * (float)SW_SEAM_SHARE;
    int changed = seam != w->seam_bound[s];
    w->seam_bound[s] = seam;
    return changed;
}

/* How far past facing away a surface's cone must be, so that every
 * triangle drawn of it, whose vertices lie on the surface or its sewn
 * border, faces away as well (GL culls by the triangle's winding, not by
 * the surface's normal): 0.05 rad, about 3 degrees. */
#define SW_SEAM_CONE_MARGIN_RAD 0.05

/* Surface s, all in box, shows only its back to the eye: its box grown by
 * its border's sewing offset (the seam vertices it draws). (The offset was
 * once read from the measurement's array, -1 for a surface not measured
 * yet: such boxes shrank by one model unit.) */
static int facing_away(sw_seam_walk *w, const sw_view *view, uint32_t s, const sw_box *box)
{
    double grow = sw_seam_walk_sewing_offset(w, s, w->sew_offset, &w->maker.room);
    sw_box b = { sw_v3_sub(box->min, sw_v3(grow, grow, grow)),
                 sw_v3_add(box->max, sw_v3(grow, grow, grow)) };
    return sw_normal_cone_back_facing(&w->cones[s], &b, view->eye, SW_SEAM_CONE_MARGIN_RAD);
}

/* Out of view, with workers on their own: the bound its kept mesh would
 * need were the eye to turn to it (half a pixel at its box's distance), so
 * the schedule can bring it up to date with time left over (w', paper 004
 * section 6.4); 0 when it has no mesh or nothing would be scheduled. */
static float culled_want(const sw_seam_walk *w, const sw_view *view, uint32_t s)
{
    if (!sw_seam_walk_async(w) || w->cache.entries[s].state != SW_SEAM_READY)
        return 0;
    sw_box b = sw_cull_tree_surface_box(&w->cull_tree, s);
    sw_vec3 e = view->eye, d;
    d.x = fmax(fmax(b.min.x - e.x, 0.0), e.x - b.max.x);
    d.y = fmax(fmax(b.min.y - e.y, 0.0), e.y - b.max.y);
    d.z = fmax(fmax(b.min.z - e.z, 0.0), e.z - b.max.z);
    double bound = sw_view_error_world(view, sw_seam_walk_error_px(w),
                                       fmax(sw_v3_length(d), view->near_z));
    return (float)fmax(bound, (double)w->floor[s]);
}

/* How many frames ahead the threaded walk makes meshes for: about a
 * batch's way from scheduled to drawn. A mesh made for the bound of the
 * frame it was asked in is behind it (coarser than the view asks) by the
 * time it is drawn whenever the eye comes closer, and stays so until the
 * next; where two silhouettes meet, such a mesh left a pixel of background
 * between them. */
#define SW_SEAM_LOOKAHEAD_FRAMES 2.0

/* The bound surface s will need SW_SEAM_LOOKAHEAD_FRAMES on, were the eye
 * to keep coming closer to it as it did since the last frame (its nearest
 * depth then in w->depth), at most twice as close; the bound itself
 * without workers (each frame's meshes are made in it), when it is not
 * coming closer, or was not in view. */
static double ahead_bound(const sw_seam_walk *w, const sw_view *view, uint32_t s, double depth,
                          double bound)
{
    double last = w->depth[s];
    if (!sw_seam_walk_async(w) || !isfinite(depth) || !isfinite(last) || !(last > depth))
        return bound;
    double ahead = fmax(depth - SW_SEAM_LOOKAHEAD_FRAMES * (last - depth), 0.5 * depth);
    return sw_view_error_world(view, sw_seam_walk_error_px(w), fmax(ahead, view->near_z));
}

/* Visible when any of its patches' boxes is (the culling tree's answer,
 * w->cull_near); depth the nearest of those.
 * A visible surface whose whole box fits within its bound is too small to
 * draw: leaving it out is within the bound (the paper's vanishing patch,
 * without waiting for its loops to collapse, which takes the seams' share
 * of the bound: a few times farther). Then the target: kept while valid,
 * else the bound's level; out of view, kept while the cache holds a mesh
 * (its seams stay where they were), else as coarse as the hierarchy goes. */
static int cull_surface(sw_seam_walk *w, const sw_view *view, uint32_t s, sw_seam_frame *frame)
{
    double depth = w->cull_near[s];
    w->visible[s] = isfinite(depth);
    double bound = w->visible[s] ? sw_view_error_world(view, sw_seam_walk_error_px(w), depth)
                                 : 0.0;
    double ahead = ahead_bound(w, view, s, depth, bound);
    w->depth[s] = (float)depth;
    int away = 0;
    if (w->visible[s]) {
        sw_box all = sw_cull_tree_surface_box(&w->cull_tree, s);
        if (sw_v3_length(sw_v3_sub(all.max, all.min)) <= bound)
            w->visible[s] = SW_SEAM_WALK_TINY;
        else
            away = w->cone_cull && facing_away(w, view, s, &all);
        frame->clamped_surfaces += w->visible[s] == 1 && bound < w->floor[s];
    }
    /* A surface facing away is handled as a drawn one in all but the
     * drawing: its bound, its tessellation and its place in the cache, so
     * the seams it shares, every neighbour's mesh and so every pixel stay
     * as they are without cone culling. (Not tessellating it would save
     * more, but then its target's hysteresis and cache residency, and
     * through the seams its neighbours' meshes, would differ within the
     * bound from a walk without cone culling.) */
    int changed = choose_target(w, s, bound, ahead);
    if (!w->visible[s])
        w->want[s] = culled_want(w, view, s);
    if (away)
        w->visible[s] = SW_SEAM_WALK_AWAY, frame->cone_culled++;
    w->evictable[s] = w->visible[s] != 1 && w->visible[s] != SW_SEAM_WALK_AWAY;
    return changed;
}

/* Every surface's nearest and farthest patch box in view into w->cull_near
 * and cull_far: the tree's walk, or (w->cull_brute) every box on its own. */
static void cull_boxes(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame)
{
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    const sw_cull_view v = { view->frustum, view->eye, view->forward, view->near_z };
    sw_cull_counts c = { 0, 0 };
    if (w->cull_brute)
        sw_cull_brute(w->pack->surfaces, w->pack->seam.surface_count, w->pack->patches, &v,
                      w->cull_near, w->cull_far, &c);
    else
        sw_cull_tree_query(&w->cull_tree, &v, w->cull_near, w->cull_far, &c);
    frame->cull_box_tests = c.box_tests;
    frame->cull_depth_tests = c.depth_tests;
    frame->cull_ms = sw_seam_walk_ms_since(&t0);
}

sw_status sw_seam_walk_move_front(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err)
{
    sw_seam_update_result r;
    sw_status st = sw_seam_fronts_update(&w->fronts, w->seam_bound, &r, err);
    if (st != SW_OK)
        return st;
    frame->seam_ops = r.splits + r.collapses;
    uint32_t n = w->pack->seam.surface_count;
    for (uint32_t s = 0; s < n; s++)
        w->dirty[s] |= (uint8_t)sw_seam_fronts_surface_changed(&w->fronts, s);
    sw_seam_fronts_clear_changed(&w->fronts);
    return SW_OK;
}

/* Every surface culled, bounded and given its target, and the part
 * levels chosen: the frame's counts of them afresh. */
static int select_surfaces(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame)
{
    int changed = 0;
    frame->visible_surfaces = frame->clamped_surfaces = frame->cone_culled = 0;
    frame->covered_surfaces = 0;
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++) {
        changed |= cull_surface(w, view, s, frame);
        frame->visible_surfaces += w->visible[s] != 0;
    }
    sw_seam_walk_choose_parts(w, view, frame);
    return changed;
}

/* Selections again for a bound raised before the plan: a few steps of
 * 4 reach the pressure's most from none. */
#define SW_SEAM_PRESSURE_AHEAD_STEPS 4

sw_status sw_seam_walk_select(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame,
                              sw_error *err)
{
    memset(frame, 0, sizeof *frame);
    sw_seam_walk_take_deferred(w, frame);
    int changed = w->frame == 0;
    w->eye = view->eye;
    cull_boxes(w, view, frame);
    changed |= select_surfaces(w, view, frame);
    for (int k = 0; k < SW_SEAM_PRESSURE_AHEAD_STEPS && sw_seam_walk_pressure_ahead(w); k++)
        changed |= select_surfaces(w, view, frame);
    /* The update is complete (no operation cap) and depends on the bounds
     * alone, so with no bound changed the front already meets them: a
     * still camera, or one whose surfaces all keep their tessellations,
     * skips the pass over the whole graph. With workers (not sync_work)
     * the schedule moves the front, when no work is in flight (the batch
     * rule in the header), for the seams of the surfaces it chose. */
    sw_status st = SW_OK;
    if (changed && !sw_seam_walk_async(w))
        st = sw_seam_walk_move_front(w, frame, err);
    if (st == SW_OK && w->workers && !w->defer_schedule)
        st = sw_seam_walk_schedule(w, frame, err);
    /* The front's own count: sw_seam_select_count would walk every loop. */
    frame->active_vertices = w->fronts.active_count;
    w->frame++;
    return st;
}

/* The cache's place for a mesh made in the frame: evicting the least
 * recently drawn surfaces out of view when it does not fit. */
static int place_in_frame(void *ctx, uint32_t s, uint32_t n, uint32_t m, sw_seam_entry *e)
{
    sw_seam_walk *w = ctx;
    if (!sw_seam_cache_place(&w->cache, s, n, m, w->evictable))
        return 0;
    e->vertex_block = w->cache.entries[s].vertex_block;
    e->index_block = w->cache.entries[s].index_block;
    return 1;
}

/* Makes surface s's entry for its target from its current loops, in the
 * frame: a mesh, planned for upload, or the reason there is none. */
static void remake(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    sw_seam_cache *c = &w->cache;
    sw_seam_cache_drop(c, s);
    w->dirty[s] = 0;
    w->maker.fill = w->fill;
    uint32_t evictions = c->evictions;
    sw_seam_entry made;
    int no_room = 0;
    uint64_t tris = sw_seam_make(&w->maker, s, w->target[s], w->seam_bound[s], c, place_in_frame,
                                 w, &made, &no_room);
    frame->evicted += c->evictions - evictions;
    made.last_frame = c->entries[s].last_frame;
    c->entries[s] = made;
    if (made.state == SW_SEAM_GONE)
        return;
    frame->retessellated++;
    frame->retess_triangles += tris;
    if (made.state == SW_SEAM_READY)
        sw_seam_walk_plan_upload(w, s, plan);
}

double sw_seam_walk_ms_since(const struct timespec *a)
{
    struct timespec b;
    clock_gettime(CLOCK_MONOTONIC, &b);
    return (double)(b.tv_sec - a->tv_sec) * 1e3 + (double)(b.tv_nsec - a->tv_nsec) * 1e-6;
}

/* Surface s's mesh for this frame: remade when it has none or it no
 * longer serves (its target moved or its loops changed). */
void sw_seam_walk_refresh(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (e->state == SW_SEAM_EMPTY || e->made_bound != w->target[s] || w->dirty[s] ||
        w->no_cache) {
        struct timespec t0;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        remake(w, s, plan, frame);
        frame->tess_ms += sw_seam_walk_ms_since(&t0);
    }
}

