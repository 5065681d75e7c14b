/* SPDX-License-Identifier: MIT */
/* Hot-plug of game controllers (sw_pads.h) with the fake enumerator
 * (sw_input_fake.h): plugged controllers are found by the next periodic
 * enumeration, a read of -1 closes them, a replug is found again, a
 * descriptor that is no controller is a log line. Argument: tests/hid. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "hid_fixture.h"
#include "sw_input_fake.h"
#include "sw_pads.h"
#include "sw_test.h"

static sw_fake_devices fake;
static sw_pads pads;
static uint8_t desc[SW_HID_DESC_MAX];

static const int64_t ms = 1000000;

static void plug_f310(int slot)
{
    size_t n = hid_fixture("logitech_f310_dinput.hex", desc, sizeof desc);
    sw_hid_info info = {.bus = 3, .vendor = 0x046D, .product = 0xC216, .version = 0x0110};
    strcpy(info.name, "F310");
    sw_fake_plug(&fake, slot, &info, desc, n);
}

static void start(void)
{
    sw_fake_init(&fake);
    sw_pads_init(&pads, sw_fake_hid_backend(&fake), NULL, 0.15f);
}

static void found_at_the_next_enumeration(void)
{
    start();
    SW_CHECK(sw_pads_poll(&pads, 0) == 0 && pads.plugs == 0);  /* nothing plugged */
    plug_f310(0);
    sw_pads_poll(&pads, 500 * ms);
    SW_CHECK(pads.plugs == 0 && fake.enumerations == 1);       /* not due yet */
    sw_pads_poll(&pads, 1000 * ms);
    SW_CHECK(pads.plugs == 1 && fake.enumerations == 2 && pads.pads[0].open);
    SW_CHECK(pads.pads[0].layout.axis_count == 4);
}

static void reports_move_the_mapped_state(void)
{
    start();
    plug_f310(0);
    sw_pads_poll(&pads, 0);
    uint8_t rest[8] = {0x80, 0x80, 0x80, 0x80, 0x08, 0, 0, 0};
    uint8_t up[8] = {0x80, 0x00, 0x80, 0x80, 0x08 | 0x10, 0, 0, 0}; /* left stick up, button 1 */
    sw_fake_report(&fake, 0, rest, 8);
    SW_CHECK(sw_pads_poll(&pads, 10 * ms) == 0);   /* 0x80 is inside the dead zone */
    sw_fake_report(&fake, 0, up, 8);
    SW_CHECK(sw_pads_poll(&pads, 20 * ms) == 1);
    SW_CHECK_NEAR(pads.pads[0].state.axis[SW_PAD_LEFTY], -1, 1e-4); /* x sits at +0.004 */
    SW_CHECK(pads.pads[0].state.buttons == 1u << SW_PAD_A);  /* default: a = b0 */
    SW_CHECK(pads.reports == 2);
}

static void unplug_closes_and_replug_reopens(void)
{
    start();
    plug_f310(1);
    sw_pads_poll(&pads, 0);
    uint8_t up[8] = {0x80, 0x00, 0x80, 0x80, 0x08, 0, 0, 0};
    sw_fake_report(&fake, 1, up, 8);
    sw_pads_poll(&pads, 10 * ms);
    SW_CHECK(pads.pads[0].open && pads.pads[0].state.axis[SW_PAD_LEFTY] < -0.9f);
    sw_fake_unplug(&fake, 1);
    SW_CHECK(sw_pads_poll(&pads, 20 * ms) == 0);      /* not input: nobody touched anything */
    SW_CHECK(!pads.pads[0].open && pads.unplugs == 1);
    SW_CHECK(pads.pads[0].state.axis[SW_PAD_LEFTY] == 0); /* the stick let go */
    plug_f310(1);
    sw_pads_poll(&pads, 500 * ms);
    SW_CHECK(!pads.pads[0].open);                     /* until the next enumeration */
    sw_pads_poll(&pads, 1000 * ms);
    SW_CHECK(pads.pads[0].open && pads.plugs == 2);
}

