/* SPDX-License-Identifier: MIT */
/* The tessellation workers T of the walk (paper 000 section 5): threads
 * that make surfaces' meshes asynchronously while the GL thread P draws.
 * The walk (the producer, on P's thread) writes a job's bounds into
 * jobs[s] and pushes s onto a worker's queue (sw_steal_queue.h: an idle
 * worker steals half of a busy one's); the worker makes the mesh with its
 * own maker (sw_seam_make.h) into fresh blocks of the cache's pools and
 * publishes made[s] with one atomic pointer swap (sw_handoff.h). P takes
 * what was published, uploads it and draws it from then on, and retires the
 * mesh it replaced; the workers give retired blocks back to the buddies
 * only after the frame that last drew them has finished. P never waits for
 * a worker and never touches the buddies (only the workers do, under
 * alloc_lock, which P never takes).
 *
 * Shared between threads:
 * - jobs[s]: written by the producer before the push, read by the worker
 *   that takes s (the queue's release/acquire orders them);
 * - made[s], slots[s]: written by that worker, then published; read by P
 *   after it takes the slot. At most one job per surface is in flight
 *   (the producer's rule), so a slot is never published twice untaken;
 * - outstanding: jobs pushed and not yet published (producer adds, worker
 *   subtracts, P reads);
 * - the cache's buddies and retire ring's consumer side: workers, under
 *   alloc_lock;
 * - stall (a test hook) and stop: written by P, read by the workers.
 * Threads are created at init (their stacks before the walk's allocation
 * count starts); all other memory comes from the arena. */
#ifndef SW_SEAM_WORKERS_H
#define SW_SEAM_WORKERS_H

#include <pthread.h>
#include <semaphore.h>
#include <stdatomic.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_buddy.h"
#include "sw_handoff.h"
#include "sw_seam_make.h"
#include "sw_steal_queue.h"

#define SW_SEAM_WORKERS_MAX 16

/* What a worker is asked to make for a surface. */
typedef struct sw_seam_job {
    float bound, seam_bound;      /* model units */
} sw_seam_job;

typedef struct sw_seam_worker {
    struct sw_seam_workers *pool;
    uint32_t index;
    sw_seam_maker maker;
    sw_seam_fill fill;
    sw_steal_queue queue;
    uint32_t *stolen;             /* what this worker took from another's queue */
    pthread_t thread;
    int started;
} sw_seam_worker;

typedef struct sw_seam_workers {
    const sw_pack *pack;
    sw_seam_cache *cache;
    uint32_t count;
    sw_seam_worker worker[SW_SEAM_WORKERS_MAX];
    sw_seam_job *jobs;            /* surface_count */
    sw_seam_entry *made;          /* surface_count */
    uint8_t *no_room;             /* surface_count: the worker's, published with made */
    sw_publish_slot *slots;       /* surface_count */
    sw_retire_ring retire;
    pthread_mutex_t alloc_lock;
    uint32_t asked_order[2];      /* under alloc_lock: the largest block asked of the vertex
                                     pool and of the index pool (its order) */
    int refused_order[2];         /* the last one refused since the last
                                     sw_seam_workers_find_room, -1 none */
    sem_t wake;                   /* posted by the producer after pushing */
    uint32_t next_queue;          /* producer's: round robin */
    _Atomic uint32_t outstanding;
    _Atomic int stop, stall;
    _Atomic int reserve;          /* the producer's: 1 while stand-ins draw what the workers
                                     have not made (their share of the pools kept) */
    _Atomic int slow_ms;          /* test hook: each job waits this long before publishing */
    _Atomic uint64_t made_triangles, busy_ns, steals; /* since init: for the controller */
    int lock_up, sem_up;
} sw_seam_workers;

/* Arena bytes of one worker (m the pack's largest surface): a maker, fill
 * fans (fill != 0), its queue and steal buffer. The state they share is in
 * the pack's runtime_bytes (sw_walk_threads_bytes). */
uint64_t sw_seam_worker_bytes(const sw_walk_sizes *m, int fill);

/* The queue's capacity per worker (jobs a frame can push to one worker). */
#define SW_SEAM_WORKER_QUEUE (1u << 13)

/* Starts count (1..SW_SEAM_WORKERS_MAX) threads: the state they share from
 * shared (counted in the pack's runtime_bytes), their own buffers from
 * arena (sw_seam_worker_bytes each). SW_ERR_ARG, NO_MEMORY or
 * SW_ERR_IO (a thread could not start); on error the started ones are
 * stopped. */
sw_status sw_seam_workers_init(sw_seam_workers *p, uint32_t count, const sw_pack *pack,
                               const sw_seam_fronts *fronts, sw_seam_cache *cache,
                               const sw_walk_sizes *m, int fill, sw_arena *shared,
                               sw_arena *arena, sw_error *err);

/* Producer: surface s with jobs[s] set is queued (round robin over the
 * workers' queues, in the order pushed); 0 when every queue is full. */
int sw_seam_workers_push(sw_seam_workers *p, uint32_t s);

/* A sw_seam_place_fn (ctx: the pool) for meshes the workers share the
 * cache with: V's stand-ins. While reserve is set, the workers' own
 * meshes leave a 1/SW_SEAM_STANDIN_RESERVE share of each pool free for
 * them. */
#define SW_SEAM_STANDIN_RESERVE 32u
int sw_seam_workers_place(void *ctx, uint32_t s, uint32_t n, uint32_t m, sw_seam_entry *e);

/* The units the cache's pools have in use (retired blocks not yet given
 * back included), read under alloc_lock. */
void sw_seam_workers_pool_use(sw_seam_workers *p, uint32_t *vertex_units, uint32_t *index_units);

/* The cache's pools as V keeps room in them. */
enum { SW_SEAM_VERTEX_POOL = 0, SW_SEAM_INDEX_POOL = 1 };

/* The order of the largest block asked of pool so far, and of the last
 * one it refused since the last sw_seam_workers_find_room (-1: none), read
 * under alloc_lock. */
void sw_seam_workers_asked(sw_seam_workers *p, int pool, uint32_t *largest, int *refused);

/* Room for a block of 2^order units of pool (sw_buddy_find_region under
 * alloc_lock, retired blocks whose frames have finished given back
 * first): 2 when one is free, 1 when a region would give one once the
 * blocks in it that freeable accepts are given up, their owners (the
 * surfaces; at most cap) then in owners and their count in *count; 0 when
 * no region would. The caller gives them up after the call
 * (sw_seam_workers_retire takes the lock). */
int sw_seam_workers_find_room(sw_seam_workers *p, int pool, uint32_t order,
                              sw_buddy_freeable_fn freeable, void *ctx, uint32_t *owners,
                              uint32_t cap, uint32_t *count);

/* Producer: a mesh given up, its blocks back to the pool at once when the
 * frame that last drew it has finished (under alloc_lock), else through
 * the retire ring; 0 when the ring is full. A mesh out of view for a while
 * so frees its room for what is made this frame; through the ring alone it
 * waited behind meshes retired since, of frames not yet drawn. */
int sw_seam_workers_retire(sw_seam_workers *p, sw_retired r);

/* Producer: wakes the workers after a round of pushes. */
void sw_seam_workers_wake(sw_seam_workers *p);

/* The producer's thread lending a hand where it may wait anyway (the first
 * frame, sync_work): takes one queued job from any worker's queue and makes
 * it with maker, as a worker would. 0 when no job was queued. */
int sw_seam_workers_help(sw_seam_workers *p, sw_seam_maker *maker);

/* Stops and joins the threads (safe on a partly started pool). */
void sw_seam_workers_stop(sw_seam_workers *p);

#endif
