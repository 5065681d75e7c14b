/* SPDX-License-Identifier: MIT */
/* seamwalk's command line into sw_options (sw_options.h): the config file
 * first, then each argument found in the option table (sw_option_table.c)
 * and read as its row's kind says, within its row's range. */
#include "sw_options.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- values ------------------------------------------------------------- */

static sw_status read_integer(const char *opt, const char *text, double min, double max,
                              long *out, sw_error *err)
{
    char *end;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || *end != '\0' || end == text || errno || v < min || v > max) {
        char lo[32], hi[32];
        sw_option_format_number(min, lo, sizeof lo);
        sw_option_format_number(max, hi, sizeof hi);
        return sw_error_set(err, SW_ERR_ARG, "%s expects an integer in %s..%s, got '%s'", opt,
                            lo, hi, text ? text : "");
    }
    *out = v;
    return SW_OK;
}

static sw_status read_real(const sw_option_desc *d, const char *text, double *out,
                           sw_error *err)
{
    char *end;
    double v = text ? strtod(text, &end) : 0;
    if (!text || *end != '\0' || end == text || !isfinite(v) || v < d->min || v > d->max) {
        char range[80];
        sw_option_format_range(d, range, sizeof range);
        return sw_error_set(err, SW_ERR_ARG, "%s expects a number in %s, got '%s'", d->name,
                            range, text ? text : "");
    }
    *out = v;
    return SW_OK;
}

/* WIDTHxHEIGHT, each side in the row's range, into width and the height
 * after it (sw_option_table.c). */
static sw_status read_size(const sw_option_desc *d, const char *text, int *size, sw_error *err)
{
    const char *x = text ? strchr(text, 'x') : NULL;
    char width[16], what[48];
    if (!x || (size_t)(x - text) >= sizeof width)
        return sw_error_set(err, SW_ERR_ARG, "%s expects WIDTHxHEIGHT, got '%s'", d->name,
                            text ? text : "");
    memcpy(width, text, (size_t)(x - text));
    width[x - text] = '\0';
    long w, h;
    snprintf(what, sizeof what, "%s width", d->name);
    sw_status st = read_integer(what, width, d->min, d->max, &w, err);
    snprintf(what, sizeof what, "%s height", d->name);
    if (st == SW_OK)
        st = read_integer(what, x + 1, d->min, d->max, &h, err);
    if (st == SW_OK) {
        size[0] = (int)w;
        size[1] = (int)h;
    }
    return st;
}

/* R,G,B: three levels in the row's range, as 0..1. */
static sw_status read_rgb(const sw_option_desc *d, const char *text, float rgb[3],
                          sw_error *err)
{
    int level[3], used = 0, ok = sscanf(text, "%d,%d,%d%n", &level[0], &level[1], &level[2],
                                        &used) == 3 && text[used] == '\0';
    for (int c = 0; ok && c < 3; c++)
        ok = level[c] >= d->min && level[c] <= d->max;
    if (!ok) {
        char range[80];
        sw_option_format_range(d, range, sizeof range);
        return sw_error_set(err, SW_ERR_ARG, "%s expects R,G,B (%s each), got '%s'", d->name,
                            range, text);
    }
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)level[c] / (float)d->max;
    return SW_OK;
}

/* A row's words, "tree|brute", as "tree or brute" ("a, b or c"). */
static void list_words(const char *words, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (const char *w = words; w && used < size;) {
        size_t n = strcspn(w, "|");
        const char *sep = w == words ? "" : w[n] ? ", " : " or ";
        int k = snprintf(out + used, size - used, "%s%.*s", sep, (int)n, w);
        used += k > 0 ? (size_t)k : 0;
        w = w[n] ? w + n + 1 : NULL;
    }
}

/* One of the row's words: its index. */
static sw_status read_word(const sw_option_desc *d, const char *text, int *out, sw_error *err)
{
    size_t len = strlen(text);
    int i = 0;
    for (const char *w = d->arg; w; i++) {
        size_t n = strcspn(w, "|");
        if (n == len && !strncmp(w, text, n)) {
            *out = i;
            return SW_OK;
        }
        w = w[n] ? w + n + 1 : NULL;
    }
    char words[128];
    list_words(d->arg, words, sizeof words);
    return sw_error_set(err, SW_ERR_ARG, "%s expects %s, got '%s'", d->name, words, text);
}

/* The config's words are in sw_display_kind's order (sw_config.h). */
static sw_display_kind display_of(sw_config_display d)
{
    switch (d) {
    case SW_DISPLAY_HEADLESS: return SW_DISPLAY_KIND_HEADLESS;
    case SW_DISPLAY_KMS: return SW_DISPLAY_KIND_KMS;
    case SW_DISPLAY_X11: return SW_DISPLAY_KIND_X11;
    case SW_DISPLAY_WAYLAND: return SW_DISPLAY_KIND_WAYLAND;
    default: return SW_DISPLAY_KIND_AUTO;
    }
}

