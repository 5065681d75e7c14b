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
    SW_CHECK(sw_buddy_order_of(0) == 0 && sw_buddy_order_of(1) == 0 && sw_buddy_order_of(2) == 1);
    SW_CHECK(sw_buddy_order_of(3) == 2 && sw_buddy_order_of(64) == 6 && sw_buddy_order_of(65) == 7);
}

/* A pool cut to fewer units hands out only those, and all of them; it is
 * not cut while a block is in use, nor to 0 or more than it has. */
static void test_shrink(void)
{
    sw_arena a;
    sw_buddy b;
    init(&b, &a, 1000);
    uint32_t at, n = 0;
    SW_CHECK(sw_buddy_alloc(&b, 1, &at));
    SW_CHECK(!sw_buddy_shrink(&b, 100) && b.units == 1000);
    SW_CHECK(sw_buddy_free(&b, at));
    SW_CHECK(!sw_buddy_shrink(&b, 0) && !sw_buddy_shrink(&b, 1001) && b.units == 1000);
    SW_CHECK(sw_buddy_shrink(&b, 100) && b.units == 100);
    SW_CHECK(sw_buddy_largest_free(&b) == 6);   /* 64 + 32 + 4 */
    while (sw_buddy_alloc(&b, 1, &at)) {
        SW_CHECK(at < 100);
        n++;
    }
    SW_CHECK_MSG(n == 100 && b.used_units == 100, "%u units handed out of 100", (unsigned)n);
}

/* Blocks owned by a multiple of 3 cannot be freed (test_random_...'s
 * owners are its slots). */
static int freeable(void *ctx, uint32_t first, uint32_t owner)
{
    (void)ctx, (void)first;
    return owner % 3 != 0;
}

/* From the shadow map: the used units of the blocks to free for the region
 * [at, at + size), UINT32_MAX when one of them cannot be freed. */
static uint32_t shadow_cost(const sw_buddy *b, const uint32_t *owner, const uint32_t *live,
                            uint32_t at, uint32_t size)
{
    uint32_t cost = 0, last = 0xFFFFFFFFu;
    for (uint32_t u = at; u < at + size; u++)
        if (owner[u] != 0xFFFFFFFFu && owner[u] != last) {
            last = owner[u];
            if (!freeable(NULL, 0, owner[u]))
                return UINT32_MAX;
            cost += sw_buddy_block_units(b, live[owner[u]]);
        }
    return cost;
}

/* sw_buddy_region_owners of the region found at at: the owners the
 * shadow map has from at on, in address order, those of its blocks; and
 * when one block covers the region, that block's owner alone. Cut at cap. */
static void check_owners(const sw_buddy *b, const uint32_t *owner, uint32_t at, uint32_t order)
{
    uint32_t got[1024], want[1024], n_want = 0, last = 0xFFFFFFFFu;
    uint32_t n = sw_buddy_region_owners(b, at, order, got, 1024);
    for (uint32_t u = at; u < at + (1u << order) && n_want < 1024; u++)
        if (owner[u] != 0xFFFFFFFFu && owner[u] != last)
            want[n_want++] = last = owner[u];
    SW_CHECK_MSG(n == n_want, "order %u at %u: %u owners listed, %u in the map",
                 (unsigned)order, (unsigned)at, (unsigned)n, (unsigned)n_want);
    for (uint32_t k = 0; k < n && k < n_want; k++)
        SW_CHECK(got[k] == want[k]);
    if (n_want > 1)
        SW_CHECK(sw_buddy_region_owners(b, at, order, got, 1) == 1 && got[0] == want[0]);
}

/* What sw_buddy_find_region must find: the cheapest aligned region's
 * cost, UINT32_MAX when none can be freed. */
static uint32_t cheapest_region(const sw_buddy *b, const uint32_t *owner, const uint32_t *live,
                                uint32_t units, uint32_t order)
{
    uint32_t size = 1u << order, best = UINT32_MAX;
    for (uint32_t at = 0; at + size <= units; at += size) {
        uint32_t cost = shadow_cost(b, owner, live, at, size);
        best = cost < best ? cost : best;
    }
    return best;
}

/* The region search and the largest free block against the shadow map;
 * then the found region freed gives a block of that order. */
static void check_regions(sw_buddy *b, uint32_t *owner, const uint32_t *live, int *used,
                          uint32_t units)
{
    for (uint32_t order = 0; order <= 10; order++) {
        uint32_t want = cheapest_region(b, owner, live, units, order), at = 0;
        int found = sw_buddy_find_region(b, order, freeable, NULL, &at);
        SW_CHECK_MSG(found == (want != UINT32_MAX), "order %u: found %d", (unsigned)order,
                     found);
        if (!found)
            continue;
        SW_CHECK(at % (1u << order) == 0 && at + (1u << order) <= units);
        SW_CHECK(shadow_cost(b, owner, live, at, 1u << order) == want);
        SW_CHECK((want == 0) == (sw_buddy_largest_free(b) >= (int)order));
        check_owners(b, owner, at, order);
    }
    int k = sw_buddy_largest_free(b);
    uint32_t at;
    SW_CHECK(k < 0 || (sw_buddy_alloc(b, 1u << k, &at) && sw_buddy_free(b, at)));
    SW_CHECK(k >= SW_BUDDY_MAX_ORDER || !sw_buddy_alloc(b, 2u << k, &at));
    /* Free the owners listed for the region found for 2^6 units: then a
     * block of 2^6 fits. */
    if (!sw_buddy_find_region(b, 6, freeable, NULL, &at))
        return;
    uint32_t listed[64], n = sw_buddy_region_owners(b, at, 6, listed, 64);
    for (uint32_t j = 0; j < n; j++) {
        uint32_t i = listed[j];
        for (uint32_t v = 0; v < units; v++)
            owner[v] = owner[v] == i ? 0xFFFFFFFFu : owner[v];
        SW_CHECK(sw_buddy_free(b, live[i]));
        used[i] = 0;
    }
    SW_CHECK(sw_buddy_largest_free(b) >= 6);
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
        sw_buddy_set_owner(&b, at, (uint32_t)i);
    }
    SW_CHECK_MSG(bad == 0, "%u overlaps or bad blocks", (unsigned)bad);
    SW_CHECK(fails < STEPS / 4);
    check_regions(&b, owner, live, used, UNITS);
    for (int i = 0; i < LIVE; i++)
        if (used[i])
            SW_CHECK(sw_buddy_free(&b, live[i]));
    SW_CHECK(b.used_units == 0);
    memset(owner, 0xFF, sizeof owner);
    check_regions(&b, owner, live, used, UNITS);
    uint32_t at;
    SW_CHECK(sw_buddy_alloc(&b, 512, &at)); /* merged back: 512 + 256 + 128 + 64 + 32 + 8 */
}

int main(void)
{
    SW_RUN(test_rounds_up_and_merges_back);
    SW_RUN(test_odd_range_and_bad_input);
    SW_RUN(test_shrink);
    SW_RUN(test_random_blocks_never_overlap);
    return sw_test_finish();
}
