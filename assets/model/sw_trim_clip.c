/* SPDX-License-Identifier: MIT */
/* Trimming loops cut along a parameter line (sw_trim_clip.h).
 *
 * Every curve is split where it crosses the line, so each crossed loop
 * becomes arcs that run from one crossing to the next, each on one side.
 * Along the line the crossings, sorted, bound the region's inside in pairs
 * (first and second, third and fourth: the loops bound it by the even-odd
 * rule); each side's loops follow an arc to its end, the line to the end's
 * partner, and the arc of the same side that starts there. With outer
 * loops counter-clockwise and holes clockwise that arc always exists; when
 * it does not, the loops were not a region (they cross) and the cut is
 * refused. */
#include "sw_trim_clip.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"

/* Samples a knot span when looking for crossings; halvings that place one. */
enum { SAMPLES_PER_SPAN = 16, BISECTIONS = 80 };

void sw_trim_set_free(sw_trim_set *set)
{
    for (size_t i = 0; i < set->curve_count; i++) {
        free(set->curves[i].knots);
        free(set->curves[i].ctrl);
    }
    free(set->curves);
    free(set->loops);
    memset(set, 0, sizeof *set);
}

static sw_status oom(sw_error *err)
{
    return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory cutting trimming loops");
}

/* Appends c, taking its arrays (freed here when the append fails). */
static sw_status push_curve(sw_trim_set *s, sw_model_trim_curve c, sw_error *err)
{
    sw_model_trim_curve *grown = sw_grow(s->curves, &s->curve_capacity, s->curve_count + 1,
                                         sizeof *grown);
    if (!grown) {
        free(c.knots);
        free(c.ctrl);
        return oom(err);
    }
    s->curves = grown;
    s->curves[s->curve_count++] = c;
    return SW_OK;
}

static sw_status push_loop(sw_trim_set *s, size_t first, int outer, sw_error *err)
{
    sw_model_loop *grown = sw_grow(s->loops, &s->loop_capacity, s->loop_count + 1, sizeof *grown);
    if (!grown)
        return oom(err);
    s->loops = grown;
    s->loops[s->loop_count++] = (sw_model_loop){first, s->curve_count - first, outer};
    return SW_OK;
}

static sw_status copy_curve(const sw_model_trim_curve *c, sw_model_trim_curve *out,
                            sw_error *err)
{
    size_t knots = (size_t)c->count + (size_t)c->degree + 1;
    *out = *c;
    out->knots = malloc(knots * sizeof *out->knots);
    out->ctrl = malloc((size_t)c->count * 4 * sizeof *out->ctrl);
    if (!out->knots || !out->ctrl) {
        free(out->knots);
        free(out->ctrl);
        return oom(err);
    }
    memcpy(out->knots, c->knots, knots * sizeof *out->knots);
    memcpy(out->ctrl, c->ctrl, (size_t)c->count * 4 * sizeof *out->ctrl);
    return SW_OK;
}

/* The straight line a-b: the cut, where it closes a loop. */
static sw_status line_curve(const double a[2], const double b[2], sw_model_trim_curve *out,
                            sw_error *err)
{
    const double knots[4] = {0, 0, 1, 1};
    const double ctrl[8] = {a[0], a[1], 0, 1, b[0], b[1], 0, 1};
    const sw_model_trim_curve line = {1, 2, (double *)knots, (double *)ctrl, 0, 0.0, 0};
    return copy_curve(&line, out, err);
}

static double t_start(const sw_model_trim_curve *c) { return c->knots[c->degree]; }
static double t_end(const sw_model_trim_curve *c) { return c->knots[c->count]; }

static void curve_uv(const sw_model_trim_curve *c, double t, double uv[2])
{
    sw_nurbs_curve view = sw_model_curve_view(c);
    sw_vec3 p = sw_nurbs_curve_point(&view, t);
    uv[0] = p.x, uv[1] = p.y;
}

