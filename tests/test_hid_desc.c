/* SPDX-License-Identifier: MIT */
/* The HID report descriptor parser and report decoder (sw_hid_desc.h),
 * against recorded descriptors of four real controllers (tests/hid/, each
 * file names its source) and every error path. Argument: tests/hid. */
#include <string.h>

#include "hid_fixture.h"
#include "sw_hid_desc.h"
#include "sw_hid_known.h"
#include "sw_test.h"

static uint8_t desc[SW_HID_DESC_MAX + 16];

static const sw_hid_field *field(const sw_hid_layout *l, int kind, int index)
{
    for (int i = 0; i < l->field_count; i++)
        if (l->fields[i].kind == kind && l->fields[i].index == index)
            return &l->fields[i];
    return NULL;
}

static void parse_fixture(const char *name, sw_hid_layout *l)
{
    size_t n = hid_fixture(name, desc, sizeof desc);
    sw_error err = {0};
    SW_CHECK_MSG(sw_hid_desc_parse(desc, n, name, l, &err) == SW_OK, "%s", err.message);
}

static void ds4_descriptor_fields(void)
{
    sw_hid_layout l;
    parse_fixture("ds4_usb.hex", &l);
    SW_CHECK(l.application == 5 && l.uses_report_ids);
    SW_CHECK(l.axis_count == 6 && l.hat_count == 1 && l.button_count == 14);
    const sw_hid_field *x = field(&l, SW_HID_AXIS, 0), *rz = field(&l, SW_HID_AXIS, 5);
    const sw_hid_field *hat = field(&l, SW_HID_HAT, 0), *b1 = field(&l, SW_HID_BUTTON, 0);
    const sw_hid_field *rx = field(&l, SW_HID_AXIS, 3);
    SW_CHECK(x && x->report_id == 1 && x->bit_offset == 0 && x->bit_size == 8 &&
             x->logical_min == 0 && x->logical_max == 255);
    SW_CHECK(rz && rz->bit_offset == 24);
    SW_CHECK(hat && hat->bit_offset == 32 && hat->bit_size == 4 && hat->logical_max == 7);
    SW_CHECK(b1 && b1->bit_offset == 36 && b1->bit_size == 1);
    SW_CHECK(rx && rx->bit_offset == 56); /* the L2 trigger, after 6 vendor bits */
}

static void ds4_recorded_rest_report(void)
{
    sw_hid_layout parsed, known;
    parse_fixture("ds4_usb.hex", &parsed);
    SW_CHECK(sw_hid_known_layout(0x054C, 0x05C4, &known) != NULL);
    uint8_t rep[64];
    SW_CHECK(hid_fixture("ds4_usb_report1_rest.hex", rep, sizeof rep) == 64);
    for (int pass = 0; pass < 2; pass++) {
        sw_hid_state s;
        sw_hid_state_reset(&s);
        SW_CHECK(sw_hid_decode(pass ? &known : &parsed, rep, 64, &s) >= 20);
        /* The sticks are X Y Z Rz in the descriptor, axes 0 1 3 4 in the known
         * layout; at 0x80 of 0..255 they sit just right of centre. */
        static const int stick_parsed[4] = {0, 1, 2, 5}, stick_known[4] = {0, 1, 3, 4};
        for (int a = 0; a < 4; a++)
            SW_CHECK_NEAR(s.axis[pass ? stick_known[a] : stick_parsed[a]], 2.0 * 128 / 255 - 1,
                          1e-6);
        SW_CHECK_NEAR(s.axis[pass ? 2 : 3], -1, 1e-9); /* the L2 trigger at rest */
        SW_CHECK(s.hat[0] == -1);   /* 8: outside 0..7, the null state */
        SW_CHECK(s.buttons == 0);
    }
}

/* Cross down, hat right, L2 half: the descriptor numbers cross button 2,
 * the known layout (hid-playstation's order) button 0. */
static void ds4_pressed_report_both_layouts(void)
{
    sw_hid_layout parsed, known;
    parse_fixture("ds4_usb.hex", &parsed);
    sw_hid_known_layout(0x054C, 0x05C4, &known);
    uint8_t rep[64] = {0x01, 0x80, 0x80, 0x80, 0x80, 0x22, 0x00, 0x00, 0x80, 0x00};
    sw_hid_state p, k;
    sw_hid_state_reset(&p);
    sw_hid_state_reset(&k);
    sw_hid_decode(&parsed, rep, sizeof rep, &p);
    sw_hid_decode(&known, rep, sizeof rep, &k);
    SW_CHECK(p.buttons == 1u << 1 && k.buttons == 1u << 0);
    SW_CHECK(p.hat[0] == 2 && k.hat[0] == 2);
    SW_CHECK_NEAR(p.axis[3], 2.0 * 128 / 255 - 1, 1e-6); /* Rx in the descriptor */
    SW_CHECK_NEAR(k.axis[2], 2.0 * 128 / 255 - 1, 1e-6); /* a2 = L2 in the known one */
}

