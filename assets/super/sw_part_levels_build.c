/* SPDX-License-Identifier: MIT */
/* Part levels: each piece's source welded, simplified toward rising
 * bounds, measured both ways, its normals chosen per corner from the
 * source's, its area shaded wrong measured (sw_part_levels_build.h). */
#include "sw_part_levels_build.h"

#include <float.h>
#include <math.h>
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_grow.h"
#include "sw_mesh_distance.h"
#include "sw_part_pieces.h"
#include "sw_part_source.h"
#include "sw_pow2.h"

/* One part's source, welded (reused from part to part). */
typedef struct part_mesh {
    float *pos, *nrm;             /* the part's source vertices */
    uint32_t *weld;               /* source vertex -> welded vertex */
    float *wpos;                  /* welded positions */
    uint32_t *idx;                /* welded triangles, none of no area */
    uint32_t *corner;             /* the source vertex of each of idx's corners */
    uint32_t *wedge_first, *wedge;/* welded vertex -> its source vertices */
    uint32_t *dest;               /* simplified triangles */
    uint64_t *keys;               /* output vertex hash: (welded << 32 | source) + 1 */
    uint32_t *key_value;
    size_t cap_v, cap_i, cap_c, cap_w, cap_d, cap_k, cap_kv, cap_n, cap_p, cap_wf, cap_wd, cap_x;
    uint32_t count, wcount, icount;
    double error;                 /* the source's measured error */
} part_mesh;

typedef struct out_arrays {
    sw_part_level *levels;
    sw_level_vertex *vertices;
    uint16_t *indices;
    size_t cap_l, cap_v, cap_i;
    uint32_t level_count, vertex_count, index_count;
} out_arrays;

static uint64_t hash64(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
}

/* Piece g's source vertices and triangles gathered from its part's
 * surfaces [first, end); 0 when out of memory, -1 when a surface of it has
 * no level. */
