/* SPDX-License-Identifier: MIT */
/* gamecontrollerdb lines (sw_gamepad_map.h). */
#include "sw_gamepad_map.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_hex.h"

static const char *const button_names[SW_PAD_BUTTON_COUNT] = {
    "a", "b", "x", "y", "back", "guide", "start", "leftstick", "rightstick",
    "leftshoulder", "rightshoulder", "dpup", "dpdown", "dpleft", "dpright"};
static const char *const axis_names[SW_PAD_AXIS_COUNT] = {
    "leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"};
static const char *const ignored_outputs[] = {"misc1", "paddle1", "paddle2", "paddle3",
                                              "paddle4", "touchpad", NULL};

typedef struct span { const char *p; size_t n; } span;

static int span_is(span s, const char *word)
{
    return strlen(word) == s.n && memcmp(s.p, word, s.n) == 0;
}

static sw_status bad(sw_error *err, const char *file, long line, const char *what, span got)
{
    int n = got.n > 40 ? 40 : (int)got.n;
    return sw_error_set(err, SW_ERR_FORMAT, "%s:%ld: %s, got '%.*s'", file, line, what, n, got.p);
}

/* Digits only, at most 255. */
static int parse_small(const char *p, size_t n, unsigned *out)
{
    if (n == 0 || n > 3)
        return 0;
    unsigned v = 0;
    for (size_t i = 0; i < n; i++) {
        if (p[i] < '0' || p[i] > '9')
            return 0;
        v = v * 10 + (unsigned)(p[i] - '0');
    }
    *out = v;
    return v <= 255;
}

static int parse_input(span v, sw_pad_binding *b)
{
    const char *p = v.p;
    size_t n = v.n;
    if (n && (*p == '+' || *p == '-')) {
        b->in_half = *p == '+' ? 1 : -1;
        p++, n--;
    }
    if (n && p[n - 1] == '~') {
        b->in_invert = 1;
        n--;
    }
    if (n < 2)
        return 0;
    unsigned idx, mask;
    if (p[0] == 'b' && !b->in_half && !b->in_invert && parse_small(p + 1, n - 1, &idx)) {
        b->in_kind = 1;
    } else if (p[0] == 'a' && parse_small(p + 1, n - 1, &idx)) {
        b->in_kind = 2;
    } else if (p[0] == 'h' && !b->in_half && !b->in_invert) {
        const char *dot = memchr(p, '.', n);
        if (!dot || !parse_small(p + 1, (size_t)(dot - p - 1), &idx) ||
            !parse_small(dot + 1, (size_t)(p + n - dot - 1), &mask) || mask == 0 || mask > 15)
            return 0;
        b->in_kind = 3;
        b->in_hat_mask = (uint8_t)mask;
    } else {
        return 0;
    }
    b->in_index = (uint8_t)idx;
    return 1;
}

/* 1: a binding, 0: an output to ignore, -1: an unknown output. */
static int parse_output(span k, sw_pad_binding *b)
{
    if (k.n && (k.p[0] == '+' || k.p[0] == '-')) {
        b->out_half = k.p[0] == '+' ? 1 : -1;
        k.p++, k.n--;
    }
    for (int i = 0; i < SW_PAD_AXIS_COUNT; i++)
        if (span_is(k, axis_names[i])) {
            b->out_kind = 2;
            b->out_index = (uint8_t)i;
            return 1;
        }
    if (b->out_half)
        return -1;
    for (int i = 0; i < SW_PAD_BUTTON_COUNT; i++)
        if (span_is(k, button_names[i])) {
            b->out_kind = 1;
            b->out_index = (uint8_t)i;
            return 1;
        }
    for (int i = 0; ignored_outputs[i]; i++)
        if (span_is(k, ignored_outputs[i]))
            return 0;
    return -1;
}

static int is_meta_key(span k)
{
    return span_is(k, "platform") || span_is(k, "crc") || span_is(k, "hint") ||
           span_is(k, "sdk>=") || span_is(k, "sdk<=");
}

static sw_status parse_binding(span item, const char *file, long line, sw_pad_mapping *out,
                               sw_error *err)
{
    const char *colon = memchr(item.p, ':', item.n);
    if (!colon)
        return bad(err, file, line, "expected OUTPUT:INPUT", item);
    span k = {item.p, (size_t)(colon - item.p)}, v = {colon + 1, item.n - k.n - 1};
    if (is_meta_key(k))
        return SW_OK;
    sw_pad_binding b = {0};
    int kind = parse_output(k, &b);
    if (kind < 0)
        return bad(err, file, line, "expected a gamepad button or axis name (a, b, x, y, "
                   "back, guide, start, leftstick, rightstick, leftshoulder, rightshoulder, "
                   "dpup, dpdown, dpleft, dpright, [+-]leftx, lefty, rightx, righty, "
                   "lefttrigger, righttrigger)", k);
    if (v.n == 0)
        return SW_OK; /* SDL writes "misc1:" for an absent control */
    if (!parse_input(v, &b))
        return bad(err, file, line, "expected bN, [+-]aN[~] or hN.M (N, M at most 255, M "
                   "1..15)", v);
    if (kind == 0)
        return SW_OK;
    if (out->binding_count == SW_PAD_BINDINGS_MAX)
        return bad(err, file, line, "expected at most 48 bindings", item);
    out->bindings[out->binding_count++] = b;
    return SW_OK;
}

