/* SPDX-License-Identifier: MIT */
/* Internal to the pack format code: the checks of the records themselves,
 * which sw_pack_read.c runs once the header, the section table and every
 * checksum have been verified and each view's byte size matches its META
 * count, and two small rules the writer (assets/pack/sw_pack_write.c) shares.
 * Split out so each file keeps one job: sw_pack_read.c the container,
 * sw_pack_validate.c, sw_pack_validate_trim.c, sw_pack_validate_seam.c and
 * sw_pack_validate_levels.c the records. */
#ifndef SW_PACK_VALIDATE_H
#define SW_PACK_VALIDATE_H

#include "sw_pack.h"
#include "sw_parts.h"

/* The header fields sw_pack_read_header (sw_pack_load.c) and
 * sw_pack_open_memory both check; what names the thing the size was
 * measured on ("data" or "file"). */
sw_status sw_pack_check_header_identity(const sw_pack_header *h, uint64_t actual_size,
                                        const char *what, sw_error *err);

/* pack's views and counts are in bounds; checks every record of META, PARTS,
 * PATCHES, CONTROL, ADJACENCY, VIEWPOINTS and PART_TRANSFORMS for values the
 * runtime relies on. */
sw_status sw_pack_validate_records(const sw_pack *pack, sw_error *err);

/* The trimmed-surface group (SURFACES, TRIM_LOOPS, TRIM_CURVES, TRIM_DATA,
 * PATCH_DOMAINS, TRIM_MASKS), in sw_pack_validate_trim.c; runs after
 * sw_pack_validate_records, so parts and patches are known good. Nothing to
 * check when the pack has no SURFACES section. */
sw_status sw_pack_validate_trim(const sw_pack *pack, sw_error *err);

/* The Seam Graph (SEAM and SEAM_*), in sw_pack_validate_seam.c; runs after
 * sw_pack_validate_trim, so SURFACES is known good. Nothing to check when
 * the pack has no SEAM section. The graph's rules in parts run by runner
 * (sw_parts.h, NULL: in order here). */
sw_status sw_pack_validate_seam(const sw_pack *pack, const sw_parts_runner *runner,
                                sw_error *err);

/* The static levels (LEVELS and LEVEL_*), in sw_pack_validate_levels.c;
 * runs after sw_pack_validate_seam, so the Seam Graph's loops the chains
 * follow are known good. Nothing to check when the pack has no LEVELS
 * section. The per-level checks in parts run by runner (sw_parts.h, NULL:
 * in order here). */
sw_status sw_pack_validate_levels(const sw_pack *pack, const sw_parts_runner *runner,
                                  sw_error *err);

/* An optional group of sections not indexed by the reader's table pass
 * (sw_pack_read.c): index[k] the table entry of types[k], or -1. Each may
 * appear once and hold a whole number of its records (record_bytes[k]);
 * else SW_ERR_FORMAT naming the section. */
sw_status sw_pack_find_group(const sw_pack *pack, const uint32_t *types,
                             const uint64_t *record_bytes, int count, int32_t *index,
                             sw_error *err);

/* The super-surfaces (SUPER_SURFACES, SUPER_MEMBERS, SUPER_OF), in
 * sw_pack_validate_super.c; called last by sw_pack_open_memory on a pack
 * whose SURFACES are known good. Finds its own sections (all three or
 * none, each at most once), maps them into out->supers and checks every
 * rule of PACK_FORMAT.md, "Super-surfaces", allocating nothing. */
sw_status sw_pack_map_supers(const uint8_t *data, sw_pack *out, sw_error *err);

/* The part levels' six sections (sw_pack_validate_part_levels.c): all or
 * none, their counts and every rule of PACK_FORMAT.md's "Part levels". */
sw_status sw_pack_map_part_levels(const uint8_t *data, sw_pack *out, sw_error *err);

/* Number of control points along edge (enum sw_patch_edge) of patch. */
static inline uint32_t sw_pack_edge_points(const sw_pack_patch *patch, uint32_t edge)
{
    return (edge == SW_EDGE_V0 || edge == SW_EDGE_V1) ? patch->degree_u + 1u
                                                      : patch->degree_v + 1u;
}

/* Length of the valid UTF-8 sequence at s (n bytes available), or 0 when
 * there is none: strict, so no overlong forms, no surrogates, nothing past
 * U+10FFFF. Part names must be valid so any text renderer can show them; the
 * writer uses this to repair names cut short by the 55-byte limit. */
static inline size_t sw_utf8_sequence_length(const unsigned char *s, size_t n)
{
    unsigned c = s[0];
    size_t len = c < 0x80 ? 1 : (c >= 0xC2 && c <= 0xDF) ? 2 : (c >= 0xE0 && c <= 0xEF) ? 3
                            : (c >= 0xF0 && c <= 0xF4) ? 4 : 0;
    if (len == 0 || len > n)
        return 0;
    for (size_t k = 1; k < len; k++)
        if ((s[k] & 0xC0) != 0x80)
            return 0;
    unsigned c1 = len > 1 ? s[1] : 0;
    if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 > 0x9F) || (c == 0xF0 && c1 < 0x90) ||
        (c == 0xF4 && c1 > 0x8F))
        return 0;
    return len;
}

/* Offset of the first byte of s[0..n) that does not start a valid UTF-8
 * sequence, or -1 when all of it is valid. */
static inline long sw_utf8_error_at(const unsigned char *s, size_t n)
{
    for (size_t i = 0; i < n;) {
        size_t len = sw_utf8_sequence_length(s + i, n - i);
        if (len == 0)
            return (long)i;
        i += len;
    }
    return -1;
}

#endif
