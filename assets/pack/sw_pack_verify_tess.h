/* SPDX-License-Identifier: MIT */
/* `seamwalk-pack verify`'s proof that no surface is lost at run time: every
 * surface of a pack with a Seam Graph is tessellated, as the runtime's seam
 * walk does it (core/sw_trim_tess.c inside the loops sw_seam_select_loop
 * gives), at the finest seam state (every original vertex) and at the
 * states for seams within 1, 4, 16, ... sewing tolerances, up to the
 * coarsest where anything is still drawn. A surface whose tessellation fails
 * at one of them would be a hole in the picture there. Host only: it
 * allocates. */
#ifndef SW_PACK_VERIFY_TESS_H
#define SW_PACK_VERIFY_TESS_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_pack.h"

typedef struct sw_pack_tess_report {
    uint32_t surfaces;            /* of the pack */
    uint32_t states;              /* seam states checked, the finest first */
    uint32_t checks;              /* surface tessellations tried (vanished ones not) */
    uint32_t failed;              /* of them, refused by the tessellator */
    uint32_t holes_filled;        /* drawn without their holes, as the runtime then draws them */
    uint32_t untangled;           /* drawn untangled: slits cut out, touching loops parted
                                     (sw_seam_surface_untangle) */
    uint32_t first_failed;        /* the first surface refused, UINT32_MAX when none was */
} sw_pack_tess_report;

/* Checks every drawn surface at every state, with the bound the runtime
 * would use there (the seams' bound over their share; 1e-3 of the surface's
 * box at the finest), coarsened like the runtime when a surface needs more
 * vertices than one draw holds. SW_OK when none failed; SW_ERR_FORMAT naming
 * the first surface that failed, its seams' bound and the tessellator's
 * reason otherwise (out is filled either way); SW_ERR_NO_MEMORY. A pack
 * without a Seam Graph has nothing to check (out all zero). */
sw_status sw_pack_verify_tessellation(const sw_pack *pack, sw_pack_tess_report *out,
                                      sw_error *err);

/* The same, also setting failed[s] to 1 for every surface s refused at one
 * of the states (failed: pack->seam.surface_count bytes, left as they are
 * for the others; NULL: none set). */
sw_status sw_pack_verify_tessellation_marks(const sw_pack *pack, uint8_t *failed,
                                            sw_pack_tess_report *out, sw_error *err);

#endif
