/* SPDX-License-Identifier: MIT */
/* The static levels' sections (LEVELS, LEVEL_RECORDS, LEVEL_SURFACES,
 * LEVEL_VERTICES, LEVEL_INDICES, LEVEL_CHAINS, LEVEL_CHAIN_POINTS;
 * core/sw_levels.h), checked once at load so that the walk draws a level
 * and its border strips without a check of its own. Runs after the Seam
 * Graph's rules: a level's chains follow its surface's loops, so the loops
 * must be known good. Rules: assets/PACK_FORMAT.md, "The static levels". */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "sw_pack_validate.h"

/* The records are read in place, so their layout is the format. */
_Static_assert(sizeof(sw_pack_levels) == 32, "sw_pack_levels");
_Static_assert(offsetof(sw_pack_levels, surface_count) == 20, "sw_pack_levels.surface_count");
_Static_assert(offsetof(sw_pack_levels, reserved) == 24, "sw_pack_levels.reserved");
_Static_assert(sizeof(sw_level) == 32, "sw_level");
_Static_assert(offsetof(sw_level, error) == 4, "sw_level.error");
_Static_assert(offsetof(sw_level, first_chain) == 24, "sw_level.first_chain");
_Static_assert(offsetof(sw_level, made_bound) == 28, "sw_level.made_bound");
_Static_assert(sizeof(sw_level_vertex) == 16, "sw_level_vertex");
_Static_assert(offsetof(sw_level_vertex, normal) == 12, "sw_level_vertex.normal");
_Static_assert(sizeof(sw_level_chain) == 8, "sw_level_chain");
_Static_assert(sizeof(sw_strip_point) == 8, "sw_strip_point");
_Static_assert(offsetof(sw_strip_point, t) == 4, "sw_strip_point.t");

#define SW_LEVEL_MAX_VERTICES 65536u /* 16-bit indices */

static sw_status check_header(const sw_pack *pack, sw_error *err)
{
    const sw_pack_levels *h = pack->levels_header;
    for (size_t i = 0; i < sizeof h->reserved; i++)
        if (h->reserved[i] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "LEVELS.reserved[%zu]: 0x%02x, expected 0", i,
                                h->reserved[i]);
    if (h->surface_count != pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "LEVELS.surface_count: %u, but SURFACES has %u "
                            "entries", (unsigned)h->surface_count, (unsigned)pack->surface_count);
    return SW_OK;
}

/* Each surface's range of levels: from 0 up to the count, at most
 * SW_LEVELS_MAX each (the walk keeps a surface's levels in a fixed array). */
static sw_status check_surface_levels(const sw_levels *l, sw_error *err)
{
    const uint32_t *sl = l->surface_levels;
    if (sl[0] != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_SURFACES[0]: %u, expected 0",
                            (unsigned)sl[0]);
    for (uint32_t s = 1; s <= l->surface_count; s++) {
        if (sl[s] < sl[s - 1])
            return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_SURFACES[%u]: %u < the previous %u, "
                                "expected non-decreasing", (unsigned)s, (unsigned)sl[s],
                                (unsigned)sl[s - 1]);
        if (sl[s] - sl[s - 1] > SW_LEVELS_MAX)
            return sw_error_set(err, SW_ERR_RANGE, "LEVEL_SURFACES[%u]: surface %u has %u "
                                "levels, at most %u", (unsigned)s, (unsigned)(s - 1),
                                (unsigned)(sl[s] - sl[s - 1]), SW_LEVELS_MAX);
    }
    if (sl[l->surface_count] != l->level_count)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_SURFACES[%u]: %u, expected the "
                            "LEVEL_RECORDS count %u", (unsigned)l->surface_count,
                            (unsigned)sl[l->surface_count], (unsigned)l->level_count);
    return SW_OK;
}

static uint32_t surface_loop_count(const sw_pack *pack, uint32_t s)
{
    return pack->seam.surface_loops[s + 1] - pack->seam.surface_loops[s];
}

/* Level k's own fields, k in surface s's range; the level before it in the
 * range is read for its error only (its own part names it if that is bad). */
