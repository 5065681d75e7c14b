/* SPDX-License-Identifier: MIT */
/* The part levels of a pack (core/sw_part_levels.h), made on the host from
 * its surfaces' static levels joined at one front (sw_part_source.h).
 *
 * Each piece's source (sw_part_pieces.h: a part, or a piece of a part cut
 * into pieces) is welded by position (the surfaces meet on shared polyline
 * vertices) and simplified by meshoptimizer (meshopt_simplify, across the
 * surfaces' borders; the piece's own open borders stay borders) toward
 * bounds of finest * step^k of the piece's size. A piece of a cut part is
 * made at each of SW_PART_LEVEL_FRONTS fronts, 4^f / 4096 of the part's
 * size: its source joined at that front, its first level that source
 * itself (so every piece has a level at every front it can be made at),
 * then simplified with its border locked (meshopt_SimplifyLockBorder), so
 * it meets the part's other pieces at that front vertex for vertex; a
 * simplified level with a triangle folded over (facing against the
 * source around all its corners, which meshoptimizer's own check misses
 * on flat ground) is left out. Each result is
 * measured, not taken from the simplifier's estimate: the sampled distance
 * both ways between it and the source (sw_mesh_distance.h), plus the
 * source's own measured error. A part's open rim is where the
 * simplifier's estimate fails most, so a simplification over its bound is
 * made again with the rim's corners held (sw_part_rim.h); not within
 * either, the first serves coarser views. Past the last bound, a level of a
 * few triangles, for a piece a few pixels across. A level is kept when
 * its error rises over
 * the one before and it has fewer triangles by at least a fifth, and it
 * fits one draw (65536 vertices).
 *
 * Normals: a welded vertex stands for one vertex of each surface that met
 * there, with that surface's normal; each corner of a simplified triangle
 * takes the one closest to the source's normal a little inside the
 * triangle from it, or that source normal when none is within 30 degrees
 * (the simplifier may put a face onto vertices of the faces around it).
 * The level's area shaded wrong is measured and stored with it
 * (sw_part_level.shading_side): its error bounds its shape, not its
 * normals.
 *
 * A piece gets no level at a front when one of its surfaces has no level
 * (that surface would be missing from it); counted. Host only:
 * allocates. */
#ifndef SW_PART_LEVELS_BUILD_H
#define SW_PART_LEVELS_BUILD_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_levels.h"
#include "sw_pack.h"
#include "sw_part_levels.h"
#include "sw_parts.h"

typedef struct sw_part_levels_options {
    double finest;      /* the finest level's bound over the part's size (0: 1/512) */
    double step;        /* each level's bound over the one before (0: 2) */
    uint32_t count;     /* bounds tried per piece and front (0: 8; at most
                           SW_PART_LEVELS_MAX - 2) */
    uint32_t cut_patches;   /* parts with more patches are cut into pieces (0:
                               SW_PART_CUT_PATCHES, sw_part_pieces.h) */
    uint32_t piece_patches; /* patches a piece, at most (0: 256) */
    const sw_parts_runner *runner;   /* makes the pieces (sw_parts.h), a mesh each piece
                                        made at once; NULL: in order here. The same
                                        levels either way */
} sw_part_levels_options;

typedef struct sw_part_levels_report {
    uint32_t parts;               /* of the pack */
    uint32_t pieces;              /* all, a part not cut being one */
    uint32_t cut_parts;           /* parts cut into pieces */
    uint32_t with_levels;         /* pieces with at least one level */
    uint32_t levels;              /* kept */
    uint32_t incomplete;          /* pieces (at a front) with a surface without a level */
    uint32_t not_smaller;         /* tried levels left out: not a fifth fewer triangles, or
                                     error not rising */
    uint32_t folded;              /* tried levels left out for a fold */
    uint32_t over_bound;          /* bounds no simplification was found within (the
                                     simplifier's own result kept) */
    uint32_t too_large;           /* tried levels over 65536 vertices */
    uint64_t source_triangles;    /* of the pieces with levels, at each front */
    uint64_t triangles[SW_PART_LEVELS_MAX];  /* kept, by rank at a front (finest 0) */
    double worst_over_bound;      /* the largest measured error over its target bound */
    double seconds;
} sw_part_levels_report;

typedef struct sw_part_levels_built {
    sw_part_levels view;
    sw_part_level *levels;
    uint32_t *piece_levels;
    uint32_t *piece_of;
    sw_level_vertex *vertices;
    uint16_t *indices;
} sw_part_levels_built;

/* The part levels of pack from its surface levels (which must be the
 * pack's: built from it). opt may be NULL. SW_ERR_NO_MEMORY; on error *out
 * is empty. */
sw_status sw_part_levels_build(const sw_pack *pack, const sw_levels *levels,
                               const sw_part_levels_options *opt, sw_part_levels_built *out,
                               sw_part_levels_report *report, sw_error *err);

void sw_part_levels_built_free(sw_part_levels_built *b);

#endif
