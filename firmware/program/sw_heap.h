/* SPDX-License-Identifier: MIT */
/* The process heap, held for the GL driver so that resident memory is
 * taken at start and does not move in a walk (docs/architecture.md,
 * "Memory after start"). Our own memory is the arena; after start only the
 * driver and libc use the heap (Mesa's llvmpipe: its binned scenes, 64 kiB
 * blocks, every frame). glibc only (elsewhere these do nothing). Called by
 * seamwalk's main thread. */
#ifndef SW_HEAP_H
#define SW_HEAP_H

#include <stddef.h>

/* Runs this program again, once, with glibc's heap on transparent huge
 * pages (the tunable glibc.malloc.hugetlb=1, which glibc reads only as a
 * process starts). Why: llvmpipe zeroes a GL buffer's store as it makes
 * it, and on 4 KiB pages the GL pool's 112 MB on the 40,000-patch
 * showroom was a page fault every 4 KiB, about 200 ms of the start. Does
 * nothing, and returns, when GLIBC_TUNABLES already names the setting
 * (set by us before, or by the user: glibc.malloc.hugetlb=0 keeps 4 KiB
 * pages), when the kernel's THP mode is not "madvise" ("always" needs no
 * advice, "never" takes none), or when the exec fails. start_s is passed
 * on (SEAMWALK_START_NS), so the start's figures count the run again;
 * sw_heap_started_s reads it back. First thing in main, before a thread. */
void sw_heap_huge_pages(char **argv, double start_s);

/* The start_s an earlier sw_heap_huge_pages passed on, or now_s when none
 * (or a malformed one: the start is then this process's). */
double sw_heap_started_s(double now_s);

/* Nothing freed is given back to the system from now on, and the heap
 * grows by at least pad_bytes at a time. Before the GL starts. */
void sw_heap_keep(size_t pad_bytes);

/* Makes every page of the heap resident now (madvise MADV_POPULATE_WRITE,
 * Linux 5.14 or later; no allocation). Returns 1 when it did, 0 when it
 * could not (no [heap] mapping found, or an older kernel). Once the driver
 * has done a loop's work: its compiles and scenes have sized the heap. */
int sw_heap_populate(void);

/* The same for a block of ours (the arena's mapping): every page resident,
 * contents unchanged, safe while other threads use it. 1 when done. */
int sw_heap_populate_block(void *block, size_t bytes);

/* A block of bytes for an arena, a mapping of its own marked for
 * transparent huge pages: the start writes a few hundred MiB into the
 * arena once, and in 4 KiB pages each first touch was a page fault, a
 * quarter of the showroom's start. Not from malloc: the heap is the GL
 * driver's. NULL when it cannot be had; give it back with its size. */
void *sw_heap_take_block(size_t bytes);
void sw_heap_give_block(void *block, size_t bytes);

#endif
