/* SPDX-License-Identifier: MIT */
/* The Wayland keyboard's keymap and key translation (platform/sw_xkb_keys.h)
 * with a real keymap: the US layout compiled by xkbcommon from
 * xkeyboard-config, written to a file and handed over by descriptor as a
 * compositor hands it (wl_keyboard.keymap), then evdev key codes looked up. */
#include <linux/input-event-codes.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <xkbcommon/xkbcommon.h>

#include "sw_test.h"
#include "sw_xkb_keys.h"

/* A file holding text (with its NUL, as compositors send it); returns its fd. */
static int keymap_file(const char *text, uint32_t *size)
{
    FILE *f = tmpfile();
    *size = (uint32_t)strlen(text) + 1;
    fwrite(text, 1, *size, f);
    fflush(f);
    int fd = dup(fileno(f));
    fclose(f);
    return fd;
}

static char *us_keymap_text(void)
{
    struct xkb_context *ctx = xkb_context_new(XKB_CONTEXT_NO_FLAGS);
    struct xkb_rule_names names = {.rules = "evdev", .model = "pc105", .layout = "us"};
    struct xkb_keymap *map = xkb_keymap_new_from_names(ctx, &names, XKB_KEYMAP_COMPILE_NO_FLAGS);
    char *text = map ? xkb_keymap_get_as_string(map, XKB_KEYMAP_FORMAT_TEXT_V1) : NULL;
    xkb_keymap_unref(map);
    xkb_context_unref(ctx);
    return text;
}

static void without_a_keymap_no_key_has_a_keysym(void)
{
    sw_xkb_keys k;
    SW_CHECK(sw_xkb_keys_init(&k, NULL) == SW_OK);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_A) == 0);
    sw_xkb_keys_destroy(&k);
}

static void the_compositors_keymap_turns_evdev_codes_into_keysyms(void)
{
    char *text = us_keymap_text();
    SW_CHECK(text != NULL);
    if (!text)
        return;
    sw_xkb_keys k;
    sw_error err = {0};
    sw_xkb_keys_init(&k, &err);
    uint32_t size;
    int fd = keymap_file(text, &size);
    sw_status st = sw_xkb_keys_set_keymap(&k, 1, fd, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_A) == XKB_KEY_a);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_ESC) == XKB_KEY_Escape);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_LEFT) == XKB_KEY_Left);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_1) == XKB_KEY_1);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_SPACE) == XKB_KEY_space);
    /* Shift held: still the base level, as X11's XLookupKeysym(ev, 0). */
    sw_xkb_keys_set_modifiers(&k, 1u << xkb_keymap_mod_get_index(k.keymap, XKB_MOD_NAME_SHIFT),
                              0, 0, 0);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_A) == XKB_KEY_a);
    SW_CHECK(sw_xkb_keys_keysym(&k, 0x2ff) == 0);   /* beyond the keymap */
    sw_xkb_keys_destroy(&k);
    free(text);
}

static void a_bad_keymap_is_refused_and_the_old_one_kept(void)
{
    char *text = us_keymap_text();
    sw_xkb_keys k;
    sw_error err = {0};
    sw_xkb_keys_init(&k, &err);
    uint32_t size;
    int fd = keymap_file(text ? text : "", &size);
    sw_xkb_keys_set_keymap(&k, 1, fd, size, &err);
    fd = keymap_file("xkb_keymap { nonsense", &size);
    SW_CHECK(sw_xkb_keys_set_keymap(&k, 1, fd, size, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(!strcmp(err.message, "wayland keyboard: the compositor's keymap does not "
                         "compile"), "%s", err.message);
    SW_CHECK(sw_xkb_keys_keysym(&k, KEY_A) == XKB_KEY_a);
    fd = keymap_file("x", &size);
    SW_CHECK(sw_xkb_keys_set_keymap(&k, 0, fd, size, &err) == SW_ERR_UNSUPPORTED);
    SW_CHECK_MSG(strstr(err.message, "not in the xkb_v1 format") != NULL, "%s", err.message);
    fd = keymap_file("", &size);
    SW_CHECK(sw_xkb_keys_set_keymap(&k, 1, fd, 0, &err) == SW_ERR_IO);   /* nothing to map */
    sw_xkb_keys_destroy(&k);
    free(text);
}

int main(void)
{
    SW_RUN(without_a_keymap_no_key_has_a_keysym);
    SW_RUN(the_compositors_keymap_turns_evdev_codes_into_keysyms);
    SW_RUN(a_bad_keymap_is_refused_and_the_old_one_kept);
    return sw_test_finish();
}
