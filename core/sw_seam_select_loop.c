/* SPDX-License-Identifier: MIT */
/* Loops' current polylines and the front's counts (sw_seam_select.h). */
#include "sw_seam_select.h"

#include <math.h>

static uint32_t shown_at(const sw_seam_select *s, uint32_t slot)
{
    return s->shown[s->leaf_lo[s->graph.slots[slot].vertex]];
}

/* The first slot (in slot order) whose predecessor shows another vertex:
 * where the polyline starts. SW_SEAM_NONE when one vertex shows everywhere. */
static uint32_t run_start(const sw_seam_select *s, const sw_seam_loop *loop)
{
    uint32_t prev = loop->first_slot + loop->slot_count - 1;
    for (uint32_t i = 0; i < loop->slot_count; i++) {
        uint32_t slot = loop->first_slot + i;
        if (shown_at(s, slot) != shown_at(s, prev))
            return slot;
        prev = slot;
    }
    return SW_SEAM_NONE;
}

typedef struct walk {
    sw_seam_point *points;
    uint32_t *slots;                    /* NULL, or the loop slot of each point */
    uint32_t capacity, count;
    uint32_t first, second, distinct;   /* the first two distinct vertices, and how many (max 3) */
    uint32_t first_slot;                /* the loop's */
} walk;

static void emit(walk *w, const sw_seam_select *s, uint32_t x, uint32_t slot)
{
    if (w->points && w->count < w->capacity)
        w->points[w->count] = (sw_seam_point){x, {s->graph.slots[slot].uv[0],
                                                  s->graph.slots[slot].uv[1]}};
    if (w->slots && w->count < w->capacity)
        w->slots[w->count] = slot - w->first_slot;
    w->count++;
    if (w->distinct == 0)
        w->first = x, w->distinct = 1;
    else if (w->distinct == 1 && x != w->first)
        w->second = x, w->distinct = 2;
    else if (w->distinct == 2 && x != w->first && x != w->second)
        w->distinct = 3;
}

/* The slot of the run (k0 .. k0 + len) whose (u, v) the header's rule picks:
 * the smallest leaf position. Leaf order puts v2's side of every collapse
 * first, so that is the rule. */
static uint32_t rule_slot(const sw_seam_select *s, const sw_seam_loop *loop, uint32_t k0,
                          uint32_t len)
{
    uint32_t best = SW_SEAM_NONE, best_pos = 0;
    for (uint32_t i = 0; i < len; i++) {
        uint32_t slot = loop->first_slot + (k0 + i) % loop->slot_count;
        uint32_t pos = s->leaf_lo[s->graph.slots[slot].vertex];
        if (best == SW_SEAM_NONE || pos < best_pos)
            best = slot, best_pos = pos;
    }
    return best;
}

static float dist3(const sw_seam_graph *g, uint32_t slot, uint32_t x)
{
    const float *a = g->vertices[g->slots[slot].vertex].p, *b = g->vertices[x].p;
    float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrtf(dx * dx + dy * dy + dz * dz);
}

static float dist_uv(const sw_seam_graph *g, uint32_t a, uint32_t b)
{
    float du = g->slots[a].uv[0] - g->slots[b].uv[0], dv = g->slots[a].uv[1] - g->slots[b].uv[1];
    return sqrtf(du * du + dv * dv);
}

static uint32_t slot_at(const sw_seam_loop *loop, uint32_t k)
{
    return loop->first_slot + k % loop->slot_count;
}

/* Model-space length per unit of (u, v) of the loop's original segment from
 * slot k to slot k + 1; -1 where the segment has no (u, v) length. */
static float segment_scale(const sw_seam_graph *g, const sw_seam_loop *loop, uint32_t k)
{
    uint32_t a = slot_at(loop, k), b = slot_at(loop, k + 1);
    float duv = dist_uv(g, a, b);
    return duv > 0 ? dist3(g, a, g->slots[b].vertex) / duv : -1.0f;
}

/* Is the mapping degenerate at slot k: one of its two segments is less than
 * a sixteenth as long in model space as its (u, v) length predicts from the
 * segments next to it? A pole side is (every point of it is one point in
 * space); an ordinary border is not, nor one where the parameterisation is
 * merely uneven. Static: the original slots only. */
static int degenerate_at(const sw_seam_graph *g, const sw_seam_loop *loop, uint32_t k)
{
    uint32_t n = loop->slot_count;
    float scale = 0, own = INFINITY;
    for (uint32_t i = 0; i < 4; i++) {
        float r = segment_scale(g, loop, k + 2 * n - 2 + i);
        if (r < 0)
            continue;
        scale = fmaxf(scale, r);
        if (i == 1 || i == 2)
            own = fminf(own, r);
    }
    return own < 0.0625f * scale;
}

int sw_seam_slot_degenerate(const sw_seam_graph *g, uint32_t loop, uint32_t k)
{
    return loop < g->loop_count && k < g->loops[loop].slot_count &&
           degenerate_at(g, &g->loops[loop], k);
}

