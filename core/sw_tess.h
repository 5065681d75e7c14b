/* SPDX-License-Identifier: MIT */
/* Uniform tessellation of a Bezier patch into caller-provided buffers, and the
 * grid size that meets an object-space error bound (paper 000, section 4.1:
 * deviation of a grid triangle with legs l1, l2 is at most
 * (l1^2 M_uu + 2 l1 l2 M_uv + l2^2 M_vv) / 8). Used by the runtime's frame loop
 * and by the benchmark. Never allocates. */
#ifndef SW_TESS_H
#define SW_TESS_H

#include <stdint.h>

#include "sw_bezier.h"

/* 16-bit indices: a grid of at most 255 x 255 segments has 65536 vertices. */
#define SW_TESS_MAX_SEGMENTS 255u

/* 16 bytes: float position, normal as signed normalised bytes (w unused, 0). */
typedef struct sw_vertex {
    float pos[3];
    int8_t normal[4];
} sw_vertex;

typedef struct sw_tess_sizes {
    uint32_t vertex_count;  /* (nu + 1) * (nv + 1) */
    uint32_t index_count;   /* 6 * nu * nv: two triangles per grid cell */
} sw_tess_sizes;

/* Exact buffer sizes for an nu x nv grid (1 <= nu, nv <= SW_TESS_MAX_SEGMENTS). */
sw_tess_sizes sw_tess_grid_sizes(uint32_t nu, uint32_t nv);

/* Tessellates the patch on the uniform (nu + 1) x (nv + 1) parameter grid.
 * Vertex (a, b) at (u, v) = (a / nu, b / nv) is written to verts[b * (nu + 1) + a];
 * indices refer to it as base_vertex + b * (nu + 1) + a, so several patches can
 * share one 16-bit vertex buffer: base_vertex + vertex_count must be <= 65536.
 * Cell (a, b) becomes triangles (v00, v10, v11) and (v00, v11, v01), in index
 * order. Bicubic patches take an unrolled fast path; all paths give positions
 * from the same Bernstein sums, so a shared edge evaluated by two patches with
 * the same boundary control points and the same segment count is bit-identical. */
void sw_tess_grid(const sw_bezier_patchf *patch, uint32_t nu, uint32_t nv, uint32_t base_vertex,
                  sw_vertex *verts, uint16_t *indices);

/* Smallest grid (by triangle count) whose derivative bound is <= error_world.
 * Returns 1 when that grid fits in SW_TESS_MAX_SEGMENTS, 0 when it was capped
 * (the bound is then not met and the caller should count it). */
int sw_tess_segments_for_error(const sw_deriv_bounds *bounds, double error_world, uint32_t *nu,
                               uint32_t *nv);

/* The bound itself: the largest deviation a grid of nu x nv can have. */
double sw_tess_grid_error_bound(const sw_deriv_bounds *bounds, uint32_t nu, uint32_t nv);

#endif
