/* SPDX-License-Identifier: MIT */
/* A surface's normal cone from its patches (sw_surface_cone.h). */
#include "sw_surface_cone.h"

#include "sw_pack_instances.h"

sw_bezier_patchf sw_pack_patch_view(const sw_pack *pack, uint32_t i, float *room)
{
    const sw_pack_patch *p = &pack->patches[i];
    return (sw_bezier_patchf){ p->degree_u, p->degree_v, (p->flags & SW_PATCH_RATIONAL) != 0,
                               sw_pack_patch_control(pack, i, room) };
}

sw_normal_cone sw_surface_normal_cone(const sw_pack *pack, uint32_t s, int tight, float *room,
                                      double *scratch)
{
    const sw_pack_surface *ps = &pack->surfaces[s];
    sw_normal_cone cone = sw_normal_cone_empty();
    for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
        const sw_bezier_patchf patch = sw_pack_patch_view(pack, i, room);
        sw_normal_cone c = sw_normal_cone_of_patch(&patch, scratch);
        cone = tight ? sw_normal_cone_union_tight(&cone, &c) : sw_normal_cone_union(&cone, &c);
    }
    return cone;
}
