/* sw_seam_select: the runtime front over the Seam Graph's collapse hierarchy
 * (paper 5.5, 6.1). The checks here recompute everything from the graph by
 * walking child links (not the module's leaf ranges and shown[]), so they
 * are independent of the code that keeps the state. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "seam_graph_gen.h"
#include "sw_alloc_count.h"
#include "sw_border_strip.h"
#include "sw_seam_select.h"
#include "sw_seam_simplify.h"
#include "sw_test.h"

typedef struct fixture {
    sw_seam_host host;
    sw_seam_graph g;
    void *block;
    sw_arena arena;
    sw_seam_select sel;
} fixture;

static void fixture_open(fixture *f, const seam_gen *p)
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

static void fixture_close(fixture *f)
{
    free(f->block);
    sw_seam_host_free(&f->host);
}

static const seam_gen grid = {.nx = 3, .ny = 3, .k = 4, .holes = 1, .bumps = 0.05f, .seed = 3};
static const seam_gen finned = {.nx = 2, .ny = 2, .k = 5, .fin = 1, .free_points = 13,
                                .bumps = 0.1f, .seed = 5};

/* ---- the independent view of a front ---- */

static uint32_t child_of(const sw_seam_graph *g, uint32_t v)
{
    return g->vertices[v].child;
}

/* The active vertex on o's path to its root; counts the active ones on it. */
static uint32_t active_on_path(const fixture *f, uint32_t o, uint32_t *actives)
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

static int is_under(const sw_seam_graph *g, uint32_t o, uint32_t v)
{
    for (uint32_t x = o; x != SW_SEAM_NONE && x <= v; x = child_of(g, x))
        if (x == v)
            return 1;
    return 0;
}

/* The header's (u, v) rule, literally: walking down from the run's vertex,
 * take v2's side where the run holds a slot of it, else v1's; the run's
 * first slot holding the original reached gives the parameters. */
static uint32_t run_uv_slot(const fixture *f, const uint32_t *run, uint32_t n, uint32_t x)
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
static uint32_t expected_loop(const fixture *f, uint32_t l, sw_seam_point *out, uint32_t *run)
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
static int check_front(const fixture *f)
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

static snapshot take_snapshot(const fixture *f)
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

static int same_snapshot(const snapshot *a, const snapshot *b, const fixture *f)
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

static void free_snapshot(snapshot *s)
{
    free(s->active);
    free(s->points);
    free(s->counts);
}

/* Splits until every original is active (bound 0 would leave vertices of
 * error 0 collapsed: collinear runs meet any bound). Returns splits. */
static uint32_t refine_all(fixture *f)
{
    uint32_t total = 0, splits = 0;
    for (uint32_t v = f->g.vertex_count; v-- > f->g.original_count;)
        if (sw_seam_select_is_active(&f->sel, v)) {
            SW_CHECK(sw_seam_select_force_split(&f->sel, v, 0, &splits, NULL) == SW_OK);
            total += splits;
        }
    return total;
}

/* ---- tests ---- */

static void test_starts_at_the_roots(void)
{
    fixture f;
    fixture_open(&f, &finned);
    for (uint32_t v = 0; v < f.g.vertex_count; v++)
        SW_CHECK(sw_seam_select_is_active(&f.sel, v) == (child_of(&f.g, v) == SW_SEAM_NONE));
    sw_seam_select_stats st = sw_seam_select_count(&f.sel);
    SW_CHECK(st.loops_vanished == f.g.loop_count);       /* one vertex per part */
    SW_CHECK(st.surfaces_vanished == f.g.surface_count);
    SW_CHECK(check_front(&f) == 0);
    fixture_close(&f);
}

/* Random legal splits and collapses, the invariants checked after each;
 * undone in reverse order, they come back to the exact starting front. */
