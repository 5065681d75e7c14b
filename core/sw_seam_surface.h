/* SPDX-License-Identifier: MIT */
/* A surface's current Seam Graph loops as the trimmed tessellator takes them
 * (sw_trim_tess.h), and the share of its error bound its seams get: what the
 * runtime's seam walk (firmware/walk/sw_seam_walk.c) and the host's verify
 * (assets/pack/sw_pack_verify_tess.c) share, so that what verify proves is
 * what the runtime draws. No allocation. */
#ifndef SW_SEAM_SURFACE_H
#define SW_SEAM_SURFACE_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_seam_select.h"
#include "sw_trim_tess.h"

/* The share of a surface's bound its seams get; the cells the seams run
 * through get the rest. A border triangle is off the surface by the seam's
 * error plus its cell's, so the two shares add up to the bound (with the
 * whole bound each, the hammer's border triangles reached 1.14 of it);
 * interior cells still get the whole bound. Why 0.35: triangles summed over
 * an orbit of every shared model were 106k at 0.2, 112k at 0.35, 126k at
 * 0.5 and 151k at 0.65 (seams are cheap, border cells are not), and a
 * smaller share keeps surfaces from vanishing until they are farther. */
#define SW_SEAM_SHARE 0.35

/* The tessellator's options for a surface drawn from its seams: crossings on
 * their seam segment (the paper's snapping distorted the border triangles
 * far beyond the bound, sw_trim_tess.h), border cells at the bound's share
 * the seams leave. */
sw_trim_tess_options sw_seam_surface_tess_options(void);

/* The caller's buffers: capacity points each (at least the surface's slots
 * in all its loops), loop_first one more than the surface's loops. */
typedef struct sw_seam_surface_buffers {
    sw_seam_point *seam_points;   /* scratch */
    sw_trim_point *points;        /* out: uv from the slots, p from the graph's vertices,
                                     id the vertex */
    uint32_t *loop_first;         /* out */
    uint32_t capacity;
} sw_seam_surface_buffers;

/* Surface `surface`'s loops at the state's front (sw_seam_select_loop with
 * pin), outer loops first, then holes; a hole that vanished is left out.
 * Returns 0 when the outer loops vanished (the surface is not drawn), else
 * 1 with *loops viewing buf and *outer the number of outer loops in it. */
int sw_seam_surface_loops(const sw_seam_select *state, uint32_t surface, float pin,
                          const sw_seam_surface_buffers *buf, sw_trim_loops *loops,
                          uint32_t *outer);

/* Cuts thin excursions out of loops the tessellator refused for crossing:
 * where a loop comes back to a vertex it showed before, and the way out and
 * back encloses next to nothing in (u, v) (the closing chord under
 * SW_SEAM_THIN of the excursion's reach from the vertex, its area under
 * SW_SEAM_THIN of the reach squared), the points after the vertex up to its
 * return are dropped. Such an excursion is a slit: both sides are the same
 * seam vertices (sewn across a slot narrower than the sewing tolerance),
 * and their two (u, v) polylines, a few micrometres apart, cross. A
 * periodic seam also brings a loop back to its vertices, but a period away
 * in (u, v): never thin. Then, where two of a loop's segments cross and
 * the lobe between them encloses under SW_SEAM_THIN of the loop's area (a
 * needle whose two sides cross short of its tip), the lobe's points go
 * (loops of up to 2048 points, four lobes each). Last, a point of one
 * loop on or within a few shrinks of an earlier loop (a hole tangent to
 * the outline, or sharing a vertex with it; shrink: sw_trim_tess_shrink of
 * the surface's patches) is moved off it, into its region, by a float step:
 * the tessellator's region shrink would move the two across each other.
 * loops views points and loop_first, which are compacted in place;
 * loop_count may drop (a loop left with fewer than three points goes;
 * *outer, the outer loops first in loops, follows). scratch lends at most
 * 21 bytes a point and is given back. Work is bounded: at most 64 points
 * read per point of a loop (excursions past that are left), 2^26 box tests
 * for the touching points. Returns the points dropped or moved (0 also
 * when scratch is too small). */
#define SW_SEAM_THIN 0.05
uint32_t sw_seam_surface_untangle(sw_trim_loops *loops, sw_trim_point *points,
                                  uint32_t *loop_first, uint32_t *outer, double shrink,
                                  sw_arena *scratch);

#endif
