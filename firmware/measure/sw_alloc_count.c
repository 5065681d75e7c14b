/* SPDX-License-Identifier: MIT */
#include "sw_alloc_count.h"

#include <stdatomic.h>
#include <stddef.h>
#include <stdlib.h>

static atomic_uint_fast64_t alloc_calls;
static atomic_uint_fast64_t free_calls;
static atomic_int wrapped;

uint64_t sw_alloc_count_allocs(void) { return atomic_load(&alloc_calls); }
uint64_t sw_alloc_count_frees(void) { return atomic_load(&free_calls); }
/* free(NULL) does nothing, but in a wrapped binary it passes through
 * __wrap_free, which marks the wrappers present: the count is active
 * whether or not our code has allocated anything by then (since the arena
 * became a mapping of its own, it may not have). */
int sw_alloc_count_active(void)
{
    void *volatile none = NULL;   /* volatile: the compiler drops a plain free(NULL) */
    free(none);
    return atomic_load(&wrapped);
}

/* Declarations for the linker's --wrap: __real_X is the original X. These are
 * defined only in binaries linked with the wrap options (see
 * firmware/CMakeLists.txt); elsewhere this file is linked without them and
 * the wrappers are simply unused. */
void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void __real_free(void *p);
int __real_posix_memalign(void **p, size_t align, size_t size);
void *__real_aligned_alloc(size_t align, size_t size);

void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t n, size_t size);
void *__wrap_realloc(void *p, size_t size);
void __wrap_free(void *p);
int __wrap_posix_memalign(void **p, size_t align, size_t size);
void *__wrap_aligned_alloc(size_t align, size_t size);

static void count_alloc(void)
{
    atomic_store(&wrapped, 1);
    atomic_fetch_add(&alloc_calls, 1);
}

void *__wrap_malloc(size_t size)
{
    count_alloc();
    return __real_malloc(size);
}

void *__wrap_calloc(size_t n, size_t size)
{
    count_alloc();
    return __real_calloc(n, size);
}

void *__wrap_realloc(void *p, size_t size)
{
    count_alloc();
    return __real_realloc(p, size);
}

void __wrap_free(void *p)
{
    atomic_store(&wrapped, 1);
    if (p)
        atomic_fetch_add(&free_calls, 1);
    __real_free(p);
}

int __wrap_posix_memalign(void **p, size_t align, size_t size)
{
    count_alloc();
    return __real_posix_memalign(p, align, size);
}

void *__wrap_aligned_alloc(size_t align, size_t size)
{
    count_alloc();
    return __real_aligned_alloc(align, size);
}
