/* SPDX-License-Identifier: MIT */
/* The progress line (sw_progress.h). */
#include "sw_progress.h"

#include <string.h>
#include <time.h>
#include <unistd.h>

static double monotonic_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void sw_progress_init(sw_progress *p, FILE *out, int quiet)
{
    memset(p, 0, sizeof *p);
    p->out = out;
    p->enabled = !quiet && out && isatty(fileno(out));
    p->clock_s = monotonic_s;
    p->min_interval_s = 0.1; /* ~10 redraws a second: smooth, and cheap over ssh */
    p->last_draw_s = -1.0;
}

/* Length of the longest prefix of s within max bytes that does not split a
 * UTF-8 character (file names are shown as given). */
static size_t utf8_prefix(const char *s, size_t max)
{
    size_t n = strlen(s);
    if (n <= max)
        return n;
    while (max > 0 && ((unsigned char)s[max] & 0xC0) == 0x80)
        max--;
    return max;
}

size_t sw_progress_format(char *buf, size_t cap, const char *stage, double fraction,
                          double count, const char *unit, double elapsed_s)
{
    if (cap <= SW_PROGRESS_WIDTH)
        return 0;
    if (!(fraction >= 0.0)) /* NaN too */
        fraction = 0.0;
    if (fraction > 1.0)
        fraction = 1.0;
    char tail[48];
    int n = snprintf(tail, sizeof tail, "  %3d%%", (int)(fraction * 100.0));
    if (unit && count > 0.0 && elapsed_s > 0.0) {
        double rate = count / elapsed_s;
        snprintf(tail + n, sizeof tail - (size_t)n, rate < 10.0 ? "  %.1f %s/s" : "  %.0f %s/s",
                 rate, unit);
    }
    size_t tail_len = strlen(tail);
    size_t room = SW_PROGRESS_WIDTH > tail_len ? SW_PROGRESS_WIDTH - tail_len : 0;
    const char *s = stage ? stage : "";
    size_t keep = strlen(s) <= room ? strlen(s) : utf8_prefix(s, room >= 3 ? room - 3 : 0);
    memcpy(buf, s, keep);
    size_t len = keep;
    if (keep < strlen(s)) {
        memcpy(buf + len, "...", 3);
        len += 3;
    }
    size_t copy = tail_len <= SW_PROGRESS_WIDTH - len ? tail_len : SW_PROGRESS_WIDTH - len;
    memcpy(buf + len, tail, copy);
    len += copy;
    buf[len] = '\0';
    return len;
}

/* Draws line over what is on the terminal line now. */
static void draw(sw_progress *p, const char *line, size_t len)
{
    fputc('\r', p->out);
    fputs(line, p->out);
    for (size_t i = len; i < p->drawn; i++)
        fputc(' ', p->out);
    fflush(p->out);
    p->drawn = len;
}

void sw_progress_update(sw_progress *p, const char *stage, double fraction, double count,
                        const char *unit)
{
    if (!p || !p->enabled)
        return;
    double now = p->clock_s();
    if (!stage)
        stage = "";
    if (strncmp(stage, p->stage, sizeof p->stage - 1) != 0) {
        snprintf(p->stage, sizeof p->stage, "%s", stage);
        p->stage_start_s = now;
        p->last_draw_s = -1.0;
    }
    if (p->last_draw_s >= 0.0 && now - p->last_draw_s < p->min_interval_s)
        return;
    char line[SW_PROGRESS_WIDTH + 1];
    size_t len = sw_progress_format(line, sizeof line, stage, fraction, count, unit,
                                    now - p->stage_start_s);
    draw(p, line, len);
    p->last_draw_s = now;
}

void sw_progress_clear(sw_progress *p)
{
    if (!p || !p->enabled || p->drawn == 0)
        return;
    fputc('\r', p->out);
    for (size_t i = 0; i < p->drawn; i++)
        fputc(' ', p->out);
    fputc('\r', p->out);
    fflush(p->out);
    p->drawn = 0;
    p->last_draw_s = -1.0;
}
