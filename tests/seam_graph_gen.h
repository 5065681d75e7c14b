/* SPDX-License-Identifier: MIT */
/* Synthetic Seam Graphs for the seam LOD tests and the benchmark, built as
 * the sewing would leave them (original vertices only): a grid of square
 * surfaces sewn along their shared sides, optionally a hole in each square,
 * a fin standing on one seam (three surfaces on it: non-manifold) and a
 * free surface whose loop is a random-ish closed polyline (a connected part
 * of its own). Host side: malloc, freed by sw_seam_host_free. */
#ifndef SEAM_GRAPH_GEN_H
#define SEAM_GRAPH_GEN_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_seam_build.h"

#define GEN_PI 3.14159265358979323846

typedef struct seam_gen {
    uint32_t nx, ny, k;    /* squares across, down; segments per side */
    int holes;             /* a hole loop of 6 vertices in every square */
    int fin;               /* a fin on the seam between squares (0,0) and (1,0) (nx >= 2) */
    uint32_t free_points;  /* > 0: a free surface with a loop of this many points */
    float bumps;           /* height of the z noise */
    uint64_t seed;
} seam_gen;

typedef struct gen_buf {
    sw_seam_host *g;
    uint32_t vcap, scap, lcap, surf_cap;
    uint64_t rng;
} gen_buf;

static double gen_rand(gen_buf *b)
{
    b->rng ^= b->rng >> 12, b->rng ^= b->rng << 25, b->rng ^= b->rng >> 27;
    return (double)((b->rng * 2685821657736338717ull) >> 11) * (1.0 / 9007199254740992.0);
}

static void *gen_grow(void *p, uint32_t *cap, uint32_t need, size_t size)
{
    if (need <= *cap)
        return p;
    while (*cap < need)
        *cap = *cap ? *cap * 2 : 64;
    void *q = realloc(p, (size_t)*cap * size);
    if (!q)
        abort();
    return q;
}

static uint32_t gen_vertex(gen_buf *b, double x, double y, double z)
{
    sw_seam_host *g = b->g;
    g->vertices = gen_grow(g->vertices, &b->vcap, g->vertex_count + 1, sizeof *g->vertices);
    g->vertices[g->vertex_count] =
        (sw_seam_vertex){{(float)x, (float)y, (float)z}, SW_SEAM_NONE, 0.0f, 0, 0, 0};
    return g->vertex_count++;
}

static void gen_begin_loop(gen_buf *b, uint32_t surface, uint32_t flags)
{
    sw_seam_host *g = b->g;
    g->loops = gen_grow(g->loops, &b->lcap, g->loop_count + 1, sizeof *g->loops);
    g->loops[g->loop_count++] = (sw_seam_loop){surface, g->slot_count, 0, flags};
}

static void gen_slot(gen_buf *b, uint32_t v, double u, double w)
{
    sw_seam_host *g = b->g;
    g->slots = gen_grow(g->slots, &b->scap, g->slot_count + 1, sizeof *g->slots);
    g->slots[g->slot_count++] = (sw_seam_slot){v, {(float)u, (float)w}};
    g->loops[g->loop_count - 1].slot_count++;
}

static int gen_cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* surface_loops, slot_refs and edges from the loops, as sewing leaves them. */
static void gen_finish(gen_buf *b, uint32_t surface_count)
{
    sw_seam_host *g = b->g;
    g->original_count = g->vertex_count;
    g->surface_count = surface_count;
    g->surface_loops = calloc((size_t)surface_count + 1, sizeof *g->surface_loops);
    for (uint32_t l = 0; l < g->loop_count; l++)
        g->surface_loops[g->loops[l].surface + 1] = l + 1;
    for (uint32_t s = 1; s <= surface_count; s++)
        if (g->surface_loops[s] < g->surface_loops[s - 1])
            g->surface_loops[s] = g->surface_loops[s - 1];
    uint32_t *fill = calloc((size_t)g->vertex_count + 1, sizeof *fill);
    for (uint32_t i = 0; i < g->slot_count; i++)
        g->vertices[g->slots[i].vertex].slot_ref_count++;
    for (uint32_t v = 0, at = 0; v < g->vertex_count; v++) {
        g->vertices[v].first_slot_ref = at;
        at += g->vertices[v].slot_ref_count;
    }
    g->slot_refs = malloc(((size_t)g->slot_count + 1) * sizeof *g->slot_refs);
    for (uint32_t i = 0; i < g->slot_count; i++) {
        uint32_t v = g->slots[i].vertex;
        g->slot_refs[g->vertices[v].first_slot_ref + fill[v]++] = i;
    }
    g->slot_ref_count = g->slot_count;
    free(fill);
    /* edges: every consecutive distinct pair once (a square's side is in two loops) */
    g->edges = malloc(((size_t)g->slot_count + 1) * sizeof *g->edges);
    uint64_t *keys = malloc(((size_t)g->slot_count + 1) * sizeof *keys);
    uint32_t n = 0;
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *lp = &g->loops[l];
        for (uint32_t i = 0; i < lp->slot_count; i++) {
            uint32_t a = g->slots[lp->first_slot + i].vertex;
            uint32_t c = g->slots[lp->first_slot + (i + 1) % lp->slot_count].vertex;
            if (a != c)
                keys[n++] = a < c ? (uint64_t)a << 32 | c : (uint64_t)c << 32 | a;
        }
    }
    qsort(keys, n, sizeof *keys, gen_cmp_u64);
    for (uint32_t i = 0; i < n; i++)
        if (!i || keys[i] != keys[i - 1])
            g->edges[g->edge_count++] = (sw_seam_edge){(uint32_t)(keys[i] >> 32), (uint32_t)keys[i]};
    free(keys);
}

