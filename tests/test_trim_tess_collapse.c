/* SPDX-License-Identifier: MIT */
/* sw_trim_tess where a loop has no area in (u, v): one whose positions span
 * area in space is drawn as a fan over them (core/sw_trim_fan.c), turned
 * as the sweep turns its triangles; one flat in space too is left out, and
 * its dropped points are counted flat (no gap). Spike tips: a dropped tip
 * is flat only when its triangle with its kept neighbours is. */
#include "trim_tess_fixture.h"

/* The cosine between triangle t's geometric normal and the mean of its
 * vertices' (unit) normals: near 1 when it faces the surface's way, 0 for
 * a triangle with no area. */
static double facing(uint32_t t)
{
    const uint16_t *tri = g_idx + 3 * t;
    const float *a = g_pos + 3 * tri[0], *b = g_pos + 3 * tri[1], *c = g_pos + 3 * tri[2];
    double e[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
    double f[3] = {(double)c[0] - a[0], (double)c[1] - a[1], (double)c[2] - a[2]};
    double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    double dot = 0, len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++)
            dot += n[j] * g_nrm[3 * tri[k] + j];
    return len > 0 ? dot / (3 * len) : 0;
}

/* Every loop point of l appears in the output with its id and position. */
static uint32_t points_missing(const loops *l, const mesh *m)
{
    uint32_t missing = 0;
    for (uint32_t i = 0; i < l->n; i++) {
        int seen = 0;
        for (uint32_t v = 0; v < m->nv && !seen; v++)
            seen = g_ids[v] == l->pts[i].id && memcmp(g_pos + 3 * v, l->pts[i].p, 12) == 0;
        missing += !seen;
    }
    return missing;
}

/* Where the surface is at (u, v), into p. */
static void place(const surface *s, double u, double v, float *p)
{
    sw_surface_point q = eval_at(s, u, v, SW_EVAL_POINT);
    p[0] = (float)q.p.x, p[1] = (float)q.p.y, p[2] = (float)q.p.z;
}

/* Three corners of a face whose (u, v) came to lie on the bump's diagonal
 * (as at a coarse seam state) while their positions still span a triangle
 * on the surface: no area in (u, v), one triangle over the three points.
 * Both ways round it faces the surface's way (CCW about its normal, as
 * the sweep's triangles); the counting pass agrees. */
static void test_collinear_loop_spanning_space_is_a_fan(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    for (int reversed = 0; reversed < 2; reversed++) {
        begin_loops(&l);
        double t[3] = {0.1, 0.5, 0.9};
        for (int k = 0; k < 3; k++) {
            double x = reversed ? t[2 - k] : t[k];
            add_point(&l, &s, x, x);
        }
        end_loop(&l);
        place(&s, 0.7, 0.3, l.pts[1].p); /* the middle corner, off the diagonal */
        mesh m;
        SW_CHECK(run(&s, &l, 1e-3, &m) == SW_OK);
        SW_CHECK_MSG(m.res.fanned_loops == 1 && m.nv == 3 && m.ni == 3,
                     "fanned %u, %u vertices, %u indices", m.res.fanned_loops, m.nv, m.ni);
        SW_CHECK(m.res.dropped_points == 0 && m.res.skipped_loops == 1);
        SW_CHECK(points_missing(&l, &m) == 0);
        SW_CHECK_MSG(facing(0) > 0.5, "the fan faces away from the surface (reversed %d)",
                     reversed);
        sw_arena a;
        sw_arena_init(&a, g_block, sizeof g_block);
        sw_trim_loops lv = view(&l);
        sw_trim_tess_result sizes;
        SW_CHECK(sw_trim_tess_sizes(s.patches, s.count, &lv, 1e-3, NULL, &a, &sizes, NULL) ==
                 SW_OK);
        SW_CHECK(sizes.vertex_count == 3 && sizes.index_count == 3 && sizes.fanned_loops == 1);
    }
}

/* The sweep's own triangles face the surface's way too: the fan's turn is
 * the sweep's (a rectangle on the bump). */
