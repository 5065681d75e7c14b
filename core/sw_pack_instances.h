/* SPDX-License-Identifier: MIT */
/* Packs of placed parts (version 2, PACK_FORMAT.md "Prototypes and
 * instances"): a part used many times in a scene is stored once, as a
 * prototype (a run of every index space that indexes nothing outside
 * itself), and each placement is an instance: the prototype, a similarity
 * transform (rotation, uniform scale, translation), a colour and a name.
 *
 * The reader maps and checks the two sections (sw_pack_map_instances).
 * sw_pack_expand then makes the placed scene as an ordinary pack view: each
 * instance's parts, patches, Seam Graph, levels and part levels moved into
 * place, in arena memory. The trims, the levels' indices and chains and
 * the part levels' indices are parametric or local, so the view shares
 * them with the prototypes instead of copying them.
 *
 * This expansion copies every instance's positions (the runtime's shares
 * the static and part levels' vertices): memory grows with the instance
 * count. It
 * is the step before a walk that keeps per instance only what the view
 * needs. The same moving of a run of records, without a
 * transform, joins packs built apart (sw_pack_block.h). */
#ifndef SW_PACK_INSTANCES_H
#define SW_PACK_INSTANCES_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_pack.h"
#include "sw_walk_memory.h"

/* Maps PROTOTYPES and INSTANCES into out (called last by the reader, on a
 * pack whose other sections are valid) and checks every rule: the runs
 * tile each space, every record of a prototype indexes only its own runs,
 * every transform is a similarity without a mirror that keeps the placed
 * coordinates finite, and the placed scene's counts fit their indices. */
sw_status sw_pack_map_instances(const uint8_t *data, sw_pack *out, sw_error *err);

/* A pack's record counts per space, as stored. */
void sw_pack_space_counts(const sw_pack *pack, uint64_t counts[SW_SPACE_COUNT]);

/* Counts of the placed scene per space: instance k adds its prototype's. */
void sw_pack_placed_counts(const sw_pack_prototype *prototypes, const sw_pack_instance *instances,
                           uint32_t instance_count, uint64_t counts[SW_SPACE_COUNT]);

/* Arena bytes sw_pack_expand takes for a placed scene of those counts,
 * worst case (alignment included); and sw_pack_expand_shared (the
 * runtime's, counted in runtime_bytes). */
uint64_t sw_pack_expand_bytes(const uint64_t counts[SW_SPACE_COUNT]);
uint64_t sw_pack_expand_shared_bytes(const uint64_t counts[SW_SPACE_COUNT]);

/* The same as the runtime takes it (sw_pack_expand_shared) for placed
 * (graph: the pack has a Seam Graph): without the seams' vertices, slots,
 * collapses and slot references where the walk's fronts read them per
 * instance (sw_seam_fronts_bytes chooses that layout). */
uint64_t sw_pack_expand_runtime_bytes(int graph, const sw_walk_placed *placed);

/* runtime_bytes of an instanced pack: the per-patch state, the expansion
 * and the walk over the placed scene (stored: the pack's own Seam Graph
 * and surfaces, whose largest surface sizes the walk's buffers; NULL
 * graph: no walk). */
uint64_t sw_pack_instanced_runtime_bytes(const sw_seam_graph *stored,
                                         const sw_pack_surface *surfaces,
                                         const sw_walk_placed *placed);

/* runtime_bytes of a validated pack, placed or not. */
uint64_t sw_pack_runtime_bytes_of(const sw_pack *pack);

/* A validated pack's runtime_bytes pool by pool (they add up to it): the
 * 64 bytes of alignment, the placed scene's expansion (version 2; 0
 * otherwise) and the walk's pools (sw_walk_memory.h). */
typedef struct sw_runtime_pools {
    uint64_t alignment, placed;
    uint64_t walk[SW_WALK_POOL_COUNT];
} sw_runtime_pools;
void sw_pack_runtime_pools(const sw_pack *pack, sw_runtime_pools *out);

/* Those pools as a list of names and bytes, in runtime_bytes' order (the
 * alignment, the placed scene, then the walk's): returns
 * SW_RUNTIME_POOL_COUNT. */
enum { SW_RUNTIME_POOL_COUNT = 2 + SW_WALK_POOL_COUNT };
int sw_runtime_pool_list(const sw_runtime_pools *pools, const char *names[SW_RUNTIME_POOL_COUNT],
                         uint64_t bytes[SW_RUNTIME_POOL_COUNT]);

/* The placed scene of a validated pack as a view in out: everything the
 * walk reads (the header, the section table, viewpoints, orientation and
 * notes stay the pack's). A pack without instances is copied as it is
 * (*out = *pack), taking nothing. SW_ERR_NO_MEMORY when the arena is
 * short of sw_pack_expand_bytes. */