sw_status sw_pad_mapping_parse_bindings(const char *text, size_t size, const char *file,
                                        long line, sw_pad_mapping *out, sw_error *err)
{
    out->binding_count = 0;
    size_t i = 0;
    while (i < size) {
        const char *comma = memchr(text + i, ',', size - i);
        size_t end = comma ? (size_t)(comma - text) : size;
        span item = {text + i, end - i};
        while (item.n && (item.p[item.n - 1] == ' ' || item.p[item.n - 1] == '\r'))
            item.n--;
        if (item.n) {
            sw_status st = parse_binding(item, file, line, out, err);
            if (st != SW_OK)
                return st;
        }
        i = end + 1;
    }
    return SW_OK;
}

static int parse_guid(span s, uint8_t guid[16])
{
    if (s.n != 32)
        return 0;
    for (int i = 0; i < 16; i++) {
        int hi = sw_hex_digit(s.p[2 * i]), lo = sw_hex_digit(s.p[2 * i + 1]);
        if (hi < 0 || lo < 0)
            return 0;
        guid[i] = (uint8_t)(hi << 4 | lo);
    }
    return 1;
}

/* "platform:X" in the line, or an empty span. */
static span platform_of(span line)
{
    static const char key[] = "platform:";
    for (size_t i = 0; i + sizeof key - 1 <= line.n; i++)
        if ((i == 0 || line.p[i - 1] == ',') && !memcmp(line.p + i, key, sizeof key - 1)) {
            const char *v = line.p + i + sizeof key - 1;
            const char *end = memchr(v, ',', (size_t)(line.p + line.n - v));
            return (span){v, end ? (size_t)(end - v) : (size_t)(line.p + line.n - v)};
        }
    return (span){line.p, 0};
}

static sw_status parse_line(span s, const char *file, long line, sw_pad_mapping_db *db,
                            sw_error *err)
{
    const char *c1 = memchr(s.p, ',', s.n);
    const char *c2 = c1 ? memchr(c1 + 1, ',', (size_t)(s.p + s.n - c1 - 1)) : NULL;
    if (!c2)
        return bad(err, file, line, "expected GUID,name,bindings", s);
    sw_pad_mapping m = {0};
    if (!parse_guid((span){s.p, (size_t)(c1 - s.p)}, m.guid))
        return bad(err, file, line, "expected a GUID of 32 hex digits", (span){s.p,
                   (size_t)(c1 - s.p)});
    size_t name_n = (size_t)(c2 - c1 - 1);
    if (name_n >= SW_PAD_NAME_MAX)
        name_n = SW_PAD_NAME_MAX - 1;
    memcpy(m.name, c1 + 1, name_n);
    m.line = line;
    sw_status st = sw_pad_mapping_parse_bindings(c2 + 1, (size_t)(s.p + s.n - c2 - 1), file,
                                                 line, &m, err);
    if (st != SW_OK)
        return st;
    span platform = platform_of(s);
    if (platform.n && !span_is(platform, "Linux"))
        return SW_OK;
    if (db->count == SW_PAD_MAPPINGS_MAX)
        return bad(err, file, line, "expected at most 128 Linux mappings (keep the lines of "
                   "the controllers the unit uses)", s);
    db->mappings[db->count++] = m;
    return SW_OK;
}

