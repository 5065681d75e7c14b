/* SPDX-License-Identifier: MIT */
/* The host side of the Seam Graph (core/sw_seam_graph.h): the arrays a build
 * owns while it sews the model's trims and simplifies the seams, before the
 * pack writer stores them. Host only (malloc). */
#ifndef SW_SEAM_BUILD_H
#define SW_SEAM_BUILD_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_seam_graph.h"

/* Owned arrays with their counts; capacities are the builder's business.
 * Fields as in sw_seam_graph. */
typedef struct sw_seam_host {
    sw_seam_vertex *vertices;
    sw_seam_slot *slots;
    sw_seam_loop *loops;
    sw_seam_edge *edges;
    sw_seam_collapse *collapses;
    uint32_t *slot_refs;
    uint32_t *surface_loops;
    uint32_t vertex_count, original_count;
    uint32_t slot_count, loop_count, edge_count, collapse_count, slot_ref_count;
    uint32_t surface_count;
    float tolerance;
} sw_seam_host;

/* A read-only view of host's arrays (valid until host changes or is freed). */
sw_seam_graph sw_seam_host_view(const sw_seam_host *host);

/* A copy of host in *out (which it overwrites; free it with
 * sw_seam_host_free). SW_ERR_NO_MEMORY when malloc fails (*out zeroed). */
sw_status sw_seam_host_copy(const sw_seam_host *host, sw_seam_host *out, sw_error *err);

/* Frees every array and zeroes host; safe on a zeroed or freed host. */
void sw_seam_host_free(sw_seam_host *host);

#endif
