/* SPDX-License-Identifier: MIT */
/* EGL on a window-system surface, shared by the KMS (GBM), X11 and Wayland
 * displays (sw_display_*.c): a platform display from EGL_EXT_platform_base,
 * a GLES2 config with a window bit and depth, a window surface, a context
 * made current. Two steps because X11 must create its window with the
 * config's visual (and GBM its surface with the config's format) between
 * them. The default framebuffer is drawn into; read back with
 * sw_egl_window_read_rgba before the swap. GL thread only. */
#ifndef SW_EGL_WINDOW_H
#define SW_EGL_WINDOW_H

#include <stdint.h>

#include "sw_error.h"

typedef struct sw_egl_window {
    void *display;      /* EGLDisplay */
    void *config;       /* EGLConfig */
    void *context;      /* EGLContext */
    void *surface;      /* EGLSurface */
    int visual_id;      /* the config's EGL_NATIVE_VISUAL_ID */
    const char *who;    /* "kms display" ...: starts every message */
} sw_egl_window;

/* Opens the EGL display of platform (EGL_PLATFORM_GBM_KHR, _X11_KHR,
 * _WAYLAND_KHR) on native_display, which the client extensions must offer
 * as khr_ext or ext_ext (say which in the error otherwise), and picks a
 * GLES2 window config; with want_visual non-zero only one of that native
 * visual (GBM: the surface's fourcc). Cleans up on failure. */
sw_status sw_egl_window_open(sw_egl_window *w, const char *who, unsigned platform,
                             const char *khr_ext, const char *ext_ext, void *native_display,
                             int want_visual, sw_error *err);

/* The surface on native_window (for X11 a pointer to the Window id, as
 * EGL_EXT_platform_x11 wants) and a GLES2 context, made current. */
sw_status sw_egl_window_attach(sw_egl_window *w, void *native_window, sw_error *err);

sw_status sw_egl_window_swap(sw_egl_window *w, sw_error *err);

/* The back buffer (width x height) into rgba, top row first. */
sw_status sw_egl_window_read_rgba(const sw_egl_window *w, int width, int height, uint8_t *rgba,
                                  sw_error *err);

void sw_egl_window_destroy(sw_egl_window *w);

/* Whole-word search in an extension string. */
int sw_egl_has_extension(const char *list, const char *name);

#endif
