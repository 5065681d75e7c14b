/* SPDX-License-Identifier: MIT */
/* Work cut into independent parts, for the checks a start waits on (the
 * pack's section checksums, the Seam Graph's rules) and for the pack
 * builder's levels. The core starts no thread of its own: a caller with
 * cores to spare (the runtime's loader, seamwalk-pack build;
 * core/sw_parts_threads.h) passes a runner that may run parts at once on
 * other threads; without one (NULL: the tests, the fuzzers) they run in
 * order on the calling thread. Either way every part runs, and the caller
 * reduces their results in part order, so the outcome and the error named
 * do not depend on the runner. */
#ifndef SW_PARTS_H
#define SW_PARTS_H

#include <stdint.h>

typedef void (*sw_part_fn)(void *arg, uint32_t part);

typedef struct sw_parts_runner {
    /* Calls fn(arg, p) exactly once for every p < count, in any order and
     * possibly at the same time on several threads; returns when all have
     * returned. Parts write only their own results. */
    void (*run)(void *ctx, sw_part_fn fn, void *arg, uint32_t count);
    void *ctx;
    uint32_t at_once;   /* parts run may run at the same time, at most (0: 1) */
} sw_parts_runner;

/* Runs the parts with runner, or in order here when runner is NULL. */
void sw_parts_run(const sw_parts_runner *runner, sw_part_fn fn, void *arg, uint32_t count);

/* How many parts runner may run at the same time (1 for NULL): a caller
 * that gives each running part scratch memory of its own makes that many. */
uint32_t sw_parts_at_once(const sw_parts_runner *runner);

/* Takes item on behalf of worker; 0 when it failed, which stops the
 * workers from taking more. */
typedef int (*sw_item_fn)(void *arg, uint32_t worker, uint32_t item);

/* Items 0 .. count - 1 of uneven cost, each taken once by one of `workers`
 * workers (the parts runner runs), the next item by whichever worker is
 * free: fn(arg, worker, item). A worker takes one item at a time, so it may
 * use what is worker's alone (its scratch memory, its counts); each worker
 * takes its items in rising order, the workers together in any. After a
 * call returns 0 no item is taken any more (those taken finish). */
void sw_parts_take_items(const sw_parts_runner *runner, uint32_t workers, sw_item_fn fn,
                         void *arg, uint32_t count);

#endif
