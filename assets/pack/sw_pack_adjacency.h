/* SPDX-License-Identifier: MIT */
/* Finds the patches of a model that share a boundary curve, for the pack's
 * ADJACENCY section (the runtime stitches seams along them). Host only; used
 * by sw_pack_contents_from_model. */
#ifndef SW_PACK_ADJACENCY_H
#define SW_PACK_ADJACENCY_H

#include <stdint.h>

#include "sw_model.h"
#include "sw_pack.h"

/* Two patches are adjacent along an edge when their boundary control rows
 * (the degree + 1 points along the edge) coincide: every coordinate within
 * 1e-9 of the diagonal of the box of all control points, every weight within
 * a relative 1e-9, in the same or in reversed order. Edges whose points all
 * coincide (collapsed edges, as at a pole) match nothing. Each pair appears
 * once, patch_a < patch_b, sorted by (patch_a, edge_a, patch_b, edge_b).
 * Expected O(n) through a hash grid on edge endpoints. *out is malloc'd (NULL
 * when there are none); the caller frees it. */
sw_status sw_pack_find_adjacency(const sw_model *model, sw_pack_adjacency **out, uint32_t *count,
                                 sw_error *err);

#endif
