/* SPDX-License-Identifier: MIT */
/* The Seam Graph sections (SEAM, SEAM_VERTICES, SEAM_SLOTS, SEAM_LOOPS,
 * SEAM_EDGES, SEAM_COLLAPSES, SEAM_SLOT_REFS, SEAM_SURFACE_LOOPS;
 * core/sw_seam_graph.h): the SEAM header record here, then every rule of the
 * graph itself in sw_seam_graph_check (core/sw_seam_check.c), the one set of
 * rules the host builders are held to as well. Rules: assets/PACK_FORMAT.md. */
#include <math.h>
#include <stdio.h>

#include "sw_pack_validate.h"
#include "sw_seam_check.h"

static int finite_non_negative(float x) { return isfinite(x) && x >= 0.0f; }

static sw_status validate_seam_header(const sw_pack *pack, sw_error *err)
{
    const sw_pack_seam *h = pack->seam_header;
    for (size_t i = 0; i < sizeof h->reserved; i++)
        if (h->reserved[i] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "SEAM.reserved[%zu]: 0x%02x, expected 0", i,
                                h->reserved[i]);
    if (!finite_non_negative(h->tolerance))
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM.tolerance: %g, expected finite >= 0",
                            (double)h->tolerance);
    if (h->surface_count != pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "SEAM.surface_count: %u, but SURFACES has %u "
                            "entries", (unsigned)h->surface_count, (unsigned)pack->surface_count);
    if ((uint64_t)h->original_count + h->collapse_count != h->vertex_count)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM.vertex_count: %u, expected original_count "
                            "%u + collapse_count %u", (unsigned)h->vertex_count,
                            (unsigned)h->original_count, (unsigned)h->collapse_count);
    if (h->slot_ref_count != h->slot_count)
        return sw_error_set(err, SW_ERR_FORMAT, "SEAM.slot_ref_count: %u, expected slot_count %u "
                            "(every slot is listed once)", (unsigned)h->slot_ref_count,
                            (unsigned)h->slot_count);
    return SW_OK;
}

sw_status sw_pack_validate_seam(const sw_pack *pack, const sw_parts_runner *runner,
                                sw_error *err)
{
    if (!pack->seam_header)
        return SW_OK;
    sw_status s = validate_seam_header(pack, err);
    return s == SW_OK ? sw_seam_graph_check_with(&pack->seam, runner, err) : s;
}
