/* SPDX-License-Identifier: MIT */
/* A line-aware scanner over a text buffer that is NOT NUL-terminated, shared by
 * the text importers (Newell listings, .bpt). It never reads past the end,
 * tracks line and column for messages, and parses numbers strictly (the whole
 * token must be the number, and it must be finite). Internal to assets/;
 * header-only so the importers share it without another library source. */
#ifndef SW_TEXT_SCAN_H
#define SW_TEXT_SCAN_H

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sw_error.h"

typedef struct sw_text_scan {
    const char *p, *end;
    const char *line_start;
    const char *file;   /* for messages */
    long line;          /* 1-based line of p */
} sw_text_scan;

/* Longest number token we copy out for strtod; real data uses ~12 chars. */
enum { SW_SCAN_TOKEN_MAX = 64 };

static inline void sw_scan_init(sw_text_scan *s, const char *text, size_t size, const char *file)
{
    s->p = text;
    s->end = text + size;
    s->line_start = text;
    s->file = file ? file : "<memory>";
    s->line = 1;
}

static inline long sw_scan_column(const sw_text_scan *s)
{
    return (long)(s->p - s->line_start) + 1;
}

/* Skips spaces, tabs and carriage returns, never the newline. */
static inline void sw_scan_skip_blanks(sw_text_scan *s)
{
    while (s->p < s->end && (*s->p == ' ' || *s->p == '\t' || *s->p == '\r'))
        s->p++;
}

static inline int sw_scan_at_eof(const sw_text_scan *s)
{
    return s->p >= s->end;
}

/* True when only blanks remain on the current line. */
static inline int sw_scan_at_eol(sw_text_scan *s)
{
    sw_scan_skip_blanks(s);
    return s->p >= s->end || *s->p == '\n';
}

/* Moves to the start of the next line (or to the end of the text). */
static inline void sw_scan_skip_line(sw_text_scan *s)
{
    const char *nl = memchr(s->p, '\n', (size_t)(s->end - s->p));
    s->p = nl ? nl + 1 : s->end;
    if (nl) {
        s->line++;
        s->line_start = s->p;
    }
}

/* Skips lines holding only blanks; stops at the first line with content. */
static inline void sw_scan_skip_empty_lines(sw_text_scan *s)
{
    while (!sw_scan_at_eof(s) && sw_scan_at_eol(s))
        sw_scan_skip_line(s);
}

/* The next token on this line (a run of non-blank bytes); len 0 at the end of
 * the line. Does not consume it. */
static inline const char *sw_scan_peek(sw_text_scan *s, size_t *len)
{
    sw_scan_skip_blanks(s);
    const char *q = s->p;
    while (q < s->end && *q != ' ' && *q != '\t' && *q != '\r' && *q != '\n')
        q++;
    *len = (size_t)(q - s->p);
    return s->p;
}

/* bytes[0..len) for a message, into out (NUL-terminated, cut to cap):
 * printable ASCII as it is, every other byte as \xNN, so a binary file
 * never sends control bytes (escape sequences, a bell) to the terminal. */
static inline void sw_text_escape(const char *bytes, size_t len, char *out, size_t cap)
{
    size_t n = 0;
    for (size_t i = 0; i < len && n + 5 <= cap; i++) {
        unsigned char c = (unsigned char)bytes[i];
        if (c >= 0x20 && c < 0x7f && c != '\\')
            out[n++] = (char)c;
        else
            n += (size_t)snprintf(out + n, cap - n, "\\x%02x", c);
    }
    if (cap > 0)
        out[n < cap ? n : cap - 1] = '\0';
}

/* Describes the token at p for a message: "'abc'" or "the end of the line";
 * bytes other than printable ASCII shown as \xNN. */
static inline const char *sw_scan_describe(sw_text_scan *s, char *buf, size_t buf_size)
{
    size_t len;
    const char *tok = sw_scan_peek(s, &len);
    if (len == 0)
        return sw_scan_at_eof(s) ? "the end of the file" : "the end of the line";
    char shown[24 * 4 + 1];
    sw_text_escape(tok, len > 24 ? 24 : len, shown, sizeof shown);
    snprintf(buf, buf_size, "'%s%s'", shown, len > 24 ? "..." : "");
    return buf;
}

