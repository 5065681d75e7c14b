/* SPDX-License-Identifier: MIT */
/* A level's border read back from its mesh (sw_levels_build.h): the mesh's
 * edges used by one triangle only, walked into closed chains, each matched
 * to the loop whose points it runs through and placed along it by slot
 * (sw_border_strip.h's t). Host only: allocates. */
#ifndef SW_LEVELS_BORDER_H
#define SW_LEVELS_BORDER_H

#include <stdint.h>

#include "sw_border_strip.h"
#include "sw_error.h"

/* One loop as the mesh was made inside it: its points' vertex ids and
 * (u, v) (the tessellator's input, in order), each point's slot, and the
 * loop's slot count (the period of t). */
typedef struct sw_border_loop {
    const uint32_t *ids;
    const float *uvs;        /* 2 per point */
    const uint32_t *slots;
    uint32_t count, period;
} sw_border_loop;

/* The mesh: its vertices' ids (a loop point's id, or another value for a
 * vertex that is no loop point), their (u, v), its triangles. */
typedef struct sw_border_mesh {
    const uint32_t *ids;
    const float *uvs;
    const uint16_t *indices;
    uint32_t vertex_count, index_count;
} sw_border_mesh;

/* Chains of mesh's border, one per loop: chain k into
 * points[first[k] .. first[k + 1]) (points: the mesh's border vertex count
 * at most; first: loop_count + 1 entries). Every border vertex that is a
 * loop point gets its slot as t; one between two loop points (a crossing)
 * gets a t between theirs by its (u, v) distance along the border. SW_OK
 * when the border is exactly one closed chain per loop, each once round in
 * slot order (sw_border_chain_valid); SW_ERR_FORMAT naming what is wrong
 * otherwise; SW_ERR_NO_MEMORY. */
sw_status sw_levels_border(const sw_border_mesh *mesh, const sw_border_loop *loops,
                           uint32_t loop_count, sw_strip_point *points, uint32_t *first,
                           sw_error *err);

#endif