static void saitek_flight_stick(void)
{
    sw_hid_layout l;
    parse_fixture("saitek_joystick.hex", &l);
    SW_CHECK(l.application == 4 && l.uses_report_ids);
    SW_CHECK(l.axis_count == 2 && l.button_count == 12 && l.hat_count == 1);
    const sw_hid_field *hat = field(&l, SW_HID_HAT, 0);
    SW_CHECK(hat && hat->bit_offset == 44 && hat->bit_size == 4); /* after a 0-bit pad */
    /* X full left, Y full down, buttons 1 and 12, hat at 6 (left). */
    uint8_t rep[] = {0x01, 0x00, 0xFF, 0x80, 0x80, 0x01, 0x68};
    sw_hid_state s;
    sw_hid_state_reset(&s);
    SW_CHECK(sw_hid_decode(&l, rep, sizeof rep, &s) == 15);
    SW_CHECK_NEAR(s.axis[0], -1, 1e-9);
    SW_CHECK_NEAR(s.axis[1], 1, 1e-9);
    SW_CHECK(s.buttons == (1u << 0 | 1u << 11));
    SW_CHECK(s.hat[0] == 6);
    uint8_t other[] = {0x02, 0x03, 0x7F};  /* report 2: vendor usages only */
    SW_CHECK(sw_hid_decode(&l, other, sizeof other, &s) == 0);
}

static void asus_gamepad_two_byte_usages(void)
{
    sw_hid_layout l;
    parse_fixture("asus_gamepad.hex", &l);
    SW_CHECK(l.application == 5 && l.axis_count == 4 && l.hat_count == 1);
    SW_CHECK(l.button_count == 9);  /* buttons 1 2 4 5 7 8 13 14 15 */
    SW_CHECK(l.sdl_button[2] == 3 && l.sdl_button[6] == 12);
    SW_CHECK(l.sdl_axis[2] == 2 && l.sdl_axis[3] == 5);  /* a2 = Z, a3 = Rz */
    /* Button 4 (third in the report), hat 0 (up), X at 255. */
    uint8_t rep[] = {0x01, 0x04, 0x00, 0xFF, 0x80, 0x80, 0x80, 0x00, 0x00};
    sw_hid_state s;
    sw_hid_state_reset(&s);
    sw_hid_decode(&l, rep, sizeof rep, &s);
    SW_CHECK(s.buttons == 1u << 3);
    SW_CHECK(s.hat[0] == 0);
    SW_CHECK_NEAR(s.axis[0], 1, 1e-9);
}

static void f310_without_report_ids(void)
{
    sw_hid_layout l;
    parse_fixture("logitech_f310_dinput.hex", &l);
    SW_CHECK(l.application == 4 && !l.uses_report_ids);
    SW_CHECK(l.axis_count == 4 && l.button_count == 12 && l.hat_count == 1);
    uint8_t rep[8] = {0x80, 0x00, 0x80, 0xFF, 0x08 | 0x20, 0x08, 0x00, 0x00};
    sw_hid_state s;
    sw_hid_state_reset(&s);
    SW_CHECK(sw_hid_decode(&l, rep, sizeof rep, &s) == 17);
    SW_CHECK(s.hat[0] == -1);                       /* 8: null */
    SW_CHECK(s.buttons == (1u << 1 | 1u << 7));     /* buttons 2 and 8 */
    SW_CHECK_NEAR(s.axis[1], -1, 1e-9);
    SW_CHECK_NEAR(s.axis[5], 1, 1e-9);              /* Rz */
    SW_CHECK(sw_hid_decode(&l, rep, 4, &s) == 4);   /* a short report: the axes only */
}

static void signed_axes(void)
{
    static const uint8_t d[] = {0x05, 0x01, 0x09, 0x05, 0xA1, 0x01, 0x16, 0x01, 0x80, 0x26,
                                0xFF, 0x7F, 0x75, 0x10, 0x95, 0x01, 0x09, 0x30, 0x81, 0x02,
                                0xC0};
    sw_hid_layout l;
    sw_error err = {0};
    SW_CHECK(sw_hid_desc_parse(d, sizeof d, "signed", &l, &err) == SW_OK);
    uint8_t rep[2] = {0x01, 0x80};  /* -32767 */
    sw_hid_state s;
    sw_hid_state_reset(&s);
    sw_hid_decode(&l, rep, 2, &s);
    SW_CHECK_NEAR(s.axis[0], -1, 1e-9);
    rep[0] = 0, rep[1] = 0;
    sw_hid_decode(&l, rep, 2, &s);
    SW_CHECK_NEAR(s.axis[0], 0, 1e-9);
}

