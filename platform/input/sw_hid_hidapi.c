/* SPDX-License-Identifier: MIT */
/* The gamepad backend on hidapi's hidraw build (sw_input_backend.h). Only
 * a unit with controllers exercises it; tests use sw_input_fake.h.
 *
 * Enumeration lists usage page 1 (Generic Desktop) with usage 4 (joystick)
 * or 5 (gamepad). hidapi 0.13 (Debian 12) has no call for the report
 * descriptor, so it is read from sysfs, /sys/class/hidraw/hidrawN/device/
 * report_descriptor, the bytes HIDIOCGRDESC returns. A read of -1 means the
 * device went away (unplugged); the input step closes it. hid_enumerate and
 * hid_open_path allocate inside libhidapi and libudev (sw_kiosk.h). */
#include <hidapi/hidapi.h>
#include <stdio.h>
#include <string.h>
#include <wchar.h>

#include "sw_input_backend.h"

static hid_device *devices[SW_PADS_MAX];
static int hidapi_up;

static int is_game_controller(const struct hid_device_info *d)
{
    return d->usage_page == 1 && (d->usage == 4 || d->usage == 5);
}

/* hidapi's bus type as the Linux BUS_* numbers SDL's GUIDs use. */
static uint16_t linux_bus(hid_bus_type bus)
{
    switch (bus) {
    case HID_API_BUS_USB: return 0x03;
    case HID_API_BUS_BLUETOOTH: return 0x05;
    case HID_API_BUS_I2C: return 0x18;
    case HID_API_BUS_SPI: return 0x1C;
    default: return 0;
    }
}

static int hidapi_enumerate(void *ctx, sw_hid_info *out, int max)
{
    (void)ctx;
    if (!hidapi_up && hid_init() == 0)
        hidapi_up = 1;
    if (!hidapi_up)
        return 0;
    struct hid_device_info *all = hid_enumerate(0, 0);
    int n = 0;
    for (struct hid_device_info *d = all; d && n < max; d = d->next) {
        if (!is_game_controller(d) || strlen(d->path) >= SW_HID_PATH_MAX)
            continue;
        sw_hid_info *i = &out[n++];
        memset(i, 0, sizeof *i);
        memcpy(i->path, d->path, strlen(d->path) + 1);
        i->bus = linux_bus(d->bus_type);
        i->vendor = d->vendor_id;
        i->product = d->product_id;
        i->version = d->release_number;
        snprintf(i->name, sizeof i->name, "%ls", d->product_string ? d->product_string : L"");
    }
    hid_free_enumeration(all);
    return n;
}

static int read_sysfs_descriptor(const char *path, uint8_t *desc, size_t cap, size_t *size,
                                 sw_error *err)
{
    const char *node = strrchr(path, '/');
    char sys[256];
    snprintf(sys, sizeof sys, "/sys/class/hidraw/%s/device/report_descriptor",
             node ? node + 1 : path);
    FILE *f = fopen(sys, "rb");
    if (!f) {
        sw_error_set(err, SW_ERR_IO, "%s: cannot read its report descriptor", sys);
        return -1;
    }
    *size = fread(desc, 1, cap, f);
    fclose(f);
    return 0;
}

static int hidapi_open(void *ctx, const sw_hid_info *info, uint8_t *desc, size_t cap,
                       size_t *size, sw_error *err)
{
    (void)ctx;
    int slot = -1;
    for (int i = 0; i < SW_PADS_MAX && slot < 0; i++)
        if (!devices[i])
            slot = i;
    if (slot < 0) {
        sw_error_set(err, SW_ERR_RANGE, "more than %d controllers", SW_PADS_MAX);
        return -1;
    }
    if (read_sysfs_descriptor(info->path, desc, cap, size, err) != 0)
        return -1;
    hid_device *d = hid_open_path(info->path);
    if (!d) {
        sw_error_set(err, SW_ERR_IO, "%s: cannot open it (is the udev rule "
                     "firmware/dist/70-seamwalk.rules installed?)", info->path);
        return -1;
    }
    hid_set_nonblocking(d, 1);
    devices[slot] = d;
    return slot;
}

static int hidapi_read(void *ctx, int handle, uint8_t *buf, size_t cap)
{
    (void)ctx;
    return hid_read(devices[handle], buf, cap);
}

static void hidapi_close(void *ctx, int handle)
{
    (void)ctx;
    hid_close(devices[handle]);
    devices[handle] = NULL;
}

sw_hid_backend sw_hid_hidapi_backend(void)
{
    return (sw_hid_backend){NULL, hidapi_enumerate, hidapi_open, hidapi_read, hidapi_close};
}
