/* SPDX-License-Identifier: MIT */
/* Signed packs: signing (assets/pack/sw_pack_sign.c), the check
 * (core/sw_pack_sign_check.c) and the key file parsers. Every byte of a
 * signed pack is flipped in turn; each flip must be refused. */
#include <sodium.h>
#include <stdint.h>
#include <string.h>

#include "sw_test.h"
#include "pack_sample.h"
#include "sw_pack_sign.h"
#include "sw_pack_signature.h"

static uint8_t owner_pk[32], owner_sk[64], other_pk[32], other_sk[64];

static uint8_t *signed_sample(uint64_t version, const uint8_t *sk, size_t *size)
{
    sample s;
    make_sample(&s);
    size_t plain_size;
    uint8_t *plain = serialize_sample(&s, &plain_size);
    sw_sign_request req = { sk, version, "sample" };
    uint8_t *out = NULL;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_sign_bytes(plain, plain_size, &req, &out, size, &err) == SW_OK, "%s",
                 err.message);
    free(plain);
    return out;
}

static sw_trusted_keys owner_keys(void)
{
    sw_trusted_keys k = { .count = 1 };
    memcpy(k.keys[0], owner_pk, 32);
    return k;
}

/* Validation and signature check, as a unit does before installing. */
static sw_status check_bytes(const uint8_t *bytes, size_t size, const sw_trusted_keys *keys,
                             sw_error *err)
{
    uint8_t *copy = malloc(size ? size : 1);
    memcpy(copy, bytes, size);
    sw_pack pack;
    const sw_pack_signature *sig;
    sw_status st = sw_pack_open_memory(copy, size, &pack, err);
    if (st == SW_OK)
        st = sw_pack_check_signature(&pack, keys, &sig, err);
    free(copy);
    return st;
}

static void test_signed_pack_validates_and_records_version_and_name(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(7, owner_sk, &size);
    sw_pack pack;
    const sw_pack_signature *sig;
    sw_trusted_keys keys = owner_keys();
    sw_error err = { 0 };
    SW_CHECK(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK);
    SW_CHECK_MSG(sw_pack_check_signature(&pack, &keys, &sig, &err) == SW_OK, "%s", err.message);
    SW_CHECK(sig->pack_version == 7 && strcmp(sig->name, "sample") == 0);
    SW_CHECK(memcmp(sig->public_key, owner_pk, 32) == 0);
    SW_CHECK(pack.header->section_count == SAMPLE_SECTIONS + 1);
    free(bytes);
}

static void test_signing_again_replaces_the_signature(void)
{
    size_t size, again_size;
    uint8_t *bytes = signed_sample(1, owner_sk, &size);
    sw_sign_request req = { other_sk, 2, "resigned" };
    uint8_t *again = NULL;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_sign_bytes(bytes, size, &req, &again, &again_size, &err) == SW_OK);
    SW_CHECK(again_size == size);
    sw_trusted_keys keys = { .count = 1 };
    memcpy(keys.keys[0], other_pk, 32);
    SW_CHECK(check_bytes(again, again_size, &keys, &err) == SW_OK);
    sw_trusted_keys owner = owner_keys();
    SW_CHECK(check_bytes(again, again_size, &owner, &err) == SW_ERR_ARG);
    free(bytes);
    free(again);
}

static void test_unsigned_pack_is_refused(void)
{
    sample s;
    make_sample(&s);
    size_t size;
    uint8_t *plain = serialize_sample(&s, &size);
    sw_trusted_keys keys = owner_keys();
    sw_error err = { 0 };
    SW_CHECK(check_bytes(plain, size, &keys, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "not signed"), "%s", err.message);
    free(plain);
}

