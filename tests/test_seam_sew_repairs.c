/* SPDX-License-Identifier: MIT */
/* What the sewing does beyond the paper's intervals (sw_sew.h): the file's
 * own gaps widen its tolerance edge by edge, trims past their domain are put
 * on it, and T-junctions the intervals missed are closed (step 3b), also
 * where other loops go round a free edge through one vertex. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model_shapes.h"
#include "seam_host_check.h"
#include "sw_seam_flatten.h"
#include "sw_seam_sew.h"
#include "sw_sew_internal.h"
#include "sw_test.h"

/* Two trimmed halves of the plane z = 0, [0, size / 2] and [size / 2 +
 * gap, size] by [0, size], each trim curve with the gap the file would
 * give it (its edge tolerance), with far (1) a plane 100 times their size
 * beside them: sewn at tol, how many edges are seams? */
static size_t seams_between(double size, double gap, double curve_gap, double tol, int far)
{
    shape_plane plane, big;
    shape_plane_init(&plane, 3, 2, 2, size, size);
    shape_plane_init(&big, 1, 1, 1, 100 * size, 100 * size);
    for (int i = 0; i < big.surface.count_u * big.surface.count_v; i++)
        big.ctrl[4 * i + 2] += 200 * size;   /* apart from the halves */
    shape_rect left, right, whole;
    shape_rect_init(&left, 0, size / 2, 0, size);
    shape_rect_init(&right, size / 2 + gap, size, 0, size);
    shape_rect_init(&whole, 0, 100 * size, 0, 100 * size);
    const double gaps[4] = {curve_gap, curve_gap, curve_gap, curve_gap};
    sw_model_loop_input a[1] = {{left.curves, NULL, 4, 1, gaps, NULL}};
    sw_model_loop_input b[1] = {{right.curves, NULL, 4, 1, gaps, NULL}};
    sw_model_loop_input c[1] = {{whole.curves, NULL, 4, 1, NULL, NULL}};
    sw_model m;
    sw_model_init(&m);
    sw_error err;
    SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, a, 1, &err) == SW_OK);
    SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, b, 1, &err) == SW_OK);
    SW_CHECK(!far || sw_model_add_surface(&m, &big.surface, 0, c, 1, &err) == SW_OK);
    SW_CHECK(m.surface_count == 2u + (far != 0) && m.curves[0].gap == curve_gap);
    sw_seam_host h;
    sw_seam_report r = {0};
    SW_CHECK(sw_seam_sew_model(&m, &(sw_seam_options){tol}, &h, &r, &err) == SW_OK);
    check_host(&h);
    sw_seam_host_free(&h);
    sw_model_free(&m);
    return r.seams;
}

/* The halves 1 across, sewn at 1e-3, alone. */
static size_t seams_between_halves(double gap, double curve_gap)
{
    return seams_between(1.0, gap, curve_gap, 1e-3, 0);
}

/* Step 3b on its own (sw_sew_tjunctions.c): one loop runs a, x, b, another
 * b, a, with x 1e-4 off the chord a-b and every edge unsewn. x goes into the
 * second loop's edge, halfway in (u, v) as in space, so both loops share
 * a-x and x-b. */
