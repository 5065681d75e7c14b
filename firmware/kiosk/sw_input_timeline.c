/* SPDX-License-Identifier: MIT */
/* Input timeline and hex byte parsers (sw_input_timeline.h). A line is cut
 * into at most 300 whitespace-separated words in place of a copy, so a line
 * of any length is read without a buffer. */
#include "sw_input_timeline.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_hex.h"

enum { WORDS_MAX = 300 };

typedef struct word { const char *p; size_t n; } word;

typedef struct line_ctx {
    const char *file;
    long line;
    sw_error *err;
} line_ctx;

static sw_status fail(const line_ctx *c, const char *what, word got)
{
    int n = got.n > 40 ? 40 : (int)got.n;
    return sw_error_set(c->err, SW_ERR_FORMAT, "%s:%ld: %s, got '%.*s'", c->file, c->line, what,
                        n, got.p ? got.p : "");
}

static int split(const char *p, size_t n, word *w, int max)
{
    int count = 0;
    size_t i = 0;
    while (i < n) {
        while (i < n && (p[i] == ' ' || p[i] == '\t' || p[i] == '\r'))
            i++;
        if (i >= n || p[i] == '#')
            break;
        size_t s = i;
        while (i < n && p[i] != ' ' && p[i] != '\t' && p[i] != '\r' && p[i] != '#')
            i++;
        if (count == max)
            return -1;
        w[count++] = (word){p + s, i - s};
    }
    return count;
}

static int is(word w, const char *s) { return strlen(s) == w.n && !memcmp(w.p, s, w.n); }

static int to_number(word w, double *out)
{
    char buf[64];
    if (w.n == 0 || w.n >= sizeof buf)
        return 0;
    memcpy(buf, w.p, w.n);
    buf[w.n] = '\0';
    char *end;
    errno = 0;
    double v = strtod(buf, &end);
    if (*end || errno || !isfinite(v) || strpbrk(buf, "xXnNiI"))
        return 0;
    *out = v;
    return 1;
}

static int to_int(word w, long lo, long hi, long *out)
{
    double v;
    if (!to_number(w, &v) || v != floor(v) || v < lo || v > hi || memchr(w.p, '.', w.n) ||
        memchr(w.p, 'e', w.n) || memchr(w.p, 'E', w.n))
        return 0;
    *out = (long)v;
    return 1;
}

/* 1..4 hex digits. */
static int to_hex16(word w, uint16_t *out)
{
    if (w.n == 0 || w.n > 4)
        return 0;
    unsigned v = 0;
    for (size_t i = 0; i < w.n; i++) {
        int d = sw_hex_digit(w.p[i]);
        if (d < 0)
            return 0;
        v = v << 4 | (unsigned)d;
    }
    *out = (uint16_t)v;
    return 1;
}

static int to_byte(word w, uint8_t *out)
{
    int hi = w.n == 2 ? sw_hex_digit(w.p[0]) : -1, lo = w.n == 2 ? sw_hex_digit(w.p[1]) : -1;
    if (hi < 0 || lo < 0)
        return 0;
    *out = (uint8_t)(hi << 4 | lo);
    return 1;
}

static int copy_text(word w, char *dst, size_t cap)
{
    if (w.n == 0 || w.n >= cap)
        return 0;
    memcpy(dst, w.p, w.n);
    dst[w.n] = '\0';
    return 1;
}

static sw_status parse_plug(const line_ctx *c, const word *w, int n, sw_timeline_event *e)
{
    if (n != 9 && n != 10)
        return fail(c, "expected TIME pad SLOT plug BUS VENDOR PRODUCT VERSION DESCRIPTOR "
                    "[NAME]", w[3]);
    if (!to_hex16(w[4], &e->bus) || !to_hex16(w[5], &e->vendor) ||
        !to_hex16(w[6], &e->product) || !to_hex16(w[7], &e->version))
        return fail(c, "expected BUS VENDOR PRODUCT VERSION as 1..4 hex digits each", w[4]);
    if (!copy_text(w[8], e->file, sizeof e->file))
        return fail(c, "expected a descriptor file name of at most 159 bytes", w[8]);
    if (n == 10 && !copy_text(w[9], e->name, sizeof e->name))
        return fail(c, "expected a name of at most 31 bytes", w[9]);
    e->kind = SW_TL_PLUG;
    return SW_OK;
}

