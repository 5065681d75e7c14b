/* SPDX-License-Identifier: MIT */
/* The SIGNATURE section's check (sw_pack_signature.h) and the trusted-key file
 * parser. Runs on the unit: no allocation, the digest streams over the
 * pack's bytes in place. */
#include "sw_pack_signature.h"

#include <sodium.h>
#include <stdio.h>
#include <string.h>

#include "sw_hex.h"

_Static_assert(sizeof(sw_pack_signature) == 160, "SIGNATURE record is 160 bytes");
_Static_assert(offsetof(sw_pack_signature, public_key) == 64, "public_key at 64");
_Static_assert(offsetof(sw_pack_signature, signature) == 96, "signature at 96");

static const char public_tag[] = "seamwalk-ed25519-public";

/* 2 * n hex digits at s into out; 0 on success, else the offending index. */
static size_t parse_hex(const char *s, size_t n, uint8_t *out)
{
    for (size_t i = 0; i < 2 * n; i++) {
        int v = sw_hex_digit(s[i]);
        if (v < 0)
            return i + 1;
        if (i % 2 == 0)
            out[i / 2] = (uint8_t)(v << 4);
        else
            out[i / 2] |= (uint8_t)v;
    }
    return 0;
}

static sw_status parse_key_line(const char *s, size_t len, const char *name, size_t line_no,
                                sw_trusted_keys *out, sw_error *err)
{
    size_t tag = sizeof public_tag - 1, hex = 2 * SW_KEY_BYTES;
    if (len < tag + 1 || memcmp(s, public_tag, tag) != 0 || s[tag] != ' ')
        return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: expected \"%s\" and a space at the "
                            "start of the line", name, line_no, public_tag);
    if (len < tag + 1 + hex || (len > tag + 1 + hex && s[tag + 1 + hex] != ' '))
        return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: expected %zu hex digits after \"%s \"",
                            name, line_no, hex, public_tag);
    if (out->count == SW_TRUSTED_KEYS_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "%s:%zu: more than %d trusted keys", name,
                            line_no, SW_TRUSTED_KEYS_MAX);
    size_t bad = parse_hex(s + tag + 1, SW_KEY_BYTES, out->keys[out->count]);
    if (bad)
        return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: column %zu: expected a hex digit",
                            name, line_no, tag + 1 + bad);
    out->count++;
    return SW_OK;
}

