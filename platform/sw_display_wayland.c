/* SPDX-License-Identifier: MIT */
/* A Wayland window for developers: the registry gives wl_compositor,
 * xdg_wm_base and wl_seat; an xdg_toplevel is configured before the first
 * frame (xdg-shell requires the ack before a buffer is attached); EGL draws
 * through a wl_egl_window. The keyboard's keymap comes from the compositor
 * as a file descriptor and is compiled with xkbcommon, so keys arrive as the
 * same keysyms X11 gives. Events are dispatched after each swap without
 * blocking. Tested on Weston's headless backend (tests/test_display_wayland.sh),
 * which has no input devices: the keyboard listener is exercised only by a
 * real compositor. */
#include "sw_display_wayland.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <errno.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <wayland-client.h>
#include <wayland-egl.h>

#include "sw_xkb_keys.h"
#include "xdg-shell-client-protocol.h"

#ifndef EGL_PLATFORM_WAYLAND_KHR
#define EGL_PLATFORM_WAYLAND_KHR 0x31D8
#endif

static void wm_base_ping(void *data, struct xdg_wm_base *base, uint32_t serial)
{
    (void)data;
    xdg_wm_base_pong(base, serial);
}
static const struct xdg_wm_base_listener wm_base_listener = {.ping = wm_base_ping};

static void surface_configure(void *data, struct xdg_surface *s, uint32_t serial)
{
    xdg_surface_ack_configure(s, serial);
    ((sw_display_wayland *)data)->configured = 1;
}
static const struct xdg_surface_listener surface_listener = {.configure = surface_configure};

/* The size stays ours (min = max size asks the compositor for that). */
static void toplevel_configure(void *data, struct xdg_toplevel *t, int32_t w, int32_t h,
                               struct wl_array *states)
{
    (void)data;
    (void)t;
    (void)w;
    (void)h;
    (void)states;
}
static void toplevel_close(void *data, struct xdg_toplevel *t)
{
    (void)t;
    *((sw_display_wayland *)data)->close_requested = 1;
}
static const struct xdg_toplevel_listener toplevel_listener = {
    .configure = toplevel_configure, .close = toplevel_close};

/* The compositor's keymap (sw_xkb_keys.h). One that does not compile leaves
 * the keys without keysyms: a developer window still shows the walk. */
static void kb_keymap(void *data, struct wl_keyboard *kb, uint32_t format, int32_t fd,
                      uint32_t size)
{
    (void)kb;
    sw_display_wayland *w = data;
    sw_xkb_keys_set_keymap(&w->xkb, format == WL_KEYBOARD_KEYMAP_FORMAT_XKB_V1, fd, size,
                           NULL);
}

static void kb_enter(void *data, struct wl_keyboard *kb, uint32_t serial,
                     struct wl_surface *s, struct wl_array *keys)
{
    (void)data; (void)kb; (void)serial; (void)s; (void)keys;
}
static void kb_leave(void *data, struct wl_keyboard *kb, uint32_t serial, struct wl_surface *s)
{
    (void)data; (void)kb; (void)serial; (void)s;
}

static void kb_key(void *data, struct wl_keyboard *kb, uint32_t serial, uint32_t time,
                   uint32_t key, uint32_t state)
{
    (void)kb; (void)serial; (void)time;
    sw_display_wayland *w = data;
    uint32_t sym = sw_xkb_keys_keysym(&w->xkb, key);
    if (sym)
        sw_key_queue_push(w->keys, sym, state == WL_KEYBOARD_KEY_STATE_PRESSED);
}

static void kb_modifiers(void *data, struct wl_keyboard *kb, uint32_t serial, uint32_t dep,
                         uint32_t lat, uint32_t lock, uint32_t group)
{
    (void)kb; (void)serial;
    sw_xkb_keys_set_modifiers(&((sw_display_wayland *)data)->xkb, dep, lat, lock, group);
}

