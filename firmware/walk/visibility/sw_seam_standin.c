/* SPDX-License-Identifier: MIT */
/* Stand-ins from static levels (sw_seam_standin.h). V's thread. */
#include "sw_seam_standin.h"

#include <math.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_walk_memory.h"

static uint32_t longest_chain(const sw_levels *lv)
{
    uint32_t most = 0;
    for (uint32_t i = 0; i < lv->chain_count; i++)
        most = lv->chains[i].point_count > most ? lv->chains[i].point_count : most;
    return most;
}

size_t sw_seam_standin_bytes(const sw_pack *pack)
{
    sw_walk_sizes m = sw_walk_largest_surface(&pack->seam, pack->surfaces);
    size_t p = (size_t)m.points + 1, l = (size_t)m.loops + 1;
    size_t t = p + longest_chain(&pack->levels) + 1;
    return sw_arena_worst_case(p * sizeof(sw_seam_point), 64) +
           sw_arena_worst_case(p * sizeof(uint32_t), 64) +
           2 * sw_arena_worst_case(l * sizeof(uint32_t), 64) + sw_arena_worst_case(l, 64) +
           sw_arena_worst_case(p * sizeof(sw_strip_point), 64) +
           sw_arena_worst_case(p * sizeof(uint32_t), 64) +
           sw_arena_worst_case(3 * t * sizeof(uint32_t), 64);
}

sw_status sw_seam_standin_init(sw_seam_standin *m, const sw_pack *pack, sw_arena *arena,
                               sw_error *err)
{
    sw_walk_sizes s = sw_walk_largest_surface(&pack->seam, pack->surfaces);
    memset(m, 0, sizeof *m);
    m->pack = pack;
    m->capacity = s.points + 1, m->max_loops = s.loops + 1;
    m->max_chain = longest_chain(&pack->levels);
    size_t t = (size_t)m->capacity + m->max_chain + 1;
    m->points = sw_arena_alloc(arena, m->capacity * sizeof *m->points, 64);
    m->slots = sw_arena_alloc(arena, m->capacity * sizeof *m->slots, 64);
    m->loop_at = sw_arena_alloc(arena, m->max_loops * sizeof *m->loop_at, 64);
    m->loop_count = sw_arena_alloc(arena, m->max_loops * sizeof *m->loop_count, 64);
    m->vanished = sw_arena_alloc(arena, m->max_loops, 64);
    m->outer = sw_arena_alloc(arena, m->capacity * sizeof *m->outer, 64);
    m->same = sw_arena_alloc(arena, m->capacity * sizeof *m->same, 64);
    m->tris = sw_arena_alloc(arena, 3 * t * sizeof *m->tris, 64);
    if (!m->points || !m->slots || !m->loop_at || !m->loop_count || !m->vanished ||
        !m->outer || !m->same || !m->tris)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the stand-ins' "
                            "buffers (%zu bytes)", sw_seam_standin_bytes(pack));
    return SW_OK;
}

/* 1 when level k has a chain for every loop of its surface. */
static int whole(const sw_levels *lv, uint32_t k, uint32_t loops)
{
    for (uint32_t i = 0; i < loops; i++)
        if (lv->chains[lv->levels[k].first_chain + i].point_count == 0)
            return 0;
    return 1;
}

float sw_seam_standin_worth(const sw_level *level, int silhouette)
{
    if (!silhouette)
        return level->error;
    return level->made_bound > 0 ? fmaxf(level->made_bound, level->error) : 4.0f * level->error;
}

uint32_t sw_seam_standin_level(const sw_pack *pack, uint32_t s, float bound, int silhouette)
{
    uint32_t first, end;
    sw_pack_surface_levels(pack, s, &first, &end);
    uint32_t loops = first < end ? pack->seam.surface_loops[s + 1] - pack->seam.surface_loops[s]
                                 : 0;
    uint32_t best = UINT32_MAX;
    for (uint32_t k = first; k < end; k++) {
        if (!whole(&pack->levels, k, loops))
            continue;
        sw_level rec = sw_pack_level(pack, s, k);
        if (best == UINT32_MAX || sw_seam_standin_worth(&rec, silhouette) <= bound)
            best = k;
    }
    return best != UINT32_MAX ? best : first < end ? first : UINT32_MAX;
}

uint32_t sw_seam_standin_coarser(const sw_pack *pack, uint32_t s, uint32_t level)
{
    uint32_t first, end;
    sw_pack_surface_levels(pack, s, &first, &end);
    uint32_t loops = first < end ? pack->seam.surface_loops[s + 1] - pack->seam.surface_loops[s]
                                 : 0;
    for (uint32_t k = level + 1; k < end; k++)
        if (k > first && whole(&pack->levels, k, loops))
            return k;
    return UINT32_MAX;
}

/* Surface s's loops at front into m; 0 when an outer loop vanished. *points
 * gets their points in all. */
