/* SPDX-License-Identifier: MIT */
#include "sw_seam_fill.h"

#include <string.h>

#include "sw_pow2.h"

#include "sw_trim_tess.h"

#define UNSET 0xFFFFFFFFu
#define TANGLED 0xFFFFFFFEu        /* next[]: the vertex starts two border edges */
#define FIRST_WINDS_UP 0x80000000u /* uses: first seen as low -> high index */

size_t sw_seam_fill_arena_bytes(uint32_t max_vertices, uint32_t max_indices)
{
    size_t table = sw_pow2_at_least(2 * max_indices, 16);
    return 2 * sw_arena_worst_case(table * sizeof(uint32_t), 64) +
           sw_arena_worst_case((size_t)max_vertices * sizeof(uint32_t), 64);
}

sw_status sw_seam_fill_init(sw_seam_fill *f, uint32_t max_vertices, uint32_t max_indices,
                            sw_arena *arena, sw_error *err)
{
    memset(f, 0, sizeof *f);
    f->table = sw_pow2_at_least(2 * max_indices, 16);
    f->max_vertices = max_vertices;
    f->keys = sw_arena_alloc(arena, f->table * sizeof(uint32_t), 64);
    f->uses = sw_arena_alloc(arena, f->table * sizeof(uint32_t), 64);
    f->next = sw_arena_alloc(arena, (size_t)max_vertices * sizeof(uint32_t), 64);
    if (!f->keys || !f->uses || !f->next)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the crossing fill "
                            "(needs %zu bytes)", sw_seam_fill_arena_bytes(max_vertices, max_indices));
    return SW_OK;
}

static int on_border(uint32_t id) { return id != SW_TRIM_INTERIOR; }

static void use_edge(sw_seam_fill *f, uint32_t size, uint16_t a, uint16_t b)
{
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a, key = (lo << 16 | hi) + 1;
    uint32_t i = (key * 2654435761u) & (size - 1);
    while (f->keys[i] && f->keys[i] != key)
        i = (i + 1) & (size - 1);
    if (!f->keys[i]) {
        f->keys[i] = key;
        f->uses[i] = a < b ? FIRST_WINDS_UP : 0;
    }
    f->uses[i]++;
}

/* next[v]: where the border edge leaving v goes, following its triangle's
 * winding (edges between border vertices used by one triangle). 0 when the
 * table cannot hold the mesh's border edges. */
static int link_border(sw_seam_fill *f, const uint32_t *ids, uint32_t vertex_count,
                       const uint16_t *indices, uint32_t index_count)
{
    uint32_t edges = 0;
    for (uint32_t t = 0; t + 2 < index_count; t += 3)
        for (int k = 0; k < 3; k++)
            edges += on_border(ids[indices[t + k]]) && on_border(ids[indices[t + (k + 1) % 3]]);
    uint32_t size = sw_pow2_at_least(2 * edges + 16, 16);
    if (size > f->table || vertex_count > f->max_vertices)
        return 0;
    memset(f->keys, 0, size * sizeof(uint32_t));
    for (uint32_t t = 0; t + 2 < index_count; t += 3)
        for (int k = 0; k < 3; k++) {
            uint16_t a = indices[t + k], b = indices[t + (k + 1) % 3];
            if (on_border(ids[a]) && on_border(ids[b]))
                use_edge(f, size, a, b);
        }
    memset(f->next, 0xFF, vertex_count * sizeof(uint32_t));
    for (uint32_t i = 0; i < size; i++) {
        if (!f->keys[i] || (f->uses[i] & ~FIRST_WINDS_UP) != 1)
            continue;
        uint32_t key = f->keys[i] - 1, lo = key >> 16, hi = key & 0xFFFFu;
        int up = (f->uses[i] & FIRST_WINDS_UP) != 0;
        uint32_t from = up ? lo : hi, to = up ? hi : lo;
        f->next[from] = f->next[from] == UNSET ? to : TANGLED;
    }
    return 1;
}

