/* SPDX-License-Identifier: MIT */
/* The threaded side of the seam walk (sw_seam_walk.h, "Threads"): which
 * surfaces get work and in what order, the batch that makes them from one
 * seam state, and the swap that shows the batch whole. Runs on the walk's
 * visibility side V (its own thread, or the GL thread's when there is
 * none); the workers only see jobs[s] and publish made[s], the GL thread
 * only the plans (sw_seam_plan.h) and sw_seam_walk_finished. */
#include <math.h>
#include <sched.h>
#include <string.h>

#include "sw_seam_surface.h"
#include "sw_seam_walk_internal.h"

/* The stand-ins' state (with a pack that has static levels). */
static size_t standin_bytes(const sw_pack *pack)
{
    if (pack->levels.level_count == 0)
        return 0;
    size_t n = (size_t)pack->seam.surface_count + 1;
    return sw_arena_worst_case(sizeof(sw_seam_standin), 64) + sw_seam_standin_bytes(pack) +
           2 * sw_arena_worst_case(n, 64) + 2 * sw_arena_worst_case(n * sizeof(float), 64) +
           2 * sw_arena_worst_case(((size_t)pack->seam.original_count + 1) * sizeof(uint32_t), 64);
}

size_t sw_seam_walk_worker_bytes(const sw_pack *pack, uint32_t count, int fill)
{
    sw_walk_sizes m = sw_walk_largest_in_pack(pack);
    return sw_arena_worst_case(sizeof(sw_seam_workers), 64) +
           (size_t)count * (size_t)sw_seam_worker_bytes(&m, fill) + standin_bytes(pack);
}

static sw_status start_standins(sw_seam_walk *w, sw_arena *arena, sw_error *err)
{
    const sw_pack *pack = w->pack;
    if (pack->levels.level_count == 0 || w->no_standins)
        return SW_OK;
    size_t n = (size_t)pack->seam.surface_count + 1;
    sw_seam_standin *m = sw_arena_alloc(arena, sizeof *m, 64);
    w->standin = sw_arena_alloc(arena, n, 64);
    w->restitch = sw_arena_alloc(arena, n, 64);
    w->standin_error = sw_arena_alloc(arena, n * sizeof(float), 64);
    w->standin_border = sw_arena_alloc(arena, n * sizeof(float), 64);
    w->drawn_shown = sw_arena_alloc(arena, ((size_t)pack->seam.original_count + 1) *
                                           sizeof(uint32_t), 64);
    w->mixed_shown = sw_arena_alloc(arena, ((size_t)pack->seam.original_count + 1) *
                                           sizeof(uint32_t), 64);
    if (!m || !w->standin || !w->restitch || !w->standin_error || !w->standin_border ||
        !w->drawn_shown ||
        !w->mixed_shown)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the stand-ins");
    memset(w->standin, 0, n);
    for (size_t s = 0; s < n; s++)
        w->standin_error[s] = w->standin_border[s] = INFINITY;
    memset(w->restitch, 0, n);
    sw_status st = sw_seam_standin_init(m, pack, arena, err);
    if (st == SW_OK)
        w->standins = m;
    return st;
}

sw_status sw_seam_walk_start_workers(sw_seam_walk *w, uint32_t count, double target_ms,
                                     sw_arena *shared, sw_arena *arena, sw_error *err)
{
    sw_seam_workers *p = sw_arena_alloc(arena, sizeof *p, 64);
    if (!p)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the workers");
    sw_status st = sw_seam_workers_init(p, count, w->pack, &w->fronts, &w->cache, &w->largest,
                                        w->fill != NULL, shared, arena, err);
    if (st == SW_OK)
        st = start_standins(w, arena, err);
    if (st != SW_OK) {
        sw_seam_workers_stop(p);
        return st;
    }
    w->workers = p;
    sw_seam_budget_init(&w->budget, target_ms);
    return SW_OK;
}

void sw_seam_walk_stop_workers(sw_seam_walk *w)
{
    if (w->workers)
        sw_seam_workers_stop(w->workers);
    w->workers = NULL;
}

