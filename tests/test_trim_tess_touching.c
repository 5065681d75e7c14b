/* SPDX-License-Identifier: MIT */
/* Loops that touch (core/sw_seam_surface.c, part_touching): a hole tangent
 * to the outline at a point of one of its segments, a hole sharing a
 * vertex's place with it, a hole a float step across it, two holes
 * touching. The tessellator's region shrink moves such points across each
 * other and refuses the surface; the walk then drew it without its holes.
 * sw_seam_surface_untangle moves the later loop's point off by a few
 * floats: the surface then tessellates whole, its area the outline's less
 * the holes', every loop point in the mesh, the moved point's position
 * unchanged. A hole that truly crosses, and one clear of the outline, are
 * left alone. */
#include "trim_tess_fixture.h"

#include "sw_seam_surface.h"

static unsigned char s_untangle[1 << 20];

static uint32_t untangle(const surface *s, loops *l, uint32_t outer)
{
    sw_arena a;
    sw_arena_init(&a, s_untangle, sizeof s_untangle);
    sw_trim_loops v = view(l);
    uint32_t moved = sw_seam_surface_untangle(&v, l->pts, l->first, &outer,
                                              sw_trim_tess_shrink(s->patches, s->count), &a);
    SW_CHECK(a.used == 0 && v.loop_count == l->count);
    return moved;
}

/* A regular polygon of n points around (cu, cv), starting at angle a0,
 * clockwise (a hole's usual turn; the tessellator takes either). */
static void add_polygon(loops *l, const surface *s, double cu, double cv, double r, int n,
                        double a0)
{
    for (int k = 0; k < n; k++) {
        double a = a0 - 2 * SW_PI * k / n;
        add_point(l, s, cu + r * cos(a), cv + r * sin(a));
    }
    end_loop(l);
}

static double loop_area(const loops *l, uint32_t k)
{
    double sum = 0;
    for (uint32_t i = l->first[k]; i < l->first[k + 1]; i++) {
        const sw_trim_point *p = &l->pts[i];
        const sw_trim_point *q = &l->pts[i + 1 == l->first[k + 1] ? l->first[k] : i + 1];
        sum += (double)p->uv[0] * q->uv[1] - (double)q->uv[0] * p->uv[1];
    }
    return fabs(0.5 * sum);
}

static double mesh_uv_area(const mesh *m)
{
    double sum = 0;
    for (uint32_t t = 0; t + 2 < m->ni; t += 3) {
        const float *a = g_uv + 2 * g_idx[t], *b = g_uv + 2 * g_idx[t + 1],
                    *c = g_uv + 2 * g_idx[t + 2];
        sum += 0.5 * fabs(((double)b[0] - a[0]) * ((double)c[1] - a[1]) -
                          ((double)b[1] - a[1]) * ((double)c[0] - a[0]));
    }
    return sum;
}

/* The loops tessellate whole: no point dropped, each loop point's id in
 * the mesh at its own position, the triangles' (u, v) area the outline's
 * less the holes'. */
static void check_whole(const surface *s, const loops *l, const loops *before)
{
    mesh m;
    SW_CHECK(run(s, l, 1e-3, &m) == SW_OK);
    SW_CHECK(m.res.dropped_points == 0);
    for (uint32_t i = 0; i < l->n; i++) {
        uint32_t found = 0;
        for (uint32_t k = 0; k < m.nv && !found; k++)
            found = g_ids[k] == l->pts[i].id &&
                    memcmp(g_pos + 3 * k, l->pts[i].p, sizeof l->pts[i].p) == 0;
        SW_CHECK_MSG(found, "loop point %u (id %u) not in the mesh at its position", i,
                     l->pts[i].id);
        /* Moved by a few floats in (u, v); its position is the seam's. */
        SW_CHECK(fabs(l->pts[i].uv[0] - before->pts[i].uv[0]) < 1e-6 &&
                 fabs(l->pts[i].uv[1] - before->pts[i].uv[1]) < 1e-6);
        SW_CHECK(memcmp(l->pts[i].p, before->pts[i].p, sizeof l->pts[i].p) == 0);
    }
    double want = loop_area(l, 0);
    for (uint32_t k = 1; k < l->count; k++)
        want -= loop_area(l, k);
    double got = mesh_uv_area(&m);
    SW_CHECK_MSG(fabs(got - want) < 1e-5 * want, "area %.9g, expected %.9g", got, want);
}

/* Does the tessellator refuse the loops as crossing? (Quietly: the fixture's
 * run prints why.) */
static int refused(const surface *s, const loops *l)
{
    sw_arena a;
    sw_arena_init(&a, g_block, sizeof g_block);
    sw_trim_loops lv = view(l);
    sw_trim_tess_buffers b = {g_pos, g_nrm, g_uv, g_ids, g_idx, MAXV, MAXI, 0, NULL, 0};
    sw_trim_tess_result res;
    return sw_trim_tess(s->patches, s->count, &lv, 1e-3, NULL, &a, &b, &res, NULL) ==
           SW_ERR_FORMAT;
}