static void test_tjunction_step_inserts_the_vertex_the_intervals_missed(void)
{
    const double p[5][3] = {{0, 0, 0}, {0.5, 1e-4, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    enum { A, X, B, C, D };
    sw_seam_polylines poly = {.p = (double *)p, .vertex_count = 5, .tolerance = 1e-3};
    sw_error err = {0};
    sew_state st = {.poly = &poly, .tol = 1e-3, .err = &err};
    sw_seam_host h = {0};
    h.slots = malloc(7 * sizeof *h.slots);
    h.loops = malloc(2 * sizeof *h.loops);
    const uint32_t order[7] = {A, X, B, C, B, A, D};
    for (int k = 0; k < 7; k++)
        h.slots[k] = (sw_seam_slot){order[k], {(float)p[order[k]][0], (float)p[order[k]][1]}};
    h.loops[0] = (sw_seam_loop){0, 0, 4, SW_SEAM_LOOP_OUTER};
    h.loops[1] = (sw_seam_loop){1, 4, 3, SW_SEAM_LOOP_OUTER};
    h.slot_count = 7, h.loop_count = 2;
    size_t inserted = 0;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK);
    SW_CHECK(inserted == 1 && h.slot_count == 8);
    SW_CHECK(h.loops[0].first_slot == 0 && h.loops[0].slot_count == 4);
    SW_CHECK(h.loops[1].first_slot == 4 && h.loops[1].slot_count == 4);
    if (h.slot_count == 8) {
        SW_CHECK(h.slots[4].vertex == B && h.slots[5].vertex == X && h.slots[6].vertex == A);
        SW_CHECK(fabsf(h.slots[5].uv[0] - 0.5f) < 1e-6f && fabsf(h.slots[5].uv[1]) < 1e-6f);
    }
    /* x farther than twice the tolerance from the chord: nothing to do */
    h.slots[5] = h.slots[6], h.slots[6] = h.slots[7];
    h.loops[1].slot_count = 3, h.slot_count = 7;
    const double far[5][3] = {{0, 0, 0}, {0.5, 3e-3, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    poly.p = (double *)far;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK && inserted == 0);
    free(h.slots);
    free(h.loops);
}

/* Step 3b beyond the tolerance: x off the chord a-b (of length 1). One
 * loop runs a, x, b, the other b, a (a fillet's arc tangent to a line,
 * its vertex near the tangent point within the tolerance of the line on
 * one face, not on the other: a lock body's free edges): the two differ
 * by x alone, and x goes in up to twice the tolerance, or a thousandth of
 * the chord up to 16 tolerances. Where x's other neighbour is not a, it
 * is a corner of its own beyond the tolerance, and stays out. */
static size_t inserted_off_the_chord(uint32_t before_x, double off, double tol)
{
    const double p[6][3] = {{0, 0, 0}, {0.5, off, 0}, {1, 0, 0},
                            {0.5, 1, 0}, {0.5, -1, 0}, {0.2, 1, 0}};
    enum { A, X, B, C, D, E };
    sw_seam_polylines poly = {.p = (double *)p, .vertex_count = 6, .tolerance = tol};
    sw_error err = {0};
    sew_state st = {.poly = &poly, .tol = tol, .err = &err};
    sw_seam_host h = {0};
    h.slots = malloc(7 * sizeof *h.slots);
    h.loops = malloc(2 * sizeof *h.loops);
    const uint32_t order[7] = {before_x, X, B, C, B, A, D};
    for (int k = 0; k < 7; k++)
        h.slots[k] = (sw_seam_slot){order[k], {(float)p[order[k]][0], (float)p[order[k]][1]}};
    h.loops[0] = (sw_seam_loop){0, 0, 4, SW_SEAM_LOOP_OUTER};
    h.loops[1] = (sw_seam_loop){1, 4, 3, SW_SEAM_LOOP_OUTER};
    h.slot_count = 7, h.loop_count = 2;
    size_t inserted = 99;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK);
    if (inserted == 1)
        SW_CHECK(h.slot_count == 8 && h.slots[5].vertex == X && h.slots[6].vertex == A);
    free(h.slots);
    free(h.loops);
    return inserted;
}

static void test_tjunction_step_reaches_twice_the_tolerance_between_shared_ends(void)
{
    enum { A, X, B, C, D, E };
    SW_CHECK(inserted_off_the_chord(A, 1.5e-3, 1e-3) == 1);
    SW_CHECK(inserted_off_the_chord(E, 1.5e-3, 1e-3) == 0);
    SW_CHECK(inserted_off_the_chord(A, 2.5e-3, 1e-3) == 0);
    /* A tolerance far below the chord (the Annex lock body: 4.1e-5 on a
     * 1.3 mm line, its arc's vertex 2.2 tolerances off): a thousandth of
     * the chord, up to 16 tolerances. */
    SW_CHECK(inserted_off_the_chord(A, 3.5e-5, 1e-5) == 1);
    SW_CHECK(inserted_off_the_chord(A, 1.5e-4, 1e-5) == 1);
    SW_CHECK(inserted_off_the_chord(A, 1.7e-4, 1e-5) == 0);
    SW_CHECK(inserted_off_the_chord(E, 3.5e-5, 1e-5) == 0);
}

/* Step 3b's second pass: a free edge a-b in one loop where other loops go
 * from a to b through x, both edges sewn (a cusp where a fillet's arc meets
 * a line, its tip a hair off the line: the Annex corner lock bodies). x
 * 2e-4 off the chord goes in; 3e-3 off (past twice the tolerance and a
 * thousandth of the chord) it stays out. */
static size_t detour_inserted(double off, uint32_t *second_loop)
{
    const double p[7][3] = {{0, 0, 0}, {0.5, off, 0}, {1, 0, 0},   {0.5, 1, 0},
                            {0.5, -1, 0}, {0.2, 0.5, 0}, {0.8, 0.5, 0}};
    enum { A, X, B, C, D, E, F };
    sw_seam_polylines poly = {.p = (double *)p, .vertex_count = 7, .tolerance = 1e-3};
    sw_error err = {0};
    sew_state st = {.poly = &poly, .tol = 1e-3, .err = &err};
    sw_seam_host h = {0};
    h.slots = malloc(13 * sizeof *h.slots);
    h.loops = malloc(4 * sizeof *h.loops);
    /* a, x, b, c; b, a, d (a-b free); x, a, e and b, x, f sew a-x and x-b. */
    const uint32_t order[13] = {A, X, B, C, B, A, D, X, A, E, B, X, F};
    for (int k = 0; k < 13; k++)
        h.slots[k] = (sw_seam_slot){order[k], {(float)p[order[k]][0], (float)p[order[k]][1]}};
    h.loops[0] = (sw_seam_loop){0, 0, 4, SW_SEAM_LOOP_OUTER};
    h.loops[1] = (sw_seam_loop){1, 4, 3, SW_SEAM_LOOP_OUTER};
    h.loops[2] = (sw_seam_loop){2, 7, 3, SW_SEAM_LOOP_OUTER};
    h.loops[3] = (sw_seam_loop){3, 10, 3, SW_SEAM_LOOP_OUTER};
    h.slot_count = 13, h.loop_count = 4;
    size_t inserted = 99;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK);
    for (uint32_t k = 0; k < 4 && k < h.loops[1].slot_count; k++)
        second_loop[k] = h.slots[h.loops[1].first_slot + k].vertex;
    SW_CHECK(h.loops[1].slot_count == 3 + inserted);
    free(h.slots);
    free(h.loops);
    return inserted;
}

