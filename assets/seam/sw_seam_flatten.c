/* SPDX-License-Identifier: MIT */
/* Trimming loops to polylines with a model-space error bound
 * (sw_seam_flatten.h; Guthe et al. 2002, section 4).
 *
 * Better than the paper, and why it still holds: the paper subdivides the
 * surface until it is flat within tol/3 in every quad-tree leaf, splits the
 * curves at the leaves' borders and then approximates each piece with [13]'s
 * estimate. Here a candidate chord of a trim curve's Bezier piece is accepted
 * on one combined bound over the box of its control points (the leaves it
 * touches, sw_seam_qtree.c):
 *
 *   err = lu * EU + lv * EV + chord,   chord = (S_uu du^2 + 2 S_uv |du dv| + S_vv dv^2) / 8
 *
 * EU, EV: the largest u and v offsets of the piece's control points from the
 * chord (the curve is a convex combination of them, and its foot point on the
 * chord the same combination of theirs, so every curve point is within
 * (EU, EV) of the chord point it projects to; the control points must project
 * inside the chord, so every chord point has such a curve point too, by
 * continuity). lu * EU + lv * EV bounds how far apart those two points land on
 * the surface; chord bounds how far the surface image of the (u, v) chord
 * leaves the 3D chord (linear interpolation error of S along it). The budget
 * is spent where it is needed instead of a fixed third for the surface, and
 * no curve/grid intersections are computed. Across an interior knot line
 * (where a NURBS may be only C0) the chord term falls back to the
 * first-derivative bound lu |du| + lv |dv|. */
#include "sw_seam_flatten.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_math.h"
#include "sw_seam_qtree.h"

enum { MAX_HALVINGS = 40, MAX_RUN = 64 };

typedef struct vbuf {
    double *uv, *p;
    uint8_t *pin;      /* 1: a curve's start (a corner of the loop): never simplified away */
    float *gap;        /* the gap of the curve(s) the vertex lies on (sw_seam_polylines.gap) */
    uint32_t *edge;    /* the shared edge of the segment from the vertex on (.edge) */
    size_t count, capacity;
} vbuf;

typedef struct flat_ctx {
    sw_seam_qtree *qt;
    double tol;        /* for the halving: tolerance / 2 */
    int min_depth;     /* halvings forced before any piece is accepted */
    size_t unproven;
    size_t clamped;    /* points moved onto the domain's border */
    float gap;         /* of the curve being flattened */
    uint32_t edge;     /* of the curve being flattened, made unique in the model */
    size_t loop_first; /* the buffer index the loop being flattened starts at */
    const uint32_t *part_edges;   /* per part: the ids before its own (NULL: none) */
    vbuf *buf;
    sw_error *err;
} flat_ctx;

static sw_status vbuf_push(flat_ctx *c, double u, double v)
{
    /* A p-curve a little past its surface's domain (exporters' fits do
     * that) goes onto the border: the surface is evaluated there anyway
     * (sw_seam_qtree_point clamps), and the runtime's tessellator refuses a
     * loop far outside the domain, which would leave a hole. */
    const double *d = c->qt->domain;
    double cu = fmin(fmax(u, d[0]), d[1]), cv = fmin(fmax(v, d[2]), d[3]);
    c->clamped += cu != u || cv != v;
    u = cu, v = cv;
    vbuf *b = c->buf;
    /* Only within the loop: the last loop may end where this one starts. */
    if (b->count > c->loop_first && b->uv[2 * b->count - 2] == u &&
        b->uv[2 * b->count - 1] == v) {
        b->gap[b->count - 1] = fmaxf(b->gap[b->count - 1], c->gap);
        b->edge[b->count - 1] = c->edge;   /* the segment from it is this curve's */
        return SW_OK; /* a degenerate piece: same point twice */
    }
    if (b->count == b->capacity) {
        size_t cap = b->capacity * 2 + 256;
        double *uv = realloc(b->uv, cap * 2 * sizeof *uv);
        if (uv)
            b->uv = uv;
        double *p = uv ? realloc(b->p, cap * 3 * sizeof *p) : NULL;
        if (p)
            b->p = p;
        uint8_t *pin = p ? realloc(b->pin, cap * sizeof *pin) : NULL;
        if (pin)
            b->pin = pin;
        float *gap = pin ? realloc(b->gap, cap * sizeof *gap) : NULL;
        if (gap)
            b->gap = gap;
        uint32_t *edge = gap ? realloc(b->edge, cap * sizeof *edge) : NULL;
        if (!edge)
            return sw_error_set(c->err, SW_ERR_NO_MEMORY, "flattening trims: out of memory");
        b->edge = edge;
        b->capacity = cap;
    }
    b->uv[2 * b->count] = u, b->uv[2 * b->count + 1] = v;
    b->pin[b->count] = 0;
    b->gap[b->count] = c->gap;
    b->edge[b->count] = c->edge;
    sw_seam_qtree_point(c->qt, u, v, b->p + 3 * b->count);
    b->count++;
    return SW_OK;
}