static void test_wrong_key_is_refused(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, other_sk, &size);
    sw_trusted_keys keys = owner_keys();
    sw_error err = { 0 };
    SW_CHECK(check_bytes(bytes, size, &keys, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(strstr(err.message, "not among the 1 trusted keys"), "%s", err.message);
    free(bytes);
}

/* A signature record that names the trusted key but was made by another:
 * the check must not trust the named key, only the signature. */
static void test_forged_key_field_is_refused(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, other_sk, &size);
    sw_pack_section *t = table_of(bytes);
    uint32_t last = header_of(bytes)->section_count - 1;
    sw_pack_signature *sig = (sw_pack_signature *)(bytes + t[last].offset);
    memcpy(sig->public_key, owner_pk, 32);
    t[last].checksum = XXH3_64bits(sig, sizeof *sig);
    reseal(bytes);
    sw_trusted_keys keys = owner_keys();
    sw_error err = { 0 };
    SW_CHECK(check_bytes(bytes, size, &keys, &err) == SW_ERR_CHECKSUM);
    free(bytes);
}

/* Every single-bit flip, at every byte, is refused by one check or other. */
static void test_every_flipped_byte_is_refused(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, owner_sk, &size);
    sw_trusted_keys keys = owner_keys();
    size_t refused = 0;
    for (size_t i = 0; i < size; i++) {
        bytes[i] ^= 0x10;
        sw_error err = { 0 };
        refused += check_bytes(bytes, size, &keys, &err) != SW_OK;
        bytes[i] ^= 0x10;
    }
    printf("flipped bytes: %zu of %zu refused\n", refused, size);
    SW_CHECK(refused == size);
    free(bytes);
}

/* A change the reader cannot see (a byte after the NUL of a part's name),
 * with its section checksum and the header's redone, so only the signature
 * can catch it. */
static void test_flip_with_valid_checksums_is_refused(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, owner_sk, &size);
    sw_pack_section *t = table_of(bytes);
    uint32_t parts = 0;
    while (t[parts].type != SW_SECTION_PARTS)
        parts++;
    bytes[t[parts].offset + offsetof(sw_pack_part, name) + 50] ^= 1;
    t[parts].checksum = XXH3_64bits(bytes + t[parts].offset, t[parts].size);
    reseal(bytes);
    sw_trusted_keys keys = owner_keys();
    sw_error err = { 0 };
    SW_CHECK_MSG(check_bytes(bytes, size, &keys, &err) == SW_ERR_CHECKSUM, "%s", err.message);
    SW_CHECK_MSG(strstr(err.message, "changed after it was signed"), "%s", err.message);
    free(bytes);
}

static void test_every_truncation_is_refused(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, owner_sk, &size);
    sw_trusted_keys keys = owner_keys();
    size_t refused = 0;
    for (size_t n = 0; n < size; n++) {
        sw_error err = { 0 };
        refused += check_bytes(bytes, n, &keys, &err) != SW_OK;
    }
    SW_CHECK(refused == size);
    free(bytes);
}

