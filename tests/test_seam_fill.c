/* SPDX-License-Identifier: MIT */
/* Fill fans over seam crossings (firmware/walk/workers/sw_seam_fill.h). The mesh is a
 * strip of three quads over a seam: its bottom border runs from seam vertex
 * a through two crossings to seam vertex b, so the neighbour's straight
 * edge a-b would meet it in two T-junctions. And fans over dropped loop
 * points: the same strip with seam vertices for crossings, its loop
 * holding points the mesh lacks. */
#include <string.h>

#include "sw_seam_fill.h"
#include "sw_test.h"
#include "sw_trim_tess.h"

enum { V = 8, STRIP = 18, CAP = 64 };

static sw_seam_fill fill;
static unsigned char block[1 << 16];

/* Bottom 0 (a), 1, 2 (crossings), 3 (b); top 4..7, seam vertices. */
static const uint32_t ids[V] = { 10, SW_TRIM_CROSSING, SW_TRIM_CROSSING, 11, 12, 13, 14, 15 };

static uint32_t make_strip(uint16_t *idx)
{
    uint32_t n = 0;
    for (uint16_t i = 0; i < 3; i++) {
        const uint16_t t[6] = { i, (uint16_t)(i + 1), (uint16_t)(5 + i),
                                i, (uint16_t)(5 + i), (uint16_t)(4 + i) };
        memcpy(idx + n, t, sizeof t);
        n += 6;
    }
    return n;
}

/* How many triangles use edge a-b. */
static int uses(const uint16_t *idx, uint32_t n, uint16_t a, uint16_t b)
{
    int count = 0;
    for (uint32_t t = 0; t + 2 < n; t += 3)
        for (int k = 0; k < 3; k++) {
            uint16_t p = idx[t + k], q = idx[t + (k + 1) % 3];
            count += (p == a && q == b) || (p == b && q == a);
        }
    return count;
}

static void init(void)
{
    sw_arena arena;
    sw_arena_init(&arena, block, sizeof block);
    SW_CHECK(sw_seam_fill_init(&fill, V, CAP, &arena, NULL) == SW_OK);
}

static void test_the_fan_closes_the_border_onto_the_seam_edge(void)
{
    init();
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 99;
    SW_CHECK(sw_seam_fill_crossings(&fill, ids, V, idx, &n, CAP, &left) == 2);
    SW_CHECK(n == STRIP + 6 && left == 0);
    /* the fan is (a, c1, c2), (a, c2, b): no vertex added */
    const uint16_t fan[6] = { 0, 1, 2, 0, 2, 3 };
    SW_CHECK(memcmp(idx + STRIP, fan, sizeof fan) == 0);
    /* the border now runs a-b: every edge at a crossing has two triangles */
    SW_CHECK(uses(idx, n, 0, 1) == 2 && uses(idx, n, 1, 2) == 2 && uses(idx, n, 2, 3) == 2);
    SW_CHECK(uses(idx, n, 0, 3) == 1);
    /* the rest of the border is as it was */
    SW_CHECK(uses(idx, n, 3, 7) == 1 && uses(idx, n, 4, 0) == 1 && uses(idx, n, 5, 6) == 1);
}

static void test_no_crossings_nothing_added(void)
{
    init();
    uint32_t plain[V];
    memcpy(plain, ids, sizeof plain);
    plain[1] = 20, plain[2] = 21;
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 99;
    SW_CHECK(sw_seam_fill_crossings(&fill, plain, V, idx, &n, CAP, &left) == 0);
    SW_CHECK(n == STRIP && left == 0);
}

static void test_a_run_that_does_not_fit_is_left_whole(void)
{
    init();
    uint16_t idx[CAP];
    uint32_t n = make_strip(idx), left = 0;
    SW_CHECK(sw_seam_fill_crossings(&fill, ids, V, idx, &n, STRIP + 3, &left) == 0);
    SW_CHECK(n == STRIP && left == 2);
}

/* The strip's loop: bottom 10, 20, 21, 11, then the top back, with the
 * seam vertices given (id 0 ends the list) put after point `after` of it. */
