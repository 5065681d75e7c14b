/* SPDX-License-Identifier: MIT */
/* The Seam Graph's collapse hierarchy (Guthe et al. 2002, sections
 * 5.2-5.5), built on the host after sewing: seamwalk-pack calls it on the
 * sewn graph before writing the pack. The runtime walks the result with
 * core/sw_seam_select.h. */
#ifndef SW_SEAM_SIMPLIFY_H
#define SW_SEAM_SIMPLIFY_H

#include "sw_seam_build.h"
#include "sw_seam_runs.h"

/* Takes graph as sewing leaves it (original vertices only: no collapses,
 * every child SW_SEAM_NONE, every error 0) and appends the collapses and the
 * vertices they create, until one vertex per connected part is left (whole
 * surfaces vanish at the coarse end). Adjacency comes from the loops: two
 * vertices are adjacent when they are consecutive and distinct in a loop;
 * graph->edges must list exactly those pairs.
 *
 * Each step collapses the cheapest edge into one of its two vertices (the
 * new vertex copies the kept one's position, paper 5.2). The cost of
 * v1 -> v2 is epsilon + d (5.3): epsilon the largest distance from v1 to the
 * edges (v2, w) that replace v1's edges (v1, w) (|v1 v2| when v1 has no
 * other neighbour), d the error stored at v1 by earlier steps; the cheaper
 * direction wins. Costs sit in a binary heap, one entry per vertex (its best
 * collapse), and after each step the costs of the new vertex and its
 * neighbours are recomputed (5.4). Vertex errors are monotone: a created
 * vertex's error is the largest of its step's and its parents'.
 *
 * Grows graph->vertices (realloc) and allocates graph->collapses (the old
 * pointer, which must hold no collapses, is freed). SW_ERR_FORMAT /
 * SW_ERR_RANGE for a malformed graph, SW_ERR_NO_MEMORY when malloc fails;
 * on failure graph is left as it came in (children and counts restored). */
sw_status sw_seam_simplify(sw_seam_host *graph, sw_error *err);

/* The same with the exact surfaces at hand for the parameter-space term of
 * epsilon (sw_seam_runs.h; beyond the paper, whose epsilon is model space
 * only); eval NULL estimates it from the loops alone, as sw_seam_simplify. */
sw_status sw_seam_simplify_on(sw_seam_host *graph, const sw_seam_surface_eval *eval,
                              sw_error *err);

/* The same with vertices that never collapse, nor take another's collapse
 * (pinned: graph->original_count bytes, 1 = pinned; NULL: none): the loops
 * they are on keep them at every state. A graph that holds collapses from
 * an earlier run is taken back to its original vertices first. */
sw_status sw_seam_simplify_pinned(sw_seam_host *graph, const sw_seam_surface_eval *eval,
                                  const uint8_t *pinned, sw_error *err);

/* Pins (pinned[v] = 1) the vertices of the loops of every surface s with
 * surfaces[s] set; returns how many of those surfaces had a vertex not
 * pinned before (0: pinning again changes nothing). */
uint32_t sw_seam_pin_surfaces(const sw_seam_host *graph, const uint8_t *surfaces,
                              uint8_t *pinned);

#endif
