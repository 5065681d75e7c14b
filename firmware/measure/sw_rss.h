/* SPDX-License-Identifier: MIT */
/* The process's resident memory, read from /proc/self/status (Linux):
 * VmRSS now and VmHWM, the most it has been. The soak (seamwalk --duration)
 * reads it at the walk's start, after its first loop and at its end, to
 * show that memory stays flat; benchmarks compare runs by it. It reads
 * into a stack buffer with open/read/close, so calling it after start-up
 * allocates nothing. */
#ifndef SW_RSS_H
#define SW_RSS_H

#include <stdint.h>

typedef struct sw_rss {
    int64_t rss_kb;      /* VmRSS; -1 when unknown */
    int64_t peak_kb;     /* VmHWM; -1 when unknown */
    int64_t file_kb;     /* RssFile: of VmRSS, pages of mapped files (a mapped pack's,
                            the kernel's to drop and read again); -1 when unknown */
    int64_t anon_kb;     /* RssAnon: of VmRSS, the process's own (the arena, the heap,
                            Mesa's); -1 when unknown */
} sw_rss;

/* 1 when VmRSS and VmHWM were read, else 0 and both -1 (no /proc, or a
 * status file without them); RssFile and RssAnon are read where the
 * kernel has them (Linux 4.5 on). */
int sw_rss_read(sw_rss *out);

/* The figure after key ("VmRSS:") in a status text of n bytes, in kB; -1
 * when the key is absent or not followed by a number. */
int64_t sw_rss_field_kb(const char *text, int n, const char *key);

#endif
