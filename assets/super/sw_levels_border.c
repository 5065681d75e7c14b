/* SPDX-License-Identifier: MIT */
/* A level's border chains (sw_levels_border.h). */
#include "sw_levels_border.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NO_NEXT 0xFFFFFFFFu

/* A loop point, found by its id and (u, v) bits. */
typedef struct point_key {
    uint32_t id, u, v, loop, point;
} point_key;

static int cmp_key(const void *pa, const void *pb)
{
    const point_key *a = pa, *b = pb;
    if (a->id != b->id)
        return a->id < b->id ? -1 : 1;
    if (a->u != b->u)
        return a->u < b->u ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v;
}

static uint32_t bits(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof b);
    return b;
}

typedef struct border {
    const sw_border_mesh *mesh;
    const sw_border_loop *loops;
    uint32_t loop_count;
    uint32_t *table, mask;        /* directed edges: (a << 16 | b) + 1, 0 empty */
    uint32_t *next;               /* vertex_count: the end of the border edge it starts */
    uint8_t *seen;
    point_key *keys;
    uint32_t key_count;
    uint32_t *cycle;              /* one cycle's vertices */
    uint32_t *chain_start, *chain_len;  /* per loop, into held (NO_NEXT: none) */
    sw_strip_point *held;         /* the chains as found */
    uint32_t held_count;
} border;

/* Inserts directed edge a-b; 0 when it was there already (two triangles
 * wound the same way over one edge: not a surface). */
static int edge_insert(border *b, uint32_t a, uint32_t c)
{
    uint32_t key = (a << 16 | c) + 1;
    for (uint32_t h = (key * 2654435761u) & b->mask;; h = (h + 1) & b->mask) {
        if (b->table[h] == key)
            return 0;
        if (b->table[h] == 0) {
            b->table[h] = key;
            return 1;
        }
    }
}

static int edge_has(const border *b, uint32_t a, uint32_t c)
{
    uint32_t key = (a << 16 | c) + 1;
    for (uint32_t h = (key * 2654435761u) & b->mask;; h = (h + 1) & b->mask) {
        if (b->table[h] == key)
            return 1;
        if (b->table[h] == 0)
            return 0;
    }
}

/* next[] for every edge whose reverse no triangle has. */
static sw_status find_border_edges(border *b, sw_error *err)
{
    const sw_border_mesh *m = b->mesh;
    for (uint32_t t = 0; t + 2 < m->index_count; t += 3)
        for (int k = 0; k < 3; k++)
            if (!edge_insert(b, m->indices[t + k], m->indices[t + (k + 1) % 3]))
                return sw_error_set(err, SW_ERR_FORMAT, "border: edge %u-%u twice in one "
                                    "direction", m->indices[t + k], m->indices[t + (k + 1) % 3]);
    for (uint32_t t = 0; t + 2 < m->index_count; t += 3)
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->indices[t + k], c = m->indices[t + (k + 1) % 3];
            if (edge_has(b, c, a))
                continue;
            if (b->next[a] != NO_NEXT)
                return sw_error_set(err, SW_ERR_FORMAT, "border: vertex %u starts two border "
                                    "edges (the border touches itself)", a);
            b->next[a] = c;
        }
    return SW_OK;
}

static void make_keys(border *b)
{
    b->key_count = 0;
    for (uint32_t l = 0; l < b->loop_count; l++)
        for (uint32_t i = 0; i < b->loops[l].count; i++)
            b->keys[b->key_count++] = (point_key){ b->loops[l].ids[i], bits(b->loops[l].uvs[2 * i]),
                                                   bits(b->loops[l].uvs[2 * i + 1]), l, i };
    qsort(b->keys, b->key_count, sizeof *b->keys, cmp_key);
}

/* The loop point mesh vertex v is, or NULL. */
static const point_key *match(const border *b, uint32_t v)
{
    const float *uv = b->mesh->uvs + 2 * (size_t)v;
    point_key k = { b->mesh->ids[v], bits(uv[0]), bits(uv[1]), 0, 0 };
    return bsearch(&k, b->keys, b->key_count, sizeof k, cmp_key);
}

/* Descents of the matched points' slots going round cycle[0 .. n) once. */
static uint32_t descents(const border *b, const uint32_t *cycle, uint32_t n)
{
    uint32_t count = 0, first = NO_NEXT, last = NO_NEXT;
    for (uint32_t i = 0; i < n; i++) {
        const point_key *k = match(b, cycle[i]);
        if (!k)
            continue;
        uint32_t slot = b->loops[k->loop].slots[k->point];
        if (first == NO_NEXT)
            first = slot;
        else
            count += slot < last;
        last = slot;
    }
    return count + (first != NO_NEXT && first < last);
}

static void reverse(uint32_t *c, uint32_t n)
{
    for (uint32_t i = 0; i < n / 2; i++) {
        uint32_t t = c[i];
        c[i] = c[n - 1 - i], c[n - 1 - i] = t;
    }
}

static double uv_step(const border *b, uint32_t v, uint32_t w)
{
    const float *p = b->mesh->uvs + 2 * (size_t)v, *q = b->mesh->uvs + 2 * (size_t)w;
    return hypot((double)q[0] - p[0], (double)q[1] - p[1]);
}

/* t of the cycle's points into out: slots where they are loop points, and
 * between two loop points p .. q by (u, v) length along the cycle. */
