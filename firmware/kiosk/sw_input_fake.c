/* SPDX-License-Identifier: MIT */
/* Fake devices (sw_input_fake.h). */
#include "sw_input_fake.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void sw_fake_init(sw_fake_devices *f) { memset(f, 0, sizeof *f); }

/* ---- gamepads ---------------------------------------------------------------- */

static int fake_enumerate(void *ctx, sw_hid_info *out, int max)
{
    sw_fake_devices *f = ctx;
    int n = 0;
    f->enumerations++;
    for (int i = 0; i < SW_PADS_MAX && n < max; i++)
        if (f->pads[i].plugged)
            out[n++] = f->pads[i].info;
    return n;
}

static int slot_of(sw_fake_devices *f, const char *path)
{
    for (int i = 0; i < SW_PADS_MAX; i++)
        if (f->pads[i].plugged && !strcmp(f->pads[i].info.path, path))
            return i;
    return -1;
}

static int fake_open(void *ctx, const sw_hid_info *info, uint8_t *desc, size_t cap,
                     size_t *size, sw_error *err)
{
    sw_fake_devices *f = ctx;
    int s = slot_of(f, info->path);
    if (s < 0) {
        sw_error_set(err, SW_ERR_IO, "%s: no such device", info->path);
        return -1;
    }
    sw_fake_pad *p = &f->pads[s];
    if (p->desc_size > cap) {
        sw_error_set(err, SW_ERR_FORMAT, "%s: descriptor larger than %zu bytes", info->path, cap);
        return -1;
    }
    memcpy(desc, p->desc, p->desc_size);
    *size = p->desc_size;
    p->opened = 1;
    p->gone = 0;
    return s;
}

static int fake_read(void *ctx, int handle, uint8_t *buf, size_t cap)
{
    sw_fake_pad *p = &((sw_fake_devices *)ctx)->pads[handle];
    if (p->gone || !p->plugged)
        return -1;
    if (p->count == 0)
        return 0;
    size_t n = p->sizes[p->head];
    n = n < cap ? n : cap;
    memcpy(buf, p->reports[p->head], n);
    p->head = (p->head + 1) % SW_FAKE_QUEUE;
    p->count--;
    return (int)n;
}

static void fake_close(void *ctx, int handle)
{
    sw_fake_pad *p = &((sw_fake_devices *)ctx)->pads[handle];
    p->opened = 0;
    p->gone = 0;
}

sw_hid_backend sw_fake_hid_backend(sw_fake_devices *f)
{
    return (sw_hid_backend){f, fake_enumerate, fake_open, fake_read, fake_close};
}

void sw_fake_plug(sw_fake_devices *f, int slot, const sw_hid_info *info, const uint8_t *desc,
                  size_t size)
{
    sw_fake_pad *p = &f->pads[slot];
    memset(p, 0, sizeof *p);
    p->info = *info;
    snprintf(p->info.path, sizeof p->info.path, "/dev/hidraw-fake%d", slot);
    p->desc_size = size < sizeof p->desc ? size : sizeof p->desc;
    memcpy(p->desc, desc, p->desc_size);
    p->plugged = 1;
}

void sw_fake_unplug(sw_fake_devices *f, int slot)
{
    sw_fake_pad *p = &f->pads[slot];
    p->gone = p->opened;
    p->plugged = 0;
    p->count = 0;
}

void sw_fake_report(sw_fake_devices *f, int slot, const uint8_t *bytes, size_t size)
{
    sw_fake_pad *p = &f->pads[slot];
    if (!p->plugged || p->count == SW_FAKE_QUEUE || size > SW_HID_REPORT_MAX) {
        f->dropped++;
        return;
    }
    int at = (p->head + p->count) % SW_FAKE_QUEUE;
    memcpy(p->reports[at], bytes, size);
    p->sizes[at] = (uint16_t)size;
    p->count++;
}

/* ---- GPIO -------------------------------------------------------------------- */

static sw_fake_line *line_named(sw_fake_devices *f, const char *name, int create)
{
    for (int i = 0; i < f->line_count; i++)
        if (!strcmp(f->lines[i].name, name))
            return &f->lines[i];
    if (!create || f->line_count == SW_FAKE_LINES)
        return NULL;
    sw_fake_line *l = &f->lines[f->line_count++];
    memset(l, 0, sizeof *l);
    snprintf(l->name, sizeof l->name, "%s", name);
    return l;
}

