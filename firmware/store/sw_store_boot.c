/* SPDX-License-Identifier: MIT */
/* Which slot a unit starts, and the state changes around a boot: counting
 * the pending slot's attempts, giving up on it, mark-good and rollback
 * (sw_pack_store.h). */
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "sw_pack_store.h"

int sw_store_boot_decide(sw_store_state *st, uint32_t max_attempts, sw_boot_choice *out)
{
    *out = (sw_boot_choice){ .slot = st->active, .fallback = SW_SLOT_NONE };
    if (st->pending == SW_SLOT_NONE)
        return 0;
    int p = st->pending;
    if (st->attempts < max_attempts) {
        st->attempts++;
        *out = (sw_boot_choice){ .slot = p, .trial = 1, .fallback = st->active,
                                 .attempt = st->attempts };
        return 1;
    }
    snprintf(out->message, sizeof out->message, "slot %c ('%s' version %" PRIu64 ") did not "
             "run healthy in %" PRIu32 " boots: falling back to %s%c", sw_slot_letter(p),
             st->slot[p].name, st->slot[p].version, st->attempts,
             st->active == SW_SLOT_NONE ? "no slot " : "slot ", sw_slot_letter(st->active));
    st->slot[p].state = SW_SLOT_BAD;
    st->pending = SW_SLOT_NONE;
    st->attempts = 0;
    return 1;
}

int sw_boot_choice_slots(const sw_boot_choice *c, int slots[2])
{
    int n = 0;
    if (c->slot != SW_SLOT_NONE)
        slots[n++] = c->slot;
    if ((c->trial || c->recovered) && c->fallback != SW_SLOT_NONE && c->fallback != c->slot)
        slots[n++] = c->fallback;
    return n;
}

void sw_boot_kind(const sw_boot_choice *c, const sw_store_state *st, int slot, char *out,
                  size_t cap)
{
    if (c->recovered)
        snprintf(out, cap, "recovered: no valid state, the newest slot that verifies");
    else if (slot == c->slot && c->trial)
        snprintf(out, cap, "pending: boot attempt %" PRIu32, c->attempt);
    else if (slot != SW_SLOT_NONE && st->slot[slot].state == SW_SLOT_PENDING)
        snprintf(out, cap, "pending, unrecorded");
    else
        snprintf(out, cap, "good");
}

