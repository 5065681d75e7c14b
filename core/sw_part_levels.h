/* SPDX-License-Identifier: MIT */
/* Part levels: a whole part drawn far away as one simplified mesh, one
 * draw, in place of its surfaces. A surface level (sw_levels.h) cannot go
 * below a few triangles a surface plus the strips to its neighbours; a
 * part of many small surfaces, a screw or a hammer, seen from the far end
 * of a hall needs fewer triangles than it has surfaces. A part level is
 * simplified across the borders of its surfaces, from the surfaces' levels
 * joined at one front of the Seam Graph (assets/super/sw_part_source.h),
 * so it has no border to join to anything: the part is drawn from it
 * whole, or not at all (paper 000's super-surface levels, taken to the
 * part).
 *
 * A large part (a floor, a building: thousands of patches) is cut into
 * pieces, compact sets of its surfaces, each with levels of its own, so
 * that a piece far away is drawn coarser than one near. A piece's levels
 * keep its border with the other pieces exactly as the front shows it:
 * they are simplified with that border locked, from a source joined at one
 * of a few fronts (SW_PART_LEVEL_FRONTS) common to the whole part. Two
 * pieces' levels at the same front meet vertex for vertex whatever their
 * levels, so the part is drawn from its pieces' levels all at one front,
 * or by its surfaces (paper 000's border at a shared error, with the fronts
 * as the shared errors).
 *
 * Its error is measured on the host both ways (the largest distance from
 * points on the level to the mesh it was simplified from, and from points
 * on that mesh to the level), plus that mesh's own measured error against
 * the exact surfaces.
 *
 * Written by the pack tool (assets/super/sw_part_levels_build.h), checked
 * by the pack reader (PACK_FORMAT.md, "PART_LEVELS"), drawn by the walk. */
#ifndef SW_PART_LEVELS_H
#define SW_PART_LEVELS_H

#include <stdint.h>

#include "sw_levels.h"

/* Levels per piece and front: a cut piece's source, one for each bound
 * the builder tries (at most 8), and a last of a few triangles. */
#define SW_PART_LEVELS_MAX 10u
#define SW_PART_LEVEL_FRONTS 3u   /* fronts of a cut part (its pieces' borders) */
/* The front of a cut part's levels of itself whole, kept with its first
 * piece: far away a whole part has no border to keep, and its pieces'
 * borders would hold it finer than the bound asks. */
#define SW_PART_LEVEL_WHOLE 255u

/* Front f of a cut part as a bound (model units): 4^f / 4096 of the
 * diagonal of its patches' boxes. The coarsest front whose levels serve
 * every piece in view is drawn, so fronts step as a whole part's levels
 * do, a few to tens of pixels apart. */
static inline double sw_part_level_front_bound(double part_diagonal, uint32_t front)
{
    return part_diagonal * (double)(1u << (2 * front)) / 4096.0;
}

/* A level's shading normal further than this from the surfaces' is shaded
 * wrong (sw_part_level.shading_side). */
#define SW_PART_LEVEL_CREASE_COS 0.8660254f   /* cos 30 degrees */

typedef struct sw_part_level {    /* 32 bytes */
    uint32_t piece;               /* the piece (a part, or a piece of a cut part) */
    float error;                  /* model units, measured (above); finite, > 0, rising
                                     strictly over a piece's levels at one front */
    uint32_t first_vertex;        /* part_level_vertices[first_vertex .. + vertex_count) */
    uint32_t vertex_count;        /* 3 .. 65536 (16-bit indices) */
    uint32_t first_index;         /* part_level_indices[first_index .. + index_count),
                                     level-local */
    uint32_t index_count;         /* a positive multiple of 3 */
    float shading_side;           /* model units: the side of a square as large as the
                                     level's area shaded wrong (its normals more than 30
                                     degrees off the surfaces' within its error, measured
                                     on the host); 0 when none; finite, >= 0. The error
                                     bounds the shape, not the normals, so the walk holds
                                     this to a bound of its own. */
    uint32_t front;               /* the front its border is locked at, < SW_PART_LEVEL_FRONTS;
                                     0 for the piece of a part not cut; SW_PART_LEVEL_WHOLE:
                                     a level of the whole cut part, on its first piece; a
                                     piece's levels by front, rising */
} sw_part_level;

/* Section PART_LEVELS: the counts. */
typedef struct sw_pack_part_levels {   /* 16 bytes */
    uint32_t level_count;
    uint32_t vertex_count;
    uint32_t index_count;
    uint32_t piece_count;         /* the pieces: at least one per part, at most one per
                                     surface */
} sw_pack_part_levels;

/* The part levels as views (host: owned by whoever built them; runtime:
 * into the pack). */
typedef struct sw_part_levels {
    const sw_part_level *levels;
    const uint32_t *piece_levels;     /* piece_count + 1: piece g has the levels
                                         [piece_levels[g], piece_levels[g + 1]), by front,
                                         finest first within one */
    const uint32_t *piece_of;         /* surface_count: each surface's piece; a piece's
                                         surfaces are of one part, and the pieces of part p
                                         follow those of part p - 1 */
    const sw_level_vertex *vertices;
    const uint16_t *indices;
    uint32_t level_count, vertex_count, index_count, piece_count, surface_count;
} sw_part_levels;

#endif