static void a_mouse_is_a_log_line(void)
{
    start();
    static const uint8_t mouse[] = {0x05, 0x01, 0x09, 0x02, 0xA1, 0x01, 0xC0};
    sw_hid_info info = {.bus = 3, .vendor = 1, .product = 2};
    sw_fake_plug(&fake, 0, &info, mouse, sizeof mouse);
    sw_pads_poll(&pads, 0);
    SW_CHECK(pads.plugs == 0 && !pads.pads[0].open && !fake.pads[0].opened);
}

/* A controller names itself (its USB product string, whatever device is
 * plugged into the kiosk): its log line shows the name's control bytes as
 * \xNN, never raw on the terminal or in the journal. */
static void a_name_with_an_escape_sequence_is_logged_escaped(void)
{
    start();
    size_t n = hid_fixture("logitech_f310_dinput.hex", desc, sizeof desc);
    sw_hid_info info = {.bus = 3, .vendor = 0x046D, .product = 0xC216};
    strcpy(info.name, "F\033]0;owned\aX");
    sw_fake_plug(&fake, 0, &info, desc, n);
    FILE *log = tmpfile();
    int saved = dup(2);
    fflush(stderr);
    dup2(fileno(log), 2);
    sw_pads_poll(&pads, 0);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    char text[512];
    rewind(log);
    size_t got = fread(text, 1, sizeof text - 1, log);
    text[got] = '\0';
    fclose(log);
    SW_CHECK(pads.plugs == 1);
    SW_CHECK_MSG(strstr(text, "(046d:c216 F\\x1b]0;owned\\x07X): 4 axes") != NULL, "%s", text);
    size_t controls = 0;
    for (size_t i = 0; i < got; i++)
        controls += text[i] != '\n' && ((unsigned char)text[i] < 0x20 || text[i] == 0x7f);
    SW_CHECK_MSG(controls == 0, "%zu control bytes in: %s", controls, text);
}

static void ds4_takes_its_known_layout_and_a_file_mapping_wins(void)
{
    static sw_pad_mapping_db db;
    static const char line[] = "030000004c050000c405000000010000,DS4 swapped,a:b1,b:b0\n";
    sw_error err = {0};
    SW_CHECK(sw_pad_mapping_db_parse(line, sizeof line - 1, "db", &db, &err) == SW_OK);
    for (int with_db = 0; with_db < 2; with_db++) {
        sw_fake_init(&fake);
        sw_pads_init(&pads, sw_fake_hid_backend(&fake), with_db ? &db : NULL, 0.15f);
        size_t n = hid_fixture("ds4_usb.hex", desc, sizeof desc);
        sw_hid_info info = {.bus = 3, .vendor = 0x054C, .product = 0x05C4, .version = 0x0100};
        sw_fake_plug(&fake, 0, &info, desc, n);
        uint8_t rep[64];
        hid_fixture("ds4_usb_report1_rest.hex", rep, sizeof rep);
        rep[5] = 0x28;  /* cross, hat centred */
        sw_fake_report(&fake, 0, rep, 64);
        sw_pads_poll(&pads, 0);
        SW_CHECK(pads.pads[0].open && pads.pads[0].layout.button_count == 13);
        SW_CHECK(pads.pads[0].state.buttons == 1u << (with_db ? SW_PAD_B : SW_PAD_A));
    }
}

int main(int argc, char **argv)
{
    if (argc > 1)
        hid_dir = argv[1];
    SW_RUN(found_at_the_next_enumeration);
    SW_RUN(reports_move_the_mapped_state);
    SW_RUN(unplug_closes_and_replug_reopens);
    SW_RUN(a_mouse_is_a_log_line);
    SW_RUN(a_name_with_an_escape_sequence_is_logged_escaped);
    SW_RUN(ds4_takes_its_known_layout_and_a_file_mapping_wins);
    return sw_test_finish();
}