void sw_seam_walk_stall_workers(sw_seam_walk *w, int stalled)
{
    if (w->workers)
        atomic_store_explicit(&w->workers->stall, stalled, memory_order_release);
}

void sw_seam_walk_slow_workers(sw_seam_walk *w, int ms)
{
    if (w->workers)
        atomic_store_explicit(&w->workers->slow_ms, ms, memory_order_relaxed);
}

/* Triangles a job for surface s at bound will make, guessed: a mesh's
 * cells grow as 1 / bound (error ~ h^2, cells ~ 1 / h^2 per area... of
 * two directions: ~ 1 / bound); with no mesh, a few dozen a patch. */
static double estimate_tris(const sw_seam_walk *w, uint32_t s, float bound)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (e->state == SW_SEAM_READY && e->index_count > 0)
        return (e->index_count / 3.0) * fmax(1.0, e->made_bound / bound);
    return 32.0 * w->pack->surfaces[s].patch_count;
}

/* Surface s's mesh given up with the last frame that drew it (its blocks
 * are free once that frame has finished: at once, or through the retire
 * ring) and the entry left empty. The ring holds two meshes a surface, or
 * as many as the vertex pool has units (each waiting mesh keeps a block),
 * so it cannot be full. */
static void retire_mesh(sw_seam_walk *w, uint32_t s)
{
    sw_seam_entry *e = &w->cache.entries[s];
    if (e->state == SW_SEAM_READY)
        sw_seam_workers_retire(w->workers,
                               (sw_retired){ e->vertex_block, e->index_block, e->last_frame });
    if (w->standin) {
        w->standin[s] = 0;
        w->standin_error[s] = w->standin_border[s] = INFINITY;
    }
    e->state = SW_SEAM_EMPTY;
    e->vertex_count = e->index_count = 0;
}

static void add_job(sw_seam_walk *w, uint32_t s)
{
    /* With sync_work the GL thread draws nothing before the batch is in
     * and the last frame has finished, so the old mesh goes now, as
     * --workers 0 remakes a surface in place: the batch then has the room
     * that walk has and makes the same meshes. (Kept beside the new one,
     * the 0.05 px views of the teacup found no room, were made coarser or
     * failed, differently from run to run.) */
    if (w->sync_work)
        retire_mesh(w, s);
    /* A surface passed over keeps the loops its mesh was made in (their
     * seams for its old bound): a mesh made inside them meets no finer
     * bound than theirs, so it is made, and labelled, for that one (then
     * drawn as late as it is, and chosen again). Labelled with its target
     * instead, such meshes drew 1-5 px on the showroom as "on time". */
    float bound = fmaxf(w->target[s], w->seam_bound[s] / (float)SW_SEAM_SHARE);
    w->workers->jobs[s] = (sw_seam_job){ bound, w->seam_bound[s] };
    w->busy[s] = 1;
    w->dirty[s] = 0;
    w->batch[w->batch_count++] = s;
}

/* A visible surface whose mesh is missing or no longer serves its target:
 * 1 and its weight w (paper 004 section 6.4) against its mesh's valid
 * range [t, KEEP t]. */
static int wants_work(const sw_seam_walk *w, uint32_t s, double *weight)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (!sw_seam_walk_needs_mesh(w, s) ||
        (e->state != SW_SEAM_EMPTY && e->made_bound == w->target[s]))
        return 0;
    /* A static level within the bound is as good as a mesh made for it. */
    if (w->standins && w->standin[s] && e->state == SW_SEAM_READY &&
        sw_seam_walk_standin_serves(w, s))
        return 0;
    int has_mesh = e->state == SW_SEAM_READY;
    double t = has_mesh ? e->made_bound : w->target[s];
    *weight = fmax(1.0, sw_seam_weight(has_mesh, t, SW_SEAM_KEEP * t, w->want[s]));
    return 1;
}

/* Out of view, its kept mesh no longer serving the bound it would need in
 * view (w->want, culled_want in sw_seam_walk.c): 1 and its weight w' =
 * 1 - 1/w, below every visible surface's (those are >= 1). Only when the
 * workers run on their own (with sync_work the frames must be what the
 * walk without workers draws, which fetches nothing ahead) and the cache
 * has room (after a batch that ran out, what is fetched ahead out of view
 * is the first thing evicted: on the courtyard a third of all jobs were
 * such churn). */
