/* SPDX-License-Identifier: MIT */
/* IGES records and sections: the buffer cut into 80-column records, grouped
 * by the section letter in column 73, the global section's delimiters, units
 * and tolerance, and the directory's two-line entries. Sequence numbers in
 * columns 74-80 are not trusted (gpucast_teapot.igs numbers every P line 4):
 * positions are the physical record index within the section. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

static const char section_letters[IGES_SECTIONS] = {'S', 'G', 'D', 'P', 'T'};

static int section_of(char c)
{
    for (int i = 0; i < IGES_SECTIONS; i++)
        if (section_letters[i] == c)
            return i;
    return -1;
}

/* Records are lines of at most 80 columns; files without line ends are a
 * sequence of 80-byte records. Trailing blanks beyond column 80 are ignored. */
static sw_status next_record(iges_reader *r, const char **p, const char *end, long number,
                             iges_line *out)
{
    const char *s = *p, *e = s;
    while (e < end && *e != '\n' && *e != '\r')
        e++;
    const char *next = e;
    if (next < end && *next == '\r')
        next++;
    if (next < end && *next == '\n' && (next == e || next[-1] == '\r'))
        next++;
    long len = e - s;
    if (len > 80) {
        const char *t = s + 80;
        while (t < e && *t == ' ')
            t++;
        if (t < e && e - s > 160 && (e - s) % 80 == 0) {
            next = s + 80;   /* no line ends: fixed 80-byte records */
        } else if (t < e) {
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: line %ld: expected at most 80 columns, found %ld", r->file,
                                number, len);
        }
        len = 80;
    }
    out->text = s;
    out->len = (int)len;
    *p = next;
    return SW_OK;
}

static sw_status check_section(iges_reader *r, const iges_line *l, long number, int *current)
{
    char c = l->len >= 73 ? l->text[72] : ' ';
    int sec = section_of(c);
    if (sec < 0) {
        if (c == 'C' || c == 'B' || (l->len >= 73 && c == 'F'))
            return sw_error_set(r->err, SW_ERR_UNSUPPORTED,
                                "%s: line %ld: compressed or binary IGES ('%c' in column 73) "
                                "is not supported",
                                r->file, number, c);
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: line %ld: expected a section letter (S, G, D, P, T) in column "
                            "73, found %s'%c'",
                            r->file, number, l->len >= 73 ? "" : "a short line, ",
                            l->len >= 73 ? c : ' ');
    }
    if (sec < *current)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: line %ld: expected section %c or later, found %c", r->file,
                            number, section_letters[*current], c);
    *current = sec;
    return SW_OK;
}

sw_status iges_split_sections(iges_reader *r, const char *text, size_t size)
{
    const char *p = text, *end = text + size;
    size_t cap = size / 73 + 2;
    r->all = malloc(cap * sizeof *r->all);
    if (!r->all)
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for %zu records",
                            r->file, cap);
    int n = 0, current = IGES_S;
    for (long number = 1; p < end; number++) {
        iges_line l;
        sw_status st = next_record(r, &p, end, number, &l);
        if (st != SW_OK)
            return st;
        int blank = 1;
        for (int i = 0; i < l.len && blank; i++)
            blank = isspace((unsigned char)l.text[i]);
        if (blank && current == IGES_T)
            continue;   /* trailing empty lines */
        if ((st = check_section(r, &l, number, &current)) != SW_OK)
            return st;
        if ((size_t)n == cap)
            return sw_error_set(r->err, SW_ERR_FORMAT, "%s: line %ld: records too short",
                                r->file, number);
        if (current == IGES_T && r->count[IGES_T] > 0)
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: line %ld: expected the end of the file after the T line",
                                r->file, number);
        if (r->count[current]++ == 0)
            r->first_line[current] = n + 1;
        r->all[n++] = l;
    }
    for (int s = 0; s < IGES_SECTIONS; s++)
        r->lines[s] = r->all + (r->count[s] ? r->first_line[s] - 1 : 0);
    if (r->count[IGES_T] == 0)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: line %d: expected the T (terminate) section, found the end of "
                            "the file",
                            r->file, n);
    if (r->count[IGES_D] % 2)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: D line %d: expected two lines per directory entry, found an "
                            "odd count",
                            r->file, r->count[IGES_D]);
    return SW_OK;
}

void iges_reader_free(iges_reader *r)
{
    free(r->all);
    free(r->ents);
    r->all = NULL;
    r->ents = NULL;
}

/* ---- directory ---------------------------------------------------------- */

static const char *const field_names[19] = {
    "", "entity type", "parameter pointer", "structure", "line font", "level", "view",
    "transformation matrix", "label display", "status", "entity type", "line weight",
    "color", "parameter line count", "form number", "reserved", "reserved", "label",
    "subscript"};

/* Field k (1..18) of an entry: 8 right-justified columns, blank meaning 0. */
static sw_status d_field(iges_reader *r, int entity, int k, int *out)
{
    int line = 2 * entity + (k > 9);
    const iges_line *l = &r->lines[IGES_D][line];
    int col = ((k - 1) % 9) * 8;
    char text[9];
    for (int i = 0; i < 8; i++)
        text[i] = col + i < l->len ? l->text[col + i] : ' ';
    text[8] = '\0';
    const char *s = text;
    while (*s == ' ')
        s++;
    long v = 0;
    int sign = 1, digits = 0;
    if (*s == '-' || *s == '+')
        sign = *s++ == '-' ? -1 : 1;
    while (*s >= '0' && *s <= '9')
        v = v * 10 + (*s++ - '0'), digits++;
    while (*s == ' ')
        s++;
    if (*s != '\0' || (!digits && sign < 0)) {
        const char *shown = text;
        while (*shown == ' ')
            shown++;
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: D line %d: expected %s in columns %d-%d, found '%s'", r->file,
                            line + 1, field_names[k], col + 1, col + 8, shown);
    }
    *out = (int)(sign * v);
    return SW_OK;
}

/* Status "BBSSUUHH": only the subordinate switch matters here; blanks are 0. */
static int d_subordinate(const iges_line *l)
{
    int v = 0;
    for (int c = 66; c <= 67; c++) {
        char ch = c < l->len ? l->text[c] : ' ';
        v = v * 10 + (ch >= '0' && ch <= '9' ? ch - '0' : 0);
    }
    return v;
}

sw_status iges_read_directory(iges_reader *r)
{
    int n = r->count[IGES_D] / 2;
    r->ent_count = n;
    r->ents = calloc(n ? (size_t)n : 1, sizeof *r->ents);
    if (!r->ents)
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for %d entities",
                            r->file, n);
    for (int e = 0; e < n; e++) {
        iges_entity *ent = &r->ents[e];
        int type2 = 0;
        sw_status st = d_field(r, e, 1, &ent->type);
        if (st == SW_OK)
            st = d_field(r, e, 2, &ent->pointer);
        if (st == SW_OK)
            st = d_field(r, e, 7, &ent->matrix_de);
        if (st == SW_OK)
            st = d_field(r, e, 10, &type2);
        if (st == SW_OK)
            st = d_field(r, e, 14, &ent->form);
        if (st != SW_OK)
            return st;
        if (type2 != ent->type)
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: D line %d: expected entity type %d (as on D line %d), "
                                "found %d",
                                r->file, 2 * e + 2, ent->type, 2 * e + 1, type2);
        ent->subordinate = d_subordinate(&r->lines[IGES_D][2 * e]);
    }
    return SW_OK;
}
