/* SPDX-License-Identifier: MIT */
#include "sw_seam_workers.h"

#include <string.h>
#include <time.h>

#include "sw_thread_name.h"

_Static_assert(sizeof(sw_seam_job) == 2 * sizeof(float), "sw_walk_threads_bytes counts a job "
               "as two floats");

uint64_t sw_seam_worker_bytes(const sw_walk_sizes *m, int fill)
{
    return sw_seam_maker_arena_bytes(m) +
           (fill ? sw_seam_fill_arena_bytes(SW_WALK_VERTICES, SW_WALK_INDICES) : 0) +
           sw_steal_queue_arena_bytes(SW_SEAM_WORKER_QUEUE) +
           sw_arena_worst_case(SW_SEAM_WORKER_QUEUE * sizeof(uint32_t), 64);
}

static uint64_t now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (uint64_t)t.tv_sec * 1000000000ull + (uint64_t)t.tv_nsec;
}

/* Under alloc_lock: retired blocks whose frames have finished go back. */
static void take_retired(sw_seam_workers *p)
{
    sw_retired r;
    while (sw_retire_ring_take(&p->retire, &r)) {
        sw_buddy_free(&p->cache->vertex_pool, r.vertex_block);
        sw_buddy_free(&p->cache->index_pool, r.index_block);
    }
}

/* Under alloc_lock: a request of units of pool noted for
 * sw_seam_workers_asked. */
static void note_asked(sw_seam_workers *p, int pool, uint32_t units, int refused)
{
    uint32_t k = sw_buddy_order_of(units);
    p->asked_order[pool] = k > p->asked_order[pool] ? k : p->asked_order[pool];
    if (refused)
        p->refused_order[pool] = (int)k;
}

/* The cache's blocks for surface s's mesh of n vertices and m indices
 * (with reserve, only when a 1/SW_SEAM_STANDIN_RESERVE share of each pool
 * stays free beside them): retired blocks whose frame has finished go back
 * first. Under alloc_lock, which the workers and V (for stand-ins) take,
 * never P. */
static int place(sw_seam_workers *p, uint32_t s, uint32_t n, uint32_t m, int reserve,
                 sw_seam_entry *e)
{
    sw_seam_cache *c = p->cache;
    uint32_t vu = (n ? n : 1), iu = (m ? m : 1);
    vu = (vu + SW_SEAM_CACHE_VERTEX_UNIT - 1) / SW_SEAM_CACHE_VERTEX_UNIT;
    iu = (iu + SW_SEAM_CACHE_INDEX_UNIT - 1) / SW_SEAM_CACHE_INDEX_UNIT;
    pthread_mutex_lock(&p->alloc_lock);
    take_retired(p);
    uint32_t vb, ib;
    uint32_t keep_v = reserve ? c->vertex_pool.units / SW_SEAM_STANDIN_RESERVE : 0;
    uint32_t keep_i = reserve ? c->index_pool.units / SW_SEAM_STANDIN_RESERVE : 0;
    int vertex_ok = sw_buddy_alloc(&c->vertex_pool, vu, &vb);
    if (vertex_ok && c->vertex_pool.units - c->vertex_pool.used_units < keep_v) {
        sw_buddy_free(&c->vertex_pool, vb);
        vertex_ok = 0;
    }
    int ok = vertex_ok && sw_buddy_alloc(&c->index_pool, iu, &ib);
    if (ok && c->index_pool.units - c->index_pool.used_units < keep_i) {
        sw_buddy_free(&c->index_pool, ib);
        ok = 0;
    }
    if (vertex_ok && !ok)
        sw_buddy_free(&c->vertex_pool, vb);
    note_asked(p, SW_SEAM_VERTEX_POOL, vu, !vertex_ok);
    note_asked(p, SW_SEAM_INDEX_POOL, iu, vertex_ok && !ok);
    if (ok) {
        sw_buddy_set_owner(&c->vertex_pool, vb, s);
        sw_buddy_set_owner(&c->index_pool, ib, s);
    }
    pthread_mutex_unlock(&p->alloc_lock);
    if (ok)
        e->vertex_block = vb, e->index_block = ib;
    return ok;
}

int sw_seam_workers_place(void *ctx, uint32_t s, uint32_t n, uint32_t m, sw_seam_entry *e)
{
    return place(ctx, s, n, m, 0, e);
}

/* The workers' own: a batch remaking meshes holds the old and the new ones
 * side by side, and took the last free room from the stand-ins of
 * surfaces coming into view (drawn from nothing meanwhile). */
static int place_job(void *ctx, uint32_t s, uint32_t n, uint32_t m, sw_seam_entry *e)
{
    sw_seam_workers *p = ctx;
    return place(p, s, n, m, atomic_load_explicit(&p->reserve, memory_order_relaxed), e);
}

void sw_seam_workers_asked(sw_seam_workers *p, int pool, uint32_t *largest, int *refused)
{
    pthread_mutex_lock(&p->alloc_lock);
    *largest = p->asked_order[pool];
    *refused = p->refused_order[pool];
    pthread_mutex_unlock(&p->alloc_lock);
}

