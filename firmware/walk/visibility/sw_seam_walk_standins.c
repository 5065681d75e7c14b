/* SPDX-License-Identifier: MIT */
/* V: surfaces in view without a mesh of the walk's own drawn from their
 * static levels (sw_seam_standin.h), joined to what is drawn beside them;
 * the borders they announce to each other, and room made for them in the
 * cache. */
#include <math.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_seam_surface.h"
#include "sw_seam_walk_internal.h"

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
    const uint32_t *at = NULL;
    uint32_t first = 0, count = sw_seam_fronts_surfaces_at(&w->fronts, o, &at, &first);
    float within = w->standin_border[s];
    for (uint32_t k = 0; k < count; k++) {
        uint32_t t = first + at[k];
        if (t != s && w->cache.entries[t].state == SW_SEAM_READY && !w->standin[t] &&
            w->visible[t] == 1)
            return sw_seam_fronts_shown(&w->fronts, drawn, o);
        within = fminf(within, w->standin_border[t]);
    }
    within = isfinite(within) ? (float)SW_SEAM_SHARE * within : 0.0f;
    return sw_seam_fronts_ancestor_within(&w->fronts, o, within);
}

/* What s's stand-in's loops may show: its level's error or, coarser, the
 * power of two at or below its target. Not the level's error alone: a
 * surface whose coarsest level is far finer than its bound (a plane is
 * exact at every level, so it keeps one) held the loops of every stand-in
 * beside it to that fineness, and at the far end of an orbit the strips
 * were most of the triangles drawn. Not the target itself:
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
            uint32_t x = sw_seam_fronts_ancestor_within(
                &w->fronts, sw_seam_fronts_slot_vertex(&w->fronts, l, k), within);
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

/* 1 when a silhouette may cross s from this frame's eye: not every normal
 * of it (its own cone, when cone culling made them) faces the eye over its
 * box; without cones, every surface may show one. */
#define SW_STANDIN_FACING_MARGIN_RAD 0.05
static int may_show_silhouette(const sw_seam_walk *w, uint32_t s)
{
    if (!w->standin_silhouettes)
        return 0;
    if (!w->cone_cull)
        return 1;
    sw_normal_cone cone = w->cones[s];
    cone.axis = sw_v3_scale(cone.axis, -1.0);   /* facing the eye: its reverse faces away */
    sw_box box = sw_cull_tree_surface_box(&w->cull_tree, s);
    return !sw_normal_cone_back_facing(&cone, &box, w->eye, SW_STANDIN_FACING_MARGIN_RAD);
}

static uint32_t level_for_target(const sw_seam_walk *w, uint32_t s)
{
    return sw_seam_standin_level(w->pack, s, w->target[s], may_show_silhouette(w, s));
}

/* The level announced for s (w->standin_error), or UINT32_MAX. */
static uint32_t announced_level(const sw_seam_walk *w, uint32_t s)
{
    uint32_t first, end;
    sw_pack_surface_levels(w->pack, s, &first, &end);
    if (isfinite(w->standin_error[s]))
        for (uint32_t k = first; k < end; k++)
            if (sw_pack_level(w->pack, s, k).error == w->standin_error[s])
                return k;
    return UINT32_MAX;
}

float sw_seam_walk_standin_worth(const sw_seam_walk *w, uint32_t s)
{
    uint32_t k = announced_level(w, s);
    if (k == UINT32_MAX)
        return INFINITY;
    sw_level rec = sw_pack_level(w->pack, s, k);
    return sw_seam_standin_worth(&rec, may_show_silhouette(w, s));
}

int sw_seam_walk_leaner_keeps_neighbours(const sw_seam_walk *w, uint32_t s, float bound)
{
    const sw_seam_graph *g = &w->pack->seam;
    uint32_t last = UINT32_MAX;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
            const uint32_t *at = NULL;
            uint32_t o = sw_seam_fronts_slot_vertex(&w->fronts, l, k), first = 0;
            uint32_t count = sw_seam_fronts_surfaces_at(&w->fronts, o, &at, &first);
            for (uint32_t i = 0; i < count; i++) {
                uint32_t t = first + at[i];
                int own_mesh = w->cache.entries[t].state == SW_SEAM_READY && !w->standin[t];
                if (t == s || t == last || own_mesh)
                    continue;
                if (!keeps_outer_loops(w, t, fmaxf(bound, w->standin_border[t])))
                    return 0;
                last = t;   /* runs of slots share the neighbour: checked once a run */
            }
        }
    return 1;
}

int sw_seam_walk_standin_serves(const sw_seam_walk *w, uint32_t s)
{
    return sw_seam_walk_standin_worth(w, s) <= w->target[s];
}

void sw_seam_walk_standin_announce(sw_seam_walk *w, uint32_t s)
{
    uint32_t level = level_for_target(w, s);
    if (level == UINT32_MAX)
        return;
    float error = sw_pack_level(w->pack, s, level).error;
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
    uint32_t k = announced_level(w, s);
    if (k != UINT32_MAX)
        return k;
    sw_seam_walk_standin_announce(w, s);
    return level_for_target(w, s);
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
    const uint32_t *drawn = w->batch_count > 0 ? w->drawn_shown : w->fronts.shown;
    const sw_seam_graph *g = &w->pack->seam;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
            uint32_t o = sw_seam_fronts_slot_vertex(&w->fronts, l, k);
            sw_seam_fronts_set_shown(&w->fronts, w->mixed_shown, o,
                                     standin_vertex(w, o, s, drawn));
        }
    return w->mixed_shown;
}

/* Region searches for stand-ins a frame: each looks through a pool's
 * blocks, and a view larger than the cache refuses stand-ins by the
 * thousand, so searching for each held the frame up for as long as the
 * view stayed too large. The rounds below go on. */