static void expect_error(const uint8_t *d, size_t n, const char *needle)
{
    sw_hid_layout l;
    sw_error err = {0};
    SW_CHECK(sw_hid_desc_parse(d, n, "bad.rdesc", &l, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, needle) && !strncmp(err.message, "bad.rdesc: ", 11),
                 "%s (expected '%s')", err.message, needle);
}

static void error_paths(void)
{
    static const uint8_t truncated[] = {0x05, 0x01, 0x26, 0xFF};
    expect_error(truncated, sizeof truncated, "byte 2: an item whose data runs past the end");
    static const uint8_t pop[] = {0xB4};
    expect_error(pop, 1, "Pop without Push");
    static const uint8_t push[] = {0xA4, 0xA4, 0xA4, 0xA4, 0xA4};
    expect_error(push, sizeof push, "byte 4: Push deeper than 4");
    static const uint8_t end[] = {0xC0};
    expect_error(end, 1, "End Collection without a Collection");
    uint8_t deep[40];
    for (int i = 0; i < 20; i++)
        deep[2 * i] = 0xA1, deep[2 * i + 1] = 0x00;
    expect_error(deep, sizeof deep, "byte 32: collections nested deeper than 16");
    static const uint8_t id0[] = {0x85, 0x00};
    expect_error(id0, 2, "Report ID 0");
    static const uint8_t mouse[] = {0x05, 0x01, 0x09, 0x02, 0xA1, 0x01, 0xC0};
    expect_error(mouse, sizeof mouse, "no Joystick, Game Pad");
    static const uint8_t long_input[] = {0x05, 0x01, 0x09, 0x05, 0xA1, 0x01, 0x75, 0x08,
                                         0x96, 0x00, 0x01, 0x81, 0x03, 0xC0};
    expect_error(long_input, sizeof long_input, "longer than 255 bytes");
    static const uint8_t many[] = {0x05, 0x01, 0x09, 0x05, 0xA1, 0x01, 0x09, 0x30, 0x75, 0x08,
                                   0x95, 0x46, 0x81, 0x02, 0xC0};
    expect_error(many, sizeof many, "more than 64");
    static const uint8_t long_item[] = {0xFE, 0x10, 0x00, 0x01};
    expect_error(long_item, sizeof long_item, "a long item past the end");
    static const uint8_t mixed[] = {0x05, 0x01, 0x09, 0x05, 0xA1, 0x01, 0x09, 0x30, 0x75, 0x08,
                                    0x95, 0x01, 0x81, 0x02, 0x85, 0x01, 0x09, 0x31, 0x81, 0x02,
                                    0xC0};
    expect_error(mixed, sizeof mixed, "before the first Report ID");
    static uint8_t huge[SW_HID_DESC_MAX + 1];
    expect_error(huge, sizeof huge, "more than a HID descriptor's 4096");
}

/* Every prefix of every recorded descriptor: an error or a layout, never a
 * crash (the fuzz target does the same under ASan). */
static void every_truncation(void)
{
    static const char *const names[] = {"ds4_usb.hex", "saitek_joystick.hex",
                                        "asus_gamepad.hex", "logitech_f310_dinput.hex"};
    for (int k = 0; k < 4; k++) {
        size_t n = hid_fixture(names[k], desc, sizeof desc);
        int failed = 0;
        for (size_t len = 0; len < n; len++) {
            sw_hid_layout l;
            sw_error err = {0};
            failed += sw_hid_desc_parse(desc, len, names[k], &l, &err) != SW_OK;
        }
        SW_CHECK(failed > 0);
    }
}

int main(int argc, char **argv)
{
    if (argc > 1)
        hid_dir = argv[1];
    SW_RUN(ds4_descriptor_fields);
    SW_RUN(ds4_recorded_rest_report);
    SW_RUN(ds4_pressed_report_both_layouts);
    SW_RUN(saitek_flight_stick);
    SW_RUN(asus_gamepad_two_byte_usages);
    SW_RUN(f310_without_report_ids);
    SW_RUN(signed_axes);
    SW_RUN(error_paths);
    SW_RUN(every_truncation);
    return sw_test_finish();
}
