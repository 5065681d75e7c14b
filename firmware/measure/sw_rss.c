/* SPDX-License-Identifier: MIT */
#include "sw_rss.h"

#include <fcntl.h>
#include <string.h>
#include <unistd.h>

int64_t sw_rss_field_kb(const char *text, int n, const char *key)
{
    int klen = (int)strlen(key);
    for (int i = 0; i + klen <= n; i++) {
        if ((i > 0 && text[i - 1] != '\n') || memcmp(text + i, key, (size_t)klen) != 0)
            continue;
        int j = i + klen;
        while (j < n && (text[j] == ' ' || text[j] == '\t'))
            j++;
        if (j >= n || text[j] < '0' || text[j] > '9')
            return -1;
        int64_t kb = 0;
        while (j < n && text[j] >= '0' && text[j] <= '9')
            kb = kb * 10 + (text[j++] - '0');
        return kb;
    }
    return -1;
}

int sw_rss_read(sw_rss *out)
{
    out->rss_kb = out->peak_kb = out->file_kb = out->anon_kb = -1;
    /* /proc/self/status is about 1.5 kB; 8 kB leaves room for kernels that
     * add fields. */
    char text[8192];
    int fd = open("/proc/self/status", O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return 0;
    int n = 0;
    for (ssize_t got; n < (int)sizeof text && (got = read(fd, text + n, sizeof text - n)) > 0;)
        n += (int)got;
    close(fd);
    out->rss_kb = sw_rss_field_kb(text, n, "VmRSS:");
    out->peak_kb = sw_rss_field_kb(text, n, "VmHWM:");
    out->file_kb = sw_rss_field_kb(text, n, "RssFile:");
    out->anon_kb = sw_rss_field_kb(text, n, "RssAnon:");
    if (out->rss_kb < 0 || out->peak_kb < 0) {
        out->rss_kb = out->peak_kb = -1;
        return 0;
    }
    return 1;
}
