/* SPDX-License-Identifier: MIT */
/* The keyboard backend on evdev (sw_input_backend.h), for the kiosk where
 * there is no window (a window's keys come through sw_window_keys.c),
 * through libevdev. "auto" takes the first /dev/input/eventN that reports
 * EV_KEY with KEY_A and KEY_SPACE (a keyboard, not a power button).
 *
 * SYN_DROPPED: when the kernel's buffer overflows it drops events and says
 * so; a key released meanwhile would stay held for ever (the camera keeps
 * walking). libevdev then reads the device's state (EVIOCGKEY) and hands
 * the difference to what it last reported as events of their own (a
 * release for every key that went up, a press for every key that went
 * down); they are read here in sync mode until libevdev has none left, so
 * the kiosk's held keys follow the keyboard again. Reading them in normal
 * mode instead would discard them.
 *
 * Non-blocking; -ENODEV means it was unplugged. GL thread only. libevdev
 * allocates its state when the device is opened (start-up), nothing per
 * event. Tested with a recorded event stream and a fake device under
 * libevdev's ioctls (tests/test_evdev_keys.c); only a unit opens a real one. */
#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "sw_input_backend.h"

static struct libevdev *key_dev;
static int key_fd = -1;
static int key_syncing;   /* after SYN_DROPPED: libevdev's resync events pending */

/* Opens path as an evdev device (a keyboard, if keyboard_only): 0 or an
 * errno value. */
static int open_device(const char *path, int keyboard_only)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return errno;
    struct libevdev *dev = NULL;
    int rc = libevdev_new_from_fd(fd, &dev);
    if (rc < 0 || (keyboard_only && !(libevdev_has_event_code(dev, EV_KEY, KEY_A) &&
                                      libevdev_has_event_code(dev, EV_KEY, KEY_SPACE)))) {
        if (dev)
            libevdev_free(dev);
        close(fd);
        return rc < 0 ? -rc : ENODEV;
    }
    key_dev = dev;
    key_fd = fd;
    key_syncing = 0;
    return 0;
}

static int open_auto(void)
{
    for (int i = 0; i < 32; i++) {
        char path[32];
        snprintf(path, sizeof path, "/dev/input/event%d", i);
        if (open_device(path, 1) == 0)
            return 0;
    }
    return -1;
}

static int evdev_open(void *ctx, const char *device, sw_error *err)
{
    (void)ctx;
    if (!strcmp(device, "auto")) {
        if (open_auto() == 0)
            return 0;
        sw_error_set(err, SW_ERR_IO, "auto: no keyboard in /dev/input");
        return -1;
    }
    int e = open_device(device, 0);
    if (e == 0)
        return 0;
    sw_error_set(err, SW_ERR_IO, "%s: %s", device,
                 e == ENOTTY || e == EINVAL ? "not an evdev device" : strerror(e));
    return -1;
}

static int evdev_read(void *ctx, int *code, int *value)
{
    (void)ctx;
    struct input_event ev;
    for (;;) {
        int rc = libevdev_next_event(key_dev, key_syncing ? LIBEVDEV_READ_FLAG_SYNC
                                                          : LIBEVDEV_READ_FLAG_NORMAL, &ev);
        if (rc == -EAGAIN) {
            if (!key_syncing)
                return 0;
            key_syncing = 0;   /* the resync is done: back to the device's events */
            continue;
        }
        if (rc == LIBEVDEV_READ_STATUS_SYNC && !key_syncing) {
            key_syncing = 1;   /* ev is the SYN_DROPPED: the state's delta follows */
            continue;
        }
        if (rc < 0)
            return rc == -EINTR ? 0 : -1;
        if (ev.type != EV_KEY)
            continue;
        *code = ev.code;
        *value = ev.value;
        return 1;
    }
}

static void evdev_close(void *ctx)
{
    (void)ctx;
    if (key_dev)
        libevdev_free(key_dev);
    if (key_fd >= 0)
        close(key_fd);
    key_dev = NULL;
    key_fd = -1;
}

sw_key_backend sw_evdev_key_backend(void)
{
    return (sw_key_backend){NULL, evdev_open, evdev_read, evdev_close};
}