static int gpio_open(void *ctx, const sw_gpio_line *g, int *high, sw_error *err)
{
    sw_fake_devices *f = ctx;
    if (!strcmp(g->chip, "missing")) {
        sw_error_set(err, SW_ERR_IO, "%s: no such GPIO chip", g->chip);
        return -1;
    }
    sw_fake_line *l = line_named(f, g->name, 1);
    if (!l) {
        sw_error_set(err, SW_ERR_IO, "more than %d fake lines", SW_FAKE_LINES);
        return -1;
    }
    /* Released at rest: low for active-high buttons, high for active-low. */
    l->high = g->active_low;
    *high = l->high;
    return (int)(l - f->lines);
}

static int gpio_read(void *ctx, int handle, sw_gpio_edge *edge)
{
    sw_fake_devices *f = ctx;
    sw_fake_line *l = &f->lines[handle];
    if (l->count == 0 || l->edges[l->head].t_ns > f->now_ns)
        return 0;
    *edge = l->edges[l->head];
    l->head = (l->head + 1) % SW_FAKE_QUEUE;
    l->count--;
    return 1;
}

static void gpio_close(void *ctx, int handle) { (void)ctx, (void)handle; }

sw_gpio_backend sw_fake_gpio_backend(sw_fake_devices *f)
{
    return (sw_gpio_backend){f, gpio_open, gpio_read, gpio_close};
}

void sw_fake_edge(sw_fake_devices *f, const char *line_name, int64_t t_ns, int high)
{
    sw_fake_line *l = line_named(f, line_name, 0);
    if (!l || l->count == SW_FAKE_QUEUE) {
        f->dropped++;
        return;
    }
    l->edges[(l->head + l->count) % SW_FAKE_QUEUE] = (sw_gpio_edge){t_ns, high};
    l->count++;
    l->high = high;
}

/* ---- keys -------------------------------------------------------------------- */

static int key_open(void *ctx, const char *device, sw_error *err)
{
    (void)ctx, (void)device, (void)err;
    return 0;
}

static int key_read(void *ctx, int *code, int *value)
{
    sw_fake_devices *f = ctx;
    if (f->key_count == 0)
        return 0;
    *code = f->keys[f->key_head].code;
    *value = f->keys[f->key_head].value;
    f->key_head = (f->key_head + 1) % SW_FAKE_QUEUE;
    f->key_count--;
    return 1;
}

static void key_close(void *ctx) { (void)ctx; }

sw_key_backend sw_fake_key_backend(sw_fake_devices *f)
{
    return (sw_key_backend){f, key_open, key_read, key_close};
}

void sw_fake_key(sw_fake_devices *f, int code, int value)
{
    if (f->key_count == SW_FAKE_QUEUE) {
        f->dropped++;
        return;
    }
    int at = (f->key_head + f->key_count) % SW_FAKE_QUEUE;
    f->keys[at].code = code;
    f->keys[at].value = value;
    f->key_count++;
}

/* ---- timeline ---------------------------------------------------------------- */

static void play_one(const sw_fake_player *p, sw_fake_devices *f, size_t i)
{
    const sw_timeline_event *e = &p->timeline->events[i];
    switch (e->kind) {
    case SW_TL_PLUG: {
        sw_hid_info info = {.bus = e->bus, .vendor = e->vendor, .product = e->product,
                            .version = e->version};
        snprintf(info.name, sizeof info.name, "%s", e->name[0] ? e->name : "timeline pad");
        sw_fake_plug(f, e->slot, &info, p->descs[i], p->desc_sizes[i]);
        break;
    }
    case SW_TL_REPORT: sw_fake_report(f, e->slot, e->bytes, e->size); break;
    case SW_TL_UNPLUG: sw_fake_unplug(f, e->slot); break;
    case SW_TL_GPIO:
        sw_fake_edge(f, e->name, (int64_t)llround(e->t_s * 1e9), e->value);
        break;
    case SW_TL_KEY: sw_fake_key(f, e->code, e->value); break;
    default: break;
    }
}

void sw_fake_play(sw_fake_player *p, sw_fake_devices *f, double now_s)
{
    f->now_ns = (int64_t)llround(now_s * 1e9);
    while (p->next < p->timeline->count && p->timeline->events[p->next].t_s <= now_s)
        play_one(p, f, p->next++);
}
