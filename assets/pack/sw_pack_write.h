/* SPDX-License-Identifier: MIT */
/* Builds a version-1 pack from a model: per-patch boxes and derivative bounds,
 * adjacency of patches that share a boundary curve, the section table with
 * checksums; writes it to memory or, atomically, to a file. Host only. */
#ifndef SW_PACK_WRITE_H
#define SW_PACK_WRITE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_import.h"
#include "sw_model.h"
#include "sw_pack.h"
#include "sw_pack_contents.h"

/* Serialises contents exactly as given (no validation, so tests can write
 * broken packs): header, section table (META, PARTS, PATCHES, CONTROL,
 * ADJACENCY, then the optional sections present in sw_section_type order,
 * the seam sections when contents->seam is set, ORIENTATION when
 * contents->orientation is, IMPORT_NOTES when contents->import_notes is, the
 * seven level sections when contents->levels is, the three super-surface
 * sections last when contents->supers is),
 * sections 64-byte aligned, checksums. *out is malloc'd; the caller frees it. */
sw_status sw_pack_serialize(const sw_pack_contents *contents, uint8_t **out, size_t *out_size,
                            sw_error *err);

/* Converts a model to contents: float control points, boxes, derivative bounds
 * (sw_bezier_second_deriv_bounds), adjacency by matching boundary control rows
 * within tolerance, and every optional section (surfaces, trimming loops and
 * curves, patch domains and masks, viewpoints, part transforms), also for
 * models of plain Bezier patches, so every pack it makes has the same
 * sections. META.units is millimetres (the model's unit). Arrays are
 * malloc'd; release with sw_pack_contents_free. */
sw_status sw_pack_contents_from_model(const sw_model *model, sw_pack_contents *out,
                                      sw_error *err);

/* Where sw_pack_contents_from_model_progress reports its stages ("patches",
 * "adjacency", "trims") and the fraction of each done. */
typedef struct sw_pack_progress {
    sw_progress_fn fn;          /* may be NULL */
    void *user;
} sw_pack_progress;

/* The same, reporting progress (progress may be NULL). */
sw_status sw_pack_contents_from_model_progress(const sw_model *model,
                                               const sw_pack_progress *progress,
                                               sw_pack_contents *out, sw_error *err);
void sw_pack_contents_free(sw_pack_contents *contents);

/* Writes bytes to path through path.tmp-XXXXXX and rename, so an existing good
 * file is never left half-written. */
sw_status sw_write_file_atomic(const char *path, const uint8_t *bytes, size_t size, sw_error *err);

#endif
