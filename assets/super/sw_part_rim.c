/* SPDX-License-Identifier: MIT */
/* Rim corners held for the simplifier (sw_part_rim.h). */
#include "sw_part_rim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

static uint64_t edge_key(uint32_t a, uint32_t b)
{
    return (uint64_t)a << 32 | b;
}

/* The triangles' directed edges, sorted; NULL when out of memory. */
static uint64_t *sorted_edges(const sw_part_tris *m)
{
    uint64_t *e = malloc(((size_t)m->icount + 1) * sizeof *e);
    for (uint32_t t = 0; e && t < m->icount; t += 3)
        for (int c = 0; c < 3; c++)
            e[t + c] = edge_key(m->idx[t + c], m->idx[t + (c + 1) % 3]);
    if (e)
        qsort(e, m->icount, sizeof *e, cmp_u64);
    return e;
}

static int has_edge(const uint64_t *e, uint32_t count, uint32_t a, uint32_t b)
{
    uint64_t k = edge_key(a, b);
    return bsearch(&k, e, count, sizeof *e, cmp_u64) != NULL;
}

/* For each vertex its rim's way in and out (the open edges a -> v and
 * v -> b: into[v] = a, out[v] = b), UINT32_MAX where it has none, or more
 * than one (meshoptimizer holds those anyway). */
static void rim_ways(const sw_part_tris *m, const uint64_t *e, uint32_t *into, uint32_t *out)
{
    for (uint32_t v = 0; v < m->wcount; v++)
        into[v] = out[v] = UINT32_MAX;
    uint8_t *seen = calloc((size_t)m->wcount + 1, 2);
    for (uint32_t i = 0; seen && i < m->icount; i++) {
        uint32_t a = (uint32_t)(e[i] >> 32), b = (uint32_t)e[i];
        if (has_edge(e, m->icount, b, a))
            continue;
        out[a] = seen[2 * (size_t)a]++ ? UINT32_MAX - 1 : b;
        into[b] = seen[2 * (size_t)b + 1]++ ? UINT32_MAX - 1 : a;
    }
    for (uint32_t v = 0; seen && v < m->wcount; v++)
        if (out[v] == UINT32_MAX - 1 || into[v] == UINT32_MAX - 1)
            into[v] = out[v] = UINT32_MAX;
    if (!seen)   /* out of memory: no corner held, the levels measured all the same */
        for (uint32_t v = 0; v < m->wcount; v++)
            into[v] = out[v] = UINT32_MAX;
    free(seen);
}

/* 1 when the rim a -> v -> b turns by more than acos(cos_turn) at v. */
static int corner(const float *p, uint32_t a, uint32_t v, uint32_t b, double cos_turn)
{
    double d0[3], d1[3], l0 = 0, l1 = 0, dot = 0;
    for (int k = 0; k < 3; k++) {
        d0[k] = (double)p[3 * (size_t)v + k] - p[3 * (size_t)a + k];
        d1[k] = (double)p[3 * (size_t)b + k] - p[3 * (size_t)v + k];
        l0 += d0[k] * d0[k], l1 += d1[k] * d1[k], dot += d0[k] * d1[k];
    }
    return l0 > 0 && l1 > 0 && dot < cos_turn * sqrt(l0 * l1);
}

/* Vertex v of triangle corner i split off onto a new copy. */
static int split(sw_part_rim *r, const sw_part_tris *m, uint32_t v, size_t i)
{
    uint32_t *c = sw_grow(r->copy_of, &r->cap_c, (size_t)r->copies + 1, sizeof *c);
    float *p = sw_grow(r->pos, &r->cap_p, 3 * ((size_t)r->vertex_count + 1), sizeof *p);
    if (c)
        r->copy_of = c;
    if (p)
        r->pos = p;
    if (!c || !p)
        return 0;
    memcpy(r->pos + 3 * (size_t)r->vertex_count, m->wpos + 3 * (size_t)v, 3 * sizeof *p);
    r->copy_of[r->copies++] = v;
    r->idx[i] = r->vertex_count++;
    return 1;
}

int sw_part_rim_hold_corners(sw_part_rim *r, const sw_part_tris *m, double cos_turn)
{
    r->vertex_count = m->wcount, r->copies = 0;
    float *p = sw_grow(r->pos, &r->cap_p, 3 * ((size_t)m->wcount + 1), sizeof *p);
    uint32_t *idx = sw_grow(r->idx, &r->cap_i, (size_t)m->icount + 1, sizeof *idx);
    if (p)
        r->pos = p;
    if (idx)
        r->idx = idx;
    uint64_t *e = p && idx ? sorted_edges(m) : NULL;
    uint32_t *ways = e ? malloc(2 * ((size_t)m->wcount + 1) * sizeof *ways) : NULL;
    int ok = ways != NULL;
    if (ok) {
        memcpy(r->pos, m->wpos, 3 * (size_t)m->wcount * sizeof *p);
        memcpy(r->idx, m->idx, (size_t)m->icount * sizeof *idx);
        uint32_t *into = ways, *out = ways + m->wcount + 1;
        rim_ways(m, e, into, out);
        /* Each corner's copy goes to the triangle whose rim edge leaves it. */
        for (size_t i = 0; ok && i < m->icount; i++) {
            uint32_t v = m->idx[i], next = m->idx[i - i % 3 + (i % 3 + 1) % 3];
            if (out[v] == next && into[v] != UINT32_MAX &&
                corner(m->wpos, into[v], v, next, cos_turn))
                ok = split(r, m, v, i);
        }
    }
    free(e);
    free(ways);
    return ok;
}

void sw_part_rim_unmap(const sw_part_rim *r, uint32_t wcount, uint32_t *dest, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (dest[i] >= wcount)
            dest[i] = r->copy_of[dest[i] - wcount];
}

void sw_part_rim_free(sw_part_rim *r)
{
    free(r->pos);
    free(r->idx);
    free(r->copy_of);
    memset(r, 0, sizeof *r);
}