/* How far the surface image of the (u, v) chord d can leave the 3D chord. */
static double chord_term(const sw_seam_bounds *b, double du, double dv)
{
    du = fabs(du), dv = fabs(dv);
    if (b->straddles)
        return b->lu * du + b->lv * dv;
    return (b->uu * du * du + 2 * b->uv * du * dv + b->vv * dv * dv) / 8;
}

/* The combined bound of the header comment for one piece (n + 1 Cartesian
 * (u, v) control points), or INFINITY when it cannot be proved this way. */
static sw_status piece_error(flat_ctx *c, const double pt[][2], int n, double *out)
{
    double du = pt[n][0] - pt[0][0], dv = pt[n][1] - pt[0][1], len2 = du * du + dv * dv;
    double eu = 0, ev = 0, box[4] = {pt[0][0], pt[0][0], pt[0][1], pt[0][1]};
    *out = INFINITY;
    for (int i = 1; i <= n; i++) {
        double x = pt[i][0] - pt[0][0], y = pt[i][1] - pt[0][1];
        double s = len2 > 0 ? (x * du + y * dv) / len2 : 0;
        if (len2 > 0 ? !(s >= 0 && s <= 1) : (x != 0 || y != 0))
            return SW_OK;
        eu = fmax(eu, fabs(x - s * du));
        ev = fmax(ev, fabs(y - s * dv));
        box[0] = fmin(box[0], pt[i][0]), box[1] = fmax(box[1], pt[i][0]);
        box[2] = fmin(box[2], pt[i][1]), box[3] = fmax(box[3], pt[i][1]);
    }
    sw_seam_bounds b;
    sw_status st = sw_seam_qtree_bounds(c->qt, box, &b, c->err);
    if (st == SW_OK)
        *out = b.lu * eu + b.lv * ev + chord_term(&b, du, dv);
    return st;
}

/* Emits the piece's end after its start (already emitted), halving the
 * homogeneous piece h (w u, w v, w) until its bound passes. */
static sw_status flatten_piece(flat_ctx *c, const double h[][3], int n, int depth)
{
    double pt[SW_BEZIER_MAX_ORDER][2];
    for (int i = 0; i <= n; i++)
        pt[i][0] = h[i][0] / h[i][2], pt[i][1] = h[i][1] / h[i][2];
    double e = INFINITY;
    if (depth >= c->min_depth) {
        sw_status st = piece_error(c, (const double(*)[2])pt, n, &e);
        if (st != SW_OK)
            return st;
    }
    if (e <= c->tol || depth >= MAX_HALVINGS) {
        c->unproven += !(e <= c->tol);
        return vbuf_push(c, pt[n][0], pt[n][1]);
    }
    double left[SW_BEZIER_MAX_ORDER][3], right[SW_BEZIER_MAX_ORDER][3], w[SW_BEZIER_MAX_ORDER][3];
    memcpy(w, h, sizeof(double) * 3 * (size_t)(n + 1));
    for (int r = 0; r <= n; r++) {
        memcpy(left[r], w[0], sizeof left[r]);
        memcpy(right[n - r], w[n - r], sizeof right[0]);
        for (int i = 0; i < n - r; i++)
            for (int k = 0; k < 3; k++)
                w[i][k] = 0.5 * (w[i][k] + w[i + 1][k]);
    }
    sw_status st = flatten_piece(c, (const double(*)[3])left, n, depth + 1);
    return st == SW_OK ? flatten_piece(c, (const double(*)[3])right, n, depth + 1) : st;
}

