/* SPDX-License-Identifier: MIT */
/* The arena: bump allocation, alignment, exhaustion, marks, in-place growth,
 * slabs, and touching the block at start. */
#define _DEFAULT_SOURCE /* mincore, MAP_ANONYMOUS */
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "sw_arena.h"
#include "sw_test.h"

static unsigned char block[1 << 16] __attribute__((aligned(64)));

static void test_alloc_respects_alignment_and_size(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    void *p1 = sw_arena_alloc(&a, 3, 1);
    void *p2 = sw_arena_alloc(&a, 8, 64);
    SW_CHECK(p1 == block);
    SW_CHECK(((uintptr_t)p2 & 63) == 0);
    SW_CHECK((unsigned char *)p2 >= block + 3);
    SW_CHECK(a.used == (size_t)((unsigned char *)p2 - block) + 8);
}

static void test_alloc_fails_cleanly_when_full(void)
{
    sw_arena a;
    sw_arena_init(&a, block, 100);
    SW_CHECK(sw_arena_alloc(&a, 100, 1) != NULL);
    SW_CHECK(sw_arena_alloc(&a, 1, 1) == NULL);
    SW_CHECK(a.used == 100);
    sw_arena_init(&a, block, 100);
    SW_CHECK(sw_arena_alloc(&a, SIZE_MAX, 1) == NULL);
    SW_CHECK(sw_arena_alloc(&a, SIZE_MAX - 8, 64) == NULL);
    SW_CHECK(a.used == 0);
}

static void test_mark_and_reset_give_memory_back(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_arena_alloc(&a, 100, 8);
    size_t mark = sw_arena_mark(&a);
    sw_arena_alloc(&a, 5000, 8);
    sw_arena_reset_to(&a, mark);
    SW_CHECK(a.used == mark);
    SW_CHECK(a.peak >= mark + 5000);
}

static void test_realloc_grows_last_block_in_place(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    char *p = sw_arena_alloc(&a, 10, 8);
    memcpy(p, "abcdefghij", 10);
    char *q = sw_arena_realloc(&a, p, 10, 1000, 8);
    SW_CHECK(q == p);
    SW_CHECK(memcmp(q, "abcdefghij", 10) == 0);
    char *other = sw_arena_alloc(&a, 4, 8);
    char *r = sw_arena_realloc(&a, q, 1000, 2000, 8);
    SW_CHECK(r != q && r > other);
    SW_CHECK(memcmp(r, "abcdefghij", 10) == 0);
    SW_CHECK(sw_arena_realloc(&a, r, 2000, sizeof block, 8) == NULL);
}

static void test_slab_takes_and_gives_every_slot(void)
{
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    sw_slab s;
    SW_CHECK(sw_slab_init(&s, &a, 48, 10) == 0);
    SW_CHECK(a.used <= sw_slab_arena_bytes(48, 10));
    void *slots[10];
    for (int i = 0; i < 10; i++) {
        slots[i] = sw_slab_take(&s);
        SW_CHECK(slots[i] != NULL);
        SW_CHECK(((uintptr_t)slots[i] - (uintptr_t)s.slots) % 48 == 0);
    }
    SW_CHECK(sw_slab_take(&s) == NULL);
    SW_CHECK(s.in_use == 10);
    sw_slab_give(&s, slots[3]);
    SW_CHECK(sw_slab_take(&s) == slots[3]);
    for (int i = 0; i < 10; i++)
        sw_slab_give(&s, slots[i]);
    SW_CHECK(s.in_use == 0);
}

static void test_slab_init_refuses_small_arena(void)
{
    sw_arena a;
    sw_arena_init(&a, block, 100);
    sw_slab s;
    SW_CHECK(sw_slab_init(&s, &a, 64, 10) == -1);
    SW_CHECK(sw_slab_init(&s, &a, 0, 10) == -1);
}

/* Pages resident in [p, p + pages pages), by mincore. */
static size_t resident_pages(unsigned char *p, size_t pages, size_t page)
{
    unsigned char vec[64];
    SW_CHECK(pages <= sizeof vec && mincore(p, pages * page, vec) == 0);
    size_t n = 0;
    for (size_t i = 0; i < pages; i++)
        n += vec[i] & 1;
    return n;
}

static void test_touch_makes_every_page_resident(void)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE), pages = 64;
    unsigned char *pages_block = mmap(NULL, pages * page, PROT_READ | PROT_WRITE,
                                      MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    SW_CHECK(pages_block != MAP_FAILED);
    sw_arena a;
    sw_arena_init(&a, pages_block, pages * page);
    SW_CHECK(resident_pages(pages_block, pages, page) == 0);
    sw_arena_touch(&a);
    SW_CHECK(resident_pages(pages_block, pages, page) == pages);
    SW_CHECK(a.used == 0 && pages_block[pages * page - 1] == 0);
    munmap(pages_block, pages * page);
}

int main(void)
{
    SW_RUN(test_alloc_respects_alignment_and_size);
    SW_RUN(test_alloc_fails_cleanly_when_full);
    SW_RUN(test_mark_and_reset_give_memory_back);
    SW_RUN(test_realloc_grows_last_block_in_place);
    SW_RUN(test_slab_takes_and_gives_every_slot);
    SW_RUN(test_slab_init_refuses_small_arena);
    SW_RUN(test_touch_makes_every_page_resident);
    return sw_test_finish();
}