static int wants_prefetch(const sw_seam_walk *w, uint32_t s, double *weight)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (w->visible[s] != 0 || w->want[s] <= 0 || e->state != SW_SEAM_READY ||
        !sw_seam_walk_async(w) || w->room_tight)
        return 0;
    double t = e->made_bound;
    double v = sw_seam_weight(1, t, SW_SEAM_KEEP * t, w->want[s]);
    *weight = sw_seam_weight_culled(v);
    return v > 0;
}

/* How much coarser than a leaner mesh's target its seams may come to be
 * drawn (it falls behind as the eye comes closer, until made again) with
 * every stand-in sewn to it keeping its loops (checked when it is chosen). */
#define SW_SEAM_LEANER_MARGIN 2.0f

/* A stand-in that serves its target but stands for a bound KEEP times
 * finer or more (its level's worth; the levels are a factor of 4 apart,
 * and at silhouettes one made for a bound at or below the target is
 * taken): the walk's own mesh for the target has fewer triangles to draw,
 * every frame it stays. 1 and a weight below 1 (by how much finer): made
 * after all the work in view, in what its budget leaves; never with
 * sync_work (the frames must be those of the walk without workers) nor
 * when the cache is tight. */
static int wants_leaner(const sw_seam_walk *w, uint32_t s, double *weight)
{
    const sw_seam_entry *e = &w->cache.entries[s];
    if (w->no_leaner_standins || !w->standins || !w->standin[s] || w->visible[s] != 1 ||
        e->state != SW_SEAM_READY ||
        !sw_seam_walk_async(w) || w->room_tight || w->busy[s])
        return 0;
    double worth = sw_seam_walk_standin_worth(w, s), target = w->target[s];
    if (!(worth * SW_SEAM_KEEP < target))
        return 0;
    *weight = 1.0 - worth / target;
    return 1;
}

/* The batch takes all the work it finds, N and M aside: with sync_work,
 * and in a first frame that waits for it (select counts the frame after
 * the schedule). */
static int no_budget(const sw_seam_walk *w)
{
    return w->sync_work || sw_seam_walk_coarse_start(w, 0);
}

enum { SW_CHOSEN = 1, SW_PASSED = 2 };   /* w->busy while a batch opens */

/* The candidates heaviest first while N lasts (all the visible ones with
 * sync_work and in the first frame); out of view ones (weights below 1)
 * only while N lasts, their targets then set to the level of their want.
 * The ones passed over are marked. */
static double choose(sw_seam_walk *w, sw_seam_frame *frame)
{
    uint32_t n = w->pack->seam.surface_count, cands = 0;
    for (uint32_t s = 0; s < n; s++) {
        double weight = 0;
        if (wants_prefetch(w, s, &weight)) {
            w->candidates[cands++] = (sw_seam_candidate){ (float)weight, s };
            continue;
        }
        if (!wants_work(w, s, &weight)) {
            if (wants_leaner(w, s, &weight))
                w->candidates[cands++] = (sw_seam_candidate){ (float)weight, s };
            continue;
        }
        if (w->need_since[s] == UINT32_MAX)
            w->need_since[s] = w->frame;
        w->candidates[cands++] = (sw_seam_candidate){ (float)weight, s };
    }
    sw_seam_candidates_sort(w->candidates, cands);
    int unlimited = no_budget(w);
    /* Time left (paper 004): the culled go only when nothing in view waits;
     * taken after visible work in the same batch they delayed its swap.
     * Leaner meshes for stand-ins in view go after the work in view, in
     * what its budget leaves: they are drawn every frame until made. */
    int time_left = cands == 0 || w->candidates[0].weight < 1.0f;
    double tris = 0;
    for (uint32_t i = 0; i < cands; i++) {
        uint32_t s = w->candidates[i].surface;
        int low = w->candidates[i].weight < 1.0f, leaner = low && w->visible[s] == 1;
        int culled = low && !leaner;
        if (culled && !time_left) {
            w->busy[s] = SW_PASSED;
            continue;
        }
        float target = culled ? sw_seam_walk_level_of(w->want[s]) : w->target[s];
        double est = estimate_tris(w, s, target);
        int take = low ? tris + est <= w->budget.new_tris
                       : unlimited || i == 0 || tris + est <= w->budget.new_tris;
        take = take && (!leaner || sw_seam_walk_leaner_keeps_neighbours(
                                       w, s, SW_SEAM_LEANER_MARGIN * target));
        w->busy[s] = take ? SW_CHOSEN : SW_PASSED;
        tris += take ? est : 0;
        frame->jobs_scheduled += (uint32_t)take;
        if (take && culled) {
            w->target[s] = target;
            frame->jobs_prefetch++;
        }
        frame->jobs_leaner += (uint32_t)(take && leaner);
    }
    return tris;
}

