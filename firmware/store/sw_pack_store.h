/* SPDX-License-Identifier: MIT */
/* The unit's pack store: a directory with two pack slots (A and B), a small
 * state file saying which slot is good, which is pending its first good
 * run, and how often the pending one was started, and, during an install,
 * a journal. Used by seamwalk-flash (install, status, rollback, mark-good)
 * and by seamwalk at boot (--store). The layout, the state file and the
 * journal are described in firmware/store/STORE.md.
 *
 * Every change of the state is one atomic step: the new text goes to
 * state.tmp, is fsynced, renamed over state, and the directory is fsynced,
 * so after a power cut the state is the old one or the new one. The state
 * is kept twice, "state" and then "state.copy", each written that way, so
 * one damaged copy loses nothing; with both damaged a boot starts the
 * newest slot that verifies and `seamwalk-flash repair` rebuilds the state
 * from the slots. A slot that
 * the state calls good or pending is never written; an install writes the
 * other slot and only then, verified, makes it pending. File I/O goes
 * through plain write/pwrite/fsync/rename calls (no stdio), so the tests'
 * fault shim sees each one. */
#ifndef SW_PACK_STORE_H
#define SW_PACK_STORE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_pack_signature.h"

enum { SW_SLOT_NONE = -1, SW_SLOT_A = 0, SW_SLOT_B = 1 };

/* The unit's trusted keys when nothing names them: outside the store, so
 * the unit's own user (who writes the store) cannot change what it trusts. */
#define SW_STORE_DEFAULT_KEYS "/etc/seamwalk/keys"
/* seamwalk-flash reads the unit's config here unless told (--config). */
#define SW_STORE_DEFAULT_CONFIG "/etc/seamwalk/seamwalk.ini"

enum sw_slot_state {
    SW_SLOT_EMPTY = 0,   /* nothing usable: never written, or being written */
    SW_SLOT_PENDING,     /* installed and verified, not yet run healthy */
    SW_SLOT_GOOD,        /* ran healthy (mark-good) */
    SW_SLOT_BAD,         /* failed its boot attempts or was rolled back */
};

typedef struct sw_store_slot {
    enum sw_slot_state state;
    uint64_t version;                  /* the pack's signed version */
    uint64_t size;                     /* bytes of the slot's pack */
    char name[SW_PACK_NAME_BYTES];     /* the pack's signed name */
} sw_store_slot;

typedef struct sw_store_state {
    uint64_t generation;               /* +1 on every write, for status and tests */
    int active;                        /* the good slot that runs, or SW_SLOT_NONE */
    int pending;                       /* the slot to try next boot, or SW_SLOT_NONE */
    uint32_t attempts;                 /* boots of the pending slot so far */
    sw_store_slot slot[2];
} sw_store_state;

/* An install in progress: which pack is going into which slot, and how many
 * of its bytes are known to be on disk. */
typedef struct sw_store_journal {
    int slot;
    uint64_t size;
    uint8_t digest[32];                /* BLAKE2b-256 of the whole pack */
    uint64_t done;                     /* bytes written and fsynced, from the start */
} sw_store_journal;

/* Text of the state file and the journal; each ends with a "check" line,
 * the XXH3-64 of the lines before it. Parsers reject anything else with the
 * line number and what was expected. */
enum { SW_STORE_TEXT_MAX = 1024 };
size_t sw_store_state_format(const sw_store_state *s, char *out, size_t cap);
sw_status sw_store_state_parse(const char *text, size_t size, const char *name,
                               sw_store_state *out, sw_error *err);
size_t sw_store_journal_format(const sw_store_journal *j, char *out, size_t cap);
sw_status sw_store_journal_parse(const char *text, size_t size, const char *name,
                                 sw_store_journal *out, sw_error *err);
const char *sw_slot_state_name(enum sw_slot_state s);
char sw_slot_letter(int slot);         /* 'A', 'B' or '-' */

typedef struct sw_store {
    char dir[3072];
    int lock_fd;                       /* -1 unless locked */
} sw_store;

/* Paths in the store: "state", "state.copy", "journal", "lock", "slot-a.swpack". */
void sw_store_path(const sw_store *s, const char *file, char *out, size_t cap);
void sw_store_slot_path(const sw_store *s, int slot, char *out, size_t cap);

/* Creates dir if missing. No I/O beyond that; lock_fd -1. */
sw_status sw_store_open(sw_store *s, const char *dir, sw_error *err);

/* flock on dir/lock. wait 0: SW_ERR_UNSUPPORTED "busy" at once when another
 * process holds it. The lock file is opened read-only when it cannot be
 * opened for writing (flock needs no write access), so a lock left by root
 * still works for the unit's user. SW_ERR_IO when it cannot be opened at
 * all. Released by sw_store_unlock or when the process ends. */
sw_status sw_store_lock(sw_store *s, int wait, sw_error *err);
void sw_store_unlock(sw_store *s);

/* How the two copies of the state read: for each, whether it is missing,
 * and why it was not used ("" if it was valid). */
enum { SW_STATE_COPIES = 2 };
typedef struct sw_state_copies {
    int used;                          /* the copy read: 0 state, 1 state.copy, -1 none */
    int valid[SW_STATE_COPIES];
    int missing[SW_STATE_COPIES];
    uint64_t generation[SW_STATE_COPIES];  /* of each valid copy */
    char why[SW_STATE_COPIES][400];
} sw_state_copies;
extern const char *const sw_state_copy_names[SW_STATE_COPIES]; /* "state", "state.copy" */

