/* SPDX-License-Identifier: MIT */
/* The pack's optional sections made from a model: SURFACES, TRIM_LOOPS,
 * TRIM_CURVES, TRIM_DATA, PATCH_DOMAINS, TRIM_MASKS, VIEWPOINTS and
 * PART_TRANSFORMS. Split from sw_pack_write.c (which converts the patches and
 * serialises) so each file keeps one job; called only by
 * sw_pack_contents_from_model. Host only. */
#ifndef SW_PACK_SECTIONS_H
#define SW_PACK_SECTIONS_H

#include <stddef.h>

#include "sw_model.h"
#include "sw_pack_contents.h"

/* Fills every optional array of out (each malloc'd and non-NULL, even when
 * empty, so every pack has the same sections) and its count from model,
 * rounding to float so that the result passes the reader's rules; what
 * rounding would break (a domain or knot range collapsing, a weight
 * underflowing, a degree above 15) is an error naming the model record.
 * On failure the arrays made so far stay in out for sw_pack_contents_free. */
sw_status sw_pack_sections_from_model(const sw_model *model, sw_pack_contents *out,
                                      sw_error *err);

/* The model's viewpoints as VIEWPOINT records (views holds
 * model->viewpoint_count), with the reader's rules checked. */
sw_status sw_pack_viewpoints_from_model(const sw_model *model, sw_pack_viewpoint *views,
                                       sw_error *err);

/* Copies a NUL-terminated name into a fixed field of cap bytes (NUL-padded),
 * cut to cap - 1 bytes and with every byte that does not start valid UTF-8
 * replaced by '?': importers pass through whatever encoding the source used,
 * and a cut may split a character. */
void sw_pack_copy_name(char *dst, size_t cap, const char *src);

#endif
