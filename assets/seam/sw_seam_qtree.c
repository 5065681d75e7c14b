/* SPDX-License-Identifier: MIT */
/* Lazy quad-trees of derivative bounds over a surface's Bezier patches
 * (sw_seam_qtree.h). Every node holds rigorous bounds for its own cell: the
 * second derivatives from the cell's sub-patch (sw_bezier_second_deriv_bounds,
 * a proof from the hodographs, not a sample), the first derivatives from their
 * value at the cell's centre plus the second-derivative bound times the half
 * cell. Children's bounds are tighter, never looser in truth, so a query may
 * stop at any node. */
#include "sw_seam_qtree.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"

/* 2^-12 of a Bezier patch per side: deeper cells would not be flat either
 * (a singular rational patch), and the bounds of a coarser cell are still
 * valid, only loose. */
enum { MAX_DEPTH = 12 };
#define NO_CHILD SIZE_MAX

struct sw_seam_qnode {
    double s0, s1, t0, t1;  /* the cell in its patch's local [0,1]^2 */
    sw_seam_bounds b;       /* in the surface's (u, v) units; straddles unused */
    size_t child;           /* first of four, or NO_CHILD */
    int patch, depth, flat;
    int measured;           /* b and flat hold; else measured when a query first reaches it */
};

static size_t patch_doubles(const sw_seam_qtree *qt)
{
    return 4 * (size_t)(qt->degree_u + 1) * (size_t)(qt->degree_v + 1);
}

static sw_bezier_patch patch_view(const sw_seam_qtree *qt, int patch)
{
    return (sw_bezier_patch){qt->degree_u, qt->degree_v, 1, qt->ctrl + (size_t)patch * patch_doubles(qt)};
}

/* Column a spans params[2a .. 2a+1] in u; row b spans the v entries after them. */
static const double *col_range(const sw_seam_qtree *qt, int a) { return qt->params + 2 * a; }
static const double *row_range(const sw_seam_qtree *qt, int b)
{
    return qt->params + 2 * qt->pieces_u + 2 * b;
}

/* The cell's bounds from its sub-patch's control points (sub, the patch's
 * layout): hodograph bounds, centre derivatives. */
static sw_status node_measure(const sw_seam_qtree *qt, sw_seam_qnode *n, const double *sub,
                              sw_error *err)
{
    sw_bezier_patch view = {qt->degree_u, qt->degree_v, 1, sub};
    sw_deriv_bounds m;
    sw_status st = sw_bezier_second_deriv_bounds(&view, &m, err);
    if (st != SW_OK)
        return st;
    sw_surface_point c;
    sw_bezier_eval(&view, 0.5, 0.5, SW_EVAL_FIRST, &c);
    int a = n->patch % qt->pieces_u, b = n->patch / qt->pieces_u;
    double w = (n->s1 - n->s0) * (col_range(qt, a)[1] - col_range(qt, a)[0]);
    double h = (n->t1 - n->t0) * (row_range(qt, b)[1] - row_range(qt, b)[0]);
    double ls = sw_v3_length(c.du) + 0.5 * (m.uu + m.uv);
    double lt = sw_v3_length(c.dv) + 0.5 * (m.uv + m.vv);
    n->b = (sw_seam_bounds){ls / w, lt / h, m.uu / (w * w), m.uv / (w * h), m.vv / (h * h), 0};
    /* Any chord inside the cell leaves the surface by at most this (the
     * chord term of sw_seam_flatten.c with |du| <= w, |dv| <= h). */
    n->flat = (m.uu + 2 * m.uv + m.vv) / 8 <= qt->flat_tol;
    n->child = NO_CHILD;
    n->measured = 1;
    return SW_OK;
}

