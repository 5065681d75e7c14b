/* SPDX-License-Identifier: MIT */
/* The option table (firmware/program/sw_option_table.h) as the one source of
 * seamwalk's ranges and defaults: the command line (sw_options.h), --help and
 * the config file's keys (sw_config.h) all take them from its rows. Every
 * case reads the limits from the table, so a range changed there must show,
 * unchanged, in the parser, in the config and in --help. */
#define _GNU_SOURCE /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_config.h"
#include "sw_options.h"
#include "sw_pack_store.h"
#include "sw_test.h"

static int is_numeric(const sw_option_desc *d)
{
    return d->kind == SW_OPTION_INT || d->kind == SW_OPTION_REAL;
}

static int takes_size(const sw_option_desc *d)
{
    return d->kind == SW_OPTION_SIZE || d->kind == SW_OPTION_HEADLESS;
}

/* ---- the rows ----------------------------------------------------------- */

static size_t size_for(const sw_option_desc *d)
{
    switch (d->kind) {
    case SW_OPTION_TEXT: return sizeof(const char *);
    case SW_OPTION_REAL: return sizeof(double);
    case SW_OPTION_RGB:
    case SW_OPTION_BACK_FACES: return 3 * sizeof(float);
    case SW_OPTION_DISPLAY: return sizeof(sw_display_kind);
    case SW_OPTION_INT: return d->field_size == sizeof(long) ? sizeof(long) : sizeof(int);
    default: return sizeof(int);
    }
}

static void every_row_is_well_formed(void)
{
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        SW_CHECK_MSG(sw_option_find(d->name) == d, "%s: named twice", d->name);
        SW_CHECK_MSG(d->field_size == size_for(d), "%s: a field of %zu bytes for its kind",
                     d->name, d->field_size);
        SW_CHECK_MSG((d->arg != NULL) == (d->kind != SW_OPTION_FLAG), "%s: arg", d->name);
        SW_CHECK_MSG(d->help || (d->flags & SW_OPTION_ALIAS), "%s: no help", d->name);
        SW_CHECK_MSG(!(d->flags & SW_OPTION_TEST_ONLY) == !!strncmp(d->name, "--test-", 7),
                     "%s: test-only rows, and they alone, are named --test-", d->name);
        if (is_numeric(d) && !d->def_text)
            SW_CHECK_MSG(d->def >= d->min && d->def <= d->max, "%s: default %g outside %g..%g",
                         d->name, d->def, d->min, d->max);
        if (d->key)
            SW_CHECK_MSG(sw_option_for_key(d->section, d->key) == d, "%s: [%s] %s twice",
                         d->name, d->section, d->key);
    }
}

