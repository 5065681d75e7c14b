/* The keyboard backend on evdev (sw_input_backend.h), for the kiosk where
 * there is no window (a window's keys come through sw_window_keys.c).
 * "auto" takes the first /dev/input/eventN that reports EV_KEY with KEY_A
 * and KEY_SPACE (a keyboard, not a power button). Non-blocking reads of
 * struct input_event; ENODEV means it was unplugged. Only a unit (or a
 * machine with /dev/input) exercises it; tests use sw_input_fake.h. */
#include <errno.h>
#include <fcntl.h>
#include <linux/input.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "sw_input_backend.h"

static int key_fd = -1;

static int has_key(const unsigned char *bits, int code)
{
    return (bits[code / 8] >> (code % 8)) & 1;
}

static int is_keyboard(int fd)
{
    unsigned char keys[KEY_MAX / 8 + 1] = {0};
    if (ioctl(fd, EVIOCGBIT(EV_KEY, sizeof keys), keys) < 0)
        return 0;
    return has_key(keys, KEY_A) && has_key(keys, KEY_SPACE);
}

static int open_auto(void)
{
    for (int i = 0; i < 32; i++) {
        char path[32];
        snprintf(path, sizeof path, "/dev/input/event%d", i);
        int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0)
            continue;
        if (is_keyboard(fd))
            return fd;
        close(fd);
    }
    return -1;
}

static int evdev_open(void *ctx, const char *device, sw_error *err)
{
    (void)ctx;
    key_fd = strcmp(device, "auto") ? open(device, O_RDONLY | O_NONBLOCK | O_CLOEXEC)
                                    : open_auto();
    if (key_fd < 0) {
        sw_error_set(err, SW_ERR_IO, "%s: %s", device,
                     strcmp(device, "auto") ? strerror(errno) : "no keyboard in /dev/input");
        return -1;
    }
    return 0;
}

static int evdev_read(void *ctx, int *code, int *value)
{
    (void)ctx;
    struct input_event ev;
    for (;;) {
        ssize_t n = read(key_fd, &ev, sizeof ev);
        if (n < 0)
            return errno == EAGAIN || errno == EINTR ? 0 : -1;
        if (n != (ssize_t)sizeof ev)
            return 0;
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
    if (key_fd >= 0)
        close(key_fd);
    key_fd = -1;
}

sw_key_backend sw_evdev_key_backend(void)
{
    return (sw_key_backend){NULL, evdev_open, evdev_read, evdev_close};
}