/* Emits the curve from its start (unless skip_start: the previous curve's end
 * stands for it) to its end. */
static sw_status flatten_curve(flat_ctx *c, const sw_nurbs_curve *curve, int skip_start)
{
    sw_status st = sw_nurbs_curve_check(curve, c->err);
    if (st != SW_OK)
        return st;
    sw_nurbs_bezier_sizes z = sw_nurbs_curve_bezier_sizes(curve);
    double *ctrl = malloc(z.ctrl_doubles * sizeof *ctrl);
    double *params = malloc(z.param_doubles * sizeof *params);
    if (!ctrl || !params)
        st = sw_error_set(c->err, SW_ERR_NO_MEMORY, "flattening trims: out of memory");
    if (st == SW_OK)
        st = sw_nurbs_curve_to_bezier(curve, ctrl, params, c->err);
    if (st == SW_OK && !skip_start)
        st = vbuf_push(c, curve->ctrl[0], curve->ctrl[1]);
    if (st == SW_OK)
        c->buf->pin[c->buf->count - 1] = 1;
    int n = curve->degree;
    for (int p = 0; st == SW_OK && p < z.pieces_u; p++) {
        double h[SW_BEZIER_MAX_ORDER][3];
        for (int i = 0; i <= n; i++) {
            const double *q = ctrl + ((size_t)p * (size_t)(n + 1) + (size_t)i) * 4;
            h[i][0] = q[0] * q[3], h[i][1] = q[1] * q[3], h[i][2] = q[3];
        }
        st = flatten_piece(c, (const double(*)[3])h, n, 0);
    }
    free(ctrl);
    free(params);
    return st;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from p to the segment a-b in 3D. */
static double point_segment3(const double *p, const double *a, const double *b)
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

/* May the vertices strictly between i and j (indices into the loop's n
 * vertices, j taken mod n) be dropped? Their 3D points within half the
 * tolerance of the new segment (the halving left the other half), and the
 * new (u, v) chord's surface image within half of it as well. */
static sw_status can_drop(flat_ctx *c, size_t first, size_t n, size_t i, size_t j, int *ok)
{
    const double *uv = c->buf->uv + 2 * first, *p = c->buf->p + 3 * first;
    size_t jm = j % n;
    *ok = 0;
    for (size_t k = i + 1; k < j; k++)
        if (c->buf->pin[first + k] || !(point_segment3(p + 3 * k, p + 3 * i, p + 3 * jm) <= c->tol))
            return SW_OK;
    double box[4] = {fmin(uv[2 * i], uv[2 * jm]), fmax(uv[2 * i], uv[2 * jm]),
                     fmin(uv[2 * i + 1], uv[2 * jm + 1]), fmax(uv[2 * i + 1], uv[2 * jm + 1])};
    sw_seam_bounds b;
    sw_status st = sw_seam_qtree_bounds(c->qt, box, &b, c->err);
    *ok = st == SW_OK && chord_term(&b, uv[2 * jm] - uv[2 * i], uv[2 * jm + 1] - uv[2 * i + 1]) <= c->tol;
    return st;
}

/* Greedy simplification of the loop's vertices [first, end) in place
 * (section 4: approximated at half the tolerance, then simplified up to
 * it); runs are at most MAX_RUN edges so the cost stays linear. Never fewer
 * than 3 vertices, and never a curve's start: the loop keeps its corners,
 * where seams to different neighbours meet (at a collapsed side, as at the
 * teaspoon's tip, a corner is within the tolerance of a chord in 3D but far
 * from it in (u, v)). */
static sw_status simplify_loop(flat_ctx *c, size_t first)
{
    size_t n = c->buf->count - first, kept = 0;
    if (n <= 3)
        return SW_OK;
    size_t *keep = malloc(n * sizeof *keep);
    if (!keep)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "simplifying trims: out of memory");
    sw_status st = SW_OK;
    for (size_t i = 0; i < n && st == SW_OK;) {
        keep[kept++] = i;
        size_t j = i + 1;
        int ok = 1;
        while (ok && j < n && j - i < MAX_RUN && st == SW_OK) {
            st = can_drop(c, first, n, i, j + 1, &ok);
            j += ok;
        }
        i = j;
    }
    if (st == SW_OK && kept >= 3) {
        double *uv = c->buf->uv + 2 * first, *p = c->buf->p + 3 * first;
        uint8_t *pin = c->buf->pin + first;
        float *gap = c->buf->gap + first;
        uint32_t *edge = c->buf->edge + first;
        for (size_t k = 0; k < kept; k++) {
            /* A kept vertex stands for the dropped ones after it: their gaps too. */
            float g = gap[keep[k]];
            for (size_t d = keep[k] + 1; d < (k + 1 < kept ? keep[k + 1] : n); d++)
                g = fmaxf(g, gap[d]);
            memmove(uv + 2 * k, uv + 2 * keep[k], 2 * sizeof *uv);
            memmove(p + 3 * k, p + 3 * keep[k], 3 * sizeof *p);
            pin[k] = pin[keep[k]];
            gap[k] = g;
            edge[k] = edge[keep[k]];   /* curve starts are kept: one curve up to the next */
        }
        c->buf->count = first + kept;
    }
    free(keep);
    return st;
}

