/* SPDX-License-Identifier: MIT */
/* A piece's source gathered, welded by position and turned one way
 * (sw_part_mesh.h). */
#include "sw_part_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"
#include "sw_pow2.h"

int sw_part_mesh_gather(sw_part_mesh *m, const sw_levels *levels, const uint32_t *piece_of,
                        const sw_part_source *src, uint32_t g, uint32_t first, uint32_t end)
{
    m->count = 0, m->icount = 0, m->error = 0;
    for (uint32_t s = first; s < end; s++) {
        if (g != SW_PART_MESH_ALL && piece_of[s] != g)
            continue;
        if (levels->surface_levels[s] == levels->surface_levels[s + 1])
            return -1;
        if (isnan(src->error[s]))
            continue;   /* its outer loop vanished at the front: the walk shows none */
        m->error = fmax(m->error, src->error[s]);
        uint32_t v0 = src->surface_vertices[s], nv = src->surface_vertices[s + 1] - v0;
        uint32_t i0 = src->surface_indices[s], ni = src->surface_indices[s + 1] - i0;
        float *p = sw_grow(m->pos, &m->cap_p, 3 * ((size_t)m->count + nv), sizeof(float));
        if (p)
            m->pos = p;
        float *n = sw_grow(m->nrm, &m->cap_n, 3 * ((size_t)m->count + nv), sizeof(float));
        if (n)
            m->nrm = n;
        uint32_t *ix = sw_grow(m->idx, &m->cap_i, (size_t)m->icount + ni, sizeof *ix);
        if (ix)
            m->idx = ix;
        uint32_t *cx = sw_grow(m->corner, &m->cap_c, (size_t)m->icount + ni, sizeof *cx);
        if (cx)
            m->corner = cx;
        if (!p || !n || !ix || !cx)
            return 0;
        memcpy(m->pos + 3 * (size_t)m->count, src->positions + 3 * (size_t)v0,
               3 * sizeof(float) * nv);
        memcpy(m->nrm + 3 * (size_t)m->count, src->normals + 3 * (size_t)v0,
               3 * sizeof(float) * nv);
        for (uint32_t i = 0; i < ni; i++)
            m->idx[m->icount + i] = m->corner[m->icount + i] = src->indices[i0 + i] - v0 + m->count;
        m->count += nv, m->icount += ni;
    }
    return 1;
}

int sw_part_mesh_weld(sw_part_mesh *m)
{
    size_t cap = sw_pow2_at_least(2 * m->count, 16);
    uint32_t *table = malloc(cap * sizeof *table);
    /* Each kept as it was when it cannot grow: freed with the rest. */
    uint32_t *wl = sw_grow(m->weld, &m->cap_w, m->count + 1, sizeof *m->weld);
    m->weld = wl ? wl : m->weld;
    float *wp = sw_grow(m->wpos, &m->cap_x, 3 * ((size_t)m->count + 1), sizeof *m->wpos);
    m->wpos = wp ? wp : m->wpos;
    uint32_t *wf = sw_grow(m->wedge_first, &m->cap_wf, m->count + 2, sizeof *m->wedge_first);
    m->wedge_first = wf ? wf : m->wedge_first;
    uint32_t *wd = sw_grow(m->wedge, &m->cap_wd, m->count + 1, sizeof *m->wedge);
    m->wedge = wd ? wd : m->wedge;
    if (!table || !wl || !wp || !wf || !wd) {
        free(table);
        return 0;
    }
    memset(table, 0xff, cap * sizeof *table);
    m->wcount = 0;
    for (uint32_t v = 0; v < m->count; v++) {
        uint32_t bits[3];
        memcpy(bits, m->pos + 3 * (size_t)v, sizeof bits);
        size_t h = sw_part_hash64(((uint64_t)bits[0] << 32 | bits[1]) ^ sw_part_hash64(bits[2])) & (cap - 1);
        while (table[h] != UINT32_MAX &&
               memcmp(m->wpos + 3 * (size_t)table[h], bits, sizeof bits))
            h = (h + 1) & (cap - 1);
        if (table[h] == UINT32_MAX) {
            table[h] = m->wcount;
            memcpy(m->wpos + 3 * (size_t)m->wcount++, bits, sizeof bits);
        }
        m->weld[v] = table[h];
    }
    free(table);
    memset(m->wedge_first, 0, ((size_t)m->wcount + 2) * sizeof *m->wedge_first);
    for (uint32_t v = 0; v < m->count; v++)
        m->wedge_first[m->weld[v] + 2]++;
    for (uint32_t w = 0; w < m->wcount; w++)
        m->wedge_first[w + 2] += m->wedge_first[w + 1];
    for (uint32_t v = 0; v < m->count; v++)
        m->wedge[m->wedge_first[m->weld[v] + 1]++] = v;
    uint32_t kept = 0;
    for (uint32_t t = 0; t + 2 < m->icount; t += 3) {
        uint32_t a = m->weld[m->idx[t]], b = m->weld[m->idx[t + 1]], c = m->weld[m->idx[t + 2]];
        if (a == b || b == c || a == c)
            continue;
        m->idx[kept] = a, m->idx[kept + 1] = b, m->idx[kept + 2] = c;
        memmove(m->corner + kept, m->corner + t, 3 * sizeof *m->corner);
        kept += 3;
    }
    m->icount = kept;
    return 1;
}