static void numbers_are_written_in_full(void)
{
    static const struct { double v; const char *text; } cases[] = {
        {1048576, "1048576"}, {1e9, "1000000000"}, {-1, "-1"}, {0.01, "0.01"}, {16.7, "16.7"},
        {0, "0"}, {2147483647, "2147483647"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[32];
        sw_option_format_number(cases[i].v, text, sizeof text);
        SW_CHECK_MSG(!strcmp(text, cases[i].text), "%g: '%s', expected '%s'", cases[i].v, text,
                     cases[i].text);
    }
}

/* ---- the command line and the config ---------------------------------- */

static sw_status parse_line(const char *name, const char *value, sw_options *o, sw_error *err)
{
    char *argv[] = {"seamwalk", "--pack", "a.swpack", "--orbit", (char *)name, (char *)value};
    return sw_options_parse(6, argv, o, err);
}

static sw_status load_key(const sw_option_desc *d, const char *value, sw_config *cfg,
                          sw_error *err)
{
    char text[256];
    snprintf(text, sizeof text, "[%s]\n%s = %s\n", d->section, d->key, value);
    return sw_config_load_memory(text, strlen(text), "x.ini", cfg, err);
}

/* The value as the option's field holds it (the width, for a size). */
static double field_value(const sw_options *o, const sw_option_desc *d)
{
    const char *at = (const char *)o + d->field;
    double real;
    int whole;
    if (d->kind == SW_OPTION_REAL) {
        memcpy(&real, at, sizeof real);
        return real;
    }
    memcpy(&whole, at, sizeof whole);
    return whole;
}

/* The row's value v as text: a number, or WxH with both sides v. */
static void value_text(const sw_option_desc *d, double v, char *out, size_t size)
{
    if (takes_size(d))
        snprintf(out, size, "%.0fx%.0f", v, v);
    else if (d->kind == SW_OPTION_INT)
        snprintf(out, size, "%.0f", v);
    else
        snprintf(out, size, "%.17g", v);
}

/* One past a limit: the next integer, or a millionth further for a real. */
static double past(const sw_option_desc *d, double limit, double away)
{
    if (d->kind == SW_OPTION_REAL)
        return limit + away * (1e-6 + 1e-6 * (limit < 0 ? -limit : limit));
    return limit + away;
}

static void refused_by_both(const sw_option_desc *d, double v, const char *range)
{
    static sw_options o;
    sw_config cfg;
    sw_error err = {0};
    char text[64];
    value_text(d, v, text, sizeof text);
    SW_CHECK_MSG(parse_line(d->name, text, &o, &err) == SW_ERR_ARG, "%s %s: taken", d->name,
                 text);
    SW_CHECK_MSG(strstr(err.message, range) != NULL, "%s %s: '%s' does not name %s", d->name,
                 text, err.message, range);
    memset(&err, 0, sizeof err);
    SW_CHECK_MSG(load_key(d, text, &cfg, &err) == SW_ERR_FORMAT, "[%s] %s = %s: taken",
                 d->section, d->key, text);
    SW_CHECK_MSG(strstr(err.message, range) != NULL && !strncmp(err.message, "x.ini:2: ", 9),
                 "[%s] %s = %s: '%s' does not name x.ini:2 and %s", d->section, d->key, text,
                 err.message, range);
}

/* The value as the command line sets it, and as the config does through
 * --config: the key lands in the option's own field. */
static void taken_by_both(const sw_option_desc *d, double v)
{
    static sw_options o;
    sw_error err = {0};
    char text[64], ini[256];
    value_text(d, v, text, sizeof text);
    sw_status st = parse_line(d->name, text, &o, &err);
    SW_CHECK_MSG(st == SW_OK && field_value(&o, d) == v, "%s %s: %s", d->name, text, err.message);
    snprintf(ini, sizeof ini, "[%s]\n%s = %s\n", d->section, d->key, text);
    FILE *f = fopen("options_key.ini", "w");
    SW_CHECK(f != NULL);
    if (!f)
        return;
    fputs(ini, f);
    fclose(f);
    char *argv[] = {"seamwalk", "--config", "options_key.ini", "--pack", "a.swpack", "--orbit"};
    st = sw_options_parse(6, argv, &o, &err);
    SW_CHECK_MSG(st == SW_OK && field_value(&o, d) == v, "[%s] %s = %s: %s (the field %g)",
                 d->section, d->key, text, err.message, field_value(&o, d));
}

/* Each option with a config key: its least and most values taken by the
 * command line and by the file alike, one past either refused by both with
 * the same limits named. */
static void an_option_and_its_key_take_the_same_range(void)
{
    int checked = 0;
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if (!d->key || !(is_numeric(d) || takes_size(d)))
            continue;
        char range[80];
        sw_option_format_range(d, range, sizeof range);
        taken_by_both(d, d->min);
        taken_by_both(d, d->max);
        refused_by_both(d, past(d, d->max, 1), range);
        refused_by_both(d, past(d, d->min, -1), range);
        checked++;
    }
    SW_CHECK_MSG(checked >= 9, "only %d rows with a config key and a range", checked);
}

/* A file that gives nothing leaves every option at the table's default: the
 * config's defaults are the table's too. */
