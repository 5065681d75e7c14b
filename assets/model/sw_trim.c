/* SPDX-License-Identifier: MIT */
/* Trim polylines, point-in-face, box and mask classification (sw_trim.h).
 * The area integral is in sw_trim_area.c. */
#include "sw_trim.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Halvings of one Bezier piece before giving up: 2^-40 of a piece is far
 * below what any sane tolerance asks, and reaching it means the tolerance is
 * below the rounding of the coordinates (the chord test can never pass). */
enum { MAX_HALVINGS = 40 };

typedef struct emitter {
    double *out;
    size_t capacity, count;
} emitter;

static void emit(emitter *e, double u, double v)
{
    if (e->out && e->count < e->capacity) {
        e->out[2 * e->count] = u;
        e->out[2 * e->count + 1] = v;
    }
    e->count++;
}

/* Distance from p to the segment a-b (a point when a == b). */
static double point_segment_distance(const double p[2], const double a[2], const double b[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/* h: n + 1 homogeneous points (w u, w v, w). Flat when every Cartesian
 * control point is within tol of the chord: the piece lies in their convex
 * hull (positive weights), and the hull then lies within tol of the chord. */
static int piece_is_flat(const double h[][3], int n, double tol)
{
    double a[2] = {h[0][0] / h[0][2], h[0][1] / h[0][2]};
    double b[2] = {h[n][0] / h[n][2], h[n][1] / h[n][2]};
    for (int i = 1; i < n; i++) {
        double p[2] = {h[i][0] / h[i][2], h[i][1] / h[i][2]};
        if (!(point_segment_distance(p, a, b) <= tol))
            return 0;
    }
    return 1;
}

/* Emits the piece's end points after its start (already emitted), halving it
 * until flat. Returns 0 when MAX_HALVINGS is exceeded. */
static int flatten_piece(const double h[][3], int n, double tol, int depth, emitter *e)
{
    if (piece_is_flat(h, n, tol)) {
        emit(e, h[n][0] / h[n][2], h[n][1] / h[n][2]);
        return 1;
    }
    if (depth >= MAX_HALVINGS)
        return 0;
    double left[SW_BEZIER_MAX_ORDER][3], right[SW_BEZIER_MAX_ORDER][3];
    double work[SW_BEZIER_MAX_ORDER][3];
    memcpy(work, h, sizeof(double) * 3 * (size_t)(n + 1));
    for (int r = 0; r <= n; r++) {
        memcpy(left[r], work[0], sizeof left[r]);
        memcpy(right[n - r], work[n - r], sizeof right[0]);
        for (int i = 0; i < n - r; i++)
            for (int k = 0; k < 3; k++)
                work[i][k] = 0.5 * (work[i][k] + work[i + 1][k]);
    }
    return flatten_piece((const double(*)[3])left, n, tol, depth + 1, e) &&
           flatten_piece((const double(*)[3])right, n, tol, depth + 1, e);
}

sw_status sw_trim_flatten_curve(const sw_nurbs_curve *curve, double tolerance, double *points_out,
                                size_t capacity, size_t *count_out, sw_error *err)
{
    if (!curve || !count_out || !(tolerance > 0) || !isfinite(tolerance))
        return sw_error_set(err, SW_ERR_ARG, "sw_trim_flatten_curve: bad argument");
    sw_status st = sw_nurbs_curve_check(curve, err);
    if (st != SW_OK)
        return st;
    sw_nurbs_bezier_sizes sizes = sw_nurbs_curve_bezier_sizes(curve);
    double *ctrl = malloc(sizes.ctrl_doubles * sizeof *ctrl);
    double *params = malloc(sizes.param_doubles * sizeof *params);
    if (!ctrl || !params) {
        free(ctrl);
        free(params);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory flattening a trim curve");
    }
    st = sw_nurbs_curve_to_bezier(curve, ctrl, params, err);
    emitter e = {points_out, capacity, 0};
    int n = curve->degree;
    for (int p = 0; st == SW_OK && p < sizes.pieces_u; p++) {
        double h[SW_BEZIER_MAX_ORDER][3];
        for (int i = 0; i <= n; i++) {
            const double *c = ctrl + ((size_t)p * (size_t)(n + 1) + (size_t)i) * 4;
            h[i][0] = c[0] * c[3], h[i][1] = c[1] * c[3], h[i][2] = c[3];
        }
        if (p == 0)
            emit(&e, curve->ctrl[0], curve->ctrl[1]); /* exact: clamped start */
        if (!flatten_piece((const double(*)[3])h, n, tolerance, 0, &e))
            st = sw_error_set(err, SW_ERR_RANGE,
                              "trim curve piece %d cannot be flattened to %g: below the "
                              "precision of its coordinates", p, tolerance);
    }
    free(ctrl);
    free(params);
    *count_out = e.count;
    if (st == SW_OK && points_out && e.count > capacity)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "polyline needs %zu points, room for %zu",
                            e.count, capacity);
    return st;
}

void sw_trim_polyline_free(sw_trim_polyline *poly)
{
    if (!poly)
        return;
    free(poly->points);
    free(poly->loop_start);
    free(poly->chunks);
    memset(poly, 0, sizeof *poly);
}

/* First and last point of a curve (its end control points: clamped knots). */
static void curve_end(const sw_nurbs_curve *c, int last, double out[2])
{
    const double *p = c->ctrl + (last ? (size_t)(c->count - 1) * 4 : 0);
    out[0] = p[0];
    out[1] = p[1];
}

static sw_status check_closed(const sw_model_loop_input *loop, size_t l, double gap, sw_error *err)
{
    for (size_t c = 0; gap >= 0 && c < loop->curve_count; c++) {
        double end[2], start[2];
        curve_end(&loop->curves[c], 1, end);
        curve_end(&loop->curves[(c + 1) % loop->curve_count], 0, start);
        double d = hypot(end[0] - start[0], end[1] - start[1]);
        if (!(d <= gap))
            return sw_error_set(err, SW_ERR_FORMAT,
                                "trim loop %zu: curve %zu ends %g from the start of the next "
                                "(allowed %g): the loop is not closed", l, c, d, gap);
    }
    return SW_OK;
}

/* Appends one loop's vertices to the growing buffer at *pts. */
static sw_status flatten_loop(const sw_model_loop_input *loop, size_t l, double tol, double **pts,
                              size_t *count, size_t *capacity, sw_error *err)
{
    size_t loop_first = *count;
    for (size_t c = 0; c < loop->curve_count; c++) {
        size_t need = 0;
        sw_status st = sw_trim_flatten_curve(&loop->curves[c], tol, NULL, 0, &need, err);
        if (st != SW_OK) {
            sw_error_prefix(err, "trim loop %zu, curve %zu", l, c);
            return st;
        }
        if (*count + need > *capacity) {
            size_t wanted = (*count + need) * 2;
            double *bigger = realloc(*pts, wanted * 2 * sizeof **pts);
            if (!bigger)
                return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory flattening trims");
            *pts = bigger;
            *capacity = wanted;
        }
        st = sw_trim_flatten_curve(&loop->curves[c], tol, *pts + 2 * *count, need, &need, err);
        if (st != SW_OK)
            return st;
        /* The next curve starts where this one ended (within the gap): one vertex. */
        size_t skip = c > 0 ? 1 : 0;
        memmove(*pts + 2 * *count, *pts + 2 * (*count + skip), 2 * (need - skip) * sizeof **pts);
        *count += need - skip;
    }
    double *first = *pts + 2 * loop_first, *last = *pts + 2 * (*count - 1);
    if (*count - loop_first > 1 && first[0] == last[0] && first[1] == last[1])
        (*count)--;
    return SW_OK;
}

static const double *edge_end(const sw_trim_polyline *poly, const sw_trim_chunk *c, size_t k)
{
    return poly->points + 2 * (k + 1 < c->loop_end ? k + 1 : c->loop_first);
}

static sw_status build_chunks(sw_trim_polyline *poly, sw_error *err)
{
    size_t n = 0;
    for (size_t l = 0; l < poly->loop_count; l++) {
        size_t edges = poly->loop_start[l + 1] - poly->loop_start[l];
        n += (edges + SW_TRIM_CHUNK_EDGES - 1) / SW_TRIM_CHUNK_EDGES;
    }
    poly->chunks = malloc((n + 1) * sizeof *poly->chunks);
    if (!poly->chunks)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for trim chunks");
    for (size_t l = 0; l < poly->loop_count; l++) {
        size_t s = poly->loop_start[l], e = poly->loop_start[l + 1];
        for (size_t k = s; k < e; k += SW_TRIM_CHUNK_EDGES) {
            sw_trim_chunk *c = &poly->chunks[poly->chunk_count++];
            *c = (sw_trim_chunk){k, k + SW_TRIM_CHUNK_EDGES < e ? k + SW_TRIM_CHUNK_EDGES : e, s, e,
                                 {INFINITY, -INFINITY, INFINITY, -INFINITY}};
            for (size_t j = c->first; j <= c->end; j++) {
                const double *p = j < c->end ? poly->points + 2 * j : edge_end(poly, c, j - 1);
                c->box[0] = p[0] < c->box[0] ? p[0] : c->box[0];
                c->box[1] = p[0] > c->box[1] ? p[0] : c->box[1];
                c->box[2] = p[1] < c->box[2] ? p[1] : c->box[2];
                c->box[3] = p[1] > c->box[3] ? p[1] : c->box[3];
            }
        }
    }
    return SW_OK;
}

static void polyline_box(sw_trim_polyline *poly, size_t count)
{
    double b[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (size_t k = 0; k < count; k++) {
        b[0] = fmin(b[0], poly->points[2 * k]);
        b[1] = fmax(b[1], poly->points[2 * k]);
        b[2] = fmin(b[2], poly->points[2 * k + 1]);
        b[3] = fmax(b[3], poly->points[2 * k + 1]);
    }
    poly->box[0] = b[0] - poly->tolerance;
    poly->box[1] = b[1] + poly->tolerance;
    poly->box[2] = b[2] - poly->tolerance;
    poly->box[3] = b[3] + poly->tolerance;
}

sw_status sw_trim_polyline_build(const sw_model_loop_input *loops, size_t loop_count,
                                 double tolerance, double gap, sw_trim_polyline *out,
                                 sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "sw_trim_polyline_build: out is NULL");
    memset(out, 0, sizeof *out);
    if ((loop_count && !loops) || !(tolerance > 0) || !isfinite(tolerance))
        return sw_error_set(err, SW_ERR_ARG, "sw_trim_polyline_build: bad argument");
    out->tolerance = tolerance;
    out->loop_start = malloc((loop_count + 1) * sizeof *out->loop_start);
    if (!out->loop_start)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for trim loops");
    size_t count = 0, capacity = 0;
    sw_status st = SW_OK;
    for (size_t l = 0; l < loop_count && st == SW_OK; l++) {
        out->loop_start[l] = count;
        if (loops[l].curve_count == 0 || !loops[l].curves)
            st = sw_error_set(err, SW_ERR_FORMAT, "trim loop %zu has no curves", l);
        if (st == SW_OK)
            st = flatten_loop(&loops[l], l, tolerance, &out->points, &count, &capacity, err);
        if (st == SW_OK)
            st = check_closed(&loops[l], l, gap, err);
    }
    if (st != SW_OK) {
        sw_trim_polyline_free(out);
        return st;
    }
    out->loop_start[loop_count] = count;
    out->loop_count = loop_count;
    polyline_box(out, count);
    st = build_chunks(out, err);
    if (st != SW_OK)
        sw_trim_polyline_free(out);
    return st;
}

/* Runs body on every edge of every loop, the closing edges included, of the
 * chunks whose box passes keep (an expression of the chunk's box cb). */
#define FOR_EACH_EDGE_KEPT(poly, cb, keep, a, b, body)                                      \
    for (size_t c_ = 0; c_ < (poly)->chunk_count; c_++) {                                   \
        const sw_trim_chunk *ch_ = &(poly)->chunks[c_];                                      \
        const double *cb = ch_->box;                                                         \
        if (!(keep))                                                                         \
            continue;                                                                        \
        for (size_t k_ = ch_->first; k_ < ch_->end; k_++) {                                  \
            const double *a = (poly)->points + 2 * k_;                                       \
            const double *b = edge_end(poly, ch_, k_);                                       \
            body                                                                             \
        }                                                                                    \
    }
#define FOR_EACH_EDGE(poly, a, b, body) FOR_EACH_EDGE_KEPT(poly, cb_, ((void)cb_, 1), a, b, body)

int sw_trim_point_inside(const sw_trim_polyline *poly, double u, double v)
{
    int inside = 0;
    /* Crossing number with a ray towards +u; an edge counts when one end is
     * above v and the other not (half-open, so vertices on the ray count once).
     * A chunk wholly above v, wholly at or below it, or wholly left of u has
     * no edge that counts. */
    FOR_EACH_EDGE_KEPT(poly, cb, cb[2] <= v && cb[3] > v && cb[1] >= u, a, b, {
        if ((a[1] > v) != (b[1] > v)) {
            double x = a[0] + (v - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if (u < x)
                inside ^= 1;
        }
    })
    return inside;
}

/* Conservative segment-box overlap: boxes overlap and the box's corners are
 * not all strictly on one side of the segment's line. */
static int segment_hits_box(const double a[2], const double b[2], const double box[4])
{
    /* Plain comparisons rather than fmin/fmax: they are libm calls here. */
    if ((a[0] < box[0] && b[0] < box[0]) || (a[0] > box[1] && b[0] > box[1]) ||
        (a[1] < box[2] && b[1] < box[2]) || (a[1] > box[3] && b[1] > box[3]))
        return 0;
    double dx = b[0] - a[0], dy = b[1] - a[1];
    int pos = 0, neg = 0;
    for (int c = 0; c < 4; c++) {
        double x = box[c & 1], y = box[2 + (c >> 1)];
        double s = dx * (y - a[1]) - dy * (x - a[0]);
        pos |= s >= 0;
        neg |= s <= 0;
    }
    return pos && neg;
}

sw_trim_coverage sw_trim_box_classify(const sw_trim_polyline *poly, const double box[4])
{
    double t = poly->tolerance;
    double grown[4] = {box[0] - t, box[1] + t, box[2] - t, box[3] + t};
    FOR_EACH_EDGE_KEPT(poly, cb, cb[1] >= grown[0] && cb[0] <= grown[1] && cb[3] >= grown[2] &&
                                     cb[2] <= grown[3], a, b, {
        if (segment_hits_box(a, b, grown))
            return SW_TRIM_PARTIAL;
    })
    /* No trim within tolerance: the box is wholly in or wholly out. */
    return sw_trim_point_inside(poly, 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]))
               ? SW_TRIM_INSIDE
               : SW_TRIM_OUTSIDE;
}

