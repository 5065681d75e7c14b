/* SPDX-License-Identifier: MIT */
/* The loops as the trimmed tessellator sees them (core/sw_trim_tess.c):
 * repeated points merged, every loop turned so the trimmed region lies on its
 * left (even-odd nesting decides which side that is, whatever the caller's
 * orientation), and the region shrink: each point moved by a tiny distance
 * into the region along its mitre, so that no loop runs exactly along a cell
 * side or touches another loop. Topology (which cell holds what, where a
 * segment crosses) is decided on the moved points only, so every cell agrees
 * with its neighbours; output keeps the caller's (u, v). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "sw_trim_tess_internal.h"

static int same_uv(const sw_trim_point *a, const sw_trim_point *b)
{
    return a->uv[0] == b->uv[0] && a->uv[1] == b->uv[1];
}

/* Distinct points of loop k: consecutive repeats and a repeated first point
 * at the end count once. */
static uint32_t distinct_points(const sw_trim_loops *l, uint32_t k)
{
    uint32_t first = l->loop_first[k], end = l->loop_first[k + 1], n = 0;
    while (end > first + 1 && same_uv(&l->points[end - 1], &l->points[first]))
        end--;
    for (uint32_t i = first; i < end; i++)
        if (i == first || !same_uv(&l->points[i], &l->points[i - 1]))
            n++;
    return n;
}

static sw_status check_loops(tt_ctx *c, const double dom[4], uint32_t *total, uint32_t *valid)
{
    const sw_trim_loops *l = c->in_loops;
    if (l->loop_count && (!l->loop_first || !l->points))
        return sw_error_set(c->err, SW_ERR_ARG, "trim tess: %u loops but no points",
                            (unsigned)l->loop_count);
    /* Real trims overshoot the surface's domain a little (the hammer's by
     * 5e-5 of it); within 1% a point is clamped onto the domain. */
    double tol = 1e-2 * fmax(dom[1] - dom[0], dom[3] - dom[2]);
    *total = *valid = 0;
    for (uint32_t k = 0; k < l->loop_count; k++) {
        if (l->loop_first[k + 1] < l->loop_first[k] || (k == 0 && l->loop_first[0] != 0))
            return sw_error_set(c->err, SW_ERR_ARG, "trim tess: loop_first[%u..%u] = %u, %u: "
                                "expected non-decreasing from 0", (unsigned)k, (unsigned)k + 1,
                                (unsigned)l->loop_first[k], (unsigned)l->loop_first[k + 1]);
        for (uint32_t i = l->loop_first[k]; i < l->loop_first[k + 1]; i++) {
            double u = l->points[i].uv[0], v = l->points[i].uv[1];
            if (!(u >= dom[0] - tol && u <= dom[1] + tol && v >= dom[2] - tol && v <= dom[3] + tol))
                return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: loop %u point %u at (%g, %g)"
                                    ": outside the domain [%g, %g] x [%g, %g]", (unsigned)k,
                                    (unsigned)i, u, v, dom[0], dom[1], dom[2], dom[3]);
        }
        uint32_t n = distinct_points(l, k);
        if (n >= 3)
            *total += n, (*valid)++;
        else
            c->res->skipped_loops++;
    }
    return SW_OK;
}

static double loop_area(const sw_tt_point *p, uint32_t first, uint32_t count)
{
    double a = 0;
    for (uint32_t i = 0; i < count; i++) {
        const sw_tt_point *x = &p[first + i], *y = &p[first + (i + 1) % count];
        a += x->u * y->v - y->u * x->v;
    }
    return 0.5 * a;
}

static int point_in_loop(const sw_tt_point *p, const sw_tt_loop *l, double u, double v)
{
    int in = 0;
    for (uint32_t i = 0; i < l->count; i++) {
        const sw_tt_point *a = &p[l->first + i], *b = &p[l->first + (i + 1) % l->count];
        if ((a->v > v) != (b->v > v) && a->u + (v - a->v) / (b->v - a->v) * (b->u - a->u) > u)
            in ^= 1;
    }
    return in;
}

/* Is b the tip of a spike, a -> b -> c turning back within 1e-6 rad of 180
 * degrees (or a repeat after clamping)? Real trims have them where a tiny
 * curve overshoots a corner and comes back; moved into the region they would
 * cross themselves. */
