/* Which slot a unit starts, and the state changes around a boot: counting
 * the pending slot's attempts, giving up on it, mark-good and rollback
 * (sw_pack_store.h). */
#include <inttypes.h>
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

sw_status sw_store_boot_begin(sw_store *s, uint32_t max_attempts, sw_boot_choice *out,
                              sw_error *err)
{
    sw_store_state st;
    sw_status rc = sw_store_lock(s, 0, err);
    if (rc == SW_ERR_UNSUPPORTED) {
        /* An install is running: the screen must not wait for it, and a
         * trial that cannot be recorded must not start. The state is read
         * unlocked; its renames are atomic. */
        if ((rc = sw_store_read_state(s, &st, err)) != SW_OK)
            return rc;
        *out = (sw_boot_choice){ .slot = st.active, .fallback = SW_SLOT_NONE };
        snprintf(out->message, sizeof out->message, "the store is busy (an install is "
                 "running): starting the good slot, no trial");
        return SW_OK;
    }
    if (rc != SW_OK)
        return rc;
    if ((rc = sw_store_read_state(s, &st, err)) != SW_OK) {
        sw_store_unlock(s);
        return rc;
    }
    sw_store_state before = st;
    if (sw_store_boot_decide(&st, max_attempts, out)) {
        sw_error werr = { 0 };
        if (sw_store_write_state(s, &st, &werr) != SW_OK) {
            /* Unrecorded trials could crash-loop for ever: run the good slot. */
            char said[sizeof out->message];
            snprintf(said, sizeof said, "%s", out->message);
            *out = (sw_boot_choice){ .slot = before.active, .fallback = SW_SLOT_NONE };
            snprintf(out->message, sizeof out->message, "%.250s%scannot record the boot "
                     "(%.300s): starting the good slot", said, *said ? "; " : "", werr.message);
        }
    }
    sw_store_unlock(s);
    return SW_OK;
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
