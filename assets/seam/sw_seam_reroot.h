/* SPDX-License-Identifier: MIT */
/* The Seam Graph cut at the finest resolution its views need: the host
 * applies, once and for good, the collapses no reachable view undoes.
 *
 * Sewing stays as fine as the model asks (its tolerance: the seams close),
 * but the hierarchy over the sewn polylines need not reach down to it. A
 * walk cannot bring the eye closer to a part than some distance, and there
 * the bound is some error (the floor): every collapse whose error is within
 * it is active in every view the pack allows. sw_seam_reroot applies them on
 * the host and makes the front they leave the graph's original vertices:
 * the pack then holds and the runtime walks only the levels views use.
 * Beyond the paper, whose hierarchy always starts at the sewn polylines.
 *
 * Which collapses: the leading run of the simplification's sequence whose
 * vertices' errors are within the floor (the sequence is made cheapest
 * first, so that is what a cut by error takes, and the front stays one the
 * simplification passed through, where each collapse's error was measured).
 * A collapse of the run that would leave a loop fewer than three distinct
 * vertices (a hole or face smaller than the floor vanishing) is not applied,
 * nor any that builds on it: they stay in the hierarchy, so every surface
 * keeps its loops at the finest level and the runtime still draws it.
 *
 * The new original vertices keep the errors they had (the floor each
 * stands for; 0 only for the sewn points nothing was applied to, a made
 * one's at least FLT_MIN even where its collapses were flat, so a reader
 * tells the two apart); the runtime bounds a surface no
 * finer than its vertices' largest and counts the views that would ask for
 * finer (a view closer than the pack allows: clamped, never silent). Each
 * loop keeps of its slots, per run of slots now showing one vertex, the one
 * whose (u, v) the runtime used for that vertex (sw_seam_select_loop's
 * rule), and every slot on a degenerate side (a pole, whose corners the
 * runtime keeps). So a view at or beyond the floor draws as before. */
#ifndef SW_SEAM_REROOT_H
#define SW_SEAM_REROOT_H

#include "sw_seam_build.h"

typedef struct sw_seam_reroot_report {
    uint32_t applied;          /* collapses applied for good */
    uint32_t kept;             /* of those within the floor, kept so that no loop vanishes */
    uint32_t originals_before, originals_after;
    uint32_t slots_before, slots_after;
} sw_seam_reroot_report;

/* Re-roots graph (simplified: its collapses as sw_seam_simplify made them)
 * at floor (model units; <= 0 changes nothing). Replaces graph's arrays
 * (the old ones freed) only on success; SW_ERR_NO_MEMORY when malloc fails,
 * SW_ERR_FORMAT for a graph sw_seam_graph_check refuses. report may be
 * NULL. */
sw_status sw_seam_reroot(sw_seam_host *graph, float floor, sw_seam_reroot_report *report,
                         sw_error *err);

#endif
