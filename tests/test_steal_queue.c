/* SPDX-License-Identifier: MIT */
/* The workers' queues (core/sw_steal_queue.h): order, capacity, stealing
 * half, and under threads every job taken exactly once (run under TSan by
 * the CI's thread step). */
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

#include "sw_steal_queue.h"
#include "sw_test.h"

static unsigned char arena_block[1 << 20];

static sw_steal_queue make(sw_arena *a, uint32_t capacity)
{
    sw_steal_queue q;
    sw_error err = { 0 };
    SW_CHECK(sw_steal_queue_init(&q, capacity, a, &err) == SW_OK);
    return q;
}

static void test_capacity_must_be_power_of_two(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_steal_queue q;
    sw_error err = { 0 };
    SW_CHECK(sw_steal_queue_init(&q, 0, &a, &err) == SW_ERR_ARG);
    SW_CHECK(sw_steal_queue_init(&q, 12, &a, &err) == SW_ERR_ARG);
    SW_CHECK(strstr(err.message, "power of two") != NULL);
    SW_CHECK(sw_steal_queue_init(&q, SW_STEAL_QUEUE_MAX * 2, &a, &err) == SW_ERR_ARG);
    sw_arena tiny;
    static unsigned char small[16];
    sw_arena_init(&tiny, small, sizeof small);
    SW_CHECK(sw_steal_queue_init(&q, 64, &tiny, &err) == SW_ERR_NO_MEMORY);
}

static void test_owner_takes_in_push_order_until_full(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_steal_queue q = make(&a, 4);
    for (uint32_t i = 0; i < 4; i++)
        SW_CHECK(sw_steal_queue_push(&q, 10 + i));
    SW_CHECK(!sw_steal_queue_push(&q, 99));
    SW_CHECK(sw_steal_queue_size(&q) == 4);
    uint32_t id = 0;
    for (uint32_t i = 0; i < 4; i++) {
        SW_CHECK(sw_steal_queue_pop(&q, &id));
        SW_CHECK(id == 10 + i);
    }
    SW_CHECK(!sw_steal_queue_pop(&q, &id));
}

static void test_thief_takes_newest_half_rounded_up(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_steal_queue q = make(&a, 16);
    for (uint32_t i = 0; i < 7; i++)
        sw_steal_queue_push(&q, i);
    uint32_t out[16];
    SW_CHECK(sw_steal_queue_steal(&q, out, 16) == 4);
    SW_CHECK(out[0] == 3 && out[1] == 4 && out[2] == 5 && out[3] == 6);
    SW_CHECK(sw_steal_queue_size(&q) == 3);
    SW_CHECK(sw_steal_queue_steal(&q, out, 1) == 1 && out[0] == 2);
    uint32_t id;
    SW_CHECK(sw_steal_queue_pop(&q, &id) && id == 0);
    SW_CHECK(sw_steal_queue_steal(&q, out, 16) == 1 && out[0] == 1);
    SW_CHECK(sw_steal_queue_steal(&q, out, 16) == 0);
}

static void test_counters_wrap(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_steal_queue q = make(&a, 8);
    uint32_t id, next = 0, out[8];
    for (uint32_t round = 0; round < 70000; round++) {
        SW_CHECK(sw_steal_queue_push(&q, round));
        if (round % 3 == 2) {
            SW_CHECK(sw_steal_queue_steal(&q, out, 8) == 1 && out[0] == round);
            continue;
        }
        if (!(sw_steal_queue_pop(&q, &id) && id == round))
            next++;
    }
    SW_CHECK(next == 0);
    SW_CHECK(sw_steal_queue_size(&q) == 0);
}

/* Threads: one producer, WORKERS owners that also steal from each other. */
enum { WORKERS = 3, JOBS = 200000, CAP = 1024 };
typedef struct shared {
    sw_steal_queue q[WORKERS];
    _Atomic uint32_t taken[JOBS];
    _Atomic int produced_all;
    _Atomic uint32_t stolen;
} shared;
static shared sh;

typedef struct worker_arg { int me; } worker_arg;

static void take(uint32_t id) { atomic_fetch_add_explicit(&sh.taken[id], 1, memory_order_relaxed); }

static void *worker(void *p)
{
    int me = ((worker_arg *)p)->me;
    uint32_t id, out[CAP];
    for (;;) {
        if (sw_steal_queue_pop(&sh.q[me], &id)) {
            take(id);
            continue;
        }
        uint32_t got = 0;
        for (int k = 1; k < WORKERS && !got; k++)
            got = sw_steal_queue_steal(&sh.q[(me + k) % WORKERS], out, CAP);
        for (uint32_t i = 0; i < got; i++)
            take(out[i]);
        atomic_fetch_add_explicit(&sh.stolen, got, memory_order_relaxed);
        if (!got && atomic_load(&sh.produced_all)) {
            int left = 0;
            for (int k = 0; k < WORKERS; k++)
                left |= sw_steal_queue_size(&sh.q[k]) != 0;
            if (!left)
                return NULL;
        }
    }
}

static void test_every_job_taken_once_under_threads(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    for (int k = 0; k < WORKERS; k++)
        sh.q[k] = make(&a, CAP);
    for (uint32_t i = 0; i < JOBS; i++)
        atomic_init(&sh.taken[i], 0);
    pthread_t t[WORKERS];
    worker_arg args[WORKERS];
    for (int k = 0; k < WORKERS; k++) {
        args[k].me = k;
        pthread_create(&t[k], NULL, worker, &args[k]);
    }
    /* Everything into queue 0 (a skewed load): the others live on steals. */
    for (uint32_t i = 0; i < JOBS; i++)
        while (!sw_steal_queue_push(&sh.q[i % 7 == 0 ? 1 : 0], i))
            ;
    atomic_store(&sh.produced_all, 1);
    for (int k = 0; k < WORKERS; k++)
        pthread_join(t[k], NULL);
    uint32_t wrong = 0;
    for (uint32_t i = 0; i < JOBS; i++)
        wrong += atomic_load(&sh.taken[i]) != 1;
    SW_CHECK_MSG(wrong == 0, "%u jobs not taken exactly once", (unsigned)wrong);
    SW_CHECK_MSG(atomic_load(&sh.stolen) > 0, "no steals happened");
}

int main(void)
{
    SW_RUN(test_capacity_must_be_power_of_two);
    SW_RUN(test_owner_takes_in_push_order_until_full);
    SW_RUN(test_thief_takes_newest_half_rounded_up);
    SW_RUN(test_counters_wrap);
    SW_RUN(test_every_job_taken_once_under_threads);
    return sw_test_finish();
}