static sw_status check_level_fields(const sw_pack *pack, uint32_t s, uint32_t k, sw_error *err)
{
    const sw_levels *l = &pack->levels;
    const sw_level *lv = &l->levels[k];
    unsigned ku = (unsigned)k;
    if (lv->surface != s)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_RECORDS[%u].surface: %u, expected %u "
                            "(LEVEL_SURFACES gives surface %u the levels [%u, %u))", ku,
                            (unsigned)lv->surface, (unsigned)s, (unsigned)s,
                            (unsigned)l->surface_levels[s], (unsigned)l->surface_levels[s + 1]);
    if (!(isfinite(lv->error) && lv->error >= 0.0f))
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_RECORDS[%u].error: %g, expected finite "
                            ">= 0", ku, (double)lv->error);
    if (k > l->surface_levels[s] && !(lv->error > l->levels[k - 1].error))
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_RECORDS[%u].error: %g, expected more than "
                            "the previous level's %g (errors rise over a surface's levels)", ku,
                            (double)lv->error, (double)l->levels[k - 1].error);
    if (lv->vertex_count < 1 || lv->vertex_count > SW_LEVEL_MAX_VERTICES)
        return sw_error_set(err, SW_ERR_RANGE, "LEVEL_RECORDS[%u].vertex_count: %u, expected "
                            "1..%u (16-bit indices)", ku, (unsigned)lv->vertex_count,
                            SW_LEVEL_MAX_VERTICES);
    if ((uint64_t)lv->first_vertex + lv->vertex_count > l->vertex_count)
        return sw_error_set(err, SW_ERR_RANGE, "LEVEL_RECORDS[%u].first_vertex: %u + vertex_count "
                            "%u exceeds LEVEL_VERTICES count %u", ku,
                            (unsigned)lv->first_vertex, (unsigned)lv->vertex_count,
                            (unsigned)l->vertex_count);
    if (lv->index_count % 3 != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_RECORDS[%u].index_count: %u, expected a "
                            "multiple of 3 (triangles)", ku, (unsigned)lv->index_count);
    if ((uint64_t)lv->first_index + lv->index_count > l->index_count)
        return sw_error_set(err, SW_ERR_RANGE, "LEVEL_RECORDS[%u].first_index: %u + index_count "
                            "%u exceeds LEVEL_INDICES count %u", ku, (unsigned)lv->first_index,
                            (unsigned)lv->index_count, (unsigned)l->index_count);
    uint32_t loops = surface_loop_count(pack, s);
    if ((uint64_t)lv->first_chain + loops > l->chain_count)
        return sw_error_set(err, SW_ERR_RANGE, "LEVEL_RECORDS[%u].first_chain: %u + the "
                            "surface's %u loops exceeds LEVEL_CHAINS count %u", ku,
                            (unsigned)lv->first_chain, (unsigned)loops,
                            (unsigned)l->chain_count);
    if (!isfinite(lv->made_bound) || lv->made_bound < 0)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_RECORDS[%u].made_bound: %g, expected "
                            "finite and >= 0", ku, (double)lv->made_bound);
    return SW_OK;
}

static sw_status check_level_indices(const sw_levels *l, uint32_t k, sw_error *err)
{
    const sw_level *lv = &l->levels[k];
    for (uint32_t i = lv->first_index; i < lv->first_index + lv->index_count; i++)
        if (l->indices[i] >= lv->vertex_count)
            return sw_error_set(err, SW_ERR_RANGE, "LEVEL_INDICES[%u]: %u, expected < %u "
                                "(LEVEL_RECORDS[%u].vertex_count)", (unsigned)i,
                                (unsigned)l->indices[i], (unsigned)lv->vertex_count, (unsigned)k);
    return SW_OK;
}

/* Level k's chain for the seam loop `loop` (its i-th loop): in bounds,
 * level-local vertices, once round the loop in t; only a hole may have
 * vanished (no points). */
static sw_status check_chain(const sw_pack *pack, uint32_t k, uint32_t i, uint32_t loop,
                             sw_error *err)
{
    const sw_levels *l = &pack->levels;
    const sw_level *lv = &l->levels[k];
    uint32_t c = lv->first_chain + i;
    const sw_level_chain *chain = &l->chains[c];
    const sw_seam_loop *sl = &pack->seam.loops[loop];
    if ((uint64_t)chain->first_point + chain->point_count > l->chain_point_count)
        return sw_error_set(err, SW_ERR_RANGE, "LEVEL_CHAINS[%u].first_point: %u + point_count "
                            "%u exceeds LEVEL_CHAIN_POINTS count %u", (unsigned)c,
                            (unsigned)chain->first_point, (unsigned)chain->point_count,
                            (unsigned)l->chain_point_count);
    const sw_strip_point *points = &l->chain_points[chain->first_point];
    for (uint32_t p = 0; p < chain->point_count; p++)
        if (points[p].vertex >= lv->vertex_count)
            return sw_error_set(err, SW_ERR_RANGE, "LEVEL_CHAIN_POINTS[%u].vertex: %u, expected "
                                "< %u (LEVEL_RECORDS[%u].vertex_count)",
                                (unsigned)(chain->first_point + p), (unsigned)points[p].vertex,
                                (unsigned)lv->vertex_count, (unsigned)k);
    if (chain->point_count > 0 &&
        !sw_border_chain_valid(points, chain->point_count, (float)sl->slot_count))
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_CHAINS[%u]: its %u points do not go once "
                            "round SEAM_LOOPS[%u] (LEVEL_RECORDS[%u]'s chain %u): expected each "
                            "t in [0, %u), rising but for one wrap", (unsigned)c,
                            (unsigned)chain->point_count, (unsigned)loop, (unsigned)k,
                            (unsigned)i, (unsigned)sl->slot_count);
    if (chain->point_count == 0 && (sl->flags & SW_SEAM_LOOP_OUTER))
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_CHAINS[%u].point_count: 0, but "
                            "SEAM_LOOPS[%u] is an outer loop (LEVEL_RECORDS[%u]'s chain %u; only "
                            "a hole vanishes)", (unsigned)c, (unsigned)loop, (unsigned)k,
                            (unsigned)i);
    return SW_OK;
}