static void reverse_curve(sw_model_trim_curve *c)
{
    size_t n = (size_t)c->count + (size_t)c->degree + 1;
    double t0 = c->knots[0], t1 = c->knots[n - 1];
    for (size_t i = 0; i < n / 2; i++) {
        double a = c->knots[i];
        c->knots[i] = t0 + t1 - c->knots[n - 1 - i];
        c->knots[n - 1 - i] = t0 + t1 - a;
    }
    if (n % 2)
        c->knots[n / 2] = t0 + t1 - c->knots[n / 2];
    for (int i = 0; i < c->count / 2; i++)
        for (int k = 0; k < 4; k++) {
            double a = c->ctrl[4 * i + k];
            c->ctrl[4 * i + k] = c->ctrl[4 * (c->count - 1 - i) + k];
            c->ctrl[4 * (c->count - 1 - i) + k] = a;
        }
}

/* Twice the signed area of a loop of set s, from its curves sampled. */
static double loop_area(const sw_trim_set *s, const sw_model_loop *l)
{
    double area = 0, first[2] = {0, 0}, prev[2] = {0, 0};
    int started = 0;
    for (size_t i = 0; i < l->curve_count; i++) {
        const sw_model_trim_curve *c = &s->curves[l->first_curve + i];
        int samples = SAMPLES_PER_SPAN * (c->count - c->degree);
        for (int k = 0; k < samples; k++) {
            double uv[2];
            curve_uv(c, t_start(c) + (t_end(c) - t_start(c)) * k / samples, uv);
            if (started)
                area += prev[0] * uv[1] - uv[0] * prev[1];
            else
                memcpy(first, uv, sizeof first), started = 1;
            memcpy(prev, uv, sizeof prev);
        }
    }
    return area + prev[0] * first[1] - first[0] * prev[1];
}

sw_status sw_trim_set_of_surface(const sw_model *model, size_t surface, sw_trim_set *out,
                                 sw_error *err)
{
    const sw_model_surface *s = &model->surfaces[surface];
    sw_status st = SW_OK;
    if (s->loop_count == 0) {
        const double *d = s->domain;
        const double corner[4][2] = {{d[0], d[2]}, {d[1], d[2]}, {d[1], d[3]}, {d[0], d[3]}};
        for (int i = 0; st == SW_OK && i < 4; i++) {
            sw_model_trim_curve c;
            st = line_curve(corner[i], corner[(i + 1) % 4], &c, err);
            if (st == SW_OK)
                st = push_curve(out, c, err);
        }
        return st == SW_OK ? push_loop(out, 0, 1, err) : st;
    }
    for (size_t l = 0; st == SW_OK && l < s->loop_count; l++) {
        const sw_model_loop *loop = &model->loops[s->first_loop + l];
        size_t first = out->curve_count;
        for (size_t i = 0; st == SW_OK && i < loop->curve_count; i++) {
            sw_model_trim_curve c;
            st = copy_curve(&model->curves[loop->first_curve + i], &c, err);
            if (st == SW_OK)
                st = push_curve(out, c, err);
        }
        if (st == SW_OK)
            st = push_loop(out, first, loop->outer, err);
    }
    return st;
}

/* ---- splitting a curve at a parameter ---------------------------------- */

/* One knot inserted at t: (knots, h) with n points (homogeneous u w, v w,
 * w) into (k2, h2) with n + 1 (Boehm). */
static void insert_once(int p, int n, const double *knots, const double *h, double t, double *k2,
                        double *h2)
{
    int k = p;
    while (k + 1 < n && knots[k + 1] <= t)
        k++;
    for (int i = 0; i <= n; i++) {
        for (int a = 0; a < 3; a++) {
            if (i <= k - p) {
                h2[3 * i + a] = h[3 * i + a];
            } else if (i <= k) {
                double alpha = (t - knots[i]) / (knots[i + p] - knots[i]);
                h2[3 * i + a] = alpha * h[3 * i + a] + (1 - alpha) * h[3 * (i - 1) + a];
            } else {
                h2[3 * i + a] = h[3 * (i - 1) + a];
            }
        }
    }
    memcpy(k2, knots, (size_t)(k + 1) * sizeof *k2);
    k2[k + 1] = t;
    memcpy(k2 + k + 2, knots + k + 1, (size_t)(n + p - k) * sizeof *k2);
}

/* The piece of a curve given by homogeneous points h[first .. first +
 * count) and the knots from knots[k0] on, as Cartesian + w. */
