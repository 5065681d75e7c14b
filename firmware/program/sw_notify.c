/* SPDX-License-Identifier: MIT */
/* The service manager's notifications (sw_notify.h). GL thread. */
#include "sw_notify.h"

#include <stdarg.h>
#include <stdio.h>
#include <systemd/sd-daemon.h>

void sw_notify_init(sw_notify *n)
{
    *n = (sw_notify){ 0 };
    uint64_t usec = 0;
    if (sd_watchdog_enabled(0, &usec) > 0)
        n->watchdog_us = usec;
}

void sw_notify_frame(sw_notify *n, double now_s)
{
    if (!n->ready) {
        /* The first ping goes with READY=1: the watchdog starts now. */
        sd_notify(0, n->watchdog_us ? "READY=1\nWATCHDOG=1" : "READY=1");
        n->ready = 1;
        n->last_ping_s = now_s;
        return;
    }
    if (n->watchdog_us && (now_s - n->last_ping_s) * 4e6 >= (double)n->watchdog_us) {
        sd_notify(0, "WATCHDOG=1");
        n->last_ping_s = now_s;
    }
}

void sw_notify_status(const char *fmt, ...)
{
    char line[512] = "STATUS=";
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line + 7, sizeof line - 7, fmt, ap);
    va_end(ap);
    sd_notify(0, line);
}
