/* SPDX-License-Identifier: MIT */
/* A parts runner (core/sw_parts.h) for the tests and the pack fuzzer: it
 * runs the parts last first. The loader's threads run the pack's checks in
 * any order, so a pack must open with the same status and message this way
 * as in order (test_pack, test_pack_seam, fuzz_pack). */
#ifndef SW_PARTS_BACKWARDS_H
#define SW_PARTS_BACKWARDS_H

#include <string.h>

#include "sw_pack.h"

static inline void sw_run_parts_backwards(void *ctx, sw_part_fn fn, void *arg, uint32_t count)
{
    (void)ctx;
    for (uint32_t p = count; p-- > 0;)
        fn(arg, p);
}

/* bytes opened with the parts run backwards: 1 when the status is `status`
 * and, for a refusal, the message is `message`; *again holds what it said. */
static inline int sw_opens_the_same_backwards(const uint8_t *bytes, size_t size,
                                              sw_status status, const char *message,
                                              sw_error *again)
{
    const sw_parts_runner backwards = {.run = sw_run_parts_backwards};
    sw_pack pack;
    *again = (sw_error){ SW_OK, "" };
    sw_status st = sw_pack_open_memory_with(bytes, size, &backwards, &pack, again);
    return st == status && (st == SW_OK || strcmp(again->message, message) == 0);
}

#endif
