/* SPDX-License-Identifier: MIT */
/* IGES free-format parameters: the G section's and each entity's P lines,
 * cut at the delimiters the G section declares, Hollerith strings (nH...)
 * skipped by their count, read up to the record delimiter (D entries' line
 * counts are not trusted), with typed accessors whose errors name the P line
 * and the entity. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

/* The characters of a run of records, columns 1..width each, as one text. */
typedef struct iges_cursor {
    const iges_line *lines;
    int count, width, line, col;
} iges_cursor;

static int cur_get(const iges_cursor *c)
{
    if (c->line >= c->count)
        return -1;
    const iges_line *l = &c->lines[c->line];
    return c->col < l->len ? (unsigned char)l->text[c->col] : ' ';
}

static void cur_next(iges_cursor *c)
{
    if (++c->col >= c->width)
        c->col = 0, c->line++;
}

static void cur_skip_blanks(iges_cursor *c)
{
    while (cur_get(c) == ' ')
        cur_next(c);
}

static sw_status push_token(iges_reader *r, iges_params *p, int kind, double num, int line,
                            const iges_cursor *str, long str_len)
{
    if (p->count == p->cap) {
        int cap = p->cap ? 2 * p->cap : 64;
        iges_token *t = realloc(p->tok, (size_t)cap * sizeof *t);
        if (!t)
            return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for parameters",
                                r->file);
        p->tok = t, p->cap = cap;
    }
    iges_token t = {kind, num, line, 0, 0, 0};
    if (str)
        t.str_line = str->line, t.str_col = str->col, t.str_len = (int)str_len;
    p->tok[p->count++] = t;
    return SW_OK;
}

/* Where a tokenizer error is: "P line 12 (entity D 57, type 126)" or "G line 2". */
static void where(const iges_reader *r, const iges_params *p, char section, int line, char *buf,
                  size_t size)
{
    if (p && p->entity >= 0)
        snprintf(buf, size, "%c line %d (entity D %d, type %d)", section, line + 1,
                 iges_de(p->entity), p->type);
    else
        snprintf(buf, size, "%c line %d", section, line + 1);
    (void)r;
}

/* Reads one Hollerith string whose count is n, cursor on the 'H'. */
static sw_status skip_hollerith(iges_reader *r, iges_cursor *c, long n, const char *at)
{
    cur_next(c);
    for (long i = 0; i < n; i++) {
        if (cur_get(c) < 0)
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: %s: expected %ld characters of a Hollerith string, found "
                                "the end of the section",
                                r->file, at, n);
        cur_next(c);
    }
    return SW_OK;
}

/* A Hollerith string starts with its count and 'H'; on no, the cursor is
 * left where it was. */
static int try_hollerith(iges_cursor *c, long *count)
{
    iges_cursor save = *c;
    long n = 0;
    int digits = 0, ch;
    while ((ch = cur_get(c)) >= '0' && ch <= '9') {
        if (n < 100000000)
            n = n * 10 + (ch - '0');
        digits++;
        cur_next(c);
    }
    if (digits && cur_get(c) == 'H') {
        *count = n;
        return 1;
    }
    *c = save;
    return 0;
}

/* One token's text up to the next delimiter (blanks dropped at its ends). */
static int token_text(iges_cursor *c, char pd, char rd, char *buf, int size, int *len)
{
    int n = 0, ch, overflow = 0, inner_blank = 0, seen_blank = 0;
    while ((ch = cur_get(c)) >= 0 && ch != pd && ch != rd) {
        if (ch == ' ') {
            seen_blank = n > 0;
        } else {
            inner_blank |= seen_blank;
            if (n < size - 1)
                buf[n++] = (char)ch;
            else
                overflow = 1;
        }
        cur_next(c);
    }
    buf[n] = '\0';
    *len = n;
    return !overflow && !inner_blank;
}

static int parse_number(const char *text, double *out)
{
    char tmp[64];
    size_t n = strlen(text);
    if (n == 0 || n >= sizeof tmp)
        return 0;
    for (size_t i = 0; i <= n; i++)
        tmp[i] = (text[i] == 'D' || text[i] == 'd') ? 'E' : text[i];
    char *end;
    errno = 0;
    double v = strtod(tmp, &end);
    if (*end != '\0' || !isfinite(v) || errno == ERANGE)
        return 0;
    *out = v;
    return 1;
}