/* Async: every surface's seams follow its target except those of the
 * surfaces passed over that have a mesh (their loops stay as their meshes
 * have them), then the front moves for them. */
static sw_status follow_seams(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err)
{
    uint32_t n = w->pack->seam.surface_count;
    int changed = w->frame == 0;
    for (uint32_t s = 0; s < n; s++) {
        /* Passed over with a mesh: its loops stay as its mesh has them
         * (a stand-in follows any front: it is made again after the swap).
         * Without one there is nothing to keep, and loops left at an old
         * bound (as coarse as the hierarchy goes, from when it was out of
         * view) would be what its first mesh is made in. */
        if (w->busy[s] == SW_PASSED && w->cache.entries[s].state == SW_SEAM_READY &&
            !(w->standin && w->standin[s]))
            continue;
        float seam = w->target[s] * (float)SW_SEAM_SHARE;
        changed |= seam != w->seam_bound[s];
        w->seam_bound[s] = seam;
    }
    return changed ? sw_seam_walk_move_front(w, frame, err) : SW_OK;
}

/* A new batch: the surfaces chosen, and every surface whose loops moved
 * and that has a mesh or is in view (its old border must not be drawn
 * beside the new ones). */
static sw_status open_batch(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err)
{
    /* What the drawn meshes show until the batch is swapped in: stand-ins
     * made meanwhile are made in it. */
    if (w->standins && sw_seam_walk_async(w))
        memcpy(w->drawn_shown, w->fronts.shown,
               w->pack->seam.original_count * sizeof *w->drawn_shown);
    double new_tris = choose(w, frame), must_tris = 0;
    sw_status st = sw_seam_walk_async(w) ? follow_seams(w, frame, err) : SW_OK;
    uint32_t n = w->pack->seam.surface_count;
    for (uint32_t s = 0; s < n && st == SW_OK; s++) {
        sw_seam_entry *e = &w->cache.entries[s];
        int chosen = w->busy[s] == SW_CHOSEN;
        w->busy[s] = 0;
        if (w->dirty[s] && !chosen && e->state != SW_SEAM_READY &&
            !sw_seam_walk_needs_mesh(w, s)) {
            /* Out of view with no mesh: made from the front of the day when
             * it is needed again. */
            e->state = SW_SEAM_EMPTY;
            w->dirty[s] = 0;
        }
        if (!chosen && w->dirty[s] && w->standin && w->standin[s]) {
            w->dirty[s] = 0;   /* a stand-in is made again after the swap, not in the batch */
            w->restitch[s] = 1;
        }
        if (!chosen && !w->dirty[s])
            continue;
        if (!chosen)
            must_tris += estimate_tris(w, s, w->target[s]);
        add_job(w, s);
    }
    w->budget.updated_used = must_tris;
    frame->jobs_scheduled = w->batch_count;
    frame->updated_tris = must_tris;
    frame->updated_cap = no_budget(w) ? 0 : w->budget.updated_tris;
    frame->budget_tris = w->budget.new_tris + w->budget.updated_tris;
    frame->budget_used = (must_tris + new_tris) / frame->budget_tris;
    return st;
}

