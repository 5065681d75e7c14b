/* SPDX-License-Identifier: MIT */
#include "sw_steal_queue.h"

static uint32_t head_of(uint64_t e) { return (uint32_t)(e & 0xFFFFu); }
static uint32_t tail_of(uint64_t e) { return (uint32_t)((e >> 16) & 0xFFFFu); }
static uint32_t size_of(uint64_t e) { return (tail_of(e) - head_of(e)) & 0xFFFFu; }

/* The word with a new head and tail; the tag counts every change, so a CAS
 * from a stale snapshot fails even when head and tail came back to the same
 * values (a pop then a push). */
static uint64_t ends_of(uint64_t old, uint32_t head, uint32_t tail)
{
    uint64_t tag = (old >> 32) + 1;
    return (tag << 32) | ((uint64_t)(tail & 0xFFFFu) << 16) | (head & 0xFFFFu);
}

size_t sw_steal_queue_arena_bytes(uint32_t capacity)
{
    return sw_arena_worst_case((size_t)capacity * sizeof(_Atomic uint32_t), 64);
}

sw_status sw_steal_queue_init(sw_steal_queue *q, uint32_t capacity, sw_arena *arena,
                              sw_error *err)
{
    if (capacity == 0 || capacity > SW_STEAL_QUEUE_MAX || (capacity & (capacity - 1)))
        return sw_error_set(err, SW_ERR_ARG, "steal queue: capacity %u is not a power of two "
                            "from 1 to %u", (unsigned)capacity, (unsigned)SW_STEAL_QUEUE_MAX);
    q->items = sw_arena_alloc(arena, (size_t)capacity * sizeof *q->items, 64);
    if (!q->items)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "steal queue: arena too small for %u ids",
                            (unsigned)capacity);
    for (uint32_t i = 0; i < capacity; i++)
        atomic_init(&q->items[i], 0);
    atomic_init(&q->ends, 0);
    q->capacity = capacity;
    return SW_OK;
}

int sw_steal_queue_push(sw_steal_queue *q, uint32_t id)
{
    uint64_t e = atomic_load_explicit(&q->ends, memory_order_acquire);
    for (;;) {
        if (size_of(e) >= q->capacity)
            return 0;
        /* The slot past the tail belongs to no one but the producer: a
         * thief with an older snapshot may read it, but its CAS then fails. */
        uint32_t t = tail_of(e);
        atomic_store_explicit(&q->items[t & (q->capacity - 1)], id, memory_order_relaxed);
        if (atomic_compare_exchange_weak_explicit(&q->ends, &e, ends_of(e, head_of(e), t + 1),
                                                  memory_order_release, memory_order_acquire))
            return 1;
    }
}

int sw_steal_queue_pop(sw_steal_queue *q, uint32_t *id)
{
    uint64_t e = atomic_load_explicit(&q->ends, memory_order_acquire);
    for (;;) {
        if (size_of(e) == 0)
            return 0;
        uint32_t h = head_of(e);
        uint32_t v = atomic_load_explicit(&q->items[h & (q->capacity - 1)], memory_order_relaxed);
        if (atomic_compare_exchange_weak_explicit(&q->ends, &e, ends_of(e, h + 1, tail_of(e)),
                                                  memory_order_acq_rel, memory_order_acquire)) {
            *id = v;
            return 1;
        }
    }
}

uint32_t sw_steal_queue_steal(sw_steal_queue *q, uint32_t *out, uint32_t max)
{
    uint64_t e = atomic_load_explicit(&q->ends, memory_order_acquire);
    for (;;) {
        uint32_t n = size_of(e), k = (n + 1) / 2;
        if (k > max)
            k = max;
        if (k == 0)
            return 0;
        uint32_t t = tail_of(e);
        /* Read before the CAS: once it succeeds the producer may reuse the
         * slots; if anyone moved in between, the CAS fails and we read again. */
        for (uint32_t i = 0; i < k; i++)
            out[i] = atomic_load_explicit(&q->items[(t - k + i) & (q->capacity - 1)],
                                          memory_order_relaxed);
        if (atomic_compare_exchange_weak_explicit(&q->ends, &e, ends_of(e, head_of(e), t - k),
                                                  memory_order_acq_rel, memory_order_acquire))
            return k;
    }
}

uint32_t sw_steal_queue_size(const sw_steal_queue *q)
{
    return size_of(atomic_load_explicit((_Atomic uint64_t *)&q->ends, memory_order_acquire));
}
