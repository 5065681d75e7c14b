/* SPDX-License-Identifier: MIT */
/* Border strips (sw_border_strip.h). */
#include "sw_border_strip.h"

#include <math.h>

int sw_border_chain_valid(const sw_strip_point *chain, uint32_t n, float period)
{
    if (!chain || n == 0 || !(period > 0) || !isfinite(period))
        return 0;
    uint32_t descents = 0;
    for (uint32_t i = 0; i < n; i++) {
        float t = chain[i].t;
        if (!(t >= 0 && t < period))
            return 0;
        descents += t < chain[(i + n - 1) % n].t;
    }
    return descents <= 1;
}

/* Where a valid chain starts in t: after its wrap (0 when it has none). */
static uint32_t chain_start(const sw_strip_point *chain, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++)
        if (chain[i].t < chain[i - 1].t)
            return i;
    return 0;
}

/* A chain walked once round from `start`, t unwrapped into one increasing
 * run: step k = 0 .. n (n is the start again, a period later). `next` is
 * the unwrapped t of step k + 1; `offset` is what was
 * added to step k + 1's stored t (a period more after the wrap). */
typedef struct rail {
    const sw_strip_point *chain;
    uint32_t n, start, k;
    float first, next, offset, period;
} rail;

static uint32_t rail_vertex(const rail *r, uint32_t k)
{
    return r->chain[(r->start + k) % r->n].vertex;
}

static float raw_t(const rail *r, uint32_t k) { return r->chain[(r->start + k) % r->n].t; }

/* Step k + 1's unwrapped t, from step k's. */
static float rail_next(rail *r)
{
    if (r->k + 1 >= r->n)
        return r->k + 1 == r->n ? r->first + r->period : INFINITY;
    if (raw_t(r, r->k + 1) < raw_t(r, r->k))
        r->offset += r->period;
    return raw_t(r, r->k + 1) + r->offset;
}

/* offset: 0, or -period for a start that stands before the loop's t = 0. */
static void rail_init(rail *r, const sw_strip_point *chain, uint32_t n, uint32_t start,
                      float offset, float period)
{
    *r = (rail){ .chain = chain, .n = n, .start = start, .offset = offset, .period = period };
    r->first = chain[start].t + offset;
    r->next = rail_next(r);
}

static void rail_advance(rail *r)
{
    r->k++;
    r->next = rail_next(r);
}

uint32_t sw_border_strip(const sw_strip_point *outer, uint32_t a, const sw_strip_point *inner,
                         uint32_t b, float period, uint32_t *tris)
{
    if (!tris || !sw_border_chain_valid(outer, a, period) ||
        !sw_border_chain_valid(inner, b, period))
        return 0;
    rail o, in;
    uint32_t so = chain_start(outer, a), si = chain_start(inner, b);
    rail_init(&o, outer, a, so, 0, period);
    /* The inner rail starts at its last point at or before the outer's
     * start, so each rung joins points that stand near each other. */
    uint32_t before = 0;
    while (before < b && inner[(si + before) % b].t <= outer[so].t)
        before++;
    if (before == 0)
        rail_init(&in, inner, b, (si + b - 1) % b, -period, period);
    else
        rail_init(&in, inner, b, (si + before - 1) % b, 0, period);
    uint32_t count = 0;
    while (o.k < a || in.k < b) {
        uint32_t *t = tris + 3 * count++;
        if (in.k == b || (o.k < a && o.next <= in.next)) {
            t[0] = rail_vertex(&o, o.k), t[1] = rail_vertex(&o, o.k + 1);
            t[2] = rail_vertex(&in, in.k);
            rail_advance(&o);
        } else {
            t[0] = rail_vertex(&o, o.k), t[1] = rail_vertex(&in, in.k + 1);
            t[2] = rail_vertex(&in, in.k);
            rail_advance(&in);
        }
    }
    return count;
}