/* Held keys do not repeat: the input step sees the press and the release. */
static void kb_repeat(void *data, struct wl_keyboard *kb, int32_t rate, int32_t delay)
{
    (void)data; (void)kb; (void)rate; (void)delay;
}

static const struct wl_keyboard_listener keyboard_listener = {
    .keymap = kb_keymap, .enter = kb_enter, .leave = kb_leave, .key = kb_key,
    .modifiers = kb_modifiers, .repeat_info = kb_repeat};

static void seat_caps(void *data, struct wl_seat *seat, uint32_t caps)
{
    sw_display_wayland *w = data;
    int has = (caps & WL_SEAT_CAPABILITY_KEYBOARD) != 0;
    if (has && !w->keyboard) {
        w->keyboard = wl_seat_get_keyboard(seat);
        wl_keyboard_add_listener(w->keyboard, &keyboard_listener, w);
    } else if (!has && w->keyboard) {
        wl_keyboard_destroy(w->keyboard);
        w->keyboard = NULL;
    }
}
static void seat_name(void *data, struct wl_seat *seat, const char *name)
{
    (void)data; (void)seat; (void)name;
}
static const struct wl_seat_listener seat_listener = {.capabilities = seat_caps,
                                                      .name = seat_name};

static void registry_global(void *data, struct wl_registry *reg, uint32_t name,
                            const char *iface, uint32_t version)
{
    sw_display_wayland *w = data;
    if (!strcmp(iface, wl_compositor_interface.name)) {
        w->compositor = wl_registry_bind(reg, name, &wl_compositor_interface, 1);
    } else if (!strcmp(iface, xdg_wm_base_interface.name)) {
        w->wm_base = wl_registry_bind(reg, name, &xdg_wm_base_interface, 1);
        xdg_wm_base_add_listener(w->wm_base, &wm_base_listener, w);
    } else if (!strcmp(iface, wl_seat_interface.name) && !w->seat) {
        w->seat = wl_registry_bind(reg, name, &wl_seat_interface, version < 4 ? version : 4);
        wl_seat_add_listener(w->seat, &seat_listener, w);
    }
}
static void registry_remove(void *data, struct wl_registry *reg, uint32_t name)
{
    (void)data; (void)reg; (void)name;
}
static const struct wl_registry_listener registry_listener = {
    .global = registry_global, .global_remove = registry_remove};

static sw_status fail(sw_display_wayland *w, sw_status st)
{
    sw_display_wayland_destroy(w);
    return st;
}

static sw_status connect_globals(sw_display_wayland *w, sw_error *err)
{
    const char *name = getenv("WAYLAND_DISPLAY");
    if (!name || !*name)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "wayland display: WAYLAND_DISPLAY is not "
                            "set (no Wayland session; use --display headless, kms or x11)");
    if (!(w->display = wl_display_connect(NULL)))
        return sw_error_set(err, SW_ERR_IO, "wayland display: cannot connect to '%s' (%s; "
                            "no compositor there, or XDG_RUNTIME_DIR is wrong)", name,
                            strerror(errno));
    sw_status st = sw_xkb_keys_init(&w->xkb, err);
    if (st != SW_OK)
        return st;
    w->registry = wl_display_get_registry(w->display);
    wl_registry_add_listener(w->registry, &registry_listener, w);
    wl_display_roundtrip(w->display);   /* the globals */
    wl_display_roundtrip(w->display);   /* the seat's capabilities and keymap */
    if (!w->compositor || !w->wm_base)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "wayland display: the compositor at '%s' "
                            "offers no %s", name, !w->compositor ? "wl_compositor" : "xdg_wm_base");
    return SW_OK;
}

