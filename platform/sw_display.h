/* SPDX-License-Identifier: MIT */
/* The display seamwalk draws into, behind one small interface so the GLES2
 * code never knows which:
 *   headless  EGL surfaceless, an offscreen framebuffer (CI; sw_egl_headless.h)
 *   kms       GBM/KMS scan-out on a kiosk without X or Wayland (sw_display_kms.c)
 *   x11       a developer window through EGL on X11 (sw_display_x11.c)
 *   wayland   a developer window through EGL on Wayland (sw_display_wayland.c)
 * "auto" picks from what EGL offers and what this machine has
 * (sw_display_choose). seamwalk calls init, then per frame draw, read back
 * (only for --png-dir), present, and destroy at exit. Windows queue their
 * key events for the input step (sw_display_poll_keys). One struct, owned by
 * the caller, no allocation in our code; GL thread only. */
#ifndef SW_DISPLAY_H
#define SW_DISPLAY_H

#include <stddef.h>
#include <stdint.h>

#include "sw_display_kms.h"
#include "sw_display_wayland.h"
#include "sw_display_x11.h"
#include "sw_egl_headless.h"
#include "sw_error.h"
#include "sw_key_queue.h"

typedef enum sw_display_kind {
    SW_DISPLAY_KIND_AUTO = 0,
    SW_DISPLAY_KIND_HEADLESS,
    SW_DISPLAY_KIND_KMS,
    SW_DISPLAY_KIND_X11,
    SW_DISPLAY_KIND_WAYLAND,
} sw_display_kind;

/* Zero means default. width, height: the headless framebuffer's size
 * (required there), a window's size (default 1280x720), the KMS mode wanted
 * (0: the connector's preferred mode, else its largest). */
typedef struct sw_display_desc {
    sw_display_kind kind;
    int width, height;
    const char *title;        /* window title; default "seamwalk" */
    const char *drm_device;   /* kms: NULL tries /dev/dri/card0..card15 in turn */
    int max_depth_bits;       /* headless: 16 or 24 (0: 24; 24 where GL_OES_depth24 is
                                 offered); windows and kms take 24 where the EGL offers it */
} sw_display_desc;

typedef struct sw_display {
    sw_display_kind kind;     /* the one running, never AUTO after init */
    int width, height;        /* what is drawn: the framebuffer, window or mode */
    char chosen_why[160];     /* why this kind ("--display kms", "auto: ...") */
    sw_key_queue keys;        /* filled by the window displays as they pump events */
    int close_requested;      /* the window was closed (X11 WM_DELETE_WINDOW, xdg close),
                                 or SIGINT/SIGTERM came (sw_display_close_on_signal) */
    int up;
    union {
        sw_egl_headless headless;
        sw_display_kms kms;
        sw_display_x11 x11;
        sw_display_wayland wayland;
    } u;
} sw_display;

/* What sw_display_choose looks at, filled by sw_display_probe from the
 * running system; tests build it by hand. */
typedef struct sw_display_env {
    const char *client_extensions;  /* eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS); NULL: none */
    int wayland_display_set;        /* WAYLAND_DISPLAY is set and not empty */
    int x_display_set;              /* DISPLAY is set and not empty */
    int drm_card_present;           /* some /dev/dri/card* exists */
} sw_display_env;

void sw_display_probe(sw_display_env *env);

/* auto's rule, in order: Wayland when WAYLAND_DISPLAY is set and EGL offers
 * EGL_KHR/EXT_platform_wayland; X11 when DISPLAY is set and it offers
 * EGL_KHR/EXT_platform_x11; KMS when a /dev/dri/card* exists and it offers
 * EGL_KHR/MESA_platform_gbm; each only if this build has it
 * (sw_display_kind_check_built); else headless (EGL_MESA_platform_surfaceless;
 * its init says so if even that is missing). A session's window wins over
 * the bare device, which a compositor holds anyway. why gets one line. */
sw_display_kind sw_display_choose(const sw_display_env *env, char *why, size_t why_size);

/* "auto", "headless", "kms", "x11", "wayland" */
const char *sw_display_kind_name(sw_display_kind kind);
/* SW_ERR_ARG naming the word and the choices for anything else. */
sw_status sw_display_kind_parse(const char *name, sw_display_kind *kind, sw_error *err);

/* SW_OK when this build has the display (auto and headless it always has);
 * else SW_ERR_ARG "built without X11 (SW_WITH_X11=OFF)". The build leaves
 * out KMS, X11 or Wayland with the CMake options SW_WITH_KMS, SW_WITH_X11
 * and SW_WITH_WAYLAND (SW_HAVE_* in the code), and auto never picks one it
 * lacks. */
sw_status sw_display_kind_check_built(sw_display_kind kind, sw_error *err);

/* Opens the display, makes its GLES2 context current with the default (or
 * headless: the offscreen) framebuffer bound. On failure cleans up and err
 * has one line saying which display, what failed and what to do. */
sw_status sw_display_init(sw_display *d, const sw_display_desc *desc, sw_error *err);

/* Shows the frame drawn since the last present: headless nothing; a window
 * swaps and pumps its events (keys, close); KMS swaps, flips and waits for
 * the flip. */
sw_status sw_display_present(sw_display *d, sw_error *err);

/* The depth bits of what is drawn into, as the GL reports them (GL thread,
 * after init). */
int sw_display_depth_bits(const sw_display *d);

/* The frame drawn, before present, into rgba (width * height * 4 bytes), top
 * row first, alpha 255. */
sw_status sw_display_read_rgba(sw_display *d, uint8_t *rgba, sw_error *err);

/* Moves up to capacity queued key events into out, oldest first; returns how
 * many. Events arrive as sw_display_present pumps the window system, so an
 * input step calls this after present. Headless and KMS have no window and
 * return 0 (the kiosk's keyboard is evdev, read by the input layer;
 * platform/input/sw_window_keys.h hands a window's keys to the same input step). */
int sw_display_poll_keys(sw_display *d, sw_key_event *out, int capacity);

void sw_display_destroy(sw_display *d);

/* A signal handler (async-signal-safe) for SIGINT and SIGTERM: the next
 * sw_display_present sets close_requested, so the walk ends as after a
 * closed window and the display is destroyed normally (for KMS: the CRTC
 * restored, master dropped) instead of the process dying mid-flip. */
void sw_display_close_on_signal(int signum);

#endif
