/* SPDX-License-Identifier: MIT */
/* Shared by the tests of sw_seam_select (test_seam_select.c: the front;
 * test_seam_select_loop.c: the loops' polylines): a simplified generated
 * graph with its state, and an independent view of a front, recomputed from
 * the graph by walking child links (not the module's leaf ranges and
 * shown[]). Include after sw_test.h. */
#ifndef SEAM_SELECT_FIXTURE_H
#define SEAM_SELECT_FIXTURE_H

#include <stdlib.h>
#include <string.h>

#include "seam_graph_gen.h"
#include "sw_seam_select.h"
#include "sw_seam_simplify.h"

typedef struct fixture {
    sw_seam_host host;
    sw_seam_graph g;
    void *block;
    sw_arena arena;
    sw_seam_select sel;
} fixture;

static inline void fixture_open(fixture *f, const seam_gen *p)
{
    seam_gen_build(p, &f->host);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(&f->host, &err) == SW_OK, "%s", err.message);
    f->g = sw_seam_host_view(&f->host);
    size_t bytes = sw_seam_select_arena_bytes(&f->g);
    f->block = malloc(bytes);
    sw_arena_init(&f->arena, f->block, bytes);
    SW_CHECK_MSG(sw_seam_select_init(&f->sel, &f->g, &f->arena, &err) == SW_OK, "%s",
                 err.message);
}

static inline void fixture_close(fixture *f)
{
    free(f->block);
    sw_seam_host_free(&f->host);
}

static const seam_gen grid = {.nx = 3, .ny = 3, .k = 4, .holes = 1, .bumps = 0.05f, .seed = 3};
static const seam_gen finned = {.nx = 2, .ny = 2, .k = 5, .fin = 1, .free_points = 13,
                                .bumps = 0.1f, .seed = 5};

/* ---- the independent view of a front ---- */

static inline uint32_t child_of(const sw_seam_graph *g, uint32_t v)
{
    return g->vertices[v].child;
}

/* The active vertex on o's path to its root; counts the active ones on it. */
static inline uint32_t active_on_path(const fixture *f, uint32_t o, uint32_t *actives)
{
    uint32_t found = SW_SEAM_NONE;
    *actives = 0;
    for (uint32_t x = o; x != SW_SEAM_NONE; x = child_of(&f->g, x))
        if (sw_seam_select_is_active(&f->sel, x)) {
            (*actives)++;
            if (found == SW_SEAM_NONE)
                found = x;
        }
    return found;
}

static inline int is_under(const sw_seam_graph *g, uint32_t o, uint32_t v)
{
    for (uint32_t x = o; x != SW_SEAM_NONE && x <= v; x = child_of(g, x))
        if (x == v)
            return 1;
    return 0;
}

/* The header's (u, v) rule, literally: walking down from the run's vertex,
 * take v2's side where the run holds a slot of it, else v1's; the run's
 * first slot holding the original reached gives the parameters. */
static inline uint32_t run_uv_slot(const fixture *f, const uint32_t *run, uint32_t n, uint32_t x)
{
    const sw_seam_graph *g = &f->g;
    while (x >= g->original_count) {
        const sw_seam_collapse *c = &g->collapses[x - g->original_count];
        int has_v2 = 0;
        for (uint32_t i = 0; i < n && !has_v2; i++)
            has_v2 = is_under(g, g->slots[run[i]].vertex, c->v2);
        x = has_v2 ? c->v2 : c->v1;
    }
    for (uint32_t i = 0; i < n; i++)
        if (g->slots[run[i]].vertex == x)
            return run[i];
    return SW_SEAM_NONE;
}

/* Loop l's polyline as the header defines it, from scratch. Returns points. */
static inline uint32_t expected_loop(const fixture *f, uint32_t l, sw_seam_point *out, uint32_t *run)
{
    const sw_seam_loop *lp = &f->g.loops[l];
    uint32_t n = lp->slot_count, actives, start = 0;
    uint32_t *shown = malloc(n * sizeof *shown);
    for (uint32_t i = 0; i < n; i++)
        shown[i] = active_on_path(f, f->g.slots[lp->first_slot + i].vertex, &actives);
    for (start = 0; start < n && shown[start] == shown[(start + n - 1) % n]; start++)
        ;
    if (start == n)
        start = 0;
    uint32_t count = 0, len = 0;
    for (uint32_t i = 0; i <= n; i++) {
        uint32_t k = (start + i) % n;
        if (i == n || (len && shown[k] != shown[(k + n - 1) % n])) {
            uint32_t x = shown[(k + n - 1) % n];
            uint32_t slot = run_uv_slot(f, run, len, x);
            out[count++] = (sw_seam_point){x, {f->g.slots[slot].uv[0], f->g.slots[slot].uv[1]}};
            len = 0;
        }
        run[len++] = lp->first_slot + k;
    }
    free(shown);
    return count;
}