/* Appends "; " (unless the message is empty) and a formatted note. */
static void say(sw_boot_choice *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void say(sw_boot_choice *c, const char *fmt, ...)
{
    size_t n = strlen(c->message);
    if (n + 3 >= sizeof c->message)
        return;
    if (n > 0) {
        memcpy(c->message + n, "; ", 2);
        n += 2;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->message + n, sizeof c->message - n, fmt, ap);
    va_end(ap);
}

/* The decision cannot be recorded (why): no trial starts. The good slot
 * runs; with none, a pending slot that has tries left runs unrecorded
 * rather than nothing, since it verified when it was installed. */
static void start_unrecorded(sw_boot_choice *c, const sw_store_state *st, uint32_t max_attempts,
                             const char *why)
{
    char said[sizeof c->message];
    snprintf(said, sizeof said, "%s", c->message);
    int p = st->pending;
    int slot = st->active != SW_SLOT_NONE ? st->active
               : p != SW_SLOT_NONE && st->attempts < max_attempts ? p : SW_SLOT_NONE;
    *c = (sw_boot_choice){ .slot = slot, .fallback = SW_SLOT_NONE };
    if (said[0])
        say(c, "%s", said);
    if (slot == SW_SLOT_NONE)
        say(c, "%s: no slot can start without recording it", why);
    else if (slot == st->active)
        say(c, "%s: starting the good slot, no trial", why);
    else
        say(c, "%s: no good slot, so the pending slot starts unrecorded", why);
}

/* No valid state: every slot file that carries a signature record, newest
 * version first; each is verified in full before it starts. */
static void recover(sw_store *s, sw_store_state *st, sw_boot_choice *c, const char *why)
{
    *st = (sw_store_state){ .active = SW_SLOT_NONE, .pending = SW_SLOT_NONE };
    sw_error ignored = { 0 };
    for (int i = 0; i < 2; i++)
        if (sw_store_peek_slot(s, i, &st->slot[i], &ignored) != SW_OK)
            st->slot[i] = (sw_store_slot){ .state = SW_SLOT_EMPTY };
    int a = st->slot[0].state == SW_SLOT_GOOD, b = st->slot[1].state == SW_SLOT_GOOD;
    int first = a && (!b || st->slot[0].version >= st->slot[1].version) ? SW_SLOT_A
                : b ? SW_SLOT_B : SW_SLOT_NONE;
    int second = first == SW_SLOT_NONE ? SW_SLOT_NONE
                 : st->slot[1 - first].state == SW_SLOT_GOOD ? 1 - first : SW_SLOT_NONE;
    st->active = first;
    *c = (sw_boot_choice){ .slot = first, .fallback = second, .recovered = 1 };
    say(c, "%.900s: starting the newest slot that verifies, unrecorded", why);
}

/* The state read, noted in the choice when a copy was not usable. 0: no
 * valid state (recovered instead). */
static int read_for_boot(sw_store *s, sw_store_state *st, sw_boot_choice *c)
{
    sw_state_copies copies;
    sw_error err = { 0 };
    char why[1000];
    if (sw_store_read_state_copies(s, st, &copies, &err) != SW_OK) {
        snprintf(why, sizeof why, "%s", err.message);
        recover(s, st, c, why);
        return 0;
    }
    for (int i = 0; i < SW_STATE_COPIES && copies.used >= 0; i++)
        if (!copies.valid[i])
            say(c, "%s: using %s (seamwalk-flash repair rewrites the other)", copies.why[i],
                sw_state_copy_names[copies.used]);
    return 1;
}

void sw_store_boot_begin(sw_store *s, uint32_t max_attempts, int record,
                         sw_store_state *state, sw_boot_choice *out)
{
    sw_error lock_err = { 0 }, werr = { 0 };
    sw_boot_choice notes = { .slot = SW_SLOT_NONE, .fallback = SW_SLOT_NONE };
    /* An install that holds the lock is never waited for: the screen must
     * come up. Unlocked, the state is only read (its renames are atomic). */
    sw_status locked = sw_store_lock(s, 0, &lock_err);
    sw_store_state st;
    if (!read_for_boot(s, &st, &notes)) {
        *out = notes;
        *state = st;
        sw_store_unlock(s);
        return;
    }
    sw_store_state after = st;
    int changed = sw_store_boot_decide(&after, max_attempts, out);
    if (notes.message[0])
        say(out, "%s", notes.message);
    sw_status wrote = SW_OK;
    if (changed && locked == SW_OK)
        wrote = record ? sw_store_write_state(s, &after, &werr)
                       : sw_store_probe_state_write(s, &after, &werr);
    sw_store_unlock(s);
    char why[600];
    if (changed && locked != SW_OK) {
        snprintf(why, sizeof why, "%s", locked == SW_ERR_UNSUPPORTED
                 ? "the store is busy (an install is running)" : lock_err.message);
        start_unrecorded(out, &st, max_attempts, why);
    } else if (changed && wrote != SW_OK) {
        /* Unrecorded trials could crash-loop for ever. */
        snprintf(why, sizeof why, "cannot record the boot (%.500s)", werr.message);
        start_unrecorded(out, &st, max_attempts, why);
    } else if (locked != SW_OK && locked != SW_ERR_UNSUPPORTED) {
        say(out, "%s: nothing recorded", lock_err.message);
    }
    *state = changed && locked == SW_OK && wrote == SW_OK ? after : st;
}

sw_status sw_store_mark_good(sw_store *s, int slot, uint64_t version, sw_error *err)
{
    sw_store_state st;
    sw_status rc = sw_store_lock(s, 0, err);
    if (rc != SW_OK)
        return rc;
    if ((rc = sw_store_read_state(s, &st, err)) == SW_OK) {
        if (slot == SW_SLOT_NONE || st.pending != slot || st.slot[slot].version != version)
            rc = sw_error_set(err, SW_ERR_ARG, "%s: slot %c version %" PRIu64 " is not the "
                              "pending slot (pending: %c)", s->dir, sw_slot_letter(slot),
                              version, sw_slot_letter(st.pending));
    }
    if (rc == SW_OK) {
        st.slot[slot].state = SW_SLOT_GOOD;
        st.active = slot;
        st.pending = SW_SLOT_NONE;
        st.attempts = 0;
        rc = sw_store_write_state(s, &st, err);
    }
    sw_store_unlock(s);
    return rc;
}

static sw_status roll_back(sw_store_state *st, const char *dir, char *said, size_t cap,
                           sw_error *err)
{
    if (st->pending != SW_SLOT_NONE) {
        int p = st->pending;
        snprintf(said, cap, "dropped pending slot %c ('%s' version %" PRIu64 "); slot %c "
                 "stays active", sw_slot_letter(p), st->slot[p].name, st->slot[p].version,
                 sw_slot_letter(st->active));
        st->slot[p].state = SW_SLOT_BAD;
        st->pending = SW_SLOT_NONE;
        st->attempts = 0;
        return SW_OK;
    }
    int a = st->active, other = a == SW_SLOT_NONE ? SW_SLOT_NONE : 1 - a;
    if (other == SW_SLOT_NONE || st->slot[other].state != SW_SLOT_GOOD)
        return sw_error_set(err, SW_ERR_ARG, "%s: nothing to roll back to (no pending slot, "
                            "and no other good slot)", dir);
    snprintf(said, cap, "slot %c ('%s' version %" PRIu64 ") is active again; slot %c marked "
             "bad", sw_slot_letter(other), st->slot[other].name, st->slot[other].version,
             sw_slot_letter(a));
    st->slot[a].state = SW_SLOT_BAD;
    st->active = other;
    return SW_OK;
}

sw_status sw_store_rollback(sw_store *s, char *said, size_t said_cap, sw_error *err)
{
    sw_store_state st;
    sw_status rc = sw_store_lock(s, 0, err);
    if (rc != SW_OK)
        return rc;
    if ((rc = sw_store_read_state(s, &st, err)) == SW_OK &&
        (rc = roll_back(&st, s->dir, said, said_cap, err)) == SW_OK)
        rc = sw_store_write_state(s, &st, err);
    sw_store_unlock(s);
    return rc;
}
