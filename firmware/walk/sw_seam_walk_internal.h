/* SPDX-License-Identifier: MIT */
/* Shared by the files of the seam walk (sw_seam_walk.c: selection, the
 * frame's own tessellation, drawing; sw_seam_walk_threads.c: scheduling
 * for the workers and swapping their batches in); not public. */
#ifndef SW_SEAM_WALK_INTERNAL_H
#define SW_SEAM_WALK_INTERNAL_H

#include <time.h>

#include "sw_seam_walk.h"

enum { SW_SEAM_WALK_TINY = 2 }; /* w->visible: in view, smaller than its bound */

/* How much finer than the view asks a kept tessellation may be: t <= b <=
 * KEEP t. Measured over 120-frame orbits at 1280x720 (triangles drawn a
 * frame, median; surfaces re-tessellated in all): teaset 37,790 / 197 at
 * 2.0, 34,673 / 330 at 1.6, 33,301 / 392 at sqrt 2; NIST part 4 47,858 /
 * 1,432, 46,942 / 1,559, 44,458 / 2,374. Below sqrt 2 (one level) nothing
 * changes; at sqrt 2 there is no hysteresis, and a surface whose bound
 * wavers across a level boundary would be redone every frame; 1.6 leaves a
 * band of 13% against that. */
#define SW_SEAM_KEEP 1.6

/* Bounds of invisible surfaces: as coarse as the hierarchy goes (their
 * vertices still meet the bounds of visible neighbours that show them). */
#define SW_SEAM_INVISIBLE_BOUND 1e30f

/* Surfaces that get a mesh this frame: the drawn ones, and those in view
 * whose normal cone faces away (not drawn, but kept as if drawn so their
 * seams, and so their neighbours' meshes, are what they would be without
 * cone culling; sw_seam_walk.c, cull_surface). */
static inline int sw_seam_walk_needs_mesh(const sw_seam_walk *w, uint32_t s)
{
    return w->visible[s] == 1 || w->visible[s] == SW_SEAM_WALK_AWAY;
}

/* Workers that run on their own (not sync_work): the schedule, not the
 * selection, moves the seams. */
static inline int sw_seam_walk_async(const sw_seam_walk *w)
{
    return w->workers && !w->sync_work;
}

/* The threaded walk's first frame: without stand-ins it is made
 * SW_SEAM_FIRST_COARSER times coarser than the view asks and waits for its
 * batch (there is nothing else to draw); with them it is drawn at once
 * from the static levels at the view's bound, and the work is budgeted
 * from the start. 1 for that first frame (its number: 0 choosing the
 * work, 1 swapping it in). */
static inline int sw_seam_walk_coarse_start(const sw_seam_walk *w, uint32_t frame)
{
    return w->workers && !w->sync_work && !w->standins && w->frame == frame;
}

/* The seam update for w->seam_bound (complete), and the surfaces whose
 * loops it changed marked dirty. */
sw_status sw_seam_walk_move_front(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err);

/* The walk's thread, after selecting: opens a batch when none is in flight
 * (async: moving the front first) and pushes its jobs
 * (sw_seam_walk_threads.c). */
sw_status sw_seam_walk_schedule(sw_seam_walk *w, sw_seam_frame *frame, sw_error *err);

/* The schedule deferred (w->defer_schedule: V's own thread, workers on
 * their own, stand-ins drawing what is not made yet): V runs it after it
 * has handed frame k's plan to the GL thread, for frame k's targets, so
 * the front's move (a pass over the whole Seam Graph) no longer holds up
 * the plan the GL thread waits for; its counts go into w->deferred, and
 * into frame k + 1's stats at that frame's select
 * (sw_seam_walk_take_deferred). The batch is then swapped in by frame
 * k + 1's plan at the soonest, as before. */
sw_status sw_seam_walk_schedule_deferred(sw_seam_walk *w, sw_error *err);
void sw_seam_walk_take_deferred(sw_seam_walk *w, sw_seam_frame *frame);

/* V, planning a frame: swaps in the batch when all of it is published
 * (waits for it only in the first frame and with sync_work); the meshes
 * swapped in go into the plan's uploads. */
