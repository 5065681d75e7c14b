/* SPDX-License-Identifier: MIT */
/* How much of a Seam Graph's border is sewn: the length of every loop's
 * edges, and of those no other loop (nor the same loop elsewhere) runs
 * along, which are the free border. For `seamwalk-pack info` and the build
 * summary, and for holding seamwalk's sewing against OpenCASCADE's
 * (tests/test_sewing_vs_occt.sh). Host only. */
#ifndef SW_SEAM_BORDER_H
#define SW_SEAM_BORDER_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_seam_graph.h"

typedef struct sw_seam_border {
    double length;          /* every edge use of every loop, model units */
    double free_length;     /* uses of edges used exactly once */
    size_t edge_uses, free_edges;
} sw_seam_border;

/* Walks the original polylines (every slot, no collapse applied); an edge is
 * the unordered pair of the vertices of two consecutive slots, slots on one
 * vertex (a pole) make none. SW_ERR_NO_MEMORY when its scratch cannot be had. */
sw_status sw_seam_border_measure(const sw_seam_graph *graph, sw_seam_border *out, sw_error *err);

#endif
