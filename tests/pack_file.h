/* SPDX-License-Identifier: MIT */
/* A pack file opened for the tests that take packs the tool built (CTest
 * passes their paths): test_levels_build, test_cluster,
 * test_part_levels_build, test_build_threads. Include after sw_test.h. */
#ifndef PACK_FILE_H
#define PACK_FILE_H

#include <stdint.h>
#include <stdlib.h>

#include "sw_pack.h"

/* The pack in the file at path, opened into *pack: its bytes (malloc'd,
 * for the caller to free when done with the pack), or NULL, a failed
 * check, when the file cannot be read or the reader refuses it. */
static inline uint8_t *sw_test_open_pack_file(const char *path, sw_pack *pack)
{
    size_t size = 0;
    uint8_t *bytes = sw_test_read_file(path, &size);
    sw_error err = { 0 };
    if (bytes && sw_pack_open_memory(bytes, size, pack, &err) != SW_OK) {
        SW_CHECK_MSG(0, "%s: %s", path, err.message);
        free(bytes);
        return NULL;
    }
    return bytes;
}

#endif
