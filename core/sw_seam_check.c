/* sw_seam_graph_check: structural checks of a Seam Graph (sw_seam_check.h). */
#include "sw_seam_check.h"

#include <math.h>

static int finite3(const float p[3]) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

static sw_status check_arrays(const sw_seam_graph *g, sw_error *err)
{
    if ((uint64_t)g->original_count + g->collapse_count != g->vertex_count)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "seam graph: vertex_count %u, expected original_count %u + "
                            "collapse_count %u", g->vertex_count, g->original_count,
                            g->collapse_count);
    if (g->vertex_count >= SW_SEAM_NONE)
        return sw_error_set(err, SW_ERR_RANGE, "seam graph: vertex_count %u too large",
                            g->vertex_count);
    if ((g->vertex_count && !g->vertices) || (g->slot_count && !g->slots) ||
        (g->loop_count && !g->loops) || (g->edge_count && !g->edges) ||
        (g->collapse_count && !g->collapses) || (g->slot_ref_count && !g->slot_refs) ||
        !g->surface_loops)
        return sw_error_set(err, SW_ERR_FORMAT, "seam graph: an array with a non-zero "
                                                "count (or surface_loops) is missing");
    if (g->slot_ref_count != g->slot_count)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "seam graph: slot_ref_count %u, expected slot_count %u",
                            g->slot_ref_count, g->slot_count);
    if (!isfinite(g->tolerance) || g->tolerance < 0.0f)
        return sw_error_set(err, SW_ERR_FORMAT, "seam graph: tolerance %g, expected finite >= 0",
                            (double)g->tolerance);
    return SW_OK;
}

static sw_status check_loops(const sw_seam_graph *g, sw_error *err)
{
    if (g->surface_loops[0] != 0 || g->surface_loops[g->surface_count] != g->loop_count)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "seam graph: surface_loops runs from %u to %u, expected 0 to "
                            "loop_count %u", g->surface_loops[0],
                            g->surface_loops[g->surface_count], g->loop_count);
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t l0 = g->surface_loops[s], l1 = g->surface_loops[s + 1];
        if (l1 < l0 || l1 > g->loop_count)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: surface_loops[%u] = %u after %u (of %u loops)",
                                s + 1, l1, l0, g->loop_count);
        for (uint32_t l = l0; l < l1; l++)
            if (g->loops[l].surface != s)
                return sw_error_set(err, SW_ERR_FORMAT,
                                    "seam graph: loop %u has surface %u, expected %u", l,
                                    g->loops[l].surface, s);
    }
    uint32_t end = 0;
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        if (loop->slot_count < 3)
            return sw_error_set(err, SW_ERR_FORMAT, "seam graph: loop %u has %u slots, "
                                "expected >= 3", l, loop->slot_count);
        if (loop->first_slot < end || loop->first_slot > g->slot_count ||
            loop->slot_count > g->slot_count - loop->first_slot)
            return sw_error_set(err, SW_ERR_RANGE,
                                "seam graph: loop %u slots [%u, +%u) outside [%u, %u)", l,
                                loop->first_slot, loop->slot_count, end, g->slot_count);
        end = loop->first_slot + loop->slot_count;
    }
    return SW_OK;
}

static sw_status check_slots(const sw_seam_graph *g, sw_error *err)
{
    for (uint32_t i = 0; i < g->slot_count; i++) {
        const sw_seam_slot *slot = &g->slots[i];
        if (slot->vertex >= g->original_count)
            return sw_error_set(err, SW_ERR_RANGE,
                                "seam graph: slot %u holds vertex %u, expected < %u", i,
                                slot->vertex, g->original_count);
        if (!isfinite(slot->uv[0]) || !isfinite(slot->uv[1]))
            return sw_error_set(err, SW_ERR_FORMAT, "seam graph: slot %u uv not finite", i);
    }
    for (uint32_t e = 0; e < g->edge_count; e++)
        if (g->edges[e].a >= g->edges[e].b || g->edges[e].b >= g->original_count)
            return sw_error_set(err, SW_ERR_RANGE,
                                "seam graph: edge %u (%u, %u), expected a < b < %u", e,
                                g->edges[e].a, g->edges[e].b, g->original_count);
    return SW_OK;
}