static void test_tjunction_step_fills_a_free_edge_with_its_detour(void)
{
    enum { A, X, B, C, D, E, F };
    uint32_t loop[4] = {0};
    SW_CHECK(detour_inserted(2e-4, loop) == 1);
    SW_CHECK(loop[0] == B && loop[1] == X && loop[2] == A && loop[3] == D);
    SW_CHECK(detour_inserted(3e-3, loop) == 0);
}

/* Step 3b's second pass, a sliver: one loop runs a-b, another d-c, with c
 * `off` from a and d 1.2 off from b, a-c and b-d sewn edges of the
 * sliver's end faces (the Bambu X1C mount: 0.002 mm wide, two faces each
 * along one long side). Within the tolerance, c merges into a and d into
 * b: both loops run a-b. Past it, nothing moves. Returns how many loops
 * use a-b. */
static int sliver_uses_of_ab(double off)
{
    const double p[10][3] = {{0, 0, 0},    {1, 0, 0},   {0, off, 0},  {1, 1.2 * off, 0},
                             {0.5, -1, 0}, {0.5, 1, 0}, {-0.5, 0, 0}, {1.5, 0, 0},
                             {-0.5, 1, 0}, {1.5, 1, 0}};
    enum { A, B, C, D, E, F, G, H, I, J };
    sw_seam_polylines poly = {.p = (double *)p, .vertex_count = 10, .tolerance = 1e-3};
    sw_error err = {0};
    sew_state st = {.poly = &poly, .tol = 1e-3, .err = &err};
    sw_seam_host h = {0};
    h.slots = malloc(18 * sizeof *h.slots);
    h.loops = malloc(6 * sizeof *h.loops);
    /* a, b, e; d, c, f; the ends c, a, g and a, c, i; b, d, h and d, b, j. */
    const uint32_t order[18] = {A, B, E, D, C, F, C, A, G, A, C, I, B, D, H, D, B, J};
    for (int k = 0; k < 18; k++)
        h.slots[k] = (sw_seam_slot){order[k], {(float)p[order[k]][0], (float)p[order[k]][1]}};
    for (uint32_t l = 0; l < 6; l++)
        h.loops[l] = (sw_seam_loop){l, 3 * l, 3, SW_SEAM_LOOP_OUTER};
    h.slot_count = 18, h.loop_count = 6;
    size_t inserted = 99;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK);
    int uses = 0;
    for (uint32_t l = 0; l < h.loop_count; l++) {
        const sw_seam_loop *lp = &h.loops[l];
        for (uint32_t k = 0; k < lp->slot_count; k++) {
            uint32_t u = h.slots[lp->first_slot + k].vertex;
            uint32_t v = h.slots[lp->first_slot + (k + 1) % lp->slot_count].vertex;
            uses += (u == A && v == B) || (u == B && v == A);
        }
    }
    free(h.slots);
    free(h.loops);
    return uses;
}

