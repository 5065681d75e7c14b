/* SPDX-License-Identifier: MIT */
#include "sw_cell_filter.h"

#include <string.h>

enum { MASK_CELLS = 32 };

/* Mask cells [lo, hi] that the grid interval [k / n, (k + 1) / n] overlaps. */
static void overlap(uint32_t k, uint32_t n, uint32_t *lo, uint32_t *hi)
{
    *lo = k * MASK_CELLS / n;
    *hi = ((k + 1) * MASK_CELLS + n - 1) / n - 1;
}

void sw_cell_filter_init(sw_cell_filter *f, const sw_pack_trim_mask *mask, uint32_t nu,
                         uint32_t nv)
{
    f->mask = mask;
    f->nu = nu;
    f->nv = nv;
    if (!mask)
        return;
    for (uint32_t a = 0; a < nu; a++) {
        uint32_t lo, hi;
        overlap(a, nu, &lo, &hi);
        uint32_t width = hi - lo + 1;
        f->col_bits[a] = (width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) << lo;
    }
    for (uint32_t b = 0; b < nv; b++) {
        uint32_t lo, hi;
        overlap(b, nv, &lo, &hi);
        f->row_lo[b] = (uint8_t)lo;
        f->row_hi[b] = (uint8_t)hi;
    }
}

int sw_cell_filter_keep(const sw_cell_filter *f, uint32_t a, uint32_t b)
{
    if (!f->mask)
        return 1;
    for (uint32_t j = f->row_lo[b]; j <= f->row_hi[b]; j++)
        if (f->mask->rows[j] & f->col_bits[a])
            return 1;
    return 0;
}

uint32_t sw_cell_filter_compact(const sw_cell_filter *f, uint16_t *indices)
{
    uint32_t kept = 0;
    if (!f->mask)
        return 6u * f->nu * f->nv;
    for (uint32_t b = 0; b < f->nv; b++) {
        for (uint32_t a = 0; a < f->nu; a++) {
            if (!sw_cell_filter_keep(f, a, b))
                continue;
            const uint16_t *cell = indices + ((size_t)b * f->nu + a) * 6;
            if (indices + kept != cell)
                memmove(indices + kept, cell, 6 * sizeof *cell);
            kept += 6;
        }
    }
    return kept;
}