/* ---- one option ----------------------------------------------------------- */

static void *field_of(sw_options *o, const sw_option_desc *d)
{
    return (char *)o + d->field;
}

/* An integer into the row's field, an int or a long. */
static void store_integer(sw_options *o, const sw_option_desc *d, long v)
{
    if (d->field_size == sizeof(long)) {
        memcpy(field_of(o, d), &v, sizeof v);
    } else {
        int i = (int)v;
        memcpy(field_of(o, d), &i, sizeof i);
    }
}

/* lit, hidden or R,G,B: back faces shaded, not drawn, or flat in a colour. */
static sw_status read_back_faces(const sw_option_desc *d, const char *v, sw_options *o,
                                 sw_error *err)
{
    o->back_hidden = !strcmp(v, "hidden");
    o->back_flat = strcmp(v, "lit") != 0 && !o->back_hidden;
    return o->back_flat ? read_rgb(d, v, o->back_color, err) : SW_OK;
}

static sw_status read_depth_bits(const sw_option_desc *d, const char *v, sw_options *o,
                                 sw_error *err)
{
    long bits;
    sw_status st = read_integer(d->name, v, d->min, d->max, &bits, err);
    if (st == SW_OK && bits != d->min && bits != d->max) {
        char words[64];
        list_words(d->arg, words, sizeof words);
        return sw_error_set(err, SW_ERR_ARG, "%s expects %s, got '%s'", d->name, words, v);
    }
    if (st == SW_OK)
        o->depth_bits = (int)bits;
    return st;
}

/* The row's value v (NULL for a flag) into its field. */
static sw_status set_value(const sw_option_desc *d, const char *v, sw_options *o, sw_error *err)
{
    long n = 1;
    sw_status st = SW_OK;
    switch (d->kind) {
    case SW_OPTION_TEXT:
        memcpy(field_of(o, d), &v, sizeof v);
        return SW_OK;
    case SW_OPTION_FLAG:
        store_integer(o, d, 1);
        return SW_OK;
    case SW_OPTION_INT:
        if ((st = read_integer(d->name, v, d->min, d->max, &n, err)) == SW_OK)
            store_integer(o, d, n);
        return st;
    case SW_OPTION_REAL:
        return read_real(d, v, field_of(o, d), err);
    case SW_OPTION_WORD:
        return read_word(d, v, field_of(o, d), err);
    case SW_OPTION_HEADLESS:
        o->display = SW_DISPLAY_KIND_HEADLESS;
        return read_size(d, v, field_of(o, d), err);
    case SW_OPTION_SIZE:
        return read_size(d, v, field_of(o, d), err);
    case SW_OPTION_DISPLAY:
        return sw_display_kind_parse(v, (sw_display_kind *)field_of(o, d), err);
    case SW_OPTION_RGB:
        o->background_set = 1;
        return read_rgb(d, v, field_of(o, d), err);
    case SW_OPTION_BACK_FACES:
        return read_back_faces(d, v, o, err);
    case SW_OPTION_DEPTH_BITS:
        return read_depth_bits(d, v, o, err);
    }
    return sw_error_set(err, SW_ERR_ARG, "%s: no parser for its kind", d->name);
}

/* ---- the whole line ------------------------------------------------------- */

/* Every default is the table's, the config's as well (sw_config_defaults
 * takes its keys' from the same rows). Without --config the config keeps its
 * defaults too: --navigate reads its devices, mapping and speeds from it. */
static void set_defaults(sw_options *o)
{
    memset(o, 0, sizeof *o);
    sw_config_defaults(&o->config);
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if (d->kind == SW_OPTION_REAL)
            memcpy(field_of(o, d), &d->def, sizeof d->def);
        else if (d->kind == SW_OPTION_INT || d->kind == SW_OPTION_WORD ||
                 d->kind == SW_OPTION_DEPTH_BITS)
            store_integer(o, d, (long)d->def);
    }
    /* The test suite's deterministic frames (tests/CMakeLists.txt sets it
     * for every test); the command line's --sync-work wins. */
    const char *sync = getenv("SEAMWALK_TEST_SYNC_WORK");
    o->sync_work = sync && !strcmp(sync, "1");
}

/* The file's values, before the command line overrides them. Its defaults
 * are the command line's, so a key the file leaves out changes nothing. */
static void apply_config(sw_options *o)
{
    const sw_config *c = &o->config;
    o->display = display_of(c->display);
    o->width = c->width;
    o->height = c->height;
    o->fov_deg = c->fov_deg;
    o->pack_path = c->pack[0] ? c->pack : NULL;
    o->store_dir = c->store[0] ? c->store : NULL;
    o->keys_path = c->keys[0] ? c->keys : NULL;
    o->boot_attempts = c->boot_attempts;
    o->good_after_s = c->good_after_s;
    o->memory_mb = c->memory_mb;
    o->max_error_px = c->max_error_px;
    o->batch_tris = c->render_batch_tris;
    o->target_ms = c->budget_frame_ms;
    o->workers = c->budget_workers;
    o->orbit = c->kiosk.nav_mode == SW_NAV_ORBIT;
}