static sw_status create_toplevel(sw_display_wayland *w, const char *title, int width,
                                 int height, sw_error *err)
{
    w->surface = wl_compositor_create_surface(w->compositor);
    w->xdg_surface = xdg_wm_base_get_xdg_surface(w->wm_base, w->surface);
    xdg_surface_add_listener(w->xdg_surface, &surface_listener, w);
    w->toplevel = xdg_surface_get_toplevel(w->xdg_surface);
    xdg_toplevel_add_listener(w->toplevel, &toplevel_listener, w);
    xdg_toplevel_set_title(w->toplevel, title);
    xdg_toplevel_set_app_id(w->toplevel, "seamwalk");
    xdg_toplevel_set_min_size(w->toplevel, width, height);
    xdg_toplevel_set_max_size(w->toplevel, width, height);
    wl_surface_commit(w->surface);
    while (!w->configured)
        if (wl_display_dispatch(w->display) < 0)
            return sw_error_set(err, SW_ERR_IO, "wayland display: the connection broke before "
                                "the window was configured");
    w->egl_window = wl_egl_window_create(w->surface, width, height);
    if (!w->egl_window)
        return sw_error_set(err, SW_ERR_GL, "wayland display: wl_egl_window_create failed");
    return SW_OK;
}

sw_status sw_display_wayland_init(sw_display_wayland *w, const char *title, int width,
                                  int height, sw_key_queue *keys, int *close_requested,
                                  sw_error *err)
{
    memset(w, 0, sizeof *w);
    w->keys = keys;
    w->close_requested = close_requested;
    sw_status st = connect_globals(w, err);
    if (st == SW_OK)
        st = sw_egl_window_open(&w->egl, "wayland display", EGL_PLATFORM_WAYLAND_KHR,
                                "EGL_KHR_platform_wayland", "EGL_EXT_platform_wayland",
                                w->display, 0, err);
    if (st == SW_OK)
        st = create_toplevel(w, title, width, height, err);
    if (st == SW_OK)
        st = sw_egl_window_attach(&w->egl, w->egl_window, err);
    return st != SW_OK ? fail(w, st) : SW_OK;
}

/* What came in since the last frame, without blocking (the
 * prepare_read/read_events protocol of wayland-client.h). */
static sw_status pump_events(sw_display_wayland *w, sw_error *err)
{
    struct wl_display *d = w->display;
    while (wl_display_prepare_read(d) != 0)
        wl_display_dispatch_pending(d);
    wl_display_flush(d);
    struct pollfd p = {.fd = wl_display_get_fd(d), .events = POLLIN};
    if (poll(&p, 1, 0) > 0)
        wl_display_read_events(d);
    else
        wl_display_cancel_read(d);
    if (wl_display_dispatch_pending(d) < 0)
        return sw_error_set(err, SW_ERR_IO, "wayland display: the compositor connection "
                            "broke (%s)", strerror(wl_display_get_error(d)));
    return SW_OK;
}

sw_status sw_display_wayland_present(sw_display_wayland *w, sw_error *err)
{
    sw_status st = sw_egl_window_swap(&w->egl, err);
    return st != SW_OK ? st : pump_events(w, err);
}

void sw_display_wayland_destroy(sw_display_wayland *w)
{
    sw_egl_window_destroy(&w->egl);
    if (w->egl_window)
        wl_egl_window_destroy(w->egl_window);
    if (w->toplevel)
        xdg_toplevel_destroy(w->toplevel);
    if (w->xdg_surface)
        xdg_surface_destroy(w->xdg_surface);
    if (w->surface)
        wl_surface_destroy(w->surface);
    if (w->keyboard)
        wl_keyboard_destroy(w->keyboard);
    if (w->seat)
        wl_seat_destroy(w->seat);
    if (w->wm_base)
        xdg_wm_base_destroy(w->wm_base);
    if (w->compositor)
        wl_compositor_destroy(w->compositor);
    if (w->registry)
        wl_registry_destroy(w->registry);
    sw_xkb_keys_destroy(&w->xkb);
    if (w->display)
        wl_display_disconnect(w->display);
    sw_key_queue *keys = w->keys;
    int *close_requested = w->close_requested;
    memset(w, 0, sizeof *w);
    w->keys = keys;
    w->close_requested = close_requested;
}
