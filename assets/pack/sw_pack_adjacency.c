/* SPDX-License-Identifier: MIT */
/* Adjacency by matching boundary control rows. Edges are entered in a hash
 * grid keyed on the cell of their first endpoint; each edge then looks up the
 * cells around both of its endpoints (first endpoint: same order, last
 * endpoint: reversed), so candidates come in O(1) each and only they get the
 * full row comparison. Cells are 4 tolerances wide, so the tolerance window
 * of a point spans at most 2 cells per axis. */
#include "sw_pack_adjacency.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define WEIGHT_RELATIVE_TOLERANCE 1e-9
#define POSITION_TOLERANCE 1e-9 /* of the box diagonal */

enum { EMPTY_SLOT = UINT32_MAX };

typedef struct edge_rec {
    int64_t cell[3];   /* of the first endpoint */
    uint32_t patch;
    uint8_t edge;      /* enum sw_patch_edge */
} edge_rec;

typedef struct finder {
    const sw_model *model;
    double tol, cell_size, origin[3];
    edge_rec *edges;
    uint32_t edge_count;
    uint32_t *slots;   /* open addressing, linear probing; edge index or EMPTY_SLOT */
    size_t mask;
    sw_pack_adjacency *pairs;
    size_t pair_count, pair_capacity;
} finder;

/* Point k of edge: edges run in the direction of increasing parameter (see
 * PACK_FORMAT.md, "Edges"). */
static const double *edge_point(const sw_model_patch *p, int edge, int k)
{
    int i = k, j = k;
    switch (edge) {
    case SW_EDGE_V0: j = 0; break;
    case SW_EDGE_U1: i = p->degree_u; break;
    case SW_EDGE_V1: j = p->degree_v; break;
    default: i = 0; break;
    }
    return &p->ctrl[((size_t)j * (size_t)(p->degree_u + 1) + (size_t)i) * 4];
}

static int edge_length(const sw_model_patch *p, int edge)
{
    return (edge == SW_EDGE_V0 || edge == SW_EDGE_V1) ? p->degree_u + 1 : p->degree_v + 1;
}

static int positions_close(const double *a, const double *b, double tol)
{
    return fabs(a[0] - b[0]) <= tol && fabs(a[1] - b[1]) <= tol && fabs(a[2] - b[2]) <= tol;
}

static int rows_match(const finder *f, const edge_rec *a, const edge_rec *b, int reversed)
{
    const sw_model_patch *pa = &f->model->patches[a->patch], *pb = &f->model->patches[b->patch];
    int n = edge_length(pa, a->edge);
    if (n != edge_length(pb, b->edge))
        return 0;
    for (int k = 0; k < n; k++) {
        const double *x = edge_point(pa, a->edge, k);
        const double *y = edge_point(pb, b->edge, reversed ? n - 1 - k : k);
        double wx = pa->rational ? x[3] : 1.0, wy = pb->rational ? y[3] : 1.0;
        if (!positions_close(x, y, f->tol) ||
            !(fabs(wx - wy) <= WEIGHT_RELATIVE_TOLERANCE * fmax(fabs(wx), fabs(wy))))
            return 0;
    }
    return 1;
}

static int edge_collapsed(const finder *f, const sw_model_patch *p, int edge)
{
    const double *first = edge_point(p, edge, 0);
    for (int k = 1; k < edge_length(p, edge); k++)
        if (!positions_close(first, edge_point(p, edge, k), f->tol))
            return 0;
    return 1;
}

static int64_t cell_coord(const finder *f, double x, int axis)
{
    double c = floor((x - f->origin[axis]) / f->cell_size);
    /* Within the box c is at most 2.5e8; clamp anyway, since converting an
     * out-of-range double to an integer is undefined behaviour. */
    return c > -4e18 ? (c < 4e18 ? (int64_t)c : (int64_t)4e18) : (int64_t)-4e18;
}

static size_t cell_hash(const int64_t c[3])
{
    uint64_t h = (uint64_t)c[0] * 0x9E3779B97F4A7C15u ^ (uint64_t)c[1] * 0xC2B2AE3D27D4EB4Fu ^
                 (uint64_t)c[2] * 0x165667B19E3779F9u;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9u;
    return (size_t)(h ^ (h >> 29));
}

static int add_pair(finder *f, const edge_rec *a, const edge_rec *b, int reversed)
{
    /* A pair can be reached twice (through both endpoint queries): keep one.
     * a's pairs are the most recent ones, so only they need scanning. */
    for (size_t k = f->pair_count; k-- > 0;) {
        const sw_pack_adjacency *q = &f->pairs[k];
        if (q->patch_a != a->patch || q->edge_a != a->edge)
            break;
        if (q->patch_b == b->patch && q->edge_b == b->edge)
            return 0;
    }
    if (f->pair_count == f->pair_capacity) {
        size_t cap = f->pair_capacity ? 2 * f->pair_capacity : 1024;
        sw_pack_adjacency *grown = realloc(f->pairs, cap * sizeof *grown);
        if (!grown)
            return -1;
        f->pairs = grown;
        f->pair_capacity = cap;
    }
    f->pairs[f->pair_count++] = (sw_pack_adjacency){ .patch_a = a->patch, .patch_b = b->patch,
                                                     .edge_a = a->edge, .edge_b = b->edge,
                                                     .reversed = (uint8_t)reversed };
    return 0;
}

/* Every edge after a whose first endpoint lies in cell c and whose row
 * matches a's. Later edges only: each pair is found from its first edge. */