/* Flattens one loop's curves head to tail into the buffer. A curve's start
 * stands in for the previous curve's end only where both are the same 3D
 * point (to rounding): a real gap between two curves keeps both ends and an
 * edge across it. */
static sw_status flatten_loop(flat_ctx *c, const sw_nurbs_curve *curves, const double *gaps,
                              const uint32_t *edges, size_t count)
{
    size_t first = c->buf->count;
    c->loop_first = first;
    for (size_t k = 0; k < count; k++) {
        int skip = 0;
        if (k > 0) {
            double q[3];
            sw_seam_qtree_point(c->qt, curves[k].ctrl[0], curves[k].ctrl[1], q);
            skip = dist3(q, c->buf->p + 3 * (c->buf->count - 1)) <= 1e-6 * c->tol;
        }
        c->gap = gaps ? (float)gaps[k] : 0.0f;
        c->edge = edges ? edges[k] : 0;
        if (skip) {  /* the previous curve's end is this one's start too */
            c->buf->gap[c->buf->count - 1] = fmaxf(c->buf->gap[c->buf->count - 1], c->gap);
            c->buf->edge[c->buf->count - 1] = c->edge;
        }
        sw_status st = flatten_curve(c, &curves[k], skip);
        if (st != SW_OK) {
            sw_error_prefix(c->err, "curve %zu", k);
            return st;
        }
    }
    vbuf *b = c->buf;
    if (b->count - first > 1 && dist3(b->p + 3 * first, b->p + 3 * (b->count - 1)) <= 1e-6 * c->tol)
        b->count--;
    return SW_OK;
}

/* The domain rectangle of an untrimmed surface as four straight curves. */
typedef struct rect_loop {
    double knots[4][4], ctrl[4][8];
    sw_nurbs_curve curves[4];
} rect_loop;

static void rect_loop_make(rect_loop *r, const double d[4])
{
    const double corner[5][2] = {{d[0], d[2]}, {d[1], d[2]}, {d[1], d[3]}, {d[0], d[3]}, {d[0], d[2]}};
    for (int k = 0; k < 4; k++) {
        double kn[4] = {0, 0, 1, 1};
        double ct[8] = {corner[k][0], corner[k][1], 0, 1, corner[k + 1][0], corner[k + 1][1], 0, 1};
        memcpy(r->knots[k], kn, sizeof kn);
        memcpy(r->ctrl[k], ct, sizeof ct);
        r->curves[k] = (sw_nurbs_curve){1, 2, r->knots[k], r->ctrl[k]};
    }
}

