/* SPDX-License-Identifier: MIT */
/* A parts runner on threads (core/sw_parts.h), for the runtime's loader
 * and seamwalk-pack build: the calling thread and up to
 * SW_PARTS_MAX_HELPERS more take parts from one atomic counter. Helpers are
 * started for a run and joined at its end (a start makes two runs: the
 * section checksums and the Seam Graph's rules; a build one a level
 * rank and one for the part levels), so none outlives the run and the
 * runner holds no memory. On the showroom the loader's two runs are most
 * of the pack's checks, and the GL thread's core is idle by the time the
 * Seam Graph's come (seamwalk_start.c). A helper that cannot be started
 * leaves its parts to the others. */
#ifndef SW_PARTS_THREADS_H
#define SW_PARTS_THREADS_H

#include <stdint.h>

#include "sw_parts.h"

#define SW_PARTS_MAX_HELPERS 63u

typedef struct sw_parts_threads {
    uint32_t helpers;   /* threads besides the caller, <= SW_PARTS_MAX_HELPERS */
} sw_parts_threads;

/* helpers is clamped to SW_PARTS_MAX_HELPERS; the runner runs helpers + 1
 * parts at once at most. */
sw_parts_runner sw_parts_threads_runner(sw_parts_threads *threads, uint32_t helpers);

#endif
