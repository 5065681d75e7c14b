/* SPDX-License-Identifier: MIT */
#define _DEFAULT_SOURCE /* madvise */
#include "sw_heap.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#define HUGE_TUNABLE "glibc.malloc.hugetlb"
#define START_ENV "SEAMWALK_START_NS"

/* 1 when the kernel gives huge pages only where advised. */
static int thp_on_advice(void)
{
    char mode[128] = "";
    int fd = open("/sys/kernel/mm/transparent_hugepage/enabled", O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return 0;
    ssize_t n = read(fd, mode, sizeof mode - 1);
    close(fd);
    mode[n > 0 ? n : 0] = '\0';
    return strstr(mode, "[madvise]") != NULL;
}

void sw_heap_huge_pages(char **argv, double start_s)
{
#ifdef __GLIBC__
    const char *tunables = getenv("GLIBC_TUNABLES");
    if ((tunables && strstr(tunables, HUGE_TUNABLE)) || !thp_on_advice())
        return;
    char value[1024], started[32];
    int n = snprintf(value, sizeof value, "%s%s" HUGE_TUNABLE "=1", tunables ? tunables : "",
                     tunables && *tunables ? ":" : "");
    if (n < 0 || (size_t)n >= sizeof value)
        return;   /* a tunables string this long is the user's business */
    snprintf(started, sizeof started, "%" PRId64, (int64_t)(start_s * 1e9));
    if (setenv("GLIBC_TUNABLES", value, 1) != 0 || setenv(START_ENV, started, 1) != 0)
        return;
    execv("/proc/self/exe", argv);
    unsetenv(START_ENV);   /* no exec: this run is the start, 4 KiB pages and all */
#else
    (void)argv;
    (void)start_s;
#endif
}

double sw_heap_started_s(double now_s)
{
    const char *started = getenv(START_ENV);
    if (!started)
        return now_s;
    char *end;
    errno = 0;
    long long ns = strtoll(started, &end, 10);
    unsetenv(START_ENV);   /* not for the programs this one starts */
    double s = (double)ns * 1e-9;
    /* A number, earlier than now and by less than a minute, or not ours. */
    int ours = errno == 0 && *end == '\0' && end != started && s <= now_s && now_s - s < 60.0;
    return ours ? s : now_s;
}

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
