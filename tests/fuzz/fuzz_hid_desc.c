/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for the HID descriptor parser and report decoder
 * (sw_hid_desc.h): every input either parses into a layout whose fields fit
 * a report, or fails with a message naming the descriptor; then the same
 * bytes are decoded as a report, which must leave axes in [-1, 1]. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_hid_desc.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static sw_hid_layout l;
    sw_error err = {0};
    if (sw_hid_desc_parse(data, size, "fuzz", &l, &err) != SW_OK) {
        if (strncmp(err.message, "fuzz: ", 6) != 0)
            abort();
        return 0;
    }
    if (l.field_count > SW_HID_FIELDS_MAX || l.axis_count > SW_HID_AXES ||
        l.button_count > SW_HID_BUTTONS_MAX || l.hat_count > SW_HID_HATS_MAX)
        abort();
    for (int i = 0; i < l.field_count; i++)
        if (l.fields[i].bit_offset + l.fields[i].bit_size > (SW_HID_REPORT_MAX - 1) * 8)
            abort();
    sw_hid_state s;
    sw_hid_state_reset(&s);
    sw_hid_decode(&l, data, size < SW_HID_REPORT_MAX ? size : SW_HID_REPORT_MAX, &s);
    for (int a = 0; a < SW_HID_AXES; a++)
        if (!(s.axis[a] >= -1 && s.axis[a] <= 1))
            abort();
    for (int h = 0; h < SW_HID_HATS_MAX; h++)
        if (s.hat[h] < -1 || s.hat[h] > 7)
            abort();
    return 0;
}