void sw_seam_walk_commit(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame);

/* Without workers, V planning a frame: surface s's mesh remade in the
 * frame when it has none or it no longer serves. */
void sw_seam_walk_refresh(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame);

/* V: surface s (with no mesh) stood in for by a static level, joined to
 * its loops as drawn, uploaded in the plan (sw_seam_standin.h); 1 when it
 * is drawn so, SW_SEAM_WALK_MET when its loops are gone at the front its
 * neighbours show (they meet across it, coarser than its bound asks:
 * counted behind, by how far), 0 when it waits (counted by the caller). */
#define SW_SEAM_WALK_MET 2

/* V: surface s counted as drawn ratio times coarser than the view asks
 * (when over 1), and for how many frames since it was first needed. */
void sw_seam_walk_count_behind(const sw_seam_walk *w, uint32_t s, double ratio,
                               sw_seam_frame *frame);
int sw_seam_walk_stand_in(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan, sw_seam_frame *frame);

/* The part levels' state, from the arena (visibility/sw_seam_part_levels.c):
 * none when the pack has none or no_part_levels is set. */
sw_status sw_seam_walk_init_parts(sw_seam_walk *w, sw_arena *arena, sw_error *err);

/* V, after culling: each part in view whose pieces all have a level within
 * the bound at their surfaces' nearest depth (at one front, when the part
 * is cut into pieces) is drawn whole from them; its surfaces in view are
 * marked SW_SEAM_WALK_PART (not drawn, no work)
 * (visibility/sw_seam_part_levels.c). */
void sw_seam_walk_choose_parts(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame);

/* V, planning: the pieces chosen above into the plan, counted. */
void sw_seam_walk_plan_parts(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame);

/* V: 1 when surface s's stand-in still serves its target: its level's
 * worth (sw_seam_standin_worth, a silhouette or not this frame) within it
 * (sw_seam_walk_standins.c). */
int sw_seam_walk_standin_serves(const sw_seam_walk *w, uint32_t s);

/* V: that worth, INFINITY when s has no level announced. */
float sw_seam_walk_standin_worth(const sw_seam_walk *w, uint32_t s);

/* V: 1 when every surface sewn to s without a mesh of its own keeps its
 * outer loops with s's seams at the walk's share of bound (a stand-in's
 * own border taken where it is coarser): a mesh of s's own made for bound
 * leaves none of them gone in the loops it is joined to (a stand-in so
 * gone waits, undrawn, for a mesh of its own). A surface with neither a
 * mesh nor a stand-in has no border yet and is checked with its seams as
 * coarse as they go, so beside one, s keeps its stand-in. */
int sw_seam_walk_leaner_keeps_neighbours(const sw_seam_walk *w, uint32_t s, float bound);

/* V: the error of the level surface s will stand in with (its target's)
 * into w->standin_error; when that changed, the stand-ins beside it are
 * marked to be made again, joined to it (sw_seam_walk_plan.c). */
void sw_seam_walk_standin_announce(sw_seam_walk *w, uint32_t s);

/* V: the stand-ins beside surface s (sharing an original with it) marked
 * to be made again (after the swap): s's mesh or stand-in changed. */
void sw_seam_walk_restitch_around(sw_seam_walk *w, uint32_t s);

/* V, planning a frame after the swap: the stand-ins whose loops the swap
 * moved, or whose neighbours' meshes changed or came into view, made
 * again (given up out of view) so they meet what is drawn now. */
void sw_seam_walk_restitch(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame);

/* The count least recently drawn meshes out of view given up (their
 * blocks free once the frames that drew them have finished); returns how
 * many. */
uint32_t sw_seam_walk_evict(sw_seam_walk *w, uint32_t count);

/* Room for a block of 2^order units in pool (SW_SEAM_VERTEX_POOL or
 * SW_SEAM_INDEX_POOL), made by giving up the meshes out of view in the
 * one aligned region whose freeing makes it, fewest units first
 * (sw_buddy_find_region), their frames finished so the room is free at
 * once. Giving up the least recently drawn frees as much but leaves it
 * scattered in blocks too small: at 400,000 patches a stand-in of 2,000
 * vertices waited, undrawn, with a tenth of the pool free. Returns the
 * meshes given up (0 also when the room was free already). */
