/* SPDX-License-Identifier: MIT */
/* Writes small IGES 5.3 files for the tests of the native IGES reader: the
 * S, G, D, P and T sections in fixed 80-column records from a list of
 * entities given as their parameter text. Millimetres, tolerance 0.001. */
#ifndef SW_TEST_IGES_TEXT_H
#define SW_TEST_IGES_TEXT_H

#include <stdio.h>
#include <string.h>

typedef struct iges_text_entity {
    int type, form;
    int matrix_de;        /* D line of a 124, or 0 */
    int subordinate;      /* status digits 3-4 */
    const char *params;   /* "126,1,1,...;" with the type first */
} iges_text_entity;

typedef struct iges_text {
    char *buf;
    size_t len, cap;
} iges_text;

static void iges_text_record(iges_text *t, const char *data, int width, char section, int seq,
                             int de)
{
    char line[96];
    if (de > 0)
        snprintf(line, sizeof line, "%-*.*s %7d%c%7d\n", width, width, data, de, section, seq);
    else
        snprintf(line, sizeof line, "%-72.72s%c%7d\n", data, section, seq);
    size_t n = strlen(line);
    if (t->len + n < t->cap) {
        memcpy(t->buf + t->len, line, n);
        t->len += n;
    }
}

/* Free-format text cut into records of width columns, between parameters. */
static int iges_text_lines(iges_text *t, const char *text, int width, char section, int seq,
                           int de)
{
    char cur[81] = "";
    int n = 0;
    const char *p = text;
    while (*p) {
        size_t tok = strcspn(p, ",;");
        if (p[tok])
            tok++;
        if (strlen(cur) + tok > (size_t)width) {
            iges_text_record(t, cur, width, section, seq + n++, de);
            cur[0] = '\0';
        }
        size_t have = strlen(cur), take = tok < 80 - have ? tok : 80 - have;
        memcpy(cur + have, p, take);
        cur[have + take] = '\0';
        p += tok;
    }
    if (cur[0])
        iges_text_record(t, cur, width, section, seq + n++, de);
    return n;
}

static const char iges_text_global[] =
    "1H,,1H;,4Htest,8Htest.igs,8Hseamwalk,3H1.0,32,38,6,308,15,4Htest,1.,2,2HMM,1,1.,"
    "15H20240101.000000,0.001,100.,4Htest,4Htest,11,0;";

/* The file for n entities; returns its length (0 if cap was too small). */
static size_t iges_text_build(const iges_text_entity *ents, int n, char *buf, size_t cap)
{
    iges_text t = {buf, 0, cap};
    iges_text_record(&t, "seamwalk test file", 72, 'S', 1, 0);
    int g = iges_text_lines(&t, iges_text_global, 72, 'G', 1, 0);
    int pline = 1, plines[64];
    for (int i = 0; i < n && i < 64; i++) {
        plines[i] = pline;
        /* Count the entity's P lines by writing them to a scratch buffer. */
        char scratch[16384];
        iges_text s = {scratch, 0, sizeof scratch};
        pline += iges_text_lines(&s, ents[i].params, 64, 'P', 1, 1);
    }
    for (int i = 0; i < n && i < 64; i++) {
        char d[96];
        int count = (i + 1 < n ? plines[i + 1] : pline) - plines[i];
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8d%8d%8d00%02d0000", ents[i].type, plines[i], 0,
                 0, 0, 0, ents[i].matrix_de, 0, ents[i].subordinate);
        iges_text_record(&t, d, 72, 'D', 2 * i + 1, 0);
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", ents[i].type, 0, 0, count,
                 ents[i].form, "", "", "", 0);
        iges_text_record(&t, d, 72, 'D', 2 * i + 2, 0);
    }
    for (int i = 0; i < n && i < 64; i++)
        iges_text_lines(&t, ents[i].params, 64, 'P', plines[i], 2 * i + 1);
    char tl[80];
    snprintf(tl, sizeof tl, "S%7dG%7dD%7dP%7d", 1, g, 2 * n, pline - 1);
    iges_text_record(&t, tl, 72, 'T', 1, 0);
    return t.len < cap ? t.len : 0;
}

#endif