/* Where segments a-b and c-d cross properly in (u, v): 1 and *t (along
 * a-b), else 0. */
static int uv_cross(const double *a, const double *b, const double *c, const double *d, double *t)
{
    double r[2] = {b[0] - a[0], b[1] - a[1]}, s[2] = {d[0] - c[0], d[1] - c[1]};
    double den = r[0] * s[1] - r[1] * s[0];
    if (den == 0)
        return 0;
    double ac[2] = {c[0] - a[0], c[1] - a[1]};
    double ta = (ac[0] * s[1] - ac[1] * s[0]) / den, tc = (ac[0] * r[1] - ac[1] * r[0]) / den;
    *t = ta;
    return ta > 0 && ta < 1 && tc > 0 && tc < 1;
}

/* Removes vertex k of the loop [first, count) from the buffer. */
static void drop_vertex(vbuf *b, size_t k)
{
    size_t after = b->count - k - 1;
    memmove(b->uv + 2 * k, b->uv + 2 * (k + 1), 2 * after * sizeof *b->uv);
    memmove(b->p + 3 * k, b->p + 3 * (k + 1), 3 * after * sizeof *b->p);
    memmove(b->pin + k, b->pin + k + 1, after * sizeof *b->pin);
    memmove(b->gap + k, b->gap + k + 1, after * sizeof *b->gap);
    memmove(b->edge + k, b->edge + k + 1, after * sizeof *b->edge);
    b->count--;
}

/* Folds at corners taken out: where a curve's (u, v) runs a little past
 * its neighbour's before turning back along it (a p-curve overshooting
 * the corner, its gap closed by a straight trim), segments i and i + 2
 * cross and the loop crosses itself there; the tessellator refuses that
 * wherever its cells are large enough to see it. The two vertices between
 * become the crossing point, which cuts off the sliver. In a loop of four
 * the sliver may lie the other way round, between segments i + 2 and i
 * (a triangle whose corner gap was closed by a straight trim: cutting
 * across i + 1, its longest side, left it a point): the shorter of the
 * two joining segments is the sliver's. */
static void unfold_loop(flat_ctx *c, size_t first)
{
    vbuf *b = c->buf;
    for (size_t i = 0, guard = 0; b->count - first > 3 && i < b->count - first &&
                                  guard < 4 * (b->count - first); guard++) {
        size_t n = b->count - first, i1 = first + (i + 1) % n, i2 = first + (i + 2) % n;
        const double *a = b->uv + 2 * (first + i), *a1 = b->uv + 2 * i1;
        const double *c2 = b->uv + 2 * i2, *c3 = b->uv + 2 * (first + (i + 3) % n);
        double t;
        const double *a3 = n == 4 ? c3 : NULL;   /* segment i + 3 joins c3 back to a */
        if (!uv_cross(a, a1, c2, c3, &t) ||
            (a3 && hypot(a[0] - a3[0], a[1] - a3[1]) < hypot(c2[0] - a1[0], c2[1] - a1[1]))) {
            i++;
            continue;
        }
        b->uv[2 * i1] = a[0] + t * (a1[0] - a[0]);
        b->uv[2 * i1 + 1] = a[1] + t * (a1[1] - a[1]);
        sw_seam_qtree_point(c->qt, b->uv[2 * i1], b->uv[2 * i1 + 1], b->p + 3 * i1);
        b->gap[i1] = fmaxf(b->gap[i1], b->gap[i2]);
        b->edge[i1] = b->edge[i2];   /* its segment now runs on along i2's */
        b->pin[i1] = 1;
        drop_vertex(b, i2);
        if (i2 < i1)
            i = i > 0 ? i - 1 : 0;   /* the loop's start moved down by one */
    }
}

/* One loop: flattened (retried with forced halvings if it came out with
 * fewer than 3 vertices: a loop of one or two short curves), simplified. */
