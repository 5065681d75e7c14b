/* SPDX-License-Identifier: MIT */
/* gamecontrollerdb mappings (sw_gamepad_map.h): SDL's GUID, SDL's own line
 * for the F310's D mode applied to a recorded-layout report, the grammar's
 * half axes and inversion, the dead zone, and every bad line. Argument:
 * tests/hid. */
#include <string.h>

#include "hid_fixture.h"
#include "sw_gamepad_map.h"
#include "sw_test.h"

static sw_pad_mapping_db db;

static void guid_as_sdl_builds_it(void)
{
    uint8_t g[16];
    sw_pad_guid(0x0003, 0x046D, 0xC216, 0x0110, g);
    static const uint8_t want[16] = {0x03, 0, 0, 0, 0x6D, 0x04, 0, 0, 0x16, 0xC2, 0, 0,
                                     0x10, 0x01, 0, 0};
    SW_CHECK(!memcmp(g, want, 16)); /* 030000006d04000016c2000010010000 */
}

static sw_status load_db(const char *text, sw_error *err)
{
    return sw_pad_mapping_db_parse(text, strlen(text), "pads.db", &db, err);
}

static void sdl_line_pastes_in(void)
{
    char path[512];
    snprintf(path, sizeof path, "%s/logitech_dual_action.gamecontrollerdb", hid_dir);
    sw_error err = {0};
    SW_CHECK_MSG(sw_pad_mapping_db_load(path, &db, &err) == SW_OK, "%s", err.message);
    SW_CHECK(db.count == 1); /* the Windows line is skipped */
    uint8_t g[16];
    sw_pad_guid(3, 0x046D, 0xC216, 0x0110, g);
    const sw_pad_mapping *m = sw_pad_mapping_find(&db, g);
    SW_CHECK(m && !strcmp(m->name, "Logitech Dual Action") && m->binding_count == 20);
    sw_pad_guid(3, 0x046D, 0xC216, 0x0300, g);  /* another version: still found */
    SW_CHECK(sw_pad_mapping_find(&db, g) == m);
    sw_pad_guid(3, 0x046D, 0xC21D, 0x0110, g);
    SW_CHECK(sw_pad_mapping_find(&db, g) == NULL);
    /* The F310's descriptor through SDL's line: button 2 is 'a', Z is rightx,
     * hat right is dpright, button 7 the left trigger. */
    uint8_t d[512];
    size_t n = hid_fixture("logitech_f310_dinput.hex", d, sizeof d);
    sw_hid_layout l;
    SW_CHECK(sw_hid_desc_parse(d, n, "f310", &l, &err) == SW_OK);
    /* Payload byte 4: the hat in bits 0-3, buttons 1-4 above; byte 5: 5-12. */
    uint8_t rep[8] = {0x80, 0x80, 0xFF, 0x80, 0x02 | 0x20, 0x00, 0x00, 0x00};
    sw_hid_state s;
    sw_hid_state_reset(&s);
    sw_hid_decode(&l, rep, 8, &s);
    sw_pad_state ps;
    sw_pad_apply(m, &l, &s, &ps);
    SW_CHECK(ps.buttons == (1u << SW_PAD_A | 1u << SW_PAD_DPRIGHT));
    SW_CHECK_NEAR(ps.axis[SW_PAD_RIGHTX], 1, 1e-6);
    rep[4] = 0x08;              /* hat null, buttons 1-4 up */
    rep[5] = 0x04;              /* button 7: lefttrigger:b6 */
    sw_hid_decode(&l, rep, 8, &s);
    sw_pad_apply(m, &l, &s, &ps);
    SW_CHECK(ps.buttons == 0);
    SW_CHECK_NEAR(ps.axis[SW_PAD_LEFTTRIGGER], 1, 1e-9);
}

static void halves_inversion_and_hat_masks(void)
{
    static sw_hid_layout l;
    memset(&l, 0, sizeof l);
    l.axis_count = 2, l.sdl_axis[0] = 0, l.sdl_axis[1] = 1;
    l.button_count = 1, l.sdl_button[0] = 0, l.hat_count = 1;
    sw_pad_mapping m;
    static const char b[] = "-leftx:-a0,+leftx:+a0,righttrigger:a1~,lefttrigger:b0,"
                            "dpup:h0.1,dpleft:h0.8,+righty:b0,misc1:b0,crc:1234,platform:Linux";
    sw_error err = {0};
    SW_CHECK(sw_pad_mapping_parse_bindings(b, sizeof b - 1, "x", 1, &m, &err) == SW_OK);
    SW_CHECK(m.binding_count == 7);
    sw_hid_state s;
    sw_hid_state_reset(&s);
    s.axis[0] = -0.5f, s.axis[1] = -1, s.buttons = 1, s.hat[0] = 7; /* up-left */
    sw_pad_state ps;
    sw_pad_apply(&m, &l, &s, &ps);
    SW_CHECK_NEAR(ps.axis[SW_PAD_LEFTX], -0.5, 1e-6);
    SW_CHECK_NEAR(ps.axis[SW_PAD_RIGHTTRIGGER], 1, 1e-6); /* inverted: -1 -> full */
    SW_CHECK_NEAR(ps.axis[SW_PAD_LEFTTRIGGER], 1, 1e-6);
    SW_CHECK_NEAR(ps.axis[SW_PAD_RIGHTY], 1, 1e-6);
    SW_CHECK(ps.buttons == (1u << SW_PAD_DPUP | 1u << SW_PAD_DPLEFT));
}