static sw_status make_piece(const sw_model_trim_curve *c, const double *h, int first, int count,
                            const double *knots, sw_model_trim_curve *out, sw_error *err)
{
    sw_model_trim_curve piece = {c->degree, count, (double *)knots, NULL, c->computed, c->gap,
                                 c->edge};
    double *ctrl = malloc((size_t)count * 4 * sizeof *ctrl);
    if (!ctrl)
        return oom(err);
    for (int i = 0; i < count; i++) {
        const double *q = h + 3 * (first + i);
        ctrl[4 * i] = q[0] / q[2], ctrl[4 * i + 1] = q[1] / q[2];
        ctrl[4 * i + 2] = 0, ctrl[4 * i + 3] = q[2];
    }
    piece.ctrl = ctrl;
    sw_status st = copy_curve(&piece, out, err);
    free(ctrl);
    return st;
}

/* c split at t (strictly inside it) into a (before) and b (after). */
static sw_status split_curve(const sw_model_trim_curve *c, double t, sw_model_trim_curve *a,
                             sw_model_trim_curve *b, sw_error *err)
{
    int p = c->degree, n = c->count, have = 0;
    for (int i = 0; i < n + p + 1; i++)
        have += c->knots[i] == t;
    if (have > p)
        return sw_error_set(err, SW_ERR_RANGE, "trim cut: a curve breaks at the cut");
    int r = p - have, cap = n + r;
    double *knots = malloc((size_t)(cap + p + 1) * 2 * sizeof *knots);
    double *h = malloc((size_t)cap * 3 * 2 * sizeof *h);
    if (!knots || !h) {
        free(knots);
        free(h);
        return oom(err);
    }
    double *k_tmp = knots + cap + p + 1, *h_tmp = h + 3 * cap;
    memcpy(knots, c->knots, (size_t)(n + p + 1) * sizeof *knots);
    for (int i = 0; i < n; i++)
        h[3 * i] = c->ctrl[4 * i] * c->ctrl[4 * i + 3],
        h[3 * i + 1] = c->ctrl[4 * i + 1] * c->ctrl[4 * i + 3], h[3 * i + 2] = c->ctrl[4 * i + 3];
    for (int i = 0; i < r; i++, n++) {
        insert_once(p, n, knots, h, t, k_tmp, h_tmp);
        memcpy(knots, k_tmp, (size_t)(n + p + 2) * sizeof *knots);
        memcpy(h, h_tmp, (size_t)(n + 1) * 3 * sizeof *h);
    }
    int j = 0;   /* the first of the p knots at t; the point at t is h[j - 1] */
    while (knots[j] < t)
        j++;
    /* a: points 0 .. j - 1, knots 0 .. j + p - 1 and t once more */
    memcpy(k_tmp, knots, (size_t)(j + p) * sizeof *k_tmp);
    k_tmp[j + p] = t;
    sw_status st = make_piece(c, h, 0, j, k_tmp, a, err);
    /* b: points j - 1 .. n - 1, knots t and then j .. n + p */
    k_tmp[0] = t;
    memcpy(k_tmp + 1, knots + j, (size_t)(n + p + 1 - j) * sizeof *k_tmp);
    if (st == SW_OK && (st = make_piece(c, h, j - 1, n - j + 1, k_tmp, b, err)) != SW_OK) {
        free(a->knots);
        free(a->ctrl);
    }
    free(knots);
    free(h);
    return st;
}

/* ---- the cut ------------------------------------------------------------ */

typedef struct piece {
    sw_model_trim_curve curve; /* owned */
    int side;                  /* 0: below the line, 1: above */
    long crossing;             /* at its end, or -1 */
    int outer;                 /* of an outer loop */
    size_t next;               /* the next piece of its loop */
} piece;

typedef struct crossing {
    double along, uv[2];       /* along: the other coordinate */
    size_t ends, starts;       /* the arcs (by first piece) ending and starting here */
    size_t partner;
} crossing;

typedef struct cutter {
    int axis;
    double at, tol;
    piece *pieces;
    size_t piece_count, piece_capacity;
    crossing *crossings;
    size_t crossing_count, crossing_capacity;
    sw_error *err;
} cutter;