/* As many of the batch's jobs as the queues take; the rest next frame. */
static void push_more(sw_seam_walk *w)
{
    uint32_t before = w->batch_pushed;
    while (w->batch_pushed < w->batch_count &&
           sw_seam_workers_push(w->workers, w->batch[w->batch_pushed]))
        w->batch_pushed++;
    if (w->batch_pushed != before)
        sw_seam_workers_wake(w->workers);
}

sw_status sw_seam_walk_schedule(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err)
{
    /* Stand-ins need room the batch must not take (sw_seam_workers.h);
     * sync_work's batches are waited for, drawn from nothing meanwhile. */
    atomic_store_explicit(&w->workers->reserve, sw_seam_walk_async(w) && w->standins != NULL,
                          memory_order_relaxed);
    sw_status st = w->batch_count == 0 ? open_batch(w, frame, err) : SW_OK;
    push_more(w);
    return st;
}

sw_status sw_seam_walk_schedule_deferred(sw_seam_walk *w, sw_error *err)
{
    memset(&w->deferred, 0, sizeof w->deferred);
    return w->workers ? sw_seam_walk_schedule(w, &w->deferred, err) : SW_OK;
}

void sw_seam_walk_take_deferred(sw_seam_walk *w, sw_seam_frame *frame)
{
    const sw_seam_frame *d = &w->deferred;
    frame->jobs_scheduled = d->jobs_scheduled, frame->jobs_prefetch = d->jobs_prefetch;
    frame->jobs_leaner = d->jobs_leaner;
    frame->updated_tris = d->updated_tris, frame->updated_cap = d->updated_cap;
    frame->budget_tris = d->budget_tris, frame->budget_used = d->budget_used;
    frame->seam_ops = d->seam_ops;
    memset(&w->deferred, 0, sizeof w->deferred);
}

/* (sw_seam_walk_internal.h) */
void sw_seam_walk_restitch_around(sw_seam_walk *w, uint32_t s)
{
    if (!w->standins)
        return;
    const sw_seam_graph *g = &w->pack->seam;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
            const uint32_t *at = NULL;
            uint32_t first = 0, count = sw_seam_fronts_surfaces_at(
                                     &w->fronts, sw_seam_fronts_slot_vertex(&w->fronts, l, k),
                                     &at, &first);
            for (uint32_t i = 0; i < count; i++)
                w->restitch[first + at[i]] |= w->standin[first + at[i]];
        }
}

/* Surface s's mesh given up (its blocks free once the frames that drew
 * it have finished), the stand-ins beside it made again. */
static void give_up(sw_seam_walk *w, uint32_t s)
{
    retire_mesh(w, s);
    sw_seam_walk_restitch_around(w, s);
    w->cache.evictions++;
}

/* The first of the m candidates (sorted here) given up until count of
 * them went or their blocks covered *vertex_units and *index_units, which
 * keep what is still short. */
static uint32_t evict_sorted(sw_seam_walk *w, uint32_t m, uint32_t count,
                             uint64_t *vertex_units, uint64_t *index_units)
{
    sw_seam_cache *c = &w->cache;
    sw_seam_candidates_sort(w->candidates, m);
    uint32_t k = 0;
    for (; k < count && k < m && (*vertex_units > 0 || *index_units > 0); k++) {
        const sw_seam_entry *e = &c->entries[w->candidates[k].surface];
        uint64_t v = sw_buddy_block_units(&c->vertex_pool, e->vertex_block);
        uint64_t i = sw_buddy_block_units(&c->index_pool, e->index_block);
        *vertex_units -= v < *vertex_units ? v : *vertex_units;
        *index_units -= i < *index_units ? i : *index_units;
        give_up(w, w->candidates[k].surface);
    }
    return k;
}

/* The least recently drawn meshes out of view, retired until count of
 * them have gone or their blocks cover *vertex_units and *index_units
 * (whichever comes first; UINT32_MAX, UINT64_MAX: no such limit). A mesh's epoch is
 * the last frame that drew it (and measured it: the GL thread reads a mesh
 * only in the frames that draw it, and at its upload, before any of them),
 * so the workers may reuse its blocks as soon as that frame has finished:
 * at once for most, drawn long ago. Returns how many went. */
