/* SPDX-License-Identifier: MIT */
/* Every surface's finest level with its border strips, at one front
 * (sw_part_source.h). */
#include "sw_part_source.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_border_strip.h"
#include "sw_grow.h"
#include "sw_seam_select.h"
#include "sw_seam_surface.h"

typedef struct source_builder {
    const sw_pack *pack;
    const sw_levels *levels;
    const float *front_bound;     /* per surface, or NULL: each surface's finest level's */
    sw_seam_select front;
    void *select_block;
    sw_seam_point *points;        /* one loop's polyline */
    uint32_t *slots;
    sw_strip_point *outer;
    uint32_t *tris;               /* a strip's triangles, or a level's */
    uint32_t max_points, max_chain;
    size_t vertex_cap, index_cap;
    sw_part_source *out;
} source_builder;

static const sw_level *finest_level(const sw_levels *lv, uint32_t s)
{
    return lv->surface_levels[s] < lv->surface_levels[s + 1]
               ? &lv->levels[lv->surface_levels[s]] : NULL;
}

static float level_bound(const sw_level *l)
{
    return l->made_bound > 0 ? l->made_bound : l->error;
}

/* Surface s's level in the source (NULL: none) and the bound its loops are
 * read at. */
static const sw_level *source_level(const source_builder *b, uint32_t s, float *bound)
{
    const sw_levels *lv = b->levels;
    const sw_level *l = finest_level(lv, s);
    if (!b->front_bound) {
        *bound = l ? level_bound(l) : 0;
        return l;
    }
    *bound = b->front_bound[s];
    if (!(*bound > 0))
        return NULL;
    for (uint32_t i = lv->surface_levels[s + 1]; l && i > lv->surface_levels[s]; i--)
        if (level_bound(&lv->levels[i - 1]) <= *bound)
            return &lv->levels[i - 1];
    return l;
}

static sw_status open_builder(source_builder *b, sw_error *err)
{
    const sw_seam_graph *g = &b->pack->seam;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t points = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            points = g->loops[l].slot_count > points ? g->loops[l].slot_count : points;
        b->max_points = points > b->max_points ? points : b->max_points;
    }
    for (uint32_t c = 0; c < b->levels->chain_count; c++)
        if (b->levels->chains[c].point_count > b->max_chain)
            b->max_chain = b->levels->chains[c].point_count;
    size_t select = sw_seam_select_arena_bytes(g), mp = (size_t)b->max_points + 1;
    size_t tris = 3 * (mp + b->max_chain + 1);
    for (uint32_t i = 0; i < b->levels->level_count; i++)
        tris = b->levels->levels[i].index_count > tris ? b->levels->levels[i].index_count : tris;
    b->select_block = malloc(select);
    b->points = malloc(mp * sizeof *b->points);
    b->slots = malloc(mp * sizeof *b->slots);
    b->outer = malloc(mp * sizeof *b->outer);
    b->tris = malloc(tris * sizeof *b->tris);   /* a strip's triangles, or a level's */
    sw_part_source *o = b->out;
    o->surface_count = g->surface_count;
    o->surface_vertices = calloc((size_t)g->surface_count + 1, sizeof *o->surface_vertices);
    o->surface_indices = calloc((size_t)g->surface_count + 1, sizeof *o->surface_indices);
    o->error = malloc(((size_t)g->surface_count + 1) * sizeof *o->error);
    if (!b->select_block || !b->points || !b->slots || !b->outer || !b->tris ||
        !o->surface_vertices || !o->surface_indices || !o->error)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part source: out of memory");
    sw_arena arena;
    sw_arena_init(&arena, b->select_block, select);
    return sw_seam_select_init_checked(&b->front, g, &arena, err);
}

/* The front every surface's finest level was made at (sw_levels_build.c
 * moves it the same way), or the front bounds'; surfaces without a level
 * leave their seams to their neighbours. */
static sw_status move_front(source_builder *b, sw_error *err)
{
    uint32_t n = b->pack->seam.surface_count;
    float *bounds = malloc(((size_t)n + 1) * sizeof *bounds);
    if (!bounds)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part source: out of memory");
    for (uint32_t s = 0; s < n; s++) {
        float at;
        bounds[s] = source_level(b, s, &at) ? (float)(at * SW_SEAM_SHARE) : 1e30f;
    }
    sw_seam_update_result r;
    sw_status st = sw_seam_select_update(&b->front, bounds, 0, &r, err);
    free(bounds);
    return st;
}

