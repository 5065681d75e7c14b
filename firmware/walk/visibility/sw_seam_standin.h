/* SPDX-License-Identifier: MIT */
/* Stand-ins: a surface in view whose own mesh is not made yet is drawn at
 * once from one of its static levels (core/sw_levels.h), joined by border
 * strips (core/sw_border_strip.h) to the loops its neighbours draw, so it
 * is not left out and meets their borders vertex for vertex.
 * The walk's visibility side V makes them (sw_seam_walk_plan.c) into the
 * cache like any mesh; the walk's own mesh replaces a stand-in when it is
 * swapped in. A stand-in is counted as behind, with its level's measured
 * error.
 *
 * The loops it is joined to are given by the caller as a front
 * (sw_seam_walk_plan.c, standin_front): at an original shared with a mesh
 * of the walk's own drawn this frame, the vertex that mesh shows; elsewhere
 * one that depends on the original and the levels of the stand-ins sewn
 * there, so stand-ins side by side meet.
 *
 * Memory: one block from the arena at init (the largest surface's slots,
 * its strips); no allocation after. Not thread-safe: V's. */
#ifndef SW_SEAM_STANDIN_H
#define SW_SEAM_STANDIN_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_border_strip.h"
#include "sw_pack.h"
#include "sw_seam_cache.h"
#include "sw_seam_make.h"
#include "sw_seam_fronts.h"
#include "sw_seam_select.h"

typedef struct sw_seam_standin {
    const sw_pack *pack;
    sw_seam_point *points;        /* the surface's loops as drawn */
    uint32_t *slots;
    uint32_t *loop_at, *loop_count;
    uint8_t *vanished;
    sw_strip_point *outer;        /* one loop's points as a chain */
    uint32_t *same;               /* one loop's points: the chain vertex each is, or itself */
    uint32_t *tris;               /* one loop's strip */
    uint32_t capacity, max_loops, max_chain;
} sw_seam_standin;

/* Arena bytes for the pack's largest surface and longest level chain. */
size_t sw_seam_standin_bytes(const sw_pack *pack);
sw_status sw_seam_standin_init(sw_seam_standin *m, const sw_pack *pack, sw_arena *arena,
                               sw_error *err);

/* What a level is worth against a bound: its error; or, where a silhouette
 * may cross the surface, the bound it was made for when that is larger. A
 * level's error is its worst point, and a silhouette shows it whole; the
 * walk's own mesh for a bound comes out well within it (its tessellator
 * proves the bound), and a stand-in drawn at its level's whole error
 * beside such meshes moved silhouettes by a pixel: between two columns,
 * one behind the other, the background showed. A level made for the bound
 * by the same tessellator is as close as the walk's own mesh. A pack that
 * keeps no made bound: four times the error. */
float sw_seam_standin_worth(const sw_level *level, int silhouette);

/* The level of surface s to stand in for a mesh made for bound (model
 * units): of its levels with a chain for every loop (a level made without
 * a hole would cover it), the coarsest worth bound or less (with or
 * without a silhouette, as above), else the finest; with no such level,
 * its finest. UINT32_MAX when s has none. */
uint32_t sw_seam_standin_level(const sw_pack *pack, uint32_t s, float bound, int silhouette);

/* The next level of s coarser than level with a chain for every loop,
 * UINT32_MAX when none is. */
uint32_t sw_seam_standin_coarser(const sw_pack *pack, uint32_t s, uint32_t level);

/* About the vertices and indices a stand-in of s from level takes: the
 * level's, and its chains' points for the strips that join each loop to
 * it (the loops' own points as the chains count them: the front it is
 * joined to is not read). */
void sw_seam_standin_estimate(const sw_pack *pack, uint32_t s, uint32_t level,
                              uint32_t *vertices, uint32_t *indices);

/* 1 when an outer loop of surface s vanishes at the fronts (m's buffers
 * are written). */
int sw_seam_standin_vanishes(sw_seam_standin *m, const sw_seam_fronts *fronts, uint32_t s);

/* Surface s's stand-in from level `level` and the loops the fronts show
 * with shown for their shown vertices (a copy of fronts->shown, NULL: the
 * fronts' own; sw_seam_fronts_loop_slots) (a
 * run of slots showing one vertex is one point: only positions are drawn,
 * and repeats of one, a pole's corners kept apart, would each add a strip
 * triangle of no area), into *e with blocks from
 * place: READY (made_bound the level's error; its (u, v) NaN: it is not
 * measured as a tessellation is), GONE when its outer loop vanished there,
 * FAILED when it needs more than one draw's 65536 vertices. 0 when place
 * found no room (*e EMPTY), else 1. A loop the level covers (a hole it has
 * no chain for) but the front still shows counts its points as cracks. */
int sw_seam_standin_make(sw_seam_standin *m, const sw_seam_fronts *fronts,
                         const uint32_t *shown, uint32_t s, uint32_t level, sw_seam_cache *c,
                         sw_seam_place_fn place, void *place_ctx, sw_seam_entry *e);

#endif