static uint32_t evict_oldest(sw_seam_walk *w, uint32_t count, uint64_t *vertex_units,
                             uint64_t *index_units)
{
    /* Oldest first by one sort of the candidates (the scratch choose()
     * used; free again by now): a search of the whole cache per mesh made
     * thousands of evictions cost seconds. Ages, not frame numbers, so the
     * float weights stay exact on a kiosk that runs for weeks. */
    sw_seam_cache *c = &w->cache;
    uint32_t n = c->surface_count, m = 0;
    for (uint32_t s = 0; s < n; s++)
        if (c->entries[s].state == SW_SEAM_READY && w->evictable[s])
            w->candidates[m++] =
                (sw_seam_candidate){ (float)(w->frame - c->entries[s].last_frame), s };
    return evict_sorted(w, m, count, vertex_units, index_units);
}

typedef struct room_search {
    sw_seam_walk *w;
    int pool;
} room_search;

/* A block V may give up at once: the mesh of its owner, out of view, last
 * drawn in a frame that has finished (so its blocks come back now). */
static int freeable(void *ctx, uint32_t first, uint32_t owner)
{
    const room_search *r = ctx;
    const sw_seam_walk *w = r->w;
    if (owner >= w->cache.surface_count)
        return 0;
    const sw_seam_entry *e = &w->cache.entries[owner];
    uint32_t block = r->pool == SW_SEAM_INDEX_POOL ? e->index_block : e->vertex_block;
    return e->state == SW_SEAM_READY && w->evictable[owner] && block == first &&
           sw_retire_ring_done(&w->workers->retire, e->last_frame);
}

/* Owners given up a search: a region of more blocks than that (tiny
 * meshes side by side) is searched again, cheaper by those gone. */
#define SW_SEAM_ROOM_OWNERS 1024u
#define SW_SEAM_ROOM_ROUNDS 4

uint32_t sw_seam_walk_room_for(sw_seam_walk *w, int pool, uint32_t order)
{
    room_search search = { w, pool };
    uint32_t owners[SW_SEAM_ROOM_OWNERS], gone = 0;
    for (int round = 0; round < SW_SEAM_ROOM_ROUNDS; round++) {
        uint32_t count = 0;
        if (sw_seam_workers_find_room(w->workers, pool, order, freeable, &search, owners,
                                      SW_SEAM_ROOM_OWNERS, &count) != 1)
            break;
        for (uint32_t k = 0; k < count; k++)
            if (owners[k] < w->cache.surface_count &&
                w->cache.entries[owners[k]].state == SW_SEAM_READY)
                give_up(w, owners[k]), gone++;
        if (count < SW_SEAM_ROOM_OWNERS)
            break;
    }
    return gone;
}

/* Under pressure: meshes in view made finer than the view now asks (their
 * bound under want / SW_SEAM_KEEP: each would be remade coarser) given
 * up, the largest first, until vertex_units and index_units came back.
 * Their surfaces are drawn from stand-ins from the next frame (now, the
 * frames drawing them still hold their blocks) until the workers remake
 * them: what they held, kept until those remakes, left the surfaces
 * coming into view without room. Returns how many went. */
static uint32_t evict_too_fine(sw_seam_walk *w, uint64_t *vertex_units, uint64_t *index_units)
{
    sw_seam_cache *c = &w->cache;
    uint32_t m = 0;
    for (uint32_t s = 0; s < c->surface_count; s++) {
        const sw_seam_entry *e = &c->entries[s];
        if (e->state == SW_SEAM_READY && !w->evictable[s] && !w->standin[s] &&
            (double)e->made_bound * SW_SEAM_KEEP < (double)w->want[s])
            w->candidates[m++] = (sw_seam_candidate){
                (float)sw_buddy_block_units(&c->vertex_pool, e->vertex_block), s };
    }
    return evict_sorted(w, m, UINT32_MAX, vertex_units, index_units);
}

