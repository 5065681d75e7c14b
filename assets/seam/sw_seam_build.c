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

static void *copy_of(const void *a, size_t n, size_t size, int *failed)
{
    void *b = malloc(n * size + 1);
    if (!b)
        *failed = 1;
    else if (n && a)
        memcpy(b, a, n * size);
    return b;
}

sw_status sw_seam_host_copy(const sw_seam_host *h, sw_seam_host *out, sw_error *err)
{
    int failed = 0;
    *out = *h;
    out->vertices = copy_of(h->vertices, h->vertex_count, sizeof *h->vertices, &failed);
    out->slots = copy_of(h->slots, h->slot_count, sizeof *h->slots, &failed);
    out->loops = copy_of(h->loops, h->loop_count, sizeof *h->loops, &failed);
    out->edges = copy_of(h->edges, h->edge_count, sizeof *h->edges, &failed);
    out->collapses = copy_of(h->collapses, h->collapse_count, sizeof *h->collapses, &failed);
    out->slot_refs = copy_of(h->slot_refs, h->slot_ref_count, sizeof *h->slot_refs, &failed);
    out->surface_loops = copy_of(h->surface_loops, (size_t)h->surface_count + 1,
                                 sizeof *h->surface_loops, &failed);
    if (!failed)
        return SW_OK;
    sw_seam_host_free(out);
    return sw_error_set(err, SW_ERR_NO_MEMORY, "seam graph: out of memory copying it");
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
