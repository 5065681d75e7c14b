/* SPDX-License-Identifier: MIT */
/* A virtual gamepad through /dev/uhid for tests/qemu/run-uhid.sh: creates a
 * HID device with a recorded descriptor (a tests/hid/ hex file), so hidraw
 * and hidapi see a real device; once something opens it (UHID_OPEN: hidapi
 * opening /dev/hidrawN) and WAIT seconds more, pushes the left stick
 * forward for PUSH seconds (reports every 10 ms in the F310's D-mode
 * layout), centres it, and after one more second destroys the device (an
 * unplug). Runs inside the QEMU guest as root.
 *   uhid_pad DESCRIPTOR.hex WAIT_S PUSH_S */
#include <fcntl.h>
#include <linux/uhid.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "sw_input_timeline.h"

static void sleep_s(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

static int send(int fd, const struct uhid_event *ev)
{
    return write(fd, ev, sizeof *ev) == (ssize_t)sizeof *ev ? 0 : -1;
}

static int report(int fd, const uint8_t *bytes, size_t n)
{
    struct uhid_event ev = {.type = UHID_INPUT2};
    ev.u.input2.size = (uint16_t)n;
    memcpy(ev.u.input2.data, bytes, n);
    return send(fd, &ev);
}

static size_t read_descriptor(const char *path, uint8_t *out, size_t cap)
{
    static char text[65536];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(text, 1, sizeof text, f) : 0, count = 0;
    if (f)
        fclose(f);
    sw_error err = {0};
    if (!n || sw_hex_parse(text, n, path, out, cap, &count, &err) != SW_OK) {
        fprintf(stderr, "uhid_pad: %s: %s\n", path, err.message[0] ? err.message : "unreadable");
        exit(1);
    }
    return count;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: uhid_pad DESCRIPTOR.hex WAIT_S PUSH_S\n");
        return 2;
    }
    struct uhid_event create = {.type = UHID_CREATE2};
    create.u.create2.rd_size = (uint16_t)read_descriptor(argv[1], create.u.create2.rd_data,
                                                         sizeof create.u.create2.rd_data);
    snprintf((char *)create.u.create2.name, sizeof create.u.create2.name, "seamwalk uhid F310");
    /* Bluetooth, not USB: hidapi's hidraw backend looks up the USB parent
     * of a USB-bus device in sysfs, which a UHID device does not have; with
     * bus USB seamwalk never opened the pad (one run, 2026-12-01). */
    create.u.create2.bus = 0x05; /* BUS_BLUETOOTH */
    create.u.create2.vendor = 0x046D;
    create.u.create2.product = 0xC216;
    create.u.create2.version = 0x0110;
    int fd = open("/dev/uhid", O_RDWR | O_CLOEXEC);
    if (fd < 0 || send(fd, &create) != 0) {
        perror("uhid_pad: /dev/uhid");
        return 1;
    }
    fprintf(stderr, "uhid_pad: created\n");
    static const uint8_t rest[8] = {0x80, 0x80, 0x80, 0x80, 0x08, 0, 0, 0};
    static const uint8_t push[8] = {0x80, 0x00, 0x80, 0x80, 0x08, 0, 0, 0};
    struct uhid_event ev;
    alarm(300); /* nobody opened it: give up rather than hang the guest */
    do { /* the kernel passes reports on only while the device is open */
        if (read(fd, &ev, sizeof ev) <= 0) {
            perror("uhid_pad: read");
            return 1;
        }
    } while (ev.type != UHID_OPEN);
    alarm(0);
    fprintf(stderr, "uhid_pad: opened\n");
    report(fd, rest, sizeof rest);
    sleep_s(atof(argv[2]));
    int sent = 0, failed = 0;
    for (double t = 0; t < atof(argv[3]); t += 0.01) {
        if (report(fd, push, sizeof push) == 0)
            sent++;
        else
            failed++;
        sleep_s(0.01);
    }
    fprintf(stderr, "uhid_pad: %d reports pushed, %d failed\n", sent, failed);
    report(fd, rest, sizeof rest);
    sleep_s(1.0);
    struct uhid_event destroy = {.type = UHID_DESTROY};
    send(fd, &destroy);
    fprintf(stderr, "uhid_pad: destroyed\n");
    close(fd);
    return 0;
}
