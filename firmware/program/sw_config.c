/* SPDX-License-Identifier: MIT */
/* The configuration file (sw_config.h). inih splits the text into sections
 * and key = value pairs; our line reader feeds it and counts lines (this inih
 * build passes no line numbers to the handler), checks each [section] header
 * as it passes, so an empty unknown section is an error too, and stops inih at
 * the first error. Keys are described by tables, one row per key, which the
 * example file firmware/dist/seamwalk.ini mirrors. A key that sets what a
 * command-line option sets takes that option's range and default from the
 * option table (sw_option_table.c), so the two cannot take different values. */
#include "sw_config.h"

#include "sw_option_table.h"

#include <assert.h>
#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum key_kind { K_INT, K_REAL, K_BOOL, K_PATH, K_NAME, K_SIZE, K_ENUM, K_LINE } key_kind;

/* One key: where its value goes (offset2: the height of a size, the offset
 * of a named-or-numbered line) and what it accepts. */
typedef struct key_desc {
    const char *section, *key;
    key_kind kind;
    size_t offset, offset2;
    double min, max;
    const char *const *words;
} key_desc;

/* min and max of a key that sets what an option sets: its range, and its
 * default, are the option's (sw_option_for_key). */
#define OF_OPTION NAN, NAN

static const char *const display_words[] = {"auto", "headless", "kms", "x11", "wayland", NULL};
static const char *const nav_words[] = {"walk", "orbit", NULL};
static const char *const bias_words[] = {"as-is", "disable", "pull-up", "pull-down", NULL};
static const char *const action_words[] = {"none", "forward", "back", "turn_left",
                                           "turn_right", "next_view", "prev_view", "home",
                                           "toggle_mode", "attract", "look_up", "look_down",
                                           "strafe_left", "strafe_right", NULL};

#define C(field) offsetof(sw_config, field)
#define K(field) offsetof(sw_config, kiosk.field)
#define G(field) offsetof(sw_kiosk_gpio, field)

static const key_desc config_keys[] = {
    {"display", "display", K_ENUM, C(display), 0, OF_OPTION, display_words},
    {"display", "size", K_SIZE, C(width), C(height), OF_OPTION, NULL},
    {"display", "fov_deg", K_REAL, C(fov_deg), 0, OF_OPTION, NULL},
    {"pack", "pack", K_PATH, C(pack), 0, OF_OPTION, NULL},
    {"pack", "store", K_PATH, C(store), 0, OF_OPTION, NULL},
    {"pack", "keys", K_PATH, C(keys), 0, OF_OPTION, NULL},
    {"pack", "boot_attempts", K_INT, C(boot_attempts), 0, OF_OPTION, NULL},
    {"pack", "good_after_s", K_REAL, C(good_after_s), 0, OF_OPTION, NULL},
    {"render", "memory_mb", K_REAL, C(memory_mb), 0, OF_OPTION, NULL},
    {"render", "max_error_px", K_REAL, C(max_error_px), 0, OF_OPTION, NULL},
    {"render", "batch_tris", K_INT, C(render_batch_tris), 0, OF_OPTION, NULL},
    {"budgets", "frame_ms", K_REAL, C(budget_frame_ms), 0, OF_OPTION, NULL},
    {"budgets", "workers", K_INT, C(budget_workers), 0, OF_OPTION, NULL},
    {"gamepad", "enabled", K_BOOL, K(gamepad_enabled), 0, 0, 0, NULL},
    {"gamepad", "mapping", K_PATH, K(gamepad_mapping), 0, 0, 0, NULL},
    {"gamepad", "dead_zone", K_REAL, K(gamepad_dead_zone), 0, 0, 0.95, NULL},
#define PAD_BUTTON(name, i) {"gamepad", name, K_ENUM, K(gamepad_action[i]), 0, 0, 0, action_words}
    PAD_BUTTON("a", 0), PAD_BUTTON("b", 1), PAD_BUTTON("x", 2), PAD_BUTTON("y", 3),
    PAD_BUTTON("back", 4), PAD_BUTTON("guide", 5), PAD_BUTTON("start", 6),
    PAD_BUTTON("leftstick", 7), PAD_BUTTON("rightstick", 8), PAD_BUTTON("leftshoulder", 9),
    PAD_BUTTON("rightshoulder", 10), PAD_BUTTON("dpup", 11), PAD_BUTTON("dpdown", 12),
    PAD_BUTTON("dpleft", 13), PAD_BUTTON("dpright", 14),
#undef PAD_BUTTON
    {"keyboard", "enabled", K_BOOL, K(keyboard_enabled), 0, 0, 0, NULL},
    {"keyboard", "device", K_PATH, K(keyboard_device), 0, 0, 0, NULL},
    {"navigation", "mode", K_ENUM, K(nav_mode), 0, 0, 0, nav_words},
    {"navigation", "walk_speed_mm_s", K_REAL, K(walk_speed_mm_s), 0, 0, 1e6, NULL},
    {"navigation", "turn_speed_deg_s", K_REAL, K(turn_speed_deg_s), 0, 0, 3600, NULL},
    {"navigation", "orbit_speed_deg_s", K_REAL, K(orbit_speed_deg_s), 0, 0, 3600, NULL},
    {"navigation", "accel_s", K_REAL, K(accel_s), 0, 0.01, 10, NULL},
    {"navigation", "eye_height_mm", K_REAL, K(eye_height_mm), 0, 0, 1e6, NULL},
    {"navigation", "transition_s", K_REAL, K(transition_s), 0, 0.05, 60, NULL},
    {"navigation", "attract_hold_s", K_REAL, K(attract_hold_s), 0, 0.5, 3600, NULL},
    {"navigation", "attract_timeout_s", K_REAL, K(attract_timeout_s), 0, 0, 86400, NULL},
};
enum { CONFIG_KEY_COUNT = sizeof config_keys / sizeof config_keys[0] };
_Static_assert(CONFIG_KEY_COUNT <= sizeof(((sw_config *)0)->key_line) / sizeof(long),
               "sw_config.key_line has a slot per key");

