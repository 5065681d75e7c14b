/* SPDX-License-Identifier: MIT */
/* Per-frame budgets of the threaded walk (paper 004 section 6.4): the
 * weight function that orders the surfaces needing work, and the
 * controller that sets N (new triangles: surfaces tessellated for a new
 * bound or for the first time) and M (updated triangles: surfaces whose
 * loops the seam update changed) for each frame so the GL thread holds
 * --target-ms, instead of the paper's fixed 1,000 and 10,000.
 *
 * The paper fixes N and M for its machine and scales N by the visible
 * error; here both follow from what is measured: the workers' throughput
 * (triangles a worker makes per millisecond, averaged) times the frame
 * time (the target, or the last frame when longer) times the workers gives
 * what they can make while one frame is drawn, so a batch is done in about
 * a frame. M is spent by the seam update, which cannot be cut short
 * without leaving loops that cross (a capped update's front gave the
 * 40,000-patch showroom 177 refused surfaces): its seams move only for the
 * surfaces N chose (sw_seam_walk_threads.c), and what the update spends
 * over M comes out of the next N; the stats count the batches that went
 * over (threads.updated: on the 40,000-patch showroom's 120-frame walk,
 * 48 of 50 budgeted batches, up to 96 times M). A cap at the choice was
 * tried and left out: each surface taken only while its neighbours'
 * remakes (estimated) fit in M. On the same walk 26 of 27 budgeted
 * batches still went over M, up to 384 times it: the surfaces in view without a mesh must
 * follow their targets all the same (left in loops from when they were
 * out of view, their meshes were made 1e29 times coarser than the bound),
 * and forced splits reach past a surface's neighbours. A back-off scale shrinks both while the
 * GL thread's frames run over the target (every mesh made is uploaded and
 * drawn by it, and on a small machine the workers share the cores with the
 * rasteriser) and grows it back when they are under; where drawing alone
 * exceeds the target, over 1.25 times that. The seam update's
 * operations are capped the same way: M over the triangles one operation
 * made dirty, on average. Used by the walk on its own thread; no
 * allocation. */
#ifndef SW_SEAM_BUDGET_H
#define SW_SEAM_BUDGET_H

#include <stdint.h>

typedef struct sw_seam_budget {
    double target_ms;
    double new_tris, updated_tris;   /* N and M for the next frame */
    double updated_used;             /* of M, what the last update spent (the walk sets it) */
    double scale;                    /* back-off, [0.1, 1] */
    double base_ms;                  /* frames that swapped nothing in, averaged */
    double tris_per_ms;              /* a worker's throughput, averaged */
    uint64_t seen_tris, seen_ns;     /* the workers' totals at the last frame */
} sw_seam_budget;

void sw_seam_budget_init(sw_seam_budget *b, double target_ms);

/* After a frame of frame_ms on the GL thread (swapped: it swapped a batch
 * in, uploads and all); made_tris and busy_ns are the workers' running
 * totals (sw_seam_workers.h). The frame time held is the target, or 1.25
 * times what drawing alone takes when that is more. */
void sw_seam_budget_after_frame(sw_seam_budget *b, double frame_ms, int swapped,
                                uint64_t made_tris, uint64_t busy_ns, uint32_t workers);

/* The weight w of paper 004 section 6.4 for a mesh valid for bounds in
 * [eps_min, eps_max] when the view asks for eps: (eps_min / eps)^2 when
 * finer is needed, eps / eps_max when it could be coarser, 0 inside; both
 * cases are >= 1. No mesh at all weighs more than any: 1e30. */
double sw_seam_weight(int has_mesh, double eps_min, double eps_max, double eps);

/* w' for a culled surface: 1 - 1 / w, below every visible one (0 for w 0). */
double sw_seam_weight_culled(double w);

/* A candidate for the frame's work, and the sort that puts the heaviest
 * first (a heap sort: in place, no allocation, unlike qsort). */
typedef struct sw_seam_candidate {
    float weight;
    uint32_t surface;
} sw_seam_candidate;
void sw_seam_candidates_sort(sw_seam_candidate *c, uint32_t n);

#endif
