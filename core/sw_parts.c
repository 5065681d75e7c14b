/* SPDX-License-Identifier: MIT */
#include "sw_parts.h"

#include <stdatomic.h>

void sw_parts_run(const sw_parts_runner *runner, sw_part_fn fn, void *arg, uint32_t count)
{
    if (runner && runner->run) {
        runner->run(runner->ctx, fn, arg, count);
        return;
    }
    for (uint32_t p = 0; p < count; p++)
        fn(arg, p);
}

uint32_t sw_parts_at_once(const sw_parts_runner *runner)
{
    return runner && runner->run && runner->at_once > 1 ? runner->at_once : 1;
}

/* One sw_parts_take_items call. Shared by its workers: next, which every
 * worker takes items from, and stop, which a worker whose item failed sets
 * and every worker reads before taking the next; the items' results are
 * read after the run, whose end orders them. */
typedef struct items_run {
    sw_item_fn fn;
    void *arg;
    uint32_t count;
    _Atomic uint32_t next;
    _Atomic int stop;
} items_run;

static void take_items(void *arg, uint32_t worker)
{
    items_run *r = arg;
    while (!atomic_load_explicit(&r->stop, memory_order_relaxed)) {
        uint32_t item = atomic_fetch_add_explicit(&r->next, 1, memory_order_relaxed);
        if (item >= r->count)
            return;
        if (!r->fn(r->arg, worker, item))
            atomic_store_explicit(&r->stop, 1, memory_order_relaxed);
    }
}

void sw_parts_take_items(const sw_parts_runner *runner, uint32_t workers, sw_item_fn fn,
                         void *arg, uint32_t count)
{
    items_run r = { .fn = fn, .arg = arg, .count = count };
    workers = workers ? workers : 1;
    atomic_init(&r.next, 0);
    atomic_init(&r.stop, 0);
    sw_parts_run(runner, take_items, &r, workers < count ? workers : count);
}
