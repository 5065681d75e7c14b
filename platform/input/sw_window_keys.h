/* SPDX-License-Identifier: MIT */
/* A developer window's keyboard as the input step's key backend
 * (sw_input_backend.h): with --navigate on an X11 or Wayland window the
 * window's key events drive the camera; on headless and KMS the kiosk reads
 * evdev instead (sw_evdev_keys.c). */
#ifndef SW_WINDOW_KEYS_H
#define SW_WINDOW_KEYS_H

#include <stdint.h>

#include "sw_display.h"
#include "sw_input_backend.h"

/* The backend reading display's queued keys; display outlives it. */
sw_key_backend sw_window_key_backend(sw_display *display);

/* 1 when display is a window whose keys the backend can read. */
int sw_window_has_keyboard(const sw_display *display);

/* The Linux KEY_* code of an X11/XKB keysym, or -1 for one without. */
int sw_window_keysym_code(uint32_t keysym);

#endif
