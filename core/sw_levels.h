/* SPDX-License-Identifier: MIT */
/* Static levels of detail (paper 000, section 4): for each surface, a few
 * meshes made on the host at increasing error, stored in the pack and drawn
 * at run time without tessellating anything. Far away a level stands for
 * the surface; close up, while the surface's own mesh is being made on the
 * fly, its finest level stands in, so no surface in view is left undrawn.
 *
 * A level is made inside the surface's loops as the Seam Graph showed them
 * at one state of its front. The front moves at run time, so a level is
 * drawn with a border strip (sw_border_strip.h) from its stored border
 * chains, one per loop of the surface, to the loops' current polylines,
 * the vertices the neighbours share: no crack, whatever level each side
 * shows. A chain's points are the level's border vertices in order round
 * the loop, each placed by t, the loop's slot it stands at (plus a
 * fraction between slots).
 *
 * Its error is measured on the host, not assumed: the largest distance
 * found from the level's triangles to the surface at the same (u, v),
 * sampled densely over every triangle (assets/super/). The strip's
 * triangles lie between the chain and the current polyline, both within
 * their errors of the border.
 *
 * Written by the pack tool (assets/super/, assets/pack/), checked by the
 * pack reader (PACK_FORMAT.md, "LEVELS"), read by the walk. */
#ifndef SW_LEVELS_H
#define SW_LEVELS_H

#include <stdint.h>

#include "sw_border_strip.h"

#define SW_LEVELS_MAX 6u          /* levels per surface */

typedef struct sw_level_vertex {  /* 16 bytes: the runtime's vertex layout */
    float p[3];                   /* model space */
    int8_t normal[4];             /* x, y, z as signed normalised bytes; w zero */
} sw_level_vertex;

typedef struct sw_level {         /* 32 bytes */
    uint32_t surface;             /* the pack's surface */
    float error;                  /* model units, measured (above); finite, >= 0, and
                                     rising strictly over a surface's levels */
    uint32_t first_vertex;        /* vertices[first_vertex .. + vertex_count) */
    uint32_t vertex_count;        /* 1 .. 65536 (16-bit indices) */
    uint32_t first_index;         /* indices[first_index .. + index_count), level-local */
    uint32_t index_count;         /* a multiple of 3 */
    uint32_t first_chain;         /* chains[first_chain .. + the surface's loop count), in
                                     the order of the Seam Graph's surface_loops */
    float made_bound;             /* model units: the bound the walk's tessellator made it
                                     for (finite, >= 0; 0: not known, a pack from before) */
} sw_level;

typedef struct sw_level_chain {   /* 8 bytes: one loop's border in one level */
    uint32_t first_point;         /* chain_points[first_point .. + point_count) */
    uint32_t point_count;         /* 0: the loop had vanished at the level's state (a hole
                                     the level covers; an outer loop never) */
} sw_level_chain;

/* Section LEVELS: the counts. */
typedef struct sw_pack_levels {   /* 32 bytes */
    uint32_t level_count;
    uint32_t vertex_count;
    uint32_t index_count;
    uint32_t chain_count;
    uint32_t chain_point_count;
    uint32_t surface_count;       /* == the SURFACES count */
    uint8_t reserved[8];          /* zero */
} sw_pack_levels;

/* The levels as views (host: owned by whoever built them; runtime: into the
 * pack). Chain points are sw_strip_point: vertex is level-local, t in
 * [0, the loop's slot_count) and valid by sw_border_chain_valid. */
typedef struct sw_levels {
    const sw_level *levels;
    const uint32_t *surface_levels;   /* surface_count + 1: surface s has the levels
                                         [surface_levels[s], surface_levels[s + 1]), finest
                                         first */
    const sw_level_vertex *vertices;
    const uint16_t *indices;
    const sw_level_chain *chains;
    const sw_strip_point *chain_points;
    uint32_t level_count, vertex_count, index_count, chain_count, chain_point_count;
    uint32_t surface_count;
} sw_levels;

#endif
