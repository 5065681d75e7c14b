/* SPDX-License-Identifier: MIT */
#include "sw_parts_threads.h"

#include <pthread.h>
#include <stdatomic.h>

#include "sw_thread_name.h"

typedef struct parts_run {
    sw_part_fn fn;
    void *arg;
    uint32_t count;
    _Atomic uint32_t next;
} parts_run;

static void take_parts(parts_run *r)
{
    for (;;) {
        uint32_t p = atomic_fetch_add_explicit(&r->next, 1, memory_order_relaxed);
        if (p >= r->count)
            return;
        r->fn(r->arg, p);
    }
}

static void *helper_main(void *arg)
{
    sw_thread_name("sw-parts");
    take_parts(arg);
    return NULL;
}

/* The parts' results are read after the joins, which order them. */
static void run_parts(void *ctx, sw_part_fn fn, void *arg, uint32_t count)
{
    const sw_parts_threads *t = ctx;
    parts_run r = {.fn = fn, .arg = arg, .count = count};
    atomic_init(&r.next, 0);
    pthread_t helper[SW_PARTS_MAX_HELPERS];
    uint32_t started = 0;
    for (uint32_t i = 0; i < t->helpers && i + 1 < count; i++)
        if (pthread_create(&helper[started], NULL, helper_main, &r) == 0)
            started++;
    take_parts(&r);
    for (uint32_t i = 0; i < started; i++)
        pthread_join(helper[i], NULL);
}

sw_parts_runner sw_parts_threads_runner(sw_parts_threads *threads, uint32_t helpers)
{
    threads->helpers = helpers < SW_PARTS_MAX_HELPERS ? helpers : SW_PARTS_MAX_HELPERS;
    return (sw_parts_runner){.run = run_parts, .ctx = threads, .at_once = threads->helpers + 1};
}