static uint32_t strip_loop(sw_trim_point *pts, int after, const uint32_t *extra)
{
    static const uint32_t border[8] = { 10, 20, 21, 11, 15, 14, 13, 12 };
    uint32_t n = 0;
    for (int i = 0; i < 8; i++) {
        pts[n++] = (sw_trim_point){ { (float)i, 0 }, { (float)i, 0, 0 }, border[i] };
        for (int j = 0; i == after && extra[j]; j++)
            pts[n++] = (sw_trim_point){ { (float)i, 0 }, { (float)i + 0.5f, 0.1f * (float)(j + 1), 0.3f }, extra[j] };
    }
    return n;
}

typedef struct strip_mesh {
    float positions[3 * 16], normals[3 * 16], uvs[2 * 16];
    uint32_t ids[16];
    uint16_t idx[CAP];
    sw_seam_fill_mesh m;
} strip_mesh;

static void make_strip_mesh(strip_mesh *s, uint32_t vertex_capacity)
{
    static const uint32_t plain[V] = { 10, 20, 21, 11, 12, 13, 14, 15 };
    memset(s, 0, sizeof *s);
    memcpy(s->ids, plain, sizeof plain);
    for (int v = 0; v < V; v++)
        s->normals[3 * v + 2] = (float)(v + 1);   /* tells the vertices' normals apart */
    uint32_t n = make_strip(s->idx);
    s->m = (sw_seam_fill_mesh){ s->positions, s->normals, s->uvs, s->ids, s->idx, V, n,
                                vertex_capacity, CAP };
}

static int has_triangle(const strip_mesh *s, uint16_t a, uint16_t b, uint16_t c)
{
    for (uint32_t t = STRIP; t + 2 < s->m.index_count; t += 3)
        if (s->idx[t] == a && s->idx[t + 1] == b && s->idx[t + 2] == c)
            return 1;
    return 0;
}

/* The fill over one loop of n points, pts[dropped[0 .. k)] listed as the
 * tessellator's drops. */
static uint32_t fill_listed(strip_mesh *s, const sw_trim_point *pts, uint32_t n, uint32_t *dropped,
                            uint32_t k, uint32_t *filled, uint32_t *left)
{
    const uint32_t first[2] = { 0, n };
    const sw_trim_loops loops = { pts, first, 1 };
    sw_seam_drop_list list = { dropped, k };
    return sw_seam_fill_drops(&fill, &loops, &list, &s->m, filled, left);
}

/* The same, none listed: the points missing are those whose seam vertex
 * the mesh lacks. */
static uint32_t fill_drops(strip_mesh *s, const sw_trim_point *pts, uint32_t n, uint32_t *filled,
                           uint32_t *left)
{
    return fill_listed(s, pts, n, NULL, 0, filled, left);
}

/* A dropped point whose seam vertex the mesh has elsewhere on the loop (a
 * sphere near its pole: a -> d -> b -> d, d dropped the first time as a
 * near repeat of a): the border a-b is joined to the neighbour's a-d-b. */
static void test_a_listed_drop_whose_vertex_is_kept_elsewhere(void)
{
    init();
    strip_mesh s;
    make_strip_mesh(&s, 16);
    static const uint32_t ids_in_order[9] = { 10, 20, 11, 21, 11, 15, 14, 13, 12 };
    sw_trim_point pts[9];
    for (uint32_t i = 0; i < 9; i++)
        pts[i] = (sw_trim_point){ { (float)i, 0 }, { (float)i, 2, 0 }, ids_in_order[i] };
    uint32_t dropped[1] = { 2 }, filled = 0, left = 9;
    SW_CHECK(fill_listed(&s, pts, 9, dropped, 1, &filled, &left) == 1);
    SW_CHECK(filled == 1 && left == 0 && s.ids[V] == 11);
    SW_CHECK(has_triangle(&s, 1, V, 2));
    /* not listed, nothing is missing: its seam vertex is in the mesh */
    make_strip_mesh(&s, 16);
    SW_CHECK(fill_drops(&s, pts, 9, &filled, &left) == 0 && filled == 0);
}

/* The strip's fill with the seam vertices `missing` (0 ends the list; none
 * of them in the mesh) after loop point `after`: the fans' triangles. */
