/* SPDX-License-Identifier: MIT */
/* Reads the recorded descriptors and reports of tests/hid/ (hex files, with
 * their sources in the comments) for the kiosk input tests. */
#ifndef HID_FIXTURE_H
#define HID_FIXTURE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_input_timeline.h"

static const char *hid_dir = "hid";

/* Reads DIR/name as hex bytes into out; exits the test on failure. */
static size_t hid_fixture(const char *name, uint8_t *out, size_t cap)
{
    char path[512], text[65536];
    snprintf(path, sizeof path, "%s/%s", hid_dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open\n", path);
        exit(1);
    }
    size_t n = fread(text, 1, sizeof text, f);
    fclose(f);
    size_t count = 0;
    sw_error err = {0};
    if (sw_hex_parse(text, n, path, out, cap, &count, &err) != SW_OK) {
        fprintf(stderr, "%s\n", err.message);
        exit(1);
    }
    return count;
}

#endif
