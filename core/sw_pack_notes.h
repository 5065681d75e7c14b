/* SPDX-License-Identifier: MIT */
/* The pack's IMPORT_NOTES section: what the host's importers skipped or
 * read past, per input file, carried so that `seamwalk-pack info` can say
 * it long after the build. The runtime ignores it. Kept apart from
 * sw_pack_read.c, as ORIENTATION is: one optional section, no group rules. */
#ifndef SW_PACK_NOTES_H
#define SW_PACK_NOTES_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_pack.h"

/* Called by sw_pack_open_memory on a pack whose table is checked: maps the
 * section into out (import_notes, import_note_count) after checking it: at
 * most one, a whole number of records, each of a known kind with a count of
 * at least 1 and both strings NUL-terminated in their fields. */
sw_status sw_pack_map_import_notes(const uint8_t *data, sw_pack *out, sw_error *err);

/* "skipped" or "(read past)" (for a message), "unknown" otherwise. */
const char *sw_pack_note_kind_name(uint32_t kind);

#endif
