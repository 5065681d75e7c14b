#define _DEFAULT_SOURCE /* madvise */
#include "sw_heap.h"

#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

/* glibc hands the top of its heap back once 128 kB of it are free and
 * takes it again for the next frame's driver work, so resident memory at a
 * loop's end went up and down with the last frames' work (585 to 594 MB on
 * the 40,000-patch showroom). A kiosk wants the memory taken and kept:
 * resident memory is then the most the heap has held. Setting it also
 * fixes the mmap threshold at 128 kB (no longer raised by what is freed),
 * so the driver's large blocks come and go as mappings. The pad makes the
 * heap grow in steps of at least pad_bytes, headroom sw_heap_populate
 * then takes too. */
void sw_heap_keep(size_t pad_bytes)
{
#ifdef __GLIBC__
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
    mallopt(M_TOP_PAD, pad_bytes < INT_MAX ? (int)pad_bytes : INT_MAX);
#else
    (void)pad_bytes;
#endif
}

/* The [heap] line's range in /proc/self/maps; 0 when there is none. Reads
 * through a small buffer: no allocation. */
static int heap_range(uintptr_t *lo, uintptr_t *hi)
{
    int fd = open("/proc/self/maps", O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return 0;
    char buf[4096];
    size_t have = 0;
    int found = 0;
    for (ssize_t got; !found && (got = read(fd, buf + have, sizeof buf - 1 - have)) > 0;) {
        have += (size_t)got;
        buf[have] = '\0';
        char *line = buf, *end;
        while (!found && (end = strchr(line, '\n'))) {
            *end = '\0';
            if (strstr(line, "[heap]")) {
                char *dash;
                *lo = (uintptr_t)strtoull(line, &dash, 16);
                *hi = (uintptr_t)strtoull(dash + 1, NULL, 16);
                found = *dash == '-';
            }
            line = end + 1;
        }
        have -= (size_t)(line - buf);
        memmove(buf, line, have);
    }
    close(fd);
    return found;
}

/* With batches bounded (sw_gl_pool.h) and the heap kept, its size stayed
 * put after the first loop, yet its resident part crept up for tens of
 * loops (the 8,000-patch showroom at 640x360: 67.2 to 70.6 MB of a 75.1 MB
 * heap in 40 s) as blocks came to parts of it never written before: the
 * first loop takes the heap to its size, scene blocks are written from
 * their start and free space not at all. madvise makes every page resident without changing a byte, free
 * chunks included. */
int sw_heap_populate(void)
{
    uintptr_t lo, hi;
    if (!heap_range(&lo, &hi))
        return 0;
    return sw_heap_populate_block((void *)lo, hi - lo);
}

int sw_heap_populate_block(void *block, size_t bytes)
{
    return block && madvise(block, bytes, MADV_POPULATE_WRITE) == 0;
}

void *sw_heap_take_block(size_t bytes)
{
    void *p = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        return NULL;
    madvise(p, bytes, MADV_HUGEPAGE);   /* ignored where the kernel offers none */
    return p;
}

void sw_heap_give_block(void *block, size_t bytes)
{
    if (block)
        munmap(block, bytes);
}
