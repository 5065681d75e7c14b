/* SPDX-License-Identifier: MIT */
/* Super-surfaces (paper 000, section 3): the pack's surfaces grouped into
 * clusters of adjacent surfaces of one part whose normals stay within a
 * cone, so that a cluster can be culled, and later drawn, as one. The
 * cluster's span is the half-angle of that cone: every normal of every
 * member (the pseudo-Gauss map of equation 1, bounded by the members'
 * normal cones, core/sw_normal_cone.h) lies within span of its axis.
 *
 * Built on the host (assets/super/sw_cluster.h), stored in the pack's
 * SUPER_SURFACES, SUPER_MEMBERS and SUPER_OF sections (PACK_FORMAT.md,
 * "Super-surfaces") and checked once by the pack reader
 * (sw_pack_validate_super.c), so code walking a validated pack's clusters
 * needs no checks. The runtime does not draw by them yet. */
#ifndef SW_SUPER_H
#define SW_SUPER_H

#include <stdint.h>

/* span at or above this: no cone (the members' normals face every way). */
#define SW_SUPER_SPAN_FULL 1.5707963267948966f /* pi / 2 */

typedef struct sw_super_surface { /* 32 bytes */
    uint32_t first_member;        /* SUPER_MEMBERS[first_member .. + member_count) */
    uint32_t member_count;        /* >= 1 */
    uint32_t part;                /* every member's part (parts are drawn apart) */
    float span;                   /* radians, in [0, pi]: the cone's half-angle;
                                     >= SW_SUPER_SPAN_FULL: no cone */
    float axis[3];                /* unit when span < SW_SUPER_SPAN_FULL, else zero */
    uint32_t reserved;            /* zero */
} sw_super_surface;

/* The clusters as views (host: owned by whoever built them; runtime: into
 * the pack). The records' member ranges tile members in order; members of
 * one record are strictly increasing; super_of is the inverse: surface s
 * is a member of super_of[s]. */
typedef struct sw_supers {
    const sw_super_surface *supers;
    const uint32_t *members;      /* surface_count surface indices */
    const uint32_t *super_of;     /* surface_count cluster indices */
    uint32_t super_count;
    uint32_t surface_count;
} sw_supers;

#endif
