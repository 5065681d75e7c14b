/* SPDX-License-Identifier: MIT */
/* --help and --help-test (sw_options.h), printed from the option table
 * (sw_option_table.c): each option's name, what it takes, its words, and a
 * line with its range, its default and the config key that sets the same. */
#include "sw_options.h"

#include <string.h>

/* Columns: a help text starts at the 23rd, a line ends by the 79th. */
enum { HELP_COLUMN = 22, HELP_WIDTH = 79, SYNOPSIS_COLUMN = 10 };

static void pad_to(FILE *out, int *col, int to)
{
    for (; *col < to; (*col)++)
        fputc(' ', out);
}

/* One '\n'-line of words from column *col on (at least indent), wrapped at
 * HELP_WIDTH. A line that starts with spaces is a list item ("  kms  full
 * screen ..."): its wrapped part lines up after the item's first word. */
static void print_line(FILE *out, const char *s, size_t len, int indent, int *col)
{
    size_t lead = strspn(s, " ");
    size_t i = lead < len ? lead : len;
    int hang = indent + (int)i, words = 0;
    pad_to(out, col, hang);
    while (i < len) {
        size_t gap = 0;
        while (i + gap < len && s[i + gap] == ' ')
            gap++;
        size_t end = i + gap;
        while (end < len && s[end] != ' ')
            end++;
        int n = (int)(end - i - gap);
        if (n == 0)
            break;
        if (words > 0 && *col + (int)gap + n > HELP_WIDTH) {
            fputc('\n', out);
            *col = 0;
            pad_to(out, col, hang);
        } else if (words > 0) {
            *col += fprintf(out, "%*s", (int)gap, "");
        }
        if (words++ == 1 && lead > 0)
            hang = *col;
        *col += fprintf(out, "%.*s", n, s + i + gap);
        i = end;
    }
}

static void print_text(FILE *out, const char *text, int indent, int *col)
{
    for (const char *s = text; *s;) {
        size_t len = strcspn(s, "\n");
        print_line(out, s, len, indent, col);
        s += len;
        if (*s == '\n' && *++s) {
            fputc('\n', out);
            *col = 0;
        }
    }
}

/* "(1..1048576, default 256; config [render] memory_mb)", or "" when the
 * row has none of the three. */
static void format_value_line(const sw_option_desc *d, char *out, size_t size)
{
    char range[80], def[80];
    sw_option_format_range(d, range, sizeof range);
    sw_option_format_default(d, def, sizeof def);
    int per_part = d->kind != SW_OPTION_INT && d->kind != SW_OPTION_REAL;
    out[0] = '\0';
    if (!range[0] && !def[0] && !d->key)
        return;
    snprintf(out, size, "(%s%s%s%s%s%s%s%s%s%s)", range, range[0] && per_part ? " each" : "",
             range[0] && def[0] ? ", " : "", def[0] ? "default " : "", def,
             (range[0] || def[0]) && d->key ? "; " : "", d->key ? "config [" : "",
             d->key ? d->section : "", d->key ? "] " : "", d->key ? d->key : "");
}

static void print_entry(FILE *out, const sw_option_desc *d)
{
    int col = fprintf(out, "  %s%s%s", d->name, d->arg ? " " : "", d->arg ? d->arg : "");
    pad_to(out, &col, col + 2 > HELP_COLUMN ? col + 2 : HELP_COLUMN);
    print_text(out, d->help ? d->help : "", HELP_COLUMN, &col);
    char value[256];
    format_value_line(d, value, sizeof value);
    if (value[0]) {
        fputc('\n', out);
        col = 0;
        print_line(out, value, strlen(value), HELP_COLUMN, &col);
    }
    fputc('\n', out);
}

/* The synopsis' words: the rows with exactly the flags want among mask, each
 * as open NAME ARG close, between them between ("--help | --version",
 * "[--frames N] [--duration S]"), wrapped under SYNOPSIS_COLUMN. */
static void print_names(FILE *out, unsigned want, unsigned mask, const char *open,
                        const char *close, const char *between, int *col)
{
    int first = 1;
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if ((d->flags & mask) != want)
            continue;
        char word[96];
        int n = snprintf(word, sizeof word, "%s%s%s%s%s", open, d->name, d->arg ? " " : "",
                         d->arg ? d->arg : "", close);
        size_t mark = strlen(between);   /* between less its trailing spaces, at a line's end */
        while (mark > 0 && between[mark - 1] == ' ')
            mark--;
        if (!first && *col + (int)strlen(between) + n > HELP_WIDTH) {
            fprintf(out, "%.*s\n", (int)mark, between);
            *col = 0;
            pad_to(out, col, SYNOPSIS_COLUMN);
        } else if (!first) {
            *col += fprintf(out, "%s", between);
        }
        *col += fprintf(out, "%s", word);
        first = 0;
    }
}

static void new_synopsis_line(FILE *out, int *col, const char *text)
{
    fprintf(out, "\n");
    *col = 0;
    pad_to(out, col, SYNOPSIS_COLUMN);
    *col += fprintf(out, "%s", text);
}

void sw_options_print_usage(FILE *out, const char *argv0)
{
    enum { HIDDEN = SW_OPTION_TEST_ONLY | SW_OPTION_ALIAS,
           GROUPS = SW_OPTION_STOPS | SW_OPTION_PACK | SW_OPTION_CAMERA };
    int col = fprintf(out, "usage: %s ", argv0);
    print_names(out, SW_OPTION_STOPS, HIDDEN | GROUPS, "", "", " | ", &col);
    col = fprintf(out, "\n       %s (", argv0);
    print_names(out, SW_OPTION_PACK, HIDDEN | GROUPS, "", "", " | ", &col);
    col += fprintf(out, ")");
    new_synopsis_line(out, &col, "(");
    print_names(out, SW_OPTION_CAMERA, HIDDEN | GROUPS, "", "", " | ", &col);
    col += fprintf(out, ")");
    new_synopsis_line(out, &col, "");
    print_names(out, 0, HIDDEN | GROUPS, "[", "]", " ", &col);
    fputs("\nWalks a seamwalk pack and shows it on a display. --pack runs the file unsigned\n"
          "(no signature checked); --store runs only packs its trusted keys signed.\n", out);
    for (size_t i = 0; i < sw_option_count; i++)
        if (!(sw_option_table[i].flags & HIDDEN))
            print_entry(out, &sw_option_table[i]);
}

void sw_options_print_test_usage(FILE *out)
{
    fputs("seamwalk's options for the tests only: each makes the walk wrong or slow on\n"
          "purpose, so a test can show that its check catches it.\n", out);
    for (size_t i = 0; i < sw_option_count; i++)
        if (sw_option_table[i].flags & SW_OPTION_TEST_ONLY)
            print_entry(out, &sw_option_table[i]);
}