static int spike(const sw_tt_point *a, const sw_tt_point *b, const sw_tt_point *c)
{
    double e1u = b->u - a->u, e1v = b->v - a->v, e2u = c->u - b->u, e2v = c->v - b->v;
    double l1 = e1u * e1u + e1v * e1v, l2 = e2u * e2u + e2v * e2v; /* squared */
    if (l1 == 0 || l2 == 0)
        return 1;
    double cross = e1u * e2v - e1v * e2u;
    return e1u * e2u + e1v * e2v < 0 && cross * cross <= 1e-12 * l1 * l2;
}

/* Counts a dropped point as lost unless a kept neighbour carries its id (a
 * seam vertex repeated at nearby (u, v) is still in the mesh). */
static uint32_t lost(const sw_trim_point *in, uint32_t dropped, uint32_t kept_a, uint32_t kept_b)
{
    return in[dropped].id != in[kept_a].id && in[dropped].id != in[kept_b].id;
}

/* Is the triangle a lost point d cuts off with its kept neighbours a and b
 * flat in space, to float rounding of their coordinates? The border then
 * runs a -> b where it ran a -> d -> b, and the meshes across a-d and d-b
 * cover that line too: no gap opens, only a T-vertex (as where a sliver
 * surface collapses to a line at a coarse seam state). With a == b (a near
 * repeat, whose next neighbour is not known yet) only d on a is flat. */
static int flat(const sw_trim_point *in, uint32_t d, uint32_t a, uint32_t b)
{
    const float *p[3] = {in[a].p, in[d].p, in[b].p};
    double big = 0, e[3][3], longest = 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            big = fmax(big, fabs((double)p[i][k]));
            e[i][k] = (double)p[(i + 1) % 3][k] - p[i][k];
        }
    for (int i = 0; i < 3; i++)
        longest = fmax(longest, sqrt(e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2]));
    double tol = 8.0 * FLT_EPSILON * big; /* as the drawn-seam check's */
    if (longest <= tol || a == b)
        return longest <= tol;
    double x = e[0][1] * e[1][2] - e[0][2] * e[1][1], y = e[0][2] * e[1][0] - e[0][0] * e[1][2],
           z = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    return sqrt(x * x + y * y + z * z) / longest <= tol; /* the height over the longest side */
}

/* Counts dropped point d (between kept a and b) into c's result, and lists
 * it where the caller asked (sw_trim_tess_buffers.dropped). */
static void count_drop(tt_ctx *c, uint32_t d, uint32_t a, uint32_t b)
{
    const sw_trim_point *in = c->in_loops->points;
    sw_trim_tess_result *res = c->res;
    if (!lost(in, d, a, b))
        return;
    if (c->out && c->out->dropped && res->dropped_points < c->out->dropped_capacity)
        c->out->dropped[res->dropped_points] = d;
    res->dropped_points++;
    res->dropped_flat += (uint32_t)flat(in, d, a, b);
}

/* Drops spike tips until none is left; returns the new count. */
static uint32_t remove_spikes(tt_ctx *c, sw_tt_point *p, uint32_t count)
{
    for (uint32_t i = 0; count >= 3 && i < count;) {
        if (!spike(&p[(i + count - 1) % count], &p[i], &p[(i + 1) % count])) {
            i++;
            continue;
        }
        count_drop(c, p[i].src, p[(i + count - 1) % count].src, p[(i + 1) % count].src);
        memmove(&p[i], &p[i + 1], sizeof *p * (count - i - 1));
        count--;
        i = i > 0 ? i - 1 : 0; /* the point before may have become a tip */
    }
    return count;
}

/* x within near of a side (lo or hi) of the domain, or of 0, moved onto it.
 * Floats near 0 resolve far finer than the domain's own rounding: a loop
 * point 1.7e-30 off a patch border at u = 0 (where an exporter wrote its
 * trim a hair off the seam) or 1e-15 inside a domain side at 1.3e-15 sits
 * off the grid line by less than the clipping's crossings there can tell
 * apart, and the walk around that cell went wrong ("loops cross", or area
 * left out). Only rounding is taken back: near is a few ulps of the
 * domain's size. (At 1e-12 of it, a point 4e-13 off a knot line 5e-11 from
 * a side was moved onto the line and tripped the clipping the same way.) */
static double onto_line(double x, double lo, double hi, double near)
{
    if (fabs(x - lo) <= near)
        return lo;
    if (fabs(x - hi) <= near)
        return hi;
    return fabs(x) <= near ? 0.0 : x;
}

/* Copies the distinct points of the loops with area, clamped to the domain,
 * without spike tips and points within 1e-6 of the domain of the last kept. */
