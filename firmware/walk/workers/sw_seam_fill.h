/* SPDX-License-Identifier: MIT */
/* Fill fans over a surface's seam crossings. The tessellator puts a vertex
 * where a cell of its grid crosses a seam segment (SW_TRIM_CROSSING, on the
 * segment's chord); the neighbour across the seam has no vertex there, so
 * the two sides meet in a T-junction. In exact arithmetic the T-vertex is
 * on the neighbour's edge; on screen the rasteriser snaps the three points
 * to its sub-pixel grid independently and pinholes can open along the
 * edge (single pixels of whatever lies behind). On the shared models the
 * drawn-seam check (sw_seam_drawn.h) finds thousands of such T-vertices a
 * frame; the dark speckle seen at 1920x1080 was mostly depth precision
 * (platform/sw_egl_headless.h, sw_seam_depth.h), not these. The fix
 * needs nothing from the neighbour: for each run a, c1 .. ck, b of
 * crossings between two seam vertices of the mesh's border, the fan
 * (a, ci, ci+1) .. (a, ck, b) closes
 * the mesh's border onto the straight edge a-b, the one the neighbour
 * draws (or closes its own crossings onto), with the same two endpoints:
 * the rasteriser's shared-edge rule then leaves no pixel out. The fans are
 * zero-area in exact arithmetic (every point on the chord a-b), so they add
 * no surface: only the slivers rounding opened. Called by the seam walk
 * after each tessellation; the triangles are appended to the mesh's
 * indices, no vertex is added. Before them, the loop points the
 * tessellator dropped get a vertex and a fan each (sw_seam_fill_drops).
 * Memory: one block sized at init; GL-free. */
#ifndef SW_SEAM_FILL_H
#define SW_SEAM_FILL_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_trim_tess.h"

typedef struct sw_seam_fill {
    uint32_t *keys, *uses;       /* border edges: key + 1 (0 empty), uses and winding */
    uint32_t *next;              /* per vertex: the end of the border edge it starts */
    uint32_t table, max_vertices;
} sw_seam_fill;

size_t sw_seam_fill_arena_bytes(uint32_t max_vertices, uint32_t max_indices);
sw_status sw_seam_fill_init(sw_seam_fill *f, uint32_t max_vertices, uint32_t max_indices,
                            sw_arena *arena, sw_error *err);

/* Appends the fans to indices (*index_count of them now, capacity in all)
 * for the mesh of vertex_count vertices whose ids are the tessellator's
 * (seam vertex, SW_TRIM_CROSSING or SW_TRIM_INTERIOR). Returns the fans'
 * triangles; *crossings_left counts crossings left unfilled (the indices'
 * capacity ran out, or a border that does not run through them once). */
uint32_t sw_seam_fill_crossings(sw_seam_fill *f, const uint32_t *ids, uint32_t vertex_count,
                                uint16_t *indices, uint32_t *index_count, uint32_t capacity,
                                uint32_t *crossings_left);

/* A surface's mesh as the tessellator wrote it, growing: sw_seam_fill_drops
 * appends vertices too. */
typedef struct sw_seam_fill_mesh {
    float *positions, *normals, *uvs;
    uint32_t *ids;
    uint16_t *indices;
    uint32_t vertex_count, index_count, vertex_capacity, index_capacity;
} sw_seam_fill_mesh;

/* Where the tessellator may list the loop points it drops
 * (sw_trim_tess_buffers.dropped), *capacity of them, until the fill runs:
 * memory of the fill's that a tessellation leaves unused. */
uint32_t *sw_seam_fill_drop_list(sw_seam_fill *f, uint32_t *capacity);

/* The loop points the tessellator dropped (sw_trim_tess_buffers.dropped):
 * points within float rounding of the last kept one in (u, v), spike tips,
 * which its clipping cannot order. Sorted in place by sw_seam_fill_drops. */
typedef struct sw_seam_drop_list {
    uint32_t *points;   /* indices into the loops' points */
    uint32_t count;
} sw_seam_drop_list;

/* Fans over the loop points the mesh lacks: those dropped, and those
 * whose seam vertex is in no vertex of it. The neighbour across the seam
 * draws them, and a gap would open between its border and ours (a
 * sphere's loop near its pole: two seam vertices at the same float
 * (u, v), 0.3 mm apart in space). For each run d1 .. dk of such points
 * between kept points a and b, each di becomes a vertex at its seam
 * vertex's position and its (u, v) (with the normal of a) and the fan (a, d1, d2)
 * .. (a, dk, b) joins the border's a-b to the neighbour's a-d1-..-b.
 * Loops none of whose points is kept (left out, drawn as a fan) are left
 * alone. Returns the fans' triangles; *filled counts the points given a
 * vertex, *left those it could not (no room). */
uint32_t sw_seam_fill_drops(sw_seam_fill *f, const sw_trim_loops *loops, sw_seam_drop_list *drops,
                            sw_seam_fill_mesh *m, uint32_t *filled, uint32_t *left);

#endif
