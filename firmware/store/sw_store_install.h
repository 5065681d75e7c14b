/* SPDX-License-Identifier: MIT */
/* seamwalk-flash's install into the pack store (sw_pack_store.h): check the
 * pack, write the inactive slot in chunks under a journal (an interrupted
 * install resumes), fsync, read it back and verify every checksum and the
 * signature, then make it pending in one atomic state update. Allocates
 * (the flash tool is not the frame loop); the caller owns the pack bytes. */
#ifndef SW_STORE_INSTALL_H
#define SW_STORE_INSTALL_H

#include <stddef.h>
#include <stdint.h>

#include "sw_pack_store.h"

typedef struct sw_install_options {
    const sw_trusted_keys *keys;       /* required: the unit's trusted keys */
    int allow_downgrade;               /* accept a version older than the active one */
    size_t chunk_bytes;                /* 0: 256 KiB per chunk and journal step */
    void (*progress)(void *user, uint64_t done, uint64_t total); /* may be NULL */
    void *progress_user;
} sw_install_options;

enum sw_install_refusal {
    SW_INSTALL_ACCEPTED = 0,
    SW_INSTALL_INVALID,                /* not a valid pack: truncated, corrupt, bad checksum */
    SW_INSTALL_UNSIGNED,
    SW_INSTALL_UNTRUSTED,              /* signed by a key the unit does not trust */
    SW_INSTALL_TAMPERED,               /* the signature does not match the bytes */
    SW_INSTALL_OLDER,                  /* older than the active pack, no --allow-downgrade */
};

typedef struct sw_install_report {
    enum sw_install_refusal refusal;
    int slot;                          /* the slot written */
    uint64_t version;
    char name[SW_PACK_NAME_BYTES];
    uint64_t resumed_at;               /* bytes kept from an interrupted install, 0 if none */
} sw_install_report;

/* The install. SW_OK: the slot is pending. Otherwise nothing the unit boots
 * has changed: report->refusal says whether the pack was refused, and err
 * why (an I/O error names the file and the call). SW_ERR_UNSUPPORTED "busy"
 * when another process holds the store's lock. */
sw_status sw_store_install(sw_store *s, const uint8_t *pack, size_t size,
                           const sw_install_options *o, sw_install_report *report,
                           sw_error *err);

/* Checks bytes as a pack signed by one of keys: the signature over the raw
 * bytes first (nothing parsed before), then the whole pack validated;
 * *refusal says how it failed. The bytes must be 8-byte aligned. */
sw_status sw_store_check_pack(const uint8_t *bytes, size_t size, const sw_trusted_keys *keys,
                              const sw_pack_signature **sig, enum sw_install_refusal *refusal,
                              sw_error *err);

/* Reads a slot's file and checks it against keys and what the state says
 * of it (size, version). */
sw_status sw_store_verify_slot(const sw_store *s, int slot, const sw_store_slot *expect,
                               const sw_trusted_keys *keys, sw_error *err);

#endif
