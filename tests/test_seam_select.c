/* SPDX-License-Identifier: MIT */
/* sw_seam_select: the runtime front over the Seam Graph's collapse hierarchy
 * (paper 5.5, 6.1). The checks here recompute everything from the graph by
 * walking child links (not the module's leaf ranges and shown[]), so they
 * are independent of the code that keeps the state. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_alloc_count.h"
#include "sw_seam_select.h"
#include "sw_test.h"
#include "seam_select_fixture.h"

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

/* Updates that fold only the bounds that changed since the last one (a few
 * surfaces a frame, as in a walk) move the front exactly as updates that
 * fold every bound: the same active vertices after every frame, and both
 * meet every bound with nothing left to collapse. */
static void test_changed_bounds_alone_give_the_same_front(void)
{
    const seam_gen *cases[] = {&grid, &finned};
    for (int c = 0; c < 2; c++) {
        fixture f, full;
        fixture_open(&f, cases[c]);
        fixture_open(&full, cases[c]);
        float *bound = malloc(f.g.surface_count * sizeof *bound);
        for (uint32_t s = 0; s < f.g.surface_count; s++)
            bound[s] = 0.05f;
        uint32_t differ = 0, moves = 0;
        for (int frame = 0; frame < 200; frame++) {
            /* one to three surfaces change level, finer or coarser */
            for (int k = 1 + frame % 3; k > 0; k--) {
                uint32_t s = (uint32_t)(sw_test_random() * f.g.surface_count) % f.g.surface_count;
                bound[s] = (float)(0.001 * pow(2.0, floor(10 * sw_test_random())));
            }
            sw_seam_update_result r, rf;
            sw_seam_select_forget_bounds(&full.sel);
            SW_CHECK(sw_seam_select_update(&f.sel, bound, 0, &r, NULL) == SW_OK && r.complete);
            SW_CHECK(sw_seam_select_update(&full.sel, bound, 0, &rf, NULL) == SW_OK && rf.complete);
            moves += r.splits + r.collapses;
            for (uint32_t v = 0; v < f.g.vertex_count; v++)
                differ += f.sel.active[v] != full.sel.active[v];
            if (frame % 20 == 0)
                check_update_result(&f, bound);
        }
        SW_CHECK_MSG(differ == 0, "case %d: %u vertices active in one front and not the other",
                     c, differ);
        SW_CHECK(moves > 0);
        free(bound);
        fixture_close(&full);
        fixture_close(&f);
    }
}

/* Two fronts over one shared topology (the instances of one part) move
 * apart, each exactly as a front with a topology of its own under the same
 * bounds; the shared arena holds the topology once and a front each. */
