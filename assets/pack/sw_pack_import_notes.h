/* SPDX-License-Identifier: MIT */
/* The import reports of a build as the pack's IMPORT_NOTES records
 * (core/sw_pack_notes.h): one per input file and kind of skipped entity or
 * message read past, so `seamwalk-pack info` can tell them later. Host only. */
#ifndef SW_PACK_IMPORT_NOTES_H
#define SW_PACK_IMPORT_NOTES_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_import.h"
#include "sw_pack.h"

/* names[i] (the input's file name, no folders) and reports[i] for n inputs.
 * *out is malloc'd (the caller frees it; NULL with *count 0 when there is
 * nothing to say). Kinds a tally counted without naming them become one
 * "(other kinds)" record. */
sw_status sw_pack_notes_from_reports(const char *const *names, const sw_import_report *reports,
                                     size_t n, sw_pack_import_note **out, uint32_t *count,
                                     sw_error *err);

#endif
