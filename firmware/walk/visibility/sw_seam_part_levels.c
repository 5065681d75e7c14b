/* SPDX-License-Identifier: MIT */
/* V's part levels (core/sw_part_levels.h): a part far enough away is
 * drawn whole from simplified meshes, one draw a piece, instead of surface
 * by surface. Chosen each frame after culling: for each piece in view the
 * coarsest level whose measured error is within the bound at the piece's
 * nearest depth in view (its surfaces' nearest patch boxes), so every
 * surface it stands for is drawn within that surface's own bound, and
 * whose area shaded wrong is at most a square of SHADING_SIDE_PX there: a
 * level's error bounds its shape, not its normals. A part cut into pieces
 * is drawn whole from a level of its own when one is within the bound at
 * its nearest depth; else from its pieces' levels when every piece of it
 * in view has one at the same front (their borders then meet vertex for
 * vertex), the coarsest such front; else, as a part none of whose levels
 * is within reach, by its surfaces again, at once from their static levels where
 * the meshes are not made yet. The surfaces a piece stands for are neither
 * drawn nor given work. */
#include <math.h>

#include "sw_seam_walk_internal.h"

/* The side, in pixels, of the most area a part level may shade wrong: a
 * few pixels of a part, where the error bound alone would let a level
 * shade a face as the faces around it. */
#define SHADING_SIDE_PX 2.0

/* part_level of a piece drawn by its part's level of itself whole: covered,
 * not drawn on its own (above every level index). */
#define SW_SEAM_PIECE_COVERED (UINT32_MAX - 1)

static int in_view(uint8_t v)
{
    return v == 1 || v == SW_SEAM_WALK_TINY || v == SW_SEAM_WALK_AWAY;
}

sw_status sw_seam_walk_init_parts(sw_seam_walk *w, sw_arena *arena, sw_error *err)
{
    const sw_part_levels *pl = &w->pack->part_levels;
    uint32_t parts = w->pack->meta->part_count;
    w->part_levels = NULL;
    if (!pl->levels || w->no_part_levels)
        return SW_OK;
    w->part_level = sw_arena_alloc(arena, ((size_t)pl->piece_count + 1) * sizeof(uint32_t), 64);
    w->part_depth = sw_arena_alloc(arena, ((size_t)pl->piece_count + 1) * sizeof(double), 64);
    w->piece_part = sw_arena_alloc(arena, ((size_t)pl->piece_count + 1) * sizeof(uint32_t), 64);
    w->part_pieces = sw_arena_alloc(arena, ((size_t)parts + 1) * sizeof(uint32_t), 64);
    if (!w->part_level || !w->part_depth || !w->piece_part || !w->part_pieces)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the part levels' "
                            "state");
    /* The reader checked that the pieces follow the parts, each a run of
     * surfaces: a part's first piece is that of its first surface. */
    for (uint32_t p = 0; p <= parts; p++)
        w->part_pieces[p] = pl->piece_count;
    for (uint32_t s = pl->surface_count; s-- > 0;) {
        uint32_t p = w->pack->surfaces[s].part;
        w->part_pieces[p] = pl->piece_of[s];
        w->piece_part[pl->piece_of[s]] = p;
    }
    for (uint32_t p = parts; p-- > 0;)   /* a part without surfaces has no piece */
        if (w->part_pieces[p] > w->part_pieces[p + 1])
            w->part_pieces[p] = w->part_pieces[p + 1];
    for (uint32_t g = 0; g < pl->piece_count; g++)
        w->part_level[g] = UINT32_MAX, w->part_depth[g] = INFINITY;
    w->part_levels = pl;
    return SW_OK;
}

/* The coarsest level of piece g at front f within bound and shading_bound,
 * UINT32_MAX when none is. */
static uint32_t coarsest_within(const sw_part_levels *pl, uint32_t g, uint32_t f, double bound,
                                double shading_bound)
{
    for (uint32_t i = pl->piece_levels[g + 1]; i > pl->piece_levels[g]; i--) {
        const sw_part_level *l = &pl->levels[i - 1];
        if (l->front == f && l->error <= bound && l->shading_side <= shading_bound)
            return i - 1;
    }
    return UINT32_MAX;
}

