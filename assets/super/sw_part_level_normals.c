/* SPDX-License-Identifier: MIT */
/* A simplified level written out with a normal per corner chosen from the
 * source's, and its area shaded wrong measured (sw_part_mesh.h). */
#include "sw_part_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"
#include "sw_pow2.h"

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

/* Of the normals the surfaces meeting at welded vertex w have there, the
 * one closest to the line of n, turned to n's side (the renderer takes a
 * normal to face the way its triangle winds, and lights both sides). */
static void closest_normal(const sw_part_mesh *m, uint32_t w, const double n[3], int8_t q[3])
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
static void source_normal(const sw_part_mesh *m, const sw_mesh_point *at, double n[3])
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
static uint32_t output_vertex(sw_part_mesh *m, sw_part_level_arrays *o, uint32_t first, size_t cap,
                              uint32_t w, const int8_t q[3])
{
    uint64_t key = ((uint64_t)w << 24 | (uint64_t)(uint8_t)q[0] << 16 |
                    (uint64_t)(uint8_t)q[1] << 8 | (uint8_t)q[2]) + 1;
    size_t h = sw_part_hash64(key) & (cap - 1);
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
static void corner_normal(const sw_part_mesh *m, const sw_mesh_grid *source_grid,
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

int sw_part_level_emit(sw_part_mesh *m, const sw_mesh_grid *source_grid, sw_part_level_arrays *o, uint32_t n,
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
        sw_part_face_normal(m->wpos + 3 * (size_t)m->dest[t], m->wpos + 3 * (size_t)m->dest[t + 1],
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
    const sw_part_mesh *m;
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

double sw_part_level_shaded_side(const sw_part_mesh *m, const sw_mesh_grid *source_grid,
                               const sw_part_level_arrays *o, const sw_part_level *l)
{
    /* The corners take the source's normals; between them, on the edges
     * too, the blend may match no face (two walls at a right angle). */
    enum { N = 6, POINTS = (N + 1) * (N + 2) / 2 - 3 };
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
        for (int i = 0; i <= N; i++)
            for (int j = 0; i + j <= N; j++) {
                if (i == N || j == N || i + j == 0)
                    continue;
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
        sw_part_face_normal(p[0], p[1], p[2], n);
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * off / POINTS;
    }
    return sqrt(area);
}
