/* SPDX-License-Identifier: MIT */
/* Runtime trimmed tessellation of one surface (Guthe et al. 2002, paper 004,
 * section 6.3, with a conformal grid in place of the paper's binary trees):
 * the surface's rational Bezier patches get one tensor grid whose cells meet
 * a proven object-space error bound, cells outside the current trimming
 * loops are dropped, cells inside are two triangles and cells the loops
 * cross are clipped by them in parameter space and triangulated. Called by
 * the runtime's tessellation workers with the loops the Seam Graph shows at
 * the moment (core/sw_seam_graph.h) and by the tests and the benchmark.
 * Never allocates: scratch comes from an sw_arena (given back before
 * returning), output goes into the caller's buffers.
 *
 * The grid: columns are the patches' knot intervals in u, rows in v, each
 * split into 2 sub-patch intervals (4 on rational surfaces), each of those
 * into a uniform count. Per sub-patch (exact de Casteljau sub-patch) the
 * bounds M_uu, M_uv, M_vv (sw_bezier_second_deriv_bounds) give the fewest
 * cells with (M_uu h_u^2 + 2 M_uv h_u h_v + M_vv h_v^2) / 8 <= error; a
 * column takes the largest count any sub-patch in it needs, a row likewise.
 * A knot interval whose sub-intervals all need one cell stays whole where
 * the whole patch's bound allows (a plane is two triangles). Only
 * sub-patches meeting the loops' box are bounded. The rows inside the box
 * are swept bottom to top with the vertex ids of two grid lines only; a cell
 * no loop touches is inside or outside by the even-odd count of the loops'
 * crossings of its row's middle line.
 *
 * Guarantees, for valid input:
 * - Watertight in parameter space: the triangles tile the trimmed region
 *   (loops even-odd, any orientation) with no T-vertex: the grid is
 *   conformal; where a crossed cell is clipped in parts, its neighbours
 *   carry the parts' corners on the shared side.
 * - The border is the seam: every loop point is an output vertex whose
 *   position is the given float[3], copied bit for bit, so two surfaces sharing
 *   a seam have bit-identical border vertices. Where a loop segment crosses a
 *   cell border the new vertex takes the position (and normal) of the nearer
 *   end of the segment (the paper's nearest-neighbour rule) instead of an
 *   interpolated one, so no position exists on the border that the neighbouring
 *   surface lacks; the vertex keeps its own (u, v). A crossing whose float
 *   (u, v) equals an end's is that loop point (the edge between collapses).
 * - Interior vertices (grid points) are evaluated on the exact surface, once
 *   each; every normal is the surface normal at the vertex's (u, v).
 * - Every triangle's vertices lie in one cell (or part of a crossed cell),
 *   and every cell meets (M_uu h_u^2 + 2 M_uv h_u h_v + M_vv h_v^2) / 8 <=
 *   error, a crossed one border_error, with M the bounds of the sub-patch
 *   holding the cell (of the whole patch for an interval left whole): the
 *   distance from any point of a triangle to the surface at the same (u, v)
 *   is then at most error (Taylor with integral remainder; the barycentric
 *   variance is at most h^2 / 4; a rigorous bound, where the paper tests
 *   the distance at sampled points only). Exception, along the border: loop
 *   points have the caller's positions (the seam's own error), and a
 *   triangle at a crossing is inscribed at the (u, v) of the loop point whose
 *   position it took, so its cell's box grows by up to half a seam segment
 *   there (see crossing_on_segment).
 * - Holes inside one cell get a grid line through them; cells with more
 *   than 32 loop points are clipped in up to 8 x 8 parts, past 2048 points
 *   grid lines are added: ear clipping stays on small rings.
 *
 * Limits: at most 65536 - base_vertex vertices (16-bit indices, GLES2): a
 * surface that needs more at the asked error gets SW_ERR_RANGE and the caller
 * coarsens. Scratch is sized by sw_trim_tess_scratch_bytes (a worst case:
 * about 21 MB for 16 bicubic patches and 16384 loop points at the full
 * 16-bit range, less with options.max_vertices). Work is O(patches + grid
 * cells in the loops' box + loop points x grid lines they cross), with no
 * search or allocation per triangle. On the benchmark's shapes
 * (tests/bench/trim_tess_bench.c, runtime options, loaded 2-core machine,
 * medians of 3 runs of 7): at 1e-4 of the size 18074 triangles in 1.1 ms
 * on the untrimmed bicubic bump (16 million a second, 0.13 of GLU's time
 * at equal measured error), 9494 in 1.1 ms on the bump with holes (8 M/s,
 * 0.07 of GLU's time), 446 in 0.14 ms on the rational
 * quarter cylinder (3 M/s; 7.6 times GLU's time: every cell is crossed);
 * at 1e-3 2146, 1434 and 166 triangles (9, 4.5 and 2.7 M/s). The cylinder
 * has a cell the full height (its mixed and axial bounds are 0:
 * sw_bezier_extrusion_mixed_bound), so what bounds it is the work per loop
 * point (clipping and ear clipping the crossed cells, a normal per loop
 * point, bucketing); elsewhere also the exact evaluation per grid
 * point; at 1e-3 the fixed cost per patch (sub-patch bounds) too. */