static void test_random_steps_keep_the_rule_and_undo_exactly(void)
{
    const seam_gen *cases[] = {&grid, &finned};
    for (int c = 0; c < 2; c++) {
        fixture f;
        fixture_open(&f, cases[c]);
        snapshot start = take_snapshot(&f);
        uint32_t created = f.g.collapse_count, log_n = 0, bad = 0;
        uint32_t *log = malloc(4000 * sizeof *log);
        int *was_split = malloc(4000 * sizeof *was_split);
        for (int t = 0; t < 40000 && log_n < 4000; t++) {
            uint32_t v = f.g.original_count + (uint32_t)(sw_test_random() * created);
            int split = sw_test_random() < 0.6;
            if (split ? !sw_seam_select_can_split(&f.sel, v) : !sw_seam_select_can_collapse(&f.sel, v))
                continue;
            sw_status st = split ? sw_seam_select_split(&f.sel, v, NULL)
                                 : sw_seam_select_collapse(&f.sel, v, NULL);
            bad += st != SW_OK;
            /* the inverse step is legal at once */
            bad += split ? !sw_seam_select_can_collapse(&f.sel, v) : !sw_seam_select_can_split(&f.sel, v);
            log[log_n] = v, was_split[log_n++] = split;
            bad += (uint32_t)check_front(&f);
        }
        SW_CHECK_MSG(log_n > 200, "only %u steps", log_n);
        printf("  case %d: %u random steps, each checked\n", c, log_n);
        SW_CHECK_MSG(bad == 0, "%u violations", bad);
        snapshot middle = take_snapshot(&f);
        SW_CHECK(!same_snapshot(&start, &middle, &f));
        while (log_n--) {
            uint32_t v = log[log_n];
            sw_status st = was_split[log_n] ? sw_seam_select_collapse(&f.sel, v, NULL)
                                            : sw_seam_select_split(&f.sel, v, NULL);
            SW_CHECK(st == SW_OK);
            bad += (uint32_t)check_front(&f);
        }
        SW_CHECK_MSG(bad == 0, "%u violations while undoing", bad);
        snapshot end = take_snapshot(&f);
        SW_CHECK(same_snapshot(&start, &end, &f));
        SW_CHECK(check_front(&f) == 0);
        free_snapshot(&start);
        free_snapshot(&middle);
        free_snapshot(&end);
        free(log);
        free(was_split);
        fixture_close(&f);
    }
}

/* Whatever front the random steps left, refining everything gives back the
 * original graph: every original active, every loop its slots (repeats
 * dropped) with the slots' own parameters. */
static void test_full_refinement_is_the_original_graph(void)
{
    fixture f;
    fixture_open(&f, &finned);
    for (int t = 0; t < 3000; t++) {
        uint32_t v = f.g.original_count + (uint32_t)(sw_test_random() * f.g.collapse_count);
        if (sw_test_random() < 0.5)
            sw_seam_select_split(&f.sel, v, NULL);
        else
            sw_seam_select_collapse(&f.sel, v, NULL);
    }
    refine_all(&f);
    SW_CHECK(sw_seam_select_count(&f.sel).active_vertices == f.g.original_count);
    sw_seam_point *pts = malloc(f.g.slot_count * sizeof *pts);
    for (uint32_t l = 0; l < f.g.loop_count; l++) {
        const sw_seam_loop *lp = &f.g.loops[l];
        uint32_t count = 0, j = 0;
        int vanished = 1;
        SW_CHECK(sw_seam_select_loop(&f.sel, l, 0.0f, pts, lp->slot_count, &count, &vanished, NULL) ==
                 SW_OK);
        SW_CHECK(!vanished && count == lp->slot_count);   /* the generator repeats nothing */
        for (uint32_t i = 0; i < lp->slot_count && j < count; i++, j++) {
            const sw_seam_slot *s = &f.g.slots[lp->first_slot + i];
            SW_CHECK(pts[j].vertex == s->vertex);
            SW_CHECK(memcmp(pts[j].uv, s->uv, sizeof s->uv) == 0);
        }
    }
    SW_CHECK(sw_seam_select_count(&f.sel).loops_vanished == 0);
    SW_CHECK(check_front(&f) == 0);
    free(pts);
    fixture_close(&f);
}

/* The surfaces whose loops show each active vertex, from the polylines. */
static void shown_bounds(const fixture *f, const float *surface_bound, float *vertex_bound)
{
    for (uint32_t v = 0; v < f->g.vertex_count; v++)
        vertex_bound[v] = INFINITY;
    sw_seam_point *pts = malloc(f->g.slot_count * sizeof *pts);
    for (uint32_t l = 0; l < f->g.loop_count; l++) {
        uint32_t count = 0;
        sw_seam_select_loop(&f->sel, l, 0.0f, pts, f->g.slot_count, &count, NULL, NULL);
        float b = surface_bound[f->g.loops[l].surface];
        for (uint32_t i = 0; i < count; i++)
            vertex_bound[pts[i].vertex] = fminf(vertex_bound[pts[i].vertex], b);
    }
    free(pts);
}