enum { GK_CHIP, GK_LINE, GK_DEBOUNCE, GK_MIN_PRESS, GK_LONG_PRESS };
static const key_desc gpio_keys[] = {
    [GK_CHIP] = {"gpio", "chip", K_NAME, G(chip), 0, 0, 0, NULL},
    [GK_LINE] = {"gpio", "line", K_LINE, G(line_name), G(line_offset), 0, 65535, NULL},
    [GK_DEBOUNCE] = {"gpio", "debounce_ms", K_INT, G(debounce_ms), 0, 1, 1000, NULL},
    [GK_MIN_PRESS] = {"gpio", "min_press_ms", K_INT, G(min_press_ms), 0, 0, 1000, NULL},
    [GK_LONG_PRESS] = {"gpio", "long_press_ms", K_INT, G(long_press_ms), 0, 0, 60000, NULL},
    {"gpio", "active_low", K_BOOL, G(active_low), 0, 0, 0, NULL},
    {"gpio", "bias", K_ENUM, G(bias), 0, 0, 0, bias_words},
    {"gpio", "action", K_ENUM, G(action), 0, 0, 0, action_words},
    {"gpio", "long_action", K_ENUM, G(long_action), 0, 0, 0, action_words},
};
enum { GPIO_KEY_COUNT = sizeof gpio_keys / sizeof gpio_keys[0] };

static const char *const section_words[] = {"display", "pack", "render", "budgets",
                                            "gamepad", "keyboard", "navigation", NULL};
enum { SECTION_NONE = -1, SECTION_GPIO = 100 };

/* The range a key takes: its own, or with OF_OPTION its option's. An
 * OF_OPTION key no option names keeps NaN, which no value is within, so the
 * example file's test (tests/test_config.c) fails on it. */
static void key_range(const key_desc *k, double *min, double *max)
{
    const sw_option_desc *o = isnan(k->min) ? sw_option_for_key(k->section, k->key) : NULL;
    assert(o || !isnan(k->min));
    *min = o ? o->min : k->min;
    *max = o ? o->max : k->max;
}

