/* SPDX-License-Identifier: MIT */
#include "sw_seam_drawn.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pow2.h"

#define CELL_BITS 21
#define CELL_MAX ((1u << CELL_BITS) - 1u)
#define FIRST_WINDS_UP 0x80000000u /* edge_uses: first seen as low -> high index */

size_t sw_seam_drawn_arena_bytes(uint32_t max_edges, uint32_t max_mesh_indices)
{
    size_t table = sw_pow2_at_least(2 * max_mesh_indices, 16);
    return sw_arena_worst_case((size_t)max_edges * sizeof(sw_seam_drawn_edge), 64) +
           sw_arena_worst_case(4 * (size_t)max_edges * sizeof(sw_seam_drawn_cell), 64) +
           2 * sw_arena_worst_case(table * sizeof(uint32_t), 64);
}

sw_status sw_seam_drawn_init(sw_seam_drawn *d, const sw_box *box, double reach,
                             uint32_t max_edges, uint32_t max_mesh_indices, sw_arena *arena,
                             sw_error *err)
{
    memset(d, 0, sizeof *d);
    d->max_edges = max_edges;
    d->max_cells = 4 * max_edges;
    d->edge_table = sw_pow2_at_least(2 * max_mesh_indices, 16);
    d->edges = sw_arena_alloc(arena, (size_t)max_edges * sizeof *d->edges, 64);
    d->cells = sw_arena_alloc(arena, (size_t)d->max_cells * sizeof *d->cells, 64);
    d->edge_keys = sw_arena_alloc(arena, d->edge_table * sizeof(uint32_t), 64);
    d->edge_uses = sw_arena_alloc(arena, d->edge_table * sizeof(uint32_t), 64);
    if (!d->edges || !d->cells || !d->edge_keys || !d->edge_uses)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the drawn-seam check "
                            "(needs %zu bytes)",
                            sw_seam_drawn_arena_bytes(max_edges, max_mesh_indices));
    /* Float positions are good to an ulp of the largest coordinate; what
     * lies within a few of them of a border is on it. */
    double big = fmax(fmax(fabs(box->min.x), fabs(box->max.x)),
                      fmax(fmax(fabs(box->min.y), fabs(box->max.y)),
                           fmax(fabs(box->min.z), fabs(box->max.z))));
    double diag = sw_v3_length(sw_v3_sub(box->max, box->min));
    d->tolerance = 8.0 * FLT_EPSILON * big + 1e-9 * diag;
    d->reach = fmax(reach, 4.0 * d->tolerance);
    d->origin = box->min;
    return SW_OK;
}

void sw_seam_drawn_begin(sw_seam_drawn *d)
{
    d->edge_count = d->cell_count = 0;
    d->overflow = 0;
}

/* Counts the use of edge a-b in the mesh's table (size a power of 2). */
static void use_edge(sw_seam_drawn *d, uint32_t size, uint16_t a, uint16_t b)
{
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a, key = (lo << 16 | hi) + 1;
    uint32_t i = (key * 2654435761u) & (size - 1);
    while (d->edge_keys[i] && d->edge_keys[i] != key)
        i = (i + 1) & (size - 1);
    if (!d->edge_keys[i]) {
        d->edge_keys[i] = key;
        d->edge_uses[i] = a < b ? FIRST_WINDS_UP : 0;
    }
    d->edge_uses[i]++;
}

void sw_seam_drawn_add_mesh(sw_seam_drawn *d, uint32_t surface, const sw_seam_mesh *mesh)
{
    uint32_t size = sw_pow2_at_least(2 * mesh->index_count, 16);
    if (size > d->edge_table) {
        d->overflow = 1;
        return;
    }
    memset(d->edge_keys, 0, size * sizeof(uint32_t));
    for (uint32_t t = 0; t + 2 < mesh->index_count; t += 3)
        for (int k = 0; k < 3; k++)
            use_edge(d, size, mesh->indices[t + k], mesh->indices[t + (k + 1) % 3]);
    for (uint32_t i = 0; i < size; i++) {
        if (!d->edge_keys[i] || (d->edge_uses[i] & ~FIRST_WINDS_UP) != 1)
            continue;
        if (d->edge_count == d->max_edges) {
            d->overflow = 1;
            return;
        }
        uint32_t key = d->edge_keys[i] - 1, lo = key >> 16, hi = key & 0xFFFFu;
        int up = (d->edge_uses[i] & FIRST_WINDS_UP) != 0;
        sw_seam_drawn_edge *e = &d->edges[d->edge_count++];
        memcpy(e->p, mesh->verts[up ? lo : hi].pos, sizeof e->p);
        memcpy(e->q, mesh->verts[up ? hi : lo].pos, sizeof e->q);
        e->surface = surface;
    }
}

static uint32_t cell_index(double x, double origin, double size)
{
    double c = floor((x - origin) / size);
    return c < 0 ? 0 : c > CELL_MAX ? CELL_MAX : (uint32_t)c;
}

static uint64_t cell_key(uint32_t x, uint32_t y, uint32_t z)
{
    return (uint64_t)x << (2 * CELL_BITS) | (uint64_t)y << CELL_BITS | z;
}

static uint64_t cell_of(const sw_seam_drawn *d, sw_vec3 p)
{
    return cell_key(cell_index(p.x, d->origin.x, d->cell_size),
                    cell_index(p.y, d->origin.y, d->cell_size),
                    cell_index(p.z, d->origin.z, d->cell_size));
}

static int compare_cells(const void *a, const void *b)
{
    const sw_seam_drawn_cell *x = a, *y = b;
    if (x->cell != y->cell)
        return x->cell < y->cell ? -1 : 1;
    return x->edge < y->edge ? -1 : x->edge > y->edge;
}

