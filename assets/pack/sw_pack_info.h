/* SPDX-License-Identifier: MIT */
/* What `seamwalk-pack info` reports about a validated pack: counts for the
 * whole pack and per part (surfaces, Bezier patches, trimming loops and
 * curves, degrees, rational counts, parameter curves computed by point
 * inversion, bounding box), the Seam Graph's counts and bytes when the
 * pack has one and the static levels' counts, bytes and errors per rank
 * when it has them, printed as aligned text or as JSON with stable
 * snake_case keys. Split from seamwalk_pack_main.c so the numbers can be
 * tested without parsing output. Host only. */
#ifndef SW_PACK_INFO_H
#define SW_PACK_INFO_H

#include <stdint.h>
#include <stdio.h>

#include "sw_pack.h"

typedef struct sw_pack_part_stats {
    uint32_t surfaces;            /* SURFACES of the part; without that section one per patch */
    uint32_t trimmed_surfaces;    /* of them, with at least one loop */
    uint32_t patches;             /* Bezier patches after knot insertion */
    uint32_t rational_patches;
    uint32_t rational_surfaces;   /* surfaces with a rational patch */
    uint32_t loops, curves;       /* trimming loops and curves of its surfaces */
    uint32_t rational_curves;
    uint32_t computed_curves;     /* SW_TRIM_COMPUTED: made by point inversion */
    int degree_min[2], degree_max[2]; /* patches, u and v; 0 when there are none */
    int trim_degree_min, trim_degree_max; /* 0 when there are no curves */
    float box_min[3], box_max[3]; /* of its patches; zero when it has none */
} sw_pack_part_stats;

/* One pass over the pack: parts[i] for each of META.part_count parts (the
 * caller's array), *total for the whole pack. */
void sw_pack_gather_stats(const sw_pack *pack, sw_pack_part_stats *parts,
                          sw_pack_part_stats *total);

/* The Seam Graph's size, for comparing with the paper's memory figures
 * (Guthe et al. 2002, section 7: about 320 bytes per boundary edge). */
typedef struct sw_pack_seam_stats {
    uint32_t vertices, original_vertices, created_vertices;
    uint32_t slots, loops, edges, collapses;
    float tolerance;
    uint64_t bytes;                 /* the eight seam sections' sizes, padding not counted */
    double bytes_per_edge;          /* bytes / edges (the paper's boundary edges) */
    double bytes_per_surface;       /* bytes / surfaces (the paper's patches) */
    double bytes_per_bezier_patch;  /* bytes / Bezier patches; each ratio 0 when dividing by 0 */
} sw_pack_seam_stats;

/* Fills *out and returns 1 when the pack has a Seam Graph; 0 otherwise. */
int sw_pack_gather_seam_stats(const sw_pack *pack, sw_pack_seam_stats *out);

/* The static levels (core/sw_levels.h), per rank: rank 0 is each surface's
 * finest level, rank 1 the next, and so on. */
typedef struct sw_pack_level_rank_stats {
    uint32_t levels;                /* surfaces with a level of this rank */
    uint64_t triangles;             /* their triangles together */
    uint64_t triangles_before;      /* the same surfaces' triangles one rank finer (rank 0:
                                       0): 1 - triangles / triangles_before is the
                                       reduction of this level */
    float error_max;                /* the largest of their errors */
    float error_median;             /* the middle one (the lower for an even count) */
} sw_pack_level_rank_stats;

typedef struct sw_pack_levels_stats {
    uint32_t levels;
    uint32_t per_surface_min, per_surface_max; /* levels of a surface, over every surface */
    uint32_t vertices, indices, triangles, chain_points;
    uint64_t bytes;                 /* the seven level sections' sizes, padding not counted */
    uint32_t rank_count;            /* per_surface_max */
    sw_pack_level_rank_stats ranks[SW_LEVELS_MAX];
} sw_pack_levels_stats;

/* Fills *out when the pack has levels (all zero otherwise). SW_ERR_NO_MEMORY
 * when the errors cannot be gathered for the medians. */
