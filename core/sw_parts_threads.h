/* SPDX-License-Identifier: MIT */
/* The loader's parts runner (core/sw_parts.h): the calling thread and up to
 * SW_PARTS_MAX_HELPERS more take parts from one atomic counter. Helpers are
 * started for a run and joined at its end (a start makes two runs: the
 * section checksums and the Seam Graph's rules), so none outlives the
 * load and the runner holds no memory. On the showroom the two runs are
 * most of the pack's checks, and the GL thread's core is idle by the time
 * the Seam Graph's come (seamwalk_start.c). A helper that cannot be started
 * leaves its parts to the others. */
#ifndef SW_PARTS_THREADS_H
#define SW_PARTS_THREADS_H

#include <stdint.h>

#include "sw_parts.h"

#define SW_PARTS_MAX_HELPERS 3u

typedef struct sw_parts_threads {
    uint32_t helpers;   /* threads besides the caller, <= SW_PARTS_MAX_HELPERS */
} sw_parts_threads;

/* helpers is clamped to SW_PARTS_MAX_HELPERS. */
sw_parts_runner sw_parts_threads_runner(sw_parts_threads *threads, uint32_t helpers);

#endif
