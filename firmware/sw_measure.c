#include "sw_measure.h"

#include <math.h>

#include "sw_cell_filter.h"

size_t sw_measure_arena_bytes(void)
{
    return 2 * sw_arena_worst_case(SW_BATCH_VERTICES * sizeof(sw_vertex), 64) +
           sw_arena_worst_case(SW_BATCH_INDICES * sizeof(uint16_t), 64);
}

sw_status sw_measure_init(sw_measure *m, sw_arena *arena, const sw_pack *pack, sw_error *err)
{
    m->grid_a = sw_arena_alloc(arena, SW_BATCH_VERTICES * sizeof(sw_vertex), 64);
    m->grid_b = sw_arena_alloc(arena, SW_BATCH_VERTICES * sizeof(sw_vertex), 64);
    m->indices = sw_arena_alloc(arena, SW_BATCH_INDICES * sizeof(uint16_t), 64);
    if (!m->grid_a || !m->grid_b || !m->indices)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the measurement buffers");
    const float *lo = pack->meta->box_min, *hi = pack->meta->box_max;
    double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    m->crack_tolerance = 1e-6 * sqrt(dx * dx + dy * dy + dz * dz);
    return SW_OK;
}

static sw_vec3 vertex_pos(const sw_vertex *v)
{
    return sw_v3(v->pos[0], v->pos[1], v->pos[2]);
}

typedef struct grid_sampler {
    const sw_bezier_patch *patch;
    const sw_vertex *grid;
    uint32_t nu, nv;
    const sw_view *view;
    sw_stats *stats;
} grid_sampler;

/* One sample: parameters (u, v) in grid units, and the flat triangle's point
 * there as a weighted sum of up to three grid vertices. */
static void sample(const grid_sampler *g, double a, double b, const uint32_t idx[3],
                   const double w[3])
{
    sw_surface_point sp;
    sw_bezier_eval(g->patch, a / g->nu, b / g->nv, SW_EVAL_POINT, &sp);
    sw_vec3 flat = sw_v3(0, 0, 0);
    for (int k = 0; k < 3; k++)
        if (w[k] != 0.0)
            flat = sw_v3_add(flat, sw_v3_scale(vertex_pos(&g->grid[idx[k]]), w[k]));
    double depth = sw_view_depth(g->view, sp.p);
    if (depth < g->view->near_z)
        depth = g->view->near_z;
    double px = sw_v3_length(sw_v3_sub(sp.p, flat)) * g->view->px_per_unit / depth;
    sw_stats_add_error_px(g->stats, px);
}

/* Each cell (a, b) is triangles (v00, v10, v11) and (v00, v11, v01) (sw_tess.h).
 * Edge midpoints shared by two triangles have the same flat point on both, so
 * each is sampled once: the bottom and left edges of every cell (plus the top
 * row and right column), the diagonal, and the two centroids. */
static void sample_cell(const grid_sampler *g, uint32_t a, uint32_t b)
{
    uint32_t row = g->nu + 1;
    uint32_t v00 = b * row + a, v10 = v00 + 1, v01 = v00 + row, v11 = v01 + 1;
    const double half[3] = { 0.5, 0.5, 0.0 }, third[3] = { 1.0 / 3, 1.0 / 3, 1.0 / 3 };
    sample(g, a + 0.5, b, (uint32_t[3]){ v00, v10, 0 }, half);
    sample(g, a, b + 0.5, (uint32_t[3]){ v00, v01, 0 }, half);
    sample(g, a + 0.5, b + 0.5, (uint32_t[3]){ v00, v11, 0 }, half);
    sample(g, a + 2.0 / 3, b + 1.0 / 3, (uint32_t[3]){ v00, v10, v11 }, third);
    sample(g, a + 1.0 / 3, b + 2.0 / 3, (uint32_t[3]){ v00, v11, v01 }, third);
    if (b + 1 == g->nv)
        sample(g, a + 0.5, b + 1, (uint32_t[3]){ v01, v11, 0 }, half);
    if (a + 1 == g->nu)
        sample(g, a + 1, b + 0.5, (uint32_t[3]){ v10, v11, 0 }, half);
}