#ifndef SW_TRIM_TESS_H
#define SW_TRIM_TESS_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_bezier.h"
#include "sw_error.h"
#include "sw_pack.h"

/* One Bezier patch of the surface and the part of the surface's (u, v)
 * domain it covers: the patch's own [0,1]^2 maps linearly onto
 * [domain[0], domain[1]] x [domain[2], domain[3]]. The patches of a surface
 * tile its domain on a grid of knot intervals (sw_pack_patch_domain): shared
 * edges have equal coordinates. */
typedef struct sw_trim_patch {
    sw_bezier_patchf patch;
    float domain[4];            /* u0, u1, v0, v1, u0 < u1, v0 < v1 */
} sw_trim_patch;

/* The patches of a validated pack's surface `surface` as sw_trim_tess takes
 * them: views into the pack (control points are not copied), domains from
 * PATCH_DOMAINS. *count is the surface's patch count; SW_ERR_NO_MEMORY when
 * capacity is smaller (nothing written beyond it), SW_ERR_RANGE for a surface
 * out of range or a pack without the trimmed-surface sections. */
sw_status sw_trim_patches_from_pack(const sw_pack *pack, uint32_t surface, sw_trim_patch *out,
                                    uint32_t capacity, uint32_t *count, sw_error *err);

/* A reader's room for one surface's patches: the patches, and the
 * control points placed as they are read (4 floats each, for a pack whose
 * points are in their parts' frames: control_local; NULL otherwise). */
typedef struct sw_trim_patch_room {
    sw_trim_patch *patches;
    uint32_t capacity;           /* patches */
    float *control;
    uint32_t control_capacity;   /* points, the surface's patches' together */
} sw_trim_patch_room;

/* The same for a pack whose control points may be placed as they are read
 * (the runtime's placed scene: sw_pack_patch_control), into room->control,
 * which the patches then view; SW_ERR_NO_MEMORY when either part of room
 * is short. sw_trim_patches_from_pack is this with no control room, for a
 * pack whose points are its own. */
sw_status sw_trim_patches_placed(const sw_pack *pack, uint32_t surface,
                                 const sw_trim_patch_room *room, uint32_t *count, sw_error *err);

/* One point of a trimming polyline: its parameters in this surface, the
 * position to draw there (the Seam Graph vertex's) and the caller's id for it
 * (the Seam Graph vertex index), reported back per output vertex. */
typedef struct sw_trim_point {
    float uv[2];
    float p[3];
    uint32_t id;
} sw_trim_point;

/* The surface's current loops: loop k is points[loop_first[k] ..
 * loop_first[k + 1]), closed (the last point joins the first, not repeated),
 * either orientation; nested loops alternate inside and outside (even-odd).
 * Loops must not cross each other or themselves. Consecutive points with equal
 * (u, v) count once (the first is kept), and the tip of a spike (the loop
 * turning back within 1e-6 rad, as where a tiny trim curve overshoots a corner)
 * is dropped, as is a point within 1e-6 of the domain's size of the previous
 * one (float zig-zags of tiny trim curves; result->dropped_points). A loop
 * with fewer than three distinct points or no area encloses nothing and is
 * skipped; one with no area in (u, v) whose positions span area in space (a
 * face smaller than a coarse bound, its corners collinear in (u, v)) is
 * drawn as a fan over its positions instead (result->fanned_loops), so the
 * borders across its seams still meet (core/sw_trim_fan.c). */
typedef struct sw_trim_loops {
    const sw_trim_point *points;
    const uint32_t *loop_first;  /* loop_count + 1 entries, non-decreasing */
    uint32_t loop_count;
} sw_trim_loops;

/* Zero means default, as everywhere in seamwalk. */
typedef struct sw_trim_tess_options {
    uint32_t max_vertices; /* default and cap: 65536 - base_vertex (16-bit indices) */
    uint32_t max_depth;    /* grid intervals per sub-patch interval at most 2^max_depth,
                              default 24, at most 40 */
    /* 0 (default): a crossing takes the nearer loop point's position (the
     * paper's rule: no T-vertex, but the triangles at a crossing are
     * distorted by up to half a seam segment, which with the Seam Graph's
     * coarse seams far exceeded the bound: 10 px on the teaset).
     * 1: a crossing is placed on its seam segment, the straight 3D chord
     * between the two loop points, where the chord comes nearest the surface
     * at the crossing's (u, v), and gets id SW_TRIM_CROSSING. The neighbour
     * across the seam draws that same chord, so the border stays closed (a
     * T-vertex on a straight edge, not a gap), and the triangles follow the
     * surface. */
    int crossing_on_segment;
    /* Error for cells a loop runs through, as a fraction of error (0: 1).
     * Their triangles take border points from the loops, which are off the
     * surface by the loops' own error: with loops within (1 - f) * error,
     * f * error here keeps the border triangles within error too. */
    double border_fraction;
} sw_trim_tess_options;

