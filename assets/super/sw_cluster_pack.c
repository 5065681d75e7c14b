/* SPDX-License-Identifier: MIT */
/* sw_cluster_pack (sw_cluster.h): a validated pack's surfaces as the
 * clustering's input: each surface's cone from its patches, its size (the
 * diagonal of its patches' boxes), its finest level's triangles and the
 * adjacency of the Seam Graph. */
#include "sw_cluster.h"

#include <math.h>
#include <stdlib.h>

#include "sw_surface_cone.h"

sw_status sw_cluster_surface_cones(const sw_pack *pack, sw_normal_cone *cones, sw_error *err)
{
    size_t doubles = sw_normal_cone_scratch_doubles(SW_BEZIER_MAX_DEGREE, SW_BEZIER_MAX_DEGREE);
    double *scratch = malloc(doubles * sizeof *scratch);
    if (!scratch)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "clustering: out of memory for the cones' "
                            "scratch");
    for (uint32_t s = 0; s < pack->surface_count; s++)
        cones[s] = sw_surface_normal_cone(pack, s, 1, NULL, scratch);
    free(scratch);
    return SW_OK;
}

/* The diagonal of the box of surface s's patches' control hulls. */
static double surface_size(const sw_pack *pack, uint32_t s)
{
    return sw_pack_patches_diagonal(pack->patches, pack->surfaces[s].first_patch,
                                    pack->surfaces[s].patch_count);
}

/* Surface s's finest level's triangles, 0 without levels. */
static uint32_t finest_triangles(const sw_levels *l, uint32_t s)
{
    if (!l || !l->surface_levels || s >= l->surface_count ||
        l->surface_levels[s] == l->surface_levels[s + 1])
        return 0;
    return l->levels[l->surface_levels[s]].index_count / 3;
}

sw_status sw_cluster_pack(const sw_pack *pack, const sw_levels *levels,
                          const sw_cluster_options *opt, sw_clusters_built *out,
                          sw_cluster_report *report, sw_error *err)
{
    if (!pack->seam_header)
        return sw_error_set(err, SW_ERR_ARG, "clustering: the pack has no Seam Graph (its "
                            "adjacency)");
    if (!levels && pack->levels_header)
        levels = &pack->levels;
    uint32_t n = pack->surface_count;
    sw_normal_cone *cones = malloc(((size_t)n + 1) * sizeof *cones);
    uint32_t *parts = malloc(((size_t)n + 1) * sizeof *parts);
    uint32_t *triangles = malloc(((size_t)n + 1) * sizeof *triangles);
    double *sizes = malloc(((size_t)n + 1) * sizeof *sizes);
    sw_surface_adjacency adjacency = { 0 };
    sw_status st = !cones || !parts || !triangles || !sizes
                       ? sw_error_set(err, SW_ERR_NO_MEMORY, "clustering: out of memory")
                       : sw_cluster_surface_cones(pack, cones, err);
    for (uint32_t s = 0; st == SW_OK && s < n; s++) {
        parts[s] = pack->surfaces[s].part;
        triangles[s] = finest_triangles(levels, s);
        sizes[s] = surface_size(pack, s);
    }
    if (st == SW_OK)
        st = sw_surface_adjacency_build(&pack->seam, &adjacency, err);
    if (st == SW_OK) {
        const sw_cluster_input in = { .surface_count = n, .cones = cones, .parts = parts,
                                      .sizes = sizes, .triangles = triangles,
                                      .adjacency = &adjacency };
        st = sw_cluster_surfaces(&in, opt, out, report, err);
    }
    sw_surface_adjacency_free(&adjacency);
    free(cones);
    free(parts);
    free(triangles);
    free(sizes);
    return st;
}
