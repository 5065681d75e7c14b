/* SPDX-License-Identifier: MIT */
/* The STEP file's quick pass (sw_step_scan.h). A tokenizer just good
 * enough to find statements: strings ('...' with '' inside), comments,
 * and parentheses; instances "#N = KEYWORD(...);". */
#include "sw_step_scan.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "sw_text_scan.h"

typedef struct step_reader {
    const char *p, *end, *file;
    long line;
    long *ids;           /* a shell's list */
    size_t ids_cap;
    long max_entities, max_faces;
} step_reader;

/* Skips blanks, newlines and comments. */
static void skip_space(step_reader *r)
{
    while (r->p < r->end) {
        if (*r->p == '\n') {
            r->line++, r->p++;
        } else if (isspace((unsigned char)*r->p)) {
            r->p++;
        } else if (*r->p == '/' && r->p + 1 < r->end && r->p[1] == '*') {
            r->p += 2;
            while (r->p < r->end && !(*r->p == '*' && r->p + 1 < r->end && r->p[1] == '/'))
                r->line += *r->p++ == '\n';
            r->p = r->p < r->end ? r->p + 2 : r->end;
        } else {
            return;
        }
    }
}

static void skip_string(step_reader *r)
{
    for (r->p++; r->p < r->end; r->p++) {
        if (*r->p == '\'') {
            if (r->p + 1 < r->end && r->p[1] == '\'') {
                r->p++;
                continue;
            }
            r->p++;
            return;
        }
        r->line += *r->p == '\n';
    }
}

/* To just past the statement's ';' (outside strings and comments). */
static void skip_statement(step_reader *r)
{
    while (r->p < r->end) {
        skip_space(r);
        if (r->p >= r->end)
            return;
        char c = *r->p;
        if (c == '\'')
            skip_string(r);
        else if (c == ';') {
            r->p++;
            return;
        } else
            r->p++;
    }
}

static int take(step_reader *r, char c)
{
    skip_space(r);
    if (r->p < r->end && *r->p == c) {
        r->p++;
        return 1;
    }
    return 0;
}

/* "#digits": the number, or -1. */
static long take_ref(step_reader *r)
{
    skip_space(r);
    if (r->p >= r->end || *r->p != '#')
        return -1;
    const char *q = r->p + 1;
    long v = 0;
    while (q < r->end && isdigit((unsigned char)*q) && v < 1000000000000L)
        v = v * 10 + (*q++ - '0');
    if (q == r->p + 1)
        return -1;
    r->p = q;
    return v;
}

static size_t take_keyword(step_reader *r, char *buf, size_t cap)
{
    skip_space(r);
    size_t n = 0;
    while (r->p < r->end && (isalnum((unsigned char)*r->p) || *r->p == '_')) {
        if (n + 1 < cap)
            buf[n++] = (char)toupper((unsigned char)*r->p);
        r->p++;
    }
    buf[n] = '\0';
    return n;
}

static int cmp_pair(const void *a, const void *b)
{
    const long *x = a, *y = b;
    return x[0] != y[0] ? (x[0] < y[0] ? -1 : 1) : (x[1] < y[1] ? -1 : x[1] > y[1]);
}

/* The shell's ids (id, position) pairs: the earliest second listing. */
static sw_status check_repeats(step_reader *r, long n, long id, const char *kw, long line,
                               sw_error *err)
{
    for (long i = n - 1; i >= 0; i--) {   /* pairs (id, position) in place */
        r->ids[2 * i] = r->ids[i];
        r->ids[2 * i + 1] = i;
    }
    if (n > 1)   /* qsort's array may not be NULL, even for none */
        qsort(r->ids, (size_t)n, 2 * sizeof(long), cmp_pair);
    /* Each run of one id holds its positions in order: its second is where
     * it is listed again; the earliest of those is reported. */
    long best = -1, face = 0, first = 0, times = 0;
    for (long i = 0; i < n;) {
        long j = i + 1;
        while (j < n && r->ids[2 * j] == r->ids[2 * i])
            j++;
        if (j - i > 1 && (best < 0 || r->ids[2 * i + 3] < best))
            best = r->ids[2 * i + 3], face = r->ids[2 * i], first = r->ids[2 * i + 1],
            times = j - i;
        i = j;
    }
    if (best < 0)
        return SW_OK;
    return sw_error_set(err, SW_ERR_FORMAT,
                        "%s:%ld: #%ld %s lists face #%ld %ld times (items %ld and %ld, of %ld); "
                        "a shell lists each face once", r->file, line, id, kw, face, times,
                        first + 1, best + 1, n);
}

