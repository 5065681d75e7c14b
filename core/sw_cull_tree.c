/* SPDX-License-Identifier: MIT */
#include "sw_cull_tree.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* Deep enough for any tree the median split builds: ceil(log2(2^32)) + 1
 * levels over surfaces and as many over one surface's patches, and a
 * depth-first walk that pushes both children holds at most one entry a
 * level plus one. */
enum { STACK = 80 };

/* A child's cull state when the parent was not inside: not yet tested. */
enum { UNTESTED = 3 };

sw_box sw_cull_patch_box(const sw_pack_patch *p)
{
    sw_box b = { sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                 sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
    return b;
}

static sw_box node_box(const sw_cull_node *n)
{
    sw_box b = { sw_v3(n->min[0], n->min[1], n->min[2]), sw_v3(n->max[0], n->max[1], n->max[2]) };
    return b;
}

/* ---- building ---- */

typedef struct builder {
    sw_cull_node *nodes;
    uint32_t used;
    uint32_t depth;                   /* deepest level reached */
    uint32_t leaf_max;                /* items a leaf holds at most */
    const uint32_t *items_base;       /* leaves point into it (leaf_max > 1) */
    /* The items' boxes: patches, or the roots of the surfaces' trees. */
    const sw_pack_patch *patches;     /* non-NULL: items are patch indices */
    const sw_cull_node *roots_nodes;  /* else items are surfaces, */
    const uint32_t *roots;            /* their boxes roots_nodes[roots[item]] */
} builder;

_Static_assert(offsetof(sw_pack_patch, box_max) == offsetof(sw_pack_patch, box_min) +
                   3 * sizeof(float), "a patch's box corners follow each other");
_Static_assert(offsetof(sw_cull_node, max) == offsetof(sw_cull_node, min) + 3 * sizeof(float),
               "a node's box corners follow each other");

/* An item's box: its low corner, its high one 3 floats on (a patch's
 * box_min then box_max, a node's min then max). */
static const float *item_corners(const builder *b, uint32_t item)
{
    return b->patches ? b->patches[item].box_min : b->roots_nodes[b->roots[item]].min;
}

static void item_box(const builder *b, uint32_t item, float min[3], float max[3])
{
    const float *c = item_corners(b, item);
    memcpy(min, c, 3 * sizeof(float));
    memcpy(max, c + 3, 3 * sizeof(float));
}

static double item_centre(const builder *b, uint32_t item, int axis)
{
    const float *c = item_corners(b, item);
    return (double)c[axis] + (double)c[3 + axis];
}

/* The widest axis of the items' box centres: the split that halves space
 * best when the median splits the count. */
static int widest_axis(const builder *b, const uint32_t *items, uint32_t count)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t i = 0; i < count; i++) {
        const float *corners = item_corners(b, items[i]);
        for (int k = 0; k < 3; k++) {
            double c = (double)corners[k] + (double)corners[3 + k];
            lo[k] = c < lo[k] ? c : lo[k], hi[k] = c > hi[k] ? c : hi[k];
        }
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (hi[k] - lo[k] > hi[axis] - lo[axis])
            axis = k;
    return axis;
}

/* Reorders items so that items[k] has the k-th smallest centre along axis,
 * none before it larger and none after it smaller (Wirth's select). */
static void select_kth(const builder *b, uint32_t *items, uint32_t count, uint32_t k, int axis)
{
    int64_t lo = 0, hi = (int64_t)count - 1;
    while (lo < hi) {
        double pivot = item_centre(b, items[k], axis);
        int64_t i = lo, j = hi;
        do {
            while (item_centre(b, items[i], axis) < pivot)
                i++;
            while (pivot < item_centre(b, items[j], axis))
                j--;
            if (i <= j) {
                uint32_t tmp = items[i];
                items[i++] = items[j], items[j--] = tmp;
            }
        } while (i <= j);
        if (j < (int64_t)k)
            lo = i;
        if ((int64_t)k < i)
            hi = j;
    }
}

static void union_of(sw_cull_node *n, const sw_cull_node *l, const sw_cull_node *r)
{
    for (int k = 0; k < 3; k++) {
        float lo = l->min[k] < r->min[k] ? l->min[k] : r->min[k];
        float hi = l->max[k] > r->max[k] ? l->max[k] : r->max[k];
        n->min[k] = lo, n->max[k] = hi;
    }
}

/* The tree over items[0 .. count), count >= 1, in preorder; its root. A
 * leaf of one item names it; a leaf of more names where they start in
 * items_base. */
