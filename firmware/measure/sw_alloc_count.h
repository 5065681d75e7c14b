/* SPDX-License-Identifier: MIT */
/* Counts the heap calls seamwalk's own code makes, so the runtime can prove
 * its frame loop allocates nothing. The seamwalk binary is linked with
 * -Wl,--wrap=malloc (and calloc, realloc, free, posix_memalign,
 * aligned_alloc), which redirects every such call in our objects to the
 * __wrap_ functions in sw_alloc_count.c. Libraries we call (Mesa, libc's own
 * internals) are not wrapped: their allocations are theirs, not the frame
 * loop's, and are not counted. */
#ifndef SW_ALLOC_COUNT_H
#define SW_ALLOC_COUNT_H

#include <stdint.h>

/* Allocating calls (malloc, calloc, realloc, posix_memalign, aligned_alloc)
 * and frees made by our code since start. Thread-safe (atomic). */
uint64_t sw_alloc_count_allocs(void);
uint64_t sw_alloc_count_frees(void);

/* 1 when the binary was linked with the wrappers, so a zero count means
 * something; 0 in builds without them (the count then stays 0). */
int sw_alloc_count_active(void);

#endif
