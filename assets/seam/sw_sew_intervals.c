/* SPDX-License-Identifier: MIT */
/* Sewing step 2, the sewing intervals (paper section 4.1, figure 2). The
 * entry sw_sew_polylines (sw_sew.h) is in sw_sew_polylines.c, steps 1 and 3
 * in sw_sew_project.c and sw_sew_merge.c.
 *
 * Positions along a loop of n vertices are ordinals in [0, n): vertex k of
 * the loop is k, a foot at t on edge k is k + t (its arc-length position on
 * the straight edge). An interval of loops A and B runs forward along A and
 * along B in direction d (+1 or -1; neighbouring faces usually run opposite);
 * both directions are grown and the longer interval kept. */
#include "sw_sew_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"

typedef struct pair_group {
    sew_state *s;
    sew_match *m;          /* the group's matches, sorted by vertex */
    size_t count;
    uint32_t loop[2];      /* A, B */
    double n[2];           /* vertices per loop */
    size_t start[2];       /* first vertex of each loop */
} pair_group;

/* side 0: position on A; side 1: on B. */
static double match_pos(const pair_group *g, const sew_match *m, int side)
{
    double pos = m->lv == g->loop[side] ? (double)(m->v - g->start[side])
                                        : (double)(m->e - g->start[side]) + m->t;
    return pos >= g->n[side] ? pos - g->n[side] : pos;
}

/* How far `to` lies ahead of `from` going in dir around a loop of n. */
static double advance(double from, double to, int dir, double n)
{
    double a = dir > 0 ? to - from : from - to;
    a = a < 0 ? a + n : a;
    return a >= n - 1e-9 ? 0 : a;
}

/* The paper's window: the foot must lie on the edge at the end point or on
 * the next one, i.e. no farther ahead than the second vertex after p. */
static double window(double p, int dir)
{
    return dir > 0 ? floor(p) + 2 - p : p - (ceil(p) - 2);
}

static double next_vertex(double p, int dir, double n)
{
    double r = dir > 0 ? floor(p) + 1 : ceil(p) - 1;
    return r >= n ? r - n : r < 0 ? r + n : r;
}

/* The unused match of loop-vertex (side, ordinal vo) whose foot on the other
 * side is nearest ahead of p_other within the window, or NULL. (Least
 * advance, not least distance: a foot farther ahead would skip vertices of
 * the other side that still have to be sewn.) */