int sw_trim_box_touches(const sw_trim_polyline *poly, const double box[4])
{
    return sw_trim_box_classify(poly, box) != SW_TRIM_OUTSIDE;
}

/* Sets the cells of rows that the edge's tolerance band may touch. */
static void mark_edge(const double a[2], const double b[2], const double domain[4], double tol,
                      uint32_t rows[32])
{
    double w = (domain[1] - domain[0]) / 32, h = (domain[3] - domain[2]) / 32;
    double i0 = floor((fmin(a[0], b[0]) - tol - domain[0]) / w);
    double i1 = floor((fmax(a[0], b[0]) + tol - domain[0]) / w);
    double j0 = floor((fmin(a[1], b[1]) - tol - domain[2]) / h);
    double j1 = floor((fmax(a[1], b[1]) + tol - domain[2]) / h);
    if (i1 < 0 || j1 < 0 || i0 > 31 || j0 > 31)
        return;
    int ilo = i0 < 0 ? 0 : (int)i0, ihi = i1 > 31 ? 31 : (int)i1;
    int jlo = j0 < 0 ? 0 : (int)j0, jhi = j1 > 31 ? 31 : (int)j1;
    for (int j = jlo; j <= jhi; j++) {
        for (int i = ilo; i <= ihi; i++) {
            double cell[4] = {domain[0] + i * w - tol, domain[0] + (i + 1) * w + tol,
                              domain[2] + j * h - tol, domain[2] + (j + 1) * h + tol};
            if (segment_hits_box(a, b, cell))
                rows[j] |= 1u << i;
        }
    }
}

