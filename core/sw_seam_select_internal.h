/* SPDX-License-Identifier: MIT */
/* Shared between the files of the Seam Graph selection (sw_seam_select*.c);
 * not public. */
#ifndef SW_SEAM_SELECT_INTERNAL_H
#define SW_SEAM_SELECT_INTERNAL_H

#include "sw_seam_select.h"

/* Calls visit(ctx, w) for every neighbour w of active vertex x (a neighbour
 * may come more than once) until visit returns non-zero; returns that value
 * (0 when every neighbour was visited). */
uint32_t sw_seam_select_scan_neighbours(const sw_seam_select *s, uint32_t x,
                                        uint32_t (*visit)(void *ctx, uint32_t w), void *ctx);

/* Forced split of active created vertex v (paper 5.5), at most max_ops
 * splits (0: no limit); on_split (may be NULL) hears of every split, with
 * ctx, the vertex split and v. Returns the splits done; v is inactive
 * afterwards unless max_ops ran out. */
typedef void (*sw_seam_on_split)(void *ctx, sw_seam_select *s, uint32_t vn, uint32_t wanted);
uint32_t sw_seam_select_force(sw_seam_select *s, uint32_t v, uint32_t max_ops,
                              sw_seam_on_split on_split, void *ctx);

/* Collapse into vn, for a caller that checked sw_seam_select_can_collapse. */
void sw_seam_select_do_collapse(sw_seam_select *s, uint32_t vn);

#endif
