/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for gamecontrollerdb files (sw_gamepad_map.h):
 * every input parses or fails with "fuzz.db:LINE: ..."; a parsed mapping
 * applied to a state keeps sticks in [-1, 1] and triggers in [0, 1]. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_gamepad_map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static sw_pad_mapping_db db;
    sw_error err = {0};
    if (sw_pad_mapping_db_parse((const char *)data, size, "fuzz.db", &db, &err) != SW_OK) {
        if (strncmp(err.message, "fuzz.db:", 8) != 0 || err.message[8] < '1' ||
            err.message[8] > '9')
            abort();
        return 0;
    }
    static sw_hid_layout l;
    l.axis_count = 6, l.button_count = 32, l.hat_count = 2;
    for (int i = 0; i < 6; i++)
        l.sdl_axis[i] = (uint8_t)i;
    for (int i = 0; i < 32; i++)
        l.sdl_button[i] = (uint8_t)i;
    sw_hid_state s = {{-1, 1, 0.5f, -0.5f, 0, 1}, {3, -1}, 0xA5A5A5A5u};
    for (int m = 0; m < db.count; m++) {
        sw_pad_state ps;
        sw_pad_apply(&db.mappings[m], &l, &s, &ps);
        sw_pad_dead_zone(&ps, 0.15f);
        for (int a = 0; a < SW_PAD_AXIS_COUNT; a++)
            if (!(ps.axis[a] >= (a >= SW_PAD_LEFTTRIGGER ? 0 : -1) && ps.axis[a] <= 1))
                abort();
        if (ps.buttons >> SW_PAD_BUTTON_COUNT)
            abort();
    }
    return 0;
}
