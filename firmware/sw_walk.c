#include "sw_walk.h"

#include <string.h>

#include "sw_cell_filter.h"

_Static_assert(sizeof(sw_patch_state) <= SW_RUNTIME_BYTES_PER_PATCH,
               "per-patch runtime state must fit what the pack header budgets");

size_t sw_walk_arena_bytes(void)
{
    return sw_arena_worst_case(SW_BATCH_VERTICES * sizeof(sw_vertex), 64) +
           sw_arena_worst_case(SW_BATCH_INDICES * sizeof(uint16_t), 64);
}

sw_status sw_walk_init(sw_walk *walk, const sw_pack *pack, sw_arena *arena, double error_px,
                       sw_error *err)
{
    memset(walk, 0, sizeof *walk);
    walk->pack = pack;
    walk->error_px = error_px;
    size_t n = pack->meta->patch_count;
    walk->state = sw_arena_alloc(arena, n * sizeof(sw_patch_state) + 1, 64);
    walk->batch_vertices = sw_arena_alloc(arena, SW_BATCH_VERTICES * sizeof(sw_vertex), 64);
    walk->batch_indices = sw_arena_alloc(arena, SW_BATCH_INDICES * sizeof(uint16_t), 64);
    if (!walk->state || !walk->batch_vertices || !walk->batch_indices)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the walk's buffers");
    memset(walk->state, 0, n * sizeof(sw_patch_state));
    return SW_OK;
}

sw_bezier_patchf sw_walk_patch(const sw_walk *walk, uint32_t i)
{
    const sw_pack_patch *p = &walk->pack->patches[i];
    return (sw_bezier_patchf){ p->degree_u, p->degree_v, (p->flags & SW_PATCH_RATIONAL) != 0,
                               walk->pack->control + (size_t)p->first_control * 4 };
}

sw_box sw_walk_patch_box(const sw_walk *walk, uint32_t i)
{
    const sw_pack_patch *p = &walk->pack->patches[i];
    return (sw_box){ sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                     sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
}

static void select_patch(sw_walk *walk, const sw_view *view, uint32_t i, sw_frame_counts *c)
{
    sw_patch_state *s = &walk->state[i];
    sw_box box = sw_walk_patch_box(walk, i);
    s->visible = sw_frustum_test_box(&view->frustum, &box) != SW_CULL_OUTSIDE;
    if (!s->visible)
        return;
    const sw_pack_patch *p = &walk->pack->patches[i];
    double depth = sw_view_box_min_depth(view, &box);
    double error_world = sw_view_error_world(view, walk->error_px, depth);
    sw_deriv_bounds bounds = { p->d2_bound[0], p->d2_bound[1], p->d2_bound[2] };
    uint32_t nu, nv;
    s->capped = !sw_tess_segments_for_error(&bounds, error_world, &nu, &nv);
    s->nu = (uint8_t)nu;
    s->nv = (uint8_t)nv;
    s->min_depth = (float)depth;
    c->visible++;
    c->capped += s->capped;
    c->triangles += 2ull * nu * nv;
}

sw_frame_counts sw_walk_select(sw_walk *walk, const sw_view *view)
{
    sw_frame_counts c = { 0, 0, 0 };
    for (uint32_t i = 0; i < walk->pack->meta->patch_count; i++)
        select_patch(walk, view, i, &c);
    return c;
}

const sw_pack_trim_mask *sw_walk_patch_mask(const sw_walk *walk, uint32_t i)
{
    const sw_pack *pack = walk->pack;
    if (!pack->patch_domains || pack->patch_domains[i].mask == SW_MASK_NONE)
        return NULL;
    return &pack->trim_masks[pack->patch_domains[i].mask];
}

static void flush(sw_walk *walk, sw_renderer *r)
{
    if (walk->batch_index_count)
        sw_renderer_draw(r, walk->batch_vertices, walk->batch_vertex_count, walk->batch_indices,
                         walk->batch_index_count);
    walk->batch_vertex_count = 0;
    walk->batch_index_count = 0;
}

/* Tessellates patch i at the end of the batch; returns the triangles kept. */
static uint32_t add_patch(sw_walk *walk, uint32_t i)
{
    const sw_patch_state *s = &walk->state[i];
    sw_tess_sizes need = sw_tess_grid_sizes(s->nu, s->nv);
    sw_bezier_patchf patch = sw_walk_patch(walk, i);
    uint16_t *indices = walk->batch_indices + walk->batch_index_count;
    sw_tess_grid(&patch, s->nu, s->nv, walk->batch_vertex_count,
                 walk->batch_vertices + walk->batch_vertex_count, indices);
    sw_cell_filter filter;
    sw_cell_filter_init(&filter, sw_walk_patch_mask(walk, i), s->nu, s->nv);
    uint32_t kept = sw_cell_filter_compact(&filter, indices);
    walk->batch_vertex_count += need.vertex_count;
    walk->batch_index_count += kept;
    return kept / 3;
}

static uint64_t draw_part(sw_walk *walk, sw_renderer *r, const sw_pack_part *part)
{
    uint64_t triangles = 0;
    sw_renderer_set_color(r, part->color);
    for (uint32_t i = part->first_patch; i < part->first_patch + part->patch_count; i++) {
        const sw_patch_state *s = &walk->state[i];
        if (!s->visible)
            continue;
        sw_tess_sizes need = sw_tess_grid_sizes(s->nu, s->nv);
        if (walk->batch_vertex_count + need.vertex_count > SW_BATCH_VERTICES ||
            walk->batch_index_count + need.index_count > SW_BATCH_INDICES)
            flush(walk, r);
        triangles += add_patch(walk, i);
    }
    flush(walk, r);
    return triangles;
}

uint64_t sw_walk_draw(sw_walk *walk, sw_renderer *r)
{
    uint64_t triangles = 0;
    for (uint32_t p = 0; p < walk->pack->meta->part_count; p++)
        triangles += draw_part(walk, r, &walk->pack->parts[p]);
    return triangles;
}
