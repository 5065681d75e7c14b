/* SPDX-License-Identifier: MIT */
/* seamwalk's options, one row each (sw_option_table.c): the name, what it
 * takes, its range and default, the sw_options field it sets, its help, whether
 * only the tests use it, and the config key (sw_config.h) that sets the same.
 * Everything that names a range or a default reads it here: the command line
 * (sw_options.c), --help and --help-test (sw_options_help.c), the config
 * file's keys (sw_config.c) and, through tests/option_table_dump.c, the check
 * of the man pages (tests/check_man.py); none can drift from another.
 *
 * The table is data only, so seamwalk-flash, which reads the config without
 * the runtime, links it alone. */
#ifndef SW_OPTION_TABLE_H
#define SW_OPTION_TABLE_H

#include <stddef.h>

/* The most tessellation threads --workers and [budgets] workers take: what
 * the walk can start (seamwalk_start.c holds it to SW_SEAM_WORKERS_MAX). */
#define SW_OPTIONS_MAX_WORKERS 16

typedef enum sw_option_kind {
    SW_OPTION_FLAG,       /* takes nothing: its int field becomes 1 */
    SW_OPTION_TEXT,       /* a file, directory or name: argv's own string */
    SW_OPTION_INT,        /* an integer in min..max, into an int or a long */
    SW_OPTION_REAL,       /* a finite number in min..max, into a double */
    SW_OPTION_WORD,       /* one of arg's words ("tree|brute"): its index, into an int */
    SW_OPTION_SIZE,       /* WIDTHxHEIGHT, each min..max, into int width and the height after it */
    SW_OPTION_HEADLESS,   /* a SIZE that also sets the display to headless */
    SW_OPTION_DISPLAY,    /* a display's name (sw_display_kind_parse) */
    SW_OPTION_RGB,        /* R,G,B, levels min..max each: the background colour */
    SW_OPTION_BACK_FACES, /* lit, hidden or R,G,B levels min..max each */
    SW_OPTION_DEPTH_BITS, /* min or max, nothing between (16 or 24) */
} sw_option_kind;

enum {
    SW_OPTION_TEST_ONLY = 1,  /* a mutant or stall for the tests: --help-test, not --help */
    SW_OPTION_STOPS = 2,      /* --help, --version: the rest of the line is not read */
    SW_OPTION_ALIAS = 4,      /* another name of the row before it, listed nowhere */
    SW_OPTION_READ_FIRST = 8, /* --config: read before the others, given once */
    SW_OPTION_PACK = 16,      /* what to walk: exactly one of these rows */
    SW_OPTION_CAMERA = 32,    /* how the camera moves: exactly one of these rows */
};

typedef struct sw_option_desc {
    const char *name;          /* "--memory-mb" */
    const char *arg;           /* what it takes, as --help shows it ("M", "0|1"); NULL: nothing */
    sw_option_kind kind;
    double min, max;           /* what a value may be (INT, REAL, SIZE, the levels of RGB) */
    double def;                /* its value when neither the line nor the config gives one */
    const char *def_text;      /* the default in words, where the number is not all of it */
    size_t field, field_size;  /* where it goes in sw_options */
    const char *section, *key; /* the config key that sets the same, or NULL */
    unsigned flags;            /* SW_OPTION_* above */
    const char *help;          /* --help's words, wrapped there; '\n' breaks a line */
} sw_option_desc;

extern const sw_option_desc sw_option_table[];
extern const size_t sw_option_count;

/* The row named name ("--frames", or an alias), or NULL. */
const sw_option_desc *sw_option_find(const char *name);

/* The row whose config key is section.key, or NULL: the config's keys that
 * set what an option sets take its range and default from it. */
const sw_option_desc *sw_option_for_key(const char *section, const char *key);

/* A number as the messages, --help and the man pages write it: integers in
 * full (1048576, not 1.04858e+06), others as %g. */
void sw_option_format_number(double value, char *out, size_t size);

/* "MIN..MAX" for a row whose arg does not already list its values (INT,
 * REAL, SIZE, RGB, BACK_FACES); empty for the rest. */
void sw_option_format_range(const sw_option_desc *d, char *out, size_t size);

/* Its default as --help states it (def_text, a WORD's word, a number), or
 * empty where a row states none (flags, and text with no default). */
void sw_option_format_default(const sw_option_desc *d, char *out, size_t size);

#endif