uint32_t sw_seam_walk_room_for(sw_seam_walk *w, int pool, uint32_t order);

/* The threaded walk keeps a share of the cache's pools free for the next
 * frame: stand-ins are made in V's half of the frame from the room there
 * is, and a full cache (meshes out of view are kept until room is needed)
 * left surfaces coming into view undrawn for a frame or two while the room
 * evicted for them came free. When a pool's free units fall below half of
 * 1/SW_SEAM_HEADROOM of it, meshes out of view go, least recently drawn
 * first, until they reach it (counted in frame->evicted); and a block as large as
 * the largest asked (up to a 32nd of the pool) free in each, by
 * sw_seam_walk_room_for. vertex_units and index_units: the pools' units in
 * use, as the plan read them. */
#define SW_SEAM_HEADROOM 8u
void sw_seam_walk_keep_room(sw_seam_walk *w, uint32_t vertex_units, uint32_t index_units,
                            sw_seam_frame *frame);

/* The screen-space bound the walk makes meshes for: error_px, times the
 * pressure while the cache cannot hold the view at it. */
static inline double sw_seam_walk_error_px(const sw_seam_walk *w)
{
    return w->error_px * w->pressure;
}

/* The threaded walk, after planning a frame: when surfaces in view waited
 * undrawn for room, the cache more than 15/16 full, and either the meshes
 * drawn filled more than half of it or a 64th of the surfaces drawn by
 * meshes and stand-ins waited (the view holds more than the cache at the
 * bound: at 4,000,000 patches, 80,000 surfaces in the first frame), the
 * bound is raised by (stand-ins + waiting) / stand-ins, from sqrt 2 to 4
 * (at most every other frame, up to SW_SEAM_PRESSURE_MAX), so every mesh
 * and stand-in is made coarser and more far parts are drawn from their
 * part levels: the view drawn coarser, counted (frame->pressure, the
 * summary line), rather than with holes. A few surfaces waiting in a cache
 * whose room a batch holds do not raise it. It comes down by sqrt 2 after
 * 16 frames in a row with none waiting and the drawn meshes under a third
 * of the cache. */
#define SW_SEAM_PRESSURE_MAX 64.0
void sw_seam_walk_pressure(sw_seam_walk *w, sw_seam_frame *frame);

/* The same before the frame is planned, from what its view needs rather
 * than what waited: after the select (the surfaces in view, their targets
 * and the part levels chosen), the room each surface drawn from the cache
 * would take as a stand-in at its target (sw_seam_standin_estimate, in
 * the pools' blocks); when that is more than half a pool, the bound is
 * raised by the share over 3/8 (sqrt 2 to 4) and 1 returned: the caller
 * selects again. Half: while the workers make a surface's mesh its
 * stand-in is drawn, so the cache holds the view about twice over (with
 * less, a small cache's walk still left surfaces undrawn each time the
 * eye turned). So the first frame of a view larger than the cache is
 * planned at a bound it can draw, where the pressure above rose only
 * after frames with holes. With stand-ins only (what the walk draws while
 * meshes are made), not with sync_work. */
int sw_seam_walk_pressure_ahead(sw_seam_walk *w);

/* Surface s's cache entry (READY) into the plan's uploads. */
void sw_seam_walk_plan_upload(sw_seam_walk *w, uint32_t s, sw_seam_plan *plan);

/* Surface s's sewing offset into known[s] the first time (sw_seam_walk.c). */
float sw_seam_walk_sewing_offset(const sw_seam_walk *w, uint32_t s, float *known,
                                 const sw_trim_patch_room *room);

double sw_seam_walk_ms_since(const struct timespec *a);

/* The level a mesh is made for bound (model units): rounded down to a power
 * of sqrt 2. */
float sw_seam_walk_level_of(double bound);

#endif
