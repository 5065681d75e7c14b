/* SPDX-License-Identifier: MIT */
/* The heap-call counter sees our code's malloc family through --wrap, so a
 * zero mallocs_after_init is evidence, not an absence of counting. */
#include <stdlib.h>

#include "sw_alloc_count.h"
#include "sw_test.h"

/* Pointers pass through a volatile sink so the optimiser cannot pair up
 * and delete the calls this test counts. */
static void *volatile sink;

static void test_counts_each_heap_call(void)
{
    uint64_t a0 = sw_alloc_count_allocs(), f0 = sw_alloc_count_frees();
    void *p = malloc(16);
    sink = p;
    void *q = calloc(2, 8);
    sink = q;
    p = realloc(sink == q ? p : NULL, 64);
    sink = p;
    void *r = NULL;
    SW_CHECK(posix_memalign(&r, 64, 128) == 0);
    free(p);
    free(q);
    free(r);
    free(NULL);
    SW_CHECK(sw_alloc_count_active() == 1);
    SW_CHECK(sw_alloc_count_allocs() - a0 == 4);
    SW_CHECK(sw_alloc_count_frees() - f0 == 3);
}

static void test_no_calls_no_count(void)
{
    uint64_t a0 = sw_alloc_count_allocs();
    volatile int x = 0;
    for (int i = 0; i < 1000; i++)
        x = x + i;
    SW_CHECK(x == 499500);
    SW_CHECK(sw_alloc_count_allocs() == a0);
}

int main(void)
{
    SW_RUN(test_counts_each_heap_call);
    SW_RUN(test_no_calls_no_count);
    return sw_test_finish();
}