static int gather(sw_seam_standin *m, const sw_seam_fronts *fronts, const uint32_t *shown,
                  uint32_t s, uint32_t *points)
{
    const sw_seam_graph *g = &m->pack->seam;
    uint32_t at = 0, first = g->surface_loops[s];
    for (uint32_t l = first; l < g->surface_loops[s + 1]; l++) {
        uint32_t count = 0;
        int vanished = 0;
        /* Cannot fail: l is in range and the buffers hold the surface's slots. */
        sw_seam_fronts_loop_slots(fronts, shown, l, 0.0f, m->points + at, m->slots + at,
                                  m->capacity - at, &count, &vanished, NULL);
        if (vanished && (g->loops[l].flags & SW_SEAM_LOOP_OUTER))
            return 0;
        m->loop_at[l - first] = at, m->loop_count[l - first] = count;
        m->vanished[l - first] = (uint8_t)vanished;
        at += count;
    }
    *points = at;
    return 1;
}

int sw_seam_standin_vanishes(sw_seam_standin *m, const sw_seam_fronts *fronts, uint32_t s)
{
    uint32_t points = 0;
    return !gather(m, fronts, NULL, s, &points);
}

_Static_assert(sizeof(sw_level_vertex) == sizeof(sw_vertex), "a level's vertices are drawn as "
               "they are stored");

/* Triangle t turned to face where its vertices' normals point. */
static void face_out(const sw_vertex *v, uint16_t *t)
{
    const float *a = v[t[0]].pos, *b = v[t[1]].pos, *c = v[t[2]].pos;
    double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0] };
    double dot = 0;
    for (int k = 0; k < 3; k++)
        dot += n[k] * ((double)v[t[0]].normal[k] + v[t[1]].normal[k] + v[t[2]].normal[k]);
    if (dot < 0) {
        uint16_t x = t[1];
        t[1] = t[2], t[2] = x;
    }
}

/* Where the strip joins one of the loop's points to a chain vertex at the
 * very same position (the front shows the vertex the level was made
 * with), the point is that vertex: same[j] its index, else the point's
 * own. So the strip's triangles of no area (many: the front often shows
 * the vertices the level was made with) repeat an index and are left out,
 * and the mesh's edges stay whole (every edge inside it used twice). */
static void join_same(sw_seam_standin *m, uint32_t count, uint32_t base, uint32_t tris,
                      const sw_vertex *v)
{
    for (uint32_t j = 0; j < count; j++)
        m->same[j] = base + j;
    for (uint32_t t = 0; t < tris; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = m->tris[3 * t + k], y = m->tris[3 * t + (k + 1) % 3];
            if (x < base)
                x = y, y = m->tris[3 * t + k];
            if (x >= base && y < base && m->same[x - base] == x &&
                !memcmp(v[x].pos, v[y].pos, sizeof v[x].pos))
                m->same[x - base] = y;
        }
}

/* Loop i's strip between its points (mesh vertices from `base`) and the
 * level's chain, appended at idx; returns the indices written (0: the
 * chains did not make a strip). The points take their normals from the
 * level's chain vertices they are joined to. */
static uint32_t strip(sw_seam_standin *m, uint32_t i, uint32_t base, const sw_level_chain *ch,
                      float period, sw_vertex *v, uint16_t *idx)
{
    const sw_strip_point *inner = m->pack->levels.chain_points + ch->first_point;
    uint32_t count = m->loop_count[i], at = m->loop_at[i];
    for (uint32_t j = 0; j < count; j++)
        m->outer[j] = (sw_strip_point){ base + j, (float)m->slots[at + j] };
    uint32_t tris = sw_border_strip(m->outer, count, inner, ch->point_count, period, m->tris);
    for (uint32_t t = 0; t < tris; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = m->tris[3 * t + k], from = m->tris[3 * t + (k + 1) % 3];
            if (x >= base && from < base)
                memcpy(v[x].normal, v[from].normal, sizeof v[x].normal);
            from = m->tris[3 * t + (k + 2) % 3];
            if (x >= base && from < base)
                memcpy(v[x].normal, v[from].normal, sizeof v[x].normal);
        }
    join_same(m, count, base, tris, v);
    uint32_t written = 0;
    for (uint32_t t = 0; t < tris; t++) {
        uint16_t *out = idx + written;
        for (int k = 0; k < 3; k++) {
            uint32_t x = m->tris[3 * t + k];
            out[k] = (uint16_t)(x >= base ? m->same[x - base] : x);
        }
        if (out[0] == out[1] || out[1] == out[2] || out[0] == out[2])
            continue;
        face_out(v, out);
        written += 3;
    }
    return written;
}

/* Vertices and indices the stand-in needs; cracks for outer loops it
 * leaves as the level has them. A hole the level was made without (its
 * tessellator refused the loops with it, and drew the surface whole) is
 * drawn filled, as the walk's own mesh draws it then
 * (sw_seam_entry.holes_filled), not counted as a crack. */
