/* SPDX-License-Identifier: MIT */
/* A pack's surface's normal cone: the union of its Bezier patches' cones
 * (sw_normal_cone.h), and the float patch view both take. The walk builds
 * its culling cones with it at load time (firmware/walk/sw_seam_walk.c), the
 * host's clustering its super-surfaces' (assets/super/sw_cluster_pack.c).
 * Pure functions; scratch is the caller's. */
#ifndef SW_SURFACE_CONE_H
#define SW_SURFACE_CONE_H

#include <stdint.h>

#include "sw_bezier.h"
#include "sw_normal_cone.h"
#include "sw_pack.h"

/* Patch i of a validated pack, viewed: its control points the pack's, or
 * where they are placed as they are read (control_local), placed into
 * room (sw_pack_patch_control; NULL for a pack whose points are its own). */
sw_bezier_patchf sw_pack_patch_view(const sw_pack *pack, uint32_t i, float *room);

/* Surface s's cone over its patches; tight: sw_normal_cone_union_tight,
 * else sw_normal_cone_union. room as sw_pack_patch_view's, for one patch
 * at a time; scratch holds
 * sw_normal_cone_scratch_doubles(SW_BEZIER_MAX_DEGREE, SW_BEZIER_MAX_DEGREE)
 * doubles. */
sw_normal_cone sw_surface_normal_cone(const sw_pack *pack, uint32_t s, int tight, float *room,
                                      double *scratch);

#endif
