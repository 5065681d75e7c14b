/* SPDX-License-Identifier: MIT */
/* Key files and pack signing (sw_pack_sign.h in this folder). */
#include "sw_pack_sign.h"
#include "sw_pack_instances.h"

#include <errno.h>
#include <fcntl.h>
#include <sodium.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_hex.h"
#include "sw_pack.h"
#include "sw_walk_memory.h"

static const char secret_tag[] = "seamwalk-ed25519-secret";

/* ---- key files ---------------------------------------------------------- */

static sw_status write_new_file(const char *path, const char *text, int mode, sw_error *err)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot create: %s%s", path, strerror(errno),
                            errno == EEXIST ? " (keygen never overwrites a key)" : "");
    size_t n = strlen(text);
    ssize_t w = write(fd, text, n);
    int failed = w != (ssize_t)n || fsync(fd) != 0;
    int saved = errno;
    if (close(fd) != 0)
        failed = 1;
    if (failed) {
        unlink(path);
        return sw_error_set(err, SW_ERR_IO, "%s: cannot write: %s", path, strerror(saved));
    }
    return SW_OK;
}

static void hex_encode(const uint8_t *bytes, size_t n, char *out)
{
    static const char digits[] = "0123456789abcdef";
    for (size_t i = 0; i < n; i++) {
        out[2 * i] = digits[bytes[i] >> 4];
        out[2 * i + 1] = digits[bytes[i] & 15];
    }
    out[2 * n] = '\0';
}

sw_status sw_keygen_files(const char *prefix, sw_error *err)
{
    if (sodium_init() < 0)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "libsodium failed to initialise");
    uint8_t pk[SW_KEY_BYTES], sk[SW_SECRET_KEY_BYTES];
    crypto_sign_keypair(pk, sk);
    char pub_path[4096], key_path[4096];
    if (snprintf(pub_path, sizeof pub_path, "%s.pub", prefix) >= (int)sizeof pub_path ||
        snprintf(key_path, sizeof key_path, "%s.key", prefix) >= (int)sizeof key_path)
        return sw_error_set(err, SW_ERR_ARG, "%s: the key path is too long", prefix);
    char secret_line[sizeof secret_tag + 2 * SW_SECRET_KEY_BYTES + 2];
    char public_line[SW_PUBLIC_KEY_LINE_BYTES];
    memcpy(secret_line, secret_tag, sizeof secret_tag - 1);
    secret_line[sizeof secret_tag - 1] = ' ';
    hex_encode(sk, sizeof sk, secret_line + sizeof secret_tag);
    strcat(secret_line, "\n");
    sw_public_key_line(pk, public_line);
    sodium_memzero(sk, sizeof sk);
    sw_status st = write_new_file(key_path, secret_line, 0600, err);
    sodium_memzero(secret_line, sizeof secret_line);
    if (st == SW_OK && (st = write_new_file(pub_path, public_line, 0644, err)) != SW_OK)
        unlink(key_path);
    return st;
}

static sw_status check_secret_line(const char *text, size_t len, const char *name, sw_error *err)
{
    size_t tag = sizeof secret_tag - 1, hex = 2 * SW_SECRET_KEY_BYTES;
    if (memchr(text, '\0', len))
        return sw_error_set(err, SW_ERR_FORMAT, "%s:1: a NUL byte in a text file", name);
    if (len < tag + 1 || memcmp(text, secret_tag, tag) != 0 || text[tag] != ' ')
        return sw_error_set(err, SW_ERR_FORMAT, "%s:1: expected \"%s\" and a space (a secret "
                            "key written by seamwalk-pack keygen)", name, secret_tag);
    if (len != tag + 1 + hex)
        return sw_error_set(err, SW_ERR_FORMAT, "%s:1: expected exactly %zu hex digits after "
                            "\"%s \", found %zu characters", name, hex, secret_tag,
                            len - tag - 1);
    return SW_OK;
}

