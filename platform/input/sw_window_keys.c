/* SPDX-License-Identifier: MIT */
/* The keyboard backend of a developer window (sw_input_backend.h): the key
 * events an X11 or Wayland window queued (platform/sw_key_queue.h, as X11/XKB
 * keysyms) handed to the input step as the Linux KEY_* codes the kiosk's key
 * table speaks, so a developer drives --navigate from the window's keyboard
 * exactly as a kiosk's evdev keyboard does. A window's keyboard never goes
 * away; keysyms without a KEY_* here are skipped (the table covers every key
 * sw_kiosk.c acts on, and the rest of the letters and digits). The window
 * does not auto-repeat (sw_display.h), so no repeat values come. */
#include <linux/input.h>
#include <stddef.h>

#include "sw_window_keys.h"

typedef struct keysym_code {
    uint32_t keysym;
    int code;
} keysym_code;

/* Linux's KEY_* numbers follow the keyboard's rows, not the alphabet. */
static const int letter_codes[26] = {
    KEY_A, KEY_B, KEY_C, KEY_D, KEY_E, KEY_F, KEY_G, KEY_H, KEY_I, KEY_J, KEY_K, KEY_L, KEY_M,
    KEY_N, KEY_O, KEY_P, KEY_Q, KEY_R, KEY_S, KEY_T, KEY_U, KEY_V, KEY_W, KEY_X, KEY_Y, KEY_Z,
};

static const keysym_code named_codes[] = {
    {0xff51, KEY_LEFT},     {0xff52, KEY_UP},        {0xff53, KEY_RIGHT},
    {0xff54, KEY_DOWN},     {0xff55, KEY_PAGEUP},    {0xff56, KEY_PAGEDOWN},
    {0xff50, KEY_HOME},     {0xff57, KEY_END},       {0xff08, KEY_BACKSPACE},
    {0xff0d, KEY_ENTER},    {0xff1b, KEY_ESC},       {0x0020, KEY_SPACE},
    {0xff09, KEY_TAB},
};

int sw_window_keysym_code(uint32_t keysym)
{
    if (keysym >= 'A' && keysym <= 'Z')
        keysym += 'a' - 'A';
    if (keysym >= 'a' && keysym <= 'z')
        return letter_codes[keysym - 'a'];
    if (keysym == '0')
        return KEY_0;
    if (keysym >= '1' && keysym <= '9')
        return KEY_1 + (int)(keysym - '1');
    for (size_t i = 0; i < sizeof named_codes / sizeof named_codes[0]; i++)
        if (named_codes[i].keysym == keysym)
            return named_codes[i].code;
    return -1;
}

static int window_open(void *ctx, const char *device, sw_error *err)
{
    (void)device;
    const sw_display *d = ctx;
    if (sw_window_has_keyboard(d))
        return 0;
    sw_error_set(err, SW_ERR_UNSUPPORTED, "the %s display has no window keyboard",
                 sw_display_kind_name(d->kind));
    return -1;
}

static int window_read(void *ctx, int *code, int *value)
{
    sw_key_event ev;
    while (sw_display_poll_keys(ctx, &ev, 1) == 1) {
        int c = sw_window_keysym_code(ev.keysym);
        if (c < 0)
            continue;
        *code = c;
        *value = ev.pressed ? 1 : 0;
        return 1;
    }
    return 0;
}

static void window_close(void *ctx) { (void)ctx; }

sw_key_backend sw_window_key_backend(sw_display *display)
{
    return (sw_key_backend){display, window_open, window_read, window_close};
}

int sw_window_has_keyboard(const sw_display *display)
{
    return display && (display->kind == SW_DISPLAY_KIND_X11 ||
                       display->kind == SW_DISPLAY_KIND_WAYLAND);
}
