/* SPDX-License-Identifier: MIT */
/* The fuzz targets' resealing of a pack (fuzz_pack.c, fuzz_pack_load.c):
 * random mutations almost never keep an XXH3 checksum valid, so an input
 * is also tried with its checksums recomputed, to reach the checks behind
 * them. */
#ifndef FUZZ_RESEAL_H
#define FUZZ_RESEAL_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <xxhash.h>

#include "sw_pack.h"

/* Recomputes what it can: section checksums whose ranges lie in the buffer,
 * then the header checksum if the table fits. Touches nothing else. */
static inline void reseal(uint8_t *buf, size_t size)
{
    sw_pack_header h;
    memcpy(&h, buf, sizeof h);
    if (h.section_count > SW_PACK_MAX_SECTIONS || 64 + (size_t)h.section_count * 32 > size)
        return;
    for (uint32_t i = 0; i < h.section_count; i++) {
        sw_pack_section s;
        memcpy(&s, buf + 64 + (size_t)i * 32, sizeof s);
        if (s.offset <= size && s.size <= size - s.offset) {
            s.checksum = XXH3_64bits(buf + s.offset, (size_t)s.size);
            memcpy(buf + 64 + (size_t)i * 32, &s, sizeof s);
        }
    }
    h.header_checksum = 0;
    memcpy(buf, &h, sizeof h);
    h.header_checksum = XXH3_64bits(buf, 64 + (size_t)h.section_count * 32);
    memcpy(buf, &h, sizeof h);
}

/* The input in a buffer of our own, which reseal may change; calloc's
 * alignment suits any type. NULL when out of memory. */
static inline uint8_t *fuzz_copy(const uint8_t *data, size_t size)
{
    uint8_t *buf = calloc(1, size ? size : 1);
    if (buf && size)
        memcpy(buf, data, size);
    return buf;
}

#endif