void sw_measure_error(sw_measure *m, const sw_walk *walk, const sw_view *view, sw_stats *stats)
{
    double ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    for (uint32_t i = 0; i < walk->pack->meta->patch_count; i++) {
        const sw_patch_state *s = &walk->state[i];
        if (!s->visible)
            continue;
        sw_bezier_patchf pf = sw_walk_patch(walk, i);
        sw_bezier_patch exact = sw_bezier_patch_from_float(&pf, ctrl);
        sw_tess_grid(&pf, s->nu, s->nv, 0, m->grid_a, m->indices);
        grid_sampler g = { &exact, m->grid_a, s->nu, s->nv, view, stats };
        sw_cell_filter filter; /* only the triangles the frame drew */
        sw_cell_filter_init(&filter, sw_walk_patch_mask(walk, i), s->nu, s->nv);
        for (uint32_t b = 0; b < s->nv; b++)
            for (uint32_t a = 0; a < s->nu; a++)
                if (sw_cell_filter_keep(&filter, a, b))
                    sample_cell(&g, a, b);
    }
    stats->measured_frames++;
}

/* Grid vertex indices along an edge (sw_patch_edge), in order. */
static uint32_t edge_vertex(uint32_t edge, uint32_t k, uint32_t nu, uint32_t nv)
{
    uint32_t row = nu + 1;
    switch (edge) {
    case SW_EDGE_V0: return k;
    case SW_EDGE_U1: return k * row + nu;
    case SW_EDGE_V1: return nv * row + k;
    default: return k * row;
    }
}

static uint32_t edge_length(uint32_t edge, uint32_t nu, uint32_t nv)
{
    return (edge == SW_EDGE_V0 || edge == SW_EDGE_V1 ? nu : nv) + 1;
}

typedef struct grid_edge {
    const sw_vertex *grid;
    uint32_t edge, nu, nv;
} grid_edge;

static sw_vec3 edge_point(const grid_edge *e, uint32_t k)
{
    return vertex_pos(&e->grid[edge_vertex(e->edge, k, e->nu, e->nv)]);
}

/* Vertices of `from` farther than tol from every segment of `onto`. */
static uint64_t off_polyline(const grid_edge *from, const grid_edge *onto, double tol)
{
    uint32_t n_from = edge_length(from->edge, from->nu, from->nv);
    uint32_t n_onto = edge_length(onto->edge, onto->nu, onto->nv);
    uint64_t off = 0;
    for (uint32_t k = 0; k < n_from; k++) {
        sw_vec3 p = edge_point(from, k);
        int on = 0;
        for (uint32_t s = 0; s + 1 < n_onto && !on; s++)
            on = sw_v3_segment_distance(p, edge_point(onto, s), edge_point(onto, s + 1)) <= tol;
        off += !on;
    }
    return off;
}

uint64_t sw_measure_cracks(sw_measure *m, const sw_walk *walk)
{
    uint64_t cracks = 0;
    for (uint32_t i = 0; i < walk->pack->meta->adjacency_count; i++) {
        const sw_pack_adjacency *adj = &walk->pack->adjacency[i];
        const sw_patch_state *sa = &walk->state[adj->patch_a], *sb = &walk->state[adj->patch_b];
        if (!sa->visible || !sb->visible)
            continue;
        sw_bezier_patchf pa = sw_walk_patch(walk, adj->patch_a);
        sw_bezier_patchf pb = sw_walk_patch(walk, adj->patch_b);
        sw_tess_grid(&pa, sa->nu, sa->nv, 0, m->grid_a, m->indices);
        sw_tess_grid(&pb, sb->nu, sb->nv, 0, m->grid_b, m->indices);
        grid_edge ea = { m->grid_a, adj->edge_a, sa->nu, sa->nv };
        grid_edge eb = { m->grid_b, adj->edge_b, sb->nu, sb->nv };
        cracks += off_polyline(&ea, &eb, m->crack_tolerance);
        cracks += off_polyline(&eb, &ea, m->crack_tolerance);
    }
    return cracks;
}