/* Room for `vertices` and `indices` more at the end of the output. */
static int make_room(source_builder *b, size_t vertices, size_t indices)
{
    sw_part_source *o = b->out;
    size_t vcap = b->vertex_cap, icap = b->index_cap;
    float *p = sw_grow(o->positions, &vcap, 3 * (o->vertex_count + vertices), sizeof(float));
    if (!p)
        return 0;
    o->positions = p;
    vcap = b->vertex_cap;
    float *nr = sw_grow(o->normals, &vcap, 3 * (o->vertex_count + vertices), sizeof(float));
    if (!nr)
        return 0;
    o->normals = nr, b->vertex_cap = vcap;
    uint32_t *ix = sw_grow(o->indices, &icap, o->index_count + indices, sizeof *ix);
    if (!ix)
        return 0;
    o->indices = ix, b->index_cap = icap;
    return 1;
}

/* Triangle abc's normal (not unit) dotted with its vertices' normals:
 * which way it faces, weighted by its area. */
static double facing(const sw_part_source *o, const uint32_t *t)
{
    const float *pa = o->positions + 3 * (size_t)t[0], *pb = o->positions + 3 * (size_t)t[1],
                *pc = o->positions + 3 * (size_t)t[2];
    double e1[3], e2[3], n[3], dot = 0;
    for (int k = 0; k < 3; k++)
        e1[k] = (double)pb[k] - pa[k], e2[k] = (double)pc[k] - pa[k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++)
            dot += n[k] * o->normals[3 * (size_t)t[c] + k];
    return dot;
}

/* Appends count triangles (vertex triples), all turned one way: the way
 * most of their area faces the surface's normals. A level is wound as its
 * (u, v) domain and a strip as its loop runs, either of which may face
 * away; turned one by one instead, the triangles of no area on a strip
 * (a point of the level's border between two of the polyline's) would
 * face at random and leave edges that are not shared both ways. */
static void add_triangles(sw_part_source *o, const uint32_t *tris, uint32_t count)
{
    double vote = 0;
    for (uint32_t t = 0; t < count; t++)
        vote += facing(o, tris + 3 * t);
    uint32_t *out = o->indices + o->index_count;
    for (uint32_t t = 0; t < count; t++) {
        const uint32_t *in = tris + 3 * t;
        out[0] = in[0], out[1] = vote < 0 ? in[2] : in[1], out[2] = vote < 0 ? in[1] : in[2];
        out += 3;
    }
    o->index_count += 3 * count;
}

/* Loop l's polyline at the front (count points, output vertices from
 * `base` on) and its strip to the level's chain (the level's nv vertices
 * from `level_base`): the strip numbers the level's vertices as the level
 * does and the polyline's after them. */
static void add_strip(source_builder *b, uint32_t loop, uint32_t count, uint32_t base,
                      uint32_t level_base, uint32_t nv, const sw_level_chain *ch)
{
    sw_part_source *o = b->out;
    const sw_seam_graph *g = &b->pack->seam;
    const sw_strip_point *inner = b->levels->chain_points + ch->first_point;
    for (uint32_t j = 0; j < count; j++) {
        memcpy(o->positions + 3 * (size_t)(base + j), g->vertices[b->points[j].vertex].p,
               3 * sizeof(float));
        memset(o->normals + 3 * (size_t)(base + j), 0, 3 * sizeof(float));
        b->outer[j] = (sw_strip_point){ nv + j, (float)b->slots[j] };
    }
    uint32_t tris = sw_border_strip(b->outer, count, inner, ch->point_count,
                                    (float)g->loops[loop].slot_count, b->tris);
    for (uint32_t i = 0; i < 3 * tris; i++)
        b->tris[i] = b->tris[i] < nv ? level_base + b->tris[i] : base + (b->tris[i] - nv);
    /* A polyline point takes the normal of a chain vertex it is joined to. */
    for (uint32_t t = 0; t < tris; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = b->tris[3 * t + k];
            float *nx = o->normals + 3 * (size_t)x;
            for (int d = 1; d < 3 && x >= base; d++) {
                uint32_t from = b->tris[3 * t + (k + d) % 3];
                if (from < base && nx[0] == 0 && nx[1] == 0 && nx[2] == 0)
                    memcpy(nx, o->normals + 3 * (size_t)from, 3 * sizeof(float));
            }
        }
    add_triangles(o, b->tris, tris);
}

