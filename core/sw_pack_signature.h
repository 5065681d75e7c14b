/* SPDX-License-Identifier: MIT */
/* Signed packs: the SIGNATURE section (type 22) and its check against a
 * unit's trusted ed25519 keys (libsodium). Written by seamwalk-pack sign
 * (assets/pack/sw_pack_sign.c); checked by seamwalk-flash before it installs
 * a pack and by seamwalk when it starts a slot of its pack store. The layout
 * and what the signature covers are in assets/PACK_FORMAT.md, "Signatures".
 *
 * The signature covers every byte of the file except three fields that
 * depend on it (the header checksum, the SIGNATURE entry's checksum and the
 * signature itself), which are read as zero: a flipped byte anywhere, gaps
 * between sections included, fails the check. XXH3 checksums are not
 * collision resistant, so the signed digest is BLAKE2b-512 of those bytes,
 * not the section checksums. Nothing here allocates. */
#ifndef SW_PACK_SIGNATURE_H
#define SW_PACK_SIGNATURE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_pack.h"

#define SW_SECTION_SIGNATURE 22u
#define SW_SIGNATURE_FORMAT 1u
enum { SW_KEY_BYTES = 32, SW_SIG_BYTES = 64, SW_DIGEST_BYTES = 64, SW_PACK_NAME_BYTES = 48 };
enum { SW_TRUSTED_KEYS_MAX = 16 };

typedef struct sw_pack_signature {    /* 160 bytes, the whole SIGNATURE section */
    uint32_t format;                  /* SW_SIGNATURE_FORMAT */
    uint32_t flags;                   /* zero */
    uint64_t pack_version;            /* monotonic, chosen by the signer; units refuse older */
    char name[SW_PACK_NAME_BYTES];    /* NUL-terminated UTF-8, e.g. "showroom-2026-12" */
    uint8_t public_key[SW_KEY_BYTES]; /* the signer's ed25519 key */
    uint8_t signature[SW_SIG_BYTES];  /* ed25519 over sw_pack_signed_digest */
} sw_pack_signature;

/* A unit's trusted keys: a fixed array, so checking needs no allocation. */
typedef struct sw_trusted_keys {
    uint32_t count;
    uint8_t keys[SW_TRUSTED_KEYS_MAX][SW_KEY_BYTES];
} sw_trusted_keys;

/* Parses a key file: one key per line as "seamwalk-ed25519-public" and 64
 * hex digits, optionally followed by a space and a comment; blank lines and
 * lines starting with '#' are skipped. Appends to out (which the caller
 * zeroes first), so several files can be combined. name labels errors
 * ("keys:3: ..."). SW_ERR_FORMAT for a malformed line, SW_ERR_RANGE past
 * SW_TRUSTED_KEYS_MAX keys. */
sw_status sw_trusted_keys_parse(const char *text, size_t size, const char *name,
                                sw_trusted_keys *out, sw_error *err);

/* Writes the public-key line for key (with a newline) into line, which must
 * hold SW_PUBLIC_KEY_LINE_BYTES. */
enum { SW_PUBLIC_KEY_LINE_BYTES = 24 + 2 * SW_KEY_BYTES + 2 };
void sw_public_key_line(const uint8_t key[SW_KEY_BYTES], char *line);

/* The pack's SIGNATURE record, if it has exactly one of the right size and
 * format. The pack must be validated (sw_pack_open_memory). SW_ERR_FORMAT
 * "not signed" when it has none. index_out (may be NULL) gets its table
 * index. */
sw_status sw_pack_signature_find(const sw_pack *pack, const sw_pack_signature **out,
                                 uint32_t *index_out, sw_error *err);

/* The SIGNATURE entry, found from the file's header and section table alone
 * (head: the file's first head_size bytes, at least 64 and the whole table;
 * file_size: the file's size), so a unit can check a pack's signature
 * before it parses any section of it: magic, total_size, the table in the
 * file, exactly one SIGNATURE entry of 160 bytes after its table entry and
 * inside the file. *table_bytes (may be NULL) gets 64 + the table's size,
 * so a caller with fewer head bytes can read that many and call again. */
sw_status sw_pack_signature_locate(const uint8_t *head, size_t head_size, uint64_t file_size,
                                   uint32_t *index, uint64_t *offset, uint64_t *table_bytes,
                                   sw_error *err);

/* A SIGNATURE record's own fields: format 1, flags 0, a NUL in the name
 * and no control byte before it. */
sw_status sw_pack_signature_record_check(const sw_pack_signature *sig, sw_error *err);

/* The index of the first control byte (below 0x20, or 0x7f) among the
 * first cap bytes of name, up to its NUL; -1 if none. A pack's name is
 * printed on terminals and in the journal, whoever signed the pack, so
 * one with an escape sequence in it is neither signed nor accepted. */
long sw_pack_name_control_at(const char *name, size_t cap);

/* The signature of raw, unvalidated bytes: located from the header and the
 * table (sw_pack_signature_locate), by one of keys, valid over the bytes.
 * Nothing else of the pack is read, so untrusted bytes reach no section
 * parser before their owner is known. *out gets a copy of the record.
 * Errors as sw_pack_check_signature. */
sw_status sw_pack_check_signature_raw(const uint8_t *data, size_t size,
                                      const sw_trusted_keys *keys, sw_pack_signature *out,
                                      sw_error *err);

/* BLAKE2b-512 of the file's size bytes with the three signature-dependent
 * fields read as zero; signature_index is the SIGNATURE section's table
 * index. Every offset it uses is checked against size, so it is safe on
 * raw bytes once sw_pack_signature_locate found the index. */
sw_status sw_pack_signed_digest(const uint8_t *data, size_t size, uint32_t signature_index,
                                uint8_t digest[SW_DIGEST_BYTES], sw_error *err);

/* Checks a validated pack's signature: present, by one of keys (if keys is
 * NULL, by the key it names, for a host-side integrity check), and valid
 * over the file. On success *out points at the record. Errors:
 * SW_ERR_FORMAT not signed; SW_ERR_ARG an untrusted key (named by its first
 * bytes); SW_ERR_CHECKSUM a bad signature (the pack was changed after it
 * was signed). */
sw_status sw_pack_check_signature(const sw_pack *pack, const sw_trusted_keys *keys,
                                  const sw_pack_signature **out, sw_error *err);

#endif