static sw_status add_piece(cutter *k, sw_model_trim_curve c, int outer, sw_error *err)
{
    piece *grown = sw_grow(k->pieces, &k->piece_capacity, k->piece_count + 1, sizeof *grown);
    if (!grown) {
        free(c.knots);
        free(c.ctrl);
        return oom(err);
    }
    k->pieces = grown;
    double uv[2];
    curve_uv(&c, 0.5 * (t_start(&c) + t_end(&c)), uv);
    k->pieces[k->piece_count++] = (piece){c, uv[k->axis] > k->at, -1, outer, 0};
    return SW_OK;
}

static sw_status add_crossing(cutter *k, const sw_model_trim_curve *c, double t, sw_error *err)
{
    crossing *grown = sw_grow(k->crossings, &k->crossing_capacity, k->crossing_count + 1,
                              sizeof *grown);
    if (!grown)
        return oom(err);
    k->crossings = grown;
    crossing *x = &k->crossings[k->crossing_count];
    curve_uv(c, t, x->uv);
    x->uv[k->axis] = k->at;
    x->along = x->uv[1 - k->axis];
    k->pieces[k->piece_count - 1].crossing = (long)k->crossing_count++;
    return SW_OK;
}

/* Coordinate axis of c at t, less the line's. */
static double coord(const cutter *k, const sw_model_trim_curve *c, double t)
{
    double uv[2];
    curve_uv(c, t, uv);
    return uv[k->axis] - k->at;
}

/* Where c crosses the line, ascending, into ts (at most cap); SW_ERR_RANGE
 * where it comes within tol of the line without a clean crossing. */
static sw_status find_crossings(const cutter *k, const sw_model_trim_curve *c, double *ts,
                                int cap, int *count, sw_error *err)
{
    *count = 0;
    double prev_t = 0, prev_f = 0;
    for (int span = c->degree; span < c->count; span++) {
        double t0 = c->knots[span], t1 = c->knots[span + 1];
        if (!(t1 > t0))
            continue;
        for (int s = span == c->degree ? 0 : 1; s <= SAMPLES_PER_SPAN; s++) {
            double t = t0 + (t1 - t0) * s / SAMPLES_PER_SPAN;
            double f = coord(k, c, t);
            if (fabs(f) <= k->tol) {
                /* On the line: a crossing only where the curve passes from
                 * one side to the other there (sampled just after it) */
                double h = (t1 - t0) / (SAMPLES_PER_SPAN * 64.0);
                int end = (span == c->degree && s == 0) ||
                          (span + 1 == c->count && s == SAMPLES_PER_SPAN);
                double before = end ? 0 : coord(k, c, t - h), after = end ? 0 : coord(k, c, t + h);
                if (end || fabs(before) <= k->tol || fabs(after) <= k->tol ||
                    (before > 0) == (after > 0))
                    return sw_error_set(err, SW_ERR_RANGE, "trim cut: a curve %s the cut at %g",
                                        end ? "ends on" : "touches", k->at);
                t += h, f = after;
            }
            if (!(span == c->degree && s == 0) && (f > 0) != (prev_f > 0)) {
                if (*count == cap)
                    return sw_error_set(err, SW_ERR_RANGE, "trim cut: a curve crosses the cut "
                                        "more than %d times", cap);
                double lo = prev_t, hi = t;
                for (int b = 0; b < BISECTIONS && hi - lo > 0; b++) {
                    double mid = 0.5 * (lo + hi);
                    if ((coord(k, c, mid) > 0) == (prev_f > 0))
                        lo = mid;
                    else
                        hi = mid;
                }
                ts[(*count)++] = 0.5 * (lo + hi);
            }
            prev_t = t, prev_f = f;
        }
    }
    return SW_OK;
}

enum { MAX_CROSSINGS_A_CURVE = 64 };

/* One curve into pieces at its crossings. */
static sw_status cut_curve(cutter *k, const sw_model_trim_curve *c, int outer, sw_error *err)
{
    double ts[MAX_CROSSINGS_A_CURVE];
    int count = 0;
    sw_status st = find_crossings(k, c, ts, MAX_CROSSINGS_A_CURVE, &count, err);
    sw_model_trim_curve rest;
    if (st == SW_OK)
        st = copy_curve(c, &rest, err);
    for (int i = 0; st == SW_OK && i < count; i++) {
        sw_model_trim_curve a, b;
        st = split_curve(&rest, ts[i], &a, &b, err);
        free(rest.knots);
        free(rest.ctrl);
        if (st != SW_OK)
            return st;
        rest = b;
        if ((st = add_piece(k, a, outer, err)) == SW_OK)
            st = add_crossing(k, &a, t_end(&a), err);
        if (st != SW_OK) {
            free(rest.knots);
            free(rest.ctrl);
        }
    }
    return st == SW_OK ? add_piece(k, rest, outer, err) : st;
}

