/* SPDX-License-Identifier: MIT */
/* HID report descriptors of game controllers: the parser
 * that turns a descriptor (HIDIOCGRDESC or sysfs report_descriptor bytes)
 * into a layout of the fields a walk needs, and the decoder that reads an
 * input report through that layout. Called by the pad layer (sw_pad.h) when
 * a controller is plugged in (parse) and for every report it reads (decode).
 * No allocation: the layout is a fixed-size struct the caller owns.
 *
 * What is kept: inside an application collection of usage Generic Desktop
 * Joystick (4), Game Pad (5) or Multi-axis Controller (8), the variable
 * (not array, not constant) Input fields of usage X, Y, Z, Rx, Ry, Rz
 * (0x30..0x35), Hat switch (0x39) and Button 1..32, each with its report ID,
 * bit position, size and logical range. Everything else is skipped but its
 * bits are counted, so later fields land where they are.
 *
 * SDL numbering (for gamecontrollerdb lines, sw_gamepad_map.h): aN is the
 * N-th present axis in usage order X..Rz, bN the N-th present button in
 * button-number order, hN the N-th hat in descriptor order, as SDL's Linux
 * backend numbers the evdev codes the kernel's hid-input makes of them. */
#ifndef SW_HID_DESC_H
#define SW_HID_DESC_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"

enum {
    SW_HID_AXES = 6,            /* X, Y, Z, Rx, Ry, Rz */
    SW_HID_BUTTONS_MAX = 32,
    SW_HID_HATS_MAX = 2,
    SW_HID_FIELDS_MAX = 64,
    SW_HID_REPORT_MAX = 256,    /* bytes of one input report, its ID byte included */
    SW_HID_DESC_MAX = 4096,     /* HID_MAX_DESCRIPTOR_SIZE in the kernel */
};

typedef enum sw_hid_field_kind { SW_HID_AXIS = 1, SW_HID_HAT, SW_HID_BUTTON } sw_hid_field_kind;

typedef struct sw_hid_field {
    uint8_t kind;               /* sw_hid_field_kind */
    uint8_t index;              /* axis 0..5 (X..Rz), hat 0..1, button 0..31 (number - 1) */
    uint8_t report_id;          /* 0 when the descriptor uses no report IDs */
    uint8_t bit_size;           /* 1..32 */
    uint16_t bit_offset;        /* from the first byte after the report ID */
    int32_t logical_min, logical_max;
} sw_hid_field;

typedef struct sw_hid_layout {
    sw_hid_field fields[SW_HID_FIELDS_MAX];
    int field_count;
    int uses_report_ids;
    uint16_t application;       /* 4 joystick, 5 gamepad, 8 multi-axis */
    /* SDL numbering: sdl_axis[n] is the axis (0..5) SDL calls an, and so on;
     * counts say how many there are. */
    uint8_t sdl_axis[SW_HID_AXES], sdl_button[SW_HID_BUTTONS_MAX];
    int axis_count, button_count, hat_count;
} sw_hid_layout;

/* The controller's state after a report. Axes are in [-1, 1] (logical
 * minimum -> -1, maximum -> 1); a hat is -1 (centred, or a null value) or
 * 0..7 clockwise from up; bit n of buttons is button n + 1. */
typedef struct sw_hid_state {
    float axis[SW_HID_AXES];
    int8_t hat[SW_HID_HATS_MAX];
    uint32_t buttons;
} sw_hid_state;

/* Parses desc[0..size). name goes into messages: "NAME: byte 12: ...".
 * SW_ERR_FORMAT for a truncated item, a Pop without Push, an End
 * Collection without Collection, nesting deeper than 16, a Report ID of 0,
 * an input report longer than SW_HID_REPORT_MAX, more than
 * SW_HID_FIELDS_MAX kept fields, or no joystick or gamepad collection. */
sw_status sw_hid_desc_parse(const uint8_t *desc, size_t size, const char *name,
                            sw_hid_layout *layout, sw_error *err);

/* Fills the SDL numbering from the fields (the parser and the known
 * layouts, sw_hid_known.h, call it). */
void sw_hid_layout_number(sw_hid_layout *layout);

/* A centred state: axes 0, hats -1, no button. */
void sw_hid_state_reset(sw_hid_state *state);

/* Reads one input report (as hidapi returns it: with the report ID byte
 * first when the layout uses IDs) into state, changing only the fields that
 * report carries. Returns how many fields it read: 0 for a report of
 * another ID or one too short for any field. */
int sw_hid_decode(const sw_hid_layout *layout, const uint8_t *report, size_t size,
                  sw_hid_state *state);

#endif
