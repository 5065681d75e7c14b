/* SPDX-License-Identifier: MIT */
/* The pieces a part's levels are made for (core/sw_part_levels.h): a part
 * of at most cut_patches patches is one piece; a larger one (a floor, a
 * building) is cut into compact pieces of at most piece_patches patches
 * each, by halving its surfaces at the median of their boxes' centres
 * along the widest axis, again and again. A piece is chosen by its
 * nearest depth, so a compact piece is drawn coarser the farther it is;
 * a piece much larger would be held fine by its nearest corner, a much
 * smaller one has more border than inside (on the 40,000-patch courtyard
 * pieces of 256 patches drew fewer triangles at the far end of its orbit
 * than 128, 512 or 1,024).
 *
 * Pieces are numbered as their first surfaces come, part after part, as
 * the pack reader requires. Host only: allocates. */
#ifndef SW_PART_PIECES_H
#define SW_PART_PIECES_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_pack.h"

/* Parts of more patches are cut by default. A whole part's own levels
 * serve a part of a few thousand patches at the far end, and each piece
 * costs build time: cut at 1,024 patches, a 1,668-patch NIST part's levels
 * took 87 s instead of 6 s. */
#define SW_PART_CUT_PATCHES 4096u

typedef struct sw_part_pieces_options {
    uint32_t cut_patches;     /* parts with more patches are cut (0: SW_PART_CUT_PATCHES) */
    uint32_t piece_patches;   /* at most this many patches a piece, but for a single
                                 surface with more (0: 256) */
} sw_part_pieces_options;

/* Each surface's piece into piece_of[pack->surface_count], their count
 * into *piece_count. opt may be NULL. SW_ERR_ARG when the pack's surfaces
 * are not in the order of their parts; SW_ERR_NO_MEMORY. */
sw_status sw_part_pieces(const sw_pack *pack, const sw_part_pieces_options *opt,
                         uint32_t *piece_of, uint32_t *piece_count, sw_error *err);

/* The diagonal of part p's patches' boxes (model units): what a cut part's
 * fronts are measured against (sw_part_level_front_bound). */
double sw_part_diagonal(const sw_pack *pack, uint32_t p);

#endif