static void place(const border *b, const uint32_t *c, uint32_t n, uint32_t period,
                  sw_strip_point *out)
{
    uint32_t p = 0;
    while (!match(b, c[p]))
        p++;
    for (uint32_t done = 0; done < n;) {
        const point_key *kp = match(b, c[p]);
        double tp = b->loops[kp->loop].slots[kp->point];
        uint32_t q = (p + 1) % n;
        double length = uv_step(b, c[p], c[q]);
        while (!match(b, c[q])) {
            uint32_t r = (q + 1) % n;
            length += uv_step(b, c[q], c[r]);
            q = r;
        }
        const point_key *kq = match(b, c[q]);
        double tq = b->loops[kq->loop].slots[kq->point];
        if (tq < tp || q == p)
            tq += period;
        out[p] = (sw_strip_point){ c[p], (float)tp };
        double along = 0;
        for (uint32_t i = (p + 1) % n; i != q; i = (i + 1) % n) {
            along += uv_step(b, c[(i + n - 1) % n], c[i]);
            double t = tp + (tq - tp) * (length > 0 ? along / length : 0.5);
            float tf = (float)fmod(t, (double)period);
            out[i] = (sw_strip_point){ c[i], tf < (float)period ? tf : 0.0f };
        }
        done += (q + n - p) % n ? (q + n - p) % n : n;
        p = q;
    }
}

/* One closed cycle from v: its loop's chain, once round in slot order. */
static sw_status take_cycle(border *b, uint32_t v, sw_error *err)
{
    uint32_t n = 0, loop = NO_NEXT;
    for (uint32_t w = v; !b->seen[w]; w = b->next[w]) {
        if (b->next[w] == NO_NEXT)
            return sw_error_set(err, SW_ERR_FORMAT, "border: open at vertex %u", w);
        b->seen[w] = 1;
        b->cycle[n++] = w;
        const point_key *k = match(b, w);
        if (k && loop != NO_NEXT && k->loop != loop)
            return sw_error_set(err, SW_ERR_FORMAT, "border: one chain runs through loops %u "
                                "and %u", loop, k->loop);
        if (k)
            loop = k->loop;
    }
    if (b->cycle[0] != v || b->next[b->cycle[n - 1]] != v)
        return sw_error_set(err, SW_ERR_FORMAT, "border: vertex %u joins a chain midway", v);
    if (loop == NO_NEXT)
        return sw_error_set(err, SW_ERR_FORMAT, "border: a chain of %u vertices holds no loop "
                            "point", n);
    if (b->chain_start[loop] != NO_NEXT)
        return sw_error_set(err, SW_ERR_FORMAT, "border: loop %u has two chains", loop);
    if (descents(b, b->cycle, n) > 1)
        reverse(b->cycle, n);
    uint32_t period = b->loops[loop].period;
    if (descents(b, b->cycle, n) > 1)
        return sw_error_set(err, SW_ERR_FORMAT, "border: loop %u's chain is not in slot order",
                            loop);
    place(b, b->cycle, n, period, b->held + b->held_count);
    if (!sw_border_chain_valid(b->held + b->held_count, n, (float)period))
        return sw_error_set(err, SW_ERR_FORMAT, "border: loop %u's chain does not go once "
                            "round", loop);
    b->chain_start[loop] = b->held_count, b->chain_len[loop] = n;
    b->held_count += n;
    return SW_OK;
}

static sw_status walk_cycles(border *b, sw_strip_point *points, uint32_t *first, sw_error *err)
{
    sw_status st = find_border_edges(b, err);
    make_keys(b);
    for (uint32_t v = 0; st == SW_OK && v < b->mesh->vertex_count; v++)
        if (b->next[v] != NO_NEXT && !b->seen[v])
            st = take_cycle(b, v, err);
    first[0] = 0;
    for (uint32_t l = 0; st == SW_OK && l < b->loop_count; l++) {
        if (b->chain_start[l] == NO_NEXT)
            return sw_error_set(err, SW_ERR_FORMAT, "border: loop %u has no chain", l);
        memcpy(points + first[l], b->held + b->chain_start[l], b->chain_len[l] * sizeof *points);
        first[l + 1] = first[l] + b->chain_len[l];
    }
    return st;
}

sw_status sw_levels_border(const sw_border_mesh *mesh, const sw_border_loop *loops,
                           uint32_t loop_count, sw_strip_point *points, uint32_t *first,
                           sw_error *err)
{
    border b = { .mesh = mesh, .loops = loops, .loop_count = loop_count };
    uint32_t size = 64, n = mesh->vertex_count, keys = 0;
    while (size < 2 * mesh->index_count + 2)
        size *= 2;
    for (uint32_t l = 0; l < loop_count; l++)
        keys += loops[l].count;
    b.mask = size - 1;
    b.table = calloc(size, sizeof *b.table);
    b.next = malloc(((size_t)n + 1) * sizeof *b.next);
    b.seen = calloc((size_t)n + 1, 1);
    b.cycle = malloc(((size_t)n + 1) * sizeof *b.cycle);
    b.held = malloc(((size_t)n + 1) * sizeof *b.held);
    b.keys = malloc(((size_t)keys + 1) * sizeof *b.keys);
    b.chain_start = malloc(((size_t)loop_count + 1) * sizeof *b.chain_start);
    b.chain_len = calloc((size_t)loop_count + 1, sizeof *b.chain_len);
    sw_status st = SW_OK;
    if (!b.table || !b.next || !b.seen || !b.cycle || !b.held || !b.keys || !b.chain_start ||
        !b.chain_len)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "border: out of memory for %u vertices", n);
    if (st == SW_OK) {
        memset(b.next, 0xFF, (size_t)n * sizeof *b.next);
        memset(b.chain_start, 0xFF, (size_t)loop_count * sizeof *b.chain_start);
        st = walk_cycles(&b, points, first, err);
    }
    free(b.table);
    free(b.next);
    free(b.seen);
    free(b.cycle);
    free(b.held);
    free(b.keys);
    free(b.chain_start);
    free(b.chain_len);
    return st;
}
