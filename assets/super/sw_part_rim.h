/* SPDX-License-Identifier: MIT */
/* The corners of a piece's open rim held in place for the simplifier. A
 * sheet's rim (a rail's feet and ends, a plate's edge) is a border
 * meshoptimizer keeps as a border, but it moves border vertices along it,
 * and a vertex at a corner of the rim moved along one side cuts the corner
 * off, far past the error it estimates. meshoptimizer 0.18 has no
 * per-vertex lock (0.21 added one), but it moves a vertex on an attribute
 * seam (two vertices at one position) only onto another seam vertex; each corner is given a copy at
 * its very position, used by one of its triangles, which makes it such a
 * seam with nowhere along it to go. The copies are mapped back after
 * simplifying, so nothing downstream sees them. Host only: allocates. */
#ifndef SW_PART_RIM_H
#define SW_PART_RIM_H

#include <stddef.h>
#include <stdint.h>

/* Welded triangles: wpos[3 * wcount], idx[icount]. */
typedef struct sw_part_tris {
    const float *wpos;
    const uint32_t *idx;
    uint32_t wcount, icount;
} sw_part_tris;

typedef struct sw_part_rim {
    float *pos;              /* the welded positions, then the corners' copies */
    uint32_t *idx;           /* the welded triangles, corners split off */
    uint32_t *copy_of;       /* copy k (vertex wcount + k) -> its corner */
    uint32_t vertex_count, copies;
    size_t cap_p, cap_i, cap_c;
} sw_part_rim;

/* r made from welded triangles m (oriented: an edge two triangles share
 * is run once each way), each rim vertex whose rim turns by more than the
 * angle whose cosine is cos_turn split as above. 0 when out of memory. */
int sw_part_rim_hold_corners(sw_part_rim *r, const sw_part_tris *m, double cos_turn);

/* The simplified triangles dest[0 .. n) back on the welded vertices
 * (the first wcount). */
void sw_part_rim_unmap(const sw_part_rim *r, uint32_t wcount, uint32_t *dest, size_t n);

void sw_part_rim_free(sw_part_rim *r);

#endif
