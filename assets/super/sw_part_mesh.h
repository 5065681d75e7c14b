/* SPDX-License-Identifier: MIT */
/* A piece's source mesh as the part levels' builder works on it
 * (sw_part_levels_build.h): gathered from the source, welded and turned
 * one way (sw_part_mesh.c); a simplified level of it written out with a
 * normal chosen per corner, and its area shaded wrong measured
 * (sw_part_level_normals.c). Internal to assets/super/. Host only:
 * allocates. */
#ifndef SW_PART_MESH_H
#define SW_PART_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "sw_levels.h"
#include "sw_mesh_distance.h"
#include "sw_part_levels.h"
#include "sw_part_rim.h"
#include "sw_part_source.h"

/* One piece's source, welded (reused from piece to piece). */
typedef struct sw_part_mesh {
    float *pos, *nrm;             /* the part's source vertices */
    uint32_t *weld;               /* source vertex -> welded vertex */
    float *wpos;                  /* welded positions */
    uint32_t *idx;                /* welded triangles, none of no area */
    uint32_t *corner;             /* the source vertex of each of idx's corners */
    uint32_t *wedge_first, *wedge;/* welded vertex -> its source vertices */
    uint32_t *dest;               /* simplified triangles */
    uint32_t *aside;              /* a simplification kept while another is made */
    sw_part_rim rim;              /* the simplifier's input, rim corners held */
    uint64_t *keys;               /* output vertex hash: (welded << 32 | source) + 1 */
    uint32_t *key_value;
    size_t cap_v, cap_i, cap_c, cap_w, cap_d, cap_k, cap_kv, cap_n, cap_p, cap_wf, cap_wd, cap_x, cap_a;
    uint32_t count, wcount, icount;
    double error;                 /* the source's measured error */
} sw_part_mesh;

/* The levels made so far, and their vertices and indices. */
typedef struct sw_part_level_arrays {
    sw_part_level *levels;
    sw_level_vertex *vertices;
    uint16_t *indices;
    size_t cap_l, cap_v, cap_i;
    uint32_t level_count, vertex_count, index_count;
} sw_part_level_arrays;

/* pieces[0 .. count) appended to o in that order, each level's first
 * vertex and first index moved past what comes before it; each piece's
 * arrays are freed once copied. 0 when out of memory (what is left in o
 * and pieces is still to be freed). */
int sw_part_level_arrays_join(sw_part_level_arrays *o, sw_part_level_arrays *pieces,
                              uint32_t count);

void sw_part_level_arrays_free(sw_part_level_arrays *a);

static inline uint64_t sw_part_hash64(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
}

/* Triangle abc's normal, not unit (its length twice the area). */
static inline void sw_part_face_normal(const float *a, const float *b, const float *c, double n[3])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        e1[k] = (double)b[k] - a[k], e2[k] = (double)c[k] - a[k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* Every surface of the range, for sw_part_mesh_gather. */
#define SW_PART_MESH_ALL UINT32_MAX

/* Piece g's source vertices and triangles gathered from its part's
 * surfaces [first, end) (all of them for g SW_PART_MESH_ALL); 0 when out
 * of memory, -1 when a surface of it has no level. */
int sw_part_mesh_gather(sw_part_mesh *m, const sw_levels *levels, const uint32_t *piece_of,
                        const sw_part_source *src, uint32_t g, uint32_t first, uint32_t end);

/* Vertices at the very same position become one; triangles that then
 * repeat a vertex are dropped. Each welded vertex keeps the list of the
 * source vertices it stands for. 0 when out of memory. */
int sw_part_mesh_weld(sw_part_mesh *m);

/* The triangles turned so that each edge two of them share is run once each
 * way, piece by piece, each piece to the side its surfaces face. The
 * surfaces' normals alone do not decide each triangle: a part's surfaces
 * may face opposite ways (the renderer lights both sides), and
 * meshoptimizer takes an edge not run both ways for a border it must keep.
 * 0 when out of memory. */
int sw_part_mesh_orient(sw_part_mesh *m);

/* The diagonal of the welded vertices' box. */
double sw_part_mesh_size(const sw_part_mesh *m);

void sw_part_mesh_free(sw_part_mesh *m);

/* The simplified triangles m->dest[0 .. n) as a level's vertices and
 * indices appended to o (*first_vertex: where its vertices start); 0 when
 * out of memory, -1 when over one draw. */
int sw_part_level_emit(sw_part_mesh *m, const sw_mesh_grid *source_grid, sw_part_level_arrays *o,
                       uint32_t n, uint32_t *first_vertex);

/* Level l's shading side (sw_part_level): the side of a square of the area
 * of its triangles whose shading normal lies more than 30 degrees off the
 * source's at every source point within the level's error (either side: the
 * renderer lights both), sampled at the 25 points of a barycentric grid of
 * sixths on each triangle but its corners. The level may lie anywhere
 * within its error of the source, so its shading may too: a point near a
 * crease matches either face. A level simplified across a crease blends the
 * two faces' normals over the triangles that span it, and a triangle whose
 * corners the simplifier took from other faces is shaded as those; one
 * across a fillet follows the fillet's normals. */
double sw_part_level_shaded_side(const sw_part_mesh *m, const sw_mesh_grid *source_grid,
                                 const sw_part_level_arrays *o, const sw_part_level *l);

#endif