/* The fan over the run of crossings after seam vertex a; the crossings it
 * covered, 0 when the run does not end at a seam vertex (a itself, for a
 * loop shrunk to one) or does not fit. */
static uint32_t fill_run(const sw_seam_fill *f, const uint32_t *ids, uint32_t vertex_count,
                         uint32_t a, uint16_t *indices, uint32_t *index_count, uint32_t capacity)
{
    uint32_t c = f->next[a], k = 0, start = *index_count;
    while (c < vertex_count && ids[c] == SW_TRIM_CROSSING && k <= vertex_count) {
        uint32_t n = f->next[c];
        k++;
        if (n == a) /* a loop left with a as its only seam vertex: the fan is whole */
            return k;
        if (n >= vertex_count)
            break;
        if (*index_count + 3 > capacity)
            break;
        indices[(*index_count)++] = (uint16_t)a;
        indices[(*index_count)++] = (uint16_t)c;
        indices[(*index_count)++] = (uint16_t)n;
        c = n;
    }
    if (k == 0 || c >= vertex_count || ids[c] == SW_TRIM_CROSSING) {
        *index_count = start;  /* not closed onto a seam vertex: left as it was */
        return 0;
    }
    return k;
}

uint32_t sw_seam_fill_crossings(sw_seam_fill *f, const uint32_t *ids, uint32_t vertex_count,
                                uint16_t *indices, uint32_t *index_count, uint32_t capacity,
                                uint32_t *crossings_left)
{
    uint32_t crossings = 0, filled = 0, triangles = 0;
    for (uint32_t v = 0; v < vertex_count; v++)
        crossings += ids[v] == SW_TRIM_CROSSING;
    *crossings_left = crossings;
    if (!crossings || !link_border(f, ids, vertex_count, indices, *index_count))
        return 0;
    for (uint32_t a = 0; a < vertex_count; a++) {
        if (ids[a] == SW_TRIM_CROSSING || !on_border(ids[a]) || f->next[a] >= vertex_count)
            continue;
        uint32_t before = *index_count;
        filled += fill_run(f, ids, vertex_count, a, indices, index_count, capacity);
        triangles += (*index_count - before) / 3;
    }
    *crossings_left = crossings - filled;
    return triangles;
}

uint32_t *sw_seam_fill_drop_list(sw_seam_fill *f, uint32_t *capacity)
{
    /* next[] is the crossings' alone, and sw_seam_fill_drops (which reads
     * the list) runs before them. */
    *capacity = f->max_vertices;
    return f->next;
}

/* The table slot of key (id + 1) in the first size slots of keys. */
static uint32_t id_slot(const sw_seam_fill *f, uint32_t size, uint32_t key)
{
    uint32_t i = (key * 2654435761u) & (size - 1);
    while (f->keys[i] && f->keys[i] != key)
        i = (i + 1) & (size - 1);
    return i;
}

/* The mesh vertex of seam vertex id, UNSET when it has none. */
static uint32_t vertex_of(const sw_seam_fill *f, uint32_t size, uint32_t id)
{
    uint32_t i = id_slot(f, size, id + 1);
    return f->keys[i] ? f->uses[i] : UNSET;
}

/* Appends the vertex of loop point p, at a's normal; UNSET when there is
 * no room. */
static uint32_t add_vertex(sw_seam_fill_mesh *m, const sw_trim_point *p, uint32_t a)
{
    if (m->vertex_count >= m->vertex_capacity)
        return UNSET;
    uint32_t v = m->vertex_count++;
    memcpy(m->positions + 3 * (size_t)v, p->p, 3 * sizeof(float));
    memcpy(m->normals + 3 * (size_t)v, m->normals + 3 * (size_t)a, 3 * sizeof(float));
    if (m->uvs)
        memcpy(m->uvs + 2 * (size_t)v, p->uv, 2 * sizeof(float));
    m->ids[v] = p->id;
    return v;
}