static void sizes(const sw_seam_standin *m, uint32_t s, const sw_level *lv_rec, uint32_t *n,
                  uint32_t *idx, uint32_t *cracks, uint8_t *holes_filled)
{
    const sw_seam_graph *g = &m->pack->seam;
    *n = lv_rec->vertex_count, *idx = lv_rec->index_count, *cracks = 0, *holes_filled = 0;
    for (uint32_t i = 0; i < g->surface_loops[s + 1] - g->surface_loops[s]; i++) {
        const sw_level_chain *ch = &m->pack->levels.chains[lv_rec->first_chain + i];
        if (ch->point_count == 0) {
            int outer = (g->loops[g->surface_loops[s] + i].flags & SW_SEAM_LOOP_OUTER) != 0;
            if (!m->vanished[i] && outer)
                *cracks += m->loop_count[i];
            else if (!m->vanished[i])
                *holes_filled = 1;
            continue;
        }
        *n += m->loop_count[i];
        *idx += 3 * (m->loop_count[i] + ch->point_count);
    }
}

void sw_seam_standin_estimate(const sw_pack *pack, uint32_t s, uint32_t level,
                              uint32_t *vertices, uint32_t *indices)
{
    const sw_seam_graph *g = &pack->seam;
    const sw_level *rec = &pack->levels.levels[level];   /* counts alone: not placed */
    uint64_t n = rec->vertex_count, idx = rec->index_count;
    for (uint32_t i = 0; i < g->surface_loops[s + 1] - g->surface_loops[s]; i++) {
        uint32_t points = pack->levels.chains[rec->first_chain + i].point_count;
        n += points, idx += 6ull * points;
    }
    *vertices = n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
    *indices = idx > UINT32_MAX ? UINT32_MAX : (uint32_t)idx;
}

int sw_seam_standin_make(sw_seam_standin *m, const sw_seam_fronts *fronts,
                         const uint32_t *shown, uint32_t s, uint32_t level, sw_seam_cache *c,
                         sw_seam_place_fn place, void *place_ctx, sw_seam_entry *e)
{
    const sw_levels *lv = &m->pack->levels;
    const sw_level placed = sw_pack_level(m->pack, s, level);
    const sw_level *rec = &placed;
    const sw_seam_graph *g = &m->pack->seam;
    memset(e, 0, sizeof *e);
    e->made_bound = e->error_bound = rec->error;
    uint32_t points = 0, n = 0, idx = 0, cracks = 0;
    uint8_t holes_filled = 0;
    if (!gather(m, fronts, shown, s, &points)) {
        e->state = SW_SEAM_GONE;
        return 1;
    }
    sizes(m, s, rec, &n, &idx, &cracks, &holes_filled);
    if (n > SW_WALK_VERTICES || idx > SW_WALK_INDICES) {
        e->state = SW_SEAM_FAILED;
        e->cracks = points;
        return 1;
    }
    if (!place(place_ctx, s, n, idx, e)) {
        memset(e, 0, sizeof *e);
        return 0;
    }
    sw_vertex *v = c->verts + (size_t)e->vertex_block * SW_SEAM_CACHE_VERTEX_UNIT;
    uint16_t *out = c->index_data + (size_t)e->index_block * SW_SEAM_CACHE_INDEX_UNIT;
    sw_pack_level_vertices(m->pack, s, rec, (sw_level_vertex *)v);
    memcpy(out, lv->indices + rec->first_index, rec->index_count * sizeof *out);
    uint32_t base = rec->vertex_count, written = rec->index_count;
    for (uint32_t i = 0; i < g->surface_loops[s + 1] - g->surface_loops[s]; i++) {
        const sw_level_chain *ch = &lv->chains[rec->first_chain + i];
        if (ch->point_count == 0)
            continue;
        for (uint32_t j = 0; j < m->loop_count[i]; j++) {
            sw_vertex *p = &v[base + j];
            sw_seam_fronts_position(fronts, m->points[m->loop_at[i] + j].vertex, p->pos);
            memset(p->normal, 0, sizeof p->normal);
        }
        float period = (float)g->loops[g->surface_loops[s] + i].slot_count;
        written += strip(m, i, base, ch, period, v, out + written);
        base += m->loop_count[i];
    }
    /* A stand-in has no parameters: measuring, which keeps them, skips it. */
    float *uv = c->uvs ? c->uvs + 2 * (size_t)e->vertex_block * SW_SEAM_CACHE_VERTEX_UNIT : NULL;
    for (uint32_t i = 0; uv && i < 2 * n; i++)
        uv[i] = NAN;
    e->vertex_count = n, e->index_count = written;
    e->cracks = cracks;
    e->holes_filled = holes_filled;
    e->state = SW_SEAM_READY;
    return 1;
}