static uint32_t build_node(builder *b, uint32_t *items, uint32_t count, uint32_t level)
{
    uint32_t self = b->used++;
    sw_cull_node *n = &b->nodes[self];
    b->depth = level > b->depth ? level : b->depth;
    if (count <= b->leaf_max) {
        item_box(b, items[0], n->min, n->max);
        for (uint32_t i = 1; i < count; i++) {
            sw_cull_node one;
            item_box(b, items[i], one.min, one.max);
            union_of(n, n, &one);
        }
        n->a = b->leaf_max == 1 ? items[0] : (uint32_t)(items - b->items_base);
        n->b = SW_CULL_LEAF | count;
        return self;
    }
    uint32_t half = count / 2;
    select_kth(b, items, count, half, widest_axis(b, items, count));
    uint32_t left = build_node(b, items, half, level + 1);
    uint32_t right = build_node(b, items + half, count - half, level + 1);
    n = &b->nodes[self];
    n->a = left, n->b = right;
    union_of(n, &b->nodes[left], &b->nodes[right]);
    return self;
}

/* Each allocation as sw_cull_tree_build makes it. */
static uint64_t take_bytes(uint64_t bytes) { return sw_arena_worst_case(bytes + 1, 64); }

uint64_t sw_cull_tree_patch_nodes(uint32_t patch_count)
{
    if (patch_count <= SW_CULL_LEAF_PATCHES)
        return patch_count ? 1 : 0;
    uint32_t half = patch_count / 2;   /* as build_node splits */
    return 1 + sw_cull_tree_patch_nodes(half) + sw_cull_tree_patch_nodes(patch_count - half);
}

uint64_t sw_cull_tree_arena_bytes(uint32_t surface_count, uint64_t patch_count,
                                  uint64_t patch_nodes)
{
    uint64_t n = surface_count;
    return take_bytes(2 * n * sizeof(sw_cull_node)) +          /* top */
           take_bytes(patch_nodes * sizeof(sw_cull_node)) +    /* patch_nodes */
           take_bytes(n * sizeof(uint32_t)) +                   /* surface_root */
           take_bytes(patch_count * sizeof(uint32_t)) +         /* patch_order */
           take_bytes(n * sizeof(uint32_t));                    /* scratch: the surfaces */
}

uint64_t sw_cull_tree_bytes_of(const sw_pack_surface *surfaces, uint32_t surface_count)
{
    uint64_t patches = 0, nodes = 0;
    for (uint32_t s = 0; s < surface_count; s++) {
        patches += surfaces[s].patch_count;
        nodes += sw_cull_tree_patch_nodes(surfaces[s].patch_count);
    }
    return sw_cull_tree_arena_bytes(surface_count, patches, nodes);
}

static void *take(sw_arena *a, uint64_t bytes, int *failed)
{
    void *p = bytes < SIZE_MAX ? sw_arena_alloc(a, (size_t)bytes + 1, 64) : NULL;
    *failed |= p == NULL;
    return p;
}

/* Every surface's tree over its patches (their order in t->patch_order);
 * the surfaces that have patches into surfaces_out (their count returned). */
static uint32_t build_patch_trees(sw_cull_tree *t, const sw_pack_surface *surfaces,
                                  uint32_t *surfaces_out)
{
    builder b = { t->patch_nodes, 0, 0, SW_CULL_LEAF_PATCHES, t->patch_order, t->patches, NULL,
                  NULL };
    uint32_t with_patches = 0, deepest = 0, at = 0;
    for (uint32_t s = 0; s < t->surface_count; s++) {
        const sw_pack_surface *ps = &surfaces[s];
        t->surface_root[s] = SW_CULL_LEAF;
        if (ps->patch_count == 0)
            continue;
        uint32_t *items = t->patch_order + at;
        for (uint32_t i = 0; i < ps->patch_count; i++)
            items[i] = ps->first_patch + i;
        at += ps->patch_count;
        b.depth = 0;
        t->surface_root[s] = build_node(&b, items, ps->patch_count, 1);
        deepest = b.depth > deepest ? b.depth : deepest;
        surfaces_out[with_patches++] = s;
    }
    t->depth = deepest;
    t->patch_node_count = b.used;
    return with_patches;
}

sw_status sw_cull_tree_build(sw_cull_tree *t, const sw_pack_surface *surfaces,
                             uint32_t surface_count, const sw_pack_patch *patches, sw_arena *arena,
                             sw_error *err)
{
    memset(t, 0, sizeof *t);
    uint64_t patch_count = 0, nodes = 0, n = surface_count;
    for (uint32_t s = 0; s < surface_count; s++) {
        patch_count += surfaces[s].patch_count;
        nodes += sw_cull_tree_patch_nodes(surfaces[s].patch_count);
    }
    int failed = 0;
    t->top = take(arena, 2 * n * sizeof(sw_cull_node), &failed);
    t->patch_nodes = take(arena, nodes * sizeof(sw_cull_node), &failed);
    t->surface_root = take(arena, n * sizeof(uint32_t), &failed);
    t->patch_order = take(arena, patch_count * sizeof(uint32_t), &failed);
    size_t mark = sw_arena_mark(arena);
    uint32_t *with_patches = take(arena, n * sizeof(uint32_t), &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the culling tree over "
                            "%u surfaces (needs %llu bytes)", surface_count,
                            (unsigned long long)sw_cull_tree_arena_bytes(surface_count,
                                                                         patch_count, nodes));
    t->patches = patches;
    t->surfaces = surfaces;
    t->surface_count = surface_count;
    uint32_t count = build_patch_trees(t, surfaces, with_patches);
    if (count > 0) {
        builder b = { t->top, 0, 0, 1, NULL, NULL, t->patch_nodes, t->surface_root };
        build_node(&b, with_patches, count, 1);
        t->top_count = b.used;
        t->depth += b.depth;
    }
    sw_arena_reset_to(arena, mark);
    return SW_OK;
}