/* After an update: every shown vertex within the bounds of the surfaces
 * showing it, and no collapse left that the rule allows and whose vertex
 * would meet the bounds of the surfaces showing its parents. */
static void check_update_result(const fixture *f, const float *surface_bound)
{
    float *vb = malloc(f->g.vertex_count * sizeof *vb);
    shown_bounds(f, surface_bound, vb);
    uint32_t too_coarse = 0, could_collapse = 0;
    for (uint32_t v = 0; v < f->g.vertex_count; v++)
        if (sw_seam_select_is_active(&f->sel, v) && f->g.vertices[v].error > vb[v])
            too_coarse++;
    for (uint32_t k = 0; k < f->g.collapse_count; k++) {
        uint32_t vn = f->g.original_count + k;
        const sw_seam_collapse *c = &f->g.collapses[k];
        if (sw_seam_select_can_collapse(&f->sel, vn) &&
            f->g.vertices[vn].error <= fminf(vb[c->v1], vb[c->v2]))
            could_collapse++;
    }
    SW_CHECK_MSG(too_coarse == 0, "%u vertices above their bound", too_coarse);
    SW_CHECK_MSG(could_collapse == 0, "%u collapses left undone", could_collapse);
    free(vb);
}

static void test_update_meets_every_bound_and_no_more(void)
{
    const seam_gen *cases[] = {&grid, &finned};
    for (int c = 0; c < 2; c++) {
        fixture f;
        fixture_open(&f, cases[c]);
        float *bound = malloc(f.g.surface_count * sizeof *bound);
        uint32_t forced = 0, splits = 0, collapses = 0;
        for (int frame = 0; frame < 40; frame++) {
            /* a viewer walking across: bounds grow with the distance to it */
            double ex = 3.0 * frame / 40.0, ey = 1.5;
            for (uint32_t s = 0; s < f.g.surface_count; s++) {
                double sx = (s % 3) + 0.5, sy = (double)(s / 3) + 0.5;
                bound[s] = (float)(0.002 * ((sx - ex) * (sx - ex) + (sy - ey) * (sy - ey)) *
                                   (0.5 + sw_test_random()));
            }
            sw_seam_update_result r;
            sw_error err = {0};
            SW_CHECK_MSG(sw_seam_select_update(&f.sel, bound, 0, &r, &err) == SW_OK, "%s",
                         err.message);
            SW_CHECK(r.complete);
            forced += r.forced_splits, splits += r.splits, collapses += r.collapses;
            check_update_result(&f, bound);
            SW_CHECK(check_front(&f) == 0);
        }
        SW_CHECK(splits > 0 && collapses > 0);
        printf("  case %d: %u splits (%u forced), %u collapses over 40 frames\n", c, splits,
               forced, collapses);
        free(bound);
        fixture_close(&f);
    }
}

static void test_huge_bound_collapses_each_part_to_a_vertex(void)
{
    fixture f;
    fixture_open(&f, &finned);
    float *b = malloc(f.g.surface_count * sizeof *b);
    refine_all(&f);
    SW_CHECK(sw_seam_select_count(&f.sel).active_vertices == f.g.original_count);
    for (uint32_t s = 0; s < f.g.surface_count; s++)
        b[s] = 1e30f;
    sw_seam_update_result r;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, &r, NULL) == SW_OK);
    uint32_t roots = 0;
    for (uint32_t v = 0; v < f.g.vertex_count; v++)
        roots += child_of(&f.g, v) == SW_SEAM_NONE;
    sw_seam_select_stats st = sw_seam_select_count(&f.sel);
    SW_CHECK(r.collapses == f.g.collapse_count && r.splits == 0);
    SW_CHECK(st.active_vertices == roots);
    SW_CHECK(st.loops_vanished == f.g.loop_count);
    SW_CHECK(st.surfaces_vanished == f.g.surface_count);
    free(b);
    fixture_close(&f);
}

/* A split the rule forbids is forced through by splitting its blockers
 * first; the state stays valid. */