static sew_match *best_foot(const pair_group *g, int side, double vo, double p_other, int dir,
                            double *adv_out)
{
    uint32_t v = (uint32_t)(g->start[side] + (size_t)vo);
    size_t lo = 0, hi = g->count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (g->m[mid].v < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    sew_match *best = NULL;
    double win = window(p_other, dir);
    for (size_t k = lo; k < g->count && g->m[k].v == v; k++) {
        if (g->m[k].used)
            continue;
        double a = advance(p_other, match_pos(g, &g->m[k], 1 - side), dir, g->n[1 - side]);
        if (a <= win && (!best || a < *adv_out)) {
            best = &g->m[k];
            *adv_out = a;
        }
    }
    return best;
}

typedef struct chain {
    sew_match **at;
    size_t count, capacity;
    double span[2];        /* total advance along A and along B */
} chain;

static int chain_push(chain *c, sew_match *m)
{
    sew_match **at = sw_grow(c->at, &c->capacity, c->count + 1, sizeof *at);
    if (!at)
        return -1;
    c->at = at;
    c->at[c->count++] = m;
    return 0;
}

/* Grows from the end (pA, pB) in directions (da along A, db along B),
 * appending to c, one vertex of either side at a time: the next A vertex if
 * it projects into the window on B, or the next B vertex if it projects into
 * the window on A, whichever comes first along A. Stops before wrapping past
 * a whole loop. Returns -1 on allocation failure. */
static int grow(pair_group *g, double pA, double pB, int da, int db, chain *c)
{
    for (;;) {
        double va = next_vertex(pA, da, g->n[0]), vb = next_vertex(pB, db, g->n[1]);
        double adv_b_of_a = 0, adv_a_of_b = 0;
        sew_match *ma = best_foot(g, 0, va, pB, db, &adv_b_of_a);
        sew_match *mb = best_foot(g, 1, vb, pA, da, &adv_a_of_b);
        double adv_a_of_a = advance(pA, va, da, g->n[0]);
        double adv_b_of_b = advance(pB, vb, db, g->n[1]);
        /* Whichever comes first along A; on a tie, first along B (else the
         * B vertex would be skipped and left unsewn). */
        if (ma && mb && (adv_a_of_b < adv_a_of_a ||
                         (adv_a_of_b == adv_a_of_a && adv_b_of_b < adv_b_of_a)))
            ma = NULL;
        double step_a = ma ? adv_a_of_a : adv_a_of_b, step_b = ma ? adv_b_of_a : adv_b_of_b;
        sew_match *m = ma ? ma : mb;
        if (!m || c->span[0] + step_a > g->n[0] || c->span[1] + step_b > g->n[1])
            return 0;
        if (chain_push(c, m) != 0)
            return -1;
        m->used = 1;
        c->span[0] += step_a, c->span[1] += step_b;
        pA = match_pos(g, m, 0), pB = match_pos(g, m, 1);
    }
}

/* The interval through seed with B running in direction d: grown forward,
 * then backward, and put in order along A (backward part reversed). Marks
 * its matches used; the caller clears them if it drops the interval. */
static int build_chain(pair_group *g, sew_match *seed, int d, chain *c)
{
    c->count = 0;
    c->span[0] = c->span[1] = 0;
    seed->used = 1;
    if (chain_push(c, seed) != 0)
        return -1;
    double pA = match_pos(g, seed, 0), pB = match_pos(g, seed, 1);
    if (grow(g, pA, pB, -1, -d, c) != 0)
        return -1;
    for (size_t i = 0, j = c->count - 1; i < j; i++, j--) {
        sew_match *t = c->at[i];
        c->at[i] = c->at[j];
        c->at[j] = t;
    }
    return grow(g, pA, pB, 1, d, c);
}

static void chain_release(chain *c)
{
    for (size_t k = 0; k < c->count; k++)
        c->at[k]->used = 0;
}

/* Removes the projections an accepted interval covers (section 4.1: "all
 * projections of points inside this interval ... are removed"): both ends
 * within its spans and at least one strictly inside. The interval's own two
 * end projections stay available, so a neighbouring interval of the same
 * pair (across a fold of one polyline, say) can start where this one ends. */
static void cover(pair_group *g, chain *c, int d)
{
    double a0 = match_pos(g, c->at[0], 0), b0 = match_pos(g, c->at[0], 1);
    const double eps = 1e-12;
    for (size_t k = 0; k < g->count; k++) {
        sew_match *m = &g->m[k];
        double a = advance(a0, match_pos(g, m, 0), 1, g->n[0]);
        double b = advance(b0, match_pos(g, m, 1), d, g->n[1]);
        int in_a = a <= c->span[0] + eps, in_b = b <= c->span[1] + eps;
        int strict = (a > eps && a < c->span[0] - eps) || (b > eps && b < c->span[1] - eps);
        if (in_a && in_b && strict)
            m->used = 1;
    }
    c->at[0]->used = 0;
    c->at[c->count - 1]->used = 0;
}

/* The better of two intervals: more projections, then the longer spans (a
 * fold of one polyline gives a short interval that must not win over the
 * seam beside it). */
static int chain_better(const chain *x, const chain *y)
{
    if (x->count != y->count)
        return x->count > y->count;
    return x->span[0] + x->span[1] > y->span[0] + y->span[1];
}

/* The 3D point of match m on side (0: A, 1: B): its vertex or its foot. */
static void side_point(const pair_group *g, const sew_match *m, int side, double out[3])
{
    const sw_seam_polylines *poly = g->s->poly;
    if (m->lv == g->loop[side]) {
        memcpy(out, poly->p + 3 * (size_t)m->v, 3 * sizeof *out);
        return;
    }
    const double *a = poly->p + 3 * (size_t)m->e;
    const double *b = poly->p + 3 * (size_t)sew_next(poly, sew_real_loop(poly, m->le), m->e);
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + m->t * (b[k] - a[k]);
}

/* Is the interval longer than the tolerance along either polyline?
 * One that does not is a point contact: where many loops meet (a pole, a
 * vertex of high valence) every vertex near the junction is within the
 * tolerance of every edge leaving it, and its feet would only scatter extra
 * vertices around the junction. */
static int chain_long(const pair_group *g, const chain *c)
{
    for (int side = 0; side < 2; side++) {
        double p[3], q[3], length = 0;
        side_point(g, c->at[0], side, p);
        for (size_t i = 1; i < c->count && length <= g->s->tol; i++) {
            side_point(g, c->at[i], side, q);
            length += sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                           (p[2] - q[2]) * (p[2] - q[2]));
            memcpy(p, q, sizeof p);
        }
        if (length > g->s->tol)
            return 1;
    }
    return 0;
}

