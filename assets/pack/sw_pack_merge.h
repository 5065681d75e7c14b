/* SPDX-License-Identifier: MIT */
/* Packs built apart joined into one pack of placed parts (version 2,
 * core/sw_pack_instances.h): each input pack becomes one prototype, its
 * records moved after the previous one's in every index space
 * (core/sw_pack_move.h), and the instances place them. The inputs are
 * packs of parts drawn where they are (version 1), each with the same
 * groups of sections (a Seam Graph, levels, clusters, part levels in all
 * or none). Host only: the arrays are malloc'd. */
#ifndef SW_PACK_MERGE_H
#define SW_PACK_MERGE_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_pack_contents.h"

typedef struct sw_pack_merged {
    sw_pack_contents contents;     /* views of the arrays below (the import notes are the
                                      inputs' in turn); viewpoints and orientation are the
                                      caller's to set */
    void *arrays[40];              /* owned */
    sw_pack_meta meta;
    sw_seam_graph seam;
    sw_levels levels;
    sw_supers supers;
    sw_part_levels part_levels;
} sw_pack_merged;

/* packs[0 .. count) into out, placed by instances (their prototype fields
 * index packs; their transforms and names are copied as given). Errors name
 * the input by its index: a pack with instances of its own, groups that
 * differ, totals past a 32-bit index. */
sw_status sw_pack_merge(const sw_pack *packs, uint32_t count, const sw_pack_instance *instances,
                        uint32_t instance_count, sw_pack_merged *out, sw_error *err);
void sw_pack_merged_free(sw_pack_merged *m);

#endif
