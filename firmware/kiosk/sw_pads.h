/* SPDX-License-Identifier: MIT */
/* The connected game controllers: hot-plug by periodic
 * enumeration, and per controller its layout (a known one, sw_hid_known.h,
 * else its parsed descriptor), its mapping (the file's line for its GUID,
 * else the known layout's, else sw_pad_default_bindings) and its state.
 * Called by the input step (sw_kiosk.h) every frame; the caller owns the
 * struct and nothing here allocates (the backend's enumerate may, see
 * sw_input_backend.h). A controller that goes away mid-walk is closed and
 * logged; its slot waits for the next enumeration to bring it back. */
#ifndef SW_PADS_H
#define SW_PADS_H

#include <stdint.h>

#include "sw_gamepad_map.h"
#include "sw_hid_desc.h"
#include "sw_input_backend.h"

typedef struct sw_pad {
    int open;
    int handle;
    sw_hid_info info;
    sw_hid_layout layout;
    sw_pad_mapping mapping;
    sw_hid_state raw;
    sw_pad_state state;          /* mapped, dead zone applied */
    uint32_t prev_buttons;       /* state.buttons before this frame's reports */
} sw_pad;

typedef struct sw_pads {
    sw_hid_backend backend;
    const sw_pad_mapping_db *db; /* may be NULL: no mapping file */
    float dead_zone;
    int64_t enumerate_every_ns, next_enumerate_ns;
    sw_pad pads[SW_PADS_MAX];
    int plugs, unplugs, reports; /* counted for the stats and the tests */
} sw_pads;

void sw_pads_init(sw_pads *pads, sw_hid_backend backend, const sw_pad_mapping_db *db,
                  float dead_zone);

/* Enumerates when due (now_ns), opens new controllers, reads every pending
 * report, closes the ones that went away. Returns 1 if any controller's
 * mapped state changed this call (input activity), else 0. */
int sw_pads_poll(sw_pads *pads, int64_t now_ns);

void sw_pads_close(sw_pads *pads);

#endif