/* Loop l of in, oriented (outer counter-clockwise, holes clockwise), cut
 * into pieces. */
static sw_status cut_loop(cutter *k, const sw_trim_set *in, const sw_model_loop *l, sw_error *err)
{
    int flip = (loop_area(in, l) < 0) == (l->outer != 0);
    sw_status st = SW_OK;
    for (size_t i = 0; st == SW_OK && i < l->curve_count; i++) {
        const sw_model_trim_curve *c = &in->curves[l->first_curve +
                                                   (flip ? l->curve_count - 1 - i : i)];
        if (!flip) {
            st = cut_curve(k, c, l->outer, err);
            continue;
        }
        sw_model_trim_curve r;
        if ((st = copy_curve(c, &r, err)) != SW_OK)
            break;
        reverse_curve(&r);
        st = cut_curve(k, &r, l->outer, err);
        free(r.knots);
        free(r.ctrl);
    }
    return st;
}

static size_t next_in(size_t i, size_t first, size_t end)
{
    return i + 1 < end ? i + 1 : first;
}

/* The arcs of the loop whose pieces are [first, end): where each starts
 * and ends, and that each keeps to one side. */
static sw_status link_arcs(cutter *k, size_t first, size_t end, sw_error *err)
{
    for (size_t i = first; i < end; i++) {
        k->pieces[i].next = next_in(i, first, end);
        if (k->pieces[i].crossing >= 0)
            k->crossings[k->pieces[i].crossing].starts = k->pieces[i].next;
    }
    for (size_t i = first; i < end; i++) {
        if (k->pieces[i].crossing < 0)
            continue;
        size_t s = k->crossings[k->pieces[i].crossing].starts, j = s;
        while (k->pieces[j].crossing < 0) {
            if (k->pieces[j].side != k->pieces[s].side)
                return sw_error_set(err, SW_ERR_RANGE, "trim cut: a curve meets the cut at %g "
                                    "without crossing it", k->at);
            j = next_in(j, first, end);
        }
        if (k->pieces[j].side != k->pieces[s].side)
            return sw_error_set(err, SW_ERR_RANGE, "trim cut: a curve meets the cut at %g "
                                "without crossing it", k->at);
        k->crossings[k->pieces[j].crossing].ends = s;
    }
    return SW_OK;
}

typedef struct along_index {
    double along;
    size_t index;
} along_index;

static int by_along(const void *a, const void *b)
{
    double p = ((const along_index *)a)->along, q = ((const along_index *)b)->along;
    return (p > q) - (p < q);
}

/* Sorts the crossings along the line and pairs them, first with second. */
static sw_status pair_crossings(cutter *k, sw_error *err)
{
    size_t n = k->crossing_count;
    if (n % 2)
        return sw_error_set(err, SW_ERR_RANGE, "trim cut: %zu crossings of the cut at %g, "
                            "expected an even count", n, k->at);
    along_index *order = malloc((n + 1) * sizeof *order);
    if (!order)
        return oom(err);
    for (size_t i = 0; i < n; i++)
        order[i] = (along_index){k->crossings[i].along, i};
    qsort(order, n, sizeof *order, by_along);
    sw_status st = SW_OK;
    for (size_t i = 0; i + 1 < n && st == SW_OK; i += 2) {
        crossing *a = &k->crossings[order[i].index], *b = &k->crossings[order[i + 1].index];
        if (b->along - a->along <= k->tol || (i + 2 < n && order[i + 2].along - b->along <= k->tol))
            st = sw_error_set(err, SW_ERR_RANGE, "trim cut: two crossings of the cut at %g "
                              "within %g", k->at, k->tol);
        a->partner = order[i + 1].index, b->partner = order[i].index;
    }
    free(order);
    return st;
}

