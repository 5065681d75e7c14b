/* SPDX-License-Identifier: MIT */
/* Known layouts (sw_hid_known.h). Bit offsets count from the byte after the
 * report ID, as sw_hid_decode reads them. */
#include "sw_hid_known.h"

#include <string.h>

typedef struct known_field {
    uint8_t kind, index;
    uint16_t bit_offset;
    uint8_t bit_size;
    int32_t logical_min, logical_max;
} known_field;

/* DualShock 4, USB report 1. Buttons in hid-playstation's evdev order:
 * cross, circle, triangle, square, L1, R1, L2, R2, share, options, PS, L3, R3;
 * axes: left x, left y, L2, right x, right y, R2. */
static const known_field ds4_usb[] = {
    {SW_HID_AXIS, 0, 0, 8, 0, 255},   {SW_HID_AXIS, 1, 8, 8, 0, 255},
    {SW_HID_AXIS, 3, 16, 8, 0, 255},  {SW_HID_AXIS, 4, 24, 8, 0, 255},
    {SW_HID_AXIS, 2, 56, 8, 0, 255},  {SW_HID_AXIS, 5, 64, 8, 0, 255},
    {SW_HID_HAT, 0, 32, 4, 0, 7},
    {SW_HID_BUTTON, 3, 36, 1, 0, 1},  {SW_HID_BUTTON, 0, 37, 1, 0, 1},
    {SW_HID_BUTTON, 1, 38, 1, 0, 1},  {SW_HID_BUTTON, 2, 39, 1, 0, 1},
    {SW_HID_BUTTON, 4, 40, 1, 0, 1},  {SW_HID_BUTTON, 5, 41, 1, 0, 1},
    {SW_HID_BUTTON, 6, 42, 1, 0, 1},  {SW_HID_BUTTON, 7, 43, 1, 0, 1},
    {SW_HID_BUTTON, 8, 44, 1, 0, 1},  {SW_HID_BUTTON, 9, 45, 1, 0, 1},
    {SW_HID_BUTTON, 11, 46, 1, 0, 1}, {SW_HID_BUTTON, 12, 47, 1, 0, 1},
    {SW_HID_BUTTON, 10, 48, 1, 0, 1},
};

static const char ds4_mapping[] =
    "a:b0,b:b1,y:b2,x:b3,leftshoulder:b4,rightshoulder:b5,back:b8,start:b9,guide:b10,"
    "leftstick:b11,rightstick:b12,dpup:h0.1,dpright:h0.2,dpdown:h0.4,dpleft:h0.8,"
    "leftx:a0,lefty:a1,lefttrigger:a2,rightx:a3,righty:a4,righttrigger:a5,";

typedef struct known_pad {
    uint16_t vendor, product;
    uint8_t report_id;
    const known_field *fields;
    int field_count;
    const char *mapping;
} known_pad;

static const known_pad known_pads[] = {
    {0x054C, 0x05C4, 1, ds4_usb, sizeof ds4_usb / sizeof ds4_usb[0], ds4_mapping},
    {0x054C, 0x09CC, 1, ds4_usb, sizeof ds4_usb / sizeof ds4_usb[0], ds4_mapping},
};

const char *sw_hid_known_layout(uint16_t vendor, uint16_t product, sw_hid_layout *layout)
{
    for (size_t k = 0; k < sizeof known_pads / sizeof known_pads[0]; k++) {
        const known_pad *kp = &known_pads[k];
        if (kp->vendor != vendor || kp->product != product)
            continue;
        memset(layout, 0, sizeof *layout);
        layout->uses_report_ids = 1;
        layout->application = 5;
        for (int i = 0; i < kp->field_count; i++) {
            const known_field *f = &kp->fields[i];
            layout->fields[i] = (sw_hid_field){f->kind, f->index, kp->report_id, f->bit_size,
                                               f->bit_offset, f->logical_min, f->logical_max};
        }
        layout->field_count = kp->field_count;
        sw_hid_layout_number(layout);
        return kp->mapping;
    }
    return NULL;
}