static sw_status parse_pad(const line_ctx *c, const word *w, int n, sw_timeline_event *e)
{
    long slot;
    if (n < 4 || !to_int(w[2], 0, 3, &slot))
        return fail(c, "expected TIME pad SLOT (0..3) plug|report|unplug ...", n > 2 ? w[2] : w[1]);
    e->slot = (uint8_t)slot;
    if (is(w[3], "plug"))
        return parse_plug(c, w, n, e);
    if (is(w[3], "unplug")) {
        if (n != 4)
            return fail(c, "expected nothing after unplug", w[4]);
        e->kind = SW_TL_UNPLUG;
        return SW_OK;
    }
    if (!is(w[3], "report"))
        return fail(c, "expected plug, report or unplug", w[3]);
    if (n < 5 || n - 4 > SW_HID_REPORT_MAX)
        return fail(c, "expected 1..256 report bytes", w[3]);
    for (int i = 4; i < n; i++)
        if (!to_byte(w[i], &e->bytes[i - 4]))
            return fail(c, "expected a report byte as two hex digits", w[i]);
    e->size = (uint16_t)(n - 4);
    e->kind = SW_TL_REPORT;
    return SW_OK;
}

static sw_status parse_event(const line_ctx *c, const word *w, int n, sw_timeline_event *e)
{
    memset(e, 0, sizeof *e);
    if (!to_number(w[0], &e->t_s) || e->t_s < 0 || e->t_s > 1e7)
        return fail(c, "expected a time in seconds, 0..1e7", w[0]);
    if (n < 2)
        return fail(c, "expected pad, gpio or key after the time", w[0]);
    if (is(w[1], "pad"))
        return parse_pad(c, w, n, e);
    long v;
    if (is(w[1], "gpio")) {
        if (n != 4 || !copy_text(w[2], e->name, sizeof e->name) || !to_int(w[3], 0, 1, &v))
            return fail(c, "expected TIME gpio NAME 0|1", w[n - 1]);
        e->kind = SW_TL_GPIO;
        e->value = (int32_t)v;
        return SW_OK;
    }
    if (is(w[1], "key")) {
        long code;
        if (n != 4 || !to_int(w[2], 0, 767, &code) || !to_int(w[3], 0, 2, &v))
            return fail(c, "expected TIME key CODE (0..767) VALUE (0, 1 or 2)", w[n - 1]);
        e->kind = SW_TL_KEY;
        e->code = (int32_t)code;
        e->value = (int32_t)v;
        return SW_OK;
    }
    return fail(c, "expected pad, gpio or key", w[1]);
}

size_t sw_timeline_count_events(const char *text, size_t size)
{
    size_t lines = 1;
    for (size_t i = 0; i < size; i++)
        lines += text[i] == '\n';
    return lines;
}

sw_status sw_timeline_parse(const char *text, size_t size, const char *file_name,
                            sw_timeline_event *events, size_t capacity, sw_timeline *out,
                            sw_error *err)
{
    static word w[WORDS_MAX]; /* start-up only, one parse at a time */
    line_ctx c = {file_name, 0, err};
    out->events = events;
    out->count = 0;
    size_t i = 0;
    double last = 0;
    while (i < size) {
        const char *nl = memchr(text + i, '\n', size - i);
        size_t end = nl ? (size_t)(nl - text) : size;
        c.line++;
        if (memchr(text + i, '\0', end - i))
            return fail(&c, "expected text, not a NUL byte", (word){"", 0});
        int n = split(text + i, end - i, w, WORDS_MAX);
        i = end + 1;
        if (n < 0)
            return fail(&c, "expected at most 300 words on a line", (word){"", 0});
        if (n == 0)
            continue;
        if (out->count == capacity)
            return fail(&c, "more events than sw_timeline_count_events said", w[0]);
        sw_timeline_event *e = &events[out->count];
        sw_status st = parse_event(&c, w, n, e);
        if (st != SW_OK)
            return st;
        if (e->t_s < last)
            return fail(&c, "expected times that never decrease", w[0]);
        last = e->t_s;
        out->count++;
    }
    return SW_OK;
}

sw_status sw_hex_parse(const char *text, size_t size, const char *file_name, uint8_t *out,
                       size_t cap, size_t *count, sw_error *err)
{
    line_ctx c = {file_name, 1, err};
    *count = 0;
    for (size_t i = 0; i < size;) {
        char ch = text[i];
        if (ch == '\n') {
            c.line++, i++;
        } else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == ',') {
            i++;
        } else if (ch == '#') {
            while (i < size && text[i] != '\n')
                i++;
        } else {
            size_t s = i;
            while (i < size && !strchr(" \t\r\n,#", text[i]) && text[i] != '\0')
                i++;
            word wd = {text + s, i - s ? i - s : 1};
            if (wd.n == 4 && wd.p[0] == '0' && (wd.p[1] == 'x' || wd.p[1] == 'X'))
                wd = (word){wd.p + 2, 2};  /* 0x05 as in C arrays */
            if (*count == cap)
                return fail(&c, "more bytes than fit", wd);
            if (!to_byte(wd, &out[*count]))
                return fail(&c, "expected a byte as two hex digits", wd);
            ++*count;
            if (i == s)
                i++;
        }
    }
    return SW_OK;
}
