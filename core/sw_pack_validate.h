/* Internal to the pack reader (sw_pack_read.c): the checks of the records
 * themselves, run once the header, the section table and every checksum have
 * been verified and each view's byte size matches its META count. Split out
 * so each file keeps one job: sw_pack_read.c the container, this the model. */
#ifndef SW_PACK_VALIDATE_H
#define SW_PACK_VALIDATE_H

#include "sw_pack.h"

/* pack's views and counts are in bounds; checks every record of META, PARTS,
 * PATCHES, CONTROL and ADJACENCY for values the runtime relies on. */
sw_status sw_pack_validate_records(const sw_pack *pack, sw_error *err);

/* Number of control points along edge (enum sw_patch_edge) of patch. */
static inline uint32_t sw_pack_edge_points(const sw_pack_patch *patch, uint32_t edge)
{
    return (edge == SW_EDGE_V0 || edge == SW_EDGE_V1) ? patch->degree_u + 1u
                                                      : patch->degree_v + 1u;
}

#endif