/* Every invariant of a front, checked from scratch. Returns failures. */
static inline int check_front(const fixture *f)
{
    const sw_seam_graph *g = &f->g;
    int bad = 0;
    uint32_t actives, active_count = 0;
    for (uint32_t o = 0; o < g->original_count; o++) {
        active_on_path(f, o, &actives);
        bad += actives != 1;
    }
    for (uint32_t v = 0; v < g->vertex_count; v++)
        active_count += sw_seam_select_is_active(&f->sel, v);
    bad += active_count != sw_seam_select_count(&f->sel).active_vertices;
    sw_seam_point *want = malloc(g->slot_count * sizeof *want);
    sw_seam_point *have = malloc(g->slot_count * sizeof *have);
    uint32_t *run = malloc((g->slot_count + 1) * sizeof *run);
    for (uint32_t l = 0; l < g->loop_count; l++) {
        uint32_t n = expected_loop(f, l, want, run), count = 0;
        int vanished = -1;
        sw_status st = sw_seam_select_loop(&f->sel, l, 0.0f, have, g->slot_count, &count, &vanished,
                                           NULL);
        bad += st != SW_OK || count != n || memcmp(want, have, n * sizeof *want) != 0;
        uint32_t distinct = 0;
        for (uint32_t i = 0; i < n && distinct < 3; i++) {
            int seen = 0;
            for (uint32_t j = 0; j < i; j++)
                seen |= want[j].vertex == want[i].vertex;
            distinct += !seen;
        }
        bad += vanished != (distinct < 3);
        /* the dependency invariant: neighbours lived at the same time */
        for (uint32_t i = 0; i < n && n > 1; i++) {
            uint32_t x = want[i].vertex, y = want[(i + 1) % n].vertex;
            bad += !(x < child_of(g, y) && y < child_of(g, x));
        }
    }
    free(want);
    free(have);
    free(run);
    return bad;
}

typedef struct snapshot {
    uint8_t *active;
    sw_seam_point *points;
    uint32_t *counts;
} snapshot;

static inline snapshot take_snapshot(const fixture *f)
{
    snapshot s = {calloc(f->g.vertex_count, 1), malloc(f->g.slot_count * sizeof *s.points),
                  malloc(f->g.loop_count * sizeof *s.counts)};
    for (uint32_t v = 0; v < f->g.vertex_count; v++)
        s.active[v] = (uint8_t)sw_seam_select_is_active(&f->sel, v);
    for (uint32_t l = 0, at = 0; l < f->g.loop_count; l++) {
        sw_seam_select_loop(&f->sel, l, 0.0f, s.points + at, f->g.slot_count - at, &s.counts[l], NULL,
                            NULL);
        at += s.counts[l];
    }
    return s;
}

static inline int same_snapshot(const snapshot *a, const snapshot *b, const fixture *f)
{
    uint32_t points = 0;
    for (uint32_t l = 0; l < f->g.loop_count; l++) {
        if (a->counts[l] != b->counts[l])
            return 0;
        points += a->counts[l];
    }
    return memcmp(a->active, b->active, f->g.vertex_count) == 0 &&
           memcmp(a->points, b->points, points * sizeof *a->points) == 0;
}

static inline void free_snapshot(snapshot *s)
{
    free(s->active);
    free(s->points);
    free(s->counts);
}

/* Splits until every original is active (bound 0 would leave vertices of
 * error 0 collapsed: collinear runs meet any bound). Returns splits. */
static inline uint32_t refine_all(fixture *f)
{
    uint32_t total = 0, splits = 0;
    for (uint32_t v = f->g.vertex_count; v-- > f->g.original_count;)
        if (sw_seam_select_is_active(&f->sel, v)) {
            SW_CHECK(sw_seam_select_force_split(&f->sel, v, 0, &splits, NULL) == SW_OK);
            total += splits;
        }
    return total;
}

/* Random legal steps from the roots; calls check(f, arg) after each and
 * returns the failures it counted. */
static inline uint32_t random_walk(fixture *f, int steps, uint32_t (*check)(const fixture *, float),
                            float arg)
{
    uint32_t created = f->g.collapse_count, bad = 0, done = 0;
    for (int t = 0; t < 1000 + 40 * steps && (int)done < steps; t++) {
        uint32_t v = f->g.original_count + (uint32_t)(sw_test_random() * created);
        int split = sw_test_random() < 0.6;
        if (split ? !sw_seam_select_can_split(&f->sel, v) : !sw_seam_select_can_collapse(&f->sel, v))
            continue;
        bad += (split ? sw_seam_select_split(&f->sel, v, NULL)
                      : sw_seam_select_collapse(&f->sel, v, NULL)) != SW_OK;
        done++;
        bad += check(f, arg);
    }
    SW_CHECK_MSG((int)done == steps, "only %u steps", done);
    return bad;
}

#endif
