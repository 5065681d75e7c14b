/* SPDX-License-Identifier: MIT */
/* sw_seam_simplify: the collapse hierarchy of a sewn Seam Graph (paper
 * 5.2-5.5), on synthetic graphs built here (seam_graph_gen.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "seam_graph_gen.h"
#include "sw_math.h"
#include "sw_seam_check.h"
#include "sw_seam_select.h"
#include "sw_seam_simplify.h"
#include "sw_seam_surface.h"
#include "sw_test.h"

/* Connected parts of the original graph, by union-find over loop-consecutive
 * pairs: computed without the simplifier. */
static uint32_t find_root(uint32_t *up, uint32_t v)
{
    while (up[v] != v)
        v = up[v] = up[up[v]];
    return v;
}

static uint32_t count_parts(const sw_seam_host *g)
{
    uint32_t *up = malloc(g->original_count * sizeof *up), parts = g->original_count;
    for (uint32_t v = 0; v < g->original_count; v++)
        up[v] = v;
    for (uint32_t e = 0; e < g->edge_count; e++) {
        uint32_t a = find_root(up, g->edges[e].a), b = find_root(up, g->edges[e].b);
        if (a != b)
            up[a] = b, parts--;
    }
    free(up);
    return parts;
}

static sw_seam_host simplified(const seam_gen *p)
{
    sw_seam_host g;
    seam_gen_build(p, &g);
    sw_error err = {0};
    sw_status st = sw_seam_simplify(&g, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return g;
}

static const seam_gen grid3 = {.nx = 3, .ny = 2, .k = 4, .holes = 1, .bumps = 0.05f, .seed = 7};
static const seam_gen finned = {.nx = 2, .ny = 2, .k = 5, .fin = 1, .free_points = 17,
                                .bumps = 0.1f, .seed = 11};

static void test_collapses_to_one_vertex_per_connected_part(void)
{
    const seam_gen *cases[] = {&grid3, &finned};
    for (int c = 0; c < 2; c++) {
        sw_seam_host g;
        seam_gen_build(cases[c], &g);
        uint32_t parts = count_parts(&g), originals = g.original_count;
        sw_status st = sw_seam_simplify(&g, NULL);
        SW_CHECK(st == SW_OK);
        SW_CHECK(g.collapse_count == originals - parts);
        SW_CHECK(g.vertex_count == originals + g.collapse_count);
        uint32_t roots = 0;
        for (uint32_t v = 0; v < g.vertex_count; v++)
            roots += g.vertices[v].child == SW_SEAM_NONE;
        SW_CHECK_MSG(roots == parts, "roots %u, parts %u", roots, parts);
        sw_seam_graph view = sw_seam_host_view(&g);
        sw_error err = {0};
        SW_CHECK_MSG(sw_seam_graph_check(&view, &err) == SW_OK, "%s", err.message);
        sw_seam_host_free(&g);
    }
}

static void test_new_vertex_copies_v2_and_errors_are_monotone(void)
{
    sw_seam_host g = simplified(&finned);
    for (uint32_t k = 0; k < g.collapse_count; k++) {
        const sw_seam_collapse *c = &g.collapses[k];
        const sw_seam_vertex *vn = &g.vertices[g.original_count + k];
        SW_CHECK(memcmp(vn->p, g.vertices[c->v2].p, sizeof vn->p) == 0);
        SW_CHECK(vn->error >= c->error);
        SW_CHECK(vn->error == fmaxf(c->error, fmaxf(g.vertices[c->v1].error,
                                                     g.vertices[c->v2].error)));
        SW_CHECK(vn->slot_ref_count == 0 && vn->reserved == 0);
    }
    /* along every path to a root, errors never decrease */
    for (uint32_t v = 0; v < g.vertex_count; v++)
        for (uint32_t x = v; g.vertices[x].child != SW_SEAM_NONE; x = g.vertices[x].child)
            SW_CHECK(g.vertices[x].error <= g.vertices[g.vertices[x].child].error);
    sw_seam_host_free(&g);
}

/* A square of 8 vertices (corners and mid-sides), flat: the mid-sides lie
 * on the corners' edges, so the first four collapses cost nothing and leave
 * the four corners; the next costs the distance of a corner to the
 * diagonal through its neighbours' ... that is, half the diagonal. */
static void test_collinear_vertices_go_first_at_zero_cost(void)
{
    sw_seam_host g = {0};
    gen_buf b = {.g = &g, .rng = 1};
    const double xy[8][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
    for (int i = 0; i < 8; i++)
        gen_vertex(&b, xy[i][0], xy[i][1], 0.0);
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    for (uint32_t i = 0; i < 8; i++)
        gen_slot(&b, i, xy[i][0] / 2, xy[i][1] / 2);
    gen_finish(&b, 1);
    SW_CHECK(sw_seam_simplify(&g, NULL) == SW_OK);
    SW_CHECK(g.collapse_count == 7);
    for (uint32_t k = 0; k < 4; k++) {
        SW_CHECK(g.collapses[k].error == 0.0f);
        SW_CHECK_MSG(g.collapses[k].v1 % 2 == 1, "collapse %u removes %u", k, g.collapses[k].v1);
    }
    /* after the mid-sides: a 2x2 square; removing a corner costs its distance to
       the diagonal, sqrt(2) */
    SW_CHECK_NEAR(g.collapses[4].error, sqrt(2.0), 1e-6);
    SW_CHECK(g.vertices[g.vertex_count - 1].child == SW_SEAM_NONE);
    sw_seam_host_free(&g);
}

/* S(u, v) = (u, v + u^2, 0): a plane whose straight lines y = c are
 * parabolas in (u, v). */
static void sheared_plane(void *ctx, uint32_t surface, double u, double v, double out[3])
{
    (void)ctx, (void)surface;
    out[0] = u, out[1] = v + u * u, out[2] = 0;
}

/* The square of the collinear test on that plane: every side is straight in
 * space, but the bottom and top are parabolas in (u, v). Collapsing them is
 * free in model space, yet the surface along the new (u, v) chord strays
 * from the side: the parameter term prices that (at the bottom, 0.25 where
 * a chord spans one unit of u), the straight sides stay free. */
static void test_a_side_curved_in_uv_is_not_free(void)
{
    const double xy[10][2] = {{0, 0}, {0.5, 0}, {1, 0}, {1.5, 0}, {2, 0},
                              {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
    const sw_seam_surface_eval exact = {sheared_plane, NULL};
    for (int with_surface = 0; with_surface < 2; with_surface++) {
        sw_seam_host g = {0};
        gen_buf b = {.g = &g, .rng = 1};
        gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
        for (int i = 0; i < 10; i++)
            gen_slot(&b, gen_vertex(&b, xy[i][0], xy[i][1], 0.0), xy[i][0],
                     xy[i][1] - xy[i][0] * xy[i][0]);
        gen_finish(&b, 1);
        SW_CHECK(sw_seam_simplify_on(&g, with_surface ? &exact : NULL, NULL) == SW_OK);
        SW_CHECK(g.collapse_count == 9);
        /* the mid-points of the straight left and right sides go first, free */
        for (uint32_t k = 0; k < 2; k++) {
            SW_CHECK(g.collapses[k].error == 0.0f);
            SW_CHECK(g.collapses[k].v1 == 5 || g.collapses[k].v1 == 9);
        }
        /* then the bottom's, at a cost: exactly 0.25 with the surface; the
           estimate from the loop alone sees less (0.05 for the middle one:
           the plane is steeper across the chord than along it) */
        if (with_surface)
            SW_CHECK_NEAR(g.collapses[2].error, 0.25, 1e-6);
        else
            SW_CHECK(g.collapses[2].error > 0.01f && g.collapses[2].error < 0.25f);
        SW_CHECK(g.collapses[2].v1 >= 1 && g.collapses[2].v1 <= 3);
        sw_seam_host_free(&g);
    }
}

/* ---- the stored errors bound the distance to the original ---- */

static uint32_t ancestor_at(const sw_seam_host *g, uint32_t o, uint32_t step)
{
    uint32_t limit = g->original_count + step;
    while (g->vertices[o].child != SW_SEAM_NONE && g->vertices[o].child < limit)
        o = g->vertices[o].child;
    return o;
}

static double point_seg(const double p[3], const float a[3], const float b[3])
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

/* After step collapses: every point of the original polylines (vertices and
 * points along the edges) lies within max(error(a), error(b)) of some
 * current segment (a, b) (or of a current vertex within its error). */
static void check_bound_at(const sw_seam_host *g, uint32_t step)
{
    uint32_t nseg = 0, cap = g->slot_count + g->vertex_count;
    uint32_t (*seg)[2] = malloc(cap * sizeof *seg);
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *lp = &g->loops[l];
        for (uint32_t i = 0; i < lp->slot_count; i++) {
            uint32_t a = ancestor_at(g, g->slots[lp->first_slot + i].vertex, step);
            uint32_t c = ancestor_at(g, g->slots[lp->first_slot + (i + 1) % lp->slot_count].vertex,
                                     step);
            if (a != c)
                seg[nseg][0] = a, seg[nseg][1] = c, nseg++;
        }
    }
    for (uint32_t v = 0; v < g->original_count + step; v++)
        if (g->vertices[v].child == SW_SEAM_NONE || g->vertices[v].child >= g->original_count + step)
            seg[nseg][0] = seg[nseg][1] = v, nseg++;
    double worst = 0.0;
    for (uint32_t e = 0; e < g->edge_count; e++)
        for (int q = 0; q <= 4; q++) {
            const float *a = g->vertices[g->edges[e].a].p, *b = g->vertices[g->edges[e].b].p;
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = a[i] + (b[i] - a[i]) * q / 4.0;
            double best = DBL_MAX;
            for (uint32_t s = 0; s < nseg; s++) {
                const sw_seam_vertex *x = &g->vertices[seg[s][0]], *y = &g->vertices[seg[s][1]];
                double slack = point_seg(p, x->p, y->p) - fmax(x->error, y->error);
                best = fmin(best, slack);
            }
            worst = fmax(worst, best);
        }
    SW_CHECK_MSG(worst <= 1e-5, "after %u collapses a point is %g beyond its bound", step, worst);
    free(seg);
}

static void test_errors_bound_the_distance_to_the_original(void)
{
    sw_seam_host g = simplified(&finned);
    for (uint32_t step = 0; step <= g.collapse_count; step += 1 + g.collapse_count / 16)
        check_bound_at(&g, step);
    check_bound_at(&g, g.collapse_count);
    sw_seam_host_free(&g);
}

static void test_same_input_same_hierarchy(void)
{
    sw_seam_host a = simplified(&grid3), b = simplified(&grid3);
    SW_CHECK(a.collapse_count == b.collapse_count);
    SW_CHECK(memcmp(a.collapses, b.collapses, a.collapse_count * sizeof *a.collapses) == 0);
    sw_seam_host_free(&a);
    sw_seam_host_free(&b);
}

/* ---- malformed input is rejected and left as it was ---- */

typedef void (*breaker)(sw_seam_host *g);
static void break_slot_vertex(sw_seam_host *g) { g->slots[3].vertex = g->original_count + 5; }
static void break_loop_size(sw_seam_host *g) { g->loops[0].slot_count = 2; }
static void break_loop_range(sw_seam_host *g) { g->loops[g->loop_count - 1].slot_count += 9; }
static void break_missing_edge(sw_seam_host *g) { g->edge_count--; }
static void break_extra_edge(sw_seam_host *g) { g->edges[0].b = g->original_count - 1; }
static void break_duplicate_edge(sw_seam_host *g) { g->edges[1] = g->edges[0]; }
static void break_child(sw_seam_host *g) { g->vertices[2].child = 0; }
static void break_error(sw_seam_host *g) { g->vertices[2].error = -1.0f; }
static void break_position(sw_seam_host *g) { g->vertices[4].p[1] = NAN; }
static void break_slot_ref(sw_seam_host *g) { g->slot_refs[0] = g->slot_refs[1]; }
static void break_surface_loops(sw_seam_host *g) { g->surface_loops[1] = g->loop_count + 1; }
static void break_loop_surface(sw_seam_host *g) { g->loops[0].surface = 1; }
static void break_counts(sw_seam_host *g) { g->vertex_count--; }
static void break_unused_vertex(sw_seam_host *g)
{
    g->vertices[g->original_count - 1].slot_ref_count = 0;
}

static void test_rejects_malformed_graphs(void)
{
    const breaker breakers[] = {break_slot_vertex, break_loop_size, break_loop_range,
                                break_missing_edge, break_extra_edge, break_duplicate_edge,
                                break_child, break_error, break_position, break_slot_ref,
                                break_surface_loops, break_loop_surface, break_counts,
                                break_unused_vertex};
    for (size_t i = 0; i < sizeof breakers / sizeof *breakers; i++) {
        sw_seam_host g;
        seam_gen_build(&grid3, &g);
        breakers[i](&g);
        uint32_t vertices = g.vertex_count;
        sw_error err = {0};
        sw_status st = sw_seam_simplify(&g, &err);
        SW_CHECK_MSG(st == SW_ERR_FORMAT || st == SW_ERR_RANGE, "breaker %zu: status %s", i,
                     sw_status_name(st));
        SW_CHECK_MSG(strncmp(err.message, "seam simplify", 13) == 0, "breaker %zu: '%s'", i,
                     err.message);
        SW_CHECK(g.collapse_count == 0 && g.vertex_count == vertices);
        sw_seam_host_free(&g);
    }
}

static void test_rejects_a_graph_already_simplified(void)
{
    sw_seam_host g = simplified(&grid3);
    uint32_t collapses = g.collapse_count;
    sw_error err = {0};
    SW_CHECK(sw_seam_simplify(&g, &err) == SW_ERR_FORMAT);
    SW_CHECK(strstr(err.message, "already has") != NULL);
    SW_CHECK(g.collapse_count == collapses);
    sw_seam_host_free(&g);
    SW_CHECK(sw_seam_simplify(NULL, &err) == SW_ERR_ARG);
}

/* A surface whose seams must stay whole (the build's repair of a pack
 * verify refuses): its loops' vertices pinned, the graph simplified again
 * keeps every one of them (no collapse takes or removes one), every loop
 * of that surface shows all its original vertices at the coarsest state,
 * and the rest still collapses. Pinning it again changes nothing. */
static void test_pinned_surface_keeps_its_seams(void)
{
    sw_seam_host g = simplified(&grid3);
    uint32_t unpinned_collapses = g.collapse_count;
    uint8_t *surfaces = calloc(g.surface_count, 1), *pinned = calloc(g.original_count, 1);
    surfaces[1] = 1;
    SW_CHECK(sw_seam_pin_surfaces(&g, surfaces, pinned) == 1);
    SW_CHECK(sw_seam_pin_surfaces(&g, surfaces, pinned) == 0);
    uint32_t count = 0;
    for (uint32_t v = 0; v < g.original_count; v++)
        count += pinned[v];
    SW_CHECK(count > 0);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify_pinned(&g, NULL, pinned, &err) == SW_OK, "%s", err.message);
    for (uint32_t c = 0; c < g.collapse_count; c++) {
        const sw_seam_collapse *k = &g.collapses[c];
        SW_CHECK(!(k->v1 < g.original_count && pinned[k->v1]));
        SW_CHECK(!(k->v2 < g.original_count && pinned[k->v2]));
    }
    for (uint32_t v = 0; v < g.original_count; v++)
        if (pinned[v])
            SW_CHECK(g.vertices[v].child == SW_SEAM_NONE);
    SW_CHECK(g.collapse_count > 0 && g.collapse_count <= unpinned_collapses - (count - 1));
    sw_seam_graph view = sw_seam_host_view(&g);
    SW_CHECK_MSG(sw_seam_graph_check(&view, &err) == SW_OK, "%s", err.message);
    free(surfaces);
    free(pinned);
    sw_seam_host_free(&g);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A hub: one vertex that a loop passes through between every pair of its
 * petals, as sewing makes where it merges a chain of close points (a bed
 * plate's corner: 4,946 neighbours, 55,955 runs). Pricing its collapses
 * one neighbour at a time over all its runs took hours there, and over five
 * minutes on these petals; a few seconds is enough, even on a busy machine
 * (its tessellation is not the point: the petals are flat). */
static void test_a_hub_of_many_petals_simplifies_fast(void)
{
    enum { PETALS = 2000 };
    sw_seam_host g = {0};
    gen_buf b = {.g = &g, .rng = 1};
    uint32_t hub = gen_vertex(&b, 0.0, 0.0, 0.0);
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    for (int i = 0; i < PETALS; i++) {
        double t = 2.0 * SW_PI * i / PETALS, dt = SW_PI / PETALS;
        gen_slot(&b, hub, 0.0, 0.0);
        for (int k = 0; k < 2; k++) {
            double x = cos(t + k * dt), y = sin(t + k * dt);
            gen_slot(&b, gen_vertex(&b, x, y, 0.0), x, y);
        }
    }
    gen_finish(&b, 1);
    double start = now_s();
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(&g, &err) == SW_OK, "%s", err.message);
    double took = now_s() - start;
    SW_CHECK_MSG(took < 30.0, "%.2f s", took);
    SW_CHECK(g.collapse_count == g.original_count - 1);
    sw_seam_graph view = sw_seam_host_view(&g);
    SW_CHECK_MSG(sw_seam_graph_check(&view, &err) == SW_OK, "%s", err.message);
    sw_seam_host_free(&g);
}

static void test_empty_graph_has_nothing_to_do(void)
{
    sw_seam_host g = {0};
    uint32_t zero = 0;
    g.surface_loops = &zero;
    SW_CHECK(sw_seam_simplify(&g, NULL) == SW_OK);
    SW_CHECK(g.collapse_count == 0);
}

/* Runs of vertex v in loop l, each original slot showing rep[its vertex]:
 * maximal stretches of the cycle showing v. */
static uint32_t runs_in_loop(const sw_seam_host *g, const uint32_t *rep, uint32_t l, uint32_t v)
{
    const sw_seam_loop *lp = &g->loops[l];
    uint32_t runs = 0, n = lp->slot_count;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t here = rep[g->slots[lp->first_slot + i].vertex];
        uint32_t before = rep[g->slots[lp->first_slot + (i + n - 1) % n].vertex];
        runs += here == v && before != v;
    }
    return runs;
}

/* Collapses, replayed in order, that leave their new vertex with more runs
 * in some loop than either of its two had there. */
static uint32_t pinching_collapses(const sw_seam_host *g)
{
    uint32_t *rep = malloc(sizeof *rep * g->original_count), pinches = 0;
    for (uint32_t v = 0; v < g->original_count; v++)
        rep[v] = v;
    for (uint32_t k = 0; k < g->collapse_count; k++) {
        uint32_t v1 = g->collapses[k].v1, v2 = g->collapses[k].v2, vn = g->original_count + k;
        uint32_t before1[8], before2[8];
        for (uint32_t l = 0; l < g->loop_count && l < 8; l++)
            before1[l] = runs_in_loop(g, rep, l, v1), before2[l] = runs_in_loop(g, rep, l, v2);
        for (uint32_t v = 0; v < g->original_count; v++)
            rep[v] = rep[v] == v1 || rep[v] == v2 ? vn : rep[v];
        for (uint32_t l = 0; l < g->loop_count && l < 8; l++) {
            uint32_t most = before1[l] > before2[l] ? before1[l] : before2[l];
            pinches += runs_in_loop(g, rep, l, vn) > most;
        }
    }
    free(rep);
    return pinches;
}

/* A thin face x a y b whose two near corners x and y (0.01 apart) are one
 * short edge of a neighbouring triangle x y c: collapsing x into y along
 * that edge would leave the thin face meeting itself at one vertex (its
 * (u, v) polyline folded there at every coarser state). No collapse
 * pinches a loop; the hierarchy still ends at one vertex. */
static void test_no_collapse_pinches_a_loop(void)
{
    sw_seam_host g = {0};
    gen_buf b = {.g = &g, .rng = 1};
    uint32_t x = gen_vertex(&b, 0, 0, 0), a = gen_vertex(&b, 10, 0.005, 0);
    uint32_t y = gen_vertex(&b, 0, 0.01, 0), w = gen_vertex(&b, -10, 0.005, 0);
    uint32_t c = gen_vertex(&b, 0, 0.005, -5);
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    gen_slot(&b, x, 0, 0);
    gen_slot(&b, a, 10, 0.005);
    gen_slot(&b, y, 0, 0.01);
    gen_slot(&b, w, -10, 0.005);
    gen_begin_loop(&b, 1, SW_SEAM_LOOP_OUTER);
    gen_slot(&b, x, 0, 0);
    gen_slot(&b, y, 1, 0);
    gen_slot(&b, c, 0.5, 1);
    gen_finish(&b, 2);
    SW_CHECK(sw_seam_simplify(&g, NULL) == SW_OK);
    SW_CHECK_MSG(pinching_collapses(&g) == 0, "%u collapses pinch a loop",
                 pinching_collapses(&g));
    SW_CHECK(g.collapse_count == 4);
    sw_seam_host_free(&g);
}


/* Do segments a-b and c-d cross or touch (collinear overlap included)? */
static int segments_meet(const float a[2], const float b[2], const float c[2], const float d[2])
{
    double d1 = ((double)b[0] - a[0]) * ((double)c[1] - a[1]) - ((double)b[1] - a[1]) * ((double)c[0] - a[0]);
    double d2 = ((double)b[0] - a[0]) * ((double)d[1] - a[1]) - ((double)b[1] - a[1]) * ((double)d[0] - a[0]);
    double d3 = ((double)d[0] - c[0]) * ((double)a[1] - c[1]) - ((double)d[1] - c[1]) * ((double)a[0] - c[0]);
    double d4 = ((double)d[0] - c[0]) * ((double)b[1] - c[1]) - ((double)d[1] - c[1]) * ((double)b[0] - c[0]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    for (int k = 0; k < 4; k++) {   /* an end on the other segment */
        const float *p = k == 0 ? c : k == 1 ? d : k == 2 ? a : b;
        const float *s0 = k < 2 ? a : c, *s1 = k < 2 ? b : d;
        double o = k == 0 ? d1 : k == 1 ? d2 : k == 2 ? d3 : d4;
        if (o == 0 && p[0] >= fminf(s0[0], s1[0]) && p[0] <= fmaxf(s0[0], s1[0]) &&
            p[1] >= fminf(s0[1], s1[1]) && p[1] <= fmaxf(s0[1], s1[1]))
            return 1;
    }
    return 0;
}

/* Pairs of segments of the loops (their (u, v) polylines) that cross or
 * touch, neighbours along a loop not counted; all pairs compared. */
static uint32_t loop_crossings(const sw_trim_loops *loops)
{
    uint32_t meets = 0;
    for (uint32_t l = 0; l < loops->loop_count; l++)
        for (uint32_t i = loops->loop_first[l]; i < loops->loop_first[l + 1]; i++) {
            uint32_t n = loops->loop_first[l + 1] - loops->loop_first[l];
            uint32_t i1 = i + 1 < loops->loop_first[l + 1] ? i + 1 : loops->loop_first[l];
            for (uint32_t m = 0; m < loops->loop_count; m++)
                for (uint32_t j = loops->loop_first[m]; j < loops->loop_first[m + 1]; j++) {
                    uint32_t j1 = j + 1 < loops->loop_first[m + 1] ? j + 1 : loops->loop_first[m];
                    if (j <= i && m == l)
                        continue;
                    if (m == l && (j == i1 || j1 == i || n <= 3))
                        continue;
                    meets += segments_meet(loops->points[i].uv, loops->points[i1].uv,
                                           loops->points[j].uv, loops->points[j1].uv);
                }
        }
    return meets;
}

/* A serpentine strip of width 1 (legs 10 long, 1 apart), outlined by
 * points 0.25 apart, as the flat spring of a public STEP file: its corners,
 * simplified, cut across the next leg. The loops as the runtime reads them
 * (sw_seam_select, sw_seam_surface_loops) at bounds from the finest to past
 * the strip's size: no state where they cross or touch. Each leg is the
 * strip's only surface, so the check of one surface's loops is all. */
static void test_no_collapse_crosses_a_loop(void)
{
    enum { LEGS = 5, MAXP = 2048 };
    float line[2 * (LEGS * 2 + 2)][2];
    int n = 0;
    line[n][0] = 0.5f, line[n][1] = 0.0f, n++;
    for (int k = 0; k < LEGS; k++) {
        float x = 0.5f + 2.0f * k, y = k % 2 ? -0.5f : 10.5f;
        if (k + 1 == LEGS) {   /* the last leg ends square, like the first */
            line[n][0] = x, line[n][1] = k % 2 ? 0.0f : 10.0f, n++;
            break;
        }
        line[n][0] = x, line[n][1] = y, n++;
        line[n][0] = x + 2.0f, line[n][1] = y, n++;
    }
    /* outline: the centre line offset by 0.5 to its left, then back on its right */
    float outline[4 * (LEGS * 2 + 2)][2];
    int m = 0;
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < n; i++) {
            int c = side ? n - 1 - i : i, dir = side ? -1 : 1;
            int pi = c - dir, ni = c + dir;
            float dx0 = 0, dy0 = 0, dx1 = 0, dy1 = 0;
            if (pi >= 0 && pi < n)
                dx0 = line[c][0] - line[pi][0], dy0 = line[c][1] - line[pi][1];
            if (ni >= 0 && ni < n)
                dx1 = line[ni][0] - line[c][0], dy1 = line[ni][1] - line[c][1];
            float l0 = hypotf(dx0, dy0), l1 = hypotf(dx1, dy1);
            float nx = 0, ny = 0;   /* left normals, summed: the corner's offset */
            if (l0 > 0)
                nx += -dy0 / l0, ny += dx0 / l0;
            if (l1 > 0)
                nx += -dy1 / l1, ny += dx1 / l1;
            float len = l0 > 0 && l1 > 0 ? 1.0f : hypotf(nx, ny);
            outline[m][0] = line[c][0] + 0.5f * nx / len, outline[m][1] = line[c][1] + 0.5f * ny / len;
            m++;
        }
    sw_seam_host g = {0};
    gen_buf b = {.g = &g, .rng = 1};
    float pts[MAXP][2];
    uint32_t np = 0;
    for (int i = 0; i < m; i++) {
        const float *a = outline[i], *c = outline[(i + 1) % m];
        int steps = (int)ceilf(hypotf(c[0] - a[0], c[1] - a[1]) / 0.25f);
        for (int k = 0; k < steps && np < MAXP; k++, np++)
            pts[np][0] = a[0] + (c[0] - a[0]) * k / steps, pts[np][1] = a[1] + (c[1] - a[1]) * k / steps;
    }
    for (uint32_t i = 0; i < np; i++)
        gen_vertex(&b, pts[i][0], pts[i][1], 0.0);
    gen_begin_loop(&b, 0, SW_SEAM_LOOP_OUTER);
    for (uint32_t i = 0; i < np; i++)
        gen_slot(&b, i, pts[i][0], pts[i][1]);
    gen_finish(&b, 1);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(&g, &err) == SW_OK, "%s", err.message);
    sw_seam_graph view = sw_seam_host_view(&g);
    size_t bytes = sw_seam_select_arena_bytes(&view);
    void *block = malloc(bytes);
    sw_arena arena;
    sw_arena_init(&arena, block, bytes);
    sw_seam_select sel;
    SW_CHECK_MSG(sw_seam_select_init(&sel, &view, &arena, &err) == SW_OK, "%s", err.message);
    sw_seam_point *seam_points = malloc(sizeof *seam_points * (np + 1));
    sw_trim_point *points = malloc(sizeof *points * (np + 1));
    uint32_t loop_first[4];
    const sw_seam_surface_buffers buf = {seam_points, points, loop_first, np};
    uint32_t states = 0;
    for (float bound = 100.0f; bound > 1e-3f; bound /= 2.0f) {
        sw_seam_update_result r;
        SW_CHECK(sw_seam_select_update(&sel, &bound, 0, &r, &err) == SW_OK);
        sw_trim_loops loops;
        uint32_t outer = 0;
        if (!sw_seam_surface_loops(&sel, 0, 0.0f, &buf, &loops, &outer))
            continue;
        states++;
        uint32_t meets = loop_crossings(&loops);
        SW_CHECK_MSG(meets == 0, "at bound %g (%u points): %u pairs of segments cross or touch",
                     (double)bound, loops.loop_first[loops.loop_count], meets);
    }
    SW_CHECK(states > 10);
    free(seam_points);
    free(points);
    free(block);
    sw_seam_host_free(&g);
}

int main(void)
{
    SW_RUN(test_collapses_to_one_vertex_per_connected_part);
    SW_RUN(test_new_vertex_copies_v2_and_errors_are_monotone);
    SW_RUN(test_collinear_vertices_go_first_at_zero_cost);
    SW_RUN(test_a_side_curved_in_uv_is_not_free);
    SW_RUN(test_errors_bound_the_distance_to_the_original);
    SW_RUN(test_same_input_same_hierarchy);
    SW_RUN(test_rejects_malformed_graphs);
    SW_RUN(test_rejects_a_graph_already_simplified);
    SW_RUN(test_pinned_surface_keeps_its_seams);
    SW_RUN(test_a_hub_of_many_petals_simplifies_fast);
    SW_RUN(test_empty_graph_has_nothing_to_do);
    SW_RUN(test_no_collapse_pinches_a_loop);
    SW_RUN(test_no_collapse_crosses_a_loop);
    return sw_test_finish();
}