/* Caller-owned output. positions and normals hold 3 floats per vertex; uvs
 * (optional, NULL to skip) 2 floats, the vertex's surface parameters; ids
 * (optional) the loop point's id for border vertices (a crossing: the id of
 * the loop point whose position it took) and SW_TRIM_INTERIOR for interior
 * ones. Indices are base_vertex + vertex number, three per triangle, counter-
 * clockwise in (u, v) (so facing along F_u x F_v). */
#define SW_TRIM_INTERIOR 0xFFFFFFFFu
#define SW_TRIM_CROSSING 0xFFFFFFFEu /* with crossing_on_segment */
typedef struct sw_trim_tess_buffers {
    float *positions, *normals, *uvs;
    uint32_t *ids;
    uint16_t *indices;
    uint32_t vertex_capacity, index_capacity;
    uint32_t base_vertex;
    /* Optional (NULL: not listed): the caller's loop points (indices into
     * loops->points) counted in result->dropped_points, the first
     * dropped_capacity of them. */
    uint32_t *dropped;
    uint32_t dropped_capacity;
} sw_trim_tess_buffers;

typedef struct sw_trim_tess_result {
    uint32_t vertex_count, index_count;  /* what the surface needs (also on NO_MEMORY) */
    uint32_t leaf_count;                 /* grid cells kept (inside or crossed) */
    uint32_t crossed_count;              /* of those, cells a loop crosses */
    uint32_t capped_count;               /* sub-patches whose count max_depth or the vertex
                                            limit capped (their bound exceeds error) */
    uint32_t skipped_loops;              /* loops with no area, or holes left inside a cell */
    uint32_t fanned_loops;               /* of them, loops with no area in (u, v) but some in
                                            space, drawn as fans of their points */
    uint32_t dropped_points;             /* loop points dropped (spike tips, near repeats)
                                            whose id no kept neighbour carries: not in
                                            the output */
    uint32_t dropped_flat;               /* of them, those whose triangle with their kept
                                            neighbours is flat in space (to float
                                            rounding): no gap, the borders across meet */
    uint32_t fallback_ears;              /* clipping steps taken without a valid ear: 0 for
                                            valid loops */
    double error_bound;                  /* the largest cell bound: <= error unless capped */
} sw_trim_tess_result;

/* How far sw_trim_tess moves each loop point into the trimmed region for
 * these patches (the region shrink: up to four times this at a sharp
 * corner). Loops that touch, or come closer than a few times this, may
 * cross once moved: sw_seam_surface_untangle parts them. */
double sw_trim_tess_shrink(const sw_trim_patch *patches, uint32_t patch_count);

/* Scratch bytes sw_trim_tess may take from its arena, worst case, for a
 * surface of patch_count patches, loops of point_count points in all, at
 * most max_degree in u and v, with options opt (NULL: defaults). */
size_t sw_trim_tess_scratch_bytes(uint32_t patch_count, uint32_t point_count, int max_degree,
                                  const sw_trim_tess_options *opt);

/* Tessellates the surface so that it deviates at most error_world (model
 * units) from the exact surface, inside the loops.
 * - SW_OK: out holds result->vertex_count vertices and result->index_count
 *   indices. No loop, or loops enclosing nothing inside the patches: SW_OK with
 *   no triangles (an untrimmed surface passes its domain rectangle as a loop).
 * - SW_ERR_NO_MEMORY: a buffer is too small (result has the counts needed,
 *   nothing beyond the capacities was written: call again with larger buffers),
 *   or the arena is (see sw_trim_tess_scratch_bytes).
 * - SW_ERR_RANGE: the surface needs more than max_vertices vertices (or
 *   cells) at this bound: the caller coarsens (a larger error_world) and
 *   calls again. Also a loop point outside the patches' domain by more than
 *   1% of its size (closer ones are clamped onto it: real trims overshoot a
 *   little), or a patch with a non-finite point or weight <= 0.
 * - SW_ERR_ARG: error_world not finite and > 0, NULL pointers, a bad degree or
 *   domain, loop_first not non-decreasing from 0.
 * - SW_ERR_FORMAT: loops that cross each other or themselves where the
 *   clipping notices it.
 * The arena is back at its mark on return. Positions are bit-identical for
 * identical input (no threads, no randomness). */
sw_status sw_trim_tess(const sw_trim_patch *patches, uint32_t patch_count,
                       const sw_trim_loops *loops, double error_world,
                       const sw_trim_tess_options *opt, sw_arena *scratch,
                       const sw_trim_tess_buffers *out, sw_trim_tess_result *result,
                       sw_error *err);

/* The sizes only: sw_trim_tess with no buffers, SW_OK (not NO_MEMORY) when
 * the rest succeeds. The work is the same as a full call, so a caller with
 * buffers of a known capacity calls sw_trim_tess directly and retries on
 * SW_ERR_NO_MEMORY. */
sw_status sw_trim_tess_sizes(const sw_trim_patch *patches, uint32_t patch_count,
                             const sw_trim_loops *loops, double error_world,
                             const sw_trim_tess_options *opt, sw_arena *scratch,
                             sw_trim_tess_result *result, sw_error *err);

#endif