static void test_public_key_file_parses_keys_and_comments(void)
{
    char line[SW_PUBLIC_KEY_LINE_BYTES], text[512];
    sw_public_key_line(owner_pk, line);
    line[strlen(line) - 1] = '\0';
    snprintf(text, sizeof text, "# the owner\n\n%s kiosk fleet\r\n%s", line, line);
    sw_trusted_keys keys = { 0 };
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_trusted_keys_parse(text, strlen(text), "keys", &keys, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(keys.count == 2 && memcmp(keys.keys[1], owner_pk, 32) == 0);
}

static void expect_key_error(const char *text, sw_status status, const char *needle)
{
    sw_trusted_keys keys = { 0 };
    sw_error err = { 0 };
    SW_CHECK(sw_trusted_keys_parse(text, strlen(text), "keys", &keys, &err) == status);
    SW_CHECK_MSG(strstr(err.message, needle), "'%s' lacks '%s'", err.message, needle);
}

static void test_public_key_file_errors_name_the_line(void)
{
    char line[SW_PUBLIC_KEY_LINE_BYTES], text[4096] = "";
    sw_public_key_line(owner_pk, line);
    expect_key_error("\nssh-ed25519 AAAA\n", SW_ERR_FORMAT, "keys:2: expected \"seamwalk");
    expect_key_error("seamwalk-ed25519-public 00ff\n", SW_ERR_FORMAT, "keys:1: expected 64 hex");
    char bad[SW_PUBLIC_KEY_LINE_BYTES];
    memcpy(bad, line, sizeof bad);
    bad[30] = 'g';
    expect_key_error(bad, SW_ERR_FORMAT, "keys:1: column 31");
    memcpy(bad, line, sizeof bad);
    bad[24 + 64] = 'x'; /* a 65th digit where the end or a space belongs */
    expect_key_error(bad, SW_ERR_FORMAT, "expected 64 hex");
    for (int i = 0; i <= SW_TRUSTED_KEYS_MAX; i++)
        strcat(text, line);
    expect_key_error(text, SW_ERR_RANGE, "keys:17: more than 16");
    sw_trusted_keys keys = { 0 };
    sw_error err = { 0 };
    SW_CHECK(sw_trusted_keys_parse("a\0b", 3, "keys", &keys, &err) == SW_ERR_FORMAT);
}

static void test_secret_key_file_round_trip_and_errors(void)
{
    char hex[129], text[256];
    for (int i = 0; i < 64; i++)
        sprintf(hex + 2 * i, "%02x", owner_sk[i]);
    snprintf(text, sizeof text, "seamwalk-ed25519-secret %s\n", hex);
    uint8_t sk[64];
    sw_error err = { 0 };
    SW_CHECK(sw_secret_key_parse(text, strlen(text), "k", sk, &err) == SW_OK);
    SW_CHECK(memcmp(sk, owner_sk, 64) == 0);
    text[30] = text[30] == '0' ? '1' : '0'; /* the seed no longer gives the stored public key */
    SW_CHECK(sw_secret_key_parse(text, strlen(text), "k", sk, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "does not belong"), "%s", err.message);
    SW_CHECK(sw_secret_key_parse(text, 40, "k", sk, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "exactly 128 hex"), "%s", err.message);
    SW_CHECK(sw_secret_key_parse("seamwalk-ed25519-public 00", 26, "k", sk, &err) ==
             SW_ERR_FORMAT);
}

/* The raw check (before any section is parsed): the signed sample passes
 * with its version and name; every flip is refused but those in the two
 * checksum fields the signature leaves out, which the reader catches. */
static void test_raw_check_refuses_flips_before_parsing(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(5, owner_sk, &size);
    sw_trusted_keys keys = owner_keys();
    sw_pack_signature sig;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_check_signature_raw(bytes, size, &keys, &sig, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK(sig.pack_version == 5 && strcmp(sig.name, "sample") == 0);
    size_t passed = 0, caught_later = 0;
    for (size_t i = 0; i < size; i++) {
        bytes[i] ^= 0x10;
        if (sw_pack_check_signature_raw(bytes, size, &keys, &sig, &err) == SW_OK) {
            passed++;
            caught_later += check_bytes(bytes, size, &keys, &err) != SW_OK;
        }
        bytes[i] ^= 0x10;
    }
    printf("raw check: %zu of %zu flips passed it (the unsigned checksum fields), %zu of them "
           "refused by the reader\n", passed, size, caught_later);
    SW_CHECK(passed == 16 && caught_later == passed);
    for (size_t n = 0; n < size; n++)
        SW_CHECK(sw_pack_check_signature_raw(bytes, n, &keys, &sig, &err) != SW_OK);
    free(bytes);
}

/* A stranger's pack with a broken section: refused for its key, since the
 * signature is checked before the section's checksum is looked at. */
static void test_raw_check_names_the_key_before_a_checksum(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, other_sk, &size);
    bytes[table_of(bytes)[0].offset] ^= 1;
    sw_trusted_keys keys = owner_keys();
    sw_pack_signature sig;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_check_signature_raw(bytes, size, &keys, &sig, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(strstr(err.message, "not among the 1 trusted keys"), "%s", err.message);
    free(bytes);
}

/* A name is printed on terminals and in the journal: one with a control
 * byte is not signed, and a record holding one (a stranger's pack in a
 * slot, say) is refused before its name could be shown or its key looked
 * at. */
static void test_a_name_with_a_control_byte_is_refused(void)
{
    sample s;
    make_sample(&s);
    size_t plain_size, size;
    uint8_t *plain = serialize_sample(&s, &plain_size);
    sw_sign_request req = { owner_sk, 1, "show\033[2Jroom" };
    uint8_t *out = NULL;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_sign_bytes(plain, plain_size, &req, &out, &size, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(!strcmp(err.message, "pack name 'show\\x1b[2Jroom': a control byte at byte 4 "
                         "(a name is shown on terminals and in the journal)"), "%s", err.message);
    free(plain);
    free(out);
    uint8_t *bytes = signed_sample(1, other_sk, &size);
    uint32_t last = header_of(bytes)->section_count - 1;
    sw_pack_signature *sig = (sw_pack_signature *)(bytes + table_of(bytes)[last].offset);
    sig->name[2] = '\a';
    sw_trusted_keys keys = owner_keys();
    sw_pack_signature got;
    SW_CHECK(sw_pack_check_signature_raw(bytes, size, &keys, &got, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "SIGNATURE.name: a control byte (0x07) at byte 2") != NULL,
                 "%s", err.message);
    sig->name[2] = 0x7f;
    table_of(bytes)[last].checksum = XXH3_64bits(sig, sizeof *sig);
    reseal(bytes);
    SW_CHECK(check_bytes(bytes, size, &keys, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "a control byte (0x7f) at byte 2") != NULL, "%s",
                 err.message);
    free(bytes);
}

/* Located from the header and table: too few bytes for the table says how
 * many are needed. */
static void test_locate_asks_for_the_whole_table(void)
{
    size_t size;
    uint8_t *bytes = signed_sample(1, owner_sk, &size);
    uint32_t index;
    uint64_t offset, table = 0;
    sw_error err = { 0 };
    SW_CHECK(sw_pack_signature_locate(bytes, 64, size, &index, &offset, &table, &err) ==
             SW_ERR_RANGE);
    SW_CHECK(table == 64u + 32u * header_of(bytes)->section_count);
    SW_CHECK(sw_pack_signature_locate(bytes, (size_t)table, size, &index, &offset, NULL,
                                      &err) == SW_OK);
    SW_CHECK(index == header_of(bytes)->section_count - 1 &&
             offset == table_of(bytes)[index].offset);
    free(bytes);
}

int main(void)
{
    SW_CHECK(sodium_init() >= 0);
    crypto_sign_keypair(owner_pk, owner_sk);
    crypto_sign_keypair(other_pk, other_sk);
    SW_RUN(test_signed_pack_validates_and_records_version_and_name);
    SW_RUN(test_signing_again_replaces_the_signature);
    SW_RUN(test_unsigned_pack_is_refused);
    SW_RUN(test_wrong_key_is_refused);
    SW_RUN(test_forged_key_field_is_refused);
    SW_RUN(test_every_flipped_byte_is_refused);
    SW_RUN(test_flip_with_valid_checksums_is_refused);
    SW_RUN(test_every_truncation_is_refused);
    SW_RUN(test_raw_check_refuses_flips_before_parsing);
    SW_RUN(test_raw_check_names_the_key_before_a_checksum);
    SW_RUN(test_a_name_with_a_control_byte_is_refused);
    SW_RUN(test_locate_asks_for_the_whole_table);
    SW_RUN(test_public_key_file_parses_keys_and_comments);
    SW_RUN(test_public_key_file_errors_name_the_line);
    SW_RUN(test_secret_key_file_round_trip_and_errors);
    return sw_test_finish();
}
