/* SPDX-License-Identifier: MIT */
/* The culling hierarchy: a bounding-volume tree over a pack's surfaces whose
 * leaves are, again, trees over each surface's patches (paper 000, section
 * 6; paper 004, section 6.2), and the per-patch loop it replaces.
 *
 * Built once at load time into the runtime's arena (sw_cull_tree_build,
 * bytes counted in the pack's runtime_bytes through core/sw_walk_memory.c),
 * queried by the seam walk every frame (firmware/walk/sw_seam_walk.c). A query
 * gives, per surface, exactly what testing each of its patch boxes against
 * the frustum gives (sw_cull_brute): the nearest depth of a patch box in view
 * (clamped to the near plane; +inf when none is in view) and the farthest
 * corner depth of those boxes (-inf when none). "Exactly" is bit for bit:
 * a node's box is the min/max of its children's, so in floating point too
 * a node outside a plane has every box below it outside, a node inside has
 * every box below it inside, and its depth range contains theirs
 * (sw_box_depth_range rounds monotonically); the tree skips only what
 * cannot change an answer. Fully inside, a subtree is accepted without
 * another plane test; fully outside, it is rejected whole; within a
 * surface, subtrees are visited nearest first and skipped once they can
 * neither bring the nearest depth closer nor the farthest farther.
 *
 * What it saves is box tests, not depth ranges: the exact nearest depth of
 * a surface in view needs the depth range of every patch of it in view, so
 * with the whole model in view (the 40,000-patch showroom's orbit) a query
 * makes 1 box test instead of 40,000 but takes about the loop's time
 * (tests/bench/cull_bench.sh: 1.79 ms against 1.74); from inside the hall
 * (908 tests a frame) it takes 0.70 ms against 1.15.
 *
 * Memory: the caller's arena (sw_cull_tree_arena_bytes); the query takes
 * the caller's output arrays and allocates nothing. Not thread-safe to
 * build; a built tree is read-only, so queries may run on any thread. */
#ifndef SW_CULL_TREE_H
#define SW_CULL_TREE_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_math.h"
#include "sw_pack.h"

#define SW_CULL_LEAF 0x80000000u /* in a node's b: a leaf, of (b & ~SW_CULL_LEAF) items */

/* Patches a leaf holds at most: below that, a subtree's boxes cost more to
 * walk than its patches' boxes cost to test (most surfaces have a few). */
#define SW_CULL_LEAF_PATCHES 4u

/* A surface wholly in view with at most this many patches has their depth
 * ranges taken one by one; with more, its tree's nearest-first walk skips
 * what cannot change the answers. */
#define SW_CULL_SCAN_PATCHES 16u

typedef struct sw_cull_node {    /* 32 bytes */
    float min[3], max[3];        /* the union of its items' boxes, exactly */
    uint32_t a, b;               /* inner: children a and b; leaf (b & SW_CULL_LEAF): in top,
                                    surface a; in patch_nodes, its patches are
                                    patch_order[a .. a + count) */
} sw_cull_node;

typedef struct sw_cull_tree {
    const sw_pack_patch *patches;  /* the pack's, read for nothing but their boxes */
    const sw_pack_surface *surfaces; /* the pack's: their patch ranges */
    sw_cull_node *top;             /* over the surfaces with patches; root top[0] */
    uint32_t top_count;            /* 2 * surfaces with patches - 1, or 0 */
    sw_cull_node *patch_nodes;     /* every surface's tree over its patches */
    uint32_t patch_node_count;
    uint32_t *surface_root;        /* surface_count: its tree's root in patch_nodes, or
                                      SW_CULL_LEAF when it has no patches */
    uint32_t *patch_order;         /* every surface's patches, as its leaves hold them */
    uint32_t surface_count;
    uint32_t depth;                /* the deepest path, top and patch levels together */
} sw_cull_tree;

/* What a query sees: the frustum, and the eye and unit view direction that
 * give depths (sw_box_depth_range), clamped below at near_z. */
typedef struct sw_cull_view {
    sw_frustum frustum;
    sw_vec3 eye, forward;
    double near_z;
} sw_cull_view;

/* What a query did, for the stats and the benchmark. */
typedef struct sw_cull_counts {
    uint64_t box_tests;            /* boxes tested against the frustum's planes */
    uint64_t depth_tests;          /* boxes whose depth range was computed */
} sw_cull_counts;

/* Nodes of one surface's tree over patch_count patches (0 for none): the
 * build halves the count until a leaf holds SW_CULL_LEAF_PATCHES, so the
 * count alone decides it. */
uint64_t sw_cull_tree_patch_nodes(uint32_t patch_count);

/* Arena bytes sw_cull_tree_build takes, worst case, for surface_count
 * surfaces holding patch_count patches in all, whose trees hold
 * patch_nodes nodes in all (sw_cull_tree_patch_nodes summed; its scratch
 * included); sw_cull_tree_bytes_of counts those from the surfaces. */
uint64_t sw_cull_tree_arena_bytes(uint32_t surface_count, uint64_t patch_count,
                                  uint64_t patch_nodes);
uint64_t sw_cull_tree_bytes_of(const sw_pack_surface *surfaces, uint32_t surface_count);

/* Builds the tree over surfaces[0 .. surface_count) and their patch ranges
 * (validated: every range within patches, every box min <= max). Splits at
 * the median of the boxes' centres along the widest axis, so the tree is
 * at most ceil(log2) + 1 levels at each level of it. SW_ERR_NO_MEMORY when
 * the arena cannot hold it. */
sw_status sw_cull_tree_build(sw_cull_tree *t, const sw_pack_surface *surfaces,
                             uint32_t surface_count, const sw_pack_patch *patches, sw_arena *arena,
                             sw_error *err);

/* Per surface s: nearest[s] and farthest[s] as described on top (both
 * arrays surface_count long, the caller's). Adds its work to *counts. */
void sw_cull_tree_query(const sw_cull_tree *t, const sw_cull_view *v, double *nearest,
                        double *farthest, sw_cull_counts *counts);

/* The same answers from every patch box tested on its own: the loop the
 * tree replaces, kept as the reference for tests and the benchmarks'
 * "before". */
void sw_cull_brute(const sw_pack_surface *surfaces, uint32_t surface_count,
                   const sw_pack_patch *patches, const sw_cull_view *v, double *nearest,
                   double *farthest, sw_cull_counts *counts);

/* Surface s's box: the union of its patches' boxes, exactly (empty when it
 * has none). */
sw_box sw_cull_tree_surface_box(const sw_cull_tree *t, uint32_t s);

/* A patch's box, as every culling path reads it. */
sw_box sw_cull_patch_box(const sw_pack_patch *p);

#endif
