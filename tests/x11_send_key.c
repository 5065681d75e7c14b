/* SPDX-License-Identifier: MIT */
/* Presses a key in another client's X11 window, as a person at the
 * keyboard would: waits until a top-level window named TITLE exists, sends it
 * a KeyPress of KEYSYM (an X keysym name: Up, n, ...), holds it HOLD_S
 * seconds, sends the KeyRelease. Used by tests/test_display_x11.sh to drive
 * seamwalk --display x11 --navigate from outside.
 *   x11_send_key TITLE KEYSYM HOLD_S WAIT_S
 * Exit 0 when both events were sent, 1 when no such window came within
 * WAIT_S seconds, 2 on bad arguments or no X display. */
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void sleep_s(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

static Window find_named(Display *x, const char *title)
{
    Window root, parent, *kids = NULL, found = 0;
    unsigned int n = 0;
    if (!XQueryTree(x, DefaultRootWindow(x), &root, &parent, &kids, &n))
        return 0;
    for (unsigned int i = 0; i < n && !found; i++) {
        char *name = NULL;
        if (XFetchName(x, kids[i], &name) && name && !strcmp(name, title))
            found = kids[i];
        XFree(name);
    }
    XFree(kids);
    return found;
}

static void send_key(Display *x, Window w, KeySym sym, int press)
{
    XKeyEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.type = press ? KeyPress : KeyRelease;
    ev.display = x;
    ev.window = w;
    ev.root = DefaultRootWindow(x);
    ev.same_screen = True;
    ev.keycode = XKeysymToKeycode(x, sym);
    XSendEvent(x, w, True, press ? KeyPressMask : KeyReleaseMask, (XEvent *)&ev);
    XFlush(x);
}

int main(int argc, char **argv)
{
    KeySym sym = argc == 5 ? XStringToKeysym(argv[2]) : NoSymbol;
    double hold = argc == 5 ? atof(argv[3]) : 0, wait = argc == 5 ? atof(argv[4]) : 0;
    if (sym == NoSymbol || hold <= 0 || wait <= 0) {
        fprintf(stderr, "usage: x11_send_key TITLE KEYSYM HOLD_S WAIT_S\n");
        return 2;
    }
    Display *x = XOpenDisplay(NULL);
    if (!x) {
        fprintf(stderr, "x11_send_key: cannot open DISPLAY\n");
        return 2;
    }
    Window w = 0;
    for (double t = 0; t < wait && !(w = find_named(x, argv[1])); t += 0.1)
        sleep_s(0.1);
    if (!w) {
        fprintf(stderr, "x11_send_key: no window named '%s' within %g s\n", argv[1], wait);
        XCloseDisplay(x);
        return 1;
    }
    send_key(x, w, sym, 1);
    sleep_s(hold);
    send_key(x, w, sym, 0);
    XCloseDisplay(x);
    return 0;
}
