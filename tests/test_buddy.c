/* SPDX-License-Identifier: MIT */
/* The buddy allocator behind the tessellation cache: blocks never overlap,
 * requests round up to powers of two, freeing merges buddies back into the
 * whole range, odd-sized ranges, exhaustion and bad frees. A randomised run
 * checks every live block against a shadow map of units. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_buddy.h"
#include "sw_test.h"

static unsigned char block[1 << 20] __attribute__((aligned(64)));

static void init(sw_buddy *b, sw_arena *a, uint32_t units)
{
    sw_arena_init(a, block, sizeof block);
    SW_CHECK(sw_buddy_init(b, units, a, NULL) == SW_OK);
}

static void test_rounds_up_and_merges_back(void)
{
    sw_arena a;
    sw_buddy b;
    init(&b, &a, 64);
    uint32_t x, y, z;
    SW_CHECK(sw_buddy_alloc(&b, 3, &x) && sw_buddy_block_units(&b, x) == 4);
    SW_CHECK(sw_buddy_alloc(&b, 17, &y) && sw_buddy_block_units(&b, y) == 32);
    SW_CHECK(sw_buddy_alloc(&b, 1, &z) && sw_buddy_block_units(&b, z) == 1);
    SW_CHECK(b.used_units == 37);
    uint32_t none;
    SW_CHECK(!sw_buddy_alloc(&b, 32, &none)); /* 27 units free, no block of 32 */
    SW_CHECK(sw_buddy_free(&b, y) && sw_buddy_free(&b, z));
    SW_CHECK(!sw_buddy_free(&b, z)); /* twice */
    uint32_t all;
    SW_CHECK(!sw_buddy_alloc(&b, 64, &all)); /* x still holds 4 */
    SW_CHECK(sw_buddy_free(&b, x) && b.used_units == 0);
    SW_CHECK(sw_buddy_alloc(&b, 64, &all) && all == 0); /* merged back whole */
}

static void test_odd_range_and_bad_input(void)
{
    sw_arena a;
    sw_buddy b;
    init(&b, &a, 13); /* 8 + 4 + 1 */
    uint32_t x, y, z, w;
    SW_CHECK(sw_buddy_alloc(&b, 8, &x) && sw_buddy_alloc(&b, 4, &y) && sw_buddy_alloc(&b, 1, &z));
    SW_CHECK(x + 8 <= 13 && y + 4 <= 13 && z < 13);
    SW_CHECK(!sw_buddy_alloc(&b, 1, &w));
    SW_CHECK(!sw_buddy_alloc(&b, 0, &w) && !sw_buddy_alloc(&b, 14, &w));
    SW_CHECK(!sw_buddy_free(&b, 13) && !sw_buddy_free(&b, x + 1));
    sw_arena_init(&a, block, 16);
    SW_CHECK(sw_buddy_init(&b, 1000, &a, NULL) == SW_ERR_NO_MEMORY);
    SW_CHECK(sw_buddy_init(&b, 0, &a, NULL) == SW_ERR_ARG);
}

static void test_random_blocks_never_overlap(void)
{
    enum { UNITS = 1000, LIVE = 64, STEPS = 20000 };
    sw_arena a;
    sw_buddy b;
    init(&b, &a, UNITS);
    uint32_t live[LIVE], owner[UNITS];
    int used[LIVE] = { 0 };
    memset(owner, 0xFF, sizeof owner);
    srand(7);
    uint32_t fails = 0, bad = 0;
    for (int step = 0; step < STEPS; step++) {
        int i = rand() % LIVE;
        if (used[i]) {
            uint32_t n = sw_buddy_block_units(&b, live[i]);
            for (uint32_t k = 0; k < n; k++)
                bad += owner[live[i] + k] != (uint32_t)i, owner[live[i] + k] = 0xFFFFFFFFu;
            bad += !sw_buddy_free(&b, live[i]);
            used[i] = 0;
            continue;
        }
        uint32_t want = 1 + (uint32_t)(rand() % 40), at;
        if (!sw_buddy_alloc(&b, want, &at)) {
            fails++;
            continue;
        }
        uint32_t n = sw_buddy_block_units(&b, at);
        bad += n < want || at + n > UNITS || (at & (n - 1)) != 0;
        for (uint32_t k = 0; k < n && at + k < UNITS; k++)
            bad += owner[at + k] != 0xFFFFFFFFu, owner[at + k] = (uint32_t)i;
        live[i] = at, used[i] = 1;
    }
    SW_CHECK_MSG(bad == 0, "%u overlaps or bad blocks", (unsigned)bad);
    SW_CHECK(fails < STEPS / 4);
    for (int i = 0; i < LIVE; i++)
        if (used[i])
            SW_CHECK(sw_buddy_free(&b, live[i]));
    SW_CHECK(b.used_units == 0);
    uint32_t at;
    SW_CHECK(sw_buddy_alloc(&b, 512, &at)); /* merged back: 512 + 256 + 128 + 64 + 32 + 8 */
}

int main(void)
{
    SW_RUN(test_rounds_up_and_merges_back);
    SW_RUN(test_odd_range_and_bad_input);
    SW_RUN(test_random_blocks_never_overlap);
    return sw_test_finish();
}