/* The keys an option sets too start at its default. */
static void option_defaults(sw_config *cfg)
{
    for (size_t i = 0; i < CONFIG_KEY_COUNT; i++) {
        const key_desc *k = &config_keys[i];
        const sw_option_desc *o = isnan(k->min) ? sw_option_for_key(k->section, k->key) : NULL;
        char *at = (char *)cfg + k->offset;
        int whole = o ? (int)o->def : 0;
        if (!o)
            continue;
        if (k->kind == K_REAL)
            memcpy(at, &o->def, sizeof o->def);
        else if (k->kind == K_INT || k->kind == K_ENUM)
            memcpy(at, &whole, sizeof whole);
        else if (k->kind == K_PATH && o->def_text)
            snprintf(at, SW_CONFIG_PATH_MAX, "%s", o->def_text);
    }
}

void sw_config_defaults(sw_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    option_defaults(cfg);
    cfg->kiosk.gamepad_enabled = 1;
    cfg->kiosk.gamepad_dead_zone = 0.15;
    static const sw_kiosk_action pad_actions[SW_KIOSK_PAD_BUTTONS] = {
        SW_ACTION_NEXT_VIEW, SW_ACTION_PREV_VIEW, SW_ACTION_TOGGLE_MODE, SW_ACTION_HOME,
        SW_ACTION_NONE, SW_ACTION_HOME, SW_ACTION_ATTRACT, SW_ACTION_NONE, SW_ACTION_NONE,
        SW_ACTION_PREV_VIEW, SW_ACTION_NEXT_VIEW, SW_ACTION_FORWARD, SW_ACTION_BACK,
        SW_ACTION_TURN_LEFT, SW_ACTION_TURN_RIGHT};
    memcpy(cfg->kiosk.gamepad_action, pad_actions, sizeof pad_actions);
    cfg->kiosk.keyboard_enabled = 1;
    memcpy(cfg->kiosk.keyboard_device, "auto", 5);
    cfg->kiosk.accel_s = 0.4;
    cfg->kiosk.eye_height_mm = 1600;
    cfg->kiosk.transition_s = 1.5;
    cfg->kiosk.attract_hold_s = 8;
    cfg->kiosk.nav_mode = SW_NAV_WALK;
    cfg->kiosk.walk_speed_mm_s = 1500;
    cfg->kiosk.turn_speed_deg_s = 90;
    cfg->kiosk.orbit_speed_deg_s = 30;
    cfg->kiosk.attract_timeout_s = 120;
}

static void gpio_defaults(sw_kiosk_gpio *g)
{
    memset(g, 0, sizeof *g);
    g->line_offset = -1;
    g->bias = SW_BIAS_AS_IS;
    g->debounce_ms = 10;
    g->min_press_ms = 2;
    g->long_press_ms = 800;
}

typedef struct config_parse {
    const char *text;
    size_t size, pos;
    const char *file;
    long line, error_line;
    sw_status status;
    sw_config *cfg;
    sw_error *err;
    int section;                    /* index into section_words, or SECTION_* */
    char section_name[48];          /* as written, for messages */
    sw_kiosk_gpio *gpio;           /* with SECTION_GPIO */
    long gpio_line[GPIO_KEY_COUNT]; /* where the gpio section's keys were given */
} config_parse;

/* Records the first error, "FILE:LINE: message"; returns 0 for inih. */
static int fail_at(config_parse *ps, long line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int fail_at(config_parse *ps, long line, const char *fmt, ...)
{
    if (ps->error_line)
        return 0;
    char msg[SW_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    ps->error_line = line > 0 ? line : 1;
    ps->status = sw_error_set(ps->err, SW_ERR_FORMAT, "%s:%ld: %s", ps->file, ps->error_line, msg);
    return 0;
}

static int parse_long(const char *text, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno)
        return 0;
    *out = v;
    return 1;
}

static int word_index(const char *const *words, const char *text)
{
    for (int i = 0; words[i]; i++)
        if (!strcmp(words[i], text))
            return i;
    return -1;
}

/* "a, b or c" for messages. */
static void list_words(const char *const *words, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; words[i] && used < size; i++) {
        const char *sep = i == 0 ? "" : words[i + 1] ? ", " : " or ";
        int n = snprintf(out + used, size - used, "%s%s", sep, words[i]);
        used += n > 0 ? (size_t)n : 0;
    }
}