static int add_triangle(sw_seam_fill_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    if (a == b || b == c || c == a)
        return 1;   /* a run that came back to a: nothing to cover there */
    if (m->index_count + 3 > m->index_capacity)
        return 0;
    m->indices[m->index_count++] = (uint16_t)a;
    m->indices[m->index_count++] = (uint16_t)b;
    m->indices[m->index_count++] = (uint16_t)c;
    return 1;
}

/* The drops, sorted (insertion: a surface drops a handful). */
static void sort_drops(uint32_t *d, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++)
        for (uint32_t j = i; j > 0 && d[j - 1] > d[j]; j--) {
            uint32_t t = d[j];
            d[j] = d[j - 1], d[j - 1] = t;
        }
}

static int is_dropped(const sw_seam_drop_list *drops, uint32_t point)
{
    uint32_t lo = 0, hi = drops->count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (drops->points[mid] < point)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < drops->count && drops->points[lo] == point;
}

/* The mesh vertex of loop point i: UNSET when it was dropped or its seam
 * vertex is not in the mesh. */
static uint32_t kept_vertex(const sw_seam_fill *f, uint32_t size, const sw_trim_loops *loops,
                            const sw_seam_drop_list *drops, uint32_t i)
{
    return is_dropped(drops, i) ? UNSET : vertex_of(f, size, loops->points[i].id);
}

/* The fan over the missing points of loop l from its point `from` on
 * (kept, mesh vertex a), once round. */
static void fill_loop(const sw_seam_fill *f, uint32_t size, const sw_trim_loops *loops,
                      const sw_seam_drop_list *drops, uint32_t l, uint32_t from, uint32_t a,
                      sw_seam_fill_mesh *m, uint32_t *filled, uint32_t *left)
{
    uint32_t first = loops->loop_first[l], n = loops->loop_first[l + 1] - first;
    uint32_t last = a;   /* the fan's last vertex: a, or the last missing point's */
    for (uint32_t j = 1; j <= n; j++) {
        uint32_t i = first + (from + j) % n;
        const sw_trim_point *p = &loops->points[i];
        uint32_t v = kept_vertex(f, size, loops, drops, i);
        if (v != UNSET) {   /* kept: the run ends here */
            if (last != a && !add_triangle(m, a, last, v))
                (*left)++;
            a = last = v;
            continue;
        }
        if (m->ids[last] == p->id)
            continue;   /* the same seam vertex again */
        uint32_t d = add_vertex(m, p, a);
        if (d == UNSET || (last != a && !add_triangle(m, a, last, d))) {
            (*left)++;
            continue;
        }
        (*filled)++;
        last = d;
    }
}

uint32_t sw_seam_fill_drops(sw_seam_fill *f, const sw_trim_loops *loops, sw_seam_drop_list *drops,
                            sw_seam_fill_mesh *m, uint32_t *filled, uint32_t *left)
{
    *filled = *left = 0;
    uint32_t size = sw_pow2_at_least(2 * m->vertex_count + 16, 16);
    if (size > f->table)
        return 0;
    sort_drops(drops->points, drops->count);
    memset(f->keys, 0, size * sizeof(uint32_t));
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        if (m->ids[v] == SW_TRIM_INTERIOR || m->ids[v] == SW_TRIM_CROSSING)
            continue;
        uint32_t i = id_slot(f, size, m->ids[v] + 1);
        if (!f->keys[i])
            f->keys[i] = m->ids[v] + 1, f->uses[i] = v;
    }
    uint32_t before = m->index_count;
    for (uint32_t l = 0; l < loops->loop_count; l++) {
        uint32_t first = loops->loop_first[l], n = loops->loop_first[l + 1] - first, from = 0;
        while (from < n && kept_vertex(f, size, loops, drops, first + from) == UNSET)
            from++;
        if (from < n)
            fill_loop(f, size, loops, drops, l, from,
                      kept_vertex(f, size, loops, drops, first + from), m, filled, left);
    }
    return (m->index_count - before) / 3;
}
