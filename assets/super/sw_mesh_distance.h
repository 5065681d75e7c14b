/* SPDX-License-Identifier: MIT */
/* How far one triangle mesh lies from another: the largest distance from
 * points sampled on mesh A's triangles to the nearest point of mesh B (a
 * one-sided Hausdorff distance, sampled). Used to measure a simplified
 * level against the mesh it was simplified from, both ways, apart from
 * the simplifier's own estimate. Host only: allocates. */
#ifndef SW_MESH_DISTANCE_H
#define SW_MESH_DISTANCE_H

#include <stdint.h>

#include "sw_error.h"

typedef struct sw_mesh_view {
    const float *positions;   /* 3 per vertex */
    const uint32_t *indices;  /* triangles */
    uint32_t vertex_count, index_count;
} sw_mesh_view;

typedef struct sw_mesh_grid sw_mesh_grid;   /* B's triangles, binned in a uniform grid */

/* The grid over b's triangles (b must outlive it), with their corners as
 * doubles (72 bytes a triangle beside the bins); NULL when out of memory or
 * b has no triangle. */
sw_mesh_grid *sw_mesh_grid_make(const sw_mesh_view *b);
void sw_mesh_grid_free(sw_mesh_grid *g);

/* The distance from point p to the nearest point of the grid's mesh. */
double sw_mesh_grid_distance(const sw_mesh_grid *g, const double p[3]);

typedef struct sw_mesh_point {
    uint32_t triangle;        /* the mesh's triangle (its first index / 3) */
    double weights[3];        /* barycentric, of its three corners */
} sw_mesh_point;

/* The same distance, and where on the mesh that nearest point is. */
double sw_mesh_grid_nearest(const sw_mesh_grid *g, const double p[3], sw_mesh_point *at);

/* visit(ctx, at) for the nearest point to p of each triangle of the grid's
 * mesh within r of p (a triangle may be visited more than once), until a
 * visit returns nonzero; returns whether one did. */
int sw_mesh_grid_within(const sw_mesh_grid *g, const double p[3], double r,
                        int (*visit)(void *ctx, const sw_mesh_point *at), void *ctx);

/* The largest distance from a's sample points to g's mesh: each triangle
 * of a sampled on a barycentric grid fine enough that neighbouring samples
 * are at most `spacing` apart (at most SW_MESH_DISTANCE_MAX_SIDE a side),
 * its corners included. The cap was 8: a coarse part level's triangles
 * across a whole plate (1,053 mm) were then sampled 130 mm apart at a
 * bound of 6.5 mm, and a level 28.7 mm off its source was measured at 6.5.
 * A coarse level has few triangles, so sampling it finely costs little. */
#define SW_MESH_DISTANCE_MAX_SIDE 256
double sw_mesh_distance(const sw_mesh_view *a, const sw_mesh_grid *g, double spacing);

#endif
