/* SPDX-License-Identifier: MIT */
/* sw_display.h: one switch per call onto the display that runs. Headless is
 * the existing sw_egl_headless, unchanged. A display the build was made
 * without (SW_HAVE_KMS, SW_HAVE_X11, SW_HAVE_WAYLAND 0) has no case: init
 * refuses it, so no other call meets it. */
#include "sw_display.h"

#include <GLES2/gl2.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

/* Written by the signal handler, read by present on the GL thread. */
static volatile sig_atomic_t close_signal;

void sw_display_close_on_signal(int signum)
{
    (void)signum;
    close_signal = 1;
}

static sw_status init_kind(sw_display *d, const sw_display_desc *desc, sw_error *err)
{
    const char *title = desc->title ? desc->title : "seamwalk";
    int w = desc->width, h = desc->height;
    sw_status st = sw_display_kind_check_built(d->kind, err);
    if (st != SW_OK)
        return st;
    (void)title;   /* only the windows use it, and a build may have neither */
    switch (d->kind) {
    case SW_DISPLAY_KIND_HEADLESS:
        if (w < 1 || h < 1)
            return sw_error_set(err, SW_ERR_ARG, "headless display (%s) needs a size: "
                                "--headless WxH, --size WxH or [display] size", d->chosen_why);
        d->width = w;
        d->height = h;
        return sw_egl_headless_init_depth(&d->u.headless, SW_GL_API_GLES2, w, h,
                                          desc->max_depth_bits ? desc->max_depth_bits : 24, err);
#if SW_HAVE_KMS
    case SW_DISPLAY_KIND_KMS:
        return sw_display_kms_init(&d->u.kms, desc->drm_device, w, h, &d->width, &d->height,
                                   err);
#endif
#if SW_HAVE_X11
    case SW_DISPLAY_KIND_X11:
        d->width = w > 0 ? w : 1280;
        d->height = h > 0 ? h : 720;
        return sw_display_x11_init(&d->u.x11, title, d->width, d->height, &d->keys,
                                   &d->close_requested, err);
#endif
#if SW_HAVE_WAYLAND
    case SW_DISPLAY_KIND_WAYLAND:
        d->width = w > 0 ? w : 1280;
        d->height = h > 0 ? h : 720;
        return sw_display_wayland_init(&d->u.wayland, title, d->width, d->height, &d->keys,
                                       &d->close_requested, err);
#endif
    default:
        return sw_error_set(err, SW_ERR_ARG, "display: unknown kind %d", (int)d->kind);
    }
}

sw_status sw_display_init(sw_display *d, const sw_display_desc *desc, sw_error *err)
{
    memset(d, 0, sizeof *d);
    sw_key_queue_clear(&d->keys);
    d->kind = desc->kind;
    if (d->kind == SW_DISPLAY_KIND_AUTO) {
        sw_display_env env;
        sw_display_probe(&env);
        d->kind = sw_display_choose(&env, d->chosen_why, sizeof d->chosen_why);
    } else {
        snprintf(d->chosen_why, sizeof d->chosen_why, "asked for %s",
                 sw_display_kind_name(d->kind));
    }
    sw_status st = init_kind(d, desc, err);
    d->up = st == SW_OK;
    /* Say that auto chose it, and why, so a failing choice is understood
     * (headless's size message says so already). */
    if (st != SW_OK && desc->kind == SW_DISPLAY_KIND_AUTO && d->kind != SW_DISPLAY_KIND_HEADLESS)
        sw_error_prefix(err, "%s", d->chosen_why);
    return st;
}

int sw_display_depth_bits(const sw_display *d)
{
    if (d->kind == SW_DISPLAY_KIND_HEADLESS)
        return d->u.headless.depth_bits;
    GLint bits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &bits);
    return bits > 0 ? bits : 16;
}

sw_status sw_display_present(sw_display *d, sw_error *err)
{
    (void)err;   /* only the windows and KMS can fail, and a build may have none */
    if (close_signal)
        d->close_requested = 1;
    switch (d->kind) {
#if SW_HAVE_KMS
    case SW_DISPLAY_KIND_KMS: return sw_display_kms_present(&d->u.kms, err);
#endif
#if SW_HAVE_X11
    case SW_DISPLAY_KIND_X11: return sw_display_x11_present(&d->u.x11, err);
#endif
#if SW_HAVE_WAYLAND
    case SW_DISPLAY_KIND_WAYLAND: return sw_display_wayland_present(&d->u.wayland, err);
#endif
    default: return SW_OK;   /* headless: the FBO is the picture; nothing to show */
    }
}

sw_status sw_display_read_rgba(sw_display *d, uint8_t *rgba, sw_error *err)
{
    switch (d->kind) {
    case SW_DISPLAY_KIND_HEADLESS: return sw_egl_headless_read_rgba(&d->u.headless, rgba, err);
    case SW_DISPLAY_KIND_KMS:
        return sw_egl_window_read_rgba(&d->u.kms.egl, d->width, d->height, rgba, err);
    case SW_DISPLAY_KIND_X11:
        return sw_egl_window_read_rgba(&d->u.x11.egl, d->width, d->height, rgba, err);
    case SW_DISPLAY_KIND_WAYLAND:
        return sw_egl_window_read_rgba(&d->u.wayland.egl, d->width, d->height, rgba, err);
    default: return sw_error_set(err, SW_ERR_ARG, "display: not initialised");
    }
}

int sw_display_poll_keys(sw_display *d, sw_key_event *out, int capacity)
{
    return sw_key_queue_take(&d->keys, out, capacity);
}

void sw_display_destroy(sw_display *d)
{
    switch (d->kind) {
    case SW_DISPLAY_KIND_HEADLESS: sw_egl_headless_destroy(&d->u.headless); break;
#if SW_HAVE_KMS
    case SW_DISPLAY_KIND_KMS: sw_display_kms_destroy(&d->u.kms); break;
#endif
#if SW_HAVE_X11
    case SW_DISPLAY_KIND_X11: sw_display_x11_destroy(&d->u.x11); break;
#endif
#if SW_HAVE_WAYLAND
    case SW_DISPLAY_KIND_WAYLAND: sw_display_wayland_destroy(&d->u.wayland); break;
#endif
    default: break;
    }
    d->up = 0;
}