static void test_forced_split_clears_its_blockers(void)
{
    fixture f;
    fixture_open(&f, &grid);
    uint32_t blocked_seen = 0;
    for (int t = 0; t < 20000 && blocked_seen < 20; t++) {
        uint32_t v = f.g.original_count + (uint32_t)(sw_test_random() * f.g.collapse_count);
        if (sw_seam_select_is_active(&f.sel, v) && !sw_seam_select_can_split(&f.sel, v)) {
            uint32_t splits = 0;
            SW_CHECK(sw_seam_select_force_split(&f.sel, v, 0, &splits, NULL) == SW_OK);
            SW_CHECK(!sw_seam_select_is_active(&f.sel, v));
            SW_CHECK(splits >= 2);
            blocked_seen++;
            SW_CHECK(check_front(&f) == 0);
        } else if (sw_test_random() < 0.5) {
            sw_seam_select_split(&f.sel, v, NULL);
        } else {
            sw_seam_select_collapse(&f.sel, v, NULL);
        }
    }
    SW_CHECK_MSG(blocked_seen >= 5, "only %u blocked splits met", blocked_seen);
    uint32_t orig = 0;
    SW_CHECK(sw_seam_select_force_split(&f.sel, orig, 0, NULL, NULL) == SW_ERR_ARG);
    fixture_close(&f);
}

/* With a cap per update, each update stops after that many steps and the
 * sequence of updates ends where one uncapped update would. */
static void test_capped_updates_converge(void)
{
    fixture f, g;
    fixture_open(&f, &finned);
    fixture_open(&g, &finned);
    float *b = malloc(f.g.surface_count * sizeof *b);
    for (uint32_t s = 0; s < f.g.surface_count; s++)
        b[s] = s % 2 ? 0.0f : 0.05f;
    sw_seam_update_result r = {0};
    int updates = 0;
    do {
        SW_CHECK(sw_seam_select_update(&f.sel, b, 7, &r, NULL) == SW_OK);
        SW_CHECK(r.splits + r.collapses <= 7);
        SW_CHECK(check_front(&f) == 0);
        updates++;
    } while (!r.complete && updates < 1000);
    SW_CHECK(updates > 2);
    SW_CHECK(sw_seam_select_update(&g.sel, b, 0, &r, NULL) == SW_OK && r.complete);
    snapshot a = take_snapshot(&f), c = take_snapshot(&g);
    SW_CHECK(same_snapshot(&a, &c, &f));
    check_update_result(&f, b);
    free_snapshot(&a);
    free_snapshot(&c);
    free(b);
    fixture_close(&f);
    fixture_close(&g);
}

/* Three surfaces on one seam: a fin that must be exact refines the seam,
 * and the grid squares on either side show the same seam vertices. */
static void test_non_manifold_seam_is_shared(void)
{
    fixture f;
    fixture_open(&f, &finned);
    float *b = malloc(f.g.surface_count * sizeof *b);
    for (uint32_t s = 0; s < f.g.surface_count; s++)
        b[s] = 1e30f;
    uint32_t fin = 4;               /* 2 x 2 squares, then the fin */
    SW_CHECK(f.g.loops[f.g.surface_loops[fin]].surface == fin);
    b[fin] = 0.0f;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, NULL, NULL) == SW_OK);
    /* every fin slot shows a vertex of error 0, and squares 0 and 1 show the
       same vertices along the seam (the fin's first k + 1 slots) */
    const sw_seam_loop *fl = &f.g.loops[f.g.surface_loops[fin]];
    uint32_t actives;
    for (uint32_t i = 0; i < fl->slot_count; i++)
        SW_CHECK(f.g.vertices[active_on_path(&f, f.g.slots[fl->first_slot + i].vertex, &actives)]
                     .error == 0.0f);
    sw_seam_point pts[64];
    for (uint32_t sq = 0; sq < 2; sq++) {
        uint32_t count = 0;
        SW_CHECK(sw_seam_select_loop(&f.sel, sq, 0.0f, pts, 64, &count, NULL, NULL) == SW_OK);
        for (uint32_t i = 0; i <= finned.k; i++) {
            uint32_t o = f.g.slots[fl->first_slot + i].vertex, found = 0;
            uint32_t x = active_on_path(&f, o, &actives);
            for (uint32_t j = 0; j < count; j++)
                found |= pts[j].vertex == x;
            SW_CHECK_MSG(found, "square %u misses seam vertex %u (shown as %u)", sq, o, x);
        }
    }
    sw_seam_select_stats st = sw_seam_select_count(&f.sel);
    SW_CHECK(st.surfaces_vanished < f.g.surface_count);
    SW_CHECK(sw_seam_select_surface_changed(&f.sel, fin));
    sw_seam_select_clear_changed(&f.sel);
    SW_CHECK(!sw_seam_select_surface_changed(&f.sel, fin));
    check_update_result(&f, b);
    free(b);
    fixture_close(&f);
}