/* Reads tokens up to the record delimiter. at_end_ok: the G section may
 * simply stop (gpucast_teapot.igs writes only "1H,"). */
static sw_status tokenize(iges_reader *r, iges_cursor *c, char section, iges_params *p,
                          int at_end_ok)
{
    char at[96], text[64];
    for (;;) {
        cur_skip_blanks(c);
        int line = c->line, ch = cur_get(c);
        where(r, p, section, line < c->count ? line : c->count - 1, at, sizeof at);
        if (ch < 0) {
            if (at_end_ok)
                return SW_OK;
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: %s: expected the record delimiter '%c', found the end of "
                                "the %c section",
                                r->file, at, r->rdelim, section);
        }
        int kind = IGES_TOK_EMPTY;
        double num = 0;
        long count = 0;
        iges_cursor str = *c;
        int is_string = try_hollerith(c, &count);
        if (is_string) {
            str = *c;
            cur_next(&str);
            sw_status st = skip_hollerith(r, c, count, at);
            if (st != SW_OK)
                return st;
            cur_skip_blanks(c);
            kind = IGES_TOK_STRING;
            ch = cur_get(c);
            if (ch >= 0 && ch != r->pdelim && ch != r->rdelim)
                return sw_error_set(r->err, SW_ERR_FORMAT,
                                    "%s: %s: expected a delimiter after a %ld-character "
                                    "Hollerith string, found '%c'",
                                    r->file, at, count, ch);
        } else {
            int len;
            int ok = token_text(c, r->pdelim, r->rdelim, text, sizeof text, &len);
            if (len > 0 && (!ok || !parse_number(text, &num)))
                return sw_error_set(r->err, SW_ERR_FORMAT,
                                    "%s: %s: expected a number or a Hollerith string, found "
                                    "'%.40s'",
                                    r->file, at, text);
            kind = len > 0 ? IGES_TOK_NUM : IGES_TOK_EMPTY;
        }
        sw_status st = push_token(r, p, kind, num, line, is_string ? &str : NULL, count);
        if (st != SW_OK)
            return st;
        ch = cur_get(c);
        if (ch >= 0)
            cur_next(c);
        if (ch == r->rdelim)
            return SW_OK;
    }
}