static int set_text(config_parse *ps, const key_desc *k, char *dst, size_t cap, const char *v)
{
    size_t len = strlen(v);
    if (len >= cap)
        return fail_at(ps, ps->line, "[%s] %s: expected at most %zu bytes, got %zu",
                       ps->section_name, k->key, cap - 1, len);
    if (k->kind != K_PATH && len == 0)
        return fail_at(ps, ps->line, "[%s] %s: expected a name, got nothing", ps->section_name,
                       k->key);
    memcpy(dst, v, len + 1);
    return 1;
}

/* "LO..HI" for messages, numbers as the options write them. */
static void format_range(double min, double max, char *out, size_t size)
{
    char lo[32], hi[32];
    sw_option_format_number(min, lo, sizeof lo);
    sw_option_format_number(max, hi, sizeof hi);
    snprintf(out, size, "%s..%s", lo, hi);
}

static int set_size(config_parse *ps, const key_desc *k, char *base, const char *v)
{
    const char *x = strchr(v, 'x');
    char w[16], range[80];
    long wv = 0, hv = 0;
    double min, max;
    key_range(k, &min, &max);
    int ok = x && (size_t)(x - v) < sizeof w;
    if (ok) {
        memcpy(w, v, (size_t)(x - v));
        w[x - v] = '\0';
        ok = parse_long(w, &wv) && parse_long(x + 1, &hv) && wv >= min && wv <= max &&
             hv >= min && hv <= max;
    }
    format_range(min, max, range, sizeof range);
    if (!ok)
        return fail_at(ps, ps->line, "[%s] %s: expected WIDTHxHEIGHT, each %s, got '%s'",
                       ps->section_name, k->key, range, v);
    int wi = (int)wv, hi = (int)hv;
    memcpy(base + k->offset, &wi, sizeof wi);
    memcpy(base + k->offset2, &hi, sizeof hi);
    return 1;
}

/* "line = 17" is an offset on the chip, anything else the line's name. */
static int set_line(config_parse *ps, const key_desc *k, char *base, const char *v)
{
    int off = -1;
    char *name = base + k->offset;
    if (isdigit((unsigned char)v[0])) {
        long offset;
        char most[32];
        sw_option_format_number(k->max, most, sizeof most);
        if (!parse_long(v, &offset) || offset > k->max)
            return fail_at(ps, ps->line, "[%s] %s: expected a line offset 0..%s or a line name, "
                           "got '%s'", ps->section_name, k->key, most, v);
        off = (int)offset;
        name[0] = '\0';
    } else if (!set_text(ps, k, name, SW_CONFIG_NAME_MAX, v)) {
        return 0;
    }
    memcpy(base + k->offset2, &off, sizeof off);
    return 1;
}

static int set_number(config_parse *ps, const key_desc *k, char *base, const char *v)
{
    char *end;
    errno = 0;
    double d = strtod(v, &end);
    int is_number = end != v && *end == '\0' && isfinite(d) && !errno;
    if (k->kind == K_INT)
        is_number = is_number && d == floor(d) && strpbrk(v, ".eExXnN") == NULL;
    if (!is_number)
        return fail_at(ps, ps->line, "[%s] %s: expected %s, got '%s'", ps->section_name, k->key,
                       k->kind == K_INT ? "an integer" : "a number", v);
    double min, max;
    char range[80];
    key_range(k, &min, &max);
    format_range(min, max, range, sizeof range);
    if (!(d >= min && d <= max))
        return fail_at(ps, ps->line, "[%s] %s: expected %s, got %s", ps->section_name, k->key,
                       range, v);
    if (k->kind == K_INT) {
        int i = (int)d;
        memcpy(base + k->offset, &i, sizeof i);
    } else {
        memcpy(base + k->offset, &d, sizeof d);
    }
    return 1;
}

static int set_word(config_parse *ps, const key_desc *k, char *base, const char *v)
{
    static const char *const bool_words[] = {"no", "yes", "off", "on", "false", "true",
                                             "0", "1", NULL};
    const char *const *words = k->kind == K_BOOL ? bool_words : k->words;
    int i = word_index(words, v);
    if (i < 0) {
        char list[256];
        list_words(words, list, sizeof list);
        return fail_at(ps, ps->line, "[%s] %s: expected %s, got '%s'", ps->section_name, k->key,
                       list, v);
    }
    int value = k->kind == K_BOOL ? i % 2 : i;
    memcpy(base + k->offset, &value, sizeof value);
    return 1;
}