/* Init, updates, steps and polylines: not one heap call, and the arena's
 * peak within what arena_bytes promised. */
static void test_no_heap_and_arena_bounded(void)
{
    seam_gen p = grid;
    sw_seam_host host;
    seam_gen_build(&p, &host);
    SW_CHECK(sw_seam_simplify(&host, NULL) == SW_OK);
    sw_seam_graph g = sw_seam_host_view(&host);
    size_t bytes = sw_seam_select_arena_bytes(&g);
    unsigned char *block = malloc(bytes);
    float *b = malloc(g.surface_count * sizeof *b);
    sw_seam_point *pts = malloc(g.slot_count * sizeof *pts);
    SW_CHECK(sw_alloc_count_active());
    uint64_t before = sw_alloc_count_allocs() + sw_alloc_count_frees();
    sw_arena arena;
    sw_arena_init(&arena, block, bytes);
    sw_seam_select sel;
    SW_CHECK(sw_seam_select_init(&sel, &g, &arena, NULL) == SW_OK);
    for (int frame = 0; frame < 10; frame++) {
        for (uint32_t s = 0; s < g.surface_count; s++)
            b[s] = (float)(0.001 * ((s * 7 + (uint32_t)frame * 3) % 11));
        SW_CHECK(sw_seam_select_update(&sel, b, frame % 2 ? 0u : 5u, NULL, NULL) == SW_OK);
        for (uint32_t l = 0; l < g.loop_count; l++) {
            uint32_t count;
            sw_seam_select_loop(&sel, l, 0.0f, pts, g.slot_count, &count, NULL, NULL);
        }
        (void)sw_seam_select_count(&sel);
    }
    uint64_t after = sw_alloc_count_allocs() + sw_alloc_count_frees();
    SW_CHECK_MSG(after == before, "%llu heap calls", (unsigned long long)(after - before));
    SW_CHECK(arena.peak <= bytes);
    /* a smaller arena: refused, not overrun */
    sw_arena small;
    sw_arena_init(&small, block, bytes / 2);
    sw_error err = {0};
    SW_CHECK(sw_seam_select_init(&sel, &g, &small, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK(small.used <= bytes / 2);
    free(pts);
    free(b);
    free(block);
    sw_seam_host_free(&host);
}

static void test_rejects_bad_input(void)
{
    fixture f;
    fixture_open(&f, &grid);
    float *b = calloc(f.g.surface_count, sizeof *b);
    sw_error err = {0};
    b[2] = NAN;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, NULL, &err) == SW_ERR_ARG);
    b[2] = -1.0f;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, NULL, &err) == SW_ERR_ARG);
    b[2] = INFINITY;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, NULL, &err) == SW_ERR_ARG);
    SW_CHECK(sw_seam_select_update(&f.sel, NULL, 0, NULL, &err) == SW_ERR_ARG);
    /* a loop out of range, a buffer too small */
    sw_seam_point pts[4];
    uint32_t count = 0;
    SW_CHECK(sw_seam_select_loop(&f.sel, f.g.loop_count, 0.0f, pts, 4, &count, NULL, &err) ==
             SW_ERR_RANGE);
    b[2] = 0.0f;
    SW_CHECK(sw_seam_select_update(&f.sel, b, 0, NULL, NULL) == SW_OK);
    SW_CHECK(sw_seam_select_loop(&f.sel, 0, 0.0f, pts, 4, &count, NULL, &err) == SW_ERR_NO_MEMORY);
    SW_CHECK(count == f.g.loops[0].slot_count);
    /* steps the rule forbids, vertices out of range */
    SW_CHECK(sw_seam_select_split(&f.sel, 0, &err) == SW_ERR_ARG);
    SW_CHECK(sw_seam_select_split(&f.sel, f.g.vertex_count, &err) == SW_ERR_ARG);
    SW_CHECK(sw_seam_select_collapse(&f.sel, f.g.vertex_count + 9, &err) == SW_ERR_ARG);
    SW_CHECK(!sw_seam_select_can_collapse(&f.sel, 3));
    /* malformed graphs: init refuses them */
    sw_seam_graph bad = f.g;
    sw_seam_collapse *coll = malloc(f.g.collapse_count * sizeof *coll);
    memcpy(coll, f.g.collapses, f.g.collapse_count * sizeof *coll);
    coll[5].v1 = coll[5].v2;
    bad.collapses = coll;
    sw_arena arena;
    sw_arena_init(&arena, f.block, sw_seam_select_arena_bytes(&f.g));
    sw_seam_select sel;
    SW_CHECK(sw_seam_select_init(&sel, &bad, &arena, &err) == SW_ERR_FORMAT);
    memcpy(coll, f.g.collapses, f.g.collapse_count * sizeof *coll);
    coll[5].v1 = f.g.original_count + 7;
    SW_CHECK(sw_seam_select_init(&sel, &bad, &arena, &err) != SW_OK);
    bad = f.g;
    bad.vertex_count--;
    SW_CHECK(sw_seam_select_init(&sel, &bad, &arena, &err) == SW_ERR_FORMAT);
    free(coll);
    free(b);
    fixture_close(&f);
}

