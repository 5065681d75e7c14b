/* SPDX-License-Identifier: MIT */
/* Surfaces whose sewn loops hold more points than one draw can show, cut
 * into pieces (sw_model_split.h) before the seams are sewn again. Every
 * loop point is a vertex of the surface's tessellation at the finest seam
 * state, and a draw holds 65536 vertices: a spring's wire swept along
 * thirty turns of a helix borders its one face with two runs of its seam,
 * 68,000 points at the sewing tolerance, and could not be drawn whole at
 * any state (the runtime and verify refused it). Host only (malloc). */
#ifndef SW_SEAM_SPLIT_H
#define SW_SEAM_SPLIT_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_model.h"
#include "sw_seam_build.h"

/* Loop points of one surface past which it is cut, and about how many
 * each piece gets: the rest of a draw is for the tessellation's own
 * vertices inside the loops. */
enum { SW_SEAM_SPLIT_POINTS = 16384, SW_SEAM_SPLIT_TARGET = 8192 };

typedef struct sw_seam_split_report {
    uint32_t cut;      /* surfaces cut */
    uint32_t pieces;   /* the pieces they became */
    uint32_t uncut;    /* surfaces past the limit no line could cut */
} sw_seam_split_report;

/* out (initialised, empty) gets model with every surface whose loops in
 * seams (sewn from model) hold more than SW_SEAM_SPLIT_POINTS points cut
 * along parameter lines into pieces of about SW_SEAM_SPLIT_TARGET, the
 * lines across the shorter way (by the points the cuts add); report says
 * what was done. report->cut 0: out is left empty, model needs nothing. */
sw_status sw_seam_split_long(const sw_model *model, const sw_seam_host *seams, sw_model *out,
                             sw_seam_split_report *report, sw_error *err);

#endif
