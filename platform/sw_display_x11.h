/* SPDX-License-Identifier: MIT */
/* The X11 developer window (sw_display.h "x11"): Xlib, EGL on X11
 * (EGL_KHR/EXT_platform_x11), a fixed-size window with the EGL config's
 * visual, key events queued (sw_key_queue.h) and the window manager's close
 * button honoured. Tested under Xvfb with Mesa's llvmpipe
 * (tests/test_display_x11.sh). */
#ifndef SW_DISPLAY_X11_H
#define SW_DISPLAY_X11_H

#include "sw_egl_window.h"
#include "sw_error.h"
#include "sw_key_queue.h"

typedef struct sw_display_x11 {
    void *xdisplay;            /* Display * */
    unsigned long window;      /* Window; 0: none */
    unsigned long colormap;    /* Colormap; 0: none */
    unsigned long wm_delete;   /* Atom WM_DELETE_WINDOW */
    sw_egl_window egl;
    sw_key_queue *keys;        /* the sw_display's */
    int *close_requested;      /* the sw_display's */
} sw_display_x11;

sw_status sw_display_x11_init(sw_display_x11 *x, const char *title, int width, int height,
                              sw_key_queue *keys, int *close_requested, sw_error *err);
sw_status sw_display_x11_present(sw_display_x11 *x, sw_error *err);
void sw_display_x11_destroy(sw_display_x11 *x);

#endif
