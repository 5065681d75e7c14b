/* SPDX-License-Identifier: MIT */
/* V's part levels (core/sw_part_levels.h): a part far enough away is
 * drawn whole from one simplified mesh, one draw, instead of surface by
 * surface. Chosen each frame after culling: the coarsest level whose
 * measured error is within the bound at the part's nearest depth in view
 * (its surfaces' nearest patch boxes), so every surface it stands for is
 * drawn within that surface's own bound, and whose area shaded wrong is at
 * most a square of SHADING_SIDE_PX there: a level's error bounds its
 * shape, not its normals. Its surfaces are then neither
 * drawn nor given work; out of its levels' reach, the part is drawn by its
 * surfaces again, at once from their static levels where the meshes are
 * not made yet. */
#include <math.h>

#include "sw_seam_walk_internal.h"

/* The side, in pixels, of the most area a part level may shade wrong: a
 * few pixels of a part, where the error bound alone would let a level
 * shade a face as the faces around it. */
#define SHADING_SIDE_PX 2.0

static int in_view(uint8_t v)
{
    return v == 1 || v == SW_SEAM_WALK_TINY || v == SW_SEAM_WALK_AWAY;
}

/* The coarsest level of part p within bound and shading_bound, UINT32_MAX
 * when none is. */
static uint32_t coarsest_within(const sw_part_levels *pl, uint32_t p, double bound,
                                double shading_bound)
{
    for (uint32_t i = pl->part_levels[p + 1]; i > pl->part_levels[p]; i--)
        if (pl->levels[i - 1].error <= bound && pl->levels[i - 1].shading_side <= shading_bound)
            return i - 1;
    return UINT32_MAX;
}

void sw_seam_walk_choose_parts(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame)
{
    const sw_part_levels *pl = w->part_levels;
    if (!pl)
        return;
    uint32_t n = w->pack->seam.surface_count;
    for (uint32_t p = 0; p < pl->part_count; p++)
        w->part_depth[p] = INFINITY, w->part_level[p] = UINT32_MAX;
    for (uint32_t s = 0; s < n; s++) {
        uint32_t p = w->pack->surfaces[s].part;
        if (in_view(w->visible[s]))
            w->part_depth[p] = fmin(w->part_depth[p], w->cull_near[s]);
    }
    for (uint32_t p = 0; p < pl->part_count; p++) {
        if (!isfinite(w->part_depth[p]))
            continue;
        double bound = w->part_levels_coarsest
                           ? INFINITY
                           : sw_view_error_world(view, w->error_px,
                                                 fmax(w->part_depth[p], view->near_z));
        w->part_level[p] = coarsest_within(pl, p, bound, bound * (SHADING_SIDE_PX / w->error_px));
    }
    for (uint32_t s = 0; s < n; s++)
        if (in_view(w->visible[s]) && w->part_level[w->pack->surfaces[s].part] != UINT32_MAX) {
            w->visible[s] = SW_SEAM_WALK_PART;
            w->evictable[s] = 1;
            frame->covered_surfaces++;
        }
}

void sw_seam_walk_plan_parts(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame)
{
    const sw_part_levels *pl = w->part_levels;
    frame->drawn_surfaces += frame->covered_surfaces;   /* drawn, through their parts */
    for (uint32_t p = 0; pl && p < pl->part_count; p++) {
        if (w->part_level[p] == UINT32_MAX)
            continue;
        const sw_part_level *l = &pl->levels[w->part_level[p]];
        const sw_seam_draw_item item = {
            .surface = UINT32_MAX, .part = p, .first_vertex = l->first_vertex,
            .first_index = l->first_index, .vertex_count = l->vertex_count,
            .index_count = l->index_count, .depth = (float)w->part_depth[p], .part_level = 1 };
        sw_seam_plan_draw(plan, &item);
        frame->part_levels++;
        frame->part_level_triangles += l->index_count / 3;
        frame->triangles += l->index_count / 3;
    }
}
