/* SPDX-License-Identifier: MIT */
/* sw_seam_reroot: the Seam Graph's hierarchy cut at a floor, on synthetic
 * graphs (seam_graph_gen.h). The cut graph's finest polylines are checked
 * against the whole graph's at the same front, walked by the runtime's own
 * select (sw_seam_select.h), not by the re-rooting's bookkeeping. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "seam_graph_gen.h"
#include "sw_seam_check.h"
#include "sw_seam_reroot.h"
#include "sw_seam_select.h"
#include "sw_seam_simplify.h"
#include "sw_test.h"

static sw_seam_host simplified(const seam_gen *p)
{
    sw_seam_host g;
    seam_gen_build(p, &g);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_simplify(&g, &err) == SW_OK, "%s", err.message);
    return g;
}

/* A select over g in its own malloc'd arena. */
typedef struct front {
    void *block;
    sw_seam_select sel;
} front;

static void front_init(front *f, const sw_seam_host *g)
{
    sw_seam_graph view = sw_seam_host_view(g);
    size_t bytes = sw_seam_select_arena_bytes(&view);
    f->block = malloc(bytes);
    sw_arena arena;
    sw_arena_init(&arena, f->block, bytes);
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_select_init(&f->sel, &view, &arena, &err) == SW_OK, "%s", err.message);
}

/* Every surface bounded by bound: the front moves to meet it. */
static void front_bound(front *f, float bound)
{
    uint32_t n = f->sel.graph.surface_count;
    float *b = malloc(((size_t)n + 1) * sizeof *b);
    for (uint32_t s = 0; s < n; s++)
        b[s] = bound;
    sw_seam_update_result r;
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_select_update(&f->sel, b, 0, &r, &err) == SW_OK, "%s", err.message);
    free(b);
}

/* The whole graph's front after its first `applied` collapses, from the
 * finest: the state the simplification passed through. */
static void front_after(front *f, uint32_t applied)
{
    front_bound(f, 0.0f);
    uint32_t o = f->sel.graph.original_count;
    for (uint32_t k = 0; k < applied; k++) {
        sw_error err = {0};
        SW_CHECK_MSG(sw_seam_select_collapse(&f->sel, o + k, &err) == SW_OK,
                     "collapse %u: %s", k, err.message);
    }
}

/* Loop l's polyline in both fronts: the same points, in the same order
 * (the cut graph's may start elsewhere along the loop), at the same
 * positions and (u, v). */
static int same_loop(const front *a, const front *b, uint32_t l, float pin)
{
    uint32_t cap = a->sel.graph.slot_count + 1, na = 0, nb = 0;
    sw_seam_point *pa = malloc(cap * sizeof *pa), *pb = malloc(cap * sizeof *pb);
    sw_seam_select_loop(&a->sel, l, pin, pa, cap, &na, NULL, NULL);
    sw_seam_select_loop(&b->sel, l, pin, pb, cap, &nb, NULL, NULL);
    int same = na == nb && na > 0;
    uint32_t shift = 0;
    for (; same && shift < nb; shift++)
        if (pa[0].uv[0] == pb[shift].uv[0] && pa[0].uv[1] == pb[shift].uv[1])
            break;
    for (uint32_t i = 0; same && i < na; i++) {
        const sw_seam_point *p = &pa[i], *q = &pb[(i + shift) % nb];
        const float *x = a->sel.graph.vertices[p->vertex].p, *y = b->sel.graph.vertices[q->vertex].p;
        same = p->uv[0] == q->uv[0] && p->uv[1] == q->uv[1] && x[0] == y[0] && x[1] == y[1] &&
               x[2] == y[2];
    }
    free(pa);
    free(pb);
    return same;
}

static const seam_gen plain = {.nx = 3, .ny = 3, .k = 12, .bumps = 0.02f, .seed = 5};
static const seam_gen holed = {.nx = 3, .ny = 2, .k = 8, .holes = 1, .bumps = 0.05f, .seed = 7};

/* The median created vertex's error: a floor that cuts about half. */
static float median_error(const sw_seam_host *g)
{
    uint32_t n = g->collapse_count;
    float *e = malloc(((size_t)n + 1) * sizeof *e);
    for (uint32_t k = 0; k < n; k++)
        e[k] = g->vertices[g->original_count + k].error;
    for (uint32_t i = 1; i < n; i++)   /* insertion sort: a few hundred */
        for (uint32_t j = i; j > 0 && e[j - 1] > e[j]; j--) {
            float t = e[j];
            e[j] = e[j - 1], e[j - 1] = t;
        }
    float m = n ? e[n / 2] : 0;
    free(e);
    return m;
}