/* A child its split left unmeasured, from its own sub-patch. */
static sw_status node_measure_alone(const sw_seam_qtree *qt, sw_seam_qnode *n, sw_error *err)
{
    double sub[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    sw_bezier_patch whole = patch_view(qt, n->patch);
    sw_bezier_subpatch(&whole, n->s0, n->s1, n->t0, n->t1, sub);
    return node_measure(qt, n, sub, err);
}

static int outside(const sw_seam_qnode *n, const double lb[4])
{
    return n->s0 > lb[1] || n->s1 < lb[0] || n->t0 > lb[3] || n->t1 < lb[2];
}

/* The four children of a leaf; those the query's box lb reaches measured
 * now, from the quarters of the leaf's sub-patch (sw_bezier_quarters: one
 * sub-patch from the whole patch a split, where each child's own took four
 * times the de Casteljau passes), the others when a query first reaches
 * them (a trim curve crosses few of them). Measuring was about half of
 * an ASan pack build (perf: the OCCT link rods 57%, a 3,000-patch parts
 * showroom 49%); these took a fifth off both. */
static sw_status node_split(sw_seam_qtree *qt, size_t index, const double lb[4], sw_error *err)
{
    sw_seam_qnode *nodes = sw_grow(qt->nodes, &qt->node_capacity, qt->node_count + 4,
                                   sizeof *nodes);
    if (!nodes)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam quad-tree: out of memory at %zu nodes",
                            qt->node_count);
    qt->nodes = nodes;
    sw_seam_qnode p = qt->nodes[index];
    enum { NET = 4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER };
    double parent[NET], quarter[4][NET];
    double *const quarters[4] = {quarter[0], quarter[1], quarter[2], quarter[3]};
    sw_bezier_patch cell = patch_view(qt, p.patch);
    if (p.depth > 0) {
        sw_bezier_subpatch(&cell, p.s0, p.s1, p.t0, p.t1, parent);
        cell.ctrl = parent;
    }
    sw_bezier_quarters(&cell, quarters);
    double sm = 0.5 * (p.s0 + p.s1), tm = 0.5 * (p.t0 + p.t1);
    size_t first = qt->node_count;
    for (int k = 0; k < 4; k++) {
        sw_seam_qnode *c = &qt->nodes[first + (size_t)k];
        *c = (sw_seam_qnode){.s0 = (k & 1) ? sm : p.s0, .s1 = (k & 1) ? p.s1 : sm,
                             .t0 = (k & 2) ? tm : p.t0, .t1 = (k & 2) ? p.t1 : tm,
                             .patch = p.patch, .depth = p.depth + 1, .child = NO_CHILD};
        sw_status st = outside(c, lb) ? SW_OK : node_measure(qt, c, quarter[k], err);
        if (st != SW_OK)
            return st;
    }
    qt->node_count += 4;
    qt->nodes[index].child = first;
    return SW_OK;
}

void sw_seam_qtree_free(sw_seam_qtree *qt)
{
    if (!qt)
        return;
    free(qt->ctrl);
    free(qt->params);
    free(qt->nodes);
    memset(qt, 0, sizeof *qt);
}

sw_status sw_seam_qtree_init(sw_seam_qtree *qt, const sw_nurbs_surface *surface, double flat_tol,
                             sw_error *err)
{
    memset(qt, 0, sizeof *qt);
    if (!surface || !(flat_tol > 0) || !isfinite(flat_tol))
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_qtree_init: bad argument");
    sw_status st = sw_nurbs_surface_check(surface, err);
    if (st != SW_OK)
        return st;
    sw_nurbs_bezier_sizes z = sw_nurbs_surface_bezier_sizes(surface);
    size_t patches = (size_t)z.pieces_u * (size_t)z.pieces_v;
    qt->ctrl = malloc(z.ctrl_doubles * sizeof *qt->ctrl);
    qt->params = malloc(z.param_doubles * sizeof *qt->params);
    qt->nodes = malloc((patches + 64) * sizeof *qt->nodes);
    if (!qt->ctrl || !qt->params || !qt->nodes) {
        sw_seam_qtree_free(qt);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam quad-tree: out of memory for %zu patches",
                            patches);
    }
    qt->node_capacity = patches + 64;
    qt->degree_u = surface->degree_u, qt->degree_v = surface->degree_v;
    qt->pieces_u = z.pieces_u, qt->pieces_v = z.pieces_v;
    qt->flat_tol = flat_tol;
    st = sw_nurbs_surface_to_bezier(surface, qt->ctrl, qt->params, err);
    for (size_t p = 0; st == SW_OK && p < patches; p++) {
        qt->nodes[p] = (sw_seam_qnode){.s0 = 0, .s1 = 1, .t0 = 0, .t1 = 1, .patch = (int)p};
        st = node_measure(qt, &qt->nodes[p], patch_view(qt, (int)p).ctrl, err);
        qt->node_count++;
    }
    if (st != SW_OK) {
        sw_seam_qtree_free(qt);
        return st;
    }
    qt->domain[0] = col_range(qt, 0)[0], qt->domain[1] = col_range(qt, qt->pieces_u - 1)[1];
    qt->domain[2] = row_range(qt, 0)[0], qt->domain[3] = row_range(qt, qt->pieces_v - 1)[1];
    return SW_OK;
}

