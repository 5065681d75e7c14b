/* SPDX-License-Identifier: MIT */
/* The seams as drawn: after a frame, the border of every drawn mesh (its
 * edges that only one of its triangles uses, in the positions the GL got)
 * against the borders of the other drawn meshes, with no help from the Seam
 * Graph's bookkeeping. Each border point of a mesh is, against the other
 * meshes' borders near it:
 *   shared     a vertex of every other border that passes through it: the
 *              rasteriser's shared-edge rule leaves no pixel uncovered;
 *   T-vertex   on another mesh's border edge (within a tolerance relative
 *              to the model: float rounding) but not its vertex: the two
 *              sides meet in exact arithmetic, not on screen, where such a
 *              joint leaves pinholes along the edge (the rasteriser snaps
 *              the three points to its sub-pixel grid differently);
 *   gap        off every other border by more than the tolerance but
 *              within the reach (the sewing tolerance): a crack;
 *   free       no other border within the reach: the model's free border,
 *              or a neighbour that was not drawn.
 * Called by the seam walk while it measures (sw_seam_walk_draw with stats):
 * begin, one add per drawn mesh, check. Memory: one block sized at init;
 * no allocation after. GL-free. */
#ifndef SW_SEAM_DRAWN_H
#define SW_SEAM_DRAWN_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_math.h"
#include "sw_seam_measure.h"

typedef struct sw_seam_drawn_edge {
    float p[3], q[3];            /* p -> q as its triangle winds */
    uint32_t surface;
} sw_seam_drawn_edge;

typedef struct sw_seam_drawn_cell {
    uint64_t cell;               /* grid cell key */
    uint32_t edge;
} sw_seam_drawn_cell;

typedef struct sw_seam_drawn {
    sw_seam_drawn_edge *edges;   /* this frame's border edges */
    sw_seam_drawn_cell *cells;   /* (cell, edge) for every cell an edge passes */
    uint32_t *edge_keys;         /* one mesh's edges: key + 1, 0 empty */
    uint32_t *edge_uses;         /* the same slots: triangles using it; the first winding */
    uint32_t max_edges, max_cells, edge_table;
    uint32_t edge_count, cell_count;
    int overflow;                /* this frame's borders did not fit: not checked */
    double tolerance, reach;     /* model units */
    sw_vec3 origin;
    double cell_size;
} sw_seam_drawn;

typedef struct sw_seam_drawn_result {
    uint64_t points, shared, t_vertices, gaps, free_points;
    int checked;                 /* 0: the frame's borders overflowed the block */
} sw_seam_drawn_result;

/* Bytes sw_seam_drawn_init takes: borders of up to max_edges edges in all,
 * meshes of up to max_mesh_indices indices. */
size_t sw_seam_drawn_arena_bytes(uint32_t max_edges, uint32_t max_mesh_indices);

/* model_box: the pack's box (the tolerance follows its size and its
 * coordinates' magnitude); reach: the sewing tolerance, model units. */
sw_status sw_seam_drawn_init(sw_seam_drawn *d, const sw_box *model_box, double reach,
                             uint32_t max_edges, uint32_t max_mesh_indices, sw_arena *arena,
                             sw_error *err);

void sw_seam_drawn_begin(sw_seam_drawn *d);

/* Mesh's border edges (used by one triangle) join the frame's. */
void sw_seam_drawn_add_mesh(sw_seam_drawn *d, uint32_t surface, const sw_seam_mesh *mesh);

/* Every border point of the frame classified as above. */
void sw_seam_drawn_check(sw_seam_drawn *d, sw_seam_drawn_result *result);

#endif
