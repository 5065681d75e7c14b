/* SPDX-License-Identifier: MIT */
/* The uniform-grid baseline of walk_baseline.h: every visible patch on the
 * same S x S grid, every frame, the cells outside its trim mask left out. */
#include <string.h>

#include "sw_cell_filter.h"
#include "sw_tess.h"
#include "walk_baseline.h"

sw_box wb_patch_box(const sw_pack *pack, uint32_t i)
{
    const sw_pack_patch *p = &pack->patches[i];
    return (sw_box){ sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                     sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
}

int wb_patch_visible(const sw_pack *pack, uint32_t i, const sw_view *view, double *depth)
{
    sw_box box = wb_patch_box(pack, i);
    if (sw_frustum_test_box(&view->frustum, &box) == SW_CULL_OUTSIDE)
        return 0;
    *depth = sw_view_box_min_depth(view, &box);
    return 1;
}

static const sw_pack_trim_mask *mask_of(const sw_pack *pack, uint32_t i)
{
    if (!pack->patch_domains || pack->patch_domains[i].mask == SW_MASK_NONE)
        return NULL;
    return &pack->trim_masks[pack->patch_domains[i].mask];
}

/* The (u, v) of the grid's vertices in the surface's domain (what the
 * measure evaluates the exact surface at). */
static void grid_uvs(const float domain[4], uint32_t n, float *uvs)
{
    for (uint32_t b = 0; b <= n; b++)
        for (uint32_t a = 0; a <= n; a++, uvs += 2) {
            uvs[0] = domain[0] + (domain[1] - domain[0]) * (float)a / (float)n;
            uvs[1] = domain[2] + (domain[3] - domain[2]) * (float)b / (float)n;
        }
}

/* Patch i (of surface s) at the end of the batch; its triangles kept. */
static uint32_t add_patch(wb_walk *w, uint32_t i, uint32_t s, double depth, const sw_view *view)
{
    const sw_trim_patch *tp = &w->patches[i];
    uint32_t n = w->segments;
    wb_batch *b = &w->batch;
    uint32_t v0 = b->vertex_count, i0 = b->index_count;
    sw_tess_grid(&tp->patch, n, n, v0, b->verts + v0, b->indices + i0);
    sw_cell_filter filter;
    sw_cell_filter_init(&filter, mask_of(w->pack, i), n, n);
    uint32_t kept = sw_cell_filter_compact(&filter, b->indices + i0);
    b->vertex_count += (n + 1) * (n + 1);
    b->index_count += kept;
    if (w->stats) {
        grid_uvs(tp->domain, n, b->uvs + 2 * (size_t)v0);
        wb_measure(w, i0, tp, 1, s, i, depth, view);
    }
    return kept / 3;
}

void wb_uniform_frame(wb_walk *w, const sw_view *view, wb_frame *out)
{
    const sw_pack *pack = w->pack;
    uint32_t n = w->segments, need_v = (n + 1) * (n + 1), need_i = 6 * n * n;
    for (uint32_t part = 0; part < pack->meta->part_count; part++) {
        const sw_pack_part *pp = &pack->parts[part];
        sw_renderer_set_color(w->renderer, pp->color);
        for (uint32_t i = pp->first_patch; i < pp->first_patch + pp->patch_count; i++) {
            double depth;
            if (!wb_patch_visible(pack, i, view, &depth))
                continue;
            if (w->batch.vertex_count + need_v > WB_BATCH_VERTICES ||
                w->batch.index_count + need_i > WB_BATCH_INDICES)
                wb_batch_flush(w);
            uint32_t s = pack->patch_domains ? pack->patch_domains[i].surface : 0;
            out->triangles += add_patch(w, i, s, depth, view);
            out->drawn++;
        }
        wb_batch_flush(w);
    }
}
