#include "sw_seam_depth.h"

#include <math.h>

/* The depths of box's nearest and farthest corners. */
static void box_range(const sw_view *view, const sw_box *b, double *lo, double *hi)
{
    for (int i = 0; i < 8; i++) {
        sw_vec3 c = sw_v3(i & 1 ? b->max.x : b->min.x, i & 2 ? b->max.y : b->min.y,
                          i & 4 ? b->max.z : b->min.z);
        double d = sw_view_depth(view, c);
        *lo = fmin(*lo, d);
        *hi = fmax(*hi, d);
    }
}

int sw_seam_depth_range(const sw_seam_walk *w, const sw_view *view, double *nearest,
                        double *farthest)
{
    const sw_pack *pack = w->pack;
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t s = 0; s < pack->seam.surface_count; s++) {
        if (w->visible[s] != 1) /* out of view, or too small to draw */
            continue;
        const sw_pack_surface *ps = &pack->surfaces[s];
        for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
            const sw_pack_patch *p = &pack->patches[i];
            sw_box box = { sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                           sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
            if (sw_frustum_test_box(&view->frustum, &box) != SW_CULL_OUTSIDE)
                box_range(view, &box, &lo, &hi);
        }
    }
    if (!(lo <= hi))
        return 0;
    *nearest = fmax(lo, view->near_z);
    *farthest = hi;
    return 1;
}
