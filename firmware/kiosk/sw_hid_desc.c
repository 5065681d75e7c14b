/* SPDX-License-Identifier: MIT */
/* The HID report descriptor parser and report decoder (sw_hid_desc.h).
 * Items follow HID 1.11 section 6.2.2: a prefix byte (size in bits 0-1, 3
 * meaning 4 bytes; type in bits 2-3; tag in bits 4-7), then the data. The
 * global state has a Push/Pop stack; the local state (usages) is cleared by
 * every main item. Input bit offsets are counted per report ID. */
#include "sw_hid_desc.h"

#include <string.h>

enum { STACK_MAX = 4, DEPTH_MAX = 16, USAGES_MAX = 64 };
enum { TYPE_MAIN = 0, TYPE_GLOBAL = 1, TYPE_LOCAL = 2 };
enum { PAGE_DESKTOP = 0x01, PAGE_BUTTON = 0x09 };

typedef struct globals {
    uint32_t usage_page;
    int32_t logical_min, logical_max;
    uint32_t report_size, report_count, report_id;
} globals;

typedef struct parser {
    const char *name;
    sw_error *err;
    sw_hid_layout *out;
    globals g, stack[STACK_MAX];
    int stack_depth;
    uint32_t usages[USAGES_MAX];  /* page << 16 | id */
    int usage_count;
    uint32_t usage_min, usage_max;
    int has_min, has_max;
    int depth;
    int game_depth;               /* depth of the open game application, 0: none */
    uint32_t input_bits[256];     /* per report ID */
    size_t at;                    /* offset of the current item, for messages */
} parser;

static sw_status fail(parser *p, const char *what)
{
    return sw_error_set(p->err, SW_ERR_FORMAT, "%s: byte %zu: %s", p->name, p->at, what);
}

static uint32_t item_udata(const uint8_t *d, int n)
{
    uint32_t v = 0;
    for (int i = 0; i < n; i++)
        v |= (uint32_t)d[i] << (8 * i);
    return v;
}

static int32_t item_sdata(const uint8_t *d, int n)
{
    uint32_t v = item_udata(d, n);
    if (n == 1)
        return (int8_t)v;
    if (n == 2)
        return (int16_t)v;
    return (int32_t)v;
}

static int is_game_usage(uint32_t usage)
{
    return usage == (PAGE_DESKTOP << 16 | 4) || usage == (PAGE_DESKTOP << 16 | 5) ||
           usage == (PAGE_DESKTOP << 16 | 8);
}

/* The usage of the n-th field of a main item: the list, then the range;
 * the last one repeats (HID 1.11 section 6.2.2.8). */
static uint32_t usage_at(const parser *p, uint32_t n)
{
    if (p->has_min && p->has_max && p->usage_max >= p->usage_min) {
        uint32_t span = p->usage_max - p->usage_min;
        return p->usage_min + (n < span ? n : span);
    }
    if (p->usage_count == 0)
        return 0;
    return p->usages[n < (uint32_t)p->usage_count ? n : (uint32_t)p->usage_count - 1];
}

static void clear_locals(parser *p)
{
    p->usage_count = 0;
    p->has_min = p->has_max = 0;
}

static sw_status keep_field(parser *p, uint32_t usage, uint32_t bit_offset)
{
    uint32_t page = usage >> 16, id = usage & 0xFFFF;
    sw_hid_field f = {0};
    if (page == PAGE_DESKTOP && id >= 0x30 && id <= 0x35) {
        f.kind = SW_HID_AXIS;
        f.index = (uint8_t)(id - 0x30);
    } else if (page == PAGE_DESKTOP && id == 0x39) {
        int hats = 0;
        for (int i = 0; i < p->out->field_count; i++)
            hats += p->out->fields[i].kind == SW_HID_HAT;
        if (hats >= SW_HID_HATS_MAX)
            return SW_OK;
        f.kind = SW_HID_HAT;
        f.index = (uint8_t)hats;
    } else if (page == PAGE_BUTTON && id >= 1 && id <= SW_HID_BUTTONS_MAX) {
        f.kind = SW_HID_BUTTON;
        f.index = (uint8_t)(id - 1);
    } else {
        return SW_OK;
    }
    if (p->g.report_size == 0 || p->g.report_size > 32)
        return SW_OK; /* nothing a controller sends; its bits are counted anyway */
    if (p->out->field_count == SW_HID_FIELDS_MAX)
        return fail(p, "more than 64 axis, hat and button fields");
    f.report_id = (uint8_t)p->g.report_id;
    f.bit_size = (uint8_t)p->g.report_size;
    f.bit_offset = (uint16_t)bit_offset;
    f.logical_min = p->g.logical_min;
    f.logical_max = p->g.logical_max;
    p->out->fields[p->out->field_count++] = f;
    return SW_OK;
}