sw_status sw_secret_key_parse(const char *text, size_t size, const char *name,
                              uint8_t sk[SW_SECRET_KEY_BYTES], sw_error *err)
{
    size_t len = size;
    if (len > 0 && text[len - 1] == '\n')
        len--;
    if (len > 0 && text[len - 1] == '\r')
        len--;
    sw_status st = check_secret_line(text, len, name, err);
    if (st != SW_OK)
        return st;
    const char *hex = text + sizeof secret_tag;
    for (size_t i = 0; i < 2 * SW_SECRET_KEY_BYTES; i++) {
        int v = sw_hex_digit(hex[i]);
        if (v < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "%s:1: column %zu: expected a hex digit",
                                name, sizeof secret_tag + i + 1);
        sk[i / 2] = (uint8_t)(i % 2 ? (sk[i / 2] | v) : v << 4);
    }
    if (sodium_init() < 0)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "libsodium failed to initialise");
    uint8_t pk[SW_KEY_BYTES], seed_pk[SW_KEY_BYTES], seed_sk[SW_SECRET_KEY_BYTES];
    crypto_sign_ed25519_sk_to_pk(pk, sk);
    crypto_sign_seed_keypair(seed_pk, seed_sk, sk);
    sodium_memzero(seed_sk, sizeof seed_sk);
    if (memcmp(pk, seed_pk, sizeof pk) != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s:1: the public half does not belong to the "
                            "seed (a damaged key file)", name);
    return SW_OK;
}

/* ---- signing -------------------------------------------------------------- */

static uint64_t align64(uint64_t x) { return (x + SW_PACK_ALIGN - 1) / SW_PACK_ALIGN * SW_PACK_ALIGN; }

/* The new file's size and the kept sections' offsets in order (SIGNATURE
 * sections of the input are dropped); returns the signature's offset. */
static uint64_t lay_out(const sw_pack *in, uint32_t kept, uint64_t *offsets)
{
    uint64_t at = align64(64u + 32u * ((uint64_t)kept + 1));
    uint32_t k = 0;
    for (uint32_t i = 0; i < in->header->section_count; i++) {
        const sw_pack_section *s = &in->sections[i];
        if (s->type == SW_SECTION_SIGNATURE)
            continue;
        offsets[k++] = at;
        at = align64(at + s->size);
    }
    return at;
}

static void copy_sections(const sw_pack *in, const uint64_t *offsets, uint8_t *out)
{
    sw_pack_section *table = (sw_pack_section *)(out + 64);
    uint32_t k = 0;
    for (uint32_t i = 0; i < in->header->section_count; i++) {
        const sw_pack_section *s = &in->sections[i];
        if (s->type == SW_SECTION_SIGNATURE)
            continue;
        table[k] = *s;
        table[k].offset = offsets[k];
        memcpy(out + offsets[k], in->data + s->offset, s->size);
        k++;
    }
}

static sw_status sign_in_place(uint8_t *out, size_t size, uint32_t sig_index,
                               const sw_sign_request *req, sw_error *err)
{
    sw_pack_header *h = (sw_pack_header *)out;
    sw_pack_section *table = (sw_pack_section *)(out + 64);
    sw_pack_signature *sig = (sw_pack_signature *)(out + table[sig_index].offset);
    uint8_t digest[SW_DIGEST_BYTES];
    sw_status st = sw_pack_signed_digest(out, size, sig_index, digest, err);
    if (st != SW_OK)
        return st;
    crypto_sign_detached(sig->signature, NULL, digest, sizeof digest, req->secret_key);
    table[sig_index].checksum = XXH3_64bits(sig, sizeof *sig);
    h->header_checksum = 0;
    h->header_checksum = XXH3_64bits(out, 64u + 32u * (size_t)h->section_count);
    return SW_OK;
}

