/* SPDX-License-Identifier: MIT */
/* An X11 window for developers: Xlib opens the server, EGL picks the config
 * and so the visual, the window is made with that visual and a fixed size
 * (the arena's read-back and the view's aspect were sized for it). Events
 * are pumped after each swap: keys into the queue, the close button into
 * close_requested. Tested under Xvfb (tests/test_display_x11.sh). */
#include "sw_display_x11.h"

#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdlib.h>
#include <string.h>

#ifndef EGL_PLATFORM_X11_KHR
#define EGL_PLATFORM_X11_KHR 0x31D5
#endif

static sw_status x11_fail(sw_display_x11 *x, sw_status st)
{
    sw_display_x11_destroy(x);
    return st;
}

static sw_status open_server(sw_display_x11 *x, sw_error *err)
{
    const char *name = getenv("DISPLAY");
    if (!name || !*name)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "x11 display: DISPLAY is not set (no X "
                            "session; use --display headless, kms or wayland)");
    x->xdisplay = XOpenDisplay(NULL);
    if (!x->xdisplay)
        return sw_error_set(err, SW_ERR_IO, "x11 display: cannot open the X display '%s' "
                            "(no X server there, or no access)", name);
    return SW_OK;
}

/* A window of the EGL config's visual: EGL on X11 refuses a surface whose
 * window's visual differs from the config's. */
static sw_status create_window(sw_display_x11 *x, const char *title, int w, int h,
                               sw_error *err)
{
    Display *dpy = x->xdisplay;
    XVisualInfo want = {.visualid = (VisualID)x->egl.visual_id}, *vi;
    int n = 0;
    vi = XGetVisualInfo(dpy, VisualIDMask, &want, &n);
    if (!vi)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "x11 display: the server has no visual "
                            "0x%x that EGL chose", (unsigned)x->egl.visual_id);
    Window root = RootWindow(dpy, vi->screen);
    x->colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    XSetWindowAttributes attr = {.colormap = x->colormap, .background_pixel = 0,
                                 .border_pixel = 0,
                                 .event_mask = KeyPressMask | KeyReleaseMask | StructureNotifyMask};
    x->window = XCreateWindow(dpy, root, 0, 0, (unsigned)w, (unsigned)h, 0, vi->depth,
                              InputOutput, vi->visual,
                              CWColormap | CWBackPixel | CWBorderPixel | CWEventMask, &attr);
    XFree(vi);
    XSizeHints hints = {.flags = PMinSize | PMaxSize, .min_width = w, .max_width = w,
                        .min_height = h, .max_height = h};
    XSetWMNormalHints(dpy, x->window, &hints);
    XStoreName(dpy, x->window, title);
    x->wm_delete = XInternAtom(dpy, "WM_DELETE_WINDOW", False);
    Atom del = x->wm_delete;
    XSetWMProtocols(dpy, x->window, &del, 1);
    /* Held keys then repeat as presses without the fake releases between. */
    XkbSetDetectableAutoRepeat(dpy, True, NULL);
    XMapWindow(dpy, x->window);
    XFlush(dpy);
    return SW_OK;
}

sw_status sw_display_x11_init(sw_display_x11 *x, const char *title, int width, int height,
                              sw_key_queue *keys, int *close_requested, sw_error *err)
{
    memset(x, 0, sizeof *x);
    x->keys = keys;
    x->close_requested = close_requested;
    sw_status st = open_server(x, err);
    if (st != SW_OK)
        return st;
    st = sw_egl_window_open(&x->egl, "x11 display", EGL_PLATFORM_X11_KHR,
                            "EGL_KHR_platform_x11", "EGL_EXT_platform_x11", x->xdisplay, 0, err);
    if (st != SW_OK)
        return x11_fail(x, st);
    if ((st = create_window(x, title, width, height, err)) != SW_OK)
        return x11_fail(x, st);
    Window win = x->window;
    if ((st = sw_egl_window_attach(&x->egl, &win, err)) != SW_OK)
        return x11_fail(x, st);
    return SW_OK;
}

/* Everything the server sent, without blocking. */
static void pump_events(sw_display_x11 *x)
{
    Display *dpy = x->xdisplay;
    while (XPending(dpy) > 0) {
        XEvent ev;
        XNextEvent(dpy, &ev);
        if (ev.type == KeyPress || ev.type == KeyRelease)
            /* Index 0: the unshifted keysym, so 'a' with or without Shift. */
            sw_key_queue_push(x->keys, (uint32_t)XLookupKeysym(&ev.xkey, 0),
                              ev.type == KeyPress);
        else if (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == x->wm_delete)
            *x->close_requested = 1;
        else if (ev.type == DestroyNotify)
            *x->close_requested = 1;
    }
}

sw_status sw_display_x11_present(sw_display_x11 *x, sw_error *err)
{
    sw_status st = sw_egl_window_swap(&x->egl, err);
    pump_events(x);
    return st;
}

void sw_display_x11_destroy(sw_display_x11 *x)
{
    sw_egl_window_destroy(&x->egl);
    if (x->xdisplay) {
        if (x->window)
            XDestroyWindow(x->xdisplay, x->window);
        if (x->colormap)
            XFreeColormap(x->xdisplay, x->colormap);
        XCloseDisplay(x->xdisplay);
    }
    x->xdisplay = NULL;
    x->window = x->colormap = 0;
}
