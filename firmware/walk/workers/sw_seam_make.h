/* SPDX-License-Identifier: MIT */
/* One surface's tessellation from its current Seam Graph loops, as the walk
 * keeps it (sw_seam_walk.h): the loops the front shows for its seams'
 * share of the bound, the trimmed tessellator at the bound (coarsened x4,
 * up to three times, when the surface needs more than 65536 vertices or
 * the cache has no room), the fill fans, the border checked bit for bit
 * against the seam vertices, and the mesh copied into the cache's pools at
 * the blocks the caller's place function gives.
 *
 * A maker is one thread's buffers: the walk has one for tessellating in
 * the frame (--workers 0) and each tessellation worker has its own
 * (sw_seam_workers.h). It only reads the pack and the selection, which must
 * not move while it runs (the walk moves the front only when no work is
 * outstanding). Memory from the arena at init; no allocation after. */
#ifndef SW_SEAM_MAKE_H
#define SW_SEAM_MAKE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_pack.h"
#include "sw_seam_cache.h"
#include "sw_seam_fill.h"
#include "sw_seam_fronts.h"
#include "sw_trim_tess.h"
#include "sw_walk_memory.h"

typedef struct sw_seam_maker {
    const sw_pack *pack;
    const sw_seam_fronts *fronts;
    sw_seam_point *loop_points;   /* the largest surface's slots */
    sw_trim_point *points;        /* the same, as the tessellator takes them */
    uint32_t *loop_first;         /* the most loops of a surface, + 1 */
    sw_trim_patch_room room;      /* the most patches of a surface, and their control
                                     points where they are placed as read */
    uint32_t patch_count;         /* the surface's, as tessellate last read them */
    uint32_t max_points;
    sw_arena scratch;             /* the tessellator's */
    float *positions, *normals, *uvs;
    uint32_t *ids;
    uint16_t *indices;            /* one surface's, as the tessellator writes it */
    sw_seam_fill *fill;           /* fans over crossings and drops; NULL: none */
} sw_seam_maker;

/* Arena bytes of one maker for the largest surface m (fill not included:
 * sw_seam_fill_arena_bytes). */
uint64_t sw_seam_maker_arena_bytes(const sw_walk_sizes *m);
sw_status sw_seam_maker_init(sw_seam_maker *k, const sw_pack *pack, const sw_seam_fronts *fronts,
                             const sw_walk_sizes *m, sw_arena *arena, sw_error *err);

/* Where a mesh of n vertices and m indices goes in the cache: 1 with the
 * entry's blocks set, 0 when there is no room. */
typedef int (*sw_seam_place_fn)(void *ctx, uint32_t surface, uint32_t n, uint32_t m,
                                sw_seam_entry *e);

/* Makes surface s's mesh for bound (model units; its seams at seam_bound)
 * into *e: READY with its blocks filled in the cache's CPU pools (not
 * uploaded), GONE when its outer loop vanished, FAILED when the
 * tessellator refused it or place found no room (*no_room then). Returns
 * the triangles made (fans not counted). */
uint64_t sw_seam_make(sw_seam_maker *k, uint32_t s, float bound, float seam_bound,
                      sw_seam_cache *c, sw_seam_place_fn place, void *place_ctx,
                      sw_seam_entry *e, int *no_room);

#endif