/* Surface s's level `l` and its strips to the front's loops, read at
 * bound `at`; 0 when out of memory, -1 when its outer loop vanished at
 * the front. */
static int add_surface(source_builder *b, uint32_t s, const sw_level *l, float at)
{
    const sw_seam_graph *g = &b->pack->seam;
    sw_part_source *o = b->out;
    float pin = (float)(at * SW_SEAM_SHARE);
    uint32_t level_base = o->vertex_count;
    size_t more_v = l->vertex_count, more_i = l->index_count;
    for (uint32_t l2 = g->surface_loops[s]; l2 < g->surface_loops[s + 1]; l2++)
        more_v += g->loops[l2].slot_count,
        more_i += 3 * ((size_t)g->loops[l2].slot_count + b->max_chain);
    if (!make_room(b, more_v, more_i))
        return 0;
    for (uint32_t i = 0; i < l->vertex_count; i++) {
        const sw_level_vertex *v = &b->levels->vertices[l->first_vertex + i];
        memcpy(o->positions + 3 * (size_t)(level_base + i), v->p, sizeof v->p);
        for (int k = 0; k < 3; k++)
            o->normals[3 * (size_t)(level_base + i) + k] = (float)v->normal[k] / 127.0f;
    }
    o->vertex_count += l->vertex_count;
    const uint16_t *li = b->levels->indices + l->first_index;
    for (uint32_t i = 0; i < l->index_count; i++)
        b->tris[i] = level_base + li[i];
    add_triangles(o, b->tris, l->index_count / 3);
    for (uint32_t i = 0; i < g->surface_loops[s + 1] - g->surface_loops[s]; i++) {
        uint32_t loop = g->surface_loops[s] + i, count = 0;
        int vanished = 0;
        sw_seam_select_loop_slots(&b->front, loop, pin, b->points, b->slots, b->max_points,
                                  &count, &vanished, NULL);
        if (vanished && (g->loops[loop].flags & SW_SEAM_LOOP_OUTER))
            return -1;
        const sw_level_chain *ch = &b->levels->chains[l->first_chain + i];
        if (vanished || ch->point_count == 0)
            continue;
        add_strip(b, loop, count, o->vertex_count, level_base, l->vertex_count, ch);
        o->vertex_count += count;
    }
    return 1;
}

sw_status sw_part_source_build(const sw_pack *pack, const sw_levels *levels,
                               const float *front_bound, sw_part_source *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    if (!pack->seam_header || !levels || !levels->levels ||
        levels->surface_count != pack->seam.surface_count)
        return sw_error_set(err, SW_ERR_ARG, "part source: the pack has no Seam Graph or levels");
    source_builder b = { .pack = pack, .levels = levels, .front_bound = front_bound, .out = out };
    sw_status st = open_builder(&b, err);
    if (st == SW_OK)
        st = move_front(&b, err);
    for (uint32_t s = 0; st == SW_OK && s < pack->seam.surface_count; s++) {
        float at;
        const sw_level *l = source_level(&b, s, &at);
        uint32_t v0 = out->vertex_count, i0 = out->index_count;
        int made = l ? add_surface(&b, s, l, at) : -1;
        if (made == 0)
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "part source: out of memory");
        if (made < 0)
            out->vertex_count = v0, out->index_count = i0;
        out->error[s] = made > 0 ? l->error : NAN;
        out->surface_vertices[s + 1] = out->vertex_count;
        out->surface_indices[s + 1] = out->index_count;
    }
    free(b.select_block);
    free(b.points);
    free(b.slots);
    free(b.outer);
    free(b.tris);
    if (st != SW_OK)
        sw_part_source_free(out);
    return st;
}

void sw_part_source_free(sw_part_source *s)
{
    free(s->positions);
    free(s->normals);
    free(s->indices);
    free(s->surface_vertices);
    free(s->surface_indices);
    free(s->error);
    memset(s, 0, sizeof *s);
}