static void radial_dead_zone(void)
{
    sw_pad_state s = {{0.1f, 0.1f, 1.0f, 0, 0, 0}, 0};
    sw_pad_dead_zone(&s, 0.15f);
    SW_CHECK(s.axis[SW_PAD_LEFTX] == 0 && s.axis[SW_PAD_LEFTY] == 0); /* |v| 0.141 < 0.15 */
    SW_CHECK_NEAR(s.axis[SW_PAD_RIGHTX], 1, 1e-6);
    sw_pad_state h = {{0.5f, 0, 0, 0, 0, 0}, 0};
    sw_pad_dead_zone(&h, 0.15f);
    SW_CHECK_NEAR(h.axis[SW_PAD_LEFTX], (0.5 - 0.15) / 0.85, 1e-6);
    sw_pad_state d = {{0.6f, 0.8f, 0, 0, 0, 0}, 0}; /* radius 1, direction kept */
    sw_pad_dead_zone(&d, 0.15f);
    SW_CHECK_NEAR(d.axis[SW_PAD_LEFTX], 0.6, 1e-6);
    SW_CHECK_NEAR(d.axis[SW_PAD_LEFTY], 0.8, 1e-6);
}

static void expect_bad(const char *text, const char *needle)
{
    sw_error err = {0};
    SW_CHECK(load_db(text, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, needle) != NULL, "%s (expected '%s')", err.message, needle);
}

static void bad_lines(void)
{
    static const char guid[] = "030000006d04000016c2000010010000";
    char line[256];
    expect_bad("# ok\n\nno commas here\n", "pads.db:3: expected GUID,name,bindings");
    expect_bad("030000006d04000016c200001001000,x,a:b0\n", "pads.db:1: expected a GUID of 32");
    expect_bad("030000006d04000016c20000100100zz,x,a:b0\n", "expected a GUID of 32 hex");
    snprintf(line, sizeof line, "%s,x,foo:b0\n", guid);
    expect_bad(line, "expected a gamepad button or axis name");
    snprintf(line, sizeof line, "%s,x,a:x1\n", guid);
    expect_bad(line, "pads.db:1: expected bN, [+-]aN[~] or hN.M");
    snprintf(line, sizeof line, "%s,x,a:h0.0\n", guid);
    expect_bad(line, "got 'h0.0'");
    snprintf(line, sizeof line, "%s,x,a:h0.16\n", guid);
    expect_bad(line, "got 'h0.16'");
    snprintf(line, sizeof line, "%s,x,a:b999\n", guid);
    expect_bad(line, "got 'b999'");
    snprintf(line, sizeof line, "%s,x,a:+b1\n", guid);
    expect_bad(line, "got '+b1'");
    snprintf(line, sizeof line, "%s,x,+a:b1\n", guid);
    expect_bad(line, "button or axis name");
    snprintf(line, sizeof line, "%s,x,ab0\n", guid);
    expect_bad(line, "expected OUTPUT:INPUT");
    static const char nul[] = "0300\0\n";
    sw_error err = {0};
    SW_CHECK(sw_pad_mapping_db_parse(nul, sizeof nul - 1, "pads.db", &db, &err) ==
             SW_ERR_FORMAT && strstr(err.message, "NUL"));
    static char many[129 * 64];
    size_t used = 0;
    for (int i = 0; i < 129; i++)
        used += (size_t)snprintf(many + used, sizeof many - used, "%s,p%d,a:b0\n", guid, i);
    expect_bad(many, "pads.db:129: expected at most 128 Linux mappings");
}

int main(int argc, char **argv)
{
    if (argc > 1)
        hid_dir = argv[1];
    SW_RUN(guid_as_sdl_builds_it);
    SW_RUN(sdl_line_pastes_in);
    SW_RUN(halves_inversion_and_hat_masks);
    SW_RUN(radial_dead_zone);
    SW_RUN(bad_lines);
    return sw_test_finish();
}
