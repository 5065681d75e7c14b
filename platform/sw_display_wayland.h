/* SPDX-License-Identifier: MIT */
/* The Wayland developer window (sw_display.h "wayland"): wayland-client with
 * xdg-shell, EGL on Wayland through wayland-egl, wl_keyboard keys turned into
 * keysyms with the compositor's keymap (xkbcommon) and queued
 * (sw_key_queue.h), xdg_toplevel close honoured. Drawing is tested on
 * Weston's headless backend (tests/test_display_wayland.sh), the keymap and
 * key translation with a real keymap (tests/test_xkb_keys.c); the keyboard
 * events and the close request from a compositor are not. The struct
 * must stay where it was initialised: the listeners point at it. Swaps keep
 * EGL's default interval of 1, so while the compositor hides the window (no
 * frame callbacks) present waits: fine for a developer window. */
#ifndef SW_DISPLAY_WAYLAND_H
#define SW_DISPLAY_WAYLAND_H

#include "sw_egl_window.h"
#include "sw_error.h"
#include "sw_key_queue.h"
#include "sw_xkb_keys.h"

typedef struct sw_display_wayland {
    void *display;             /* struct wl_display * */
    void *registry, *compositor, *wm_base, *seat, *keyboard;
    void *surface, *xdg_surface, *toplevel;
    void *egl_window;          /* struct wl_egl_window * */
    sw_xkb_keys xkb;           /* the compositor's keymap */
    int configured;            /* the first xdg_surface.configure was acked */
    sw_egl_window egl;
    sw_key_queue *keys;        /* the sw_display's */
    int *close_requested;      /* the sw_display's */
} sw_display_wayland;

sw_status sw_display_wayland_init(sw_display_wayland *w, const char *title, int width,
                                  int height, sw_key_queue *keys, int *close_requested,
                                  sw_error *err);
sw_status sw_display_wayland_present(sw_display_wayland *w, sw_error *err);
void sw_display_wayland_destroy(sw_display_wayland *w);

#endif
