/* SPDX-License-Identifier: MIT */
/* The pack as flat arrays in memory, before it is serialised: what the
 * writer (sw_pack_write.h) lays out and the section builders
 * (sw_pack_sections.h) fill. Host only. */
#ifndef SW_PACK_CONTENTS_H
#define SW_PACK_CONTENTS_H

#include <stdint.h>

#include "sw_levels.h"
#include "sw_pack.h"
#include "sw_seam_graph.h"
#include "sw_super.h"

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
    /* The up axis, or NULL for no ORIENTATION section (readers take +y).
     * Not owned, like seam. */
    const sw_pack_orientation *orientation;
    /* The import notes, or NULL for no IMPORT_NOTES section (nothing to
     * say). Not owned, like seam. */
    const sw_pack_import_note *import_notes;
    uint32_t import_note_count;
    /* The static levels of detail (core/sw_levels.h), or NULL for none:
     * written as the LEVELS record (the view's counts) and the six LEVEL_*
     * sections. Not owned, like seam; the pack validates only with a Seam
     * Graph whose loops the chains follow, and levels->surface_count equal
     * to surface_count above. */
    const sw_levels *levels;
    /* The super-surfaces (core/sw_super.h), or NULL for none: written as
     * SUPER_SURFACES, SUPER_MEMBERS and SUPER_OF. Not owned, like seam;
     * supers->surface_count must be surface_count above. */
    const sw_supers *supers;
    /* The part levels (core/sw_part_levels.h), or NULL for none: written
     * as the PART_LEVELS record and the four PART_LEVEL_* sections. Not
     * owned, like seam; part_levels->part_count must be meta.part_count. */
    const sw_part_levels *part_levels;
    /* The prototypes and their instances (core/sw_pack_instances.h), or
     * NULL for a pack of parts drawn where they are (version 1). Not owned,
     * like seam. */
    const sw_pack_prototype *prototypes;
    uint32_t prototype_count;
    const sw_pack_instance *instances;
    uint32_t instance_count;
} sw_pack_contents;

#endif
