/* SPDX-License-Identifier: MIT */
#include "sw_xkb_keys.h"

#include <errno.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include <xkbcommon/xkbcommon.h>

sw_status sw_xkb_keys_init(sw_xkb_keys *k, sw_error *err)
{
    memset(k, 0, sizeof *k);
    k->context = xkb_context_new(XKB_CONTEXT_NO_FLAGS);
    if (!k->context)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "wayland keyboard: xkb_context_new failed");
    return SW_OK;
}

sw_status sw_xkb_keys_set_keymap(sw_xkb_keys *k, int xkb_v1, int fd, uint32_t size,
                                 sw_error *err)
{
    if (!xkb_v1) {
        close(fd);
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "wayland keyboard: the keymap is not "
                            "in the xkb_v1 format");
    }
    /* MAP_PRIVATE: from wl_seat version 7 the compositor may share one
     * read-only file among clients. */
    char *text = size ? mmap(NULL, size, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
    int map_errno = errno;
    close(fd);
    if (text == MAP_FAILED)
        return sw_error_set(err, SW_ERR_IO, "wayland keyboard: cannot map the keymap (%u "
                            "bytes): %s", size, strerror(map_errno));
    /* The text ends in a NUL inside size; new_from_buffer would count it. */
    struct xkb_keymap *map = xkb_keymap_new_from_buffer(k->context, text, strnlen(text, size),
                                                        XKB_KEYMAP_FORMAT_TEXT_V1,
                                                        XKB_KEYMAP_COMPILE_NO_FLAGS);
    munmap(text, size);
    if (!map)
        return sw_error_set(err, SW_ERR_FORMAT, "wayland keyboard: the compositor's keymap "
                            "does not compile");
    struct xkb_state *state = xkb_state_new(map);
    if (!state) {
        xkb_keymap_unref(map);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "wayland keyboard: xkb_state_new failed");
    }
    xkb_state_unref(k->state);
    xkb_keymap_unref(k->keymap);
    k->keymap = map;
    k->state = state;
    return SW_OK;
}

void sw_xkb_keys_set_modifiers(sw_xkb_keys *k, uint32_t depressed, uint32_t latched,
                               uint32_t locked, uint32_t group)
{
    if (k->state)
        xkb_state_update_mask(k->state, depressed, latched, locked, 0, 0, group);
}

uint32_t sw_xkb_keys_keysym(const sw_xkb_keys *k, uint32_t evdev_code)
{
    if (!k->state)
        return 0;
    /* XKB key codes are evdev's plus 8, the X11 convention. */
    xkb_keycode_t code = evdev_code + 8;
    xkb_layout_index_t layout = xkb_state_key_get_layout(k->state, code);
    if (layout == XKB_LAYOUT_INVALID)
        return 0;
    const xkb_keysym_t *syms = NULL;
    int n = xkb_keymap_key_get_syms_by_level(k->keymap, code, layout, 0, &syms);
    return n > 0 ? syms[0] : 0;
}

void sw_xkb_keys_destroy(sw_xkb_keys *k)
{
    xkb_state_unref(k->state);
    xkb_keymap_unref(k->keymap);
    xkb_context_unref(k->context);
    memset(k, 0, sizeof *k);
}
