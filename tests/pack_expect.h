/* SPDX-License-Identifier: MIT */
/* Shared by the pack reader's tests (test_pack_seam.c, test_pack_levels.c):
 * a pack must open with the status expected, its message naming the rule,
 * and the same with the checks' parts run backwards. Include after
 * sw_test.h. */
#ifndef PACK_EXPECT_H
#define PACK_EXPECT_H

#include <string.h>

#include "parts_backwards.h"
#include "sw_pack.h"

static void expect_open(const uint8_t *bytes, size_t size, sw_status status, const char *needle)
{
    sw_pack pack;
    sw_error err = { 0 }, backwards_err;
    sw_status got = sw_pack_open_memory(bytes, size, &pack, &err);
    SW_CHECK_MSG(got == status, "expected %s, got %s: %s", sw_status_name(status),
                 sw_status_name(got), err.message);
    SW_CHECK_MSG(status == SW_OK || strstr(err.message, needle) != NULL, "\"%s\" not in \"%s\"",
                 needle, err.message);
    /* The loader's threads run the checks' parts in any order. */
    SW_CHECK_MSG(sw_opens_the_same_backwards(bytes, size, got, err.message, &backwards_err),
                 "parts run backwards: \"%s\", in order: %s \"%s\"", backwards_err.message,
                 sw_status_name(got), err.message);
}

#endif