/* Toggles, in row j's parity, every cell centre left of where edge a-b
 * crosses the row's centre line (the crossing rule of sw_trim_point_inside,
 * for 32 centres at once). Only the rows the edge spans are visited. */
static void toggle_rows(const double a[2], const double b[2], const double domain[4],
                        uint32_t parity[32])
{
    double w = (domain[1] - domain[0]) / 32, h = (domain[3] - domain[2]) / 32;
    double lo = (fmin(a[1], b[1]) - domain[2]) / h - 0.5;
    double hi = (fmax(a[1], b[1]) - domain[2]) / h - 0.5;
    if (hi < -1 || lo > 32)
        return;
    int j0 = lo < 0 ? 0 : (int)lo, j1 = hi > 31 ? 31 : (int)ceil(hi);
    for (int j = j0; j <= j1; j++) {
        double v = domain[2] + (j + 0.5) * h;
        if ((a[1] > v) == (b[1] > v))
            continue;
        double x = a[0] + (v - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
        double t = ceil((x - domain[0]) / w - 0.5);
        int k = t < 0 ? 0 : t > 32 ? 32 : (int)t;
        parity[j] ^= k == 32 ? 0xFFFFFFFFu : (1u << k) - 1u;
    }
}

sw_trim_coverage sw_trim_mask(const sw_trim_polyline *poly, const double domain[4],
                              uint32_t rows[32])
{
    uint32_t band[32] = {0};
    memset(rows, 0, 32 * sizeof *rows);
    FOR_EACH_EDGE(poly, a, b, {
        mark_edge(a, b, domain, poly->tolerance, band);
        toggle_rows(a, b, domain, rows);
    })
    uint32_t any_band = 0, all_inside = 0xFFFFFFFFu, any = 0;
    for (int j = 0; j < 32; j++) {
        any_band |= band[j];
        all_inside &= rows[j];
        rows[j] |= band[j];
        any |= rows[j];
    }
    if (!any)
        return SW_TRIM_OUTSIDE;
    return !any_band && all_inside == 0xFFFFFFFFu ? SW_TRIM_INSIDE : SW_TRIM_PARTIAL;
}