sw_box sw_cull_tree_surface_box(const sw_cull_tree *t, uint32_t s)
{
    uint32_t root = t->surface_root[s];
    return root == SW_CULL_LEAF ? sw_box_empty() : node_box(&t->patch_nodes[root]);
}

/* ---- querying ---- */

static sw_cull test_node(const sw_cull_node *n, const sw_cull_view *v, sw_cull_counts *c)
{
    sw_box b = node_box(n);
    c->box_tests++;
    return sw_frustum_test_box(&v->frustum, &b);
}

typedef struct patch_entry {
    uint32_t node;
    int state;                    /* sw_cull, or UNTESTED */
    double lo, hi;                /* its box's depth range */
} patch_entry;

static patch_entry patch_entry_of(const sw_cull_tree *t, uint32_t node, int state,
                                  const sw_cull_view *v, sw_cull_counts *c)
{
    patch_entry e = { node, state, 0, 0 };
    sw_box b = node_box(&t->patch_nodes[node]);
    c->depth_tests++;
    sw_box_depth_range(&b, v->eye, v->forward, &e.lo, &e.hi);
    return e;
}

/* A leaf's patches: tested one by one unless the leaf is inside, or holds
 * one patch and was itself tested (state SW_CULL_INTERSECTS: its box is
 * that patch's). */
static void cull_leaf(const sw_cull_tree *t, const sw_cull_view *v, const sw_cull_node *n,
                      int state, double *best_lo, double *best_hi, sw_cull_counts *c)
{
    uint32_t count = n->b & ~SW_CULL_LEAF;
    int known = state == SW_CULL_INSIDE || (state == SW_CULL_INTERSECTS && count == 1);
    for (uint32_t k = 0; k < count; k++) {
        sw_box box = sw_cull_patch_box(&t->patches[t->patch_order[n->a + k]]);
        if (!known) {
            c->box_tests++;
            if (sw_frustum_test_box(&v->frustum, &box) == SW_CULL_OUTSIDE)
                continue;
        }
        double lo, hi;
        c->depth_tests++;
        sw_box_depth_range(&box, v->eye, v->forward, &lo, &hi);
        lo = lo > v->near_z ? lo : v->near_z;
        *best_lo = lo < *best_lo ? lo : *best_lo;
        *best_hi = hi > *best_hi ? hi : *best_hi;
    }
}

/* One surface's patches below root, whose state the top level found:
 * nearest first, a subtree skipped when it can change neither answer. */
static void cull_patches(const sw_cull_tree *t, const sw_cull_view *v, uint32_t root, int state,
                         double *nearest, double *farthest, sw_cull_counts *c)
{
    patch_entry stack[STACK];
    int top = 0;
    double best_lo = INFINITY, best_hi = -INFINITY;
    stack[top++] = patch_entry_of(t, root, state, v, c);
    while (top > 0) {
        patch_entry e = stack[--top];
        double lo = e.lo > v->near_z ? e.lo : v->near_z; /* as sw_view_box_min_depth */
        if (lo >= best_lo && e.hi <= best_hi)
            continue;
        const sw_cull_node *n = &t->patch_nodes[e.node];
        int st = e.state == UNTESTED ? (int)test_node(n, v, c) : e.state;
        if (st == SW_CULL_OUTSIDE)
            continue;
        if (n->b & SW_CULL_LEAF) {
            cull_leaf(t, v, n, st, &best_lo, &best_hi, c);
            continue;
        }
        int child = st == SW_CULL_INSIDE ? SW_CULL_INSIDE : UNTESTED;
        patch_entry a = patch_entry_of(t, n->a, child, v, c);
        patch_entry b = patch_entry_of(t, n->b, child, v, c);
        /* The nearer one on top: it is popped first. */
        stack[top++] = a.lo < b.lo ? b : a;
        stack[top++] = a.lo < b.lo ? a : b;
    }
    *nearest = best_lo;
    *farthest = best_hi;
}