/* Untangle moves `expect` points, then the loops tessellate whole.
 * Returns 1 when the raw loops were refused (whether the shrink's crossing
 * shows depends on where the grid's lines fall). */
static int check_parted(const surface *s, loops *l, uint32_t expect)
{
    static loops before;
    before = *l;
    int raw_refused = refused(s, l);
    uint32_t moved = untangle(s, l, 1);
    SW_CHECK_MSG(moved == expect, "moved %u points, expected %u", moved, expect);
    check_whole(s, l, &before);
    return raw_refused;
}

/* A hole touching the outline's left side at 16 heights: its leftmost
 * point on the side between two of the side's points (the Bambu mount's
 * plate: a slot tangent to the edge), at one of them, or a float across. */
enum { TANGENT, AT_VERTEX, ACROSS };

static int hole_at_the_side(int how, float side)
{
    int refused = 0;
    for (int j = 0; j < 16; j++) {
        surface s;
        make_bump(&s, 2);
        static loops l;
        begin_loops(&l);
        /* Just under the grid lines (k / 32 here), where the crossing straddles one. */
        double v = (10 + j * 12 / 15) / 32.0 - 1e-4 * (1 + j % 3);
        add_rect(&l, &s, side, 0.95, 0.05, 0.95, how == AT_VERTEX ? 64 : 3);
        add_polygon(&l, &s, side + 0.2, v, 0.2, 24, SW_PI);
        sw_trim_point *p = &l.pts[l.first[1]];
        p->uv[0] = how == ACROSS ? nextafterf(side, 0) : side;
        if (how == AT_VERTEX) {   /* the side's nearest point */
            uint32_t best = 0;
            for (uint32_t i = 0; i < l.first[1]; i++)
                if (l.pts[i].uv[0] == side && fabs(l.pts[i].uv[1] - v) < fabs(l.pts[best].uv[1] - v))
                    best = i;
            p->uv[1] = l.pts[best].uv[1];
        }
        refused += check_parted(&s, &l, 1);
        SW_CHECK(p->uv[0] > side);   /* moved into the region */
    }
    printf("  the raw loops were refused at %d of 16 heights\n", refused);
    return refused;
}

static void test_a_hole_tangent_to_a_side_is_parted(void)
{
    SW_CHECK(hole_at_the_side(TANGENT, 0.0f) + hole_at_the_side(TANGENT, 0.1f) > 0);
}

static void test_a_hole_at_a_vertex_of_the_outline_is_parted(void)
{
    SW_CHECK(hole_at_the_side(AT_VERTEX, 0.0f) + hole_at_the_side(AT_VERTEX, 0.1f) > 0);
}

static void test_a_hole_a_float_across_is_parted(void)
{
    SW_CHECK(hole_at_the_side(ACROSS, 0.1f) + hole_at_the_side(ACROSS, 0.5f) > 0);
}

/* Two holes tangent to each other: the later one's point moves. */
static void test_two_holes_touching_are_parted(void)
{
    surface s;
    make_bump(&s, 2);
    static loops l;
    begin_loops(&l);
    add_rect(&l, &s, 0.05, 0.95, 0.05, 0.95, 3);
    add_polygon(&l, &s, 0.3, 0.5, 0.2, 32, 0);    /* rightmost point (0.5, 0.5) */
    add_polygon(&l, &s, 0.7, 0.5, 0.2, 32, SW_PI); /* leftmost (0.5, 0.5) */
    l.pts[l.first[2]].uv[0] = l.pts[l.first[1]].uv[0];
    l.pts[l.first[2]].uv[1] = l.pts[l.first[1]].uv[1];
    SW_CHECK(check_parted(&s, &l, 1));
}

/* A hole that truly crosses the outline, and one well clear of it, are
 * not moved: the first is still refused (the walk then draws it without
 * its holes, counted), the second tessellates as it was. */
static void test_a_crossing_or_a_clear_hole_is_left(void)
{
    surface s;
    make_bump(&s, 2);
    static loops l;
    begin_loops(&l);
    add_rect(&l, &s, 0.1, 0.9, 0.1, 0.9, 3);
    add_polygon(&l, &s, 0.3, 0.55, 0.25, 24, SW_PI);   /* leftmost at u = 0.05 */
    SW_CHECK(untangle(&s, &l, 1) == 0);
    SW_CHECK(refused(&s, &l));
    begin_loops(&l);
    add_rect(&l, &s, 0.1, 0.9, 0.1, 0.9, 3);
    add_polygon(&l, &s, 0.3, 0.55, 0.19, 24, SW_PI);   /* 0.01 clear */
    static loops before;
    before = l;
    SW_CHECK(untangle(&s, &l, 1) == 0);
    check_whole(&s, &l, &before);
}

int main(void)
{
    SW_RUN(test_a_hole_tangent_to_a_side_is_parted);
    SW_RUN(test_a_hole_at_a_vertex_of_the_outline_is_parted);
    SW_RUN(test_a_hole_a_float_across_is_parted);
    SW_RUN(test_two_holes_touching_are_parted);
    SW_RUN(test_a_crossing_or_a_clear_hole_is_left);
    return sw_test_finish();
}
