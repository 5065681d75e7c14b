/* SPDX-License-Identifier: MIT */
/* The trim-mask cell filter: which grid cells of a patch are drawn. */
#include <string.h>

#include "sw_cell_filter.h"
#include "sw_test.h"

static void write_grid_indices(uint32_t nu, uint32_t nv, uint16_t *idx)
{
    for (uint32_t c = 0; c < nu * nv; c++)
        for (int k = 0; k < 6; k++)
            idx[c * 6 + k] = (uint16_t)c; /* each cell's indices carry its number */
}

static void test_no_mask_keeps_every_cell(void)
{
    sw_cell_filter f;
    sw_cell_filter_init(&f, NULL, 5, 3);
    uint16_t idx[6 * 15];
    write_grid_indices(5, 3, idx);
    SW_CHECK(sw_cell_filter_compact(&f, idx) == 6 * 15);
    SW_CHECK(sw_cell_filter_keep(&f, 4, 2));
}

static void test_coarse_grid_keeps_cells_overlapping_a_set_bit(void)
{
    sw_pack_trim_mask m;
    memset(&m, 0, sizeof m);
    m.rows[9] = 1u << 17; /* mask cell (17, 9) */
    sw_cell_filter f;
    sw_cell_filter_init(&f, &m, 4, 4); /* each grid cell spans 8 x 8 mask cells */
    for (uint32_t b = 0; b < 4; b++)
        for (uint32_t a = 0; a < 4; a++)
            SW_CHECK(sw_cell_filter_keep(&f, a, b) == (a == 2 && b == 1));
    uint16_t idx[6 * 16];
    write_grid_indices(4, 4, idx);
    SW_CHECK(sw_cell_filter_compact(&f, idx) == 6);
    SW_CHECK(idx[0] == 1 * 4 + 2 && idx[5] == 1 * 4 + 2);
}

static void test_fine_grid_keeps_cells_inside_the_bit_and_its_border(void)
{
    sw_pack_trim_mask m;
    memset(&m, 0, sizeof m);
    m.rows[0] = 1u << 31; /* the last mask column of the first row */
    sw_cell_filter f;
    sw_cell_filter_init(&f, &m, 64, 64); /* two grid cells per mask cell each way */
    int kept = 0;
    for (uint32_t b = 0; b < 64; b++)
        for (uint32_t a = 0; a < 64; a++)
            kept += sw_cell_filter_keep(&f, a, b);
    SW_CHECK(kept == 4);
    SW_CHECK(sw_cell_filter_keep(&f, 62, 0) && sw_cell_filter_keep(&f, 63, 1));
    SW_CHECK(!sw_cell_filter_keep(&f, 61, 0) && !sw_cell_filter_keep(&f, 63, 2));
}

static void test_uneven_grid_is_conservative(void)
{
    /* A grid column that straddles two mask columns is kept when either is set. */
    sw_pack_trim_mask m;
    memset(&m, 0, sizeof m);
    for (int j = 0; j < 32; j++)
        m.rows[j] = 1u << 10;
    sw_cell_filter f;
    sw_cell_filter_init(&f, &m, 3, 1); /* columns span 10.67 mask cells */
    SW_CHECK(sw_cell_filter_keep(&f, 0, 0));  /* [0, 10.67] overlaps column [10, 11] */
    SW_CHECK(sw_cell_filter_keep(&f, 1, 0));  /* [10.67, 21.33] overlaps it too */
    SW_CHECK(!sw_cell_filter_keep(&f, 2, 0)); /* [21.33, 32] does not */
}

static void test_full_mask_keeps_all_and_empty_keeps_none(void)
{
    sw_pack_trim_mask full, empty;
    memset(&full, 0xFF, sizeof full);
    memset(&empty, 0, sizeof empty);
    sw_cell_filter f;
    uint16_t idx[6 * 255];
    sw_cell_filter_init(&f, &full, 255, 1);
    write_grid_indices(255, 1, idx);
    SW_CHECK(sw_cell_filter_compact(&f, idx) == 6 * 255);
    sw_cell_filter_init(&f, &empty, 255, 1);
    SW_CHECK(sw_cell_filter_compact(&f, idx) == 0);
}

int main(void)
{
    SW_RUN(test_no_mask_keeps_every_cell);
    SW_RUN(test_coarse_grid_keeps_cells_overlapping_a_set_bit);
    SW_RUN(test_fine_grid_keeps_cells_inside_the_bit_and_its_border);
    SW_RUN(test_uneven_grid_is_conservative);
    SW_RUN(test_full_mask_keeps_all_and_empty_keeps_none);
    return sw_test_finish();
}
