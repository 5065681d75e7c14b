/* SPDX-License-Identifier: MIT */
/* A buddy allocator over a range of units (no memory of its own to hand
 * out: it says where in the caller's pools a block lies). The tessellation
 * cache keeps every surface's mesh in one block of a vertex pool and one of
 * an index pool, in the arena and in GL buffers of the same layout, so a
 * block's place is its offset in both. Blocks are 2^k units; a request is
 * rounded up (at most 2x waste), freeing merges buddies, both O(log units).
 * The bookkeeping comes from an arena at init; no allocation after. Not
 * thread-safe: one owner. */
#ifndef SW_BUDDY_H
#define SW_BUDDY_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"

#define SW_BUDDY_MAX_ORDER 31

typedef struct sw_buddy {
    uint32_t units;
    uint32_t *next, *prev;     /* units: free-list links of a free block's first unit;
                                  next: a used block's owner */
    uint8_t *order;            /* units: a block's order, at its first unit */
    uint8_t *state;            /* units: 0 inside a block, 1 first unit of a free block,
                                  2 first unit of a used block */
    uint32_t head[SW_BUDDY_MAX_ORDER + 1];
    uint32_t used_units;       /* in used blocks, rounded sizes */
} sw_buddy;

size_t sw_buddy_arena_bytes(uint32_t units);

/* Covers [0, units) with the largest aligned free blocks. SW_ERR_ARG for
 * units 0, SW_ERR_NO_MEMORY when the arena is too small. */
sw_status sw_buddy_init(sw_buddy *b, uint32_t units, sw_arena *arena, sw_error *err);

/* The pool cut to its first units (a test's smaller cache, in the same
 * arrays): 1, or 0 when a block is in use or units is 0 or more than it
 * has (nothing changes). */
int sw_buddy_shrink(sw_buddy *b, uint32_t units);

/* The order of the block a request of count units gets: the smallest k
 * with 2^k >= count (0 for 0 or 1). */
static inline uint32_t sw_buddy_order_of(uint64_t count)
{
    uint32_t k = 0;
    while ((1ull << k) < count)
        k++;
    return k;
}

/* A block of at least count units (count >= 1): 1 and *first set, or 0 when
 * no free block is large enough (nothing changes). */
int sw_buddy_alloc(sw_buddy *b, uint32_t count, uint32_t *first);

/* Gives back the block starting at first (a value sw_buddy_alloc returned
 * and not yet freed; anything else is ignored and returns 0). */
int sw_buddy_free(sw_buddy *b, uint32_t first);

/* Units the block at first spans (0 when first starts no used block). */
uint32_t sw_buddy_block_units(const sw_buddy *b, uint32_t first);

/* The order of the largest free block (2^order units), -1 when none is
 * free: a request of 2^k units succeeds exactly when k <= it. O(orders). */
int sw_buddy_largest_free(const sw_buddy *b);

/* A used block's owner: a number the caller gives it (a surface), kept
 * where a free block keeps its links, so it costs nothing;
 * SW_BUDDY_NO_OWNER from alloc until set. */
#define SW_BUDDY_NO_OWNER 0xFFFFFFFFu
void sw_buddy_set_owner(sw_buddy *b, uint32_t first, uint32_t owner);

/* Can the used block at first, owned by owner, be freed now? */
typedef int (*sw_buddy_freeable_fn)(void *ctx, uint32_t first, uint32_t owner);

/* Where a block of 2^order units can be made by freeing blocks: the
 * aligned region of that size, inside the pool, all of whose used blocks
 * freeable() accepts, with the fewest used units (the first such, lowest
 * address, on a tie). 1 and *first (its first unit) when there is one, 0
 * when not; a region already free is one with none. Freeing the region's
 * used blocks merges it into a free block of at least that order: the
 * room the largest-free check above asks for, made by freeing
 * where it helps rather than oldest first. O(blocks). */
int sw_buddy_find_region(const sw_buddy *b, uint32_t order, sw_buddy_freeable_fn freeable,
                         void *ctx, uint32_t *first);

/* The owners of the used blocks in the region of 2^order units from first
 * (one sw_buddy_find_region gave: its blocks lie inside it, or one block
 * covers it), at most cap of them, into owners; returns how many. So the
 * caller frees what the search chose without a pass over every owner it
 * has, which a view larger than the cache asks for many times a frame. */
uint32_t sw_buddy_region_owners(const sw_buddy *b, uint32_t first, uint32_t order,
                                uint32_t *owners, uint32_t cap);

#endif
