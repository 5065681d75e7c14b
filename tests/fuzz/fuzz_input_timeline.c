/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for input timelines and hex files
 * (sw_input_timeline.h): every input parses into events with times that
 * never decrease, or fails with "fuzz.timeline:LINE: ..."; the same bytes
 * go through the hex parser with a small buffer. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_input_timeline.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    size_t n = sw_timeline_count_events(text, size);
    sw_timeline_event *ev = calloc(n, sizeof *ev);
    if (!ev)
        return 0;
    sw_timeline tl;
    sw_error err = {0};
    if (sw_timeline_parse(text, size, "fuzz.timeline", ev, n, &tl, &err) == SW_OK) {
        for (size_t i = 0; i < tl.count; i++)
            if ((i && ev[i].t_s < ev[i - 1].t_s) || ev[i].kind < SW_TL_PLUG ||
                ev[i].kind > SW_TL_KEY || ev[i].slot > 3 || ev[i].size > SW_HID_REPORT_MAX)
                abort();
    } else if (strncmp(err.message, "fuzz.timeline:", 14) != 0) {
        abort();
    }
    free(ev);
    uint8_t bytes[16];
    size_t count;
    if (sw_hex_parse(text, size, "fuzz.hex", bytes, sizeof bytes, &count, &err) == SW_OK &&
        count > sizeof bytes)
        abort();
    return 0;
}
