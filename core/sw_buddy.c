/* SPDX-License-Identifier: MIT */
#include "sw_buddy.h"

#include <string.h>

#define NONE 0xFFFFFFFFu
enum { INSIDE = 0, FREE = 1, USED = 2 };

size_t sw_buddy_arena_bytes(uint32_t units)
{
    size_t n = (size_t)units + 1;
    return 2 * sw_arena_worst_case(n * sizeof(uint32_t), 8) + 2 * sw_arena_worst_case(n, 8);
}

static void push(sw_buddy *b, uint32_t first, uint32_t k)
{
    b->order[first] = (uint8_t)k;
    b->state[first] = FREE;
    b->prev[first] = NONE;
    b->next[first] = b->head[k];
    if (b->head[k] != NONE)
        b->prev[b->head[k]] = first;
    b->head[k] = first;
}

static void unlink_block(sw_buddy *b, uint32_t first)
{
    uint32_t k = b->order[first], p = b->prev[first], n = b->next[first];
    if (p != NONE)
        b->next[p] = n;
    else
        b->head[k] = n;
    if (n != NONE)
        b->prev[n] = p;
    b->state[first] = INSIDE;
}

/* [0, units) free: the largest block aligned at each position that still
 * fits. */
static void cover(sw_buddy *b, uint32_t units)
{
    b->units = units;
    for (int k = 0; k <= SW_BUDDY_MAX_ORDER; k++)
        b->head[k] = NONE;
    for (uint32_t at = 0; at < units;) {
        uint32_t k = 0;
        while (k < SW_BUDDY_MAX_ORDER && (at & ((2u << k) - 1)) == 0 &&
               (uint64_t)at + (2ull << k) <= units)
            k++;
        push(b, at, k);
        at += 1u << k;
    }
}

sw_status sw_buddy_init(sw_buddy *b, uint32_t units, sw_arena *arena, sw_error *err)
{
    memset(b, 0, sizeof *b);
    if (units == 0)
        return sw_error_set(err, SW_ERR_ARG, "buddy: no units");
    size_t n = (size_t)units + 1;
    b->next = sw_arena_alloc(arena, n * sizeof(uint32_t), 8);
    b->prev = sw_arena_alloc(arena, n * sizeof(uint32_t), 8);
    b->order = sw_arena_alloc(arena, n, 8);
    b->state = sw_arena_alloc(arena, n, 8);
    if (!b->next || !b->prev || !b->order || !b->state)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "buddy: arena too small for %u units",
                            (unsigned)units);
    memset(b->state, INSIDE, n);
    cover(b, units);
    return SW_OK;
}

int sw_buddy_shrink(sw_buddy *b, uint32_t units)
{
    if (units == 0 || units > b->units || b->used_units != 0)
        return 0;
    memset(b->state, INSIDE, (size_t)b->units + 1);
    cover(b, units);
    return 1;
}

int sw_buddy_alloc(sw_buddy *b, uint32_t count, uint32_t *first)
{
    if (count == 0 || count > b->units)
        return 0;
    uint32_t want = sw_buddy_order_of(count), k = want;
    while (k <= SW_BUDDY_MAX_ORDER && b->head[k] == NONE)
        k++;
    if (k > SW_BUDDY_MAX_ORDER)
        return 0;
    uint32_t at = b->head[k];
    unlink_block(b, at);
    while (k > want) { /* split: the upper half stays free */
        k--;
        push(b, at + (1u << k), k);
    }
    b->order[at] = (uint8_t)want;
    b->state[at] = USED;
    b->next[at] = SW_BUDDY_NO_OWNER;
    b->used_units += 1u << want;
    *first = at;
    return 1;
}

int sw_buddy_free(sw_buddy *b, uint32_t first)
{
    if (first >= b->units || b->state[first] != USED)
        return 0;
    uint32_t k = b->order[first];
    b->used_units -= 1u << k;
    b->state[first] = INSIDE;
    while (k < SW_BUDDY_MAX_ORDER) {
        uint32_t buddy = first ^ (1u << k);
        if (buddy >= b->units || b->state[buddy] != FREE || b->order[buddy] != k)
            break;
        unlink_block(b, buddy);
        first = first < buddy ? first : buddy;
        k++;
    }
    push(b, first, k);
    return 1;
}

uint32_t sw_buddy_block_units(const sw_buddy *b, uint32_t first)
{
    return first < b->units && b->state[first] == USED ? 1u << b->order[first] : 0;
}

int sw_buddy_largest_free(const sw_buddy *b)
{
    for (int k = SW_BUDDY_MAX_ORDER; k >= 0; k--)
        if (b->head[k] != NONE)
            return k;
    return -1;
}

void sw_buddy_set_owner(sw_buddy *b, uint32_t first, uint32_t owner)
{
    if (first < b->units && b->state[first] == USED)
        b->next[first] = owner;
}

/* The region [at, at + size) as it would be freed: its used units, or
 * UINT64_MAX when a used block in it cannot be freed. Blocks tile the
 * pool, so its blocks start at at and follow each other. */
static uint64_t region_cost(const sw_buddy *b, uint64_t at, uint64_t size,
                            sw_buddy_freeable_fn freeable, void *ctx)
{
    uint64_t used = 0;
    for (uint64_t u = at; u < at + size; u += 1ull << b->order[u])
        if (b->state[u] == USED) {
            if (!freeable(ctx, (uint32_t)u, b->next[u]))
                return UINT64_MAX;
            used += 1ull << b->order[u];
        }
    return used;
}

int sw_buddy_find_region(const sw_buddy *b, uint32_t order, sw_buddy_freeable_fn freeable,
                         void *ctx, uint32_t *first)
{
    if (order > SW_BUDDY_MAX_ORDER)
        return 0;
    uint64_t size = 1ull << order, best = UINT64_MAX;
    for (uint64_t at = 0; at + size <= b->units;) {
        uint64_t block = 1ull << b->order[at];
        if (block > size) {
            /* One block covers this region and the next: free, or one
             * block freed whole, its cost the same in each. */
            uint64_t cost = b->state[at] != USED                      ? 0
                            : freeable(ctx, (uint32_t)at, b->next[at]) ? block
                                                                       : UINT64_MAX;
            if (cost < best)
                best = cost, *first = (uint32_t)at;
            at += block;
        } else {
            uint64_t cost = region_cost(b, at, size, freeable, ctx);
            if (cost < best)
                best = cost, *first = (uint32_t)at;
            at += size;
        }
        if (best == 0)
            break;
    }
    return best != UINT64_MAX;
}

uint32_t sw_buddy_region_owners(const sw_buddy *b, uint32_t first, uint32_t order,
                                uint32_t *owners, uint32_t cap)
{
    if (order > SW_BUDDY_MAX_ORDER || first >= b->units)
        return 0;
    uint64_t end = (uint64_t)first + (1ull << order);
    uint32_t n = 0;
    for (uint64_t u = first; u < end && u < b->units && n < cap; u += 1ull << b->order[u])
        if (b->state[u] == USED)
            owners[n++] = b->next[u];
    return n;
}
