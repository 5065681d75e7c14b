/* SPDX-License-Identifier: MIT */
/* seamwalk under systemd (firmware/dist/seamwalk.service, Type=notify): the
 * service manager's notifications through libsystemd's sd_notify. READY=1
 * once the first frame is on the display (so `systemctl start` returns
 * when there is a picture, and the watchdog starts then); WATCHDOG=1 from
 * the frame loop, at most every quarter of WatchdogSec= (a frame loop that
 * hangs stops them and systemd restarts the unit); STATUS= lines for
 * `systemctl status`. Without NOTIFY_SOCKET (a developer's shell, the
 * tests) every call does nothing. Called on the GL thread only (main's
 * frame loop); allocates nothing after sw_notify_init. */
#ifndef SW_NOTIFY_H
#define SW_NOTIFY_H

#include <stdint.h>

typedef struct sw_notify {
    int ready;               /* READY=1 sent */
    uint64_t watchdog_us;    /* WatchdogSec= as systemd passed it; 0: no watchdog */
    double last_ping_s;      /* when WATCHDOG=1 was last sent */
} sw_notify;

/* Reads the watchdog interval systemd passed (WATCHDOG_USEC, WATCHDOG_PID). */
void sw_notify_init(sw_notify *n);

/* After a frame is on the display, now_s on a monotonic clock: READY=1 the
 * first time, then WATCHDOG=1 when a quarter of the interval has passed. */
void sw_notify_frame(sw_notify *n, double now_s);

/* STATUS=..., formatted into a fixed buffer (no allocation). */
void sw_notify_status(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