static int visit_cell(finder *f, uint32_t a_index, const int64_t c[3])
{
    const edge_rec *a = &f->edges[a_index];
    for (size_t s = cell_hash(c) & f->mask; f->slots[s] != EMPTY_SLOT; s = (s + 1) & f->mask) {
        const edge_rec *b = &f->edges[f->slots[s]];
        if (f->slots[s] <= a_index || b->patch == a->patch || memcmp(b->cell, c, sizeof b->cell))
            continue;
        int reversed = rows_match(f, a, b, 0) ? 0 : rows_match(f, a, b, 1) ? 1 : -1;
        if (reversed >= 0 && add_pair(f, a, b, reversed) != 0)
            return -1;
    }
    return 0;
}

/* The cells that b's first endpoint may lie in if it is within tol of q. */
static int visit_near(finder *f, uint32_t a_index, const double *q)
{
    int64_t lo[3], hi[3], c[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = cell_coord(f, q[k] - f->tol, k);
        hi[k] = cell_coord(f, q[k] + f->tol, k);
    }
    for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
        for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
            for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
                if (visit_cell(f, a_index, c) != 0)
                    return -1;
    return 0;
}

/* Origin and tolerance from the box of every control point. */
static void measure(finder *f)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (size_t i = 0; i < f->model->patch_count; i++) {
        const sw_model_patch *p = &f->model->patches[i];
        size_t n = (size_t)(p->degree_u + 1) * (size_t)(p->degree_v + 1);
        for (size_t k = 0; k < n * 4; k++) {
            if (k % 4 == 3)
                continue;
            lo[k % 4] = fmin(lo[k % 4], p->ctrl[k]);
            hi[k % 4] = fmax(hi[k % 4], p->ctrl[k]);
        }
    }
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        f->origin[k] = lo[k];
        d2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    f->tol = POSITION_TOLERANCE * sqrt(d2);
    f->cell_size = 4 * f->tol;
}

/* Collects the non-collapsed edges and enters them in the hash grid. */
static int build_grid(finder *f)
{
    size_t n = f->model->patch_count * 4;
    size_t cap = 16;
    while (cap < 2 * n)
        cap *= 2;
    f->edges = malloc((n ? n : 1) * sizeof *f->edges);
    f->slots = malloc(cap * sizeof *f->slots);
    if (!f->edges || !f->slots)
        return -1;
    memset(f->slots, 0xFF, cap * sizeof *f->slots); /* EMPTY_SLOT */
    f->mask = cap - 1;
    for (size_t i = 0; i < f->model->patch_count; i++) {
        const sw_model_patch *p = &f->model->patches[i];
        for (int e = 0; e < 4; e++) {
            if (edge_collapsed(f, p, e))
                continue;
            edge_rec *r = &f->edges[f->edge_count];
            *r = (edge_rec){ .patch = (uint32_t)i, .edge = (uint8_t)e };
            const double *p0 = edge_point(p, e, 0);
            for (int k = 0; k < 3; k++)
                r->cell[k] = cell_coord(f, p0[k], k);
            size_t s = cell_hash(r->cell) & f->mask;
            while (f->slots[s] != EMPTY_SLOT)
                s = (s + 1) & f->mask;
            f->slots[s] = f->edge_count++;
        }
    }
    return 0;
}

static int compare_pairs(const void *x, const void *y)
{
    const sw_pack_adjacency *a = x, *b = y;
    uint64_t ka = (uint64_t)a->patch_a << 34 | (uint64_t)a->edge_a << 32 | a->patch_b;
    uint64_t kb = (uint64_t)b->patch_a << 34 | (uint64_t)b->edge_a << 32 | b->patch_b;
    if (ka != kb)
        return ka < kb ? -1 : 1;
    return (a->edge_b > b->edge_b) - (a->edge_b < b->edge_b);
}

static int find_pairs(finder *f)
{
    for (uint32_t a = 0; a < f->edge_count; a++) {
        const sw_model_patch *p = &f->model->patches[f->edges[a].patch];
        int e = f->edges[a].edge;
        if (visit_near(f, a, edge_point(p, e, 0)) != 0 ||
            visit_near(f, a, edge_point(p, e, edge_length(p, e) - 1)) != 0)
            return -1;
    }
    return 0;
}

sw_status sw_pack_find_adjacency(const sw_model *model, sw_pack_adjacency **out, uint32_t *count,
                                 sw_error *err)
{
    *out = NULL;
    *count = 0;
    finder f = { .model = model };
    measure(&f);
    /* No extent (or no patches): every edge is collapsed, nothing can match. */
    if (!(f.tol > 0) || !isfinite(f.tol))
        return SW_OK;
    int failed = build_grid(&f) != 0 || find_pairs(&f) != 0;
    free(f.edges);
    free(f.slots);
    if (failed) {
        free(f.pairs);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "adjacency: out of memory for %zu patches",
                            model->patch_count);
    }
    if (f.pair_count > UINT32_MAX) {
        free(f.pairs);
        return sw_error_set(err, SW_ERR_RANGE, "adjacency: %zu pairs, a pack holds at most %u",
                            f.pair_count, UINT32_MAX);
    }
    if (f.pair_count > 1) /* pairs is NULL when none were found */
        qsort(f.pairs, f.pair_count, sizeof *f.pairs, compare_pairs);
    *out = f.pairs;
    *count = (uint32_t)f.pair_count;
    return SW_OK;
}
