/* SPDX-License-Identifier: MIT */
#include "sw_arena.h"

#include <assert.h>
#include <string.h>

void sw_arena_init(sw_arena *arena, void *block, size_t size)
{
    arena->base = block;
    arena->size = block ? size : 0;
    arena->used = 0;
    arena->peak = 0;
    arena->last = SIZE_MAX;
}

void sw_arena_touch(sw_arena *arena)
{
    if (arena->base)
        memset(arena->base, 0, arena->size);
}

static size_t align_up(size_t offset, uintptr_t base, size_t align)
{
    uintptr_t p = base + offset;
    uintptr_t aligned = (p + (align - 1)) & ~(uintptr_t)(align - 1);
    return offset + (size_t)(aligned - p);
}

void *sw_arena_alloc(sw_arena *arena, size_t size, size_t align)
{
    assert(align && (align & (align - 1)) == 0 && align <= 4096);
    size_t start = align_up(arena->used, (uintptr_t)arena->base, align);
    if (start > arena->size || size > arena->size - start)
        return NULL;
    arena->last = start;
    arena->used = start + size;
    if (arena->used > arena->peak)
        arena->peak = arena->used;
    return arena->base + start;
}

void *sw_arena_realloc(sw_arena *arena, void *ptr, size_t old_size, size_t new_size, size_t align)
{
    if (!ptr)
        return sw_arena_alloc(arena, new_size, align);
    size_t offset = (size_t)((unsigned char *)ptr - arena->base);
    if (offset == arena->last && arena->last + old_size == arena->used) {
        if (new_size > arena->size - offset)
            return NULL;
        arena->used = offset + new_size;
        if (arena->used > arena->peak)
            arena->peak = arena->used;
        return ptr;
    }
    void *fresh = sw_arena_alloc(arena, new_size, align);
    if (fresh)
        memcpy(fresh, ptr, old_size < new_size ? old_size : new_size);
    return fresh;
}

size_t sw_arena_mark(const sw_arena *arena) { return arena->used; }

void sw_arena_reset_to(sw_arena *arena, size_t mark)
{
    assert(mark <= arena->used);
    arena->used = mark;
    arena->last = SIZE_MAX;
}

size_t sw_slab_arena_bytes(size_t slot_size, uint32_t slot_count)
{
    return sw_arena_worst_case(slot_size * slot_count, 64) +
           sw_arena_worst_case(sizeof(uint32_t) * slot_count, sizeof(uint32_t));
}

int sw_slab_init(sw_slab *slab, sw_arena *arena, size_t slot_size, uint32_t slot_count)
{
    if (!slot_size || !slot_count || slot_size > SIZE_MAX / slot_count)
        return -1;
    slab->slots = sw_arena_alloc(arena, slot_size * slot_count, 64);
    slab->next_free = sw_arena_alloc(arena, sizeof(uint32_t) * slot_count, sizeof(uint32_t));
    if (!slab->slots || !slab->next_free)
        return -1;
    slab->slot_size = slot_size;
    slab->slot_count = slot_count;
    for (uint32_t i = 0; i < slot_count; i++)
        slab->next_free[i] = i + 1 < slot_count ? i + 1 : UINT32_MAX;
    slab->free_head = 0;
    slab->in_use = 0;
    return 0;
}

void *sw_slab_take(sw_slab *slab)
{
    if (slab->free_head == UINT32_MAX)
        return NULL;
    uint32_t i = slab->free_head;
    slab->free_head = slab->next_free[i];
    slab->in_use++;
    return slab->slots + (size_t)i * slab->slot_size;
}

uint32_t sw_slab_index(const sw_slab *slab, const void *slot)
{
    return (uint32_t)(((const unsigned char *)slot - slab->slots) / slab->slot_size);
}

void sw_slab_give(sw_slab *slab, void *slot)
{
    uint32_t i = sw_slab_index(slab, slot);
    assert(i < slab->slot_count);
    slab->next_free[i] = slab->free_head;
    slab->free_head = i;
    slab->in_use--;
}
