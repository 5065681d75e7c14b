/* SPDX-License-Identifier: MIT */
/* sw_seam_host: views and release (sw_seam_build.h). */
#include "sw_seam_build.h"

#include <stdlib.h>
#include <string.h>

sw_seam_graph sw_seam_host_view(const sw_seam_host *host)
{
    return (sw_seam_graph){
        .vertices = host->vertices, .slots = host->slots, .loops = host->loops,
        .edges = host->edges, .collapses = host->collapses, .slot_refs = host->slot_refs,
        .surface_loops = host->surface_loops, .vertex_count = host->vertex_count,
        .original_count = host->original_count, .slot_count = host->slot_count,
        .loop_count = host->loop_count, .edge_count = host->edge_count,
        .collapse_count = host->collapse_count, .slot_ref_count = host->slot_ref_count,
        .surface_count = host->surface_count, .tolerance = host->tolerance};
}

void sw_seam_host_free(sw_seam_host *host)
{
    if (!host)
        return;
    free(host->vertices);
    free(host->slots);
    free(host->loops);
    free(host->edges);
    free(host->collapses);
    free(host->slot_refs);
    free(host->surface_loops);
    memset(host, 0, sizeof *host);
}