static double gen_height(const seam_gen *p, gen_buf *b, double x, double y)
{
    return p->bumps * (0.6 * sin(1.7 * x + 0.3) * cos(1.1 * y) + 0.4 * (gen_rand(b) - 0.5));
}

/* Lattice vertex (i, j) of the grid (on a line of it), made on first use. */
static uint32_t gen_lattice(const seam_gen *p, gen_buf *b, uint32_t *ids, uint32_t i, uint32_t j)
{
    uint32_t *id = &ids[(size_t)j * (p->nx * p->k + 1) + i];
    if (*id == SW_SEAM_NONE)
        *id = gen_vertex(b, (double)i / p->k, (double)j / p->k,
                         gen_height(p, b, (double)i / p->k, (double)j / p->k));
    return *id;
}

static void gen_square(const seam_gen *p, gen_buf *b, uint32_t *ids, uint32_t cx, uint32_t cy,
                       uint32_t surface)
{
    uint32_t k = p->k, i0 = cx * k, j0 = cy * k;
    gen_begin_loop(b, surface, SW_SEAM_LOOP_OUTER);
    for (uint32_t side = 0; side < 4; side++)
        for (uint32_t t = 0; t < k; t++) {
            uint32_t di = side == 0 ? t : side == 1 ? k : side == 2 ? k - t : 0;
            uint32_t dj = side == 0 ? 0 : side == 1 ? t : side == 2 ? k : k - t;
            gen_slot(b, gen_lattice(p, b, ids, i0 + di, j0 + dj), (double)di / k, (double)dj / k);
        }
    if (!p->holes)
        return;
    gen_begin_loop(b, surface, 0);
    for (uint32_t t = 0; t < 6; t++) {
        double a = -2.0 * GEN_PI * t / 6, u = 0.5 + 0.2 * cos(a), w = 0.5 + 0.2 * sin(a);
        uint32_t v = gen_vertex(b, cx + u, cy + w, gen_height(p, b, cx + u, cy + w));
        gen_slot(b, v, u, w);
    }
}

/* A square standing on the seam x = 1, 0 <= y <= 1 (shared vertices along it). */
static void gen_fin(const seam_gen *p, gen_buf *b, uint32_t *ids, uint32_t surface)
{
    uint32_t k = p->k;
    gen_begin_loop(b, surface, SW_SEAM_LOOP_OUTER);
    for (uint32_t t = 0; t < k; t++)
        gen_slot(b, gen_lattice(p, b, ids, k, t), (double)t / k, 0.0);
    const sw_seam_vertex *corner = &b->g->vertices[gen_lattice(p, b, ids, k, k)];
    double zc = corner->p[2];
    gen_slot(b, gen_lattice(p, b, ids, k, k), 1.0, 0.0);
    for (uint32_t t = 1; t <= k; t++)
        gen_slot(b, gen_vertex(b, 1.0, 1.0, zc + (double)t / k), 1.0, (double)t / k);
    for (uint32_t t = 1; t < k; t++)
        gen_slot(b, gen_vertex(b, 1.0, 1.0 - (double)t / k, zc + 1.0), 1.0 - (double)t / k, 1.0);
    for (uint32_t t = 0; t < k; t++)
        gen_slot(b, gen_vertex(b, 1.0, 0.0, zc + 1.0 - (double)t / k), 0.0, 1.0 - (double)t / k);
}

static void gen_free_loop(const seam_gen *p, gen_buf *b, uint32_t surface)
{
    gen_begin_loop(b, surface, SW_SEAM_LOOP_OUTER);
    for (uint32_t t = 0; t < p->free_points; t++) {
        double a = 2.0 * GEN_PI * t / p->free_points, r = 0.5 + 0.15 * gen_rand(b);
        uint32_t v = gen_vertex(b, -2.0 + r * cos(a), 0.5 + r * sin(a), 0.1 * gen_rand(b));
        gen_slot(b, v, 0.5 + 0.5 * r * cos(a), 0.5 + 0.5 * r * sin(a));
    }
}

/* Fills *g (zeroed first) with the graph p describes. */
static void seam_gen_build(const seam_gen *p, sw_seam_host *g)
{
    memset(g, 0, sizeof *g);
    g->tolerance = 1e-3f;
    gen_buf b = {.g = g, .rng = p->seed ? p->seed : 0x9E3779B97F4A7C15ull};
    size_t lattice = (size_t)(p->nx * p->k + 1) * (p->ny * p->k + 1);
    uint32_t *ids = malloc(lattice * sizeof *ids);
    memset(ids, 0xFF, lattice * sizeof *ids);
    uint32_t surface = 0;
    for (uint32_t cy = 0; cy < p->ny; cy++)
        for (uint32_t cx = 0; cx < p->nx; cx++)
            gen_square(p, &b, ids, cx, cy, surface++);
    if (p->fin && p->nx >= 2)
        gen_fin(p, &b, ids, surface++);
    if (p->free_points >= 3)
        gen_free_loop(p, &b, surface++);
    free(ids);
    gen_finish(&b, surface);
}

#endif
