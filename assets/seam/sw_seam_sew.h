/* SPDX-License-Identifier: MIT */
/* The original Seam Graph of a model: its trimming loops flattened within
 * the sewing tolerance (sw_seam_flatten.h) and sewn across surfaces
 * (sw_sew.h), in an sw_seam_host with no collapses yet (Guthe et al. 2002,
 * sections 4 and 4.1). The pack builder calls it before the collapse
 * hierarchy is built. Host only (malloc). */
#ifndef SW_SEAM_SEW_H
#define SW_SEAM_SEW_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"
#include "sw_seam_build.h"

/* Zero means default for every field. */
typedef struct sw_seam_options {
    /* Model units (mm). 0: the model's tolerance (model_tolerance, from the
     * file), but at least 1e-5 of the size of its smallest part (box
     * diagonal) and 1e-6 of the whole model's. Why 1e-5 of a part: files
     * state tolerances tighter than their faces meet (the OCCT screw's 1e-6
     * of its size left 1414 of 10343 edges unsewn, its faces' gaps being
     * just wider; at 1e-5, 6 of 2888; the hammer 2131 -> 59, linkrods
     * 5633 -> 1713), and an unsewn border is simplified on each side alone;
     * of the smallest part, so a showroom's small parts are not sewn shut.
     * Why 1e-6 of the whole: float positions resolve about 1e-7 of it, and
     * a showroom's seams finer than that are pack size for nothing (a 40000
     * patch hall: 2.2 M boundary vertices and 278 MB at the 0.01 mm of its
     * smallest part, 0.8 M and 116 MB at 1e-6 of the hall). A model that
     * states none (Newell, .bpt) gets the same floor: such inputs share
     * their boundary rows exactly, and a larger default would sew shut real
     * features of that size (the Newell teapot's lid has a hole of radius
     * 1.3e-4 of its diagonal at the knob). An empty model gets 1e-3. */
    double tolerance;
} sw_seam_options;

/* The widest a trim's own gap (its edge's tolerance) may reach when sewn,
 * as a fraction of the model's box (sw_seam_sew.c, hold_gaps). */
#define SW_SEAM_GAP_CAP 1e-2

typedef struct sw_seam_report {
    size_t loops;
    size_t boundary_vertices;   /* vertex_count */
    size_t boundary_edges;      /* edge_count */
    size_t seams;               /* edges shared by >= 2 loops */
    size_t free_edges;          /* edges of one loop only */
    size_t nonmanifold_edges;   /* edges of > 2 loops */
    double tolerance;           /* the tolerance used */
    size_t unproven_pieces;     /* trim pieces the flattener could not prove (sw_seam_flatten.h) */
    size_t clamped;             /* trim points outside their domain put on its border */
    size_t gaps_held;           /* trim vertices whose gap was held to SW_SEAM_GAP_CAP */
    size_t inserted;            /* points inserted into edges by sewing */
    double flatten_s, sew_s;    /* wall time of the two stages */
} sw_seam_report;

/* The tolerance opt (may be NULL) asks for, resolved against the model as
 * documented above. */
double sw_seam_default_tolerance(const sw_model *model, const sw_seam_options *opt);

/* Flattens and sews every surface of model into out (zeroed first; on
 * failure left empty). Fills every array of sw_seam_host: vertices, slots,
 * loops grouped by surface in surface order (SW_SEAM_LOOP_OUTER on outer
 * loops and on the domain rectangle of untrimmed surfaces), edges (a < b,
 * each once), slot_refs grouped by vertex, surface_loops (surface_count + 1),
 * tolerance; collapse_count 0, vertex_count == original_count. report may be
 * NULL. SW_ERR_ARG for NULL model or out or a negative or non-finite
 * tolerance; SW_ERR_FORMAT for a trim loop with no extent. */
sw_status sw_seam_sew_model(const sw_model *model, const sw_seam_options *opt, sw_seam_host *out,
                            sw_seam_report *report, sw_error *err);

#endif