static int set_value(config_parse *ps, const key_desc *k, char *base, const char *v)
{
    switch (k->kind) {
    case K_INT:
    case K_REAL:
        return set_number(ps, k, base, v);
    case K_BOOL:
    case K_ENUM:
        return set_word(ps, k, base, v);
    case K_PATH:
        return set_text(ps, k, base + k->offset, SW_CONFIG_PATH_MAX, v);
    case K_NAME:
        return set_text(ps, k, base + k->offset, SW_CONFIG_NAME_MAX, v);
    case K_SIZE:
        return set_size(ps, k, base, v);
    case K_LINE:
        return set_line(ps, k, base, v);
    }
    return 0;
}

/* ---- sections ------------------------------------------------------------ */

static long later(long a, long b) { return a > b ? a : b; }

/* The checks that need the whole [gpio NAME] section. */
static int end_gpio_section(config_parse *ps)
{
    sw_kiosk_gpio *g = ps->gpio;
    const long *at = ps->gpio_line;
    ps->gpio = NULL;
    if (!g)
        return 1;
    if (!at[GK_CHIP])
        return fail_at(ps, g->line, "[gpio %s] chip: missing (expected chip = gpiochipN or the "
                       "chip's label)", g->name);
    if (!at[GK_LINE])
        return fail_at(ps, g->line, "[gpio %s] line: missing (expected line = OFFSET or the "
                       "line's name)", g->name);
    if (g->min_press_ms > g->debounce_ms)
        return fail_at(ps, later(at[GK_MIN_PRESS], at[GK_DEBOUNCE]), "[gpio %s] min_press_ms: "
                       "expected at most debounce_ms (%d), got %d", g->name, g->debounce_ms,
                       g->min_press_ms);
    if (g->long_press_ms != 0 && g->long_press_ms <= g->debounce_ms)
        return fail_at(ps, later(at[GK_LONG_PRESS], at[GK_DEBOUNCE]), "[gpio %s] long_press_ms: "
                       "expected 0 or more than debounce_ms (%d), got %d", g->name,
                       g->debounce_ms, g->long_press_ms);
    return 1;
}

