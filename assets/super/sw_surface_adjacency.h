/* SPDX-License-Identifier: MIT */
/* Which surfaces of a pack touch: two surfaces are adjacent when one
 * original Seam Graph vertex sits in loops of both (they were sewn there,
 * along a seam or at a corner). The clustering into super-surfaces
 * (sw_cluster.h) grows and merges along it. Host only: allocates. */
#ifndef SW_SURFACE_ADJACENCY_H
#define SW_SURFACE_ADJACENCY_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_seam_graph.h"

/* Surface s's neighbours are next[first[s] .. first[s + 1]), increasing,
 * never s itself; each pair is listed from both sides. */
typedef struct sw_surface_adjacency {
    uint32_t *first;          /* surface_count + 1 */
    uint32_t *next;
    uint32_t surface_count;
} sw_surface_adjacency;

/* From a checked graph (sw_seam_graph_check). SW_ERR_NO_MEMORY; on error
 * *out is empty. */
sw_status sw_surface_adjacency_build(const sw_seam_graph *g, sw_surface_adjacency *out,
                                     sw_error *err);

/* From pairs (a, b), a != b, in any order with repeats (tests build
 * adjacency by hand this way). */
sw_status sw_surface_adjacency_from_pairs(uint32_t surface_count, const uint32_t (*pairs)[2],
                                          uint64_t pair_count, sw_surface_adjacency *out,
                                          sw_error *err);

void sw_surface_adjacency_free(sw_surface_adjacency *a);

#endif