sw_status sw_pack_expand(const sw_pack *pack, sw_arena *arena, sw_pack *out, sw_error *err);

/* The same as the runtime holds it: where the walk's fronts read the
 * seams per instance (sw_seam_fronts.h), the placed graph keeps its
 * counts, loops and surfaces' loops, its vertices, slots, collapses and
 * slot references NULL (sw_pack_expand_runtime_bytes); the static and part levels' vertices
 * are not copied per instance but shared with the prototypes, in their
 * frames (out->level_vertices_local = 1; each level's first_vertex indexes
 * the pack's own LEVEL_VERTICES or PART_LEVEL_VERTICES): whoever reads them
 * places a surface's or a piece's with its part's transform
 * (out->part_transforms), as the stand-ins are made
 * (firmware/walk/visibility/sw_seam_standin.c) and the part levels drawn
 * (the GL thread's model matrix). So are the static levels' records
 * (out->stored_surface names each surface's stored one, whose records
 * sw_pack_surface_levels and sw_pack_level read, scaled as drawn;
 * out->levels.surface_levels is NULL), and the patches' domains
 * (sw_pack_domain_of; out->patch_domains is NULL). The patches' control points are shared
 * so too (out->control_local = 1, out->control the pack's own CONTROL,
 * which each patch's first_control indexes): whoever reads them places a
 * patch's with sw_pack_patch_control; the patches' boxes are the placed
 * points' and their second-derivative bounds INFINITY (the walk takes
 * none). What the walk never reads is left out:
 * the seam edges, the patches' adjacency and the super-surfaces (their
 * counts 0, their pointers NULL). A pack without instances is copied as it is, its
 * vertices placed already. */
sw_status sw_pack_expand_shared(const sw_pack *pack, sw_arena *arena, sw_pack *out,
                                sw_error *err);

/* The vertices of static level rec (of surface s) as drawn, into out
 * (rec->vertex_count of them): where pack shares them with its prototype
 * (level_vertices_local), placed by s's part's transform with the mover
 * the expansion uses, so the same floats as sw_pack_expand's copy; else
 * as stored. */
void sw_pack_level_vertices(const sw_pack *pack, uint32_t s, const sw_level *rec,
                            sw_level_vertex *out);

/* Surface s's static levels: the records [*first, *end) of
 * pack->levels.levels, none when it has none. Where pack shares them with
 * its prototype (stored_surface), they are the prototype's surface's
 * stored records, read with sw_pack_level; else the pack's own. */
void sw_pack_surface_levels(const sw_pack *pack, uint32_t s, uint32_t *first, uint32_t *end);

/* The domain of surface s's patch i (of its patch_count): where pack
 * shares them (stored_surface), its prototype's surface's stored one
 * (the same: a domain is parametric); else the pack's own; NULL without
 * PATCH_DOMAINS. */
const sw_pack_patch_domain *sw_pack_domain_of(const sw_pack *pack, uint32_t s, uint32_t i);

/* Record k of surface s's levels as drawn: where shared, its error and
 * made_bound scaled by s's part's transform as sw_pack_expand scales them
 * (the same floats) and its surface s; else the pack's record. */
sw_level sw_pack_level(const sw_pack *pack, uint32_t s, uint32_t k);

/* The control points of patch i as drawn ((degree_u + 1) (degree_v + 1)
 * of them, 4 floats each): where pack shares them with its prototype
 * (control_local), placed by the patch's part's transform into room
 * (which must hold them; SW_BEZIER_MAX_ORDER^2 points at most) with the
 * mover the expansion uses, so the same floats as sw_pack_expand's copy;
 * else the pack's own (room untouched, may be NULL). */
const float *sw_pack_patch_control(const sw_pack *pack, uint32_t i, float *room);

/* The name of a prototype's part placed by an instance: the instance's
 * name, followed by "/" and the part's when the part has one (a product of
 * an assembly), cut to fit 56 bytes with its NUL. */
void sw_instance_part_name(const char *instance, const char *part, char out[56]);

/* Where point p of a prototype lands under an instance's transform (the
 * expansion's arithmetic: doubles, rounded once), and the transform's
 * scale. */
void sw_instance_place(const float transform[16], const float p[3], float out[3]);
/* 1 when transform (or NULL: none) moves anything: one that does not is
 * not applied, the expansion copies (-0.0 stays -0.0), and so must whoever
 * places as it does. */
int sw_instance_moves(const float *transform);
double sw_instance_scale(const float transform[16]);

#endif
