/* SPDX-License-Identifier: MIT */
#include "sw_seam_depth.h"

#include "sw_seam_walk.h"

#include <math.h>

static int drawn(const sw_seam_walk *w, uint32_t s)
{
    /* Out of view, or too small to draw, are not; those facing away count,
     * so that cone culling leaves the depth planes, and so every pixel of
     * what is drawn, as they were; and those drawn by their part's level. */
    return w->visible[s] == 1 || w->visible[s] == SW_SEAM_WALK_AWAY ||
           w->visible[s] == SW_SEAM_WALK_PART;
}

/* The nearest depth at which surface s can be seen, its patch boxes
 * clipped to the view's sides, or best when that is no nearer. Clipping
 * only takes a box's nearest depth farther: a box whose unclipped nearest
 * corner is not before best cannot better it, and is not clipped. */
static double visible_nearest(const sw_seam_walk *w, const sw_view *view, uint32_t s,
                              double best)
{
    const sw_pack_surface *surface = &w->pack->surfaces[s];
    for (uint32_t i = 0; i < surface->patch_count; i++) {
        const sw_pack_patch *p = &w->pack->patches[surface->first_patch + i];
        sw_box b = { sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                     sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
        double near_depth, far_depth;
        sw_box_depth_range(&b, view->eye, view->forward, &near_depth, &far_depth);
        if (near_depth < best)
            best = fmin(best, sw_box_visible_min_depth(&b, &view->frustum, view->eye,
                                                       view->forward));
    }
    return best;
}

/* The nearest depth at which a surface can be seen, over the surfaces whose
 * box starts nearer than far (and at or beyond from, done in a round
 * before): *best the least of theirs, *beyond the nearest box start of
 * the others. */
static void nearest_in_band(const sw_seam_walk *w, const sw_view *view, double from, double far,
                            double *best, double *beyond)
{
    *beyond = INFINITY;
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++) {
        double r = w->cull_near[s];
        if (!drawn(w, s) || r < from)
            continue;
        if (r < far)
            *best = r < *best ? visible_nearest(w, view, s, *best) : *best;
        else
            *beyond = fmin(*beyond, r);
    }
}

int sw_seam_depth_range(const sw_seam_walk *w, const sw_view *view, double *nearest,
                        double *farthest)
{
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++)
        if (drawn(w, s)) {
            lo = fmin(lo, w->cull_near[s]);
            hi = fmax(hi, w->cull_far[s]);
        }
    if (!(lo <= hi))
        return 0;
    /* The select's culling left each surface's nearest (clamped to the near
     * plane) and farthest patch box in view. A box's nearest corner is a
     * poor near plane where the box reaches past the view's sides: a floor
     * the eye stands over starts at the eye, and a near plane there left
     * the depth buffer too coarse to tell a column's front from its back
     * 20 m away. So boxes are clipped to the view's sides, nearest first,
     * in bands of growing depth, until the nearest seen lies before every
     * box not clipped yet; at most a few rounds, each a pass over the
     * surfaces, and few boxes clipped: those near the eye. */
    double best = INFINITY, beyond = INFINITY, from = -INFINITY;
    double band = 8.0 * fmax(lo, view->near_z);
    for (int round = 0; round < 16; round++, from = band, band *= 8.0) {
        nearest_in_band(w, view, from, band, &best, &beyond);
        if (best <= beyond)
            break;
    }
    *nearest = fmax(fmin(fmin(best, beyond), hi), view->near_z);
    *farthest = hi;
    return 1;
}
