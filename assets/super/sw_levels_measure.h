/* SPDX-License-Identifier: MIT */
/* A level's error, measured apart from how it was made: every triangle
 * sampled on a barycentric grid and compared with the exact surface at the
 * same (u, v) (sw_surface_at.h). Host only. */
#ifndef SW_LEVELS_MEASURE_H
#define SW_LEVELS_MEASURE_H

#include <stdint.h>

#include "sw_trim_tess.h"

/* The largest distance found, over the points of a grid of n + 1 points a
 * side (n >= 1) on each triangle of the mesh (positions and uvs per vertex,
 * triangles of local indices), between the point and the surface at its
 * (u, v) interpolated the same way. */
double sw_levels_measure(const sw_trim_patch *patches, uint32_t patch_count,
                         const float *positions, const float *uvs, const uint16_t *indices,
                         uint32_t index_count, uint32_t n);

#endif