/* Copies the next token into buf as a C string; 0 when there is none or it is
 * longer than SW_SCAN_TOKEN_MAX - 1 bytes. */
static inline size_t sw_scan_copy_token(sw_text_scan *s, char buf[SW_SCAN_TOKEN_MAX])
{
    size_t len;
    const char *tok = sw_scan_peek(s, &len);
    if (len == 0 || len >= SW_SCAN_TOKEN_MAX)
        return 0;
    memcpy(buf, tok, len);
    buf[len] = '\0';
    return len;
}

/* Fails with "file:line:col: expected WHAT, found TOKEN". */
static inline sw_status sw_scan_fail(sw_text_scan *s, sw_error *err, sw_status status,
                                     const char *what)
{
    char buf[112];
    const char *found = sw_scan_describe(s, buf, sizeof buf);
    return sw_error_set(err, status, "%s:%ld:%ld: expected %s, found %s", s->file, s->line,
                        sw_scan_column(s), what, found);
}

/* Parses one finite double token. */
static inline sw_status sw_scan_double(sw_text_scan *s, double *out, const char *what,
                                       sw_error *err)
{
    char buf[SW_SCAN_TOKEN_MAX];
    size_t len = sw_scan_copy_token(s, buf);
    if (len == 0)
        return sw_scan_fail(s, err, SW_ERR_FORMAT, what);
    char *stop;
    errno = 0;
    double v = strtod(buf, &stop);
    /* ERANGE on underflow still yields a usable (tiny) value; on overflow the
     * result is infinite and the finiteness test rejects it. */
    if (stop != buf + len || !isfinite(v))
        return sw_scan_fail(s, err, SW_ERR_FORMAT, what);
    s->p += len;
    *out = v;
    return SW_OK;
}

/* Parses one decimal integer token in lo..hi. */
static inline sw_status sw_scan_long(sw_text_scan *s, long *out, long lo, long hi,
                                     const char *what, sw_error *err)
{
    char buf[SW_SCAN_TOKEN_MAX];
    size_t len = sw_scan_copy_token(s, buf);
    if (len == 0)
        return sw_scan_fail(s, err, SW_ERR_FORMAT, what);
    char *stop;
    errno = 0;
    long v = strtol(buf, &stop, 10);
    if (stop != buf + len)
        return sw_scan_fail(s, err, SW_ERR_FORMAT, what);
    if (errno == ERANGE || v < lo || v > hi)
        return sw_error_set(err, SW_ERR_RANGE, "%s:%ld:%ld: %s %s out of range %ld..%ld",
                            s->file, s->line, sw_scan_column(s), what, buf, lo, hi);
    s->p += len;
    *out = v;
    return SW_OK;
}

/* Requires that only blanks remain on the line, then moves to the next. */
static inline sw_status sw_scan_end_line(sw_text_scan *s, const char *after, sw_error *err)
{
    if (!sw_scan_at_eol(s)) {
        char buf[112];
        const char *found = sw_scan_describe(s, buf, sizeof buf);
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s:%ld:%ld: expected the end of the line after %s, found %s",
                            s->file, s->line, sw_scan_column(s), after, found);
    }
    sw_scan_skip_line(s);
    return SW_OK;
}

/* Reads a whole file into a malloc'd buffer (not NUL-terminated; the caller
 * frees it). Errors name the path. */
static inline sw_status sw_read_whole_file(const char *path, char **out, size_t *out_size,
                                           sw_error *err)
{
    *out = NULL;
    *out_size = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    /* Devices and FIFOs (a scene naming /dev/zero) would never end. */
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(f);
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path,
                            S_ISDIR(st.st_mode) ? "a directory, not a file" : "not a regular file");
    }
    size_t cap = 1 << 16, size = 0;
    char *buf = malloc(cap);
    while (buf) {
        size += fread(buf + size, 1, cap - size, f);
        if (size < cap)
            break;
        char *bigger = cap <= SIZE_MAX / 2 ? realloc(buf, cap * 2) : NULL;
        if (!bigger) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = bigger;
        cap *= 2;
    }
    int failed = ferror(f);
    fclose(f);
    if (!buf)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: out of memory reading the file", path);
    if (failed) {
        free(buf);
        return sw_error_set(err, SW_ERR_IO, "%s: read error", path);
    }
    *out = buf;
    *out_size = size;
    return SW_OK;
}

#endif