static void test_sweep_faces_the_same_way(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_rect(&l, &s, 0.1, 0.9, 0.2, 0.8, 3);
    mesh m;
    SW_CHECK(run(&s, &l, 1e-2, &m) == SW_OK && m.ni > 0 && m.res.fanned_loops == 0);
    /* Triangles at crossings may have no area in space (a crossing takes its
     * loop point's position) or none in (u, v), standing on the border:
     * those face no way; the rest face the surface's. */
    uint32_t away = 0, toward = 0;
    for (uint32_t t = 0; t < m.ni / 3; t++)
        away += facing(t) < -0.5, toward += facing(t) > 0.5;
    SW_CHECK_MSG(away == 0 && toward > m.ni / 6, "%u of %u triangles face away, %u toward",
                 away, m.ni / 3, toward);
}

/* A loop on one line in space as well bounds nothing anywhere: no fan; the
 * tip it drops is counted, and counted flat. */
static void test_collinear_in_space_is_left_out(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    begin_loops(&l);
    add_point(&l, &s, 0.1, 0.1);
    add_point(&l, &s, 0.5, 0.5);
    add_point(&l, &s, 0.9, 0.9);
    end_loop(&l);
    for (uint32_t i = 0; i < 3; i++) /* positions on the line x = y = z */
        for (int k = 0; k < 3; k++)
            l.pts[i].p[k] = l.pts[i].uv[0];
    mesh m;
    SW_CHECK(run(&s, &l, 1e-3, &m) == SW_OK);
    SW_CHECK(m.nv == 0 && m.ni == 0 && m.res.fanned_loops == 0 && m.res.skipped_loops == 1);
    SW_CHECK_MSG(m.res.dropped_points == 1 && m.res.dropped_flat == 1, "dropped %u, flat %u",
                 m.res.dropped_points, m.res.dropped_flat);
}

/* A loop with a spike: out from the rectangle's corner and back along the
 * same line in (u, v). Positions on the surface: the tip cuts a triangle
 * off in space, a gap (not flat). Positions moved onto the chord from the
 * corner through the next point: flat. */
static void test_spike_tip_is_flat_only_on_its_line(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 1);
    for (int on_line = 0; on_line < 2; on_line++) {
        begin_loops(&l);
        add_point(&l, &s, 0.2, 0.2);
        add_point(&l, &s, 0.8, 0.2);
        add_point(&l, &s, 0.8, 0.8);
        add_point(&l, &s, 0.5, 0.8);  /* back from the tip to here */
        add_point(&l, &s, 0.1, 0.8);  /* the tip */
        add_point(&l, &s, 0.3, 0.8);
        add_point(&l, &s, 0.2, 0.5);
        end_loop(&l);
        if (on_line) { /* the tip's position on the line through its kept neighbours */
            const float *a = l.pts[3].p, *b = l.pts[5].p;
            for (int k = 0; k < 3; k++)
                l.pts[4].p[k] = a[k] + 2.0f * (b[k] - a[k]);
        }
        mesh m;
        SW_CHECK(run(&s, &l, 1e-2, &m) == SW_OK && m.ni > 0);
        SW_CHECK_MSG(m.res.dropped_points == 1 && m.res.dropped_flat == (uint32_t)on_line,
                     "on the line %d: dropped %u, flat %u", on_line, m.res.dropped_points,
                     m.res.dropped_flat);
    }
}

/* A collapsed loop beside a whole one: the whole one swept, the collapsed
 * one fanned, every point of both in the output. */
static void test_fan_beside_a_swept_loop(void)
{
    static surface s;
    static loops l;
    make_bump(&s, 2);
    begin_loops(&l);
    add_rect(&l, &s, 0.05, 0.45, 0.05, 0.45, 2);
    add_point(&l, &s, 0.6, 0.9);
    add_point(&l, &s, 0.75, 0.75);
    add_point(&l, &s, 0.9, 0.6);
    end_loop(&l);
    place(&s, 0.85, 0.85, l.pts[l.n - 2].p);
    mesh m;
    SW_CHECK(run(&s, &l, 1e-2, &m) == SW_OK);
    SW_CHECK(m.res.fanned_loops == 1 && m.res.dropped_points == 0);
    SW_CHECK(points_missing(&l, &m) == 0);
    SW_CHECK(facing(m.ni / 3 - 1) > 0.5); /* the fan comes last */
}

int main(void)
{
    SW_RUN(test_collinear_loop_spanning_space_is_a_fan);
    SW_RUN(test_sweep_faces_the_same_way);
    SW_RUN(test_collinear_in_space_is_left_out);
    SW_RUN(test_spike_tip_is_flat_only_on_its_line);
    SW_RUN(test_fan_beside_a_swept_loop);
    return sw_test_finish();
}