int sw_seam_workers_find_room(sw_seam_workers *p, int pool, uint32_t order,
                              sw_buddy_freeable_fn freeable, void *ctx, uint32_t *owners,
                              uint32_t cap, uint32_t *count)
{
    sw_buddy *b = pool == SW_SEAM_INDEX_POOL ? &p->cache->index_pool : &p->cache->vertex_pool;
    uint32_t first = 0;
    *count = 0;
    pthread_mutex_lock(&p->alloc_lock);
    take_retired(p);
    p->refused_order[pool] = -1;
    int room = sw_buddy_largest_free(b) >= (int)order            ? 2
               : sw_buddy_find_region(b, order, freeable, ctx, &first) ? 1
                                                                        : 0;
    if (room == 1)
        *count = sw_buddy_region_owners(b, first, order, owners, cap);
    pthread_mutex_unlock(&p->alloc_lock);
    return room;
}

void sw_seam_workers_pool_use(sw_seam_workers *p, uint32_t *vertex_units, uint32_t *index_units)
{
    pthread_mutex_lock(&p->alloc_lock);
    *vertex_units = p->cache->vertex_pool.used_units;
    *index_units = p->cache->index_pool.used_units;
    pthread_mutex_unlock(&p->alloc_lock);
}

int sw_seam_workers_retire(sw_seam_workers *p, sw_retired r)
{
    if (!sw_retire_ring_done(&p->retire, r.epoch))
        return sw_retire_ring_put(&p->retire, r);
    pthread_mutex_lock(&p->alloc_lock);
    sw_buddy_free(&p->cache->vertex_pool, r.vertex_block);
    sw_buddy_free(&p->cache->index_pool, r.index_block);
    pthread_mutex_unlock(&p->alloc_lock);
    return 1;
}

static void run_job(sw_seam_workers *p, sw_seam_maker *maker, uint32_t s)
{
    uint64_t t0 = now_ns();
    const sw_seam_job job = p->jobs[s];
    int no_room = 0;
    uint64_t tris = sw_seam_make(maker, s, job.bound, job.seam_bound, p->cache,
                                 place_job, p, &p->made[s], &no_room);
    p->no_room[s] = (uint8_t)no_room;
    atomic_fetch_add_explicit(&p->made_triangles, tris, memory_order_relaxed);
    atomic_fetch_add_explicit(&p->busy_ns, now_ns() - t0, memory_order_relaxed);
    int slow = atomic_load_explicit(&p->slow_ms, memory_order_relaxed);
    if (slow) /* the test hook: batches that take many frames */
        nanosleep(&(struct timespec){ slow / 1000, (long)(slow % 1000) * 1000000 }, NULL);
    /* The one atomic swap that hands the mesh over; the producer's rule
     * (one job per surface in flight, taken before the next) leaves the
     * slot empty here. */
    sw_publish_put(&p->slots[s], &p->made[s]);
    atomic_fetch_sub_explicit(&p->outstanding, 1, memory_order_release);
}

/* Half of a busy worker's queue, the next one after this worker first. */
static uint32_t steal(sw_seam_worker *w)
{
    sw_seam_workers *p = w->pool;
    for (uint32_t k = 1; k < p->count; k++) {
        uint32_t got = sw_steal_queue_steal(&p->worker[(w->index + k) % p->count].queue,
                                            w->stolen, SW_SEAM_WORKER_QUEUE);
        if (got) {
            atomic_fetch_add_explicit(&p->steals, 1, memory_order_relaxed);
            return got;
        }
    }
    return 0;
}

static void *worker_main(void *arg)
{
    sw_seam_worker *w = arg;
    sw_seam_workers *p = w->pool;
    sw_thread_name("sw-worker");
    while (!atomic_load_explicit(&p->stop, memory_order_acquire)) {
        if (atomic_load_explicit(&p->stall, memory_order_acquire)) {
            nanosleep(&(struct timespec){ 0, 1000000 }, NULL);   /* the test hook: idle */
            continue;
        }
        uint32_t s;
        if (sw_steal_queue_pop(&w->queue, &s)) {
            run_job(p, &w->maker, s);
            continue;
        }
        uint32_t got = steal(w);
        for (uint32_t i = 0; i < got; i++)
            run_job(p, &w->maker, w->stolen[i]);
        if (!got)
            sem_wait(&p->wake);
    }
    return NULL;
}

static sw_status init_worker(sw_seam_workers *p, uint32_t i, const sw_seam_fronts *fronts,
                             const sw_walk_sizes *m, int fill, sw_arena *arena, sw_error *err)
{
    sw_seam_worker *w = &p->worker[i];
    w->pool = p;
    w->index = i;
    sw_status st = sw_seam_maker_init(&w->maker, p->pack, fronts, m, arena, err);
    if (st == SW_OK && fill)
        st = sw_seam_fill_init(&w->fill, SW_WALK_VERTICES, SW_WALK_INDICES, arena, err);
    if (st == SW_OK)
        st = sw_steal_queue_init(&w->queue, SW_SEAM_WORKER_QUEUE, arena, err);
    if (st != SW_OK)
        return st;
    w->maker.fill = fill ? &w->fill : NULL;
    w->stolen = sw_arena_alloc(arena, SW_SEAM_WORKER_QUEUE * sizeof(uint32_t), 64);
    if (!w->stolen)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for worker %u", i);
    return SW_OK;
}