/* Side side's loops through the crossings into out. */
static sw_status join_side(cutter *k, int side, uint8_t *used, sw_trim_set *out, sw_error *err)
{
    sw_status st = SW_OK;
    for (size_t x = 0; st == SW_OK && x < k->crossing_count; x++) {
        size_t start = k->crossings[x].starts;
        if (used[start] || k->pieces[start].side != side)
            continue;
        size_t first = out->curve_count, cur = start;
        int outer = 0;
        for (size_t steps = 0; st == SW_OK; steps++) {
            if (steps > k->crossing_count || used[cur])
                return sw_error_set(err, SW_ERR_RANGE, "trim cut: the loops do not close "
                                    "along the cut at %g", k->at);
            used[cur] = 1;
            size_t j = cur;
            for (;; j = k->pieces[j].next) {   /* the arc: up to its crossing */
                sw_model_trim_curve c;
                outer |= k->pieces[j].outer;
                if ((st = copy_curve(&k->pieces[j].curve, &c, err)) != SW_OK ||
                    (st = push_curve(out, c, err)) != SW_OK || k->pieces[j].crossing >= 0)
                    break;
            }
            if (st != SW_OK)
                break;
            const crossing *end = &k->crossings[k->pieces[j].crossing];
            const crossing *to = &k->crossings[end->partner];
            sw_model_trim_curve line;
            if ((st = line_curve(end->uv, to->uv, &line, err)) != SW_OK ||
                (st = push_curve(out, line, err)) != SW_OK)
                break;
            if (k->pieces[to->starts].side != side)
                return sw_error_set(err, SW_ERR_RANGE, "trim cut: the loops at the cut at %g "
                                    "run the wrong way round", k->at);
            if (to->starts == start)
                break;
            cur = to->starts;
        }
        if (st == SW_OK)
            st = push_loop(out, first, outer, err);
    }
    return st;
}

static void cutter_free(cutter *k)
{
    for (size_t i = 0; i < k->piece_count; i++) {
        free(k->pieces[i].curve.knots);
        free(k->pieces[i].curve.ctrl);
    }
    free(k->pieces);
    free(k->crossings);
}

/* A loop the line misses, whole to its side. */
static sw_status keep_whole(const cutter *k, size_t first, size_t end, sw_trim_set *low,
                            sw_trim_set *high, sw_error *err)
{
    sw_trim_set *out = k->pieces[first].side ? high : low;
    size_t from = out->curve_count;
    sw_status st = SW_OK;
    for (size_t i = first; st == SW_OK && i < end; i++) {
        sw_model_trim_curve c;
        if ((st = copy_curve(&k->pieces[i].curve, &c, err)) == SW_OK)
            st = push_curve(out, c, err);
    }
    return st == SW_OK ? push_loop(out, from, k->pieces[first].outer, err) : st;
}

sw_status sw_trim_clip(const sw_trim_set *in, int axis, double at, double tol, sw_trim_set *low,
                       sw_trim_set *high, sw_error *err)
{
    if ((axis != 0 && axis != 1) || !isfinite(at) || !(tol >= 0))
        return sw_error_set(err, SW_ERR_ARG, "trim cut: axis %d at %g within %g: expected axis "
                            "0 or 1, a finite line and tol >= 0", axis, at, tol);
    cutter k = {.axis = axis, .at = at, .tol = tol};
    sw_status st = SW_OK;
    for (size_t l = 0; st == SW_OK && l < in->loop_count; l++) {
        size_t first = k.piece_count, crossings = k.crossing_count;
        st = cut_loop(&k, in, &in->loops[l], err);
        if (st != SW_OK || k.piece_count == first)
            continue;
        if (k.crossing_count == crossings)
            st = keep_whole(&k, first, k.piece_count, low, high, err);
        else
            st = link_arcs(&k, first, k.piece_count, err);
    }
    if (st == SW_OK)
        st = pair_crossings(&k, err);
    uint8_t *used = st == SW_OK ? calloc(k.piece_count + 1, 1) : NULL;
    if (st == SW_OK && !used)
        st = oom(err);
    for (int side = 0; st == SW_OK && side < 2; side++)
        st = join_side(&k, side, used, side ? high : low, err);
    free(used);
    cutter_free(&k);
    return st;
}
