/* SPDX-License-Identifier: MIT */
/* The X11 window (platform/sw_display_x11.c) on a real X server: run by
 * tests/test_display_x11.sh under Xvfb with Mesa's llvmpipe. The window
 * draws and reads back, key events sent to it come out of
 * sw_display_poll_keys as keysyms, the window manager's close message sets
 * close_requested, and auto picks X11 when DISPLAY is set. */
#include <X11/Xlib.h>
#include <X11/keysym.h>
#include <GLES2/gl2.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_display.h"
#include "sw_test.h"

static sw_display d;   /* one window for the whole test, as seamwalk has */

/* Events from another client, as a keyboard or window manager would send them. */
static Display *other;

static void send_key(KeySym sym, int press)
{
    XKeyEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.type = press ? KeyPress : KeyRelease;
    ev.display = other;
    ev.window = d.u.x11.window;
    ev.root = DefaultRootWindow(other);
    ev.same_screen = True;
    ev.keycode = XKeysymToKeycode(other, sym);
    XSendEvent(other, d.u.x11.window, True, press ? KeyPressMask : KeyReleaseMask,
               (XEvent *)&ev);
}

static void send_close(void)
{
    XClientMessageEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.type = ClientMessage;
    ev.window = d.u.x11.window;
    ev.message_type = XInternAtom(other, "WM_PROTOCOLS", False);
    ev.format = 32;
    ev.data.l[0] = (long)XInternAtom(other, "WM_DELETE_WINDOW", False);
    XSendEvent(other, d.u.x11.window, False, NoEventMask, (XEvent *)&ev);
}

/* Presents until want events have come (or 2 s): delivery is asynchronous. */
static int collect(sw_key_event *out, int want)
{
    int n = 0;
    sw_error err = {0};
    for (int i = 0; i < 200 && n < want; i++) {
        SW_CHECK(sw_display_present(&d, &err) == SW_OK);
        n += sw_display_poll_keys(&d, out + n, want - n);
        nanosleep(&(struct timespec){0, 10000000}, NULL);
    }
    return n;
}

static void the_window_draws_and_reads_back(void)
{
    static uint8_t rgba[320 * 240 * 4];
    sw_error err = {0};
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    SW_CHECK_MSG(sw_display_read_rgba(&d, rgba, &err) == SW_OK, "%s", err.message);
    SW_CHECK(rgba[0] == 0 && rgba[1] == 255 && rgba[2] == 0 && rgba[3] == 255);
    size_t last = sizeof rgba - 4;
    SW_CHECK(rgba[last] == 0 && rgba[last + 1] == 255 && rgba[last + 2] == 0);
    SW_CHECK_MSG(sw_display_present(&d, &err) == SW_OK, "%s", err.message);
}

static void keys_sent_to_the_window_are_polled_as_keysyms(void)
{
    send_key(XK_a, 1);
    send_key(XK_a, 0);
    send_key(XK_Escape, 1);
    XSync(other, False);
    sw_key_event keys[3];
    SW_CHECK(collect(keys, 3) == 3);
    SW_CHECK(keys[0].keysym == XK_a && keys[0].pressed == 1);
    SW_CHECK(keys[1].keysym == XK_a && keys[1].pressed == 0);
    SW_CHECK(keys[2].keysym == XK_Escape && keys[2].pressed == 1);
    SW_CHECK(!d.close_requested);
}

static void the_close_message_requests_close(void)
{
    send_close();
    XSync(other, False);
    sw_error err = {0};
    for (int i = 0; i < 200 && !d.close_requested; i++) {
        SW_CHECK(sw_display_present(&d, &err) == SW_OK);
        nanosleep(&(struct timespec){0, 10000000}, NULL);
    }
    SW_CHECK(d.close_requested);
}

static void auto_picks_x11_when_display_is_set(void)
{
    sw_display_env env;
    sw_display_probe(&env);
    char why[160];
    SW_CHECK(sw_display_choose(&env, why, sizeof why) == SW_DISPLAY_KIND_X11 ||
             env.wayland_display_set);
}

int main(void)
{
    if (!getenv("DISPLAY")) {
        fprintf(stderr, "test_display_x11: needs DISPLAY (tests/test_display_x11.sh runs Xvfb)\n");
        return 2;
    }
    sw_error err = {0};
    sw_display_desc desc = {.kind = SW_DISPLAY_KIND_X11, .width = 320, .height = 240};
    sw_status st = sw_display_init(&d, &desc, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    if (st != SW_OK)
        return sw_test_finish();
    SW_CHECK(d.kind == SW_DISPLAY_KIND_X11 && d.width == 320 && d.height == 240);
    other = XOpenDisplay(NULL);
    SW_CHECK(other != NULL);
    if (other) {
        SW_RUN(the_window_draws_and_reads_back);
        SW_RUN(keys_sent_to_the_window_are_polled_as_keysyms);
        SW_RUN(the_close_message_requests_close);
        XCloseDisplay(other);
    }
    sw_display_destroy(&d);
    SW_RUN(auto_picks_x11_when_display_is_set);
    return sw_test_finish();
}