static sw_status init_shared(sw_seam_workers *p, uint32_t n, sw_arena *arena, sw_error *err)
{
    p->jobs = sw_arena_alloc(arena, (n + 1ull) * sizeof *p->jobs, 64);
    p->made = sw_arena_alloc(arena, (n + 1ull) * sizeof *p->made, 64);
    p->no_room = sw_arena_alloc(arena, n + 1ull, 64);
    p->slots = sw_arena_alloc(arena, (n + 1ull) * sizeof *p->slots, 64);
    if (!p->jobs || !p->made || !p->no_room || !p->slots)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the workers' state");
    memset(p->made, 0, (n + 1ull) * sizeof *p->made);
    memset(p->no_room, 0, n + 1ull);
    for (uint32_t s = 0; s <= n; s++)
        atomic_init(&p->slots[s], NULL);
    return sw_retire_ring_init(&p->retire, sw_walk_retire_capacity(n, p->cache->vertices), arena,
                               err);
}

sw_status sw_seam_workers_init(sw_seam_workers *p, uint32_t count, const sw_pack *pack,
                               const sw_seam_fronts *fronts, sw_seam_cache *cache,
                               const sw_walk_sizes *m, int fill, sw_arena *shared,
                               sw_arena *arena, sw_error *err)
{
    memset(p, 0, sizeof *p);
    if (count < 1 || count > SW_SEAM_WORKERS_MAX)
        return sw_error_set(err, SW_ERR_ARG, "workers: %u, expected 1 to %d", (unsigned)count,
                            SW_SEAM_WORKERS_MAX);
    p->pack = pack, p->cache = cache, p->count = count;
    p->refused_order[0] = p->refused_order[1] = -1;
    atomic_init(&p->outstanding, 0);
    atomic_init(&p->stop, 0);
    atomic_init(&p->stall, 0);
    atomic_init(&p->slow_ms, 0);
    atomic_init(&p->reserve, 0);
    atomic_init(&p->made_triangles, 0);
    atomic_init(&p->busy_ns, 0);
    atomic_init(&p->steals, 0);
    sw_status st = init_shared(p, cache->surface_count, shared, err);
    for (uint32_t i = 0; i < count && st == SW_OK; i++)
        st = init_worker(p, i, fronts, m, fill, arena, err);
    if (st != SW_OK)
        return st;
    if (pthread_mutex_init(&p->alloc_lock, NULL) != 0 || sem_init(&p->wake, 0, 0) != 0)
        return sw_error_set(err, SW_ERR_IO, "workers: cannot make their lock or semaphore");
    p->lock_up = p->sem_up = 1;
    for (uint32_t i = 0; i < count; i++) {
        if (pthread_create(&p->worker[i].thread, NULL, worker_main, &p->worker[i]) != 0) {
            sw_seam_workers_stop(p);
            return sw_error_set(err, SW_ERR_IO, "workers: cannot start thread %u", i);
        }
        p->worker[i].started = 1;
    }
    return SW_OK;
}

int sw_seam_workers_push(sw_seam_workers *p, uint32_t s)
{
    for (uint32_t k = 0; k < p->count; k++) {
        uint32_t q = (p->next_queue + k) % p->count;
        /* Counted before a worker can see it, so the count never dips
         * below what is in flight. */
        atomic_fetch_add_explicit(&p->outstanding, 1, memory_order_relaxed);
        if (sw_steal_queue_push(&p->worker[q].queue, s)) {
            p->next_queue = (q + 1) % p->count;
            return 1;
        }
        atomic_fetch_sub_explicit(&p->outstanding, 1, memory_order_relaxed);
    }
    return 0;
}

int sw_seam_workers_help(sw_seam_workers *p, sw_seam_maker *maker)
{
    for (uint32_t k = 0; k < p->count; k++) {
        uint32_t s;
        if (sw_steal_queue_steal(&p->worker[k].queue, &s, 1)) {
            run_job(p, maker, s);
            return 1;
        }
    }
    return 0;
}

void sw_seam_workers_wake(sw_seam_workers *p)
{
    for (uint32_t k = 0; k < p->count; k++)
        sem_post(&p->wake);
}

void sw_seam_workers_stop(sw_seam_workers *p)
{
    atomic_store_explicit(&p->stop, 1, memory_order_release);
    if (p->sem_up)
        for (uint32_t k = 0; k < p->count; k++)
            sem_post(&p->wake);
    for (uint32_t i = 0; i < p->count; i++)
        if (p->worker[i].started)
            pthread_join(p->worker[i].thread, NULL);
    for (uint32_t i = 0; i < p->count; i++)
        p->worker[i].started = 0;
    if (p->sem_up)
        sem_destroy(&p->wake);
    if (p->lock_up)
        pthread_mutex_destroy(&p->alloc_lock);
    p->sem_up = p->lock_up = 0;
}
