/* SPDX-License-Identifier: MIT */
/* Gamepad mappings in SDL's gamecontrollerdb grammar, so
 * lines written for SDL paste into [gamepad] mapping = FILE unchanged:
 *
 *   GUID,name,binding,binding,...      one controller per line
 *   binding = OUTPUT:INPUT
 *   OUTPUT  = a b x y back guide start leftstick rightstick leftshoulder
 *             rightshoulder dpup dpdown dpleft dpright leftx lefty rightx
 *             righty lefttrigger righttrigger, an axis optionally with a
 *             '+' or '-' prefix (that half of it); misc1, paddle1..4 and
 *             touchpad are accepted and ignored
 *   INPUT   = bN (button N) | aN (axis N) with an optional '+'/'-' prefix
 *             (half of it) and '~' suffix (inverted) | hN.M (hat N, mask M:
 *             1 up, 2 right, 4 down, 8 left)
 *   platform:NAME, crc:XXXX, hint:..., sdk>=:..., sdk<=:... are read and
 *   only platform is used: lines for another platform than Linux are
 *   checked and skipped. '#' starts a comment line; blank lines are fine.
 *
 * The GUID is SDL 2's for a Linux joystick: 16 bytes, little-endian 16-bit
 * words bus, CRC of the name (0 in older lines), vendor, 0, product, 0,
 * version, 0; written as 32 hex digits. Matching ignores the CRC, and falls
 * back to ignoring the version, as SDL does. Numbering of bN, aN and hN:
 * sw_hid_desc.h. Called at start-up (parsing, into caller memory) and per
 * report (sw_pad_apply, no allocation). */
#ifndef SW_GAMEPAD_MAP_H
#define SW_GAMEPAD_MAP_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_hid_desc.h"

typedef enum sw_pad_button {
    SW_PAD_A, SW_PAD_B, SW_PAD_X, SW_PAD_Y, SW_PAD_BACK, SW_PAD_GUIDE, SW_PAD_START,
    SW_PAD_LEFTSTICK, SW_PAD_RIGHTSTICK, SW_PAD_LEFTSHOULDER, SW_PAD_RIGHTSHOULDER,
    SW_PAD_DPUP, SW_PAD_DPDOWN, SW_PAD_DPLEFT, SW_PAD_DPRIGHT, SW_PAD_BUTTON_COUNT
} sw_pad_button;

typedef enum sw_pad_axis {
    SW_PAD_LEFTX, SW_PAD_LEFTY, SW_PAD_RIGHTX, SW_PAD_RIGHTY, SW_PAD_LEFTTRIGGER,
    SW_PAD_RIGHTTRIGGER, SW_PAD_AXIS_COUNT
} sw_pad_axis;

enum { SW_PAD_BINDINGS_MAX = 48, SW_PAD_MAPPINGS_MAX = 128, SW_PAD_NAME_MAX = 64 };

/* A controller's state in gamepad terms: sticks in [-1, 1] (y down
 * positive, as SDL), triggers in [0, 1]; bit n of buttons is sw_pad_button n. */
typedef struct sw_pad_state {
    float axis[SW_PAD_AXIS_COUNT];
    uint32_t buttons;
} sw_pad_state;

typedef struct sw_pad_binding {
    uint8_t in_kind;      /* 1 button, 2 axis, 3 hat */
    uint8_t in_index;
    uint8_t in_hat_mask;
    int8_t in_half;       /* 0 whole axis, 1 its + half, -1 its - half */
    uint8_t in_invert;
    uint8_t out_kind;     /* 1 button, 2 axis */
    uint8_t out_index;
    int8_t out_half;
} sw_pad_binding;

typedef struct sw_pad_mapping {
    uint8_t guid[16];
    char name[SW_PAD_NAME_MAX];
    sw_pad_binding bindings[SW_PAD_BINDINGS_MAX];
    int binding_count;
    long line;            /* in its file, for messages */
} sw_pad_mapping;

typedef struct sw_pad_mapping_db {
    sw_pad_mapping mappings[SW_PAD_MAPPINGS_MAX];
    int count;
} sw_pad_mapping_db;

/* SDL's GUID for a Linux joystick (CRC 0). */
void sw_pad_guid(uint16_t bus, uint16_t vendor, uint16_t product, uint16_t version,
                 uint8_t guid[16]);

/* Parses the bindings "a:b0,leftx:a0,..." (the part after GUID,name,) of
 * one mapping; file and line name messages. */
sw_status sw_pad_mapping_parse_bindings(const char *text, size_t size, const char *file,
                                        long line, sw_pad_mapping *out, sw_error *err);

/* Parses a whole file of lines into db (Linux and platform-less lines kept).
 * SW_ERR_FORMAT "FILE:LINE: what was expected, got what" at the first bad
 * line; more than SW_PAD_MAPPINGS_MAX kept lines is an error too. */
sw_status sw_pad_mapping_db_parse(const char *text, size_t size, const char *file,
                                  sw_pad_mapping_db *db, sw_error *err);

/* Reads and parses a file of at most 1 MiB (start-up only: it mallocs). */
sw_status sw_pad_mapping_db_load(const char *path, sw_pad_mapping_db *db, sw_error *err);

/* The mapping for guid: exact but for the CRC, then ignoring the version
 * too; NULL when none. */
const sw_pad_mapping *sw_pad_mapping_find(const sw_pad_mapping_db *db, const uint8_t guid[16]);

/* The mapping used when neither the file nor a known layout has one: a0/a1
 * left stick, a2/a3 right stick, b0..b7 a b x y leftshoulder rightshoulder
 * back start, h0 the d-pad (what generic DirectInput pads such as a
 * Logitech F310 in D mode report). */
const char *sw_pad_default_bindings(void);

/* The controller's raw state through a mapping; no dead zone. */
void sw_pad_apply(const sw_pad_mapping *m, const sw_hid_layout *layout,
                  const sw_hid_state *raw, sw_pad_state *out);

/* A radial dead zone on each stick: |v| < dead_zone gives 0, and the rest
 * is rescaled so the stick still reaches 1 at full deflection (and the
 * output is continuous at the zone's edge). */
void sw_pad_dead_zone(sw_pad_state *s, float dead_zone);

#endif
