#include "sw_seam_depth.h"

#include <math.h>

int sw_seam_depth_range(const sw_seam_walk *w, const sw_view *view, double *nearest,
                        double *farthest)
{
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++) {
        /* Out of view, or too small to draw; those facing away count, so
         * that cone culling leaves the depth planes, and so every pixel of
         * what is drawn, as they were. */
        if (w->visible[s] != 1 && w->visible[s] != SW_SEAM_WALK_AWAY)
            continue;
        /* The select's culling left each surface's nearest (already clamped
         * to the near plane) and farthest patch box in view. */
        lo = fmin(lo, w->cull_near[s]);
        hi = fmax(hi, w->cull_far[s]);
    }
    if (!(lo <= hi))
        return 0;
    *nearest = fmax(lo, view->near_z);
    *farthest = hi;
    return 1;
}
