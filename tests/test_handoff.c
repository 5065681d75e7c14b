/* SPDX-License-Identifier: MIT */
/* The hand-over primitives (core/sw_handoff.h): a published mesh is seen
 * whole, a take empties the slot, and a retired mesh comes back for reuse
 * only after the frame that last drew it has finished. The threaded cases
 * run under TSan in the CI's thread step. */
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

#include "sw_handoff.h"
#include "sw_test.h"

static unsigned char arena_block[1 << 16];

static void test_take_empties_the_slot(void)
{
    sw_publish_slot slot;
    atomic_init(&slot, NULL);
    int a = 1, b = 2;
    SW_CHECK(sw_publish_take(&slot) == NULL);
    SW_CHECK(sw_publish_put(&slot, &a) == NULL);
    SW_CHECK(sw_publish_put(&slot, &b) == &a);   /* the untaken one comes back to the worker */
    SW_CHECK(sw_publish_take(&slot) == &b);
    SW_CHECK(sw_publish_take(&slot) == NULL);
}

static void test_ring_refuses_bad_capacity_and_when_full(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_retire_ring r;
    sw_error err = { 0 };
    SW_CHECK(sw_retire_ring_init(&r, 6, &a, &err) == SW_ERR_ARG);
    SW_CHECK(sw_retire_ring_init(&r, 2, &a, &err) == SW_OK);
    SW_CHECK(sw_retire_ring_put(&r, (sw_retired){ 1, 1, 0 }));
    SW_CHECK(sw_retire_ring_put(&r, (sw_retired){ 2, 2, 0 }));
    SW_CHECK(!sw_retire_ring_put(&r, (sw_retired){ 3, 3, 0 }));
}

static void test_retired_waits_for_its_frame(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_retire_ring r;
    sw_error err = { 0 };
    SW_CHECK(sw_retire_ring_init(&r, 8, &a, &err) == SW_OK);
    sw_retired got;
    SW_CHECK(sw_retire_ring_put(&r, (sw_retired){ 7, 9, 5 }));  /* last drawn in frame 5 */
    SW_CHECK(!sw_retire_ring_take(&r, &got));
    SW_CHECK(!sw_retire_ring_done(&r, 5) && !sw_retire_ring_done(&r, 0));
    sw_retire_ring_finish(&r, 5);                               /* frames before 5 done */
    SW_CHECK(!sw_retire_ring_take(&r, &got));
    SW_CHECK(sw_retire_ring_done(&r, 4) && !sw_retire_ring_done(&r, 5));
    sw_retire_ring_finish(&r, 6);                               /* frame 5 done */
    SW_CHECK(sw_retire_ring_done(&r, 5) && !sw_retire_ring_done(&r, 6));
    SW_CHECK(sw_retire_ring_take(&r, &got));
    SW_CHECK(got.vertex_block == 7 && got.index_block == 9 && got.epoch == 5);
    SW_CHECK(!sw_retire_ring_take(&r, &got));
    /* Across the counter's wrap. */
    sw_retire_ring_finish(&r, UINT32_MAX);
    SW_CHECK(sw_retire_ring_put(&r, (sw_retired){ 1, 1, UINT32_MAX }));
    SW_CHECK(!sw_retire_ring_take(&r, &got));
    sw_retire_ring_finish(&r, 0);
    SW_CHECK(sw_retire_ring_done(&r, UINT32_MAX) && !sw_retire_ring_done(&r, 0));
    SW_CHECK(sw_retire_ring_take(&r, &got) && got.epoch == UINT32_MAX);
}

/* Threads: a worker fills a buffer of its pool with one pattern and
 * publishes it; the GL side takes it, checks every word, draws it for a
 * frame and retires it; the worker reuses a buffer only when the ring gives
 * it back. A torn or early-reused buffer shows as a wrong word. */
enum { BUFFERS = 8, WORDS = 512, ROUNDS = 20000 };
static uint32_t pool[BUFFERS][WORDS];
static sw_publish_slot slot;
static sw_retire_ring ring;
static _Atomic int stop;
static _Atomic uint32_t reading[BUFFERS]; /* 1 while the GL side reads buffer k */
static uint32_t early;                    /* the producer's: reuses while being read */

static void *producer(void *unused)
{
    (void)unused;
    uint8_t free_buf[BUFFERS];
    memset(free_buf, 1, sizeof free_buf);
    uint32_t round = 0;
    while (round < ROUNDS) {
        sw_retired back;
        while (sw_retire_ring_take(&ring, &back))
            free_buf[back.vertex_block] = 1;
        int k = 0;
        while (k < BUFFERS && !free_buf[k])
            k++;
        if (k == BUFFERS)
            continue;   /* all in use: the GL side will retire one */
        free_buf[k] = 0;
        early += atomic_load(&reading[k]) != 0;
        for (int i = 0; i < WORDS; i++)
            pool[k][i] = round * 31u + (uint32_t)i;
        pool[k][0] = round;
        void *old = sw_publish_put(&slot, pool[k]);
        if (old)   /* never taken: never drawn, straight back to the pool */
            free_buf[((uint32_t(*)[WORDS])old) - pool] = 1;
        round++;
    }
    atomic_store(&stop, 1);
    return NULL;
}

static void test_published_buffers_seen_whole_and_reused_only_after_retire(void)
{
    sw_arena a;
    sw_arena_init(&a, arena_block, sizeof arena_block);
    sw_error err = { 0 };
    SW_CHECK(sw_retire_ring_init(&ring, 16, &a, &err) == SW_OK);
    atomic_init(&slot, NULL);
    pthread_t t;
    pthread_create(&t, NULL, producer, NULL);
    uint32_t frame = 1, bad = 0, seen = 0;
    int drawn = -1;
    while (!atomic_load(&stop) || atomic_load(&slot)) {
        uint32_t *p = sw_publish_take(&slot);
        if (p) {
            int k = (int)(((uint32_t(*)[WORDS])p) - pool);
            atomic_store(&reading[k], 1);
            for (int i = 1; i < WORDS; i++)
                bad += p[i] != p[0] * 31u + (uint32_t)i;
            atomic_store(&reading[k], 0);
            if (drawn >= 0)
                SW_CHECK(sw_retire_ring_put(&ring, (sw_retired){ (uint32_t)drawn, 0, frame }));
            drawn = k;
            seen++;
        }
        sw_retire_ring_finish(&ring, frame);   /* frames before this one are finished */
        frame++;
    }
    pthread_join(t, NULL);
    SW_CHECK_MSG(bad == 0, "%u words torn", (unsigned)bad);
    SW_CHECK_MSG(early == 0, "%u buffers reused while read", (unsigned)early);
    SW_CHECK(seen > 0);
}

int main(void)
{
    SW_RUN(test_take_empties_the_slot);
    SW_RUN(test_ring_refuses_bad_capacity_and_when_full);
    SW_RUN(test_retired_waits_for_its_frame);
    SW_RUN(test_published_buffers_seen_whole_and_reused_only_after_retire);
    return sw_test_finish();
}