sw_status sw_pack_gather_levels_stats(const sw_pack *pack, sw_pack_levels_stats *out,
                                      sw_error *err);

/* The super-surfaces (core/sw_super.h): how many, their members, spans and
 * the triangles of their members' finest static levels together. Medians
 * are the lower middle for an even count. */
typedef struct sw_pack_super_stats {
    uint32_t supers;
    uint32_t members_min, members_median, members_max;
    uint32_t no_cone;               /* spans of pi/2 or more: no cone to cull by */
    float span_median;              /* radians, over every super-surface */
    float span_max_cone;            /* radians, the largest below pi/2 (0: none) */
    int with_triangles;             /* the pack has levels: the triangles below are known */
    uint64_t triangles_min, triangles_median, triangles_max;
    uint64_t bytes;                 /* the three sections' sizes */
} sw_pack_super_stats;

/* Fills *out when the pack has super-surfaces (all zero otherwise).
 * SW_ERR_NO_MEMORY when the medians' scratch cannot be allocated. In
 * sw_pack_info_super.c, with the report's lines below. */
sw_status sw_pack_gather_super_stats(const sw_pack *pack, sw_pack_super_stats *out,
                                     sw_error *err);

/* The text line(s), nothing for a pack without super-surfaces. */
void sw_pack_print_super_text(FILE *out, const sw_pack *pack, const sw_pack_super_stats *s);

/* "super_surfaces": {...}, or null for a pack without them. */
void sw_pack_print_super_json(FILE *out, const sw_pack *pack, const sw_pack_super_stats *s);

/* The part levels (core/sw_part_levels.h): parts with them, and per rank
 * the levels, triangles and largest error (sw_pack_info_part_levels.c).
 * Text: nothing without them; JSON: "part_levels": {...} or null. */
void sw_pack_print_part_levels_text(FILE *out, const sw_pack *pack);
void sw_pack_print_part_levels_json(FILE *out, const sw_pack *pack);

/* "mm", "m" or "unspecified" for META.units. */
const char *sw_pack_units_name(uint32_t units);

/* The info report of the pack read from path, to out. SW_ERR_NO_MEMORY when
 * the per-part table cannot be allocated (nothing printed then). */
sw_status sw_pack_print_info(FILE *out, const char *path, const sw_pack *pack, int json,
                             sw_error *err);

/* The placed parts (sw_pack_info_instances.c): the box of the placed
 * scene (the stored box for a pack without instances), and the
 * prototypes, instances and placed counts, as text and as JSON keys
 * (prototype_count, instance_count, placed, prototypes, instances; the
 * counts 0 and nothing else without instances). */
void sw_pack_placed_box(const sw_pack *pack, float lo[3], float hi[3]);
void sw_pack_print_instances_text(FILE *out, const sw_pack *pack);
void sw_pack_print_instances_json(FILE *out, const sw_pack *pack);

/* The parts a pack of placed parts places, as info lists them: each
 * instance's copy of its prototype's parts, named and coloured by the
 * instance, its first patch in the placed scene, its transform the
 * instance's, its stats the stored part's (stored[part]) with the box it is
 * placed in; total sums them. Arrays malloc'd; free with
 * sw_pack_placed_parts_free. */
typedef struct sw_pack_placed_parts {
    uint32_t count;
    sw_pack_part *parts;
    float *transforms;
    sw_pack_part_stats *stats;
    sw_pack_part_stats total;
} sw_pack_placed_parts;
sw_status sw_pack_place_parts(const sw_pack *pack, const sw_pack_part_stats *stored,
                              sw_pack_placed_parts *out, sw_error *err);
void sw_pack_placed_parts_free(sw_pack_placed_parts *p);

/* s's counts added to sum (degrees and boxes widened). */
void sw_pack_stats_add(sw_pack_part_stats *sum, const sw_pack_part_stats *s);

/* s (at most max bytes) as a JSON string. */
void sw_pack_json_string(FILE *out, const char *s, size_t max);

#endif