uint32_t sw_seam_walk_evict(sw_seam_walk *w, uint32_t count)
{
    uint64_t all_v = UINT64_MAX, all_i = UINT64_MAX;
    return evict_oldest(w, count, &all_v, &all_i);
}

void sw_seam_walk_keep_room(sw_seam_walk *w, uint32_t vertex_units, uint32_t index_units,
                            sw_seam_frame *frame)
{
    const sw_buddy *v = &w->cache.vertex_pool, *i = &w->cache.index_pool;
    uint64_t want_v = v->units / SW_SEAM_HEADROOM, want_i = i->units / SW_SEAM_HEADROOM;
    uint64_t free_v = v->units - vertex_units, free_i = i->units - index_units;
    uint32_t before = w->cache.evictions;
    if (free_v < want_v / 2 || free_i < want_i / 2) {  /* between a half and the whole share:
                                                         not every frame */
        uint64_t short_v = free_v < want_v ? want_v - free_v : 0;
        uint64_t short_i = free_i < want_i ? want_i - free_i : 0;
        evict_oldest(w, UINT32_MAX, &short_v, &short_i);
        if (w->pressure > 1.0)
            evict_too_fine(w, &short_v, &short_i);
    }
    /* The free share may lie in blocks too small for the largest mesh
     * asked: a block that size kept free, up to a 32nd of the pool. */
    for (int pool = SW_SEAM_VERTEX_POOL; pool <= SW_SEAM_INDEX_POOL; pool++) {
        const sw_buddy *b = pool == SW_SEAM_INDEX_POOL ? i : v;
        uint32_t largest, cap = 0;
        int refused;
        sw_seam_workers_asked(w->workers, pool, &largest, &refused);
        while ((2ull << cap) <= b->units / 32)
            cap++;
        sw_seam_walk_room_for(w, pool, largest < cap ? largest : cap);
    }
    frame->evicted += w->cache.evictions - before;
}

/* Surface s's published mesh becomes the drawn one; the mesh it replaces
 * is retired. */
static void consume(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    sw_seam_workers *p = w->workers;
    sw_seam_entry *made = sw_publish_take(&p->slots[s]);
    sw_seam_entry *e = &w->cache.entries[s];
    uint32_t last = e->last_frame;
    retire_mesh(w, s);
    *e = *made;
    e->last_frame = last;
    w->busy[s] = 0;
    w->need_since[s] = UINT32_MAX;
    if (e->state != SW_SEAM_GONE)
        frame->retessellated++;
    if (e->state == SW_SEAM_READY) {
        frame->retess_triangles += e->index_count / 3 - e->fill_triangles;
        sw_seam_walk_plan_upload(w, s, plan);
    }
}

void sw_seam_walk_restitch(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame)
{
    if (!w->standins)
        return;
    uint32_t n = w->pack->seam.surface_count;
    /* A mesh of the walk's own coming into view: the stand-ins beside it
     * took the sewn polyline where it was not drawn. */
    for (uint32_t s = 0; s < n; s++)
        if (w->visible[s] == 1 && !w->standin[s] &&
            w->cache.entries[s].state == SW_SEAM_READY &&
            w->cache.entries[s].last_frame + 1 != w->frame)
            sw_seam_walk_restitch_around(w, s);
    for (uint32_t s = 0; s < n; s++)
        if (w->visible[s] == 1 && s != w->drop_surface &&
            w->cache.entries[s].state == SW_SEAM_EMPTY)
            sw_seam_walk_standin_announce(w, s);
    for (uint32_t s = 0; s < n; s++) {
        if (!w->standin[s] || !w->restitch[s])
            continue;
        w->restitch[s] = 0;
        float shown = w->standin_error[s], border = w->standin_border[s];
        retire_mesh(w, s);
        /* what its neighbours were joined to */
        w->standin_error[s] = shown, w->standin_border[s] = border;
        if (sw_seam_walk_needs_mesh(w, s)) {
            sw_seam_walk_stand_in(w, s, plan, frame);
        } else {
            w->standin_error[s] = w->standin_border[s] = INFINITY;
            sw_seam_walk_restitch_around(w, s);
        }
    }
}