static void test_cut_draws_as_the_whole_graph_at_the_floor(void)
{
    sw_seam_host whole = simplified(&plain), cut;
    SW_CHECK(sw_seam_host_copy(&whole, &cut, NULL) == SW_OK);
    float floor = median_error(&whole);
    sw_seam_reroot_report rep;
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_reroot(&cut, floor, &rep, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(rep.applied > whole.collapse_count / 4 && rep.kept == 0,
                 "applied %u, kept %u of %u", rep.applied, rep.kept, whole.collapse_count);
    SW_CHECK(cut.original_count == whole.original_count - rep.applied);
    SW_CHECK(cut.collapse_count == whole.collapse_count - rep.applied);
    SW_CHECK(rep.slots_after < rep.slots_before && rep.slots_after == cut.slot_count);
    float worst = 0;
    for (uint32_t v = 0; v < cut.original_count; v++)
        worst = fmaxf(worst, cut.vertices[v].error);
    SW_CHECK_MSG(worst > 0 && worst <= floor, "originals' errors up to %g, floor %g",
                 (double)worst, (double)floor);
    front a, b;
    front_init(&a, &whole);
    front_after(&a, rep.applied);
    front_init(&b, &cut);
    front_bound(&b, 0.0f);
    uint32_t differ = 0;
    for (uint32_t l = 0; l < whole.loop_count; l++)
        differ += !same_loop(&a, &b, l, 0.0f) + !same_loop(&a, &b, l, floor);
    SW_CHECK_MSG(differ == 0, "%u loop polylines differ", differ);
    /* Coarser: both fronts at twice the floor draw the same. */
    front_bound(&a, 2 * floor);
    front_bound(&b, 2 * floor);
    uint32_t va = 0, vb = 0;
    for (uint32_t v = 0; v < whole.vertex_count; v++)
        va += a.sel.active[v];
    for (uint32_t v = 0; v < cut.vertex_count; v++)
        vb += b.sel.active[v];
    SW_CHECK_MSG(va == vb, "active vertices at twice the floor: %u whole, %u cut", va, vb);
    free(a.block);
    free(b.block);
    sw_seam_host_free(&whole);
    sw_seam_host_free(&cut);
}

/* Holes of six vertices would vanish under a floor past their size: those
 * collapses stay in the hierarchy, and no loop is ever down to fewer than
 * three vertices at the finest. */
static void test_no_loop_vanishes_at_the_floor(void)
{
    sw_seam_host g = simplified(&holed);
    float floor = g.vertices[g.vertex_count - 1].error;   /* everything within it */
    sw_seam_reroot_report rep;
    sw_error err = {0};
    SW_CHECK_MSG(sw_seam_reroot(&g, floor, &rep, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(rep.kept > 0 && rep.applied > 0, "applied %u, kept %u", rep.applied, rep.kept);
    sw_seam_graph view = sw_seam_host_view(&g);
    SW_CHECK_MSG(sw_seam_graph_check(&view, &err) == SW_OK, "%s", err.message);
    front f;
    front_init(&f, &g);
    front_bound(&f, 0.0f);
    uint32_t vanished_loops = 0, cap = g.slot_count + 1;
    sw_seam_point *pts = malloc(cap * sizeof *pts);
    for (uint32_t l = 0; l < g.loop_count; l++) {
        int vanished = 1;
        sw_seam_select_loop(&f.sel, l, 0.0f, pts, cap, NULL, &vanished, NULL);
        vanished_loops += vanished;
    }
    SW_CHECK_MSG(vanished_loops == 0, "%u of %u loops vanished at the finest", vanished_loops,
                 g.loop_count);
    free(pts);
    free(f.block);
    sw_seam_host_free(&g);
}

static void test_no_floor_changes_nothing(void)
{
    sw_seam_host g = simplified(&plain), copy;
    SW_CHECK(sw_seam_host_copy(&g, &copy, NULL) == SW_OK);
    sw_seam_reroot_report rep;
    SW_CHECK(sw_seam_reroot(&g, 0.0f, &rep, NULL) == SW_OK && rep.applied == 0);
    SW_CHECK(sw_seam_reroot(&g, -1.0f, &rep, NULL) == SW_OK && rep.applied == 0);
    SW_CHECK(g.vertex_count == copy.vertex_count && g.slot_count == copy.slot_count &&
             memcmp(g.vertices, copy.vertices, g.vertex_count * sizeof *g.vertices) == 0 &&
             memcmp(g.slots, copy.slots, g.slot_count * sizeof *g.slots) == 0);
    /* A floor below every error (the first collapse's) applies nothing. */
    float below = g.vertices[g.original_count].error * 0.5f;
    SW_CHECK(sw_seam_reroot(&g, below, &rep, NULL) == SW_OK && rep.applied == 0 &&
             g.vertex_count == copy.vertex_count);
    sw_seam_host_free(&g);
    sw_seam_host_free(&copy);
}

static void test_a_cut_graph_cuts_again_and_refuses_a_bad_one(void)
{
    sw_seam_host g = simplified(&plain);
    float floor = median_error(&g);
    sw_seam_reroot_report one, two;
    SW_CHECK(sw_seam_reroot(&g, floor, &one, NULL) == SW_OK && one.applied > 0);
    SW_CHECK(sw_seam_reroot(&g, 4 * floor, &two, NULL) == SW_OK && two.applied > 0);
    sw_seam_graph view = sw_seam_host_view(&g);
    SW_CHECK(sw_seam_graph_check(&view, NULL) == SW_OK);
    /* A graph the check refuses is refused, and left as it was. */
    g.vertices[0].p[0] = NAN;
    uint32_t before = g.original_count;
    sw_error err = {0};
    SW_CHECK(sw_seam_reroot(&g, 8 * floor, &two, &err) == SW_ERR_FORMAT);
    SW_CHECK_MSG(strstr(err.message, "SEAM_VERTICES[0]") != NULL, "%s", err.message);
    SW_CHECK(g.original_count == before);
    sw_seam_host_free(&g);
}

int main(void)
{
    SW_RUN(test_cut_draws_as_the_whole_graph_at_the_floor);
    SW_RUN(test_no_loop_vanishes_at_the_floor);
    SW_RUN(test_no_floor_changes_nothing);
    SW_RUN(test_a_cut_graph_cuts_again_and_refuses_a_bad_one);
    return sw_test_finish();
}
