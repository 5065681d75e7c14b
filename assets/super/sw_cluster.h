/* SPDX-License-Identifier: MIT */
/* Clustering a pack's surfaces into super-surfaces (paper 000, section 3;
 * core/sw_super.h for what is stored).
 *
 * The unit is the surface, not the Bezier patch: a surface's patches come
 * from one NURBS surface by knot insertion and are grouped first, as the
 * paper does with "the natural structure of the input". A surface's cone
 * is the union of its patches' normal cones (core/sw_normal_cone.h), a
 * proven bound of its pseudo-Gauss map (equation 1); a cluster's span is
 * the half-angle of the smallest cone holding its members' cones, as far
 * as pairwise unions find it.
 *
 * Seeded growth: seeds are taken flattest first (the smallest cone, ties to
 * the larger surface): a flat seed leaves the whole budget alpha for its
 * neighbours, so clusters grow large where the model is flat and the
 * curved surfaces, which fit nowhere, are left for last. A cluster adds,
 * among the unclustered surfaces of its part adjacent to it (sw_surface_
 * adjacency.h), the one whose union increases the span least, while the
 * span stays at most alpha and the caps hold.
 *
 * Better than the paper (its section 7.1): a cluster's size is capped, in
 * surfaces and in triangles of its members' finest static levels, so a
 * large flat region does not become one super-surface whose detail cannot
 * be chosen apart; and clusters with fewer than min_members surfaces are
 * merged into the adjacent cluster of their part whose union has the least
 * span, while that stays at most alpha and within the caps, until no such
 * pair is left. Under one alpha the growth itself leaves no such pair but
 * by rounding: a cluster stops only when every unclustered neighbour would
 * push it past alpha or a cap, and the smallest cone holding two cones
 * only widens as they do, so a later neighbouring cluster holding that
 * surface cannot fit either (0 merges on the teaset and the 2,000-patch
 * showroom). The pass costs one look at each small cluster's neighbours
 * and makes "no two small neighbours that could merge" a guarantee rather
 * than a property of the seed order; the small clusters that remain are
 * the surfaces too curved to share a cone under alpha.
 *
 * A surface whose own cone exceeds alpha (a full cylinder, a sphere) is a
 * cluster alone, with its own span. Host only: allocates. */
#ifndef SW_CLUSTER_H
#define SW_CLUSTER_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_levels.h"
#include "sw_normal_cone.h"
#include "sw_pack.h"
#include "sw_super.h"
#include "sw_surface_adjacency.h"

/* Zero means the default. */
typedef struct sw_cluster_options {
    double alpha_rad;         /* the largest span a cluster grows to, radians, below pi/2
                                 (0: 50 degrees) */
    uint32_t max_members;     /* surfaces per cluster (0: 64) */
    uint32_t max_triangles;   /* triangles of the members' finest levels (0: 16384) */
    uint32_t min_members;     /* clusters below this are small: merged where they can be
                                 (0: 4) */
} sw_cluster_options;

#define SW_CLUSTER_ALPHA_DEFAULT 0.8726646259971648 /* 50 degrees */
#define SW_CLUSTER_MAX_MEMBERS_DEFAULT 64u
#define SW_CLUSTER_MAX_TRIANGLES_DEFAULT 16384u
#define SW_CLUSTER_MIN_MEMBERS_DEFAULT 4u

/* What clustering is given, per surface; the tests build it by hand. */
typedef struct sw_cluster_input {
    uint32_t surface_count;
    const sw_normal_cone *cones;      /* each surface's cone (empty: no normals known) */
    const uint32_t *parts;            /* each surface's part */
    const double *sizes;              /* seeds' tie-break, larger first; NULL: none */
    const uint32_t *triangles;        /* finest level's triangles; NULL: 0 each */
    const sw_surface_adjacency *adjacency;
} sw_cluster_input;

typedef struct sw_cluster_report {
    uint32_t surfaces, clusters;
    uint32_t merged;          /* small clusters merged into a neighbour */
    uint32_t wide_alone;      /* surfaces whose own cone exceeds alpha */
    uint32_t capped;          /* growths stopped by a cap with a neighbour under alpha */
    double seconds;
} sw_cluster_report;

/* Owned arrays, viewed by .view (what the pack writer takes). */
typedef struct sw_clusters_built {
    sw_supers view;
    sw_super_surface *supers;
    uint32_t *members;
    uint32_t *super_of;
} sw_clusters_built;

/* Clusters in (opt may be NULL: defaults; report may be NULL). Records in
 * the order they were grown, members increasing. SW_ERR_ARG for options
 * out of range, SW_ERR_NO_MEMORY; on error *out is empty. */
sw_status sw_cluster_surfaces(const sw_cluster_input *in, const sw_cluster_options *opt,
                              sw_clusters_built *out, sw_cluster_report *report, sw_error *err);

/* The same for a validated pack with a Seam Graph (SW_ERR_ARG otherwise):
 * cones from its patches, adjacency from its graph, triangles from levels
 * (NULL: the pack's own levels, or none). */
sw_status sw_cluster_pack(const sw_pack *pack, const sw_levels *levels,
                          const sw_cluster_options *opt, sw_clusters_built *out,
                          sw_cluster_report *report, sw_error *err);

/* Each surface's cone, the union of its patches' (tight, as the clusters'
 * are): cones[pack->surface_count]. SW_ERR_NO_MEMORY for the scratch. */
sw_status sw_cluster_surface_cones(const sw_pack *pack, sw_normal_cone *cones, sw_error *err);

/* The stored span and axis of a cone (span pi and a zero axis for none). */
void sw_cluster_store_cone(const sw_normal_cone *c, sw_super_surface *rec);

void sw_clusters_built_free(sw_clusters_built *b);

#endif