static int gather_piece(part_mesh *m, const sw_levels *levels, const uint32_t *piece_of,
                        const sw_part_source *src, uint32_t g, uint32_t first, uint32_t end)
{
    m->count = 0, m->icount = 0, m->error = 0;
    for (uint32_t s = first; s < end; s++) {
        if (piece_of[s] != g)
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

/* Vertices at the very same position become one; triangles that then
 * repeat a vertex are dropped. Each welded vertex keeps the list of the
 * source vertices it stands for. 0 when out of memory. */
static int weld(part_mesh *m)
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
        size_t h = hash64(((uint64_t)bits[0] << 32 | bits[1]) ^ hash64(bits[2])) & (cap - 1);
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
    size_t h = hash64(key) & (e->cap - 1);
    while (e->keys[h] && e->keys[h] != key)
        h = (h + 1) & (e->cap - 1);
    e->keys[h] = key;
    return h;
}

static void fill_edges(const part_mesh *m, edge_table *e)
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
static void turn_over(part_mesh *m, uint32_t t)
{
    uint32_t *c = m->idx + 3 * (size_t)t, *s = m->corner + 3 * (size_t)t, x = c[1], y = s[1];
    c[1] = c[2], c[2] = x;
    s[1] = s[2], s[2] = y;
}

/* From seed, the triangles reached over edges two share, each turned to
 * run such an edge the other way from the one it came from, into
 * queue[0 .. return). */
static uint32_t spread(part_mesh *m, const edge_table *e, uint32_t seed, uint32_t *queue,
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
static void face_out(part_mesh *m, const uint32_t *tris, uint32_t count)
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

/* The triangles turned so that each edge two of them share is run once each
 * way, piece by piece, each piece to the side its surfaces face. The
 * surfaces' normals alone do not decide each triangle: a part's surfaces
 * may face opposite ways (the renderer lights both sides), and
 * meshoptimizer takes an edge not run both ways for a border it must keep.
 * 0 when out of memory. */
static int orient(part_mesh *m)
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

static double part_size(const part_mesh *m)
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

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

/* Of the normals the surfaces meeting at welded vertex w have there, the
 * one closest to the line of n, turned to n's side (the renderer takes a
 * normal to face the way its triangle winds, and lights both sides). */
static void closest_normal(const part_mesh *m, uint32_t w, const double n[3], int8_t q[3])
{
    double best = -1, sign = 1;
    const float *pick = m->nrm + 3 * (size_t)m->wedge[m->wedge_first[w]];
    for (uint32_t i = m->wedge_first[w]; i < m->wedge_first[w + 1]; i++) {
        const float *nv = m->nrm + 3 * (size_t)m->wedge[i];
        double d = n[0] * nv[0] + n[1] * nv[1] + n[2] * nv[2];
        if (fabs(d) > best)
            best = fabs(d), pick = nv, sign = d < 0 ? -1 : 1;
    }
    for (int k = 0; k < 3; k++)
        q[k] = snorm8((float)(sign * pick[k]));
}

static void face_normal(const float *a, const float *b, const float *c, double n[3])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        e1[k] = (double)b[k] - a[k], e2[k] = (double)c[k] - a[k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* The unit normal weights w blend from corner normals q (snorm8). */
static void blend_normal(const int8_t *q[3], const double w[3], double n[3])
{
    for (int k = 0; k < 3; k++)
        n[k] = w[0] * q[0][k] + w[1] * q[1][k] + w[2] * q[2][k];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3 && len > 0; k++)
        n[k] /= len;
}

/* The shading normal of the source (the mesh simplified from) at point
 * `at` of it: its triangle's corners' normals, each its own surface's. */
static void source_normal(const part_mesh *m, const sw_mesh_point *at, double n[3])
{
    const uint32_t *c = m->corner + 3 * (size_t)at->triangle;
    for (int k = 0; k < 3; k++)
        n[k] = at->weights[0] * m->nrm[3 * (size_t)c[0] + k] +
               at->weights[1] * m->nrm[3 * (size_t)c[1] + k] +
               at->weights[2] * m->nrm[3 * (size_t)c[2] + k];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3 && len > 0; k++)
        n[k] /= len;
}

/* Output vertex for welded w with normal q (packed snorm8 x, y, z): the one
 * made already, else a new one. UINT32_MAX past one draw's vertices. */
static uint32_t output_vertex(part_mesh *m, out_arrays *o, uint32_t first, size_t cap,
                              uint32_t w, const int8_t q[3])
{
    uint64_t key = ((uint64_t)w << 24 | (uint64_t)(uint8_t)q[0] << 16 |
                    (uint64_t)(uint8_t)q[1] << 8 | (uint8_t)q[2]) + 1;
    size_t h = hash64(key) & (cap - 1);
    while (m->keys[h] && m->keys[h] != key)
        h = (h + 1) & (cap - 1);
    if (m->keys[h])
        return m->key_value[h];
    uint32_t local = o->vertex_count - first;
    if (local >= 65536)
        return UINT32_MAX;
    m->keys[h] = key, m->key_value[h] = local;
    sw_level_vertex *v = &o->vertices[o->vertex_count++];
    memcpy(v->p, m->wpos + 3 * (size_t)w, sizeof v->p);
    memcpy(v->normal, q, 3);
    v->normal[3] = 0;
    return local;
}

/* The normal corner k of triangle v gets: of those the surfaces meeting
 * there have, the one closest to the source's normal a little inside the
 * triangle from that corner, turned to the triangle's side. A corner's own
 * normals are those of the surfaces it lies on: where the simplifier put
 * a triangle of one face onto vertices of the faces around it (a flat
 * side on the rim around it), none of them is that face's, and the face
 * would be shaded as its rim; it then takes the source's normal there. */
static void corner_normal(const part_mesh *m, const sw_mesh_grid *source_grid,
                          const uint32_t v[3], int k, const double fn[3], int8_t q[3])
{
    double x[3], ns[3];
    for (int j = 0; j < 3; j++)
        x[j] = 0.8 * m->wpos[3 * (size_t)v[k] + j] + 0.1 * m->wpos[3 * (size_t)v[(k + 1) % 3] + j] +
               0.1 * m->wpos[3 * (size_t)v[(k + 2) % 3] + j];
    sw_mesh_point at;
    sw_mesh_grid_nearest(source_grid, x, &at);
    source_normal(m, &at, ns);
    if (ns[0] * fn[0] + ns[1] * fn[1] + ns[2] * fn[2] < 0)
        for (int j = 0; j < 3; j++)
            ns[j] = -ns[j];
    closest_normal(m, v[k], ns, q);
    double qn[3] = { q[0], q[1], q[2] }, len = sqrt(qn[0] * qn[0] + qn[1] * qn[1] + qn[2] * qn[2]);
    if (!(len > 0) || (qn[0] * ns[0] + qn[1] * ns[1] + qn[2] * ns[2]) / len < SW_PART_LEVEL_CREASE_COS)
        for (int j = 0; j < 3; j++)
            q[j] = snorm8((float)ns[j]);
}

/* The simplified triangles dest[0 .. n) as a level's vertices and indices
 * appended to o; 0 when out of memory, -1 when over one draw. */
static int emit(part_mesh *m, const sw_mesh_grid *source_grid, out_arrays *o, uint32_t n,
                uint32_t *first_vertex)
{
    size_t cap = sw_pow2_at_least(2 * n, 16);
    uint64_t *ks = sw_grow(m->keys, &m->cap_k, cap, sizeof *m->keys);
    m->keys = ks ? ks : m->keys;
    uint32_t *kv = sw_grow(m->key_value, &m->cap_kv, cap, sizeof *m->key_value);
    m->key_value = kv ? kv : m->key_value;
    sw_level_vertex *vs = sw_grow(o->vertices, &o->cap_v, (size_t)o->vertex_count + n,
                                  sizeof *vs);
    if (vs)
        o->vertices = vs;
    uint16_t *is = sw_grow(o->indices, &o->cap_i, (size_t)o->index_count + n, sizeof *is);
    if (is)
        o->indices = is;
    if (!ks || !kv || !vs || !is)
        return 0;
    memset(m->keys, 0, cap * sizeof *m->keys);
    *first_vertex = o->vertex_count;
    for (uint32_t t = 0; t + 2 < n; t += 3) {
        double fn[3];
        face_normal(m->wpos + 3 * (size_t)m->dest[t], m->wpos + 3 * (size_t)m->dest[t + 1],
                    m->wpos + 3 * (size_t)m->dest[t + 2], fn);
        for (int k = 0; k < 3; k++) {
            int8_t q[3];
            corner_normal(m, source_grid, m->dest + t, k, fn, q);
            uint32_t v = output_vertex(m, o, *first_vertex, cap, m->dest[t + k], q);
            if (v == UINT32_MAX)
                return -1;
            o->indices[o->index_count + t + k] = (uint16_t)v;
        }
    }
    return 1;
}

typedef struct normal_match {
    const part_mesh *m;
    double level[3];   /* the level's shading normal at the point */
    double best;       /* the largest |cos| to a source normal within reach */
} normal_match;

/* Whether the source's normal at `at` matches the level's (stops the
 * search). */
static int match_normal(void *ctx, const sw_mesh_point *at)
{
    normal_match *nm = ctx;
    double ns[3];
    source_normal(nm->m, at, ns);
    nm->best = fmax(nm->best, fabs(nm->level[0] * ns[0] + nm->level[1] * ns[1] +
                                   nm->level[2] * ns[2]));
    return nm->best >= SW_PART_LEVEL_CREASE_COS;
}

/* The level l's shading side (sw_part_level): the side of a square
 * of the area of its triangles whose shading normal lies more than 30
 * degrees off the source's at every source point within the level's
 * error (either side: the renderer lights both), sampled at the 10 points
 * of a barycentric grid of sixths inside each triangle. The level may lie
 * anywhere within its error of the source, so its shading may too: a
 * point near a crease matches either face. A level simplified across a
 * crease blends the two faces' normals over the triangles that span it,
 * and a triangle whose corners the simplifier took from other faces is
 * shaded as those; one across a fillet follows the fillet's normals. */
static double miss_shaded_side(const part_mesh *m, const sw_mesh_grid *source_grid,
                               const out_arrays *o, const sw_part_level *l)
{
    enum { N = 6, INSIDE = (N - 1) * (N - 2) / 2 };
    double area = 0;
    for (uint32_t t = 0; t + 2 < l->index_count; t += 3) {
        const float *p[3];
        const int8_t *q[3];
        for (int k = 0; k < 3; k++) {
            const sw_level_vertex *c =
                &o->vertices[l->first_vertex + o->indices[l->first_index + t + k]];
            p[k] = c->p, q[k] = c->normal;
        }
        int off = 0;
        for (int i = 1; i < N; i++)
            for (int j = 1; i + j < N; j++) {
                double w[3] = { (double)i / N, (double)j / N, (double)(N - i - j) / N }, x[3];
                for (int k = 0; k < 3; k++)
                    x[k] = w[0] * p[0][k] + w[1] * p[1][k] + w[2] * p[2][k];
                sw_mesh_point at;
                double near = sw_mesh_grid_nearest(source_grid, x, &at);
                double reach = fmax(near, l->error);
                normal_match nm = { m, { 0, 0, 0 }, 0 };
                blend_normal(q, w, nm.level);
                /* the nearest first, then close by, then all within reach */
                off += !match_normal(&nm, &at) &&
                       !sw_mesh_grid_within(source_grid, x, fmin(reach, 2 * near + reach / 16),
                                            match_normal, &nm) &&
                       !sw_mesh_grid_within(source_grid, x, reach, match_normal, &nm);
            }
        double n[3];
        face_normal(p[0], p[1], p[2], n);
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * off / INSIDE;
    }
    return sqrt(area);
}

/* 1 when a triangle of m->dest[0 .. n) faces against the source around
 * all three of its corners (each corner's source triangles' summed
 * normal more than 60 degrees off): a fold. meshoptimizer rejects a
 * collapse that turns a triangle over, but on flat ground of many pieces
 * it still folded a triangle over its neighbour (a quarter of a paving
 * stone, 125 mm, under its measured error). Sliver triangles across a
 * thin curved part face every way at their corners and are not folds. */
static int folds(const part_mesh *m, size_t n)
{
    double *vn = calloc(3 * (size_t)m->wcount + 3, sizeof *vn);
    if (!vn)
        return 1;
    for (uint32_t t = 0; t < m->icount; t += 3) {
        double f[3];
        face_normal(m->wpos + 3 * (size_t)m->idx[t], m->wpos + 3 * (size_t)m->idx[t + 1],
                    m->wpos + 3 * (size_t)m->idx[t + 2], f);
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                vn[3 * (size_t)m->idx[t + c] + k] += f[k];
    }
    int fold = 0;
    for (size_t t = 0; t < n && !fold; t += 3) {
        double nt[3];
        face_normal(m->wpos + 3 * (size_t)m->dest[t], m->wpos + 3 * (size_t)m->dest[t + 1],
                    m->wpos + 3 * (size_t)m->dest[t + 2], nt);
        double lt = sqrt(nt[0] * nt[0] + nt[1] * nt[1] + nt[2] * nt[2]);
        int against = 0;
        for (int c = 0; c < 3 && lt > 0; c++) {
            const double *v = vn + 3 * (size_t)m->dest[t + c];
            double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            against += lv > 0 && nt[0] * v[0] + nt[1] * v[1] + nt[2] * v[2] < -0.5 * lt * lv;
        }
        fold = against == 3;
    }
    free(vn);
    return fold;
}

/* One piece's levels at one front, being made. */
typedef struct piece_job {
    uint32_t piece, front;
    int cut;                      /* its part is cut: border locked, source kept first */
    const sw_part_levels_options *opt;
    sw_part_levels_report *r;
    sw_mesh_view source;
    sw_mesh_grid *source_grid;
    float last_error;
    uint32_t last_indices, kept;
} piece_job;

/* The level in m->dest[0 .. n) with its measured error appended to o as
 * the job's next level: 1 kept, 0 left out (too large), -1 out of memory. */
static int keep_level(part_mesh *m, out_arrays *o, piece_job *j, size_t n, float error)
{
    uint32_t first_vertex = 0, first_index = o->index_count;
    int made = emit(m, j->source_grid, o, (uint32_t)n, &first_vertex);
    sw_part_level *l = sw_grow(o->levels, &o->cap_l, (size_t)o->level_count + 1, sizeof *l);
    if (made == 0 || !l)
        return -1;
    o->levels = l;
    if (made < 0) {
        o->vertex_count = first_vertex;
        j->r->too_large++;
        return 0;
    }
    o->index_count += (uint32_t)n;
    sw_part_level *kept = &o->levels[o->level_count++];
    *kept = (sw_part_level){ j->piece, error, first_vertex, o->vertex_count - first_vertex,
                             first_index, (uint32_t)n, 0, j->front };
    kept->shading_side = (float)miss_shaded_side(m, j->source_grid, o, kept);
    j->r->triangles[j->kept++] += n / 3;
    j->last_error = error, j->last_indices = (uint32_t)n;
    return 1;
}

/* The simplification toward bound into m->dest: its index count, 0 when
 * it is not kept (not a fifth smaller, or folded: counted). */
static size_t simplify_toward(part_mesh *m, piece_job *j, double bound, double scale)
{
    size_t n = meshopt_simplify(m->dest, m->idx, m->icount, m->wpos, m->wcount,
                                3 * sizeof(float), 0, (float)((bound - m->error) / scale),
                                j->cut ? meshopt_SimplifyLockBorder : 0, NULL);
    if (n == 0 || n > 0.8 * j->last_indices) {
        j->r->not_smaller++;
        return 0;
    }
    if (j->cut && folds(m, n)) {
        j->r->folded++;
        return 0;
    }
    return n;
}

/* The job's levels toward rising bounds, kept as the header says. */
static sw_status build_piece(part_mesh *m, out_arrays *o, piece_job *j, sw_error *err)
{
    uint32_t *dest = sw_grow(m->dest, &m->cap_d, m->icount + 1, sizeof *m->dest);
    if (!dest)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    m->dest = dest;
    double size = part_size(m), scale = meshopt_simplifyScale(m->wpos, m->wcount, 12);
    j->source = (sw_mesh_view){ m->wpos, m->idx, m->wcount, m->icount };
    j->source_grid = sw_mesh_grid_make(&j->source);
    if (!j->source_grid)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: grid");
    j->last_error = 0, j->last_indices = m->icount, j->kept = 0;
    int room = 1;
    if (scale > 0 && j->cut) {   /* the source itself: a level at this front */
        memcpy(m->dest, m->idx, m->icount * sizeof *m->idx);
        room = keep_level(m, o, j, m->icount, (float)fmax(m->error, FLT_MIN)) >= 0;
    }
    for (uint32_t k = 0; room && scale > 0 && k < j->opt->count; k++) {
        double bound = size * j->opt->finest * pow(j->opt->step, k);
        if (bound <= 2 * m->error)
            continue;   /* the source is not that much closer to the surfaces */
        size_t n = simplify_toward(m, j, bound, scale);
        if (n == 0)
            continue;
        sw_mesh_view lod = { m->wpos, m->dest, m->wcount, (uint32_t)n };
        sw_mesh_grid *lod_grid = sw_mesh_grid_make(&lod);
        if (!lod_grid) {
            room = 0;
            break;
        }
        double spacing = 2 * bound;
        double d = fmax(sw_mesh_distance(&lod, j->source_grid, spacing),
                        sw_mesh_distance(&j->source, lod_grid, spacing));
        sw_mesh_grid_free(lod_grid);
        float error = (float)(d + m->error);
        if (!(error > j->last_error)) {
            j->r->not_smaller++;
            continue;
        }
        room = keep_level(m, o, j, n, error) >= 0;
        j->r->worst_over_bound = fmax(j->r->worst_over_bound, error / bound);
    }
    sw_mesh_grid_free(j->source_grid);
    if (!room)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    j->r->source_triangles += j->kept ? m->icount / 3 : 0;
    j->r->levels += j->kept;
    return SW_OK;
}

static void free_part_mesh(part_mesh *m)
{
    void *blocks[] = { m->pos, m->nrm, m->weld, m->wpos, m->idx, m->corner, m->wedge_first, m->wedge,
                       m->dest, m->keys, m->key_value };
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

/* The meshes the pieces are simplified from: each surface's finest level at
 * its own front (for a part not cut: it has no border), and the surfaces
 * of cut parts at each of the fronts their pieces share. */
typedef struct piece_sources {
    sw_part_source finest, front[SW_PART_LEVEL_FRONTS];
    int cut_any;
} piece_sources;

static sw_status build_sources(const sw_pack *pack, const sw_levels *levels,
                               const uint8_t *cut, piece_sources *ps, sw_error *err)
{
    memset(ps, 0, sizeof *ps);
    sw_status st = sw_part_source_build(pack, levels, NULL, &ps->finest, err);
    uint32_t n = pack->surface_count;
    for (uint32_t p = 0; p < pack->meta->part_count; p++)
        ps->cut_any |= cut[p];
    if (st != SW_OK || !ps->cut_any)
        return st;
    float *bound = malloc(((size_t)n + 1) * sizeof *bound);
    double *diagonal = malloc(((size_t)pack->meta->part_count + 1) * sizeof *diagonal);
    if (!bound || !diagonal)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    for (uint32_t p = 0; st == SW_OK && p < pack->meta->part_count; p++)
        diagonal[p] = cut[p] ? sw_part_diagonal(pack, p) : 0;
    for (uint32_t f = 0; st == SW_OK && f < SW_PART_LEVEL_FRONTS; f++) {
        for (uint32_t s = 0; s < n; s++) {
            uint32_t p = pack->surfaces[s].part;
            bound[s] = cut[p] ? (float)sw_part_level_front_bound(diagonal[p], f) : 0.0f;
        }
        st = sw_part_source_build(pack, levels, bound, &ps->front[f], err);
    }
    free(bound);
    free(diagonal);
    return st;
}

static void free_sources(piece_sources *ps)
{
    sw_part_source_free(&ps->finest);
    for (uint32_t f = 0; f < SW_PART_LEVEL_FRONTS; f++)
        sw_part_source_free(&ps->front[f]);
}

/* Piece g of the part whose surfaces are [first, end), at every front it
 * is made at. */
static sw_status build_one_piece(part_mesh *m, out_arrays *o, const sw_levels *levels,
                                 const uint32_t *piece_of, const piece_sources *ps, int cut,
                                 uint32_t g, uint32_t first, uint32_t end,
                                 const sw_part_levels_options *opt, sw_part_levels_report *r,
                                 sw_error *err)
{
    uint32_t before = o->level_count;
    sw_status st = SW_OK;
    for (uint32_t f = 0; st == SW_OK && f < (cut ? SW_PART_LEVEL_FRONTS : 1u); f++) {
        const sw_part_source *src = cut ? &ps->front[f] : &ps->finest;
        int got = gather_piece(m, levels, piece_of, src, g, first, end);
        r->incomplete += got < 0;
        piece_job j = { .piece = g, .front = f, .cut = cut, .opt = opt, .r = r };
        if (got == 0 || (got > 0 && (!weld(m) || !orient(m))))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
        else if (got > 0 && m->icount > 0)
            st = build_piece(m, o, &j, err);
    }
    r->with_levels += o->level_count > before;
    return st;
}

static sw_status build_all(const sw_pack *pack, const sw_levels *levels, const uint32_t *piece_of,
                           const uint8_t *cut, const piece_sources *ps,
                           const sw_part_levels_options *opt, out_arrays *o,
                           uint32_t *piece_levels, sw_part_levels_report *r, sw_error *err)
{
    part_mesh m = { 0 };
    sw_status st = SW_OK;
    /* Part by part (a run of surfaces): its pieces are first .. end. */
    for (uint32_t s = 0, e; st == SW_OK && s < pack->surface_count; s = e) {
        uint32_t part = pack->surfaces[s].part, first = piece_of[s], end = first + 1;
        for (e = s; e < pack->surface_count && pack->surfaces[e].part == part; e++)
            end = piece_of[e] + 1 > end ? piece_of[e] + 1 : end;
        for (uint32_t g = first; st == SW_OK && g < end; g++) {
            st = build_one_piece(&m, o, levels, piece_of, ps, cut[part], g, s, e, opt, r, err);
            piece_levels[g + 1] = o->level_count;
        }
    }
    free_part_mesh(&m);
    return st;
}

/* The pieces, and which parts are cut (more than one piece). */
static sw_status cut_parts(const sw_pack *pack, const sw_part_levels_options *opt,
                           sw_part_levels_built *out, uint8_t **cut, sw_part_levels_report *r,
                           sw_error *err)
{
    out->piece_of = malloc(((size_t)pack->surface_count + 1) * sizeof *out->piece_of);
    *cut = calloc((size_t)pack->meta->part_count + 1, 1);
    if (!out->piece_of || !*cut)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    sw_part_pieces_options po = { opt->cut_patches, opt->piece_patches };
    sw_status st = sw_part_pieces(pack, &po, out->piece_of, &r->pieces, err);
    for (uint32_t s = 1; st == SW_OK && s < pack->surface_count; s++)
        if (out->piece_of[s] != out->piece_of[s - 1] &&
            pack->surfaces[s].part == pack->surfaces[s - 1].part)
            (*cut)[pack->surfaces[s].part] = 1;
    for (uint32_t p = 0; st == SW_OK && p < pack->meta->part_count; p++)
        r->cut_parts += (*cut)[p];
    return st;
}

sw_status sw_part_levels_build(const sw_pack *pack, const sw_levels *levels,
                               const sw_part_levels_options *opt, sw_part_levels_built *out,
                               sw_part_levels_report *report, sw_error *err)
{
    memset(out, 0, sizeof *out);
    memset(report, 0, sizeof *report);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    sw_part_levels_options o = opt ? *opt : (sw_part_levels_options){ 0 };
    o.finest = o.finest > 0 ? o.finest : 1.0 / 512;
    o.step = o.step > 1 ? o.step : 2.0;
    o.count = o.count ? (o.count < SW_PART_LEVELS_MAX ? o.count : SW_PART_LEVELS_MAX)
                      : SW_PART_LEVELS_MAX;
    report->parts = pack->meta->part_count;
    uint8_t *cut = NULL;
    piece_sources ps;
    memset(&ps, 0, sizeof ps);
    sw_status st = cut_parts(pack, &o, out, &cut, report, err);
    if (st == SW_OK)
        st = build_sources(pack, levels, cut, &ps, err);
    out_arrays arrays = { 0 };
    if (st == SW_OK) {
        out->piece_levels = calloc((size_t)report->pieces + 1, sizeof *out->piece_levels);
        st = out->piece_levels ? build_all(pack, levels, out->piece_of, cut, &ps, &o, &arrays,
                                           out->piece_levels, report, err)
                               : sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    }
    free_sources(&ps);
    free(cut);
    out->levels = arrays.levels, out->vertices = arrays.vertices, out->indices = arrays.indices;
    out->view = (sw_part_levels){ out->levels, out->piece_levels, out->piece_of, out->vertices,
                                  out->indices, arrays.level_count, arrays.vertex_count,
                                  arrays.index_count, report->pieces, pack->surface_count };
    if (st != SW_OK)
        sw_part_levels_built_free(out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    report->seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    return st;
}

void sw_part_levels_built_free(sw_part_levels_built *b)
{
    free(b->levels);
    free(b->piece_levels);
    free(b->piece_of);
    free(b->vertices);
    free(b->indices);
    memset(b, 0, sizeof *b);
}