static void bounds_max(sw_seam_bounds *acc, const sw_seam_bounds *b)
{
    acc->lu = fmax(acc->lu, b->lu), acc->lv = fmax(acc->lv, b->lv);
    acc->uu = fmax(acc->uu, b->uu), acc->uv = fmax(acc->uv, b->uv), acc->vv = fmax(acc->vv, b->vv);
}

/* Max over the leaves under node index that touch the local box (s0, s1, t0, t1). */
static sw_status visit(sw_seam_qtree *qt, size_t index, const double lb[4], sw_seam_bounds *acc,
                       sw_error *err)
{
    sw_seam_qnode *n = &qt->nodes[index];
    if (outside(n, lb))
        return SW_OK;
    sw_status st = n->measured ? SW_OK : node_measure_alone(qt, n, err);
    if (st != SW_OK)
        return st;
    if (n->child == NO_CHILD && !n->flat && n->depth < MAX_DEPTH) {
        st = node_split(qt, index, lb, err);   /* may move the nodes */
        if (st != SW_OK)
            return st;
    }
    size_t child = qt->nodes[index].child;
    if (child == NO_CHILD) {
        bounds_max(acc, &qt->nodes[index].b);
        return SW_OK;
    }
    for (size_t k = 0; k < 4; k++) {
        st = visit(qt, child + k, lb, acc, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

/* First piece (of count, ranges at r + 2i) whose range ends at or after x. */
static int first_piece(const double *r, int count, size_t stride, double x)
{
    int lo = 0, hi = count - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (r[stride * (size_t)mid + 1] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

sw_status sw_seam_qtree_bounds(sw_seam_qtree *qt, const double box[4], sw_seam_bounds *out,
                               sw_error *err)
{
    double b[4] = {fmin(fmax(box[0], qt->domain[0]), qt->domain[1]),
                   fmin(fmax(box[1], qt->domain[0]), qt->domain[1]),
                   fmin(fmax(box[2], qt->domain[2]), qt->domain[3]),
                   fmin(fmax(box[3], qt->domain[2]), qt->domain[3])};
    memset(out, 0, sizeof *out);
    /* Outside the domain the surface is evaluated at the clamped (u, v):
     * continuous, but kinked where a chord crosses the domain's border. */
    const double *d = qt->domain;
    out->straddles = (box[0] < d[0] && d[0] < box[1]) || (box[0] < d[1] && d[1] < box[1]) ||
                     (box[2] < d[2] && d[2] < box[3]) || (box[2] < d[3] && d[3] < box[3]);
    const double *cols = col_range(qt, 0), *rows = row_range(qt, 0);
    for (int a = first_piece(cols, qt->pieces_u, 2, b[0]); a < qt->pieces_u; a++) {
        const double *cu = cols + 2 * a;
        if (cu[0] > b[1])
            break;
        if (cu[0] > b[0] && cu[0] < b[1])
            out->straddles = 1;
        for (int r = first_piece(rows, qt->pieces_v, 2, b[2]); r < qt->pieces_v; r++) {
            const double *cv = rows + 2 * r;
            if (cv[0] > b[3])
                break;
            if (cv[0] > b[2] && cv[0] < b[3])
                out->straddles = 1;
            double wu = cu[1] - cu[0], wv = cv[1] - cv[0];
            double lb[4] = {(b[0] - cu[0]) / wu, (b[1] - cu[0]) / wu, (b[2] - cv[0]) / wv,
                            (b[3] - cv[0]) / wv};
            sw_status st = visit(qt, (size_t)r * (size_t)qt->pieces_u + (size_t)a, lb, out, err);
            if (st != SW_OK)
                return st;
        }
    }
    return SW_OK;
}

void sw_seam_qtree_point(const sw_seam_qtree *qt, double u, double v, double out[3])
{
    u = fmin(fmax(u, qt->domain[0]), qt->domain[1]);
    v = fmin(fmax(v, qt->domain[2]), qt->domain[3]);
    const double *cols = col_range(qt, 0), *rows = row_range(qt, 0);
    int a = first_piece(cols, qt->pieces_u, 2, u), b = first_piece(rows, qt->pieces_v, 2, v);
    const double *cu = cols + 2 * a, *cv = rows + 2 * b;
    double s = fmin(fmax((u - cu[0]) / (cu[1] - cu[0]), 0.0), 1.0);
    double t = fmin(fmax((v - cv[0]) / (cv[1] - cv[0]), 0.0), 1.0);
    sw_bezier_patch view = patch_view(qt, b * qt->pieces_u + a);
    sw_surface_point p;
    sw_bezier_eval(&view, s, t, SW_EVAL_POINT, &p);
    out[0] = p.p.x, out[1] = p.p.y, out[2] = p.p.z;
}
