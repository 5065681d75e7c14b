/* SPDX-License-Identifier: MIT */
/* Fake devices behind the device layer's interface (sw_input_backend.h):
 * what tests and `seamwalk --input-timeline` drive instead of hidapi,
 * libgpiod and evdev. A fake controller slot holds a recorded descriptor and
 * a queue of reports; the enumerator lists the slots plugged now (so
 * hot-plug is a slot appearing between two enumerations), and a read after
 * unplug returns -1 as hidapi's does. Fake GPIO lines are matched to
 * [gpio NAME] sections by name and queue edges with timestamps; a button
 * on a chip named "missing" fails to open, like an absent chip. Fixed
 * sizes, no allocation. */
#ifndef SW_INPUT_FAKE_H
#define SW_INPUT_FAKE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_input_backend.h"
#include "sw_input_timeline.h"

enum { SW_FAKE_QUEUE = 64, SW_FAKE_LINES = 16 };

typedef struct sw_fake_pad {
    int plugged, opened, gone;    /* gone: unplugged while open */
    sw_hid_info info;
    uint8_t desc[SW_HID_DESC_MAX];
    size_t desc_size;
    uint8_t reports[SW_FAKE_QUEUE][SW_HID_REPORT_MAX];
    uint16_t sizes[SW_FAKE_QUEUE];
    int head, count;
} sw_fake_pad;

typedef struct sw_fake_line {
    char name[SW_GPIO_NAME_MAX];
    int high;
    sw_gpio_edge edges[SW_FAKE_QUEUE];
    int head, count;
} sw_fake_line;

typedef struct sw_fake_devices {
    sw_fake_pad pads[SW_PADS_MAX];
    sw_fake_line lines[SW_FAKE_LINES];
    int line_count;
    struct { int code, value; } keys[SW_FAKE_QUEUE];
    int key_head, key_count;
    int64_t now_ns;               /* edges later than this are not read yet, as on a line */
    int enumerations;             /* how often the enumerator ran */
    int dropped;                  /* events that found a full queue */
} sw_fake_devices;

void sw_fake_init(sw_fake_devices *f);

sw_hid_backend sw_fake_hid_backend(sw_fake_devices *f);
sw_gpio_backend sw_fake_gpio_backend(sw_fake_devices *f);
sw_key_backend sw_fake_key_backend(sw_fake_devices *f);

/* Scripting. plug copies desc; report and edge queue (dropped when full). */
void sw_fake_plug(sw_fake_devices *f, int slot, const sw_hid_info *info, const uint8_t *desc,
                  size_t size);
void sw_fake_unplug(sw_fake_devices *f, int slot);
void sw_fake_report(sw_fake_devices *f, int slot, const uint8_t *bytes, size_t size);
void sw_fake_edge(sw_fake_devices *f, const char *line_name, int64_t t_ns, int high);
void sw_fake_key(sw_fake_devices *f, int code, int value);

/* A timeline being played into fake devices: events up to a time. */
typedef struct sw_fake_player {
    const sw_timeline *timeline;
    const uint8_t *const *descs;  /* descs[i], sizes[i]: event i's descriptor (plugs only) */
    const size_t *desc_sizes;
    size_t next;
} sw_fake_player;

/* Feeds every event with t_s <= now_s and sets f->now_ns. */
void sw_fake_play(sw_fake_player *p, sw_fake_devices *f, double now_s);

#endif