static uint32_t fill_missing(strip_mesh *s, uint32_t vertex_capacity, sw_trim_point *pts,
                             int after, const uint32_t *missing, uint32_t *filled,
                             uint32_t *left)
{
    init();
    make_strip_mesh(s, vertex_capacity);
    return fill_drops(s, pts, strip_loop(pts, after, missing), filled, left);
}

static void test_a_dropped_point_gets_its_vertex_and_a_fan(void)
{
    strip_mesh s;
    sw_trim_point pts[16];
    const uint32_t missing[] = { 30, 0 };
    uint32_t filled = 0, left = 9;
    SW_CHECK(fill_missing(&s, 16, pts, 1, missing, &filled, &left) == 1);
    SW_CHECK(filled == 1 && left == 0 && s.m.vertex_count == V + 1);
    /* at its seam vertex's position, with its kept neighbour's normal */
    SW_CHECK(s.ids[V] == 30 && memcmp(s.positions + 3 * V, pts[2].p, sizeof pts[2].p) == 0);
    SW_CHECK(s.normals[3 * V + 2] == 2.0f);
    /* the fan joins the border's 20-21 (vertices 1, 2) to 20-30-21 */
    SW_CHECK(has_triangle(&s, 1, V, 2));
}

static void test_a_run_of_dropped_points_is_one_fan(void)
{
    strip_mesh s;
    sw_trim_point pts[16];
    const uint32_t missing[] = { 30, 30, 31, 0 };   /* 30 twice in a row: one vertex */
    uint32_t filled = 0, left = 9;
    SW_CHECK(fill_missing(&s, 16, pts, 1, missing, &filled, &left) == 2);
    SW_CHECK(filled == 2 && left == 0 && s.m.vertex_count == V + 2);
    SW_CHECK(has_triangle(&s, 1, V, V + 1) && has_triangle(&s, 1, V + 1, 2));
}

/* Dropped after the loop's last point: the run wraps round to its first. */
static void test_a_run_across_the_loops_start(void)
{
    strip_mesh s;
    sw_trim_point pts[16];
    const uint32_t missing[] = { 30, 0 };
    uint32_t filled = 0, left = 9;
    SW_CHECK(fill_missing(&s, 16, pts, 7, missing, &filled, &left) == 1);
    SW_CHECK(has_triangle(&s, 4, V, 0));   /* from 12 (vertex 4) to 10 (vertex 0) */
}

static void test_drops_without_room_are_told(void)
{
    strip_mesh s;
    sw_trim_point pts[16];
    const uint32_t missing[] = { 30, 0 };
    uint32_t filled = 9, left = 0;
    SW_CHECK(fill_missing(&s, V, pts, 1, missing, &filled, &left) == 0);   /* no room */
    SW_CHECK(filled == 0 && left == 1 && s.m.vertex_count == V && s.m.index_count == STRIP);
}

/* A loop none of whose seam vertices is in the mesh was left out whole
 * (drawn some other way, or not at all): it is not filled. */
static void test_a_loop_left_out_is_left_alone(void)
{
    init();
    strip_mesh s;
    make_strip_mesh(&s, 16);
    sw_trim_point pts[4];
    for (uint32_t i = 0; i < 4; i++)
        pts[i] = (sw_trim_point){ { (float)i, 1 }, { (float)i, 1, 0 }, 40 + i };
    uint32_t filled = 9, left = 9;
    SW_CHECK(fill_drops(&s, pts, 4, &filled, &left) == 0);
    SW_CHECK(filled == 0 && left == 0 && s.m.vertex_count == V && s.m.index_count == STRIP);
}

int main(void)
{
    SW_RUN(test_the_fan_closes_the_border_onto_the_seam_edge);
    SW_RUN(test_no_crossings_nothing_added);
    SW_RUN(test_a_run_that_does_not_fit_is_left_whole);
    SW_RUN(test_a_dropped_point_gets_its_vertex_and_a_fan);
    SW_RUN(test_a_run_of_dropped_points_is_one_fan);
    SW_RUN(test_a_run_across_the_loops_start);
    SW_RUN(test_drops_without_room_are_told);
    SW_RUN(test_a_loop_left_out_is_left_alone);
    SW_RUN(test_a_listed_drop_whose_vertex_is_kept_elsewhere);
    return sw_test_finish();
}
