/* SPDX-License-Identifier: MIT */
/* sw_seam_surface_untangle (core/sw_seam_surface.h): a slit (a loop out
 * and back along the same seam vertices, its two (u, v) sides crossing) is
 * cut back to where it left; a spike (A B A) whose tip encloses nothing
 * goes; a needle's tip beyond where its two sides cross goes; a periodic
 * seam's vertices, met again a period away, stay; a hole left with fewer
 * than three points goes and the outer count follows; the arena is given
 * back. */
#include <string.h>

#include "sw_seam_surface.h"
#include "sw_test.h"

#define CAP 64

typedef struct fixture {
    sw_trim_point pts[CAP];
    uint32_t first[8];
    uint32_t n, loops;
    double shrink;   /* the tessellator's (sw_trim_tess_shrink); 0: no touching points parted */
} fixture;

static void add(fixture *f, double u, double v, uint32_t id)
{
    f->pts[f->n] = (sw_trim_point){{(float)u, (float)v}, {(float)u, (float)v, 0}, id};
    f->n++;
}

static void end_loop(fixture *f) { f->first[++f->loops] = f->n; }

static uint32_t untangle(fixture *f, uint32_t *outer, sw_trim_loops *out)
{
    static unsigned char block[1 << 16];
    sw_arena a;
    sw_arena_init(&a, block, sizeof block);
    *out = (sw_trim_loops){f->pts, f->first, f->loops};
    uint32_t dropped = sw_seam_surface_untangle(out, f->pts, f->first, outer, f->shrink, &a);
    SW_CHECK(a.used == 0);
    return dropped;
}

static int has_id(const sw_trim_loops *l, uint32_t id)
{
    for (uint32_t i = 0; i < l->loop_first[l->loop_count]; i++)
        if (l->points[i].id == id)
            return 1;
    return 0;
}

/* A square whose bottom side has a slit up to its middle: out along
 * vertices 2, 3, 4 and back along 3, 2, the two sides a thousandth apart
 * and crossing. Cut back to vertex 1 where it left the side. */
static void test_slit_is_cut(void)
{
    fixture f = {.first = {0}};
    add(&f, 0, 0, 0);
    add(&f, 4.999, 0, 1);
    add(&f, 5.0004, 2, 2);
    add(&f, 4.9996, 4, 3);
    add(&f, 5, 5, 4);
    add(&f, 5.0003, 4, 3);
    add(&f, 4.9997, 2, 2);
    add(&f, 5.001, 0, 1);
    add(&f, 10, 0, 5);
    add(&f, 10, 10, 6);
    add(&f, 0, 10, 7);
    end_loop(&f);
    uint32_t outer = 1;
    sw_trim_loops l;
    SW_CHECK(untangle(&f, &outer, &l) == 6);
    SW_CHECK(l.loop_count == 1 && outer == 1 && l.loop_first[1] == 5);
    SW_CHECK(!has_id(&l, 2) && !has_id(&l, 3) && !has_id(&l, 4));
    SW_CHECK(l.points[1].id == 1 && l.points[1].uv[0] == 4.999f && l.points[2].id == 5);
}

/* A B A with B a tip thinner than a twentieth of its reach: B goes. */
static void test_thin_spike_goes(void)
{
    fixture f = {.first = {0}};
    add(&f, 0, 0, 0);
    add(&f, 5, 0, 1);
    add(&f, 5.01, 3, 2);
    add(&f, 5.02, 0, 1);
    add(&f, 10, 0, 3);
    add(&f, 5, 8, 4);
    end_loop(&f);
    uint32_t outer = 1;
    sw_trim_loops l;
    SW_CHECK(untangle(&f, &outer, &l) == 2);
    SW_CHECK(l.loop_first[1] == 4 && !has_id(&l, 2));
}

/* A band's loop: seam vertices 0 (bottom) and 3 (top) stand at u = 0 and
 * u = 2 pi. A period apart: nothing is thin, nothing goes. */
static void test_periodic_seam_stays(void)
{
    fixture f = {.first = {0}};
    const double tau = 6.283185307179586;
    add(&f, 0, 0, 0);
    add(&f, tau / 3, 0, 1);
    add(&f, 2 * tau / 3, 0, 2);
    add(&f, tau, 0, 0);
    add(&f, tau, 1, 3);
    add(&f, 2 * tau / 3, 1, 4);
    add(&f, tau / 3, 1, 5);
    add(&f, 0, 1, 3);
    end_loop(&f);
    uint32_t outer = 1;
    sw_trim_loops l;
    SW_CHECK(untangle(&f, &outer, &l) == 0);
    SW_CHECK(l.loop_count == 1 && l.loop_first[1] == 8);
}

/* A needle down from the top side whose two sides, distinct vertices, cross
 * short of its tip (5 and 6): the tip's lobe goes, the needle stays. */
static void test_needle_tip_lobe_goes(void)
{
    fixture f = {.first = {0}};
    add(&f, 0, 0, 0);
    add(&f, 10, 0, 1);
    add(&f, 10, 10, 2);
    add(&f, 5.2, 10, 3);
    add(&f, 5.001, 4, 4);
    add(&f, 5.0, 2, 5);
    add(&f, 5.0005, 2, 6);
    add(&f, 4.999, 4, 7);
    add(&f, 4.8, 10, 8);
    add(&f, 0, 10, 9);
    end_loop(&f);
    uint32_t outer = 1;
    sw_trim_loops l;
    SW_CHECK(untangle(&f, &outer, &l) == 2);
    SW_CHECK(l.loop_first[1] == 8 && !has_id(&l, 5) && !has_id(&l, 6));
    SW_CHECK(has_id(&l, 4) && has_id(&l, 7));
}

/* A hole that is only a slit (A B A plus nothing) has nothing left: it goes,
 * the outer loop stays, the outer count with it. */
static void test_hole_left_empty_goes(void)
{
    fixture f = {.first = {0}};
    add(&f, 0, 0, 0);
    add(&f, 10, 0, 1);
    add(&f, 10, 10, 2);
    add(&f, 0, 10, 3);
    end_loop(&f);
    add(&f, 4, 5, 10);
    add(&f, 6, 5.0001, 11);
    add(&f, 4.0001, 5.0002, 10);
    end_loop(&f);
    uint32_t outer = 1;
    sw_trim_loops l;
    SW_CHECK(untangle(&f, &outer, &l) == 2);
    SW_CHECK(l.loop_count == 1 && outer == 1 && l.loop_first[1] == 4);
}

int main(void)
{
    SW_RUN(test_slit_is_cut);
    SW_RUN(test_thin_spike_goes);
    SW_RUN(test_periodic_seam_stays);
    SW_RUN(test_needle_tip_lobe_goes);
    SW_RUN(test_hole_left_empty_goes);
    return sw_test_finish();
}