static sw_status main_input(parser *p, uint32_t flags)
{
    uint64_t bits = (uint64_t)p->g.report_size * p->g.report_count;
    uint32_t start = p->input_bits[p->g.report_id];
    if (start + bits > (uint64_t)(SW_HID_REPORT_MAX - 1) * 8)
        return fail(p, "an input report longer than 255 bytes after its ID");
    int constant = flags & 1, variable = flags & 2;
    if (p->game_depth && !constant && variable) {
        for (uint32_t n = 0; n < p->g.report_count; n++) {
            sw_status st = keep_field(p, usage_at(p, n), start + n * p->g.report_size);
            if (st != SW_OK)
                return st;
        }
    }
    p->input_bits[p->g.report_id] = start + (uint32_t)bits;
    return SW_OK;
}

static sw_status main_item(parser *p, int tag, uint32_t data)
{
    sw_status st = SW_OK;
    switch (tag) {
    case 0x8: /* Input */
        st = main_input(p, data);
        break;
    case 0xA: /* Collection */
        if (p->depth == DEPTH_MAX)
            return fail(p, "collections nested deeper than 16");
        p->depth++;
        if (data == 1 && !p->game_depth && is_game_usage(usage_at(p, 0))) {
            p->game_depth = p->depth;
            if (!p->out->application)
                p->out->application = (uint16_t)(usage_at(p, 0) & 0xFFFF);
        }
        break;
    case 0xC: /* End Collection */
        if (p->depth == 0)
            return fail(p, "End Collection without a Collection");
        if (p->game_depth == p->depth)
            p->game_depth = 0;
        p->depth--;
        break;
    default: /* Output, Feature: no input bits */
        break;
    }
    clear_locals(p);
    return st;
}

static sw_status global_item(parser *p, int tag, const uint8_t *d, int n)
{
    uint32_t u = item_udata(d, n);
    switch (tag) {
    case 0x0: p->g.usage_page = u; break;
    case 0x1: p->g.logical_min = item_sdata(d, n); break;
    /* The kernel's rule (hid-core.c): a maximum is unsigned unless the
     * minimum is negative; descriptors rely on it (0x25 0xFF after min 0). */
    case 0x2: p->g.logical_max = p->g.logical_min < 0 ? item_sdata(d, n) : (int32_t)u; break;
    case 0x7: p->g.report_size = u; break;
    case 0x8:
        if (u == 0 || u > 255)
            return fail(p, "Report ID 0 or above 255");
        p->g.report_id = u;
        p->out->uses_report_ids = 1;
        break;
    case 0x9: p->g.report_count = u; break;
    case 0xA:
        if (p->stack_depth == STACK_MAX)
            return fail(p, "Push deeper than 4");
        p->stack[p->stack_depth++] = p->g;
        break;
    case 0xB:
        if (p->stack_depth == 0)
            return fail(p, "Pop without Push");
        p->g = p->stack[--p->stack_depth];
        break;
    default: break; /* physical range, units: not needed to normalise */
    }
    if (p->g.report_size > 256 || p->g.report_count > 65535)
        return fail(p, "Report Size above 256 or Report Count above 65535");
    return SW_OK;
}

/* A usage of 1 or 2 bytes takes the current page; of 4 bytes it names its own. */
static uint32_t full_usage(const parser *p, uint32_t u, int n)
{
    return n == 4 ? u : (p->g.usage_page << 16) | (u & 0xFFFF);
}

static void local_item(parser *p, int tag, const uint8_t *d, int n)
{
    uint32_t u = item_udata(d, n);
    if (tag == 0x0 && p->usage_count < USAGES_MAX)
        p->usages[p->usage_count++] = full_usage(p, u, n);
    else if (tag == 0x1)
        p->usage_min = full_usage(p, u, n), p->has_min = 1;
    else if (tag == 0x2)
        p->usage_max = full_usage(p, u, n), p->has_max = 1;
}

static sw_status check_end(parser *p, size_t size)
{
    p->at = size;
    if (!p->out->application)
        return fail(p, "no Joystick, Game Pad or Multi-axis Controller application collection");
    for (int i = 0; i < p->out->field_count; i++)
        if (p->out->uses_report_ids && p->out->fields[i].report_id == 0)
            return fail(p, "an input field before the first Report ID while others have IDs");
    sw_hid_layout_number(p->out);
    return SW_OK;
}