/* --config FILE anywhere on the command line; the main loop checks it again. */
static const char *find_config(int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--config"))
            return argv[i + 1];
    return NULL;
}

/* How many of a group's rows (SW_OPTION_PACK, SW_OPTION_CAMERA) are set. */
static int given(const sw_options *o, unsigned group)
{
    int count = 0;
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        const void *at = (const char *)o + d->field;
        const char *text;
        int flag;
        if (!(d->flags & group))
            continue;
        if (d->kind == SW_OPTION_TEXT) {
            memcpy(&text, at, sizeof text);
            count += text != NULL;
        } else {
            memcpy(&flag, at, sizeof flag);
            count += flag != 0;
        }
    }
    return count;
}

/* What the file chose in groups where the command line's choice replaces it
 * as a whole (--pack or --store; --path, --orbit or --view; the size). */
typedef struct config_choice {
    const char *pack_path, *store_dir;
    int orbit, width, height;
} config_choice;

static config_choice take_choice(sw_options *o)
{
    config_choice c = {o->pack_path, o->store_dir, o->orbit, o->width, o->height};
    o->pack_path = o->store_dir = NULL;
    o->orbit = o->width = o->height = 0;
    return c;
}

static void merge_choice(sw_options *o, const config_choice *c)
{
    if (!given(o, SW_OPTION_PACK)) {
        o->pack_path = c->pack_path;
        o->store_dir = c->store_dir;
    }
    if (!given(o, SW_OPTION_CAMERA))
        o->orbit = c->orbit;
    if (o->width)
        return;
    o->width = c->width;
    o->height = c->height;
}

/* "give exactly one of --pack FILE and --store DIR" unless one is given. */
static sw_status check_one_of(const sw_options *o, unsigned group, sw_error *err)
{
    if (given(o, group) == 1)
        return SW_OK;
    char list[256];
    size_t used = 0;
    int left = 0;
    for (size_t i = 0; i < sw_option_count; i++)
        left += (sw_option_table[i].flags & group) != 0;
    for (size_t i = 0; i < sw_option_count && used < sizeof list; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        if (!(d->flags & group))
            continue;
        left--;
        const char *sep = used == 0 ? "" : left == 0 ? " and " : ", ";
        int n = snprintf(list + used, sizeof list - used, "%s%s%s%s", sep, d->name,
                         d->arg ? " " : "", d->arg ? d->arg : "");
        used += n > 0 ? (size_t)n : 0;
    }
    return sw_error_set(err, SW_ERR_ARG, "give exactly one of %s", list);
}

/* What this build was made without is a usage error when the walk would
 * need it: a display left out, or [gpio] buttons for --navigate without
 * libgpiod (SW_WITH_GPIOD=OFF). Gamepads are looked for, not asked for, so
 * sw_kiosk_run.c only says they are missing. */
static sw_status check_built(const sw_options *o, sw_error *err)
{
    sw_status st = sw_display_kind_check_built(o->display, err);
    if (st != SW_OK || SW_HAVE_GPIOD || !o->navigate || o->config.kiosk.gpio_count == 0)
        return st;
    return sw_error_set(err, SW_ERR_ARG, "[gpio %s]: built without libgpiod (SW_WITH_GPIOD=OFF)",
                        o->config.kiosk.gpio[0].name);
}

sw_status sw_options_parse(int argc, char **argv, sw_options *o, sw_error *err)
{
    set_defaults(o);
    sw_status st = SW_OK;
    o->config_path = find_config(argc, argv);
    if (o->config_path) {
        if ((st = sw_config_load(o->config_path, &o->config, err)) != SW_OK)
            return st;
        apply_config(o);
    }
    config_choice choice = take_choice(o);
    for (int i = 1; i < argc && st == SW_OK; i++) {
        const sw_option_desc *d = sw_option_find(argv[i]);
        const char *v = d && d->arg && i + 1 < argc ? argv[++i] : NULL;
        if (!d)
            return sw_error_set(err, SW_ERR_ARG, "unknown option '%s'", argv[i]);
        if (d->arg && !v)
            return sw_error_set(err, SW_ERR_ARG, "%s: missing its value (%s)", d->name, d->arg);
        if (d->flags & SW_OPTION_READ_FIRST) {
            if (v != o->config_path)
                return sw_error_set(err, SW_ERR_ARG, "%s given twice", d->name);
            continue;
        }
        st = set_value(d, v, o, err);
        if (d->flags & SW_OPTION_STOPS)
            return st;
    }
    if (st == SW_OK)
        merge_choice(o, &choice);
    if (st == SW_OK)
        st = check_one_of(o, SW_OPTION_PACK, err);
    if (st == SW_OK)
        st = check_one_of(o, SW_OPTION_CAMERA, err);
    return st != SW_OK ? st : check_built(o, err);
}