static int begin_gpio_section(config_parse *ps, const char *name)
{
    size_t len = strlen(name);
    if (len == 0 || len >= SW_CONFIG_NAME_MAX || strspn(name, "abcdefghijklmnopqrstuvwxyz"
                   "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != len)
        return fail_at(ps, ps->line, "[%s]: expected [gpio NAME], NAME of 1..%d letters, digits, "
                       "'_' or '-'", ps->section_name, SW_CONFIG_NAME_MAX - 1);
    sw_config *cfg = ps->cfg;
    for (int i = 0; i < cfg->kiosk.gpio_count; i++)
        if (!strcmp(cfg->kiosk.gpio[i].name, name))
            return fail_at(ps, ps->line, "[%s]: expected a new button name, [gpio %s] is on line "
                           "%ld", ps->section_name, name, cfg->kiosk.gpio[i].line);
    if (cfg->kiosk.gpio_count == SW_CONFIG_GPIO_MAX)
        return fail_at(ps, ps->line, "[%s]: expected at most %d [gpio] sections",
                       ps->section_name, SW_CONFIG_GPIO_MAX);
    sw_kiosk_gpio *g = &cfg->kiosk.gpio[cfg->kiosk.gpio_count++];
    gpio_defaults(g);
    memcpy(g->name, name, len + 1);
    g->line = ps->line;
    memset(ps->gpio_line, 0, sizeof ps->gpio_line);
    ps->gpio = g;
    ps->section = SECTION_GPIO;
    return 1;
}

/* A "[...]" line, checked as it passes so that an empty unknown section is
 * caught as well; inih reads the same text up to the ']'. */
static int begin_section(config_parse *ps, const char *header, size_t len)
{
    if (!end_gpio_section(ps))
        return 0;
    const char *close = memchr(header, ']', len);
    if (!close)
        return fail_at(ps, ps->line, "expected ']' to close the section name");
    const char *rest = close + 1 + strspn(close + 1, " \t\r\n");
    if (*rest && *rest != ';' && *rest != '#')
        return fail_at(ps, ps->line, "expected nothing but a comment after ']'");
    size_t n = (size_t)(close - header - 1);
    if (n >= sizeof ps->section_name)
        return fail_at(ps, ps->line, "section name longer than %zu bytes",
                       sizeof ps->section_name - 1);
    memcpy(ps->section_name, header + 1, n);
    ps->section_name[n] = '\0';
    int i = word_index(section_words, ps->section_name);
    if (i >= 0) {
        ps->section = i;
        return 1;
    }
    if (!strncmp(ps->section_name, "gpio", 4) && (ps->section_name[4] == ' ' ||
                                                  ps->section_name[4] == '\t'))
        return begin_gpio_section(ps, ps->section_name + 5 + strspn(ps->section_name + 5, " \t"));
    return fail_at(ps, ps->line, "unknown section [%s] (expected [display], [pack], [render], "
                   "[budgets], [gamepad], [keyboard], [navigation] or [gpio NAME])",
                   ps->section_name);
}

/* ---- keys ------------------------------------------------------------------ */

static int unknown_key(config_parse *ps, const key_desc *keys, size_t count,
                       const char *section, const char *key)
{
    char list[384];
    size_t used = 0;
    list[0] = '\0';
    for (size_t i = 0; i < count && used < sizeof list; i++) {
        if (strcmp(keys[i].section, section) != 0)
            continue;
        int n = snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", keys[i].key);
        used += n > 0 ? (size_t)n : 0;
    }
    return fail_at(ps, ps->line, "[%s] unknown key '%s' (expected %s)", ps->section_name, key,
                   list);
}

/* Sets key in base from the table rows of section; line_of[i] remembers
 * where row i was given (a key twice is an error). */
static int set_key(config_parse *ps, const key_desc *keys, size_t count, const char *section,
                   long *line_of, char *base, const char *key, const char *value)
{
    for (size_t i = 0; i < count; i++) {
        if (strcmp(keys[i].section, section) != 0 || strcmp(keys[i].key, key) != 0)
            continue;
        if (line_of[i])
            return fail_at(ps, ps->line, "[%s] %s: given twice (first on line %ld)",
                           ps->section_name, key, line_of[i]);
        if (!set_value(ps, &keys[i], base, value))
            return 0;
        line_of[i] = ps->line;
        return 1;
    }
    return unknown_key(ps, keys, count, section, key);
}

static int handle_key(void *user, const char *section, const char *key, const char *value)
{
    (void)section; /* the reader tracks sections itself, with their lines */
    config_parse *ps = user;
    if (ps->error_line)
        return 0;
    if (ps->section == SECTION_NONE)
        return fail_at(ps, ps->line, "%s: expected a [section] before the first key", key);
    if (ps->section == SECTION_GPIO)
        return set_key(ps, gpio_keys, GPIO_KEY_COUNT, "gpio", ps->gpio_line, (char *)ps->gpio,
                       key, value);
    return set_key(ps, config_keys, CONFIG_KEY_COUNT, section_words[ps->section],
                   ps->cfg->key_line, (char *)ps->cfg, key, value);
}

/* ---- reading ----------------------------------------------------------------- */

/* An fgets-style reader over the text for ini_parse_stream; returns NULL (the
 * end, for inih) at the first error. */
static char *read_line(char *str, int num, void *stream)
{
    config_parse *ps = stream;
    if (ps->error_line || ps->pos >= ps->size || num < 2)
        return NULL;
    const char *start = ps->text + ps->pos;
    const char *nl = memchr(start, '\n', ps->size - ps->pos);
    size_t len = nl ? (size_t)(nl - start) + 1 : ps->size - ps->pos;
    ps->line++;
    if (len > (size_t)num - 1) {
        fail_at(ps, ps->line, "line longer than %d bytes", num - 2);
        return NULL;
    }
    memcpy(str, start, len);
    str[len] = '\0';
    ps->pos += len;
    /* Classify the line as inih will: after a UTF-8 BOM on line 1, with
     * isspace() as its idea of blank. */
    size_t lead = ps->line == 1 && len >= 3 && !memcmp(str, "\xEF\xBB\xBF", 3) ? 3 : 0;
    size_t indent = 0;
    while (isspace((unsigned char)str[lead + indent]))
        indent++;
    char first = str[lead + indent];
    /* inih would read an indented line as more of the previous value, on a
     * line number the handler is not told. */
    if (indent > 0 && first != '\0' && first != ';' && first != '#') {
        fail_at(ps, ps->line, "unexpected indentation (continuation lines are not read)");
        return NULL;
    }
    if (first == '[' && !begin_section(ps, str + lead + indent, len - lead - indent))
        return NULL;
    return str;
}

static long key_index(const char *section, const char *key)
{
    for (size_t i = 0; i < CONFIG_KEY_COUNT; i++)
        if (!strcmp(config_keys[i].section, section) && !strcmp(config_keys[i].key, key))
            return (long)i;
    return -1;
}

static void check_whole_file(config_parse *ps)
{
    const sw_config *cfg = ps->cfg;
    long pack = cfg->key_line[key_index("pack", "pack")];
    long store = cfg->key_line[key_index("pack", "store")];
    if (cfg->pack[0] && cfg->store[0]) /* "pack =" with no value means none */
        fail_at(ps, later(pack, store), "[pack] %s: expected pack = FILE or store = DIR, not "
                "both (the other is on line %ld)", pack > store ? "pack" : "store",
                pack > store ? store : pack);
}

static sw_status parse(config_parse *ps)
{
    const char *nul = memchr(ps->text, '\0', ps->size);
    if (nul) {
        long line = 1;
        for (const char *p = ps->text; p < nul; p++)
            line += *p == '\n';
        fail_at(ps, line, "NUL byte in a text file");
        return ps->status;
    }
    int syntax_line = ini_parse_stream(read_line, ps, handle_key, ps);
    if (syntax_line > 0 && (!ps->error_line || syntax_line < ps->error_line)) {
        ps->error_line = 0;
        fail_at(ps, syntax_line, "expected [section] or key = value");
    } else if (syntax_line < 0 && !ps->error_line) {
        ps->error_line = 1;
        ps->status = sw_error_set(ps->err, SW_ERR_NO_MEMORY, "%s: inih failed (%d)", ps->file,
                                  syntax_line);
    }
    if (!ps->error_line)
        end_gpio_section(ps);
    if (!ps->error_line)
        check_whole_file(ps);
    return ps->error_line ? ps->status : SW_OK;
}

sw_status sw_config_load_memory(const char *text, size_t size, const char *file_name,
                                sw_config *cfg, sw_error *err)
{
    sw_config_defaults(cfg);
    config_parse ps = {.text = text, .size = size, .file = file_name, .cfg = cfg, .err = err,
                       .section = SECTION_NONE};
    return parse(&ps);
}

sw_status sw_config_load(const char *path, sw_config *cfg, sw_error *err)
{
    enum { LIMIT = 1 << 20 };
    sw_config_defaults(cfg);
    FILE *f = fopen(path, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    char *text = malloc(LIMIT + 1);
    size_t size = text ? fread(text, 1, LIMIT + 1, f) : 0;
    int bad = text ? ferror(f) : 0;
    fclose(f);
    sw_status st;
    if (!text)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: no memory to read it", path);
    else if (bad)
        st = sw_error_set(err, SW_ERR_IO, "%s: read error", path);
    else if (size > LIMIT)
        st = sw_error_set(err, SW_ERR_FORMAT, "%s: larger than 1 MiB, not a config file", path);
    else
        st = sw_config_load_memory(text, size, path, cfg, err);
    free(text);
    return st;
}

long sw_config_key_line(const sw_config *cfg, const char *section_dot_key)
{
    const char *dot = strchr(section_dot_key, '.');
    char section[32];
    if (!dot || (size_t)(dot - section_dot_key) >= sizeof section)
        return 0;
    memcpy(section, section_dot_key, (size_t)(dot - section_dot_key));
    section[dot - section_dot_key] = '\0';
    long i = key_index(section, dot + 1);
    return i < 0 ? 0 : cfg->key_line[i];
}

const char *sw_config_display_name(sw_config_display display)
{
    return (unsigned)display < 5 ? display_words[display] : "?";
}