static sw_status check_vertex_slots(const sw_seam_graph *g, uint32_t v, sw_error *err)
{
    const sw_seam_vertex *vx = &g->vertices[v];
    if (v >= g->original_count) {
        if (vx->slot_ref_count)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: created vertex %u has %u slot_refs, expected 0", v,
                                vx->slot_ref_count);
        return SW_OK;
    }
    if (!vx->slot_ref_count || vx->first_slot_ref > g->slot_ref_count ||
        vx->slot_ref_count > g->slot_ref_count - vx->first_slot_ref)
        return sw_error_set(err, SW_ERR_RANGE,
                            "seam graph: vertex %u slot_refs [%u, +%u), expected a non-empty "
                            "range inside %u", v, vx->first_slot_ref, vx->slot_ref_count,
                            g->slot_ref_count);
    for (uint32_t r = 0; r < vx->slot_ref_count; r++) {
        uint32_t slot = g->slot_refs[vx->first_slot_ref + r];
        if (slot >= g->slot_count || g->slots[slot].vertex != v)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: vertex %u slot_ref %u names slot %u, which does "
                                "not hold it", v, vx->first_slot_ref + r, slot);
    }
    return SW_OK;
}

static sw_status check_vertices(const sw_seam_graph *g, sw_error *err)
{
    for (uint32_t v = 0; v < g->vertex_count; v++) {
        const sw_seam_vertex *vx = &g->vertices[v];
        if (!finite3(vx->p) || !isfinite(vx->error) || vx->error < 0.0f || vx->reserved)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: vertex %u: position or error not finite, error "
                                "negative or reserved not zero", v);
        if (v < g->original_count && vx->error != 0.0f)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: original vertex %u has error %g, expected 0", v,
                                (double)vx->error);
        if (vx->child != SW_SEAM_NONE) {
            if (vx->child <= v || vx->child >= g->vertex_count)
                return sw_error_set(err, SW_ERR_RANGE,
                                    "seam graph: vertex %u has child %u, expected in (%u, %u)",
                                    v, vx->child, v, g->vertex_count);
            const sw_seam_collapse *c = &g->collapses[vx->child - g->original_count];
            if (c->v1 != v && c->v2 != v)
                return sw_error_set(err, SW_ERR_FORMAT,
                                    "seam graph: vertex %u has child %u, whose collapse merges "
                                    "%u and %u", v, vx->child, c->v1, c->v2);
        }
        sw_status st = check_vertex_slots(g, v, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

static sw_status check_collapses(const sw_seam_graph *g, sw_error *err)
{
    for (uint32_t k = 0; k < g->collapse_count; k++) {
        const sw_seam_collapse *c = &g->collapses[k];
        uint32_t vn = g->original_count + k;
        if (c->v1 == c->v2 || c->v1 >= vn || c->v2 >= vn)
            return sw_error_set(err, SW_ERR_RANGE,
                                "seam graph: collapse %u merges %u and %u, expected two "
                                "different vertices < %u", k, c->v1, c->v2, vn);
        if (g->vertices[c->v1].child != vn || g->vertices[c->v2].child != vn)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: collapse %u: vertices %u and %u have children "
                                "%u and %u, expected %u", k, c->v1, c->v2,
                                g->vertices[c->v1].child, g->vertices[c->v2].child, vn);
        float e = g->vertices[vn].error;
        if (!isfinite(c->error) || c->error < 0.0f || e < c->error ||
            e < g->vertices[c->v1].error || e < g->vertices[c->v2].error)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "seam graph: collapse %u: error %g, vertex %u error %g, "
                                "expected monotone (>= the step's and the parents')", k,
                                (double)c->error, vn, (double)e);
    }
    return SW_OK;
}

sw_status sw_seam_graph_check(const sw_seam_graph *graph, sw_error *err)
{
    if (!graph)
        return sw_error_set(err, SW_ERR_ARG, "seam graph: no graph");
    sw_status st = check_arrays(graph, err);
    if (st == SW_OK)
        st = check_loops(graph, err);
    if (st == SW_OK)
        st = check_slots(graph, err);
    if (st == SW_OK)
        st = check_collapses(graph, err);
    if (st == SW_OK)
        st = check_vertices(graph, err);
    return st;
}