#define SW_STANDIN_SEARCHES 16u

/* No room for a stand-in. First the region that gives the block refused
 * (sw_seam_walk_room_for): a pool most of whose free room lies in blocks
 * too small kept refusing it while least recently drawn meshes went.
 * Else meshes out of view go, least recently drawn first, in rounds of
 * 64, 128, 256... a frame (each round sorts the cache: at most
 * log2(surfaces / 64) + 1 of them) until none is left out of view.
 * Those drawn in frames that have finished (most of them: they went out
 * of view a while ago) free their blocks at once, so the stand-in is tried
 * again now, not a frame later, in which a turn of the eye would leave
 * hundreds of surfaces undrawn. 1 when some went. */
static int make_room(sw_seam_walk *w, sw_seam_frame *frame)
{
    if (w->standin_evicted != w->frame)
        w->standin_evicted = w->frame, w->standin_evict_rounds = 0, w->standin_searches = 0;
    uint32_t gone = 0;
    for (int pool = SW_SEAM_VERTEX_POOL; pool <= SW_SEAM_INDEX_POOL; pool++) {
        uint32_t largest;
        int refused;
        sw_seam_workers_asked(w->workers, pool, &largest, &refused);
        if (refused >= 0 && w->standin_searches < SW_STANDIN_SEARCHES) {
            w->standin_searches++;
            gone += sw_seam_walk_room_for(w, pool, (uint32_t)refused);
        }
    }
    frame->evicted += gone;
    if (gone > 0)
        return 1;
    if (w->standin_evict_rounds == UINT32_MAX)
        return 0;   /* nothing left out of view this frame */
    uint32_t want = 64u << (w->standin_evict_rounds < 24 ? w->standin_evict_rounds : 24);
    gone = sw_seam_walk_evict(w, want);
    w->standin_evict_rounds = gone < want ? UINT32_MAX : w->standin_evict_rounds + 1;
    frame->evicted += gone;
    return gone > 0;
}

/* The largest error of the vertices the front s's stand-in was joined to
 * (w->mixed_shown, at s's originals) shows, over the seams' share of s's
 * own bound this frame (w->want): at most 1 when, gone in those loops, s
 * vanishes within its bound, as the walk's own mesh made in the frame
 * would. (The select's front is moved for the targets, which may be finer
 * than the bound: a mesh is made for a level at or below it, and, coming
 * closer, for the bound a few frames on.) */
static double joined_over_bound(const sw_seam_walk *w, uint32_t s)
{
    const sw_seam_graph *g = &w->pack->seam;
    double within = SW_SEAM_SHARE * w->want[s], worst = 0;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
            uint32_t o = sw_seam_fronts_slot_vertex(&w->fronts, l, k);
            uint32_t x = sw_seam_fronts_shown(&w->fronts, w->mixed_shown, o);
            worst = fmax(worst, sw_seam_fronts_error(&w->fronts, x));
        }
    return worst > within ? worst / within : 0.0;
}

int sw_seam_walk_stand_in(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame)
{
    uint32_t level = standin_level(w, s);
    if (level == UINT32_MAX)
        return 0;
    sw_seam_entry *e = &w->cache.entries[s];
    uint32_t last = e->last_frame;
    const uint32_t *front = standin_front(w, s);
    int made = sw_seam_standin_make(w->standins, &w->fronts, front, s, level, &w->cache,
                                    sw_seam_workers_place, w->workers, e);
    if (!made && make_room(w, frame))
        made = sw_seam_standin_make(w->standins, &w->fronts, front, s, level, &w->cache,
                                    sw_seam_workers_place, w->workers, e);
    /* Still no room: a coarser level, inside the same announced border (the
     * strips join the loops its neighbours were joined to), drawn coarser
     * than its target (behind, measured apart) rather than not at all. */
    for (uint32_t k = sw_seam_standin_coarser(w->pack, s, level); !made && k != UINT32_MAX;
         k = sw_seam_standin_coarser(w->pack, s, k)) {
        made = sw_seam_standin_make(w->standins, &w->fronts, front, s, k, &w->cache,
                                    sw_seam_workers_place, w->workers, e);
        frame->standins_coarser += (uint32_t)made;
    }
    if (!made) {
        e->last_frame = last;
        return 0;   /* it waits, undrawn and counted */
    }
    /* Gone in the loops it was made in (its neighbours' meshes show its
     * seams coarser) is not gone at the surface's own bound: its
     * neighbours meet across it, coarser than the bound, until its mesh is
     * made; counted behind, by how far. Gone at the front its own bound
     * moved too: it vanishes within the bound, as the walk's own mesh would
     * (the paper's vanishing patch), until its mesh is made. */
    double over = e->state == SW_SEAM_GONE ? joined_over_bound(w, s) : 0;
    int vanished = e->state == SW_SEAM_GONE &&
                   (over <= 1 || sw_seam_standin_vanishes(w->standins, &w->fronts, s));
    if (e->state != SW_SEAM_READY && !vanished)
        memset(e, 0, sizeof *e);
    e->last_frame = last;
    if (e->state == SW_SEAM_EMPTY && over > 1) {
        /* Its neighbours' meshes meet across it, where its loops are gone:
         * the area is drawn, by them, coarser than its bound asks. */
        if (w->need_since[s] == UINT32_MAX)
            w->need_since[s] = w->frame - 1;
        sw_seam_walk_count_behind(w, s, over, frame);
        return SW_SEAM_WALK_MET;
    }
    if (e->state != SW_SEAM_READY)
        return 0;
    w->standin[s] = 1;
    frame->standins_made++;
    if (w->need_since[s] == UINT32_MAX)
        w->need_since[s] = w->frame - 1;
    sw_seam_walk_plan_upload(w, s, plan);
    return 1;
}
