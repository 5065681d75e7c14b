/* SPDX-License-Identifier: MIT */
/* Input timelines: a recorded or scripted sequence of
 * device events that `seamwalk --input-timeline FILE` replays through the
 * fake devices (sw_input_fake.h) on a simulated clock, so a headless walk
 * is driven exactly as a unit's devices would drive it and replays to the
 * same camera poses every time. Parsed at start-up into caller memory.
 *
 * Format (text): '#' starts a comment to the end of the line; blank lines
 * are ignored; every other line is an event, its time in seconds from the
 * start of the walk first, times never decreasing:
 *   TIME pad SLOT plug BUS VENDOR PRODUCT VERSION DESCRIPTOR [NAME]
 *        a controller appears in slot 0..3 (hot-plug: the next periodic
 *        enumeration finds it); BUS, VENDOR, PRODUCT, VERSION in hex
 *        (0003 054c 05c4 0100); DESCRIPTOR a file of hex bytes
 *        (sw_hex_parse), relative to the timeline's directory
 *   TIME pad SLOT report HEX...      one input report, as hidapi returns it
 *        (the report ID first when the device uses IDs), up to 256 bytes
 *   TIME pad SLOT unplug             the controller goes away; its next
 *        read returns -1
 *   TIME gpio NAME LEVEL             an edge on [gpio NAME]'s line; LEVEL
 *        0 or 1 is the physical level after it; TIME is its timestamp
 *   TIME key CODE VALUE              a Linux KEY_* code (decimal), VALUE 1
 *        down, 0 up, 2 repeat
 * Errors name FILE:LINE and what was expected. */
#ifndef SW_INPUT_TIMELINE_H
#define SW_INPUT_TIMELINE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_hid_desc.h"

typedef enum sw_timeline_kind {
    SW_TL_PLUG = 1, SW_TL_REPORT, SW_TL_UNPLUG, SW_TL_GPIO, SW_TL_KEY
} sw_timeline_kind;

enum { SW_TIMELINE_NAME_MAX = 32, SW_TIMELINE_FILE_MAX = 160 };

typedef struct sw_timeline_event {
    double t_s;
    uint8_t kind;                /* sw_timeline_kind */
    uint8_t slot;                /* pad events */
    uint16_t size;               /* report bytes */
    uint16_t bus, vendor, product, version;
    int32_t code, value;         /* key; gpio level in value */
    char name[SW_TIMELINE_NAME_MAX];   /* gpio button; pad name */
    char file[SW_TIMELINE_FILE_MAX];   /* plug: the descriptor file as written */
    uint8_t bytes[SW_HID_REPORT_MAX];
} sw_timeline_event;

typedef struct sw_timeline {
    sw_timeline_event *events;   /* caller-owned */
    size_t count;
} sw_timeline;

/* An upper bound on the events in text, to size the array. */
size_t sw_timeline_count_events(const char *text, size_t size);

sw_status sw_timeline_parse(const char *text, size_t size, const char *file_name,
                            sw_timeline_event *events, size_t capacity, sw_timeline *out,
                            sw_error *err);

/* Hex bytes ("05 01 09 05", '#' comments, any whitespace; pairs of digits)
 * into out[0..cap): SW_ERR_FORMAT "FILE:LINE: ..." on anything else or
 * more than cap bytes. */
sw_status sw_hex_parse(const char *text, size_t size, const char *file_name, uint8_t *out,
                       size_t cap, size_t *count, sw_error *err);

#endif