static sw_status check_request(const sw_pack *in, uint32_t kept, const sw_sign_request *req,
                               sw_error *err)
{
    if (!req->name || strlen(req->name) >= SW_PACK_NAME_BYTES)
        return sw_error_set(err, SW_ERR_ARG, "pack name: expected 1..%d bytes",
                            SW_PACK_NAME_BYTES - 1);
    long at = sw_pack_name_control_at(req->name, SW_PACK_NAME_BYTES);
    if (at >= 0)
        return sw_error_set(err, SW_ERR_ARG, "pack name '%s': a control byte at byte %ld "
                            "(a name is shown on terminals and in the journal)", req->name, at);
    if (kept + 1 > SW_PACK_MAX_SECTIONS)
        return sw_error_set(err, SW_ERR_RANGE, "the pack has %u sections: no room for a "
                            "SIGNATURE (at most %u)", (unsigned)in->header->section_count,
                            SW_PACK_MAX_SECTIONS);
    return sodium_init() < 0 ? sw_error_set(err, SW_ERR_UNSUPPORTED, "libsodium failed") : SW_OK;
}

static void fill_signature(sw_pack_signature *sig, const sw_sign_request *req)
{
    memset(sig, 0, sizeof *sig);
    sig->format = SW_SIGNATURE_FORMAT;
    sig->pack_version = req->pack_version;
    memcpy(sig->name, req->name, strlen(req->name));
    crypto_sign_ed25519_sk_to_pk(sig->public_key, req->secret_key);
}

static sw_status build_signed(const sw_pack *in, uint32_t kept, const sw_sign_request *req,
                              uint8_t **out, size_t *out_size, sw_error *err)
{
    uint64_t *offsets = malloc(((size_t)kept + 1) * sizeof *offsets);
    if (!offsets)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    uint64_t sig_at = lay_out(in, kept, offsets);
    size_t size = (size_t)(sig_at + sizeof(sw_pack_signature));
    uint8_t *bytes = calloc(1, size);
    if (!bytes) {
        free(offsets);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes for the pack", size);
    }
    sw_pack_header *h = (sw_pack_header *)bytes;
    *h = *in->header;
    h->section_count = kept + 1;
    h->total_size = size;
    h->runtime_bytes = sw_pack_runtime_bytes_of(in);
    copy_sections(in, offsets, bytes);
    free(offsets);
    sw_pack_section *entry = (sw_pack_section *)(bytes + 64) + kept;
    *entry = (sw_pack_section){ .type = SW_SECTION_SIGNATURE, .offset = sig_at,
                                .size = sizeof(sw_pack_signature) };
    fill_signature((sw_pack_signature *)(bytes + sig_at), req);
    sw_status st = sign_in_place(bytes, size, kept, req, err);
    if (st != SW_OK) {
        free(bytes);
        return st;
    }
    *out = bytes;
    *out_size = size;
    return SW_OK;
}

sw_status sw_pack_sign_bytes(const uint8_t *in, size_t in_size, const sw_sign_request *req,
                             uint8_t **out, size_t *out_size, sw_error *err)
{
    *out = NULL;
    *out_size = 0;
    sw_pack pack;
    sw_status st = sw_pack_open_memory(in, in_size, &pack, err);
    if (st != SW_OK)
        return st;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < pack.header->section_count; i++)
        kept += pack.sections[i].type != SW_SECTION_SIGNATURE;
    if ((st = check_request(&pack, kept, req, err)) != SW_OK)
        return st;
    if ((st = build_signed(&pack, kept, req, out, out_size, err)) != SW_OK)
        return st;
    /* The result must read back as a valid, correctly signed pack. */
    const sw_pack_signature *sig;
    sw_pack check;
    st = sw_pack_open_memory(*out, *out_size, &check, err);
    if (st == SW_OK)
        st = sw_pack_check_signature(&check, NULL, &sig, err);
    if (st != SW_OK) {
        sw_error_prefix(err, "signed pack fails its own check");
        free(*out);
        *out = NULL;
    }
    return st;
}