/* Surface s wholly in view: every patch's depth range, one after the
 * other when there are few; the tree's nearest-first walk when there are
 * many (it skips the subtrees that cannot change the answers). */
static void inside_surface(const sw_cull_tree *t, const sw_cull_view *v, uint32_t s,
                           double *nearest, double *farthest, sw_cull_counts *c)
{
    const sw_pack_surface *ps = &t->surfaces[s];
    if (ps->patch_count > SW_CULL_SCAN_PATCHES) {
        cull_patches(t, v, t->surface_root[s], SW_CULL_INSIDE, nearest, farthest, c);
        return;
    }
    double best_lo = INFINITY, best_hi = -INFINITY;
    for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
        sw_box box = sw_cull_patch_box(&t->patches[i]);
        double lo, hi;
        c->depth_tests++;
        sw_box_depth_range(&box, v->eye, v->forward, &lo, &hi);
        lo = lo > v->near_z ? lo : v->near_z;
        best_lo = lo < best_lo ? lo : best_lo;
        best_hi = hi > best_hi ? hi : best_hi;
    }
    *nearest = best_lo;
    *farthest = best_hi;
}

/* A top-level subtree wholly in view: in preorder it is the run from its
 * root to its rightmost leaf, and every leaf in that run is a surface in
 * view. */
static void inside_subtree(const sw_cull_tree *t, const sw_cull_view *v, uint32_t node,
                           double *nearest, double *farthest, sw_cull_counts *c)
{
    uint32_t last = node;
    while (!(t->top[last].b & SW_CULL_LEAF))
        last = t->top[last].b;
    for (uint32_t k = node; k <= last; k++)
        if (t->top[k].b & SW_CULL_LEAF) {
            uint32_t s = t->top[k].a;
            inside_surface(t, v, s, &nearest[s], &farthest[s], c);
        }
}

static double centre_depth(const sw_cull_node *n, const sw_cull_view *v)
{
    sw_vec3 c = sw_v3(0.5 * ((double)n->min[0] + n->max[0]), 0.5 * ((double)n->min[1] + n->max[1]),
                      0.5 * ((double)n->min[2] + n->max[2]));
    return sw_v3_dot(sw_v3_sub(c, v->eye), v->forward);
}

void sw_cull_tree_query(const sw_cull_tree *t, const sw_cull_view *v, double *nearest,
                        double *farthest, sw_cull_counts *counts)
{
    for (uint32_t s = 0; s < t->surface_count; s++)
        nearest[s] = INFINITY, farthest[s] = -INFINITY;
    if (t->top_count == 0)
        return;
    struct { uint32_t node; int state; } stack[STACK];
    int top = 0;
    stack[top].node = 0, stack[top++].state = UNTESTED;
    while (top > 0) {
        uint32_t node = stack[--top].node;
        int state = stack[top].state;
        const sw_cull_node *n = &t->top[node];
        int st = state == UNTESTED ? (int)test_node(n, v, counts) : state;
        if (st == SW_CULL_OUTSIDE)
            continue;
        if (st == SW_CULL_INSIDE) {
            inside_subtree(t, v, node, nearest, farthest, counts);
            continue;
        }
        if (n->b & SW_CULL_LEAF) {
            /* The surface's root has this leaf's box: st holds for it. */
            uint32_t s = n->a;
            cull_patches(t, v, t->surface_root[s], st, &nearest[s], &farthest[s], counts);
            continue;
        }
        /* Front to back by the children's centres (cheap; the answers do
         * not depend on the order at this level). */
        int a_first = centre_depth(&t->top[n->a], v) < centre_depth(&t->top[n->b], v);
        stack[top].node = a_first ? n->b : n->a, stack[top++].state = UNTESTED;
        stack[top].node = a_first ? n->a : n->b, stack[top++].state = UNTESTED;
    }
}

void sw_cull_brute(const sw_pack_surface *surfaces, uint32_t surface_count,
                   const sw_pack_patch *patches, const sw_cull_view *v, double *nearest,
                   double *farthest, sw_cull_counts *counts)
{
    for (uint32_t s = 0; s < surface_count; s++) {
        double lo_best = INFINITY, hi_best = -INFINITY;
        const sw_pack_surface *ps = &surfaces[s];
        for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
            sw_box box = sw_cull_patch_box(&patches[i]);
            counts->box_tests++;
            if (sw_frustum_test_box(&v->frustum, &box) == SW_CULL_OUTSIDE)
                continue;
            double lo, hi;
            counts->depth_tests++;
            sw_box_depth_range(&box, v->eye, v->forward, &lo, &hi);
            lo = lo > v->near_z ? lo : v->near_z;
            lo_best = fmin(lo_best, lo);
            hi_best = fmax(hi_best, hi);
        }
        nearest[s] = lo_best;
        farthest[s] = hi_best;
    }
}