sw_status sw_trusted_keys_parse(const char *text, size_t size, const char *name,
                                sw_trusted_keys *out, sw_error *err)
{
    size_t line_no = 0;
    for (size_t at = 0; at < size;) {
        const char *s = text + at;
        const char *nl = memchr(s, '\n', size - at);
        size_t len = nl ? (size_t)(nl - s) : size - at;
        at += len + (nl != NULL);
        line_no++;
        if (memchr(s, '\0', len))
            return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: a NUL byte in a text file", name,
                                line_no);
        if (len > 0 && s[len - 1] == '\r')
            len--;
        if (len == 0 || s[0] == '#')
            continue;
        sw_status st = parse_key_line(s, len, name, line_no, out, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

void sw_public_key_line(const uint8_t key[SW_KEY_BYTES], char *line)
{
    static const char digits[] = "0123456789abcdef";
    size_t n = sizeof public_tag - 1;
    memcpy(line, public_tag, n);
    line[n++] = ' ';
    for (size_t i = 0; i < SW_KEY_BYTES; i++) {
        line[n++] = digits[key[i] >> 4];
        line[n++] = digits[key[i] & 15];
    }
    line[n++] = '\n';
    line[n] = '\0';
}

sw_status sw_pack_signature_record_check(const sw_pack_signature *sig, sw_error *err)
{
    if (sig->format != SW_SIGNATURE_FORMAT || sig->flags != 0)
        return sw_error_set(err, SW_ERR_VERSION, "SIGNATURE.format %u flags %u: expected "
                            "format %u, flags 0", (unsigned)sig->format, (unsigned)sig->flags,
                            SW_SIGNATURE_FORMAT);
    if (!memchr(sig->name, '\0', sizeof sig->name))
        return sw_error_set(err, SW_ERR_FORMAT, "SIGNATURE.name: not NUL-terminated within "
                            "%d bytes", SW_PACK_NAME_BYTES);
    long at = sw_pack_name_control_at(sig->name, sizeof sig->name);
    if (at >= 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SIGNATURE.name: a control byte (0x%02x) at "
                            "byte %ld", (unsigned)(unsigned char)sig->name[at], at);
    return SW_OK;
}

long sw_pack_name_control_at(const char *name, size_t cap)
{
    for (size_t i = 0; i < cap && name[i]; i++)
        if ((unsigned char)name[i] < 0x20 || name[i] == 0x7f)
            return (long)i;
    return -1;
}

sw_status sw_pack_signature_locate(const uint8_t *head, size_t head_size, uint64_t file_size,
                                   uint32_t *index, uint64_t *offset, uint64_t *table_bytes,
                                   sw_error *err)
{
    sw_pack_header h;
    if (head_size < sizeof h || file_size < sizeof h)
        return sw_error_set(err, SW_ERR_FORMAT, "header: %llu bytes, a pack is at least %zu",
                            (unsigned long long)file_size, sizeof h);
    memcpy(&h, head, sizeof h);
    if (memcmp(h.magic, SW_PACK_MAGIC, 8) != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "header: not a seamwalk pack (bad magic)");
    if (h.total_size != file_size)
        return sw_error_set(err, SW_ERR_FORMAT, "header: total_size %llu, but the file is %llu "
                            "bytes", (unsigned long long)h.total_size,
                            (unsigned long long)file_size);
    uint64_t table = 64u + 32u * (uint64_t)h.section_count;
    if (table_bytes)
        *table_bytes = table;
    if (h.section_table_offset != 64 || h.section_count == 0 ||
        h.section_count > SW_PACK_MAX_SECTIONS || table > file_size)
        return sw_error_set(err, SW_ERR_FORMAT, "header: a section table of %u entries at %u "
                            "does not fit the file", (unsigned)h.section_count,
                            (unsigned)h.section_table_offset);
    if (head_size < table)
        return sw_error_set(err, SW_ERR_RANGE, "header: %llu bytes of table needed",
                            (unsigned long long)table);
    int found = -1;
    sw_pack_section e;
    for (uint32_t i = 0; i < h.section_count; i++) {
        memcpy(&e, head + 64 + 32u * i, sizeof e);
        if (e.type != SW_SECTION_SIGNATURE)
            continue;
        if (found >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "sections %d and %u: two SIGNATURE "
                                "sections, expected one", found, (unsigned)i);
        found = (int)i;
        *offset = e.offset;
        if (e.size != sizeof(sw_pack_signature) || e.offset < table ||
            e.offset > file_size - sizeof(sw_pack_signature))
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (SIGNATURE): %llu bytes at %llu, "
                                "expected %zu inside the file after the table", (unsigned)i,
                                (unsigned long long)e.size, (unsigned long long)e.offset,
                                sizeof(sw_pack_signature));
    }
    if (found < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "not signed: no SIGNATURE section (sign it "
                            "with seamwalk-pack sign)");
    *index = (uint32_t)found;
    return SW_OK;
}

sw_status sw_pack_signature_find(const sw_pack *pack, const sw_pack_signature **out,
                                 uint32_t *index_out, sw_error *err)
{
    int32_t found = -1;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        if (pack->sections[i].type != SW_SECTION_SIGNATURE)
            continue;
        if (found >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "sections %d and %u: two SIGNATURE "
                                "sections, expected one", found, (unsigned)i);
        found = (int32_t)i;
    }
    if (found < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "not signed: no SIGNATURE section (sign it "
                            "with seamwalk-pack sign)");
    const sw_pack_section *s = &pack->sections[found];
    if (s->size != sizeof(sw_pack_signature))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (SIGNATURE): %llu bytes, expected "
                            "%zu", found, (unsigned long long)s->size, sizeof(sw_pack_signature));
    const sw_pack_signature *sig = (const sw_pack_signature *)(pack->data + s->offset);
    sw_status st = sw_pack_signature_record_check(sig, err);
    if (st != SW_OK)
        return st;
    *out = sig;
    if (index_out)
        *index_out = (uint32_t)found;
    return SW_OK;
}

/* Feeds data[from, to) to the hash, with the bytes inside the holes (sorted,
 * disjoint [start, end) ranges) replaced by zeros. */
static void hash_with_holes(crypto_generichash_state *h, const uint8_t *data, uint64_t from,
                            uint64_t to, const uint64_t holes[][2], int hole_count)
{
    static const uint8_t zeros[64];
    for (int i = 0; i < hole_count; i++) {
        if (holes[i][0] > from)
            crypto_generichash_update(h, data + from, holes[i][0] - from);
        crypto_generichash_update(h, zeros, holes[i][1] - holes[i][0]);
        from = holes[i][1];
    }
    if (to > from)
        crypto_generichash_update(h, data + from, to - from);
}

