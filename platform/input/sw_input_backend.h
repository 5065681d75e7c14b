/* SPDX-License-Identifier: MIT */
/* The thin device layer under the kiosk's inputs: what
 * the input step (sw_kiosk.h) needs from hidapi, libgpiod and evdev, as
 * three small tables of functions, so tests and headless runs plug in the
 * fake devices of sw_input_fake.h (recorded descriptors and reports, a
 * hot-plugging enumerator, scripted GPIO edges, key events) and the real
 * ones (sw_hid_hidapi.c, sw_gpio_gpiod.c, sw_evdev_keys.c) only run on a
 * unit. Every read never blocks; every call is made from the GL thread. */
#ifndef SW_INPUT_BACKEND_H
#define SW_INPUT_BACKEND_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"

enum { SW_HID_PATH_MAX = 128, SW_PADS_MAX = 4, SW_GPIO_NAME_MAX = 32, SW_GPIO_LINES_MAX = 16 };

typedef struct sw_hid_info {
    char path[SW_HID_PATH_MAX];   /* hidapi's path (/dev/hidrawN), the device's identity */
    uint16_t bus, vendor, product, version;
    char name[64];
} sw_hid_info;

typedef struct sw_hid_backend {
    void *ctx;
    /* The game controllers present now (usage page 1, usage 4 or 5), at
     * most max. hidapi's enumeration allocates inside libhidapi and libudev:
     * the input step calls this once a second, see sw_kiosk.h. */
    int (*enumerate)(void *ctx, sw_hid_info *out, int max);
    /* Opens one, non-blocking, and reads its report descriptor into
     * desc[0..cap). A handle >= 0, or -1 with err set. */
    int (*open)(void *ctx, const sw_hid_info *info, uint8_t *desc, size_t cap, size_t *size,
                sw_error *err);
    /* One pending input report into buf: its size, 0 when none is pending,
     * -1 when the device is gone (hidapi's read of -1: unplugged). */
    int (*read)(void *ctx, int handle, uint8_t *buf, size_t cap);
    void (*close)(void *ctx, int handle);
} sw_hid_backend;

typedef enum sw_gpio_bias {
    SW_GPIO_BIAS_AS_IS = 0, SW_GPIO_BIAS_DISABLE, SW_GPIO_BIAS_PULL_UP, SW_GPIO_BIAS_PULL_DOWN
} sw_gpio_bias;

/* A button's line as a backend requests it, filled by the kiosk from the
 * button's [gpio NAME] section (sw_kiosk.c). A backend holds at most
 * SW_GPIO_LINES_MAX lines open at once. */
typedef struct sw_gpio_line {
    char name[SW_GPIO_NAME_MAX];       /* the button's (NAME); fake lines go by it */
    char chip[SW_GPIO_NAME_MAX];       /* gpiochip0, a path, a label or a number */
    char line_name[SW_GPIO_NAME_MAX];  /* the line by name, or empty and: */
    int line_offset;                   /* the line by offset */
    int active_low;                    /* pressed pulls it low (fake lines rest high) */
    sw_gpio_bias bias;
} sw_gpio_line;

typedef struct sw_gpio_edge {
    int64_t t_ns;                 /* the kernel's event timestamp */
    int high;                     /* the line's level after the edge */
} sw_gpio_edge;

typedef struct sw_gpio_backend {
    void *ctx;
    /* Requests the button's line for both-edge events with its bias and
     * fills its present level (physical, not inverted: the debouncer applies
     * active_low). A handle >= 0, or -1 with err (no chip, no line, busy). */
    int (*open)(void *ctx, const sw_gpio_line *line, int *high, sw_error *err);
    /* One pending edge: 1, or 0 when none is pending. */
    int (*read)(void *ctx, int handle, sw_gpio_edge *edge);
    void (*close)(void *ctx, int handle);
} sw_gpio_backend;

typedef struct sw_key_backend {
    void *ctx;
    /* device: an evdev path, or "auto" for the first keyboard in
     * /dev/input. 0, or -1 with err. */
    int (*open)(void *ctx, const char *device, sw_error *err);
    /* One pending key event: 1 with a Linux KEY_* code and value 1 down,
     * 0 up, 2 repeat; 0 when none is pending; -1 when the device is gone. */
    int (*read)(void *ctx, int *code, int *value);
    void (*close)(void *ctx);
} sw_key_backend;

/* The real devices (only built with hidapi, libgpiod and linux/input.h). */
sw_hid_backend sw_hid_hidapi_backend(void);
sw_gpio_backend sw_gpio_gpiod_backend(void);
sw_key_backend sw_evdev_key_backend(void);

#endif