static sw_status one_loop(flat_ctx *c, const sw_nurbs_curve *curves, const double *gaps,
                          const uint32_t *edges, size_t count)
{
    size_t first = c->buf->count;
    sw_status st = SW_OK;
    for (c->min_depth = 0; st == SW_OK && c->min_depth <= 4; c->min_depth += 2) {
        c->buf->count = first;
        st = flatten_loop(c, curves, gaps, edges, count);
        if (c->buf->count - first >= 3)
            break;
    }
    c->min_depth = 0;
    if (st == SW_OK && c->buf->count - first < 3)
        return sw_error_set(c->err, SW_ERR_FORMAT,
                            "the loop has no extent in model space (%zu distinct points)",
                            c->buf->count - first);
    if (st == SW_OK)
        st = simplify_loop(c, first);
    if (st == SW_OK)
        unfold_loop(c, first);
    return st;
}

void sw_seam_polylines_free(sw_seam_polylines *poly)
{
    if (!poly)
        return;
    free(poly->uv);
    free(poly->p);
    free(poly->gap);
    free(poly->edge);
    free(poly->loop_start);
    free(poly->loop_surface);
    free(poly->loop_outer);
    free(poly->surface_loops);
    memset(poly, 0, sizeof *poly);
}

/* Room for one more loop record (loop_start keeps one extra entry). */
static sw_status reserve_loop(sw_seam_polylines *out, size_t *capacity, sw_error *err)
{
    if (out->loop_count + 1 < *capacity)
        return SW_OK;
    size_t cap = *capacity * 2 + 64;
    size_t *starts = realloc(out->loop_start, cap * sizeof *starts);
    if (starts)
        out->loop_start = starts;
    uint32_t *surf = starts ? realloc(out->loop_surface, cap * sizeof *surf) : NULL;
    if (surf)
        out->loop_surface = surf;
    uint8_t *outer = surf ? realloc(out->loop_outer, cap * sizeof *outer) : NULL;
    if (!outer)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "flattening trims: out of memory for loops");
    out->loop_outer = outer;
    *capacity = cap;
    return SW_OK;
}

/* Every loop of surface s (or its domain rectangle) into out. */
static sw_status flatten_surface(const sw_model *model, size_t s, flat_ctx *c,
                                 sw_seam_polylines *out, size_t *loop_capacity)
{
    const sw_model_surface *surf = &model->surfaces[s];
    size_t loops = surf->loop_count ? surf->loop_count : 1;
    rect_loop rect;
    rect_loop_make(&rect, c->qt->domain);
    sw_nurbs_curve views[64], *curves = views;
    double view_gaps[64], *gaps = view_gaps;
    uint32_t view_edges[64], *edges = view_edges;
    sw_status st = SW_OK;
    for (size_t l = 0; l < loops && st == SW_OK; l++) {
        const sw_model_loop *ml = surf->loop_count ? &model->loops[surf->first_loop + l] : NULL;
        size_t count = ml ? ml->curve_count : 4;
        if (ml && count > 64) {
            curves = malloc(count * sizeof *curves);
            gaps = malloc(count * sizeof *gaps);
            edges = malloc(count * sizeof *edges);
            if (!curves || !gaps || !edges) {
                free(curves);
                free(gaps);
                free(edges);
                return sw_error_set(c->err, SW_ERR_NO_MEMORY, "flattening trims: out of memory");
            }
        }
        for (size_t k = 0; ml && k < count; k++) {
            curves[k] = sw_model_curve_view(&model->curves[ml->first_curve + k]);
            gaps[k] = model->curves[ml->first_curve + k].gap;
            uint32_t e = model->curves[ml->first_curve + k].edge;
            edges[k] = e && c->part_edges ? c->part_edges[surf->part] + e : 0;
        }
        st = reserve_loop(out, loop_capacity, c->err);
        if (st == SW_OK)
            st = one_loop(c, ml ? curves : rect.curves, ml ? gaps : NULL, ml ? edges : NULL,
                          count);
        if (curves != views) {
            free(curves);
            free(gaps);
            free(edges);
        }
        curves = views, gaps = view_gaps, edges = view_edges;
        if (st != SW_OK) {
            sw_error_prefix(c->err, "loop %zu", l);
            break;
        }
        out->loop_surface[out->loop_count] = (uint32_t)s;
        out->loop_outer[out->loop_count] = (uint8_t)(ml ? ml->outer != 0 : 1);
        out->loop_start[++out->loop_count] = c->buf->count;
    }
    return st;
}