static void test_shared_topology_fronts_move_apart(void)
{
    fixture own[2];
    fixture_open(&own[0], &finned);
    fixture_open(&own[1], &finned);
    const sw_seam_graph *g = &own[0].g;
    size_t bytes = sw_seam_topology_arena_bytes(g) +
                   2 * (sw_seam_select_front_bytes(g) + sw_seam_select_shown_bytes(g) +
                        sw_seam_select_scratch_bytes(g));
    SW_CHECK(bytes < 2 * sw_seam_select_arena_bytes(g));
    void *block = malloc(bytes);
    sw_arena arena;
    sw_arena_init(&arena, block, bytes);
    sw_seam_topology t;
    sw_seam_select shared[2];
    SW_CHECK(sw_seam_topology_init(&t, g, &arena, NULL) == SW_OK);
    for (int i = 0; i < 2; i++)
        SW_CHECK(sw_seam_select_init_shared(&shared[i], &t, NULL, NULL, &arena, NULL) == SW_OK);
    SW_CHECK(arena.peak <= bytes);
    float *bound[2];
    for (int i = 0; i < 2; i++)
        bound[i] = malloc(g->surface_count * sizeof(float));
    uint32_t differ = 0, apart = 0;
    for (int frame = 0; frame < 60; frame++) {
        for (uint32_t s = 0; s < g->surface_count; s++) {
            bound[0][s] = (float)(0.001 * pow(2.0, floor(10 * sw_test_random())));
            bound[1][s] = 1000.0f * bound[0][s] * (frame % 2 ? 1e-3f : 1.0f);
        }
        for (int i = 0; i < 2; i++) {
            sw_seam_update_result r;
            SW_CHECK(sw_seam_select_update(&shared[i], bound[i], 0, &r, NULL) == SW_OK);
            SW_CHECK(sw_seam_select_update(&own[i].sel, bound[i], 0, &r, NULL) == SW_OK);
            for (uint32_t v = 0; v < g->vertex_count; v++)
                differ += shared[i].active[v] != own[i].sel.active[v];
            for (uint32_t o = 0; o < g->original_count; o++)
                differ += shared[i].shown[o] != own[i].sel.shown[o];
        }
        for (uint32_t v = 0; v < g->vertex_count; v++)
            apart += shared[0].active[v] != shared[1].active[v];
    }
    SW_CHECK_MSG(differ == 0, "%u vertices differ from the fronts of their own", differ);
    SW_CHECK_MSG(apart > 0, "the two fronts never differed: nothing was tested");
    for (int i = 0; i < 2; i++)
        free(bound[i]), fixture_close(&own[i]);
    free(block);
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

/* The surfaces at each original, against a count of the loops' slots that
 * sit at it (the graph's own loops, not the state's leaf order); the fin's
 * seam has three, a free border point one; created vertices none. */
static void test_surfaces_at_each_original(void)
{
    fixture f;
    fixture_open(&f, &finned);
    uint32_t *want = calloc(f.g.surface_count, sizeof *want);
    uint32_t most = 0;
    for (uint32_t o = 0; o < f.g.original_count; o++) {
        memset(want, 0, f.g.surface_count * sizeof *want);
        uint32_t slots = 0;
        for (uint32_t l = 0; l < f.g.loop_count; l++)
            for (uint32_t i = 0; i < f.g.loops[l].slot_count; i++)
                if (f.g.slots[f.g.loops[l].first_slot + i].vertex == o) {
                    want[f.g.loops[l].surface]++;
                    slots++;
                }
        const uint32_t *at = NULL;
        uint32_t count = sw_seam_select_surfaces_at(&f.sel, o, &at);
        SW_CHECK_MSG(count == slots, "original %u: %u surfaces, %u slots", o, count, slots);
        for (uint32_t k = 0; k < count; k++) {
            SW_CHECK(at[k] < f.g.surface_count);
            if (at[k] < f.g.surface_count)
                want[at[k]]--;
        }
        for (uint32_t t = 0; t < f.g.surface_count; t++)
            SW_CHECK_MSG(want[t] == 0, "original %u: surface %u off by %d", o, t, (int)want[t]);
        most = count > most ? count : most;
    }
    SW_CHECK(most >= 3);   /* the fin's seam */
    const uint32_t *at = NULL;
    SW_CHECK(sw_seam_select_surfaces_at(&f.sel, f.g.original_count, &at) == 0 && !at);
    free(want);
    fixture_close(&f);
}

int main(void)
{
    SW_RUN(test_starts_at_the_roots);
    SW_RUN(test_random_steps_keep_the_rule_and_undo_exactly);
    SW_RUN(test_full_refinement_is_the_original_graph);
    SW_RUN(test_update_meets_every_bound_and_no_more);
    SW_RUN(test_changed_bounds_alone_give_the_same_front);
    SW_RUN(test_shared_topology_fronts_move_apart);
    SW_RUN(test_huge_bound_collapses_each_part_to_a_vertex);
    SW_RUN(test_forced_split_clears_its_blockers);
    SW_RUN(test_capped_updates_converge);
    SW_RUN(test_non_manifold_seam_is_shared);
    SW_RUN(test_surfaces_at_each_original);
    SW_RUN(test_no_heap_and_arena_bounded);
    SW_RUN(test_rejects_bad_input);
    return sw_test_finish();
}
