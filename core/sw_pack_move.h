/* SPDX-License-Identifier: MIT */
/* A run of a pack's records moved to another place in its index spaces, and
 * optionally placed by a transform: how packs built apart are joined (the
 * host's merge, assets/pack/sw_pack_merge.h) and how an instance of a
 * prototype is made at load (sw_pack_instances.h). Each call copies n
 * records from src to dst, adding move->shift[s] to every index into space
 * s; a shift of 0 leaves an index pointing at the source's records (the
 * expansion shares the trims that way). Seam vertices are renumbered apart:
 * the originals come first in every graph, so an original keeps its place
 * among the originals and a created vertex among the created ones.
 *
 * With a transform (a similarity: sw_pack_instances.h checks it), points
 * are moved by it, normals and cone axes turned, and every model-space
 * length (errors, bounds, sides) multiplied by its scale. No allocation,
 * no checks: the source is a validated pack. */
#ifndef SW_PACK_MOVE_H
#define SW_PACK_MOVE_H

#include <stdint.h>

#include "sw_pack.h"

typedef struct sw_pack_move {
    int64_t shift[SW_SPACE_COUNT];
    uint32_t src_originals;     /* the source graph's original vertex count */
    uint32_t dst_originals;     /* the destination graph's */
    const float *transform;     /* 16 floats as sw_pack_instance's, or NULL: no move in space */
    double scale;               /* the transform's scale; 1 without one */
} sw_pack_move;

/* A seam vertex's number in the destination (SW_SEAM_NONE stays). */
uint32_t sw_pack_move_vertex(const sw_pack_move *m, uint32_t v);

void sw_pack_move_parts(const sw_pack_move *m, const sw_pack_part *src, uint32_t n,
                        sw_pack_part *dst);
void sw_pack_move_control(const sw_pack_move *m, const float *src, uint32_t n, float *dst);
/* src_control: the source's whole CONTROL, which src's first_control
 * index. A transformed patch's box is made again from its points moved as
 * sw_pack_move_control moves them (the same floats), and with bounds its
 * second-derivative bounds too; without, they are left INFINITY (no bound),
 * for a reader that takes none (the runtime's placed scene). */
void sw_pack_move_patches(const sw_pack_move *m, const sw_pack_patch *src, uint32_t n,
                          const float *src_control, int bounds, sw_pack_patch *dst);
void sw_pack_move_adjacency(const sw_pack_move *m, const sw_pack_adjacency *src, uint32_t n,
                            sw_pack_adjacency *dst);
void sw_pack_move_surfaces(const sw_pack_move *m, const sw_pack_surface *src, uint32_t n,
                           sw_pack_surface *dst);
void sw_pack_move_trim_loops(const sw_pack_move *m, const sw_pack_trim_loop *src, uint32_t n,
                             sw_pack_trim_loop *dst);
void sw_pack_move_trim_curves(const sw_pack_move *m, const sw_pack_trim_curve *src, uint32_t n,
                              sw_pack_trim_curve *dst);
void sw_pack_move_patch_domains(const sw_pack_move *m, const sw_pack_patch_domain *src,
                                uint32_t n, sw_pack_patch_domain *dst);

void sw_pack_move_seam_vertices(const sw_pack_move *m, const sw_seam_vertex *src, uint32_t n,
                                sw_seam_vertex *dst);
void sw_pack_move_seam_slots(const sw_pack_move *m, const sw_seam_slot *src, uint32_t n,
                             sw_seam_slot *dst);
void sw_pack_move_seam_loops(const sw_pack_move *m, const sw_seam_loop *src, uint32_t n,
                             sw_seam_loop *dst);
void sw_pack_move_seam_edges(const sw_pack_move *m, const sw_seam_edge *src, uint32_t n,
                             sw_seam_edge *dst);
void sw_pack_move_seam_collapses(const sw_pack_move *m, const sw_seam_collapse *src, uint32_t n,
                                 sw_seam_collapse *dst);
/* Entries of an index array into space s (slot refs, a surface's first
 * loop, a cluster's members, ...), each shifted by m->shift[s]. */
void sw_pack_move_indices(const sw_pack_move *m, int space, const uint32_t *src, uint32_t n,
                          uint32_t *dst);

void sw_pack_move_levels(const sw_pack_move *m, const sw_level *src, uint32_t n, sw_level *dst);
/* Level vertices of space s (SW_SPACE_LEVEL_VERTICES or the part levels'). */
void sw_pack_move_level_vertices(const sw_pack_move *m, const sw_level_vertex *src, uint32_t n,
                                 sw_level_vertex *dst);
void sw_pack_move_level_chains(const sw_pack_move *m, const sw_level_chain *src, uint32_t n,
                               sw_level_chain *dst);
void sw_pack_move_supers(const sw_pack_move *m, const sw_super_surface *src, uint32_t n,
                         sw_super_surface *dst);
void sw_pack_move_part_levels(const sw_pack_move *m, const sw_part_level *src, uint32_t n,
                              sw_part_level *dst);

#endif
