/* SPDX-License-Identifier: MIT */
/* A pack file opened for the tests that take packs the tool built (CTest
 * passes their paths): test_levels_build, test_cluster,
 * test_part_levels_build, test_build_threads. Include after sw_test.h. */
#ifndef PACK_FILE_H
#define PACK_FILE_H

#include <stdint.h>
#include <stdlib.h>

#include "sw_pack.h"
#include "sw_pack_instances.h"

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

/* The same, a pack of placed parts expanded into the scene the runtime
 * walks (a plain pack as it is): *placed is malloc'd for the caller to
 * free after the bytes' pack, NULL when nothing was expanded. */
static inline uint8_t *sw_test_open_placed_pack(const char *path, sw_pack *pack, void **placed)
{
    *placed = NULL;
    sw_pack stored;
    uint8_t *bytes = sw_test_open_pack_file(path, &stored);
    if (!bytes)
        return NULL;
    *pack = stored;
    if (!stored.instances)
        return bytes;
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(stored.prototypes, stored.instances, stored.instance_count, counts);
    size_t need = (size_t)sw_pack_expand_bytes(counts);
    sw_arena arena;
    sw_error err = { 0 };
    *placed = malloc(need);
    sw_arena_init(&arena, *placed, need);
    if (!*placed || sw_pack_expand(&stored, &arena, pack, &err) != SW_OK) {
        SW_CHECK_MSG(0, "%s: %s", path, *placed ? err.message : "out of memory");
        free(*placed);
        free(bytes);
        *placed = NULL;
        return NULL;
    }
    return bytes;
}

#endif
