/* SPDX-License-Identifier: MIT */
/* seamwalk --store: the runtime's side of the pack store (sw_pack_store.h).
 * At start it takes the boot decision (the pending slot on trial, counted
 * before loading, else the good slot), checks the loaded pack's signature
 * against the unit's trusted keys, falls back to the good slot when the
 * trial does not start, and after --good-after-s seconds of healthy frames
 * marks the trial good. Called by seamwalk_main.c: sw_boot_begin before
 * start, sw_boot_check_raw on the slot's bytes before they are parsed, and
 * sw_boot_poll_good after every frame (no allocation there). */
#ifndef SW_BOOT_H
#define SW_BOOT_H

#include <stdint.h>

#include "sw_pack.h"
#include "sw_pack_store.h"

typedef struct sw_boot {
    sw_store store;
    sw_trusted_keys keys;
    sw_store_state state;              /* as it was after this boot was recorded */
    sw_boot_choice choice;
    int slot;                          /* the slot running, SW_SLOT_NONE before or if none */
    int trial;                         /* the running slot is the pending one on trial */
    int marked_good;                   /* 1 marked, -1 marking failed (logged) */
    const char *no_picture;            /* why frames prove nothing (headless): never marked good */
    char pack_path[3200];              /* the slot file being started */
    char log[2560];                    /* what the boot did, for the log and the stats */
} sw_boot;

/* Opens the store, reads the trusted keys (keys_path, or
 * SW_STORE_DEFAULT_KEYS when NULL), records the boot (sw_store_boot_begin:
 * no store problem stops it). A keys file that cannot be read or trusted
 * is not fatal: nothing will start and the log says why. */
void sw_boot_begin(sw_boot *b, const char *dir, const char *keys_path, uint32_t max_attempts);

/* The slots to try, in order (the choice, then its fallback); count 0..2. */
int sw_boot_candidates(const sw_boot *b, int slots[2]);

/* Sets pack_path to slot's file. */
const char *sw_boot_prepare(sw_boot *b, int slot);

/* A slot's raw bytes, before any section is parsed (sw_pack_load_checked):
 * signed by a trusted key, and the version the state has for the slot. */
sw_status sw_boot_check_raw(const sw_boot *b, int slot, const uint8_t *bytes, size_t size,
                            sw_error *err);

/* The slot started: remembers it and adds a line to the log. */
void sw_boot_started(sw_boot *b, int slot);

/* Adds a line to the log (and stderr). */
void sw_boot_note(sw_boot *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The frames show no picture (why: a headless display), so they prove
 * nothing: a trial slot is never marked good in this run (its boot attempt
 * stays counted). Logged once when the running slot is on trial. */
void sw_boot_no_picture(sw_boot *b, const char *why);

/* After a healthy frame, healthy_s seconds into the walk: marks a trial
 * slot good once healthy_s >= good_after_s (retried while the store is
 * busy), never after sw_boot_no_picture. Allocates nothing. */
void sw_boot_poll_good(sw_boot *b, double healthy_s, double good_after_s);

#endif