sw_status sw_pack_signed_digest(const uint8_t *data, size_t size, uint32_t signature_index,
                                uint8_t digest[SW_DIGEST_BYTES], sw_error *err)
{
    const sw_pack_header *h = (const sw_pack_header *)data;
    if (size < sizeof *h || signature_index >= h->section_count ||
        64u + 32u * (uint64_t)h->section_count > size)
        return sw_error_set(err, SW_ERR_ARG, "signed digest: the pack is not validated");
    const sw_pack_section *s = (const sw_pack_section *)(data + 64) + signature_index;
    uint64_t entry = 64u + 32u * (uint64_t)signature_index;
    uint64_t sig_at = s->offset + offsetof(sw_pack_signature, signature);
    if (s->size != sizeof(sw_pack_signature) || s->offset < entry + 32 || s->offset > size ||
        sig_at + SW_SIG_BYTES > size)
        return sw_error_set(err, SW_ERR_ARG, "signed digest: SIGNATURE entry out of place");
    const uint64_t holes[3][2] = {
        { offsetof(sw_pack_header, header_checksum), offsetof(sw_pack_header, reserved) },
        { entry + offsetof(sw_pack_section, checksum), entry + 32 },
        { sig_at, sig_at + SW_SIG_BYTES },
    };
    if (sodium_init() < 0)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "libsodium failed to initialise");
    crypto_generichash_state state;
    crypto_generichash_init(&state, NULL, 0, SW_DIGEST_BYTES);
    static const char domain[] = "seamwalk pack signature 1";
    crypto_generichash_update(&state, (const uint8_t *)domain, sizeof domain);
    hash_with_holes(&state, data, 0, size, holes, 3);
    crypto_generichash_final(&state, digest, SW_DIGEST_BYTES);
    return SW_OK;
}

static int key_trusted(const sw_trusted_keys *keys, const uint8_t key[SW_KEY_BYTES])
{
    for (uint32_t i = 0; i < keys->count && i < SW_TRUSTED_KEYS_MAX; i++)
        if (sodium_memcmp(keys->keys[i], key, SW_KEY_BYTES) == 0)
            return 1;
    return 0;
}

/* The record's key is trusted and its signature matches data's digest. */
static sw_status check_record(const uint8_t *data, size_t size, uint32_t index,
                              const sw_pack_signature *sig, const sw_trusted_keys *keys,
                              sw_error *err)
{
    if (keys && !key_trusted(keys, sig->public_key))
        return sw_error_set(err, SW_ERR_ARG, "signed by key %02x%02x%02x%02x..., which is not "
                            "among the %u trusted keys", sig->public_key[0],
                            sig->public_key[1], sig->public_key[2], sig->public_key[3],
                            (unsigned)keys->count);
    uint8_t digest[SW_DIGEST_BYTES];
    sw_status st = sw_pack_signed_digest(data, size, index, digest, err);
    if (st != SW_OK)
        return st;
    if (crypto_sign_verify_detached(sig->signature, digest, sizeof digest, sig->public_key) != 0)
        return sw_error_set(err, SW_ERR_CHECKSUM, "SIGNATURE: does not match the pack's bytes "
                            "(changed after it was signed, or not signed by key %02x%02x%02x"
                            "%02x...)", sig->public_key[0], sig->public_key[1],
                            sig->public_key[2], sig->public_key[3]);
    return SW_OK;
}

sw_status sw_pack_check_signature_raw(const uint8_t *data, size_t size,
                                      const sw_trusted_keys *keys, sw_pack_signature *out,
                                      sw_error *err)
{
    uint32_t index = 0;
    uint64_t offset = 0;
    sw_status st = sw_pack_signature_locate(data, size, size, &index, &offset, NULL, err);
    if (st != SW_OK)
        return st;
    memcpy(out, data + offset, sizeof *out);
    if ((st = sw_pack_signature_record_check(out, err)) != SW_OK)
        return st;
    return check_record(data, size, index, out, keys, err);
}

sw_status sw_pack_check_signature(const sw_pack *pack, const sw_trusted_keys *keys,
                                  const sw_pack_signature **out, sw_error *err)
{
    const sw_pack_signature *sig = NULL;
    uint32_t index = 0;
    sw_status st = sw_pack_signature_find(pack, &sig, &index, err);
    if (st == SW_OK)
        st = check_record(pack->data, pack->size, index, sig, keys, err);
    if (st == SW_OK)
        *out = sig;
    return st;
}