/* After "#id = CLOSED_SHELL": ('name', (#f, #f, ...)). A list that is not
 * of that shape is left to OpenCASCADE. */
static sw_status read_shell(step_reader *r, long id, const char *kw, long line,
                            sw_step_scan_result *out, sw_error *err)
{
    if (!take(r, '('))
        return SW_OK;
    skip_space(r);
    if (r->p < r->end && *r->p == '\'')
        skip_string(r);
    else if (!take(r, '$') && !take(r, '*'))
        return SW_OK;
    if (!take(r, ',') || !take(r, '('))
        return SW_OK;
    long n = 0;
    for (long ref; (ref = take_ref(r)) >= 0;) {
        if (n >= r->max_faces)
            return sw_error_set(err, SW_ERR_RANGE, "%s:%ld: #%ld %s lists more than %ld faces "
                                "(the limit)", r->file, line, id, kw, r->max_faces);
        if ((size_t)n * 2 + 2 > r->ids_cap) {
            size_t cap = r->ids_cap ? r->ids_cap * 2 : 1024;
            long *ids = realloc(r->ids, cap * sizeof *ids);
            if (!ids)
                return sw_error_set(err, SW_ERR_NO_MEMORY, "%s:%ld: out of memory for a shell "
                                    "of %ld faces", r->file, line, n);
            r->ids = ids, r->ids_cap = cap;
        }
        r->ids[n++] = ref;
        if (!take(r, ','))
            break;
    }
    out->shells++;
    if (n > out->faces_max)
        out->faces_max = n;
    return check_repeats(r, n, id, kw, line, err);
}

static sw_status read_statements(step_reader *r, sw_step_scan_result *out, sw_error *err)
{
    while (r->p < r->end) {
        skip_space(r);
        long line = r->line, id = take_ref(r);
        if (id >= 0 && take(r, '=')) {
            if (++out->entities > r->max_entities)
                return sw_error_set(err, SW_ERR_RANGE, "%s:%ld: more than %ld entity instances "
                                    "(the limit)", r->file, line, r->max_entities);
            char kw[32];
            take_keyword(r, kw, sizeof kw);
            if (!strcmp(kw, "CLOSED_SHELL") || !strcmp(kw, "OPEN_SHELL")) {
                sw_status st = read_shell(r, id, kw, line, out, err);
                if (st != SW_OK)
                    return st;
            }
        }
        skip_statement(r);
    }
    return SW_OK;
}

sw_status sw_step_scan_within(const char *text, size_t size, const char *file,
                              const sw_step_scan_limits *limits, sw_step_scan_result *out,
                              sw_error *err)
{
    memset(out, 0, sizeof *out);
    step_reader r = {text, text + size, file ? file : "<memory>", 1, NULL, 0,
                     SW_STEP_MAX_ENTITIES, SW_STEP_MAX_SHELL_FACES};
    if (limits && limits->entities > 0)
        r.max_entities = limits->entities;
    if (limits && limits->shell_faces > 0)
        r.max_faces = limits->shell_faces;
    sw_status st = read_statements(&r, out, err);
    free(r.ids);
    return st;
}

sw_status sw_step_scan(const char *text, size_t size, const char *file,
                       sw_step_scan_result *out, sw_error *err)
{
    return sw_step_scan_within(text, size, file, NULL, out, err);
}

sw_status sw_step_scan_file(const char *path, sw_step_scan_result *out, sw_error *err)
{
    char *text;
    size_t size;
    sw_status st = sw_read_whole_file(path, &text, &size, err);
    if (st != SW_OK)
        return st;
    st = sw_step_scan(text, size, path, out, err);
    free(text);
    return st;
}