/* Everything about level k of surface s, in rule order. */
static sw_status check_level(const sw_pack *pack, uint32_t s, uint32_t k, sw_error *err)
{
    sw_status st = check_level_fields(pack, s, k, err);
    if (st == SW_OK)
        st = check_level_indices(&pack->levels, k, err);
    uint32_t first_loop = pack->seam.surface_loops[s];
    for (uint32_t i = 0; st == SW_OK && i < surface_loop_count(pack, s); i++)
        st = check_chain(pack, k, i, first_loop + i, err);
    return st;
}

static sw_status check_vertex(const sw_levels *l, uint32_t i, sw_error *err)
{
    const sw_level_vertex *v = &l->vertices[i];
    for (int k = 0; k < 3; k++)
        if (!isfinite(v->p[k]))
            return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_VERTICES[%u].p.%c: %g, expected a "
                                "finite number", (unsigned)i, "xyz"[k], (double)v->p[k]);
    if (v->normal[3] != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "LEVEL_VERTICES[%u].normal[3]: %d, expected 0",
                            (unsigned)i, (int)v->normal[3]);
    return SW_OK;
}

/* The per-level and per-vertex checks in parts (sw_parts.h), as the Seam
 * Graph's are: the surfaces' levels in quarters (each level with its
 * indices and chains), then the vertices in halves. Every part reads only
 * what the header and LEVEL_SURFACES checks have bounded, finds the first
 * problem in its own range and stops; the first failing part in this order
 * names the problem, the same one a single pass in rule order would. */
enum { LEVEL_PARTS = 4, VERTEX_PARTS = 2, CHECK_PARTS = LEVEL_PARTS + VERTEX_PARTS };

typedef struct levels_job {
    const sw_pack *pack;
    sw_status status[CHECK_PARTS];
    sw_error err[CHECK_PARTS];
} levels_job;

/* Part p of count's share of n items: [*lo, *hi). */
static void share(uint32_t n, uint32_t p, uint32_t count, uint32_t *lo, uint32_t *hi)
{
    *lo = (uint32_t)((uint64_t)n * p / count);
    *hi = (uint32_t)((uint64_t)n * (p + 1) / count);
}

static sw_status check_surfaces(const sw_pack *pack, uint32_t p, sw_error *err)
{
    const sw_levels *l = &pack->levels;
    uint32_t lo, hi;
    share(l->surface_count, p, LEVEL_PARTS, &lo, &hi);
    sw_status st = SW_OK;
    for (uint32_t s = lo; st == SW_OK && s < hi; s++)
        for (uint32_t k = l->surface_levels[s]; st == SW_OK && k < l->surface_levels[s + 1]; k++)
            st = check_level(pack, s, k, err);
    return st;
}

static sw_status check_vertices(const sw_levels *l, uint32_t p, sw_error *err)
{
    uint32_t lo, hi;
    share(l->vertex_count, p, VERTEX_PARTS, &lo, &hi);
    sw_status st = SW_OK;
    for (uint32_t i = lo; st == SW_OK && i < hi; i++)
        st = check_vertex(l, i, err);
    return st;
}

static void run_part(void *arg, uint32_t p)
{
    levels_job *job = arg;
    sw_error *err = &job->err[p];
    job->status[p] = p < LEVEL_PARTS ? check_surfaces(job->pack, p, err)
                                     : check_vertices(&job->pack->levels, p - LEVEL_PARTS, err);
}

sw_status sw_pack_validate_levels(const sw_pack *pack, const sw_parts_runner *runner,
                                  sw_error *err)
{
    if (!pack->levels_header)
        return SW_OK;
    sw_status s = check_header(pack, err);
    if (s == SW_OK)
        s = check_surface_levels(&pack->levels, err);
    if (s != SW_OK)
        return s;
    levels_job job = {.pack = pack};
    sw_parts_run(runner, run_part, &job, CHECK_PARTS);
    for (int p = 0; p < CHECK_PARTS; p++)
        if (job.status[p] != SW_OK) {
            if (err)
                *err = job.err[p];
            return job.status[p];
        }
    return SW_OK;
}
