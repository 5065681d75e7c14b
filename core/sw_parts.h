/* SPDX-License-Identifier: MIT */
/* Work cut into independent parts, for the checks a start waits on (the
 * pack's section checksums, the Seam Graph's rules). The core starts no
 * thread of its own: a caller with cores to spare (the runtime's loader,
 * core/sw_parts_threads.h) passes a runner that may run parts at once on
 * other threads; without one (NULL: the host tool, the tests, the fuzzers)
 * they run in order on the calling thread. Either way every part runs, and
 * the caller reduces their results in part order, so the outcome and the
 * error named do not depend on the runner. */
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
} sw_parts_runner;

/* Runs the parts with runner, or in order here when runner is NULL. */
void sw_parts_run(const sw_parts_runner *runner, sw_part_fn fn, void *arg, uint32_t count);

#endif