/* Reads both copies and takes the valid one with the higher generation.
 * Both missing: an empty store (generation 0), SW_OK, unless a slot file
 * is there that no install is writing (by the journal): then the state was
 * lost, SW_ERR_FORMAT. No valid copy but one present: the copies' errors,
 * each naming its file. Either error says that seamwalk-flash repair
 * rebuilds the state. copies may be NULL. */
sw_status sw_store_read_state_copies(const sw_store *s, sw_store_state *out,
                                     sw_state_copies *copies, sw_error *err);
sw_status sw_store_read_state(const sw_store *s, sw_store_state *out, sw_error *err);
/* generation + 1, then each copy in turn: write-temp, fsync, rename, fsync
 * the directory. */
sw_status sw_store_write_state(const sw_store *s, sw_store_state *st, sw_error *err);
/* What sw_store_write_state would do up to the rename: the new text to
 * state.tmp, fsynced, then removed. Changes nothing the unit reads. */
sw_status sw_store_probe_state_write(const sw_store *s, const sw_store_state *st,
                                     sw_error *err);

/* What a slot file says of itself, from its header, section table and
 * SIGNATURE record alone (nothing verified, no allocation): version, name,
 * the file's size, state good. A missing or unsigned file: SW_SLOT_EMPTY
 * and why in err. */
sw_status sw_store_peek_slot(const sw_store *s, int slot, sw_store_slot *out, sw_error *err);

sw_status sw_store_read_journal(const sw_store *s, sw_store_journal *out, int *present,
                                sw_error *err);
sw_status sw_store_write_journal(const sw_store *s, const sw_store_journal *j, sw_error *err);
sw_status sw_store_remove_journal(const sw_store *s, sw_error *err);

/* Reads a keys file (sw_trusted_keys_parse, at most 16 KiB) into keys;
 * SW_ERR_FORMAT if it holds none. No allocation, no ownership check. */
sw_status sw_store_read_keys(const char *path, sw_trusted_keys *keys, sw_error *err);

/* The unit's trust anchor: sw_store_read_keys, but only from a file that
 * no one but root can change. The file and every directory above it, on
 * the path as named and as resolved, must be owned by root and writable by
 * neither group nor others (a link: owned by root; a directory with the
 * sticky bit, like /tmp, may be writable by all); else SW_ERR_ARG naming
 * the file or directory, its owner and mode.
 * A file the unit's own user could rewrite would let whoever runs as that
 * user sign the packs it starts. */
sw_status sw_store_read_trusted_keys(const char *path, sw_trusted_keys *keys, sw_error *err);

/* Writes size bytes to path atomically (temp, fsync, rename, fsync dir). */
sw_status sw_store_write_atomic(const char *path, const char *bytes, size_t size, sw_error *err);
sw_status sw_store_sync_dir(const char *dir, sw_error *err);

/* ---- boot ---------------------------------------------------------------- */

/* What to start: slot (or SW_SLOT_NONE), whether it is the pending slot on
 * trial, and the slot to fall back to if it does not load. */
typedef struct sw_boot_choice {
    int slot;
    int trial;
    int fallback;                      /* the good slot, or SW_SLOT_NONE */
    int recovered;                     /* no valid state: the slots newest first, unrecorded */
    uint32_t attempt;                  /* this boot's attempt number when trial */
    char message[1024];                /* what happened, for the log: "" or why */
} sw_boot_choice;

/* The slots to try, in order (the choice, then its fallback); count 0..2. */
int sw_boot_choice_slots(const sw_boot_choice *c, int slots[2]);

/* How slot runs under choice c, for the boot's log and boot-check alike:
 * "good", "pending: boot attempt N", "pending, unrecorded" or
 * "recovered: ...". */
void sw_boot_kind(const sw_boot_choice *c, const sw_store_state *st, int slot, char *out,
                  size_t cap);

/* The decision alone, on a state (no I/O): the pending slot while it has
 * had fewer than max_attempts boots, else the good one. Boots of the good
 * slot are not counted, so power cuts never use up its tries. Changes *st
 * as the boot would record it (attempts + 1, or the pending slot marked bad
 * once its tries are used up); returns 1 when *st changed. */
int sw_store_boot_decide(sw_store_state *st, uint32_t max_attempts, sw_boot_choice *out);

/* At boot: locks, reads the state, decides, records the attempt before the
 * pack is loaded (so a crash or power cut while loading counts), unlocks.
 * No store problem stops a boot: if the lock cannot be taken (an install
 * holds it, never waited for; or the file cannot be opened) or the state
 * cannot be written, a trial is not started: the good slot runs instead
 * (with no good slot, a pending one that has tries left runs unrecorded),
 * and the message says why. With no valid state (both copies damaged or
 * unreadable, or missing beside slot files) the slots are offered newest
 * version first, unrecorded. record 0 (seamwalk-flash boot-check): the
 * same steps, but the write is only probed (sw_store_probe_state_write)
 * and nothing changes. *state: the state the boot goes by (as recorded). */
void sw_store_boot_begin(sw_store *s, uint32_t max_attempts, int record,
                         sw_store_state *state, sw_boot_choice *out);

/* After healthy running: if slot is still the pending one with this
 * version, it becomes the active good slot. Non-blocking: SW_ERR_UNSUPPORTED
 * while an install holds the lock (try again later). Allocates nothing. */
sw_status sw_store_mark_good(sw_store *s, int slot, uint64_t version, sw_error *err);

/* seamwalk-flash rollback: a pending slot is dropped (marked bad); with
 * none pending, the active slot is marked bad and the other good one runs.
 * SW_ERR_ARG "nothing to roll back to" otherwise. */
sw_status sw_store_rollback(sw_store *s, char *said, size_t said_cap, sw_error *err);

#endif
