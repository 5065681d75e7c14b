/* SPDX-License-Identifier: MIT */
/* The input timeline and hex parsers (sw_input_timeline.h): every event
 * kind, comments, and each error with its FILE:LINE message. */
#include <string.h>

#include "sw_input_timeline.h"
#include "sw_test.h"

static sw_timeline_event events[16];
static sw_timeline tl;

static sw_status parse(const char *text, sw_error *err)
{
    return sw_timeline_parse(text, strlen(text), "walk.timeline", events, 16, &tl, err);
}

static void every_kind(void)
{
    static const char text[] =
        "# a walk\n"
        "0 pad 0 plug 0003 046d c216 0110 hid/f310.hex F310   # plugged at start\n"
        "\n"
        "0.5 pad 0 report 80 00 80 80 08 00 00 00\n"
        "1.25 gpio next 0\n"
        "1.25 key 49 1\n"
        "2 pad 0 unplug\n";
    sw_error err = {0};
    SW_CHECK_MSG(parse(text, &err) == SW_OK, "%s", err.message);
    SW_CHECK(tl.count == 5);
    SW_CHECK(events[0].kind == SW_TL_PLUG && events[0].vendor == 0x046D &&
             events[0].product == 0xC216 && events[0].version == 0x0110 && events[0].bus == 3 &&
             !strcmp(events[0].file, "hid/f310.hex") && !strcmp(events[0].name, "F310"));
    SW_CHECK(events[1].kind == SW_TL_REPORT && events[1].size == 8 && events[1].bytes[4] == 8);
    SW_CHECK(events[2].kind == SW_TL_GPIO && !strcmp(events[2].name, "next") &&
             events[2].value == 0 && events[2].t_s == 1.25);
    SW_CHECK(events[3].kind == SW_TL_KEY && events[3].code == 49 && events[3].value == 1);
    SW_CHECK(events[4].kind == SW_TL_UNPLUG && events[4].slot == 0);
    SW_CHECK(sw_timeline_count_events(text, sizeof text - 1) >= tl.count);
}

static void expect(const char *text, const char *needle)
{
    sw_error err = {0};
    SW_CHECK(parse(text, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "%s (expected '%s')", err.message, needle);
}

static void errors_name_the_line(void)
{
    expect("0 pad 0 unplug\nx pad 0 unplug\n", "walk.timeline:2: expected a time in seconds");
    expect("-1 key 1 1\n", "expected a time in seconds");
    expect("1 pad 0 unplug\n0.5 pad 0 unplug\n", "walk.timeline:2: expected times that never");
    expect("1 mouse 0\n", "expected pad, gpio or key, got 'mouse'");
    expect("1\n", "expected pad, gpio or key after the time");
    expect("1 pad 4 unplug\n", "expected TIME pad SLOT (0..3)");
    expect("1 pad 0 jump\n", "expected plug, report or unplug, got 'jump'");
    expect("1 pad 0 unplug now\n", "expected nothing after unplug");
    expect("1 pad 0 report\n", "expected 1..256 report bytes");
    expect("1 pad 0 report 0g\n", "expected a report byte as two hex digits, got '0g'");
    expect("1 pad 0 report 123\n", "got '123'");
    expect("1 pad 0 plug 3 46d c216\n", "expected TIME pad SLOT plug BUS");
    expect("1 pad 0 plug 3 46d c216 12345 f.hex\n", "as 1..4 hex digits");
    expect("1 gpio next 2\n", "expected TIME gpio NAME 0|1");
    expect("1 gpio next\n", "expected TIME gpio NAME 0|1");
    expect("1 key 800 1\n", "expected TIME key CODE (0..767)");
    expect("1 key 30 3\n", "expected TIME key CODE");
    expect("1e8 key 30 1\n", "0..1e7");
    expect("nan key 30 1\n", "expected a time");
    char nul[] = "1 key 30 1\n2 key\0 30 1\n";
    sw_error err = {0};
    SW_CHECK(sw_timeline_parse(nul, sizeof nul - 1, "walk.timeline", events, 16, &tl, &err) ==
                 SW_ERR_FORMAT && strstr(err.message, "walk.timeline:2: expected text"));
    static char wide[2000];
    memcpy(wide, "1 pad 0 report", 14);
    for (int i = 0; i < 300; i++)
        memcpy(wide + 14 + 3 * i, " 00", 3);
    expect(wide, "at most 300 words");
}

static void hex_files(void)
{
    uint8_t out[8];
    size_t n;
    sw_error err = {0};
    static const char good[] = "# c\n05 01, 0x09 0X05\n\ta1 # end\n";
    SW_CHECK(sw_hex_parse(good, sizeof good - 1, "d.hex", out, 8, &n, &err) == SW_OK && n == 5);
    SW_CHECK(out[0] == 5 && out[2] == 9 && out[3] == 5 && out[4] == 0xA1);
    static const char bad[] = "05\n0z\n";
    SW_CHECK(sw_hex_parse(bad, sizeof bad - 1, "d.hex", out, 8, &n, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "d.hex:2: expected a byte as two hex digits, got '0z'"),
                 "%s", err.message);
    static const char many[] = "00 01 02 03 04 05 06 07 08";
    SW_CHECK(sw_hex_parse(many, sizeof many - 1, "d.hex", out, 8, &n, &err) == SW_ERR_FORMAT &&
             strstr(err.message, "more bytes than fit"));
    static const char odd[] = "050";
    SW_CHECK(sw_hex_parse(odd, 3, "d.hex", out, 8, &n, &err) == SW_ERR_FORMAT);
}

int main(void)
{
    SW_RUN(every_kind);
    SW_RUN(errors_name_the_line);
    SW_RUN(hex_files);
    return sw_test_finish();
}