/* Sewing may put one vertex in consecutive slots: the polyline drops the
 * repeat (the first and last slots too) and takes the run's first slot's
 * parameters; the loop vanishes once it is down to two vertices. */
static void test_consecutive_repeats_are_dropped(void)
{
    fixture f;
    sw_seam_host *g = &f.host;
    memset(g, 0, sizeof *g);
    gen_buf b = {.g = g, .rng = 1};
    const double xy[5][2] = {{0, 0}, {1, 0}, {1.2, 1}, {0.5, 1.7}, {-0.2, 1}};
    for (int i = 0; i < 5; i++)
        gen_vertex(&b, xy[i][0], xy[i][1], 0.0);
    const uint32_t order[8] = {0, 1, 1, 2, 3, 4, 4, 0};
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    for (uint32_t i = 0; i < 8; i++)
        gen_slot(&b, order[i], 0.1 * i, 0.0);
    gen_finish(&b, 1);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(g, &err) == SW_OK, "%s", err.message);
    f.g = sw_seam_host_view(g);
    size_t bytes = sw_seam_select_arena_bytes(&f.g);
    f.block = malloc(bytes);
    sw_arena_init(&f.arena, f.block, bytes);
    SW_CHECK(sw_seam_select_init(&f.sel, &f.g, &f.arena, NULL) == SW_OK);
    refine_all(&f);
    sw_seam_point pts[8];
    uint32_t count = 0;
    int vanished = 1;
    SW_CHECK(sw_seam_select_loop(&f.sel, 0, 0.0f, pts, 8, &count, &vanished, NULL) == SW_OK);
    SW_CHECK(count == 5 && !vanished);
    /* starts at slot 1 (slot 0 continues the run of vertex 0 from slot 7) */
    const uint32_t want_v[5] = {1, 2, 3, 4, 0};
    const float want_u[5] = {0.1f, 0.3f, 0.4f, 0.5f, 0.7f};
    for (uint32_t i = 0; i < 5 && i < count; i++) {
        SW_CHECK(pts[i].vertex == want_v[i]);
        SW_CHECK(pts[i].uv[0] == want_u[i]);
    }
    SW_CHECK(check_front(&f) == 0);
    uint32_t steps = 0;
    for (uint32_t v = f.g.original_count; v < f.g.vertex_count && steps < 2; v++)
        if (sw_seam_select_can_collapse(&f.sel, v))
            steps += sw_seam_select_collapse(&f.sel, v, NULL) == SW_OK;
    SW_CHECK(steps == 2);
    SW_CHECK(sw_seam_select_loop(&f.sel, 0, 0.0f, pts, 8, &count, &vanished, NULL) == SW_OK);
    SW_CHECK(count == 3 && !vanished);
    for (uint32_t v = f.g.original_count; v < f.g.vertex_count && steps < 3; v++)
        if (sw_seam_select_can_collapse(&f.sel, v))
            steps += sw_seam_select_collapse(&f.sel, v, NULL) == SW_OK;
    SW_CHECK(sw_seam_select_loop(&f.sel, 0, 0.0f, pts, 8, &count, &vanished, NULL) == SW_OK);
    SW_CHECK(count == 2 && vanished);
    SW_CHECK(sw_seam_select_count(&f.sel).surfaces_vanished == 1);
    SW_CHECK(check_front(&f) == 0);
    fixture_close(&f);
}

/* Random legal steps from the roots; calls check(f, arg) after each and
 * returns the failures it counted. */