static void copy_loops(tt_ctx *c, const double dom[4])
{
    const sw_trim_loops *l = c->in_loops;
    /* Points closer than this to the previous kept one are dropped: float
     * (u, v) of tiny trim curves zig-zag at the float step and would cross. */
    double eps = 1e-6 * fmax(dom[1] - dom[0], dom[3] - dom[2]);
    double near = SW_TT_ONTO_LINE_ULPS * DBL_EPSILON *
                  fmax(fmax(dom[1] - dom[0], dom[3] - dom[2]),
                       fmax(fmax(fabs(dom[0]), fabs(dom[1])), fmax(fabs(dom[2]), fabs(dom[3]))));
    uint32_t n = 0, m = 0;
    for (uint32_t k = 0; k < l->loop_count; k++) {
        uint32_t count = distinct_points(l, k), first = n;
        if (count < 3)
            continue;
        const uint32_t dropped_before = c->res->dropped_points;
        const uint32_t flat_before = c->res->dropped_flat;
        uint32_t end = l->loop_first[k + 1];
        while (end > l->loop_first[k] + 1 &&
               same_uv(&l->points[end - 1], &l->points[l->loop_first[k]]))
            end--;
        for (uint32_t i = l->loop_first[k]; i < end; i++) {
            double u = l->points[i].uv[0], v = l->points[i].uv[1]; /* checked finite */
            u = onto_line(u < dom[0] ? dom[0] : u > dom[1] ? dom[1] : u, dom[0], dom[1], near);
            v = onto_line(v < dom[2] ? dom[2] : v > dom[3] ? dom[3] : v, dom[2], dom[3], near);
            if (n > first && fabs(u - c->pts[n - 1].u) + fabs(v - c->pts[n - 1].v) < eps) {
                if (!same_uv(&l->points[i], &l->points[i - 1]))
                    count_drop(c, i, c->pts[n - 1].src, c->pts[n - 1].src);
                continue;
            }
            sw_tt_point *p = &c->pts[n++];
            p->u = u, p->v = v, p->src = i, p->loop = m;
        }
        while (n - first > 1 && fabs(c->pts[n - 1].u - c->pts[first].u) +
                                        fabs(c->pts[n - 1].v - c->pts[first].v) < eps) {
            n--;
            count_drop(c, c->pts[n].src, c->pts[n - 1].src, c->pts[first].src);
        }
        count = remove_spikes(c, c->pts + first, n - first);
        n = first + count;
        if (count < 3 || loop_area(c->pts, first, count) == 0) {
            n = first;
            c->res->skipped_loops++;
            if (sw_tt_loop_spans_space(l, k)) { /* drawn as a fan: its points are all in */
                c->collapsed[c->collapsed_count++] = k;
                c->res->dropped_points = dropped_before;
                c->res->dropped_flat = flat_before;
            }
            continue;
        }
        c->loops[m].first = first, c->loops[m].count = count;
        m++;
    }
    c->trims.loop_count = m;
    c->trims.point_count = n;
}

static void reverse_loop(sw_tt_point *p, const sw_tt_loop *l)
{
    for (uint32_t i = 0, j = l->count - 1; i < j; i++, j--) {
        sw_tt_point t = p[l->first + i];
        p[l->first + i] = p[l->first + j];
        p[l->first + j] = t;
    }
}

/* Even-odd nesting: a loop nested in an even number of others bounds the
 * region from outside (region inside it), an odd one is a hole. The test
 * point is the middle of the loop's longest segment, away from touching
 * points. */
static void orient_loops(tt_ctx *c)
{
    for (uint32_t k = 0; k < c->trims.loop_count; k++) {
        sw_tt_loop *l = &c->loops[k];
        double best = -1, tu = 0, tv = 0;
        for (uint32_t i = 0; i < l->count; i++) {
            const sw_tt_point *a = &c->pts[l->first + i], *b = &c->pts[l->first + (i + 1) % l->count];
            double d = (b->u - a->u) * (b->u - a->u) + (b->v - a->v) * (b->v - a->v);
            if (d > best)
                best = d, tu = 0.5 * (a->u + b->u), tv = 0.5 * (a->v + b->v);
        }
        int depth = 0;
        for (uint32_t j = 0; j < c->trims.loop_count; j++)
            depth += j != k && point_in_loop(c->pts, &c->loops[j], tu, tv);
        l->hole = depth % 2;
    }
    for (uint32_t k = 0; k < c->trims.loop_count; k++) {
        sw_tt_loop *l = &c->loops[k];
        int ccw = loop_area(c->pts, l->first, l->count) > 0;
        if (ccw == l->hole)
            reverse_loop(c->pts, l);
        for (uint32_t i = 0; i < l->count; i++)
            c->pts[l->first + i].next = l->first + (i + 1) % l->count;
    }
}

