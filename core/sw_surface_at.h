/* SPDX-License-Identifier: MIT */
/* The exact surface of a trimmed surface's patches at a (u, v), and how far
 * its sewn border lies from it: what every measurement of drawn or stored
 * triangles against the surface uses (the walk's error, the static levels'
 * stored error, the benchmarks). No allocation; GL-free. */
#ifndef SW_SURFACE_AT_H
#define SW_SURFACE_AT_H

#include <stdint.h>

#include "sw_math.h"
#include "sw_seam_graph.h"
#include "sw_trim_tess.h"

/* The point at (u, v) of the patch whose domain holds it (the nearest one
 * for points an ulp outside). */
sw_vec3 sw_surface_at(const sw_trim_patch *patches, uint32_t patch_count, double u, double v);

/* The same at many (u, v) of one surface in a row (a level's samples): the
 * patch found last is tried first, its control points made double once.
 * Only where the surface's patch domains do not overlap, so the answers
 * are sw_surface_at's; otherwise (or past SW_SURFACE_SAMPLER_PAIRS
 * patches, where checking each pair would cost more than it saves) every
 * point is looked up as there. */
#define SW_SURFACE_SAMPLER_PAIRS 256u
typedef struct sw_surface_sampler {
    const sw_trim_patch *patches;
    uint32_t patch_count;
    int disjoint;
    const sw_trim_patch *last;    /* NULL: none yet */
    sw_bezier_patch exact;        /* last's, in ctrl */
    double ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
} sw_surface_sampler;
void sw_surface_sampler_init(sw_surface_sampler *s, const sw_trim_patch *patches,
                             uint32_t patch_count);
sw_vec3 sw_surface_sampler_at(sw_surface_sampler *s, double u, double v);

/* The largest distance of loop's sewn polyline (its slots at full detail and
 * the middle of each segment) from the surface at the same (u, v): the
 * file's own gaps, which sewing joins across and no level of detail makes
 * smaller. Only sewn points count: where the pack's hierarchy was cut at a
 * floor (assets/seam/sw_seam_reroot.h), a vertex with an error of its own
 * stands for a level of detail, whose distance from the surface is error
 * to be measured, not a gap to be forgiven; so the slots of such vertices,
 * and the segments with one at an end, are left out. */
double sw_seam_sewing_offset(const sw_seam_graph *g, const sw_seam_loop *loop,
                             const sw_trim_patch *patches, uint32_t patch_count);

/* The same for a loop of slot_count slots read through at (the walk's
 * fronts, whose graphs are the prototypes', placed as they are read):
 * slot k's position, parameters and vertex error. */
typedef struct sw_sewn_point {
    float p[3], uv[2], error;
} sw_sewn_point;
typedef void (*sw_sewn_point_fn)(const void *ctx, uint32_t k, sw_sewn_point *out);
double sw_seam_sewing_offset_of(uint32_t slot_count, sw_sewn_point_fn at, const void *ctx,
                                const sw_trim_patch *patches, uint32_t patch_count);

#endif