static void test_tjunction_step_closes_a_sliver_narrower_than_the_tolerance(void)
{
    SW_CHECK(sliver_uses_of_ab(5e-4) == 2);
    SW_CHECK(sliver_uses_of_ab(2e-3) == 1);
}

/* A cone (mayo's #332): its side's one loop from the base's seam point
 * round the base, up the seam line, along the apex's degenerate edge
 * (sampled as points 1e-13 apart) and down the seam line again; the base
 * disk's loop round the other way. The apex's points are one vertex, so
 * the seam line's two sides meet at both ends and are sewn: no free edge
 * (without it both sides were free). */
static void test_a_cone_is_sewn_along_its_seam_line(void)
{
    enum { AROUND = 32, APEX = 4, N = 1 + AROUND + APEX + AROUND };
    double p[3 * N], uv[2 * N];
    size_t n = 0;
    for (int k = 0; k <= AROUND; k++, n++) {   /* the base, from the seam round to it */
        double a = 2 * SW_PI * k / AROUND;
        p[3 * n] = 3 * cos(a), p[3 * n + 1] = 3 * sin(a), p[3 * n + 2] = 0;
        uv[2 * n] = a, uv[2 * n + 1] = 0;
    }
    for (int k = 0; k < APEX; k++, n++) {      /* the apex, its points a hair apart */
        p[3 * n] = 1e-13 * k, p[3 * n + 1] = 0, p[3 * n + 2] = 5;
        uv[2 * n] = 2 * SW_PI * (1 - (double)k / (APEX - 1)), uv[2 * n + 1] = 5;
    }
    size_t disk = n;
    for (int k = 0; k < AROUND; k++, n++) {    /* the disk, the other way round */
        double a = -2 * SW_PI * k / AROUND;
        p[3 * n] = 3 * cos(a), p[3 * n + 1] = 3 * sin(a), p[3 * n + 2] = 0;
        uv[2 * n] = p[3 * n], uv[2 * n + 1] = p[3 * n + 1];
    }
    size_t loop_start[3] = {0, disk, n}, surface_loops[3] = {0, 1, 2};
    uint32_t loop_surface[2] = {0, 1};
    uint8_t loop_outer[2] = {1, 1};
    sw_seam_polylines poly = {.uv = uv, .p = p, .vertex_count = n, .loop_start = loop_start,
                              .loop_surface = loop_surface, .loop_outer = loop_outer,
                              .loop_count = 2, .surface_loops = surface_loops,
                              .surface_count = 2, .tolerance = 1e-4};
    sw_seam_host h;
    sw_sew_counts counts = {0};
    sw_error err = {0};
    SW_CHECK(sw_sew_polylines(&poly, 1e-4, &h, &counts, &err) == SW_OK);
    SW_CHECK_MSG(counts.free_edges == 0, "%zu free edges", counts.free_edges);
    check_host(&h);
    sw_seam_host_free(&h);
}