sw_status sw_pad_mapping_db_parse(const char *text, size_t size, const char *file,
                                  sw_pad_mapping_db *db, sw_error *err)
{
    db->count = 0;
    long line = 0;
    size_t i = 0;
    while (i < size) {
        const char *nl = memchr(text + i, '\n', size - i);
        size_t end = nl ? (size_t)(nl - text) : size;
        span s = {text + i, end - i};
        line++;
        i = end + 1;
        while (s.n && (s.p[0] == ' ' || s.p[0] == '\t'))
            s.p++, s.n--;
        while (s.n && (s.p[s.n - 1] == ' ' || s.p[s.n - 1] == '\r' || s.p[s.n - 1] == '\t'))
            s.n--;
        if (s.n == 0 || s.p[0] == '#')
            continue;
        if (memchr(s.p, '\0', s.n))
            return bad(err, file, line, "expected text, not a NUL byte", s);
        sw_status st = parse_line(s, file, line, db, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

sw_status sw_pad_mapping_db_load(const char *path, sw_pad_mapping_db *db, sw_error *err)
{
    enum { LIMIT = 1 << 20 };
    FILE *f = fopen(path, "rb");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    char *text = malloc(LIMIT + 1);
    size_t size = text ? fread(text, 1, LIMIT + 1, f) : 0;
    fclose(f);
    sw_status st;
    if (!text)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: no memory to read it", path);
    else if (size > LIMIT)
        st = sw_error_set(err, SW_ERR_FORMAT, "%s: larger than 1 MiB", path);
    else
        st = sw_pad_mapping_db_parse(text, size, path, db, err);
    free(text);
    return st;
}

void sw_pad_guid(uint16_t bus, uint16_t vendor, uint16_t product, uint16_t version,
                 uint8_t guid[16])
{
    const uint16_t words[8] = {bus, 0, vendor, 0, product, 0, version, 0};
    for (int i = 0; i < 8; i++) {
        guid[2 * i] = (uint8_t)(words[i] & 0xFF);
        guid[2 * i + 1] = (uint8_t)(words[i] >> 8);
    }
}

/* Bytes 2-3 are the CRC, 12-13 the version. */
static int guid_match(const uint8_t *a, const uint8_t *b, int with_version)
{
    for (int i = 0; i < 16; i++) {
        if (i == 2 || i == 3 || (!with_version && (i == 12 || i == 13)))
            continue;
        if (a[i] != b[i])
            return 0;
    }
    return 1;
}

const sw_pad_mapping *sw_pad_mapping_find(const sw_pad_mapping_db *db, const uint8_t guid[16])
{
    for (int pass = 1; pass >= 0; pass--)
        for (int i = 0; i < db->count; i++)
            if (guid_match(db->mappings[i].guid, guid, pass))
                return &db->mappings[i];
    return NULL;
}

const char *sw_pad_default_bindings(void)
{
    return "a:b0,b:b1,x:b2,y:b3,leftshoulder:b4,rightshoulder:b5,back:b6,start:b7,"
           "leftx:a0,lefty:a1,rightx:a2,righty:a3,"
           "dpup:h0.1,dpright:h0.2,dpdown:h0.4,dpleft:h0.8";
}

/* Hat direction 0..7 clockwise from up as SDL's bit mask. */
static unsigned hat_mask(int dir)
{
    static const unsigned masks[8] = {1, 3, 2, 6, 4, 12, 8, 9};
    return dir >= 0 && dir < 8 ? masks[dir] : 0;
}

/* The input's value: 0/1 for buttons and hats, the axis in [-1, 1], or a
 * half of it in [0, 1]; -2 when the controller has no such input. */
static float input_value(const sw_pad_binding *b, const sw_hid_layout *l, const sw_hid_state *s)
{
    if (b->in_kind == 1)
        return b->in_index < l->button_count
                   ? (float)((s->buttons >> l->sdl_button[b->in_index]) & 1) : -2;
    if (b->in_kind == 3)
        return b->in_index < l->hat_count
                   ? (hat_mask(s->hat[b->in_index]) & b->in_hat_mask ? 1.0f : 0.0f) : -2;
    if (b->in_index >= l->axis_count)
        return -2;
    float v = s->axis[l->sdl_axis[b->in_index]];
    if (b->in_invert)
        v = -v;
    if (b->in_half)
        v = b->in_half > 0 ? fmaxf(v, 0) : fmaxf(-v, 0);
    return v;
}

void sw_pad_apply(const sw_pad_mapping *m, const sw_hid_layout *l, const sw_hid_state *raw,
                  sw_pad_state *out)
{
    memset(out, 0, sizeof *out);
    for (int i = 0; i < m->binding_count; i++) {
        const sw_pad_binding *b = &m->bindings[i];
        float v = input_value(b, l, raw);
        if (v == -2)
            continue;
        int whole_axis = b->in_kind == 2 && !b->in_half;
        if (b->out_kind == 1) {
            if (v > 0.5f)
                out->buttons |= 1u << b->out_index;
            continue;
        }
        if (b->out_index >= SW_PAD_LEFTTRIGGER)
            v = whole_axis ? (v + 1) * 0.5f : v;  /* triggers run 0..1 */
        else if (b->out_half)
            v = b->out_half * (whole_axis ? (v + 1) * 0.5f : v);
        if (fabsf(v) > fabsf(out->axis[b->out_index]))
            out->axis[b->out_index] = v;
    }
}

static void dead_zone_pair(float *x, float *y, float dz)
{
    float r = sqrtf(*x * *x + *y * *y);
    if (r <= dz || r == 0) {
        *x = *y = 0;
        return;
    }
    float scale = (fminf(r, 1.0f) - dz) / (1.0f - dz) / r;
    *x *= scale;
    *y *= scale;
}

void sw_pad_dead_zone(sw_pad_state *s, float dz)
{
    dead_zone_pair(&s->axis[SW_PAD_LEFTX], &s->axis[SW_PAD_LEFTY], dz);
    dead_zone_pair(&s->axis[SW_PAD_RIGHTX], &s->axis[SW_PAD_RIGHTY], dz);
}
