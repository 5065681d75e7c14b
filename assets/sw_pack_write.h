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

/* The flat arrays of a pack, as the writer lays them out. Tests build these
 * by hand to make packs with chosen faults. */
typedef struct sw_pack_contents {
    sw_pack_meta meta;                  /* counts must match the arrays */
    const sw_pack_part *parts;
    const sw_pack_patch *patches;
    const float *control;               /* 4 floats per point */
    const sw_pack_adjacency *adjacency;
    /* Optional sections: each is written when its pointer is not NULL (even
     * with a count of 0) and left out when it is NULL. */
    const sw_pack_surface *surfaces;
    uint32_t surface_count;
    const sw_pack_trim_loop *trim_loops;
    uint32_t trim_loop_count;
    const sw_pack_trim_curve *trim_curves;
    uint32_t trim_curve_count;
    const float *trim_data;
    uint32_t trim_data_count;
    const sw_pack_patch_domain *patch_domains;  /* meta.patch_count records */
    const sw_pack_trim_mask *trim_masks;
    uint32_t trim_mask_count;
    const sw_pack_viewpoint *viewpoints;
    uint32_t viewpoint_count;
    const float *part_transforms;               /* 16 * meta.part_count floats */
    /* The Seam Graph, or NULL for none: written as the SEAM header (its
     * counts and tolerance) and the seven SEAM_* sections. Not owned:
     * sw_pack_contents_free leaves it alone; the graph's surface_count must
     * be surface_count above for the pack to validate. */
    const sw_seam_graph *seam;
} sw_pack_contents;

/* Serialises contents exactly as given (no validation, so tests can write
 * broken packs): header, section table (META, PARTS, PATCHES, CONTROL,
 * ADJACENCY, then the optional sections present in sw_section_type order,
 * the seam sections last when contents->seam is set),
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