static void a_key_left_out_keeps_the_options_default(void)
{
    FILE *f = fopen("options_empty.ini", "w");
    SW_CHECK(f != NULL);
    if (f)
        fclose(f);
    static sw_options o;
    sw_error err = {0};
    char *argv[] = {"seamwalk", "--config", "options_empty.ini", "--pack", "a.swpack", "--orbit"};
    SW_CHECK_MSG(sw_options_parse(6, argv, &o, &err) == SW_OK, "%s", err.message);
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if (d->key && is_numeric(d))
            SW_CHECK_MSG(field_value(&o, d) == d->def, "%s: %g from the empty file, default %g",
                         d->name, field_value(&o, d), d->def);
    }
    SW_CHECK(!strcmp(o.keys_path, SW_STORE_DEFAULT_KEYS) &&
             !strcmp(sw_option_find("--keys")->def_text, SW_STORE_DEFAULT_KEYS));
}

/* ---- --help -------------------------------------------------------------- */

static char *capture(int test_usage)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    if (!f)
        return NULL;
    if (test_usage)
        sw_options_print_test_usage(f);
    else
        sw_options_print_usage(f, "seamwalk");
    fclose(f);
    return text;
}

/* The entry's own text: from "\n  NAME ARG" to the next entry. */
static const char *entry_of(const char *help, const sw_option_desc *d, char *out, size_t size)
{
    char head[96];
    snprintf(head, sizeof head, "\n  %s%s%s ", d->name, d->arg ? " " : "", d->arg ? d->arg : "");
    const char *at = strstr(help, head);
    if (!at)
        return NULL;
    const char *end = strstr(at + strlen(head), "\n  -");
    snprintf(out, size, "%.*s", (int)(end ? end - at : (long)strlen(at)), at);
    return out;
}

static void help_states_each_options_range_default_and_key(void)
{
    char *help = capture(0), *tests = capture(1);
    SW_CHECK(help && tests);
    for (size_t i = 0; help && tests && i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        char entry[4096], range[80], def[96], key[96];
        if (d->flags & SW_OPTION_ALIAS)
            continue;
        int test_only = (d->flags & SW_OPTION_TEST_ONLY) != 0;
        SW_CHECK_MSG(!entry_of(test_only ? help : tests, d, entry, sizeof entry),
                     "%s in the wrong help", d->name);
        SW_CHECK_MSG(entry_of(test_only ? tests : help, d, entry, sizeof entry), "%s: no entry",
                     d->name);
        if (!entry_of(test_only ? tests : help, d, entry, sizeof entry))
            continue;
        sw_option_format_range(d, range, sizeof range);
        sw_option_format_default(d, def, sizeof def);
        snprintf(key, sizeof key, "config [%s] %s)", d->section, d->key);
        SW_CHECK_MSG(!range[0] || strstr(entry, range), "%s: no '%s' in %s", d->name, range,
                     entry);
        SW_CHECK_MSG(!def[0] || strstr(entry, def), "%s: no '%s' in %s", d->name, def, entry);
        SW_CHECK_MSG(!d->key || strstr(entry, key), "%s: no '%s' in %s", d->name, key, entry);
    }
    free(help);
    free(tests);
}

/* Every line of --help fits 79 columns. */
static void help_lines_fit_the_terminal(void)
{
    for (int which = 0; which < 2; which++) {
        char *help = capture(which);
        SW_CHECK(help != NULL);
        for (const char *s = help; s && *s;) {
            size_t n = strcspn(s, "\n");
            SW_CHECK_MSG(n <= 79, "a line of %zu columns: %.*s", n, (int)n, s);
            s += n + (s[n] == '\n');
        }
        free(help);
    }
}

int main(void)
{
    SW_RUN(every_row_is_well_formed);
    SW_RUN(numbers_are_written_in_full);
    SW_RUN(an_option_and_its_key_take_the_same_range);
    SW_RUN(a_key_left_out_keeps_the_options_default);
    SW_RUN(help_states_each_options_range_default_and_key);
    SW_RUN(help_lines_fit_the_terminal);
    return sw_test_finish();
}