sw_status iges_fail(iges_reader *r, const iges_params *p, int i, sw_status st, const char *fmt,
                    ...)
{
    char msg[SW_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    int line = r->ents[p->entity].pointer - 1;
    if (p->count > 0)
        line = p->tok[i >= 0 && i < p->count ? i : p->count - 1].line;
    return sw_error_set(r->err, st, "%s: P line %d (entity D %d, type %d): %s", r->file,
                        line + 1, iges_de(p->entity), p->type, msg);
}

sw_status iges_fail_entity(iges_reader *r, int entity, sw_status st, const char *fmt, ...)
{
    char msg[SW_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return sw_error_set(r->err, st, "%s: D line %d (type %d): %s", r->file, iges_de(entity),
                        r->ents[entity].type, msg);
}

sw_status iges_params_read(iges_reader *r, int entity, iges_params *p)
{
    memset(p, 0, sizeof *p);
    p->entity = entity;
    p->type = r->ents[entity].type;
    int ptr = r->ents[entity].pointer;
    if (ptr < 1 || ptr > r->count[IGES_P])
        return iges_fail_entity(r, entity, SW_ERR_FORMAT,
                                "expected a parameter pointer in columns 9-16 between 1 and "
                                "%d, found %d",
                                r->count[IGES_P], ptr);
    iges_cursor c = {r->lines[IGES_P], r->count[IGES_P], 64, ptr - 1, 0};
    sw_status st = tokenize(r, &c, 'P', p, 0);
    if (st != SW_OK)
        return st;
    if (p->count == 0 || p->tok[0].kind != IGES_TOK_NUM || p->tok[0].num != p->type)
        return iges_fail(r, p, 0, SW_ERR_FORMAT,
                         "expected the entity type %d as the first parameter", p->type);
    return SW_OK;
}

void iges_params_free(iges_params *p)
{
    free(p->tok);
    p->tok = NULL;
    p->count = p->cap = 0;
}

static const char *kind_name(int kind)
{
    return kind == IGES_TOK_STRING ? "a string" : kind == IGES_TOK_EMPTY ? "nothing" : "a number";
}

sw_status iges_param_need(iges_reader *r, const iges_params *p, int first, int n,
                          const char *what)
{
    if (n < 0 || first + (long)n > p->count)
        return iges_fail(r, p, p->count - 1, SW_ERR_FORMAT, "expected %d %s, found %d", n, what,
                         p->count > first ? p->count - first : 0);
    return SW_OK;
}

sw_status iges_param_real(iges_reader *r, const iges_params *p, int i, const char *what,
                          double *out)
{
    if (i >= p->count)
        return iges_fail(r, p, i, SW_ERR_FORMAT,
                         "expected %s (parameter %d), found the end of the record", what, i);
    if (p->tok[i].kind != IGES_TOK_NUM)
        return iges_fail(r, p, i, SW_ERR_FORMAT, "expected %s (parameter %d), found %s", what,
                         i, kind_name(p->tok[i].kind));
    *out = p->tok[i].num;
    return SW_OK;
}

sw_status iges_param_real_or(iges_reader *r, const iges_params *p, int i, const char *what,
                             double fallback, double *out)
{
    if (i >= p->count || p->tok[i].kind == IGES_TOK_EMPTY) {
        *out = fallback;
        return SW_OK;
    }
    return iges_param_real(r, p, i, what, out);
}

sw_status iges_param_int(iges_reader *r, const iges_params *p, int i, const char *what, int lo,
                         int hi, int *out)
{
    double v = 0;
    sw_status st = iges_param_real(r, p, i, what, &v);
    if (st != SW_OK)
        return st;
    if (v != floor(v) || v < lo || v > hi)
        return iges_fail(r, p, i, SW_ERR_FORMAT,
                         "expected %s (parameter %d) an integer in %d..%d, found %g", what, i,
                         lo, hi, v);
    *out = (int)v;
    return SW_OK;
}

sw_status iges_param_int_or(iges_reader *r, const iges_params *p, int i, const char *what,
                            int lo, int hi, int fallback, int *out)
{
    if (i >= p->count || p->tok[i].kind == IGES_TOK_EMPTY) {
        *out = fallback;
        return SW_OK;
    }
    return iges_param_int(r, p, i, what, lo, hi, out);
}

sw_status iges_param_entity(iges_reader *r, const iges_params *p, int i, const char *what,
                            int allow_null, int *out)
{
    int v = 0;
    sw_status st = iges_param_int(r, p, i, what, allow_null ? 0 : 1, 2 * r->ent_count - 1, &v);
    if (st != SW_OK)
        return st;
    if (v == 0) {
        *out = -1;
        return SW_OK;
    }
    if (v % 2 == 0)
        return iges_fail(r, p, i, SW_ERR_FORMAT,
                         "expected %s (parameter %d) to point at a D entry (an odd line), "
                         "found %d",
                         what, i, v);
    *out = (v - 1) / 2;
    return SW_OK;
}

/* ---- the global section ----------------------------------------------- */

/* G parameters 1 and 2 declare the delimiters: "1Hx" or nothing (',' and
 * ';'). Ends with the cursor after the delimiter that follows. */
static sw_status read_delimiter(iges_reader *r, iges_cursor *c, char *delim, int number,
                                int *ended)
{
    cur_skip_blanks(c);
    int ch = cur_get(c);
    if (ch < 0) {
        *ended = 1;
        return SW_OK;
    }
    if (ch == '1') {
        cur_next(c);
        if (cur_get(c) != 'H')
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: G line %d: expected G parameter %d as 1Hx or nothing",
                                r->file, c->line + 1, number);
        cur_next(c);
        ch = cur_get(c);
        if (ch < 0 || ch == ' ')
            return sw_error_set(r->err, SW_ERR_FORMAT,
                                "%s: G line %d: expected a delimiter character after 1H",
                                r->file, c->line + 1);
        *delim = (char)ch;
        cur_next(c);
        cur_skip_blanks(c);
        ch = cur_get(c);
    }
    if (ch < 0 || ch == r->rdelim) {
        *ended = 1;
        return SW_OK;
    }
    if (ch != r->pdelim)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: G line %d: expected the delimiter '%c' after G parameter %d, "
                            "found '%c'",
                            r->file, c->line + 1, r->pdelim, number, ch);
    cur_next(c);
    return SW_OK;
}

