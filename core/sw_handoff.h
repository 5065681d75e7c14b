/* SPDX-License-Identifier: MIT */
/* The hand-over of tessellations between the threads of the walk (paper
 * 000 section 5.2): a worker writes a new tessellation into fresh memory
 * and publishes it with one atomic pointer swap; the GL thread takes what
 * was published since its last frame, draws it from then on, and retires
 * the mesh it replaced into a ring stamped with the frame (the epoch) it
 * was last drawn in. The allocator's owner frees a retired mesh only once
 * the GL thread has finished that frame, so no memory is reused while it
 * can still be read (the GL thread reads the drawn meshes for upload and
 * measurement). Nobody waits: a full ring refuses, an empty slot is NULL.
 *
 * Shared between threads, all through C11 atomics:
 * - sw_publish_slot: written (put) by a worker, read and cleared (take) by
 *   the GL thread; the release of put orders the mesh's bytes before it.
 * - sw_retire_ring: one producer (the GL thread) and one consumer at a
 *   time (whoever holds the allocator); `done_epoch` written by the GL
 *   thread at the end of each frame, read by the consumer.
 * Memory from the caller's arena; no allocation. */
#ifndef SW_HANDOFF_H
#define SW_HANDOFF_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"

typedef _Atomic(void *) sw_publish_slot;

/* Worker: publishes p; returns what was there and not yet taken (NULL
 * normally: the caller then owns it and must give it back). */
static inline void *sw_publish_put(sw_publish_slot *slot, void *p)
{
    return atomic_exchange_explicit(slot, p, memory_order_acq_rel);
}

/* GL thread: what was published since the last take, or NULL; the slot is
 * empty afterwards. */
static inline void *sw_publish_take(sw_publish_slot *slot)
{
    if (!atomic_load_explicit(slot, memory_order_relaxed))
        return NULL;   /* the common case, without a write to the line */
    return atomic_exchange_explicit(slot, NULL, memory_order_acq_rel);
}

/* One retired mesh: its blocks in the cache's pools and the epoch (frame)
 * the GL thread last drew it in. */
typedef struct sw_retired {
    uint32_t vertex_block, index_block;
    uint32_t epoch;
} sw_retired;

typedef struct sw_retire_ring {
    sw_retired *items;          /* capacity */
    uint32_t capacity;          /* a power of two */
    _Atomic uint32_t head;      /* consumer's: next to free */
    _Atomic uint32_t tail;      /* producer's: next to fill */
    _Atomic uint32_t done_epoch;/* GL thread: frames before this one are finished */
} sw_retire_ring;

size_t sw_retire_ring_arena_bytes(uint32_t capacity);

/* capacity: a power of two >= 1, else SW_ERR_ARG; SW_ERR_NO_MEMORY when the
 * arena is too small. done_epoch starts at 0 (nothing finished). */
sw_status sw_retire_ring_init(sw_retire_ring *r, uint32_t capacity, sw_arena *arena,
                              sw_error *err);

/* Producer: retires a mesh last drawn in frame epoch. 0 when full. */
int sw_retire_ring_put(sw_retire_ring *r, sw_retired item);

/* GL thread: every frame before epoch has finished drawing. */
void sw_retire_ring_finish(sw_retire_ring *r, uint32_t epoch);

/* 1 when the frame epoch has finished drawing (any thread). */
int sw_retire_ring_done(const sw_retire_ring *r, uint32_t epoch);

/* Consumer: the oldest retired mesh whose frame has finished; 0 when there
 * is none (empty, or the oldest may still be read). */
int sw_retire_ring_take(sw_retire_ring *r, sw_retired *item);

#endif
