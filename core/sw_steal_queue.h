/* SPDX-License-Identifier: MIT */
/* A worker's queue of tessellation jobs with lock-free stealing (paper 000
 * section 5.1, after Kumar et al.'s load balancing): the visibility side
 * (one producer) appends job ids at the tail, the owning worker takes them
 * from the head in the order they came (the weight order the scheduler
 * pushed them in), and an idle worker takes the back half of a busy one's
 * queue in one compare-and-swap. No locks anywhere; every operation is one
 * CAS on a single 64-bit word (head, tail, a tag against ABA), retried when
 * another party moved first.
 *
 * Shared between threads: `ends` and `items`. Who writes: the producer
 * writes items at the tail and moves the tail up; the owner moves the head
 * up; a thief moves the tail down. Who reads: all three. Exactly one
 * producer per queue (a thief keeps what it stole in its own hands, it
 * never pushes: two producers could overwrite each other's slot).
 *
 * Memory: capacity uint32 slots from the caller (sw_steal_queue_bytes);
 * no allocation. */
#ifndef SW_STEAL_QUEUE_H
#define SW_STEAL_QUEUE_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"

/* Head and tail are 16-bit counters, so at most 2^15 waiting ids a queue. */
#define SW_STEAL_QUEUE_MAX (1u << 15)

typedef struct sw_steal_queue {
    _Atomic uint64_t ends;      /* head (bits 0-15), tail (16-31), tag (32-63) */
    _Atomic uint32_t *items;    /* capacity: job ids, the slot of count c at c % capacity */
    uint32_t capacity;          /* a power of two, <= SW_STEAL_QUEUE_MAX */
} sw_steal_queue;

/* Arena bytes of a queue of capacity ids, worst case. */
size_t sw_steal_queue_arena_bytes(uint32_t capacity);

/* capacity: a power of two from 1 to SW_STEAL_QUEUE_MAX (SW_ERR_ARG
 * otherwise); SW_ERR_NO_MEMORY when the arena is too small. */
sw_status sw_steal_queue_init(sw_steal_queue *q, uint32_t capacity, sw_arena *arena,
                              sw_error *err);

/* Producer only: appends id; 0 when the queue is full (nothing changes). */
int sw_steal_queue_push(sw_steal_queue *q, uint32_t id);

/* Owner only (any one thread at a time): the oldest id; 0 when empty. */
int sw_steal_queue_pop(sw_steal_queue *q, uint32_t *id);

/* A thief: moves the newest half of q's ids (rounded up: the last one too)
 * into out[0 .. returned), oldest first, at most max of them; 0 when q is
 * empty. */
uint32_t sw_steal_queue_steal(sw_steal_queue *q, uint32_t *out, uint32_t max);

/* Ids waiting (a snapshot: others may move it at once). */
uint32_t sw_steal_queue_size(const sw_steal_queue *q);

#endif