/* The mitre at b between a -> b and b -> c: the direction into the left of
 * both segments, lengthened so both are offset by one unit (capped at 4 for
 * sharp corners; a spike takes the first segment's normal). */
static void mitre(const sw_tt_point *a, const sw_tt_point *b, const sw_tt_point *c, double *du,
                  double *dv)
{
    double e1u = b->u - a->u, e1v = b->v - a->v, e2u = c->u - b->u, e2v = c->v - b->v;
    double l1 = sqrt(e1u * e1u + e1v * e1v), l2 = sqrt(e2u * e2u + e2v * e2v);
    double n1u = -e1v / l1, n1v = e1u / l1, n2u = -e2v / l2, n2v = e2u / l2;
    double mu = n1u + n2u, mv = n1v + n2v, ml = sqrt(mu * mu + mv * mv);
    if (!(ml > 1e-3)) {
        *du = n1u, *dv = n1v;
        return;
    }
    mu /= ml, mv /= ml;
    double cosine = mu * n1u + mv * n1v, scale = 1 / fmax(cosine, 0.25);
    *du = mu * scale, *dv = mv * scale;
}

static sw_status shrink_region(tt_ctx *c, const double dom[4])
{
    uint32_t n = c->trims.point_count;
    double *shift = sw_arena_alloc(c->arena, sizeof(double) * 2 * (n + 1), 8);
    if (!shift)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for loops");
    double delta = sw_tt_shrink_of(dom);
    for (uint32_t k = 0; k < c->trims.loop_count; k++) {
        const sw_tt_loop *l = &c->loops[k];
        for (uint32_t i = 0; i < l->count; i++) {
            uint32_t b = l->first + i, a = l->first + (i + l->count - 1) % l->count;
            mitre(&c->pts[a], &c->pts[b], &c->pts[c->pts[b].next], &shift[2 * b],
                  &shift[2 * b + 1]);
        }
    }
    for (uint32_t i = 0; i < n; i++)
        c->pts[i].u += delta * shift[2 * i], c->pts[i].v += delta * shift[2 * i + 1];
    for (uint32_t k = 0; k < c->trims.loop_count; k++) {
        sw_tt_loop *l = &c->loops[k];
        l->box[0] = l->box[2] = INFINITY, l->box[1] = l->box[3] = -INFINITY;
        for (uint32_t i = l->first; i < l->first + l->count; i++) {
            double u = c->pts[i].u, v = c->pts[i].v; /* finite: no fmin/fmax calls */
            l->box[0] = u < l->box[0] ? u : l->box[0], l->box[1] = u > l->box[1] ? u : l->box[1];
            l->box[2] = v < l->box[2] ? v : l->box[2], l->box[3] = v > l->box[3] ? v : l->box[3];
        }
    }
    return SW_OK;
}

sw_status sw_tt_prepare_loops(tt_ctx *c, const double dom[4])
{
    uint32_t total = 0, valid = 0;
    sw_status st = check_loops(c, dom, &total, &valid);
    if (st != SW_OK)
        return st;
    c->pts = sw_arena_alloc(c->arena, sizeof *c->pts * (total + 1), 8);
    c->loops = sw_arena_alloc(c->arena, sizeof *c->loops * (valid + 1), 8);
    c->stamp = sw_arena_alloc(c->arena, sizeof(uint32_t) * (total + 1), 4);
    c->seam_out = sw_arena_alloc(c->arena, sizeof(uint32_t) * (total + 1), 4);
    c->collapsed = sw_arena_alloc(c->arena, sizeof(uint32_t) * (valid + 1), 4);
    c->collapsed_count = 0;
    if (!c->pts || !c->loops || !c->stamp || !c->seam_out || !c->collapsed)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for %u loop "
                            "points", (unsigned)total);
    copy_loops(c, dom);
    orient_loops(c);
    size_t mark = sw_arena_mark(c->arena);
    st = shrink_region(c, dom);
    sw_arena_reset_to(c->arena, mark);
    for (uint32_t i = 0; i < c->trims.point_count; i++)
        c->stamp[i] = 0, c->seam_out[i] = SW_TT_NONE;
    c->trims.pts = c->pts;
    c->trims.loops = c->loops;
    return st;
}
