/* SPDX-License-Identifier: MIT */
/* The Wayland window's keyboard (sw_display_wayland.c): the keymap the
 * compositor sends with wl_keyboard.keymap (XKB text in a shared file) and
 * the translation of its key codes (evdev numbers) into X11/XKB keysyms, the
 * numbers sw_key_queue.h carries. Apart from the listener so it is tested
 * with a real keymap and no compositor (tests/test_xkb_keys.c). GL thread. */
#ifndef SW_XKB_KEYS_H
#define SW_XKB_KEYS_H

#include <stdint.h>

#include "sw_error.h"

typedef struct sw_xkb_keys {
    void *context;   /* struct xkb_context * */
    void *keymap;    /* struct xkb_keymap *; NULL until a keymap came */
    void *state;     /* struct xkb_state * */
} sw_xkb_keys;

sw_status sw_xkb_keys_init(sw_xkb_keys *k, sw_error *err);

/* wl_keyboard.keymap: xkb_v1 says the format is WL_KEYBOARD_KEYMAP_FORMAT_XKB_V1;
 * fd holds size bytes of keymap text and is closed here whatever happens. A
 * keymap that does not compile keeps the previous one. */
sw_status sw_xkb_keys_set_keymap(sw_xkb_keys *k, int xkb_v1, int fd, uint32_t size,
                                 sw_error *err);

/* wl_keyboard.modifiers: the layout group can change what a key means. */
void sw_xkb_keys_set_modifiers(sw_xkb_keys *k, uint32_t depressed, uint32_t latched,
                               uint32_t locked, uint32_t group);

/* The keysym of an evdev key code at the base level (unshifted, as X11's
 * XLookupKeysym(ev, 0) gives it); 0 without a keymap or for a code the
 * keymap lacks. */
uint32_t sw_xkb_keys_keysym(const sw_xkb_keys *k, uint32_t evdev_code);

void sw_xkb_keys_destroy(sw_xkb_keys *k);

#endif