static int add_join(sew_state *s, const sew_match *m)
{
    sew_join *joins = sw_grow(s->joins, &s->join_capacity, s->join_count + 1, sizeof *joins);
    if (!joins)
        return -1;
    s->joins = joins;
    s->joins[s->join_count++] = (sew_join){m->v, m->e, m->t};
    return 0;
}

static int compare_dist(const void *x, const void *y)
{
    const sew_match *const *a = x, *const *b = y;
    return ((*a)->dist > (*b)->dist) - ((*a)->dist < (*b)->dist);
}

/* Seeds in order of distance; each seed tries both directions of B. */
static int group_intervals(pair_group *g, sew_match **seeds, chain *c, chain *alt)
{
    for (size_t k = 0; k < g->count; k++)
        seeds[k] = &g->m[k];
    qsort(seeds, g->count, sizeof *seeds, compare_dist);
    for (size_t k = 0; k < g->count; k++) {
        if (seeds[k]->used)
            continue;
        if (build_chain(g, seeds[k], 1, c) != 0)
            return -1;
        chain_release(c);
        if (build_chain(g, seeds[k], -1, alt) != 0)
            return -1;
        int d = -1;
        chain *best = alt;
        if (chain_better(c, alt)) {
            chain_release(alt);
            if (build_chain(g, seeds[k], 1, c) != 0)
                return -1;
            d = 1;
            best = c;
        }
        if (best->count < 2 || !(best->span[0] > 0) || !(best->span[1] > 0)) {
            chain_release(best);
            seeds[k]->used = 1;
            continue;
        }
        g->s->intervals++;
        /* A point contact merges vertices with vertices only. */
        int feet = chain_long(g, best);
        for (size_t i = 0; i < best->count; i++)
            if ((feet || best->at[i]->t == 0 || best->at[i]->t == 1) &&
                add_join(g->s, best->at[i]) != 0)
                return -1;
        cover(g, best, d);
    }
    return 0;
}

static int compare_matches(const void *x, const void *y)
{
    const sew_match *a = x, *b = y;
    uint32_t alo = a->lv < a->le ? a->lv : a->le, ahi = a->lv < a->le ? a->le : a->lv;
    uint32_t blo = b->lv < b->le ? b->lv : b->le, bhi = b->lv < b->le ? b->le : b->lv;
    if (alo != blo)
        return alo < blo ? -1 : 1;
    if (ahi != bhi)
        return ahi < bhi ? -1 : 1;
    if (a->v != b->v)
        return a->v < b->v ? -1 : 1;
    if (a->e != b->e)
        return a->e < b->e ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

sw_status sew_intervals(sew_state *s)
{
    const sw_seam_polylines *poly = s->poly;
    if (s->match_count > 1)
        qsort(s->matches, s->match_count, sizeof *s->matches, compare_matches);
    sew_match **seeds = malloc((s->match_count + 1) * sizeof *seeds);
    chain c = {0}, alt = {0};
    int failed = !seeds;
    for (size_t i = 0; !failed && i < s->match_count;) {
        const sew_match *m0 = &s->matches[i];
        uint32_t lo = m0->lv < m0->le ? m0->lv : m0->le, hi = m0->lv < m0->le ? m0->le : m0->lv;
        size_t j = i + 1;
        while (j < s->match_count && ((s->matches[j].lv == lo && s->matches[j].le == hi) ||
                                      (s->matches[j].lv == hi && s->matches[j].le == lo)))
            j++;
        /* hi may be a copy of lo (a loop sewn to itself): sizes of the real one */
        uint32_t real = sew_real_loop(poly, hi);
        pair_group g = {s, s->matches + i, j - i, {lo, hi},
                        {(double)(poly->loop_start[lo + 1] - poly->loop_start[lo]),
                         (double)(poly->loop_start[real + 1] - poly->loop_start[real])},
                        {poly->loop_start[lo], poly->loop_start[real]}};
        failed = group_intervals(&g, seeds, &c, &alt) != 0;
        i = j;
    }
    free(seeds);
    free(c.at);
    free(alt.at);
    if (failed)
        return sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory for intervals");
    return SW_OK;
}