/* One run, slots k0 .. k0 + len (mod the loop) all showing x. One point, the
 * rule's, unless the run holds slots where the parameterisation is
 * degenerate (a pole side, as on the Newell lid at its knob: one point in
 * space, a whole side in (u, v)) within pin of x: a single (u, v) would turn
 * the L-shaped path around the domain's corner into a chord across it, with
 * the triangles under the chord far off the surface (teaset: 5 px of a
 * 0.5 px bound). Then the first and last of those slots give points too, all
 * at x, in slot order with the rule's slot; repeats of one (u, v) dropped.
 * Only the two ends: every slot of a pole would add points that change
 * nothing. */
static void emit_run(walk *w, const sw_seam_select *s, const sw_seam_loop *loop, uint32_t x,
                     uint32_t k0, uint32_t len, float pin)
{
    const sw_seam_graph *g = &s->graph;
    uint32_t rule = rule_slot(s, loop, k0, len);
    uint32_t first = len, last = len, rule_i = (rule - loop->first_slot + loop->slot_count - k0) %
                                               loop->slot_count;
    for (uint32_t i = 0; pin > 0 && len > 1 && i < len; i++) {
        if (dist3(g, slot_at(loop, k0 + i), x) > pin || !degenerate_at(g, loop, k0 + i))
            continue;
        first = first == len ? i : first;
        last = i;
    }
    /* In slot order: the rule's slot may lie before, between or after. */
    uint32_t order[3] = { first, rule_i, last };
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2 - a; b++)
            if (order[b] > order[b + 1]) {
                uint32_t t = order[b];
                order[b] = order[b + 1], order[b + 1] = t;
            }
    uint32_t prev = SW_SEAM_NONE;
    for (int i = 0; i < 3 && order[i] < len; i++) {
        uint32_t slot = slot_at(loop, k0 + order[i]);
        if (prev != SW_SEAM_NONE && dist_uv(g, prev, slot) == 0)
            continue;
        emit(w, s, x, slot);
        prev = slot;
    }
}

/* One pass over the loop's slots from the start of a run. */
static void walk_loop(const sw_seam_select *s, const sw_seam_loop *loop, float pin, walk *w)
{
    uint32_t start = run_start(s, loop);
    uint32_t offset = start == SW_SEAM_NONE ? 0 : start - loop->first_slot;
    uint32_t run_k = offset, cur = shown_at(s, loop->first_slot + offset);
    for (uint32_t i = 1; i < loop->slot_count; i++) {
        uint32_t k = (offset + i) % loop->slot_count;
        uint32_t x = shown_at(s, loop->first_slot + k);
        if (x == cur)
            continue;
        emit_run(w, s, loop, cur, run_k, (k + loop->slot_count - run_k) % loop->slot_count, pin);
        cur = x, run_k = k;
    }
    uint32_t len = (offset + loop->slot_count - run_k) % loop->slot_count;
    emit_run(w, s, loop, cur, run_k, len ? len : loop->slot_count, pin);
}

sw_status sw_seam_select_loop(const sw_seam_select *s, uint32_t loop, float pin,
                              sw_seam_point *points, uint32_t capacity, uint32_t *count,
                              int *vanished, sw_error *err)
{
    return sw_seam_select_loop_slots(s, loop, pin, points, NULL, capacity, count, vanished, err);
}

sw_status sw_seam_select_loop_slots(const sw_seam_select *s, uint32_t loop, float pin,
                                    sw_seam_point *points, uint32_t *slots, uint32_t capacity,
                                    uint32_t *count, int *vanished, sw_error *err)
{
    if (count)
        *count = 0;
    if (!s || loop >= s->graph.loop_count)
        return sw_error_set(err, SW_ERR_RANGE, "seam select: loop %u of %u", loop,
                            s ? s->graph.loop_count : 0);
    walk w = {.points = points, .slots = points ? slots : NULL,
              .capacity = points ? capacity : 0, .first_slot = s->graph.loops[loop].first_slot};
    walk_loop(s, &s->graph.loops[loop], pin, &w);
    if (count)
        *count = w.count;
    if (vanished)
        *vanished = w.distinct < 3;
    if (w.count > w.capacity)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "seam select: loop %u has %u points, buffer holds %u", loop, w.count,
                            w.capacity);
    return SW_OK;
}

sw_seam_select_stats sw_seam_select_count(const sw_seam_select *s)
{
    sw_seam_select_stats st = {0};
    if (!s)
        return st;
    const sw_seam_graph *g = &s->graph;
    st.active_vertices = s->active_count;
    for (uint32_t surface = 0; surface < g->surface_count; surface++) {
        int outer_gone = 0;
        for (uint32_t l = g->surface_loops[surface]; l < g->surface_loops[surface + 1]; l++) {
            walk w = {0};
            walk_loop(s, &g->loops[l], 0.0f, &w);
            if (w.distinct >= 3)
                continue;
            st.loops_vanished++;
            if (g->loops[l].flags & SW_SEAM_LOOP_OUTER)
                outer_gone = 1;
        }
        st.surfaces_vanished += (uint32_t)outer_gone;
    }
    return st;
}