static sw_vec3 vec_of(const float p[3]) { return sw_v3(p[0], p[1], p[2]); }

/* Every edge into the cells it passes (sampled at half a cell, so none is
 * skipped), cells sorted. Cell size: twice the mean border edge, so an edge
 * spans a few cells and a cell holds a few edges. 0 on overflow. */
static int bin_edges(sw_seam_drawn *d)
{
    double total = 0;
    for (uint32_t i = 0; i < d->edge_count; i++)
        total += sw_v3_length(sw_v3_sub(vec_of(d->edges[i].q), vec_of(d->edges[i].p)));
    d->cell_size = d->edge_count && total > 0 ? 2.0 * total / d->edge_count : 1.0;
    d->cell_size = fmax(d->cell_size, 4.0 * d->reach);
    for (uint32_t i = 0; i < d->edge_count; i++) {
        sw_vec3 p = vec_of(d->edges[i].p), q = vec_of(d->edges[i].q);
        double len = sw_v3_length(sw_v3_sub(q, p));
        uint32_t n = (uint32_t)ceil(len / (0.5 * d->cell_size));
        uint64_t last = UINT64_MAX;
        for (uint32_t k = 0; k <= n; k++) {
            double t = n ? (double)k / n : 0.0;
            uint64_t c = cell_of(d, sw_v3_add(p, sw_v3_scale(sw_v3_sub(q, p), t)));
            if (c == last)
                continue;
            if (d->cell_count == d->max_cells)
                return 0;
            d->cells[d->cell_count++] = (sw_seam_drawn_cell){ c, i };
            last = c;
        }
    }
    qsort(d->cells, d->cell_count, sizeof *d->cells, compare_cells);
    return 1;
}

static double segment_distance(sw_vec3 p, sw_vec3 a, sw_vec3 b)
{
    sw_vec3 ab = sw_v3_sub(b, a);
    double len2 = sw_v3_dot(ab, ab);
    double t = len2 > 0 ? sw_v3_dot(sw_v3_sub(p, a), ab) / len2 : 0.0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return sw_v3_length(sw_v3_sub(p, sw_v3_add(a, sw_v3_scale(ab, t))));
}

/* What the borders of other surfaces near a point say about it. */
typedef struct nearby {
    uint32_t surface[32];
    uint8_t vertex[32], on_edge[32];
    int count;
    double nearest;
} nearby;

static void note(nearby *n, uint32_t surface, int is_vertex, int on_edge)
{
    int i = 0;
    while (i < n->count && n->surface[i] != surface)
        i++;
    if (i == n->count) {
        if (n->count == 32)
            return;
        n->surface[i] = surface, n->vertex[i] = 0, n->on_edge[i] = 0, n->count++;
    }
    n->vertex[i] |= (uint8_t)is_vertex;
    n->on_edge[i] |= (uint8_t)on_edge;
}

static void look_in_cell(const sw_seam_drawn *d, uint64_t key, const sw_seam_drawn_edge *me,
                         nearby *n)
{
    uint32_t lo = 0, hi = d->cell_count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (d->cells[mid].cell < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    sw_vec3 p = vec_of(me->p);
    for (uint32_t i = lo; i < d->cell_count && d->cells[i].cell == key; i++) {
        const sw_seam_drawn_edge *e = &d->edges[d->cells[i].edge];
        if (e->surface == me->surface)
            continue;
        int is_vertex = !memcmp(e->p, me->p, sizeof e->p) || !memcmp(e->q, me->p, sizeof e->q);
        double dist = is_vertex ? 0.0 : segment_distance(p, vec_of(e->p), vec_of(e->q));
        n->nearest = fmin(n->nearest, dist);
        if (is_vertex || dist <= d->tolerance)
            note(n, e->surface, is_vertex, !is_vertex);
    }
}

/* The edge's first point against the other borders in the 27 cells around it. */
static void classify(const sw_seam_drawn *d, const sw_seam_drawn_edge *e, sw_seam_drawn_result *r)
{
    nearby n = { .count = 0, .nearest = INFINITY };
    sw_vec3 p = vec_of(e->p);
    uint32_t cx = cell_index(p.x, d->origin.x, d->cell_size);
    uint32_t cy = cell_index(p.y, d->origin.y, d->cell_size);
    uint32_t cz = cell_index(p.z, d->origin.z, d->cell_size);
    for (int k = 0; k < 27; k++) {
        int64_t x = (int64_t)cx + k % 3 - 1, y = (int64_t)cy + k / 3 % 3 - 1,
                z = (int64_t)cz + k / 9 - 1;
        if (x >= 0 && y >= 0 && z >= 0 && x <= CELL_MAX && y <= CELL_MAX && z <= CELL_MAX)
            look_in_cell(d, cell_key((uint32_t)x, (uint32_t)y, (uint32_t)z), e, &n);
    }
    r->points++;
    int t_vertex = 0;
    for (int i = 0; i < n.count; i++)
        t_vertex |= n.on_edge[i] && !n.vertex[i];
    if (t_vertex)
        r->t_vertices++;
    else if (n.count)
        r->shared++;
    else if (n.nearest <= d->reach)
        r->gaps++;
    else
        r->free_points++;
}

void sw_seam_drawn_check(sw_seam_drawn *d, sw_seam_drawn_result *r)
{
    memset(r, 0, sizeof *r);
    if (d->overflow || !bin_edges(d)) {
        d->overflow = 1;
        return;
    }
    /* Each border point starts exactly one border edge (the edges follow
     * their triangles' winding round the border), so it is checked once. */
    for (uint32_t i = 0; i < d->edge_count; i++)
        classify(d, &d->edges[i], r);
    r->checked = 1;
}
