/* SPDX-License-Identifier: MIT */
/* seamwalk-pack keygen, sign and verify --key: the command lines over
 * sw_pack_sign.h. Exit status 0, 1 failure (one line on stderr), 2 usage. */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sodium.h>

#include "sw_pack.h"
#include "sw_pack_sign.h"
#include "sw_pack_verify_tess.h"
#include "sw_pack_write.h"
#include "sw_text_scan.h"

static int usage(const char *fmt, const char *arg)
{
    return sw_usage_error("seamwalk-pack", fmt, arg);
}

static int fail(const sw_error *err)
{
    fprintf(stderr, "seamwalk-pack: %s\n", err->message);
    return 1;
}

int sw_pack_cmd_keygen(int argc, char **argv)
{
    if (argc != 2 || strcmp(argv[0], "-o") != 0)
        return usage("keygen: %s", "expected -o PREFIX");
    sw_error err = { 0 };
    if (sw_keygen_files(argv[1], &err) != SW_OK)
        return fail(&err);
    printf("seamwalk-pack: wrote %s.key (secret: keep it off the units) and %s.pub\n", argv[1],
           argv[1]);
    return 0;
}

typedef struct sign_args {
    const char *pack, *key, *name, *out;
    uint64_t version;
    int have_version;
} sign_args;

static int parse_version(const char *s, uint64_t *out)
{
    char *end;
    if (!s || s[0] < '0' || s[0] > '9')
        return 0;
    *out = strtoull(s, &end, 10);
    return *end == '\0';
}

static int parse_sign(int argc, char **argv, sign_args *a)
{
    for (int i = 0; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(o, "--key") == 0 && v)
            a->key = v, i++;
        else if (strcmp(o, "--name") == 0 && v)
            a->name = v, i++;
        else if (strcmp(o, "-o") == 0 && v)
            a->out = v, i++;
        else if (strcmp(o, "--version") == 0) {
            if (!parse_version(v, &a->version))
                return usage("sign: --version takes a whole number, not '%s'", v ? v : "");
            a->have_version = 1, i++;
        } else if (o[0] == '-' || a->pack)
            return usage("sign: unexpected '%s'", o);
        else
            a->pack = o;
    }
    if (!a->pack || !a->key || !a->name || !a->have_version)
        return usage("sign: %s", "needs PACK, --key, --version and --name");
    if (!a->out)
        a->out = a->pack;
    return 0;
}

static sw_status read_secret(const char *path, uint8_t sk[SW_SECRET_KEY_BYTES], sw_error *err)
{
    char *text;
    size_t size;
    sw_status st = sw_read_whole_file(path, &text, &size, err);
    if (st == SW_OK)
        st = sw_secret_key_parse(text, size, path, sk, err);
    if (text)
        sodium_memzero(text, size);
    free(text);
    return st;
}

static sw_status sign_file(const sign_args *a, sw_error *err)
{
    uint8_t sk[SW_SECRET_KEY_BYTES];
    char *in = NULL;
    uint8_t *out = NULL;
    size_t in_size, out_size;
    sw_status st = read_secret(a->key, sk, err);
    if (st == SW_OK && (st = sw_read_whole_file(a->pack, &in, &in_size, err)) == SW_OK) {
        sw_sign_request req = { sk, a->version, a->name };
        st = sw_pack_sign_bytes((const uint8_t *)in, in_size, &req, &out, &out_size, err);
        if (st != SW_OK)
            sw_error_prefix(err, "%s", a->pack);
    }
    sodium_memzero(sk, sizeof sk);
    if (st == SW_OK)
        st = sw_write_file_atomic(a->out, out, out_size, err);
    free(in);
    free(out);
    return st;
}

int sw_pack_cmd_sign(int argc, char **argv)
{
    sign_args a = { 0 };
    int rc = parse_sign(argc, argv, &a);
    if (rc != 0)
        return rc;
    sw_error err = { 0 };
    if (sign_file(&a, &err) != SW_OK)
        return fail(&err);
    printf("seamwalk-pack: signed %s as '%s' version %" PRIu64 " -> %s\n", a.pack, a.name,
           a.version, a.out);
    return 0;
}

static sw_status verify_file(const char *pack_path, const char *keys_path, sw_error *err)
{
    char *keys_text = NULL, *bytes = NULL;
    size_t keys_size, size;
    sw_trusted_keys keys = { 0 };
    sw_pack pack;
    const sw_pack_signature *sig;
    sw_status st = sw_read_whole_file(keys_path, &keys_text, &keys_size, err);
    if (st == SW_OK)
        st = sw_trusted_keys_parse(keys_text, keys_size, keys_path, &keys, err);
    if (st == SW_OK && keys.count == 0)
        st = sw_error_set(err, SW_ERR_FORMAT, "%s: no keys in the file", keys_path);
    if (st == SW_OK && (st = sw_read_whole_file(pack_path, &bytes, &size, err)) == SW_OK) {
        st = sw_pack_open_memory(bytes, size, &pack, err);
        if (st == SW_OK)
            st = sw_pack_check_signature(&pack, &keys, &sig, err);
        sw_pack_tess_report tess;   /* and, as unsigned verify, every surface drawable */
        if (st == SW_OK)
            st = sw_pack_verify_tessellation(&pack, &tess, err);
        if (st != SW_OK)
            sw_error_prefix(err, "%s", pack_path);
        else
            printf("%s: ok (%" PRIu32 " patches, %" PRIu64 " bytes), signed '%s' version %"
                   PRIu64 "\n", pack_path, pack.meta->patch_count, pack.header->total_size,
                   sig->name, sig->pack_version);
    }
    free(keys_text);
    free(bytes);
    return st;
}

int sw_pack_cmd_verify_signed(int argc, char **argv)
{
    const char *pack = NULL, *keys = NULL;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--key") == 0 && i + 1 < argc && !keys)
            keys = argv[++i];
        else if (argv[i][0] != '-' && !pack)
            pack = argv[i];
        else
            return usage("verify: unexpected '%s'", argv[i]);
    }
    if (!pack || !keys)
        return usage("verify: %s", "expected PACK --key KEYS.pub");
    sw_error err = { 0 };
    return verify_file(pack, keys, &err) == SW_OK ? 0 : fail(&err);
}