/* Step 3b where the vertex is already the neighbour (the boxed sphere's
 * fillet tip at a sphere's pole): one loop runs x, a, b, C, the other b, x,
 * D, with x 2e-4 from a and on the chord a-b. Inserting x into a-b would
 * make the first loop x, a, x, b: a spike out to a, which the other loop
 * lacks (a gap point where the seams are drawn). a merges into x instead:
 * both loops run x, b; every slot stays, a's with its own (u, v). */
static void test_tjunction_step_merges_a_spike_tip_into_its_neighbour(void)
{
    const double p[5][3] = {{2e-4, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    enum { X, A, B, C, D };
    sw_seam_polylines poly = {.p = (double *)p, .vertex_count = 5, .tolerance = 1e-3};
    sw_error err = {0};
    sew_state st = {.poly = &poly, .tol = 1e-3, .err = &err};
    sw_seam_host h = {0};
    h.slots = malloc(7 * sizeof *h.slots);
    h.loops = malloc(2 * sizeof *h.loops);
    const uint32_t order[7] = {X, A, B, C, B, X, D};
    for (int k = 0; k < 7; k++)
        h.slots[k] = (sw_seam_slot){order[k], {(float)k, (float)(k * k)}};
    h.loops[0] = (sw_seam_loop){0, 0, 4, SW_SEAM_LOOP_OUTER};
    h.loops[1] = (sw_seam_loop){1, 4, 3, SW_SEAM_LOOP_OUTER};
    h.slot_count = 7, h.loop_count = 2;
    size_t inserted = 0;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK);
    SW_CHECK(inserted == 1 && h.slot_count == 7);
    SW_CHECK(h.loops[0].slot_count == 4 && h.loops[1].first_slot == 4);
    const uint32_t want[7] = {X, X, B, C, B, X, D};
    int wrong = 0;
    for (int k = 0; k < 7; k++)
        wrong += h.slots[k].vertex != want[k] || h.slots[k].uv[0] != (float)k;
    SW_CHECK(wrong == 0);
    /* a farther from x than the tolerance is a corner of its own: x goes
     * into a-b as any T-junction (the spike's edge then runs twice along
     * the loop, a seam with itself, as the boxed sphere's fillet ends) */
    for (int k = 0; k < 7; k++)
        h.slots[k].vertex = order[k];
    const double far[5][3] = {{2e-3, 1e-4, 0}, {0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    poly.p = (double *)far;
    SW_CHECK(sew_insert_tjunctions(&st, &h, &inserted) == SW_OK && inserted == 1);
    SW_CHECK(h.slot_count == 8 && h.slots[1].vertex == A && h.slots[2].vertex == X);
    free(h.slots);
    free(h.loops);
}

/* A trim running 2% past its surface's domain (exporters' p-curves do;
 * the runtime's tessellator refuses a loop that far out, leaving a hole):
 * flattened onto the domain's border, every point inside, counted. */
static void test_trim_past_the_domain_is_put_on_it(void)
{
    shape_plane plane;
    shape_plane_init(&plane, 3, 2, 2, 1, 1);
    shape_rect wide;
    shape_rect_init(&wide, 0.2, 1.02, 0.1, 0.9);
    sw_model_loop_input loop[1] = {{wide.curves, NULL, 4, 1, NULL, NULL}};
    sw_model m;
    sw_model_init(&m);
    sw_error err;
    SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, loop, 1, &err) == SW_OK);
    sw_seam_polylines pl;
    SW_CHECK(sw_seam_flatten_model(&m, 1e-3, &pl, &err) == SW_OK);
    const double *d = m.surfaces[0].domain;
    size_t outside = 0;
    for (size_t v = 0; v < pl.vertex_count; v++)
        outside += pl.uv[2 * v] < d[0] || pl.uv[2 * v] > d[1] || pl.uv[2 * v + 1] < d[2] ||
                   pl.uv[2 * v + 1] > d[3];
    SW_CHECK(outside == 0);
    SW_CHECK(pl.clamped >= 2);   /* at least the two corners at u = 1.02 */
    sw_seam_polylines_free(&pl);
    sw_model_free(&m);
}

/* Borders 3e-3 apart, tolerance 1e-3: left apart unless the file says each
 * border may be off its edge by enough that both together reach across. */
static void test_trim_gaps_widen_the_tolerance(void)
{
    SW_CHECK(seams_between_halves(3e-3, 0) == 0);
    SW_CHECK(seams_between_halves(3e-3, 1e-3) == 0);     /* 2e-3 together: short */
    SW_CHECK(seams_between_halves(3e-3, 2e-3) >= 1);     /* 4e-3 together */
    SW_CHECK(seams_between_halves(0.5e-3, 0) >= 1);      /* within the tolerance alone */
}

/* A trim's gap is also held to SW_SEAM_GAP_CAP of its own surface's loops
 * (0.11 across: 1.1e-3), not only of the model (over 20 across): halves
 * 0.1 across beside a plane 10 across, sewn at 1e-4, 5e-3
 * apart whose edges claim 5e-3 each stay apart (a threaded hole in a 350
 * mm bed had its helix sewn across its turns by such edges); 1e-3 apart,
 * within both held gaps, they meet. */
static void test_gaps_are_held_to_their_surface(void)
{
    SW_CHECK(seams_between(0.1, 5e-3, 5e-3, 1e-4, 1) == 0);
    SW_CHECK(seams_between(0.1, 1e-3, 1e-3, 1e-4, 1) >= 1);
}

/* A trim's gap is held to SW_SEAM_GAP_CAP of the model (its box is 1.41
 * across: 0.0141): borders 0.05 apart whose edges claim 0.05 each stay
 * apart (a sloppy edge's tolerance of 6 mm on a 41 mm part sewed its
 * vertices into every border within it); 0.02 apart they still meet. */
static void test_gaps_are_held_to_the_model(void)
{
    SW_CHECK(seams_between_halves(0.05, 0.05) == 0);
    SW_CHECK(seams_between_halves(0.02, 0.02) >= 1);
}

int main(void)
{
    SW_RUN(test_trim_gaps_widen_the_tolerance);
    SW_RUN(test_gaps_are_held_to_the_model);
    SW_RUN(test_gaps_are_held_to_their_surface);
    SW_RUN(test_trim_past_the_domain_is_put_on_it);
    SW_RUN(test_tjunction_step_inserts_the_vertex_the_intervals_missed);
    SW_RUN(test_tjunction_step_merges_a_spike_tip_into_its_neighbour);
    SW_RUN(test_tjunction_step_fills_a_free_edge_with_its_detour);
    SW_RUN(test_tjunction_step_closes_a_sliver_narrower_than_the_tolerance);
    SW_RUN(test_a_cone_is_sewn_along_its_seam_line);
    SW_RUN(test_tjunction_step_reaches_twice_the_tolerance_between_shared_ends);
    return sw_test_finish();
}
