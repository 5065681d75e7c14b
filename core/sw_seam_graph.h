/* SPDX-License-Identifier: MIT */
/* The Seam Graph (Guthe et al. 2002, sections 4-5, paper 004 in
 * ../shared/papers): the sewn trimming polylines of a model's surfaces, as
 * flat arrays with indices, and the edge-collapse hierarchy over them.
 *
 * Built on the host (assets/seam/: trims to polylines, sewing, the
 * collapses) and stored in the pack; the runtime selects a view-dependent cut
 * of the hierarchy each frame (core/sw_seam_select.c) and tessellates every
 * surface inside its currently active loops (core/sw_trim_tess.c). Host and
 * runtime share these structs; the pack stores the same records.
 *
 * Terms (the paper's in brackets):
 * - surface [Patch]: a trimmed NURBS surface of the model, the pack's
 *   sw_pack_surface (an untrimmed Bezier input is one surface per patch,
 *   bounded by its domain's four sides).
 * - loop [Boundary]: one closed boundary of a surface in its parameter
 *   space: the outer trim or a hole, or the domain rectangle of an untrimmed
 *   surface. It is a cyclic list of slots (the last joins the first).
 * - slot [an entry of a BoundaryPart's vertex list]: one place in a loop,
 *   holding the original vertex sewn there and that vertex's (u, v) in the
 *   loop's surface. Slots never change; what a slot shows at a level of
 *   detail is the active ancestor of its vertex (below).
 * - vertex [BoundaryVertex]: a sewing point in model space. Where surfaces
 *   were sewn, one vertex sits in slots of several loops (of two surfaces
 *   along an ordinary seam, of more along a non-manifold one, of one surface
 *   along a free edge). The first original_count vertices are the sewn
 *   polylines' vertices; each collapse adds one vertex after them.
 * - edge [BoundaryEdge]: two vertices consecutive in some loop, listed once
 *   however many loops run along it.
 *
 * Level of detail (sections 5.2-5.5). Collapse k, (v1, v2 -> vn) with
 * vn = original_count + k, merges the edge v1-v2 into a copy of v2: vn has
 * v2's position, and both v1 and v2 get vn as their child. The hierarchy is a
 * forest; its roots are the vertices left when simplification stopped (one
 * per connected part). The numbering is El-Sana and Varshney's: a vertex's
 * index is its number, so "created later" is "larger index".
 *
 * The runtime keeps a front of active vertices (every original vertex has
 * exactly one active ancestor, itself included). A slot shows its vertex's
 * active ancestor; walking a loop's slots and dropping consecutive repeats
 * (the first and last too) gives the loop's current polyline. A slot's (u, v)
 * is used for the vertex it shows unless another slot of the run holds that
 * vertex itself; so vn keeps v2's parameters where v2 was sewn and takes
 * v1's elsewhere (within the collapse error in model space). A loop whose
 * polyline is down to fewer than three distinct vertices has vanished, and
 * a surface whose outer loop vanished is not drawn: whole patches vanish far
 * away, as the paper wants.
 *
 * Positions are floats: they are what the runtime draws, and both surfaces
 * along a seam take their border vertices from here, so the two sides are
 * bit-identical. */
#ifndef SW_SEAM_GRAPH_H
#define SW_SEAM_GRAPH_H

#include <stdint.h>

#define SW_SEAM_NONE 0xFFFFFFFFu /* no vertex / no child (a macro: fits no int enum) */

typedef struct sw_seam_vertex {  /* 32 bytes */
    float p[3];                  /* model space, the pack's units */
    uint32_t child;              /* the vertex it collapses into, SW_SEAM_NONE for a root */
    float error;                 /* model-space error of the polylines once this vertex
                                    exists: 0 for original vertices; for a created one, the
                                    max of its collapse's error and its parents' (monotone
                                    along every path to a root) */
    uint32_t first_slot_ref;     /* original vertices: the slots they sit in are */
    uint32_t slot_ref_count;     /* slot_refs[first_slot_ref .. + slot_ref_count); 0 for
                                    created vertices */
    uint32_t reserved;           /* zero */
} sw_seam_vertex;

typedef struct sw_seam_slot {    /* 12 bytes */
    uint32_t vertex;             /* the original vertex (< original_count) sewn here */
    float uv[2];                 /* its parameters in the loop's surface */
} sw_seam_slot;

enum { SW_SEAM_LOOP_OUTER = 1u };
typedef struct sw_seam_loop {    /* 16 bytes */
    uint32_t surface;            /* index into the pack's SURFACES */
    uint32_t first_slot;         /* slots[first_slot .. first_slot + slot_count) */
    uint32_t slot_count;         /* >= 3 */
    uint32_t flags;              /* SW_SEAM_LOOP_* */
} sw_seam_loop;

typedef struct sw_seam_edge {    /* 8 bytes: original vertices, a < b */
    uint32_t a, b;
} sw_seam_edge;

typedef struct sw_seam_collapse {/* 12 bytes: collapse k makes vertex original_count + k */
    uint32_t v1;                 /* removed */
    uint32_t v2;                 /* kept: the new vertex copies its position */
    float error;                 /* this step's error (the paper's epsilon + d) */
} sw_seam_collapse;

/* The whole graph as views (host: owned by whoever built it; runtime: into
 * the pack). vertex_count == original_count + collapse_count. */
typedef struct sw_seam_graph {
    const sw_seam_vertex *vertices;
    const sw_seam_slot *slots;
    const sw_seam_loop *loops;       /* grouped by surface, in surface order */
    const sw_seam_edge *edges;
    const sw_seam_collapse *collapses;
    const uint32_t *slot_refs;       /* slot indices, grouped by original vertex */
    const uint32_t *surface_loops;   /* surface_count + 1: surface s has the loops
                                        [surface_loops[s], surface_loops[s + 1]) */
    uint32_t vertex_count, original_count;
    uint32_t slot_count, loop_count, edge_count, collapse_count, slot_ref_count;
    uint32_t surface_count;          /* the pack's surfaces, every one listed */
    float tolerance;                 /* the sewing tolerance it was built with */
} sw_seam_graph;

#endif