static uint32_t random_walk(fixture *f, int steps, uint32_t (*check)(const fixture *, float),
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

/* Every loop's polyline with pin equals the one without. */
static uint32_t pin_changes_nothing(const fixture *f, float pin)
{
    uint32_t bad = 0, n0 = 0, n1 = 0;
    sw_seam_point *a = malloc(f->g.slot_count * sizeof *a), *b = malloc(f->g.slot_count * sizeof *b);
    for (uint32_t l = 0; l < f->g.loop_count; l++) {
        sw_seam_select_loop(&f->sel, l, 0.0f, a, f->g.slot_count, &n0, NULL, NULL);
        sw_seam_select_loop(&f->sel, l, pin, b, f->g.slot_count, &n1, NULL, NULL);
        bad += n0 != n1 || memcmp(a, b, n0 * sizeof *a) != 0;
    }
    free(a);
    free(b);
    return bad;
}

/* Borders whose (u, v) follow model space (the generated grid: bumps, no
 * pole) give the same polylines with any pin, at every front on the way. */
static void test_pin_leaves_regular_borders_alone(void)
{
    fixture f;
    fixture_open(&f, &grid);
    SW_CHECK_MSG(random_walk(&f, 1500, pin_changes_nothing, 1e30f) == 0, "pinned polylines differ");
    fixture_close(&f);
}

/* A quarter disc (u radial, v the angle): its pole side u = 0 is one vertex
 * in two slots, (0, 1) and (0, 0) in (u, v), between two straight radial
 * sides (as at the tip of a Bezier patch whose first row of control points
 * is one point). */
static void build_pole(fixture *f)
{
    sw_seam_host *g = &f->host;
    memset(g, 0, sizeof *g);
    gen_buf b = {.g = g, .rng = 7};
    const double pi2 = 1.5707963267948966;
    const double uv[13][2] = {{0, 1}, {0, 0}, {0.25, 0}, {0.5, 0}, {0.75, 0}, {1, 0},
                              {1, 0.25}, {1, 0.5}, {1, 0.75}, {1, 1}, {0.75, 1}, {0.5, 1},
                              {0.25, 1}};
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    uint32_t pole = gen_vertex(&b, 0.0, 0.0, 0.0);
    for (int i = 0; i < 13; i++) {
        double r = uv[i][0], a = uv[i][1] * pi2;
        gen_slot(&b, i < 2 ? pole : gen_vertex(&b, r * cos(a), r * sin(a), 0.0), uv[i][0],
                 uv[i][1]);
    }
    gen_finish(&b, 1);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(g, &err) == SW_OK, "%s", err.message);
    f->g = sw_seam_host_view(g);
    size_t bytes = sw_seam_select_arena_bytes(&f->g);
    f->block = malloc(bytes);
    sw_arena_init(&f->arena, f->block, bytes);
    SW_CHECK(sw_seam_select_init(&f->sel, &f->g, &f->arena, NULL) == SW_OK);
}

/* Pole slots whose shown vertex lies within near of the slot's own vertex
 * but which are not a point of that vertex at the slot's (u, v) in the
 * polyline taken with pin. */