/* Edge (a, b) of triangle t's corners k, k + 1 as a key, lowest first. */
static uint64_t edge_key(uint32_t a, uint32_t b)
{
    return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
}

/* Each edge's first two triangles (a third or more: UINT32_MAX - 1, not
 * spread over), in an open-addressed table of cap slots. */
typedef struct edge_table {
    uint64_t *keys;
    uint32_t *first, *second;
    size_t cap;
} edge_table;

static size_t edge_slot(const edge_table *e, uint32_t a, uint32_t b)
{
    uint64_t key = edge_key(a, b) + 1;
    size_t h = sw_part_hash64(key) & (e->cap - 1);
    while (e->keys[h] && e->keys[h] != key)
        h = (h + 1) & (e->cap - 1);
    e->keys[h] = key;
    return h;
}

static void fill_edges(const sw_part_mesh *m, edge_table *e)
{
    for (uint32_t t = 0; t < m->icount / 3; t++)
        for (int k = 0; k < 3; k++) {
            size_t h = edge_slot(e, m->idx[3 * t + k], m->idx[3 * t + (k + 1) % 3]);
            if (e->first[h] == UINT32_MAX)
                e->first[h] = t, e->second[h] = UINT32_MAX;
            else
                e->second[h] = e->second[h] == UINT32_MAX && e->first[h] != t ? t
                                                                                : UINT32_MAX - 1;
        }
}

/* Triangle t wound the other way (its corners' source vertices with it). */
static void turn_over(sw_part_mesh *m, uint32_t t)
{
    uint32_t *c = m->idx + 3 * (size_t)t, *s = m->corner + 3 * (size_t)t, x = c[1], y = s[1];
    c[1] = c[2], c[2] = x;
    s[1] = s[2], s[2] = y;
}

/* From seed, the triangles reached over edges two share, each turned to
 * run such an edge the other way from the one it came from, into
 * queue[0 .. return). */
static uint32_t spread(sw_part_mesh *m, const edge_table *e, uint32_t seed, uint32_t *queue,
                       uint8_t *done)
{
    uint32_t head = 0, tail = 0;
    done[seed] = 1, queue[tail++] = seed;
    while (head < tail) {
        uint32_t t = queue[head++];
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->idx[3 * t + k], b = m->idx[3 * t + (k + 1) % 3];
            size_t h = edge_slot(e, a, b);
            uint32_t u = e->first[h] == t ? e->second[h] : e->first[h];
            if (e->second[h] >= UINT32_MAX - 1 || done[u])
                continue;
            uint32_t *c = m->idx + 3 * (size_t)u;
            if ((c[0] == a && c[1] == b) || (c[1] == a && c[2] == b) || (c[2] == a && c[0] == b))
                turn_over(m, u);
            done[u] = 1, queue[tail++] = u;
        }
    }
    return tail;
}

/* The triangles tris[0 .. count), one piece turned one way, turned over
 * when most of their area faces against the surfaces' normals: so the
 * piece's front is the surfaces' (hidden back faces stay hidden, shown
 * ones stay shown). */
