/* SPDX-License-Identifier: MIT */
/* The arena: one block taken at start-up, handed out by bump allocation and by
 * fixed-size slabs. The runtime sizes it from the pack header and its options
 * before the first frame; nothing after that calls malloc. The caller owns the
 * block; the arena never frees it. Not thread-safe: one owner per arena. */
#ifndef SW_ARENA_H
#define SW_ARENA_H

#include <stddef.h>
#include <stdint.h>

typedef struct sw_arena {
    unsigned char *base;
    size_t size;
    size_t used;
    size_t peak;       /* high-water mark of used, for the stats */
    size_t last;       /* offset of the most recent allocation, for in-place growth */
} sw_arena;

void sw_arena_init(sw_arena *arena, void *block, size_t size);

/* Writes zeros over the whole block, so that every page of it is resident
 * from now on: a large malloc only reserves addresses and the pages come as
 * they are first written, which in a walk is whenever a cache or queue
 * first reaches them (loops into a soak). Touched at start, resident memory
 * is what the walk will hold, and a device short of memory fails at start
 * instead of hours into the walk. */
void sw_arena_touch(sw_arena *arena);

/* size bytes aligned to align (a power of two, at most 4096); NULL when the
 * arena cannot hold them. size 0 returns a valid unique-enough pointer. */
void *sw_arena_alloc(sw_arena *arena, size_t size, size_t align);

/* Grows or shrinks an allocation. In place when ptr is the most recent
 * allocation, otherwise a new block with the old bytes copied. NULL (and ptr
 * untouched) when the arena cannot hold new_size. ptr NULL acts as alloc. */
void *sw_arena_realloc(sw_arena *arena, void *ptr, size_t old_size, size_t new_size, size_t align);

/* Marks let a caller take scratch memory and give it all back at once. */
size_t sw_arena_mark(const sw_arena *arena);
void sw_arena_reset_to(sw_arena *arena, size_t mark);

/* Bytes an allocation of size with align may take, worst case, for sizing. */
static inline size_t sw_arena_worst_case(size_t size, size_t align) { return size + align - 1; }

/* A slab: slot_count slots of slot_size bytes carved from an arena, taken and
 * given back in O(1) through a free list of indices. */
typedef struct sw_slab {
    unsigned char *slots;
    uint32_t *next_free;   /* next_free[i]: the free slot after i, or UINT32_MAX */
    size_t slot_size;
    uint32_t slot_count;
    uint32_t free_head;
    uint32_t in_use;
} sw_slab;

/* Bytes sw_slab_init takes from an arena, worst case. */
size_t sw_slab_arena_bytes(size_t slot_size, uint32_t slot_count);
/* 0 on success, -1 when the arena is too small or the arguments are zero. */
int sw_slab_init(sw_slab *slab, sw_arena *arena, size_t slot_size, uint32_t slot_count);
void *sw_slab_take(sw_slab *slab);          /* NULL when every slot is taken */
void sw_slab_give(sw_slab *slab, void *slot);
uint32_t sw_slab_index(const sw_slab *slab, const void *slot);

#endif