static double g_num(const iges_params *g, int number, double fallback)
{
    int i = number - 1;
    return i < g->count && g->tok[i].kind == IGES_TOK_NUM ? g->tok[i].num : fallback;
}

static double unit_by_name(const iges_reader *r, const iges_params *g)
{
    static const struct { const char *name; double mm; } names[] = {
        {"IN", 25.4}, {"INCH", 25.4}, {"MM", 1.0}, {"FT", 304.8}, {"MI", 1609344.0},
        {"M", 1000.0}, {"KM", 1e6}, {"MIL", 0.0254}, {"UM", 0.001}, {"CM", 10.0},
        {"UIN", 2.54e-5}};
    if (g->count < 15 || g->tok[14].kind != IGES_TOK_STRING)
        return 0;
    const iges_token *t = &g->tok[14];
    char name[8] = {0};
    iges_cursor c = {r->lines[IGES_G], r->count[IGES_G], 72, t->str_line, t->str_col};
    for (int k = 0; k < t->str_len && k < 7; k++, cur_next(&c))
        name[k] = (char)cur_get(&c);
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (t->str_len < 8 && strcmp(name, names[k].name) == 0)
            return names[k].mm;
    return 0;
}

static sw_status read_units(iges_reader *r, const iges_params *g)
{
    static const double flag_mm[12] = {0, 25.4, 1.0, 0, 304.8, 1609344.0, 1000.0, 1e6,
                                       0.0254, 0.001, 10.0, 2.54e-5};
    double scale = g_num(g, 13, 1.0), flag = g_num(g, 14, 1.0);
    int line = r->count[IGES_G];
    if (!(scale > 0))
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: G line %d: expected a positive model space scale (G 13), "
                            "found %g",
                            r->file, line, scale);
    if (flag != floor(flag) || flag < 1 || flag > 11)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: G line %d: expected a units flag (G 14) in 1..11, found %g",
                            r->file, line, flag);
    double mm = flag == 3 ? unit_by_name(r, g) : flag_mm[(int)flag];
    if (mm == 0)
        return sw_error_set(r->err, SW_ERR_FORMAT,
                            "%s: G line %d: units flag 3 needs a units name (G 15) such as "
                            "2HMM or 4HINCH",
                            r->file, line);
    /* Model space scale is model units per real unit (IGES 5.3, 2.2.4.3). */
    r->units_to_mm = mm / scale;
    double res = g_num(g, 19, 0.0);
    r->resolution = res > 0 ? res : 0;
    return SW_OK;
}

sw_status iges_read_global(iges_reader *r)
{
    r->pdelim = ',', r->rdelim = ';';
    r->units_to_mm = 25.4;   /* the units flag's default is 1, inches */
    iges_params g = {NULL, 0, 0, -1, 0};
    iges_cursor c = {r->lines[IGES_G], r->count[IGES_G], 72, 0, 0};
    int ended = 0;
    sw_status st = read_delimiter(r, &c, &r->pdelim, 1, &ended);
    if (st == SW_OK && !ended)
        st = read_delimiter(r, &c, &r->rdelim, 2, &ended);
    if (st == SW_OK && r->pdelim == r->rdelim)
        st = sw_error_set(r->err, SW_ERR_FORMAT,
                          "%s: G line 1: expected different parameter and record delimiters, "
                          "found '%c' for both",
                          r->file, r->pdelim);
    if (st == SW_OK)
        st = push_token(r, &g, IGES_TOK_EMPTY, 0, 0, NULL, 0);
    if (st == SW_OK)
        st = push_token(r, &g, IGES_TOK_EMPTY, 0, 0, NULL, 0);
    if (st == SW_OK && !ended)
        st = tokenize(r, &c, 'G', &g, 1);
    if (st == SW_OK)
        st = read_units(r, &g);
    iges_params_free(&g);
    return st;
}

sw_status iges_param_reals(iges_reader *r, const iges_params *p, int first, int n,
                           const char *what, double *out)
{
    sw_status st = iges_param_need(r, p, first, n, what);
    for (int i = 0; st == SW_OK && i < n; i++)
        st = iges_param_real(r, p, first + i, what, &out[i]);
    return st;
}
