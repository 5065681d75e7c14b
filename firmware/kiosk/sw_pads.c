/* SPDX-License-Identifier: MIT */
/* Connected controllers (sw_pads.h). */
#include "sw_pads.h"

#include <stdio.h>
#include <string.h>

#include "sw_error.h"
#include "sw_hid_known.h"

void sw_pads_init(sw_pads *p, sw_hid_backend backend, const sw_pad_mapping_db *db,
                  float dead_zone)
{
    memset(p, 0, sizeof *p);
    p->backend = backend;
    p->db = db;
    p->dead_zone = dead_zone;
    p->enumerate_every_ns = 1000000000; /* a second: plugging in feels immediate enough */
}

static sw_pad *pad_with_path(sw_pads *p, const char *path)
{
    for (int i = 0; i < SW_PADS_MAX; i++)
        if (p->pads[i].open && !strcmp(p->pads[i].info.path, path))
            return &p->pads[i];
    return NULL;
}

/* Layout and mapping for a newly opened controller. */
static sw_status describe(sw_pads *p, sw_pad *pad, const uint8_t *desc, size_t size,
                          sw_error *err)
{
    const sw_hid_info *in = &pad->info;
    const char *bindings = sw_hid_known_layout(in->vendor, in->product, &pad->layout);
    if (!bindings) {
        sw_status st = sw_hid_desc_parse(desc, size, in->path, &pad->layout, err);
        if (st != SW_OK)
            return st;
        bindings = sw_pad_default_bindings();
    }
    uint8_t guid[16];
    sw_pad_guid(in->bus, in->vendor, in->product, in->version, guid);
    const sw_pad_mapping *m = p->db ? sw_pad_mapping_find(p->db, guid) : NULL;
    if (m) {
        pad->mapping = *m;
        return SW_OK;
    }
    memcpy(pad->mapping.guid, guid, 16);
    return sw_pad_mapping_parse_bindings(bindings, strlen(bindings), "built-in", 1,
                                         &pad->mapping, err);
}

static void plug(sw_pads *p, const sw_hid_info *info)
{
    sw_pad *pad = NULL;
    for (int i = 0; i < SW_PADS_MAX && !pad; i++)
        if (!p->pads[i].open)
            pad = &p->pads[i];
    if (!pad)
        return; /* four at once is plenty for one screen */
    static uint8_t desc[SW_HID_DESC_MAX]; /* the GL thread's only: one open at a time */
    size_t size = 0;
    sw_error err = {0};
    memset(pad, 0, sizeof *pad);
    pad->info = *info;
    pad->handle = p->backend.open(p->backend.ctx, info, desc, sizeof desc, &size, &err);
    if (pad->handle < 0) {
        fprintf(stderr, "seamwalk: gamepad %s: %s\n", info->path, err.message);
        return;
    }
    if (describe(p, pad, desc, size, &err) != SW_OK) {
        fprintf(stderr, "seamwalk: gamepad %s (%04x:%04x) not used: %s\n", info->path,
                info->vendor, info->product, err.message);
        p->backend.close(p->backend.ctx, pad->handle);
        return;
    }
    sw_hid_state_reset(&pad->raw);
    pad->open = 1;
    p->plugs++;
    /* The name is the device's own (its USB product string): whatever
     * control bytes it holds reach the log as \xNN, not the terminal. */
    fprintf(stderr, "seamwalk: gamepad %s (%04x:%04x ", info->path, info->vendor, info->product);
    sw_fput_escaped(stderr, info->name, sizeof info->name);
    fprintf(stderr, "): %d axes, %d buttons, %d hats\n", pad->layout.axis_count,
            pad->layout.button_count, pad->layout.hat_count);
}

static void unplug(sw_pads *p, sw_pad *pad)
{
    fprintf(stderr, "seamwalk: gamepad %s unplugged\n", pad->info.path);
    p->backend.close(p->backend.ctx, pad->handle);
    pad->open = 0;
    p->unplugs++;
}

static void enumerate(sw_pads *p)
{
    sw_hid_info found[8];
    int n = p->backend.enumerate(p->backend.ctx, found, 8);
    for (int i = 0; i < n; i++)
        if (!pad_with_path(p, found[i].path))
            plug(p, &found[i]);
}

/* Every pending report; 1 if the mapped state changed. */
static int read_pad(sw_pads *p, sw_pad *pad)
{
    uint8_t buf[SW_HID_REPORT_MAX];
    sw_pad_state before = pad->state;
    pad->prev_buttons = pad->state.buttons;
    for (int guard = 0; guard < 64; guard++) { /* a flood must not stall the frame */
        int n = p->backend.read(p->backend.ctx, pad->handle, buf, sizeof buf);
        if (n < 0) {
            unplug(p, pad);
            memset(&pad->state, 0, sizeof pad->state);
            return 0; /* the sticks let go, but nobody touched anything */
        }
        if (n == 0)
            break;
        sw_hid_decode(&pad->layout, buf, (size_t)n, &pad->raw);
        p->reports++;
    }
    sw_pad_apply(&pad->mapping, &pad->layout, &pad->raw, &pad->state);
    sw_pad_dead_zone(&pad->state, p->dead_zone);
    return memcmp(&before, &pad->state, sizeof before) != 0;
}

int sw_pads_poll(sw_pads *p, int64_t now_ns)
{
    if (now_ns >= p->next_enumerate_ns) {
        enumerate(p);
        p->next_enumerate_ns = now_ns + p->enumerate_every_ns;
    }
    int changed = 0;
    for (int i = 0; i < SW_PADS_MAX; i++)
        if (p->pads[i].open)
            changed |= read_pad(p, &p->pads[i]);
    return changed;
}

void sw_pads_close(sw_pads *p)
{
    for (int i = 0; i < SW_PADS_MAX; i++)
        if (p->pads[i].open) {
            p->backend.close(p->backend.ctx, p->pads[i].handle);
            p->pads[i].open = 0;
        }
}