static uint32_t corners_lost(const fixture *f, float pin, float near)
{
    sw_seam_point pts[13];
    uint32_t count = 0, actives, lost = 0;
    int vanished = 0;
    lost += sw_seam_select_loop(&f->sel, 0, pin, pts, 13, &count, &vanished, NULL) != SW_OK;
    for (uint32_t slot = 0; slot < 2 && !vanished; slot++) {
        uint32_t o = f->g.slots[slot].vertex, x = active_on_path(f, o, &actives);
        const float *p = f->g.vertices[o].p, *q = f->g.vertices[x].p;
        float d = sqrtf((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
        int found = 0;
        for (uint32_t i = 0; i < count; i++)
            found |= pts[i].vertex == x && pts[i].uv[0] == f->g.slots[slot].uv[0] &&
                     pts[i].uv[1] == f->g.slots[slot].uv[1];
        lost += d <= near && !found;
    }
    return lost;
}

static uint32_t pinned_corners_lost(const fixture *f, float pin)
{
    return corners_lost(f, pin, pin);
}

/* The pole keeps its corners in (u, v) at every front where they are near
 * enough; without pin one (u, v) stands for the whole pole, at full detail
 * too. */
static void test_pin_keeps_a_poles_corners(void)
{
    fixture f;
    build_pole(&f);
    refine_all(&f);
    SW_CHECK(pinned_corners_lost(&f, 1e-3f) == 0);
    SW_CHECK(corners_lost(&f, 0.0f, 1e-3f) == 1);
    uint32_t lost = 0, unpinned = 0;
    for (int t = 0; t < 400; t++) {
        lost += random_walk(&f, 1, pinned_corners_lost, 0.3f);
        unpinned += corners_lost(&f, 0.0f, 0.3f) > 0;
    }
    SW_CHECK_MSG(lost == 0, "%u corners lost", lost);
    SW_CHECK_MSG(unpinned > 0, "no front showed the difference");
    printf("  %u of 400 fronts lose a pole corner without pin, none with\n", unpinned);
    fixture_close(&f);
}

/* Each loop's points with their slots: the same points as
 * sw_seam_select_loop, each point's (u, v) its slot's, its vertex the
 * active ancestor of its slot's original, and the slots once round the
 * loop in order (a chain sw_border_strip takes, t = slot). */
static uint32_t slots_wrong(const fixture *f, float pin)
{
    uint32_t wrong = 0, n = f->g.slot_count;
    sw_seam_point *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    uint32_t *slots = malloc(n * sizeof *slots);
    sw_strip_point *chain = malloc(n * sizeof *chain);
    for (uint32_t l = 0; l < f->g.loop_count; l++) {
        const sw_seam_loop *lp = &f->g.loops[l];
        uint32_t na = 0, nb = 0;
        sw_seam_select_loop(&f->sel, l, pin, a, n, &na, NULL, NULL);
        sw_seam_select_loop_slots(&f->sel, l, pin, b, slots, n, &nb, NULL, NULL);
        wrong += na != nb || memcmp(a, b, na * sizeof *a) != 0;
        for (uint32_t i = 0; i < nb; i++) {
            if (slots[i] >= lp->slot_count) {
                wrong++;
                continue;
            }
            const sw_seam_slot *sl = &f->g.slots[lp->first_slot + slots[i]];
            uint32_t x = sl->vertex;
            while (!sw_seam_select_is_active(&f->sel, x))
                x = f->g.vertices[x].child;
            wrong += memcmp(sl->uv, b[i].uv, sizeof sl->uv) != 0 || x != b[i].vertex;
            chain[i] = (sw_strip_point){ i, (float)slots[i] };
        }
        wrong += nb > 0 && !sw_border_chain_valid(chain, nb, (float)lp->slot_count);
    }
    free(a);
    free(b);
    free(slots);
    free(chain);
    return wrong;
}

static void test_points_name_their_slots(void)
{
    const seam_gen *cases[] = {&grid, &finned};
    for (int c = 0; c < 2; c++) {
        fixture f;
        fixture_open(&f, cases[c]);
        uint32_t wrong = slots_wrong(&f, 0.0f);
        for (int t = 0; t < 200; t++)
            wrong += random_walk(&f, 3, slots_wrong, 0.0f);
        SW_CHECK_MSG(wrong == 0, "case %d: %u loops wrong", c, wrong);
        fixture_close(&f);
    }
    fixture f;
    build_pole(&f);
    uint32_t wrong = 0;
    for (int t = 0; t < 200; t++)
        wrong += random_walk(&f, 1, slots_wrong, 0.3f);
    SW_CHECK_MSG(wrong == 0, "pole: %u loops wrong", wrong);
    fixture_close(&f);
}

int main(void)
{
    SW_RUN(test_starts_at_the_roots);
    SW_RUN(test_random_steps_keep_the_rule_and_undo_exactly);
    SW_RUN(test_full_refinement_is_the_original_graph);
    SW_RUN(test_update_meets_every_bound_and_no_more);
    SW_RUN(test_huge_bound_collapses_each_part_to_a_vertex);
    SW_RUN(test_forced_split_clears_its_blockers);
    SW_RUN(test_capped_updates_converge);
    SW_RUN(test_non_manifold_seam_is_shared);
    SW_RUN(test_no_heap_and_arena_bounded);
    SW_RUN(test_rejects_bad_input);
    SW_RUN(test_consecutive_repeats_are_dropped);
    SW_RUN(test_pin_leaves_regular_borders_alone);
    SW_RUN(test_pin_keeps_a_poles_corners);
    SW_RUN(test_points_name_their_slots);
    return sw_test_finish();
}