/* Piece g's coarsest level at front f within the bound at depth. */
static uint32_t level_at(const sw_seam_walk *w, const sw_view *view, uint32_t g, uint32_t f,
                         double depth)
{
    double bound = w->part_levels_coarsest
                       ? INFINITY
                       : sw_view_error_world(view, sw_seam_walk_error_px(w),
                                             fmax(depth, view->near_z));
    return coarsest_within(w->part_levels, g, f, bound, bound * (SHADING_SIDE_PX / w->error_px));
}

/* Cut part p (pieces [a, b)) whole from a level of its own, kept with its
 * first piece, the other pieces marked covered by it; 0 when none is
 * within the bound at its nearest depth in view. */
static int choose_whole(sw_seam_walk *w, const sw_view *view, uint32_t a, uint32_t b)
{
    double depth = INFINITY;
    for (uint32_t g = a; g < b; g++)
        depth = fmin(depth, w->part_depth[g]);
    uint32_t l = isfinite(depth) ? level_at(w, view, a, SW_PART_LEVEL_WHOLE, depth) : UINT32_MAX;
    if (l == UINT32_MAX)
        return 0;
    for (uint32_t g = a; g < b; g++)
        w->part_level[g] = SW_SEAM_PIECE_COVERED;
    w->part_level[a] = l, w->part_depth[a] = depth;
    return 1;
}

/* Part p's pieces in view, each from its coarsest level within its bound
 * at one front, the coarsest front that serves them all; none when no
 * front does. A cut part whole first, where a level of its own serves. */
static void choose_part(sw_seam_walk *w, const sw_view *view, uint32_t p)
{
    uint32_t a = w->part_pieces[p], b = w->part_pieces[p + 1];
    if (b - a > 1 && choose_whole(w, view, a, b))
        return;
    uint32_t fronts = b - a > 1 ? SW_PART_LEVEL_FRONTS : 1;
    for (uint32_t f = fronts; f-- > 0;) {
        int all = 1, any = 0;
        for (uint32_t g = a; g < b && all; g++) {
            if (!isfinite(w->part_depth[g]))
                continue;
            w->part_level[g] = level_at(w, view, g, f, w->part_depth[g]);
            all = w->part_level[g] != UINT32_MAX, any = 1;
        }
        if (any && all)
            return;
        for (uint32_t g = a; g < b; g++)
            w->part_level[g] = UINT32_MAX;
    }
}

void sw_seam_walk_choose_parts(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame)
{
    const sw_part_levels *pl = w->part_levels;
    if (!pl)
        return;
    uint32_t n = w->pack->seam.surface_count;
    for (uint32_t g = 0; g < pl->piece_count; g++)
        w->part_depth[g] = INFINITY, w->part_level[g] = UINT32_MAX;
    for (uint32_t s = 0; s < n; s++) {
        uint32_t g = pl->piece_of[s];
        if (in_view(w->visible[s]))
            w->part_depth[g] = fmin(w->part_depth[g], w->cull_near[s]);
    }
    for (uint32_t p = 0; p < w->pack->meta->part_count; p++)
        choose_part(w, view, p);
    for (uint32_t s = 0; s < n; s++)
        if (in_view(w->visible[s]) && w->part_level[pl->piece_of[s]] != UINT32_MAX) {
            w->visible[s] = SW_SEAM_WALK_PART;
            w->evictable[s] = 1;
            frame->covered_surfaces++;
        }
}

void sw_seam_walk_plan_parts(sw_seam_walk *w, sw_seam_plan *plan, sw_seam_frame *frame)
{
    const sw_part_levels *pl = w->part_levels;
    frame->drawn_surfaces += frame->covered_surfaces;   /* drawn, through their pieces */
    for (uint32_t g = 0; pl && g < pl->piece_count; g++) {
        if (w->part_level[g] >= SW_SEAM_PIECE_COVERED)
            continue;   /* none, or drawn by its part's level of itself whole */
        const sw_part_level *l = &pl->levels[w->part_level[g]];
        const sw_seam_draw_item item = {
            .surface = UINT32_MAX, .part = w->piece_part[g], .first_vertex = l->first_vertex,
            .first_index = l->first_index, .vertex_count = l->vertex_count,
            .index_count = l->index_count, .depth = (float)w->part_depth[g], .part_level = 1 };
        sw_seam_plan_draw(plan, &item);
        frame->part_levels++;
        frame->part_level_triangles += l->index_count / 3;
        frame->triangles += l->index_count / 3;
    }
}
