/* SPDX-License-Identifier: MIT */
/* The baselines' draw batch and their measure (walk_baseline.h): the same
 * renderer call and the same independent measures as seamwalk's walk. */
#include <time.h>

#include "sw_seam_measure.h"
#include "walk_baseline.h"

void wb_batch_flush(wb_walk *w)
{
    wb_batch *b = &w->batch;
    if (b->index_count)
        sw_renderer_draw(w->renderer, b->verts, b->vertex_count, b->indices, b->index_count);
    b->vertex_count = b->index_count = 0;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

void wb_measure(wb_walk *w, uint32_t first_index, const sw_trim_patch *patches, uint32_t count,
                uint32_t surface, uint32_t id, double depth, const sw_view *view)
{
    if (!w->stats)
        return;
    double t0 = now_ms();
    const wb_batch *b = &w->batch;
    /* Indices are the batch's, so the mesh is the whole batch's vertices
     * with this surface's (or patch's) triangles. */
    const sw_seam_mesh mesh = { b->verts, b->uvs, b->indices + first_index, b->vertex_count,
                                b->index_count - first_index };
    const sw_seam_exact exact = { patches, count, w->sew_offset[surface], depth, 0.5,
                                  w->bound_floor };
    sw_seam_measure_mesh(&mesh, &exact, view, w->stats, &w->acc);
    if (w->drawn)
        sw_seam_drawn_add_mesh(w->drawn, id, &mesh);
    w->measure_ms += now_ms() - t0;
}