sw_status sw_hid_desc_parse(const uint8_t *desc, size_t size, const char *name,
                            sw_hid_layout *layout, sw_error *err)
{
    static parser zero;
    parser p = zero;
    p.name = name;
    p.err = err;
    p.out = layout;
    memset(layout, 0, sizeof *layout);
    if (size > SW_HID_DESC_MAX)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: %zu bytes, more than a HID descriptor's "
                            "4096", name, size);
    size_t i = 0;
    while (i < size) {
        p.at = i;
        uint8_t prefix = desc[i];
        if (prefix == 0xFE) { /* long item: data size, tag, data (none defined) */
            if (i + 3 > size || i + 3 + desc[i + 1] > size)
                return fail(&p, "a long item past the end");
            i += 3 + (size_t)desc[i + 1];
            continue;
        }
        int n = (prefix & 3) == 3 ? 4 : prefix & 3, type = (prefix >> 2) & 3, tag = prefix >> 4;
        if (i + 1 + (size_t)n > size)
            return fail(&p, "an item whose data runs past the end");
        const uint8_t *d = desc + i + 1;
        sw_status st = SW_OK;
        if (type == TYPE_MAIN)
            st = main_item(&p, tag, item_udata(d, n));
        else if (type == TYPE_GLOBAL)
            st = global_item(&p, tag, d, n);
        else if (type == TYPE_LOCAL)
            local_item(&p, tag, d, n);
        if (st != SW_OK)
            return st;
        i += 1 + (size_t)n;
    }
    return check_end(&p, size);
}

void sw_hid_layout_number(sw_hid_layout *l)
{
    uint32_t axes = 0, buttons = 0;
    l->hat_count = 0;
    for (int i = 0; i < l->field_count; i++) {
        const sw_hid_field *f = &l->fields[i];
        if (f->kind == SW_HID_AXIS)
            axes |= 1u << f->index;
        else if (f->kind == SW_HID_BUTTON)
            buttons |= 1u << f->index;
        else if (f->kind == SW_HID_HAT && f->index + 1 > l->hat_count)
            l->hat_count = f->index + 1;
    }
    l->axis_count = l->button_count = 0;
    for (int a = 0; a < SW_HID_AXES; a++)
        if (axes & (1u << a))
            l->sdl_axis[l->axis_count++] = (uint8_t)a;
    for (int b = 0; b < SW_HID_BUTTONS_MAX; b++)
        if (buttons & (1u << b))
            l->sdl_button[l->button_count++] = (uint8_t)b;
}

void sw_hid_state_reset(sw_hid_state *s)
{
    memset(s, 0, sizeof *s);
    for (int h = 0; h < SW_HID_HATS_MAX; h++)
        s->hat[h] = -1;
}

static int64_t field_value(const sw_hid_field *f, const uint8_t *payload)
{
    uint64_t v = 0;
    for (int b = 0; b < f->bit_size; b++) {
        unsigned bit = f->bit_offset + (unsigned)b;
        v |= (uint64_t)((payload[bit >> 3] >> (bit & 7)) & 1) << b;
    }
    if (f->logical_min < 0 && f->bit_size < 64 && (v >> (f->bit_size - 1)) & 1)
        return (int64_t)v - ((int64_t)1 << f->bit_size); /* two's complement */
    return (int64_t)v;
}

/* 8 positions over the logical range, or 4 stepping by two (HID hats with
 * a maximum of 3 are the four-way kind); outside the range: centred. */
static int8_t hat_direction(const sw_hid_field *f, int64_t v)
{
    int64_t span = (int64_t)f->logical_max - f->logical_min;
    if (v < f->logical_min || v > f->logical_max)
        return -1;
    if (span == 7)
        return (int8_t)(v - f->logical_min);
    if (span == 3)
        return (int8_t)((v - f->logical_min) * 2);
    return -1;
}

static float axis_value(const sw_hid_field *f, int64_t v)
{
    double lo = f->logical_min, hi = f->logical_max;
    if (hi <= lo)
        return 0.0f;
    double x = 2.0 * ((double)v - lo) / (hi - lo) - 1.0;
    return (float)(x < -1 ? -1 : x > 1 ? 1 : x);
}

int sw_hid_decode(const sw_hid_layout *l, const uint8_t *report, size_t size, sw_hid_state *s)
{
    if (size == 0 || size > SW_HID_REPORT_MAX)
        return 0;
    unsigned id = l->uses_report_ids ? report[0] : 0;
    const uint8_t *payload = l->uses_report_ids ? report + 1 : report;
    size_t bits = (size - (l->uses_report_ids ? 1 : 0)) * 8;
    int n = 0;
    for (int i = 0; i < l->field_count; i++) {
        const sw_hid_field *f = &l->fields[i];
        if (f->report_id != id || (size_t)f->bit_offset + f->bit_size > bits)
            continue;
        int64_t v = field_value(f, payload);
        if (f->kind == SW_HID_AXIS)
            s->axis[f->index] = axis_value(f, v);
        else if (f->kind == SW_HID_HAT)
            s->hat[f->index] = hat_direction(f, v);
        else if (v != 0)
            s->buttons |= 1u << f->index;
        else
            s->buttons &= ~(1u << f->index);
        n++;
    }
    return n;
}