/* Per part, the number of shared-edge ids of the parts before it, so that
 * part p's edge e is part_edges[p] + e across the model (a part placed
 * twice is two parts); NULL when the model names none, or when they pass
 * 32 bits or memory runs out (then edges are not told apart). */
static uint32_t *model_edge_bases(const sw_model *model)
{
    size_t parts = model->part_count;
    for (size_t s = 0; s < model->surface_count; s++)
        parts = model->surfaces[s].part + 1 > parts ? model->surfaces[s].part + 1 : parts;
    uint32_t *base = calloc(parts + 1, sizeof *base);
    if (!base)
        return NULL;
    for (size_t s = 0; s < model->surface_count; s++) {
        const sw_model_surface *surf = &model->surfaces[s];
        for (size_t l = surf->first_loop; l < surf->first_loop + surf->loop_count; l++)
            for (size_t k = 0; k < model->loops[l].curve_count; k++) {
                uint32_t e = model->curves[model->loops[l].first_curve + k].edge;
                base[surf->part + 1] = e > base[surf->part + 1] ? e : base[surf->part + 1];
            }
    }
    /* each part's largest id, one place on: summed, the ids before each */
    uint64_t total = 0;
    for (size_t p = 0; p <= parts; p++) {
        total += base[p];
        base[p] = (uint32_t)(total < UINT32_MAX ? total : 0);
    }
    if (total == 0 || total >= UINT32_MAX) {
        free(base);
        return NULL;
    }
    return base;
}

sw_status sw_seam_flatten_model(const sw_model *model, double tolerance, sw_seam_polylines *out,
                                sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_flatten_model: out is NULL");
    memset(out, 0, sizeof *out);
    if (!model || !(tolerance > 0) || !isfinite(tolerance))
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_flatten_model: model is NULL or tolerance "
                                             "%g is not a positive number", tolerance);
    if (model->surface_count >= UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "%zu surfaces: too many", model->surface_count);
    vbuf buf = {0};
    size_t loop_capacity = 0;
    out->tolerance = tolerance;
    out->surface_count = model->surface_count;
    out->surface_loops = malloc((model->surface_count + 1) * sizeof *out->surface_loops);
    sw_status st = out->surface_loops ? reserve_loop(out, &loop_capacity, err)
                                      : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    if (st == SW_OK)
        out->loop_start[0] = 0;
    uint32_t *part_edges = st == SW_OK ? model_edge_bases(model) : NULL;
    flat_ctx c = {.tol = tolerance / 2, .part_edges = part_edges, .buf = &buf, .err = err};
    for (size_t s = 0; st == SW_OK && s < model->surface_count; s++) {
        out->surface_loops[s] = out->loop_count;
        sw_seam_qtree qt;
        sw_nurbs_surface view = sw_model_surface_view(&model->surfaces[s]);
        /* The paper's quad-tree criterion: flat within a third of the tolerance. */
        st = sw_seam_qtree_init(&qt, &view, tolerance / 3, err);
        c.qt = &qt;
        if (st == SW_OK)
            st = flatten_surface(model, s, &c, out, &loop_capacity);
        sw_seam_qtree_free(&qt);
        if (st != SW_OK)
            sw_error_prefix(err, "surface %zu", s);
    }
    free(buf.pin);
    free(part_edges);
    if (st != SW_OK) {
        free(buf.uv);
        free(buf.p);
        free(buf.gap);
        free(buf.edge);
        sw_seam_polylines_free(out);
        return st;
    }
    out->surface_loops[model->surface_count] = out->loop_count;
    out->uv = buf.uv, out->p = buf.p, out->gap = buf.gap, out->vertex_count = buf.count;
    out->edge = buf.edge;
    out->unproven = c.unproven;
    out->clamped = c.clamped;
    return SW_OK;
}
