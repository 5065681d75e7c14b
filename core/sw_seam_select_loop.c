/* Loops' current polylines and the front's counts (sw_seam_select.h). */
#include "sw_seam_select.h"

static uint32_t shown_at(const sw_seam_select *s, uint32_t slot)
{
    return s->shown[s->graph.slots[slot].vertex];
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
    uint32_t capacity, count;
    uint32_t first, second, distinct;   /* the first two distinct vertices, and how many (max 3) */
} walk;

static void emit(walk *w, const sw_seam_select *s, uint32_t x, uint32_t slot)
{
    if (w->points && w->count < w->capacity)
        w->points[w->count] = (sw_seam_point){x, {s->graph.slots[slot].uv[0],
                                                  s->graph.slots[slot].uv[1]}};
    w->count++;
    if (w->distinct == 0)
        w->first = x, w->distinct = 1;
    else if (w->distinct == 1 && x != w->first)
        w->second = x, w->distinct = 2;
    else if (w->distinct == 2 && x != w->first && x != w->second)
        w->distinct = 3;
}

/* One pass over the loop's slots from the start of a run. A run's (u, v)
 * comes from its slot with the smallest leaf position: leaf order puts v2's
 * side of every collapse first, so that is the rule in the header. */
static void walk_loop(const sw_seam_select *s, const sw_seam_loop *loop, walk *w)
{
    uint32_t start = run_start(s, loop);
    uint32_t offset = start == SW_SEAM_NONE ? 0 : start - loop->first_slot;
    uint32_t cur = SW_SEAM_NONE, best = 0, best_pos = 0;
    for (uint32_t i = 0; i < loop->slot_count; i++) {
        uint32_t k = offset + i;
        uint32_t slot = loop->first_slot + (k >= loop->slot_count ? k - loop->slot_count : k);
        uint32_t x = shown_at(s, slot), pos = s->leaf_lo[s->graph.slots[slot].vertex];
        if (x != cur) {
            if (cur != SW_SEAM_NONE)
                emit(w, s, cur, best);
            cur = x, best = slot, best_pos = pos;
        } else if (pos < best_pos) {
            best = slot, best_pos = pos;
        }
    }
    emit(w, s, cur, best);
}

sw_status sw_seam_select_loop(const sw_seam_select *s, uint32_t loop, sw_seam_point *points,
                              uint32_t capacity, uint32_t *count, int *vanished, sw_error *err)
{
    if (count)
        *count = 0;
    if (!s || loop >= s->graph.loop_count)
        return sw_error_set(err, SW_ERR_RANGE, "seam select: loop %u of %u", loop,
                            s ? s->graph.loop_count : 0);
    walk w = {.points = points, .capacity = points ? capacity : 0};
    walk_loop(s, &s->graph.loops[loop], &w);
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
            walk_loop(s, &g->loops[l], &w);
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
