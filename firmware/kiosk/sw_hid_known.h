/* SPDX-License-Identifier: MIT */
/* Known controller layouts: controllers whose descriptor
 * does not say what a walk needs. The DualShock 4 over USB describes its
 * triggers as Rx/Ry and its right stick as Z/Rz, and Linux's hid-playstation
 * driver (what SDL's Linux mappings were written against) orders them
 * differently again; its USB report 1 is 64 bytes with the sticks in bytes
 * 1-4, the hat and face buttons in byte 5, shoulders, share, options and
 * the stick clicks in byte 6, PS in byte 7 and the analog triggers in bytes
 * 8 and 9 (the layout hid-playstation.c reads as dualshock4_input_report_usb).
 * The known layout numbers axes and buttons as hid-playstation's evdev
 * device does, and comes with a built-in gamecontrollerdb line, so pasted
 * Linux mappings for it work unchanged. Called by the pad layer at plug. */
#ifndef SW_HID_KNOWN_H
#define SW_HID_KNOWN_H

#include <stdint.h>

#include "sw_hid_desc.h"

/* Fills layout and returns the built-in mapping (the part after
 * "GUID,name,") when vendor:product is a known controller; NULL otherwise. */
const char *sw_hid_known_layout(uint16_t vendor, uint16_t product, sw_hid_layout *layout);

#endif
