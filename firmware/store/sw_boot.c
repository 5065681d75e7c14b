/* SPDX-License-Identifier: MIT */
/* The runtime's side of the pack store (sw_boot.h). */
#include "sw_boot.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void sw_boot_note(sw_boot *b, const char *fmt, ...)
{
    size_t n = strlen(b->log);
    if (n + 2 >= sizeof b->log)
        return;
    if (n > 0)
        b->log[n++] = '\n';
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(b->log + n, sizeof b->log - n, fmt, ap);
    va_end(ap);
    fprintf(stderr, "seamwalk: store: %s\n", b->log + n);
}

void sw_boot_begin(sw_boot *b, const char *dir, const char *keys_path, uint32_t max_attempts)
{
    memset(b, 0, sizeof *b);
    b->slot = b->choice.slot = b->choice.fallback = SW_SLOT_NONE;
    sw_error err = { 0 };
    sw_status st = sw_store_open(&b->store, dir, &err);
    if (st == SW_OK)
        st = sw_store_read_trusted_keys(keys_path ? keys_path : SW_STORE_DEFAULT_KEYS, &b->keys,
                                        &err);
    if (st != SW_OK) {
        sw_boot_note(b, "%s", err.message);
        return;
    }
    sw_store_boot_begin(&b->store, max_attempts, 1, &b->state, &b->choice);
    if (b->choice.message[0])
        sw_boot_note(b, "%s", b->choice.message);
}

int sw_boot_candidates(const sw_boot *b, int slots[2])
{
    return sw_boot_choice_slots(&b->choice, slots);
}

const char *sw_boot_prepare(sw_boot *b, int slot)
{
    sw_store_slot_path(&b->store, slot, b->pack_path, sizeof b->pack_path);
    return b->pack_path;
}

sw_status sw_boot_check_raw(const sw_boot *b, int slot, const uint8_t *bytes, size_t size,
                            sw_error *err)
{
    sw_pack_signature sig;
    sw_status st = sw_pack_check_signature_raw(bytes, size, &b->keys, &sig, err);
    if (st != SW_OK)
        return st;
    if (sig.pack_version != b->state.slot[slot].version)
        return sw_error_set(err, SW_ERR_FORMAT, "slot %c holds version %" PRIu64 ", the state "
                            "says %" PRIu64, sw_slot_letter(slot), sig.pack_version,
                            b->state.slot[slot].version);
    return SW_OK;
}

void sw_boot_started(sw_boot *b, int slot)
{
    const sw_store_slot *s = &b->state.slot[slot];
    char kind[128];
    b->slot = slot;
    b->trial = slot == b->choice.slot && b->choice.trial;
    sw_boot_kind(&b->choice, &b->state, slot, kind, sizeof kind);
    sw_boot_note(b, "starting slot %c ('%s' version %" PRIu64 "), %s", sw_slot_letter(slot),
                 s->name, s->version, kind);
}

void sw_boot_no_picture(sw_boot *b, const char *why)
{
    b->no_picture = why;
    if (b->trial)
        sw_boot_note(b, "slot %c stays pending: %s, so no frame shows that it works",
                     sw_slot_letter(b->slot), why);
}

void sw_boot_poll_good(sw_boot *b, double healthy_s, double good_after_s)
{
    if (!b->trial || b->marked_good || b->no_picture || healthy_s < good_after_s)
        return;
    sw_error err = { 0 };
    sw_status st = sw_store_mark_good(&b->store, b->slot, b->state.slot[b->slot].version, &err);
    if (st == SW_ERR_UNSUPPORTED)
        return; /* an install holds the lock: next frame */
    b->marked_good = st == SW_OK ? 1 : -1;
    if (st == SW_OK)
        sw_boot_note(b, "slot %c ran healthy for %.1f s: marked good", sw_slot_letter(b->slot),
                     healthy_s);
    else
        sw_boot_note(b, "cannot mark slot %c good: %s", sw_slot_letter(b->slot), err.message);
}
