/* SPDX-License-Identifier: MIT */
/* Section types by name (sw_pack.h), for the reader's and the tools'
 * messages: a table apart from the reader, which grows with each group. */
#include "sw_pack.h"

const char *sw_section_type_name(uint32_t type)
{
    switch (type) {
    case SW_SECTION_META: return "META";
    case SW_SECTION_PARTS: return "PARTS";
    case SW_SECTION_PATCHES: return "PATCHES";
    case SW_SECTION_CONTROL: return "CONTROL";
    case SW_SECTION_ADJACENCY: return "ADJACENCY";
    case SW_SECTION_SURFACES: return "SURFACES";
    case SW_SECTION_TRIM_LOOPS: return "TRIM_LOOPS";
    case SW_SECTION_TRIM_CURVES: return "TRIM_CURVES";
    case SW_SECTION_TRIM_DATA: return "TRIM_DATA";
    case SW_SECTION_PATCH_DOMAINS: return "PATCH_DOMAINS";
    case SW_SECTION_TRIM_MASKS: return "TRIM_MASKS";
    case SW_SECTION_VIEWPOINTS: return "VIEWPOINTS";
    case SW_SECTION_PART_TRANSFORMS: return "PART_TRANSFORMS";
    case SW_SECTION_SEAM: return "SEAM";
    case SW_SECTION_SEAM_VERTICES: return "SEAM_VERTICES";
    case SW_SECTION_SEAM_SLOTS: return "SEAM_SLOTS";
    case SW_SECTION_SEAM_LOOPS: return "SEAM_LOOPS";
    case SW_SECTION_SEAM_EDGES: return "SEAM_EDGES";
    case SW_SECTION_SEAM_COLLAPSES: return "SEAM_COLLAPSES";
    case SW_SECTION_SEAM_SLOT_REFS: return "SEAM_SLOT_REFS";
    case SW_SECTION_SEAM_SURFACE_LOOPS: return "SEAM_SURFACE_LOOPS";
    case SW_SECTION_ORIENTATION: return "ORIENTATION";
    case SW_SECTION_IMPORT_NOTES: return "IMPORT_NOTES";
    case SW_SECTION_LEVELS: return "LEVELS";
    case SW_SECTION_LEVEL_RECORDS: return "LEVEL_RECORDS";
    case SW_SECTION_LEVEL_SURFACES: return "LEVEL_SURFACES";
    case SW_SECTION_LEVEL_VERTICES: return "LEVEL_VERTICES";
    case SW_SECTION_LEVEL_INDICES: return "LEVEL_INDICES";
    case SW_SECTION_LEVEL_CHAINS: return "LEVEL_CHAINS";
    case SW_SECTION_LEVEL_CHAIN_POINTS: return "LEVEL_CHAIN_POINTS";
    case SW_SECTION_SUPER_SURFACES: return "SUPER_SURFACES";
    case SW_SECTION_SUPER_MEMBERS: return "SUPER_MEMBERS";
    case SW_SECTION_SUPER_OF: return "SUPER_OF";
    case SW_SECTION_PART_LEVELS: return "PART_LEVELS";
    case SW_SECTION_PART_LEVEL_RECORDS: return "PART_LEVEL_RECORDS";
    case SW_SECTION_PART_LEVEL_RANGES: return "PART_LEVEL_RANGES";
    case SW_SECTION_PART_LEVEL_VERTICES: return "PART_LEVEL_VERTICES";
    case SW_SECTION_PART_LEVEL_INDICES: return "PART_LEVEL_INDICES";
    case SW_SECTION_PART_LEVEL_PIECE_OF: return "PART_LEVEL_PIECE_OF";
    case SW_SECTION_PROTOTYPES: return "PROTOTYPES";
    case SW_SECTION_INSTANCES: return "INSTANCES";
    }
    return "unknown";
}