static int batch_done(const sw_seam_walk *w)
{
    return w->batch_pushed == w->batch_count &&
           atomic_load_explicit(&w->workers->outstanding, memory_order_acquire) == 0;
}

/* The first frame and sync_work wait for the batch; the walk's thread makes
 * jobs itself meanwhile rather than sleep. */
static void wait_batch(sw_seam_walk *w)
{
    w->maker.fill = w->fill;
    while (!batch_done(w)) {
        push_more(w);
        if (!sw_seam_workers_help(w->workers, &w->maker))
            sched_yield();
    }
}

/* Jobs the cache had no room for (the drawn meshes and the batch's new
 * ones live side by side until the swap): meshes out of view are evicted
 * (free once this frame has finished) and the jobs go again, at most
 * SW_SEAM_ROOM_RETRIES times a batch; then the batch is swapped in with
 * them failed (a hole each, counted as cracks). 1 when jobs went again. */
#define SW_SEAM_ROOM_RETRIES 4
static int retry_no_room(sw_seam_walk *w, sw_seam_frame *frame)
{
    sw_seam_workers *p = w->workers;
    if (w->room_retries >= SW_SEAM_ROOM_RETRIES)
        return 0;
    uint32_t keep = 0;   /* the batch reordered: the jobs that are done first */
    for (uint32_t i = 0; i < w->batch_count; i++) {
        if (p->no_room[w->batch[i]])
            continue;
        uint32_t t = w->batch[keep];
        w->batch[keep++] = w->batch[i];
        w->batch[i] = t;
    }
    if (keep == w->batch_count)
        return 0;
    /* Two meshes out of view for each job that found no room (meshes are
     * alike in size, and blocks come in powers of two), at least 8: a
     * fixed 8 left batches of thousands of small surfaces (the courtyard)
     * with thousands of holes after the last retry, where the walk
     * without workers, which evicts until a mesh fits, had none. */
    uint32_t failed = w->batch_count - keep;
    uint32_t before = w->cache.evictions;
    sw_seam_walk_evict(w, failed > 4 ? 2 * failed : 8);
    frame->evicted += w->cache.evictions - before;
    for (uint32_t i = keep; i < w->batch_count; i++) {
        uint32_t s = w->batch[i];
        sw_publish_take(&p->slots[s]);   /* failed for room: it holds no blocks */
        p->no_room[s] = 0;
    }
    w->batch_pushed = keep;
    w->room_retries++;
    push_more(w);
    return 1;
}

void sw_seam_walk_commit(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame)
{
    if (w->batch_count == 0)
        return;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if (w->sync_work || sw_seam_walk_coarse_start(w, 1))
        wait_batch(w);
    else
        push_more(w);
    while (batch_done(w) && retry_no_room(w, frame) &&
           (w->sync_work || sw_seam_walk_coarse_start(w, 1)))
        wait_batch(w);
    if (batch_done(w)) {
        for (uint32_t i = 0; i < w->batch_count; i++) {
            consume(w, w->batch[i], plan, frame);
            sw_seam_walk_restitch_around(w, w->batch[i]);
        }
        w->batch_count = w->batch_pushed = 0;
        w->room_tight = w->room_retries > 0;
        w->room_retries = 0;
        frame->batches_committed = 1;
    }
    frame->tess_ms += sw_seam_walk_ms_since(&t0);
}

void sw_seam_walk_finished(sw_seam_walk *w, uint32_t number)
{
    /* Plan number was made with w->frame == number + 1 and stamped its
     * meshes' last_frame so: every epoch up to that one is finished. */
    if (w->workers)
        sw_retire_ring_finish(&w->workers->retire, number + 2);
}

void sw_seam_walk_learn(sw_seam_walk *w, double frame_ms, int swapped)
{
    if (!w->workers)
        return;
    sw_seam_budget_after_frame(&w->budget, frame_ms, swapped,
                               atomic_load_explicit(&w->workers->made_triangles,
                                                    memory_order_relaxed),
                               atomic_load_explicit(&w->workers->busy_ns, memory_order_relaxed),
                               w->workers->count);
}
