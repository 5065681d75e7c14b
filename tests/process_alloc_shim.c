/* SPDX-License-Identifier: MIT */
/* A preload library that counts every heap call of the whole process, for
 * the test that sets seamwalk's own count (sw_alloc_count, which sees only
 * our code through --wrap) beside what the process really does, Mesa's
 * llvmpipe and libc included:
 *   LD_PRELOAD=process_alloc_shim.so seamwalk ...
 * seamwalk finds sw_process_alloc_count with dlsym and reports the calls
 * made during its walk as process_mallocs_after_init. glibc's __libc_*
 * entry points do the work, so no dlsym is needed here (dlsym allocates). */
#include <errno.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

void *__libc_malloc(size_t size);
void *__libc_calloc(size_t n, size_t size);
void *__libc_realloc(void *p, size_t size);
void __libc_free(void *p);
void *__libc_memalign(size_t align, size_t size);

static _Atomic uint64_t calls;

uint64_t sw_process_alloc_count(void);
uint64_t sw_process_alloc_count(void) { return atomic_load(&calls); }

void *malloc(size_t size)
{
    atomic_fetch_add(&calls, 1);
    return __libc_malloc(size);
}

void *calloc(size_t n, size_t size)
{
    atomic_fetch_add(&calls, 1);
    return __libc_calloc(n, size);
}

void *realloc(void *p, size_t size)
{
    atomic_fetch_add(&calls, 1);
    return __libc_realloc(p, size);
}

void free(void *p)
{
    __libc_free(p);
}

int posix_memalign(void **out, size_t align, size_t size)
{
    atomic_fetch_add(&calls, 1);
    void *p = __libc_memalign(align, size);
    if (!p)
        return ENOMEM;
    *out = p;
    return 0;
}

void *aligned_alloc(size_t align, size_t size)
{
    atomic_fetch_add(&calls, 1);
    return __libc_memalign(align, size);
}

void *memalign(size_t align, size_t size);
void *memalign(size_t align, size_t size)
{
    atomic_fetch_add(&calls, 1);
    return __libc_memalign(align, size);
}