static void face_out(sw_part_mesh *m, const uint32_t *tris, uint32_t count)
{
    double vote = 0;
    for (uint32_t i = 0; i < count; i++) {
        const uint32_t *c = m->idx + 3 * (size_t)tris[i];
        const float *a = m->wpos + 3 * (size_t)c[0], *b = m->wpos + 3 * (size_t)c[1],
                    *d = m->wpos + 3 * (size_t)c[2];
        double e1[3], e2[3], n[3], sum[3] = { 0, 0, 0 };
        for (int k = 0; k < 3; k++)
            e1[k] = (double)b[k] - a[k], e2[k] = (double)d[k] - a[k];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        for (int j = 0; j < 3; j++)
            for (uint32_t w = m->wedge_first[c[j]]; w < m->wedge_first[c[j] + 1]; w++)
                for (int k = 0; k < 3; k++)
                    sum[k] += m->nrm[3 * (size_t)m->wedge[w] + k];
        vote += n[0] * sum[0] + n[1] * sum[1] + n[2] * sum[2];
    }
    for (uint32_t i = 0; vote < 0 && i < count; i++)
        turn_over(m, tris[i]);
}

int sw_part_mesh_orient(sw_part_mesh *m)
{
    uint32_t tris = m->icount / 3;
    edge_table e = { .cap = sw_pow2_at_least(4 * m->icount, 16) };
    e.keys = calloc(e.cap, sizeof *e.keys);
    e.first = malloc(e.cap * sizeof *e.first);
    e.second = malloc(e.cap * sizeof *e.second);
    uint32_t *queue = malloc(((size_t)tris + 1) * sizeof *queue);
    uint8_t *done = calloc((size_t)tris + 1, 1);
    int ok = e.keys && e.first && e.second && queue && done;
    if (ok) {
        memset(e.first, 0xff, e.cap * sizeof *e.first);
        fill_edges(m, &e);
        for (uint32_t seed = 0; seed < tris; seed++)
            if (!done[seed])
                face_out(m, queue, spread(m, &e, seed, queue, done));
    }
    free(e.keys), free(e.first), free(e.second), free(queue), free(done);
    return ok;
}

double sw_part_mesh_size(const sw_part_mesh *m)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t w = 0; w < m->wcount; w++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], m->wpos[3 * (size_t)w + k]),
            hi[k] = fmax(hi[k], m->wpos[3 * (size_t)w + k]);
    double d = 0;
    for (int k = 0; k < 3; k++)
        d += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0;
    return sqrt(d);
}

void sw_part_mesh_free(sw_part_mesh *m)
{
    void *blocks[] = { m->pos, m->nrm, m->weld, m->wpos, m->idx, m->corner, m->wedge_first, m->wedge,
                       m->dest, m->aside, m->keys, m->key_value };
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
    sw_part_rim_free(&m->rim);
}

int sw_part_level_arrays_join(sw_part_level_arrays *o, sw_part_level_arrays *pieces,
                              uint32_t count)
{
    size_t levels = o->level_count, vertices = o->vertex_count, indices = o->index_count;
    for (uint32_t i = 0; i < count; i++)
        levels += pieces[i].level_count, vertices += pieces[i].vertex_count,
            indices += pieces[i].index_count;
    if (levels > UINT32_MAX || vertices > UINT32_MAX || indices > UINT32_MAX)
        return 0;
    sw_part_level *l = sw_grow(o->levels, &o->cap_l, levels + 1, sizeof *l);
    o->levels = l ? l : o->levels;
    sw_level_vertex *v = sw_grow(o->vertices, &o->cap_v, vertices + 1, sizeof *v);
    o->vertices = v ? v : o->vertices;
    uint16_t *x = sw_grow(o->indices, &o->cap_i, indices + 1, sizeof *x);
    o->indices = x ? x : o->indices;
    if (!l || !v || !x)
        return 0;
    for (uint32_t i = 0; i < count; i++) {
        sw_part_level_arrays *p = &pieces[i];
        for (uint32_t k = 0; k < p->level_count; k++) {
            sw_part_level *to = &o->levels[o->level_count + k];
            *to = p->levels[k];
            to->first_vertex += o->vertex_count, to->first_index += o->index_count;
        }
        if (p->vertex_count)   /* a piece without levels has no arrays */
            memcpy(o->vertices + o->vertex_count, p->vertices, p->vertex_count * sizeof *v);
        if (p->index_count)
            memcpy(o->indices + o->index_count, p->indices, p->index_count * sizeof *x);
        o->level_count += p->level_count, o->vertex_count += p->vertex_count;
        o->index_count += p->index_count;
        sw_part_level_arrays_free(p);
    }
    return 1;
}

void sw_part_level_arrays_free(sw_part_level_arrays *a)
{
    free(a->levels);
    free(a->vertices);
    free(a->indices);
    memset(a, 0, sizeof *a);
}
