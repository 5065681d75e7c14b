/* SPDX-License-Identifier: MIT */
/* The mesh a part's levels are simplified from (sw_part_levels_build.h):
 * every surface's static level (core/sw_levels.h) joined by its border
 * strips (core/sw_border_strip.h) to one state of the Seam Graph's front:
 * each surface's finest level at the front the finest levels were made
 * at, or, for the fronts of a part cut into pieces, each surface's
 * coarsest level made within a bound at the front moved to that bound. Neighbours then end on
 * the same polyline vertices, so the surfaces of a part meet vertex for
 * vertex, as the walk's stand-ins meet: a part's surfaces welded by
 * position are one mesh with no crack, which a simplifier may then reduce
 * across the surfaces' borders.
 *
 * Its error per surface is the finest level's (measured against the exact
 * surface); a strip lies between the level's chain and the polyline, both
 * within that error of the border. Host only: allocates. */
#ifndef SW_PART_SOURCE_H
#define SW_PART_SOURCE_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_levels.h"
#include "sw_pack.h"

typedef struct sw_part_source {
    float *positions;            /* 3 per vertex, model space */
    float *normals;              /* 3 per vertex, unit (the surface's at the vertex) */
    uint32_t *indices;           /* triangles of vertex numbers, each facing its surface's
                                    normals */
    uint32_t *surface_vertices;  /* surface_count + 1: surface s's vertices are
                                    [surface_vertices[s], surface_vertices[s + 1]) */
    uint32_t *surface_indices;   /* surface_count + 1, the same for its indices */
    float *error;                /* per surface: its finest level's error; NAN when it has
                                    no mesh here (no level, or its outer loop vanished) */
    uint32_t vertex_count, index_count, surface_count;
} sw_part_source;

/* The source mesh of every surface of pack with levels. front_bound NULL:
 * each surface's finest level, at the front each surface's finest level's
 * made bound moves it to. Else front_bound[s] > 0 (model units) gives
 * surface s its coarsest level made within it (its finest when none is)
 * and its loops at the front every surface's front_bound moves it to, so
 * surfaces with one bound meet on the same polyline whatever their
 * levels; front_bound[s] 0 leaves s out of the source (no mesh, error
 * NAN). SW_ERR_ARG without a Seam Graph or levels; SW_ERR_NO_MEMORY. */
sw_status sw_part_source_build(const sw_pack *pack, const sw_levels *levels,
                               const float *front_bound, sw_part_source *out, sw_error *err);

void sw_part_source_free(sw_part_source *s);

#endif
