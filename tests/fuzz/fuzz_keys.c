/* SPDX-License-Identifier: MIT */
/* Fuzz target: the key file parsers, trusted public keys
 * (core/sw_pack_sign_check.c) and the signer's secret key
 * (assets/pack/sw_pack_sign.c). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "sw_pack_sign.h"
#include "sw_pack_signature.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_trusted_keys keys = { 0 };
    if (sw_trusted_keys_parse((const char *)data, size, "fuzz", &keys, NULL) == SW_OK &&
        keys.count > SW_TRUSTED_KEYS_MAX)
        abort();
    uint8_t sk[SW_SECRET_KEY_BYTES];
    (void)sw_secret_key_parse((const char *)data, size, "fuzz", sk, NULL);
    return 0;
}
