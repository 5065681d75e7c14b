/* SPDX-License-Identifier: MIT */
/* Sewing (Guthe et al. 2002, section 4.1): the flattened trimming loops of
 * all surfaces (sw_seam_flatten.h) joined where they run within the sewing
 * tolerance of each other, so that the loops share vertices along every seam:
 * the original (un-simplified) Seam Graph in an sw_seam_host. Host only;
 * called by sw_seam_sew_model (sw_seam_sew.h), which most callers want.
 *
 * Steps:
 *  1. every polyline vertex is projected onto every edge of other loops
 *     that a 3D uniform grid names as near; projections within the
 *     tolerance whose foot lies on the edge are kept (a foot within a quarter
 *     of the tolerance, and of the edge, of an end is that end vertex), and
 *     only where one of the vertex's edges runs within 60 degrees of the
 *     target edge (edges shorter than twice the tolerance have no direction
 *     to trust): near a junction of several loops every vertex is within the
 *     tolerance of every edge leaving it. Where the file's topology names
 *     the shared edge both are uses of (sw_seam_polylines.edge), only
 *     projections onto the same edge count: a sliver narrower than the
 *     tolerance has each long side sewn to its own neighbour;
 *  2. per pair of loops, sewing intervals grow from the best projections
 *     along both polylines at once, one vertex of either side at a time
 *     (whichever comes first along them), a vertex joining only with a
 *     projection onto the edge at the interval's end on the other side or
 *     the next one (the paper's rule). Both directions of the other polyline
 *     are tried and the interval with more projections (then the longer one)
 *     kept. Projections strictly inside a finished interval are removed; its
 *     two end projections stay, so the next interval can start there;
 *  3. every projection of an interval merges its vertex with its foot: an
 *     end vertex, or a point inserted into the edge (so a T-junction gets the
 *     vertex on the long side). An interval no longer than the tolerance on
 *     either side is a point contact and merges vertices with vertices only.
 *     The merges are a union-find, so intervals of several pairs along one
 *     seam combine into one chain of shared vertices (the paper's
 *     recombination into n-surface intervals, figure 3): non-manifold seams
 *     come out with one vertex list. Two classes whose positions are more
 *     than twice the tolerance apart are never merged (a guard against
 *     chains of merges drifting; it did not trigger on the shared models).
 *
 * No fold-overs: interval growth only moves forward along both polylines
 * (a window of advances >= 0), and a foot's position along a straight edge is
 * its arc length, so the order of sewn points along each polyline is the
 * arc-length order of their partners: the arc-length reparameterisation of
 * the paper holds by construction.
 *
 * An inserted point's (u, v) in its loop is the linear interpolation of the
 * edge's ends at the foot's parameter (not point inversion): the edge's (u, v)
 * segment maps onto the surface within half the tolerance of its 3D segment
 * (sw_seam_flatten.h, promise 2), so the slot is within about the tolerance
 * of the vertex it holds.
 *
 * A merged vertex takes the position of the first original vertex in it (in
 * loop order): every other member was within the tolerance of its partner.
 * Vertices sewn to nothing stay where they are, on free edges.
 *
 * Slots: every polyline vertex keeps its slot (with its exact (u, v)) even
 * where sewing merged it with its neighbour (a patch side collapsed to a
 * point); inserted points that add no new vertex are left out.
 *
 * Partial: loops are sewn to other loops only; a loop that meets itself (the
 * seam line of a closed cylinder's single loop) keeps both sides as free
 * edges. Geometry that is degenerate at the tolerance's own scale (a side a
 * few tolerances long folding back along its neighbour, as at the Newell
 * teapot's knob) can come out as two layers of vertices up to twice the
 * tolerance apart instead of one seam. */
#ifndef SW_SEW_H
#define SW_SEW_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_seam_build.h"
#include "sw_seam_flatten.h"

/* What the sewing found; edges counted once each, by how many distinct loops
 * run along them. */
typedef struct sw_sew_counts {
    size_t projections;   /* kept projections (step 1) */
    size_t intervals;     /* accepted sewing intervals (step 2) */
    size_t inserted;      /* points inserted into edges (step 3) */
    size_t seams, free_edges, nonmanifold_edges;
} sw_sew_counts;

/* Sews poly with tolerance (> 0; usually poly->tolerance) into out (zeroed
 * first; on failure left empty). Fills every array of sw_seam_host with no
 * collapses: vertex_count == original_count, every child SW_SEAM_NONE,
 * error 0. counts may be NULL. */
sw_status sw_sew_polylines(const sw_seam_polylines *poly, double tolerance, sw_seam_host *out,
                           sw_sew_counts *counts, sw_error *err);

#endif
