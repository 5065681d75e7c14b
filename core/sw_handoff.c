/* SPDX-License-Identifier: MIT */
#include "sw_handoff.h"

size_t sw_retire_ring_arena_bytes(uint32_t capacity)
{
    return sw_arena_worst_case((size_t)capacity * sizeof(sw_retired), 64);
}

sw_status sw_retire_ring_init(sw_retire_ring *r, uint32_t capacity, sw_arena *arena,
                              sw_error *err)
{
    if (capacity == 0 || (capacity & (capacity - 1)))
        return sw_error_set(err, SW_ERR_ARG, "retire ring: capacity %u is not a power of two",
                            (unsigned)capacity);
    r->items = sw_arena_alloc(arena, (size_t)capacity * sizeof *r->items, 64);
    if (!r->items)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "retire ring: arena too small for %u "
                            "meshes", (unsigned)capacity);
    r->capacity = capacity;
    atomic_init(&r->head, 0);
    atomic_init(&r->tail, 0);
    atomic_init(&r->done_epoch, 0);
    return SW_OK;
}

int sw_retire_ring_put(sw_retire_ring *r, sw_retired item)
{
    uint32_t t = atomic_load_explicit(&r->tail, memory_order_relaxed);
    uint32_t h = atomic_load_explicit(&r->head, memory_order_acquire);
    if (t - h >= r->capacity)
        return 0;
    r->items[t & (r->capacity - 1)] = item;
    atomic_store_explicit(&r->tail, t + 1, memory_order_release);
    return 1;
}

void sw_retire_ring_finish(sw_retire_ring *r, uint32_t epoch)
{
    atomic_store_explicit(&r->done_epoch, epoch, memory_order_release);
}

int sw_retire_ring_done(const sw_retire_ring *r, uint32_t epoch)
{
    /* The difference, not a plain <, keeps it right when the frame counter
     * wraps. */
    uint32_t done = atomic_load_explicit(&r->done_epoch, memory_order_acquire);
    return (int32_t)(done - epoch) > 0;
}

int sw_retire_ring_take(sw_retire_ring *r, sw_retired *item)
{
    uint32_t h = atomic_load_explicit(&r->head, memory_order_relaxed);
    uint32_t t = atomic_load_explicit(&r->tail, memory_order_acquire);
    if (h == t)
        return 0;
    sw_retired it = r->items[h & (r->capacity - 1)];
    /* The oldest put decides (the producer frees meshes of finished
     * frames itself, so those put are of the last frame or two). */
    if (!sw_retire_ring_done(r, it.epoch))
        return 0;
    *item = it;
    atomic_store_explicit(&r->head, h + 1, memory_order_release);
    return 1;
}
