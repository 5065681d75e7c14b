/* SPDX-License-Identifier: MIT */
/* Surface adjacency from the Seam Graph (sw_surface_adjacency.h): every
 * original vertex's slots name their loops' surfaces; each pair of distinct
 * surfaces met at one vertex is an edge, kept once after a sort. */
#include "sw_surface_adjacency.h"

#include <stdlib.h>
#include <string.h>

typedef struct pair_list {
    uint64_t *keys;           /* (a << 32) | b, both directions */
    uint64_t count, cap;
} pair_list;

static int push_pair(pair_list *l, uint32_t a, uint32_t b)
{
    if (l->count + 2 > l->cap) {
        uint64_t cap = l->cap ? 2 * l->cap : 1024;
        uint64_t *k = realloc(l->keys, (size_t)cap * sizeof *k);
        if (!k)
            return 0;
        l->keys = k, l->cap = cap;
    }
    l->keys[l->count++] = (uint64_t)a << 32 | b;
    l->keys[l->count++] = (uint64_t)b << 32 | a;
    return 1;
}

static int compare_keys(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return (a > b) - (a < b);
}

/* The sorted, deduplicated keys as rows per surface. */
static sw_status rows_from_keys(pair_list *l, uint32_t surface_count, sw_surface_adjacency *out,
                                sw_error *err)
{
    if (l->count > 1)   /* no pairs: keys may be NULL, which qsort may not take */
        qsort(l->keys, (size_t)l->count, sizeof *l->keys, compare_keys);
    out->surface_count = surface_count;
    out->first = calloc((size_t)surface_count + 1, sizeof *out->first);
    out->next = malloc(((size_t)l->count + 1) * sizeof *out->next);
    if (!out->first || !out->next) {
        sw_surface_adjacency_free(out);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "surface adjacency: out of memory for %llu "
                            "pairs", (unsigned long long)l->count);
    }
    uint32_t n = 0;
    for (uint64_t i = 0; i < l->count; i++) {
        if (i > 0 && l->keys[i] == l->keys[i - 1])
            continue;
        out->first[(l->keys[i] >> 32) + 1]++;
        out->next[n++] = (uint32_t)l->keys[i];
    }
    for (uint32_t s = 0; s < surface_count; s++)
        out->first[s + 1] += out->first[s];
    return SW_OK;
}

sw_status sw_surface_adjacency_from_pairs(uint32_t surface_count, const uint32_t (*pairs)[2],
                                          uint64_t pair_count, sw_surface_adjacency *out,
                                          sw_error *err)
{
    memset(out, 0, sizeof *out);
    pair_list l = { 0 };
    for (uint64_t i = 0; i < pair_count; i++) {
        if (pairs[i][0] >= surface_count || pairs[i][1] >= surface_count ||
            pairs[i][0] == pairs[i][1]) {
            free(l.keys);
            return sw_error_set(err, SW_ERR_ARG, "surface adjacency: pair %llu (%u, %u) is not "
                                "two surfaces of %u", (unsigned long long)i,
                                (unsigned)pairs[i][0], (unsigned)pairs[i][1],
                                (unsigned)surface_count);
        }
        if (!push_pair(&l, pairs[i][0], pairs[i][1])) {
            free(l.keys);
            return sw_error_set(err, SW_ERR_NO_MEMORY, "surface adjacency: out of memory");
        }
    }
    sw_status st = rows_from_keys(&l, surface_count, out, err);
    free(l.keys);
    return st;
}

/* slot -> its loop's surface (the slots' loops are found by the loops'
 * slot ranges; a checked graph puts every slot in exactly one loop). */
static uint32_t *slot_surfaces(const sw_seam_graph *g)
{
    uint32_t *of = malloc(((size_t)g->slot_count + 1) * sizeof *of);
    for (uint32_t l = 0; of && l < g->loop_count; l++)
        for (uint32_t k = 0; k < g->loops[l].slot_count; k++)
            of[g->loops[l].first_slot + k] = g->loops[l].surface;
    return of;
}

static int compare_u32(const void *x, const void *y)
{
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return (a > b) - (a < b);
}

/* The pairs of distinct surfaces met at original vertex v, each once: a
 * vertex may stand in thousands of slots of a few surfaces (a printer
 * bed's outline sewn 54 slots to a vertex), and a pair per two slots ran
 * out of memory. seen: scratch for the vertex's slots. */
static int pairs_at(const sw_seam_graph *g, const uint32_t *surface_of, uint32_t v, pair_list *l,
                    uint32_t *seen)
{
    const sw_seam_vertex *vx = &g->vertices[v];
    uint32_t n = 0;
    for (uint32_t i = 0; i < vx->slot_ref_count; i++)
        seen[n++] = surface_of[g->slot_refs[vx->first_slot_ref + i]];
    if (n > 1)
        qsort(seen, n, sizeof *seen, compare_u32);
    uint32_t distinct = 0;
    for (uint32_t i = 0; i < n; i++)
        if (i == 0 || seen[i] != seen[i - 1])
            seen[distinct++] = seen[i];
    for (uint32_t i = 0; i < distinct; i++)
        for (uint32_t j = i + 1; j < distinct; j++)
            if (!push_pair(l, seen[i], seen[j]))
                return 0;
    return 1;
}

sw_status sw_surface_adjacency_build(const sw_seam_graph *g, sw_surface_adjacency *out,
                                     sw_error *err)
{
    memset(out, 0, sizeof *out);
    uint32_t *surface_of = slot_surfaces(g);
    uint32_t most = 0;
    for (uint32_t v = 0; v < g->original_count; v++)
        most = g->vertices[v].slot_ref_count > most ? g->vertices[v].slot_ref_count : most;
    uint32_t *seen = malloc(((size_t)most + 1) * sizeof *seen);
    pair_list l = { 0 };
    int ok = surface_of != NULL && seen != NULL;
    for (uint32_t v = 0; ok && v < g->original_count; v++)
        ok = pairs_at(g, surface_of, v, &l, seen);
    free(surface_of);
    free(seen);
    sw_status st = ok ? rows_from_keys(&l, g->surface_count, out, err)
                      : sw_error_set(err, SW_ERR_NO_MEMORY, "surface adjacency: out of memory");
    free(l.keys);
    return st;
}

void sw_surface_adjacency_free(sw_surface_adjacency *a)
{
    free(a->first);
    free(a->next);
    memset(a, 0, sizeof *a);
}
