/* SPDX-License-Identifier: MIT */
/* Host side of signed packs: ed25519 key pairs (libsodium) in key files, and
 * re-writing a pack with a SIGNATURE section (core/sw_pack_signature.h has the
 * record and the check). Used by seamwalk-pack keygen / sign / verify --key.
 * Host only: allocates, and the caller frees what it gets. */
#ifndef SW_PACK_SIGN_HOST_H
#define SW_PACK_SIGN_HOST_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_pack_signature.h"

enum { SW_SECRET_KEY_BYTES = 64 };   /* libsodium's: the seed, then the public key */

typedef struct sw_sign_request {
    const uint8_t *secret_key;       /* SW_SECRET_KEY_BYTES */
    uint64_t pack_version;           /* recorded in the pack; units refuse older ones */
    const char *name;                /* at most SW_PACK_NAME_BYTES - 1 bytes */
} sw_sign_request;

/* Makes a key pair and writes PREFIX.pub (the public-key line, mode 0644) and
 * PREFIX.key ("seamwalk-ed25519-secret" and 128 hex digits, mode 0600). Never
 * overwrites: SW_ERR_IO naming the file if either exists. */
sw_status sw_keygen_files(const char *prefix, sw_error *err);

/* Parses a secret key file (one line as keygen writes it) into sk; checks
 * that the public half matches the seed. Errors name the file and line. */
sw_status sw_secret_key_parse(const char *text, size_t size, const char *name,
                              uint8_t sk[SW_SECRET_KEY_BYTES], sw_error *err);

/* Validates the pack in in[0, in_size) (8-byte aligned), drops any SIGNATURE
 * section it has, and lays it out again with a new one signed by the
 * request's key: same sections in the same order, 64-byte aligned, the
 * SIGNATURE last, header and checksums recomputed. *out is malloc'd. */
sw_status sw_pack_sign_bytes(const uint8_t *in, size_t in_size, const sw_sign_request *req,
                             uint8_t **out, size_t *out_size, sw_error *err);

/* seamwalk-pack's commands (argv after the command name); exit status 0, 1
 * failure, 2 usage. */
int sw_pack_cmd_keygen(int argc, char **argv);
int sw_pack_cmd_sign(int argc, char **argv);
int sw_pack_cmd_verify_signed(int argc, char **argv);

#endif
