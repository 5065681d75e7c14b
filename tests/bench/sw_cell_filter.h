/* SPDX-License-Identifier: MIT */
/* Which cells of a patch's uniform grid survive its trim mask
 * (sw_pack_trim_mask: 32 x 32 cells of the patch's domain that touch the
 * trimmed face). A grid cell is kept when it overlaps any set mask cell, so
 * the filter is as conservative as the mask: nothing of the face is lost,
 * and what is drawn beyond the trim is at most one mask cell wide. The
 * runtime draws through the Seam Graph (exact trims) and no longer uses it:
 * it stays for the uniform-grid baseline of the walkthrough benchmark. No
 * allocation. */
#ifndef SW_CELL_FILTER_H
#define SW_CELL_FILTER_H

#include <stdint.h>

#include "sw_pack.h"
#include "sw_tess.h"

typedef struct sw_cell_filter {
    const sw_pack_trim_mask *mask;   /* NULL: every cell is kept */
    uint32_t nu, nv;
    uint32_t col_bits[SW_TESS_MAX_SEGMENTS];  /* mask columns grid column a overlaps */
    uint8_t row_lo[SW_TESS_MAX_SEGMENTS];     /* mask rows grid row b overlaps: lo..hi */
    uint8_t row_hi[SW_TESS_MAX_SEGMENTS];
} sw_cell_filter;

void sw_cell_filter_init(sw_cell_filter *f, const sw_pack_trim_mask *mask, uint32_t nu,
                         uint32_t nv);
int sw_cell_filter_keep(const sw_cell_filter *f, uint32_t a, uint32_t b);

/* Removes the triangles of dropped cells from the index list sw_tess_grid
 * wrote (six indices per cell, cell (a, b) at (b * nu + a) * 6), keeping the
 * order; returns the number of indices left. */
uint32_t sw_cell_filter_compact(const sw_cell_filter *f, uint16_t *indices);

#endif
