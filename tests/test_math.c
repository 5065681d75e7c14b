/* SPDX-License-Identifier: MIT */
/* sw_math: camera matrices against hand-computed values, frustum culling of
 * boxes, box and segment distances. */
#include <math.h>
#include <stdint.h>

#include "sw_math.h"
#include "sw_test.h"

#define SW_PI 3.14159265358979323846

static sw_box box_of(double x0, double y0, double z0, double x1, double y1, double z1)
{
    sw_box b = {{x0, y0, z0}, {x1, y1, z1}};
    return b;
}

/* Eye on +x looking at the origin with y up: the eye's right is world -z,
 * so the rows are s = (0,0,-1), u = (0,1,0), -f = (1,0,0), translation (0,0,-3). */
static void test_look_at_matches_hand_computed(void)
{
    sw_mat4 m = sw_mat4_look_at(sw_v3(3, 0, 0), sw_v3(0, 0, 0), sw_v3(0, 1, 0));
    const double expect[16] = {0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, -3, 1};
    for (int i = 0; i < 16; i++)
        SW_CHECK_NEAR(m.m[i], expect[i], 1e-15);
    sw_vec3 p = sw_mat4_transform_point(&m, sw_v3(0, 0, 1));
    SW_CHECK_NEAR(p.x, -1, 1e-15);
    SW_CHECK_NEAR(p.y, 0, 1e-15);
    SW_CHECK_NEAR(p.z, -3, 1e-15);
}

/* fovy 90 degrees (f = 1), aspect 2, near 1, far 3: diagonal 0.5, 1, -2, and
 * m[14] = 2 * 3 * 1 / (1 - 3) = -3; near maps to z = -1, far to z = +1. */
static void test_perspective_matches_hand_computed(void)
{
    sw_mat4 m = sw_mat4_perspective(SW_PI / 2, 2, 1, 3);
    const double expect[16] = {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -3, 0};
    for (int i = 0; i < 16; i++)
        SW_CHECK_NEAR(m.m[i], expect[i], 1e-15);
    SW_CHECK_NEAR(sw_mat4_transform_point(&m, sw_v3(0, 0, -1)).z, -1, 1e-15);
    SW_CHECK_NEAR(sw_mat4_transform_point(&m, sw_v3(0, 0, -3)).z, 1, 1e-15);
    SW_CHECK_NEAR(sw_mat4_transform_point(&m, sw_v3(2, 1, -1)).x, 1, 1e-15);
}

static void test_mat4_mul_and_rotate(void)
{
    sw_mat4 r = sw_mat4_rotate(sw_v3(0, 0, 2), SW_PI / 2);
    sw_vec3 p = sw_mat4_transform_point(&r, sw_v3(1, 0, 0));
    SW_CHECK_NEAR(p.x, 0, 1e-15);
    SW_CHECK_NEAR(p.y, 1, 1e-15);
    sw_mat4 t = sw_mat4_translate(sw_v3(1, 2, 3));
    sw_mat4 tr = sw_mat4_mul(&t, &r); /* rotate first, then translate */
    p = sw_mat4_transform_point(&tr, sw_v3(1, 0, 0));
    SW_CHECK_NEAR(p.x, 1, 1e-15);
    SW_CHECK_NEAR(p.y, 3, 1e-15);
    SW_CHECK_NEAR(p.z, 3, 1e-15);
    float f[16];
    sw_mat4_to_float(&tr, f);
    SW_CHECK(f[13] == 2.0f && f[15] == 1.0f);
}

static sw_frustum test_frustum(void)
{
    /* Eye at z = 10 looking down -z, 90 degree square view, near 1, far 100:
     * the visible region at depth d is |x|, |y| <= d. */
    sw_mat4 view = sw_mat4_look_at(sw_v3(0, 0, 10), sw_v3(0, 0, 0), sw_v3(0, 1, 0));
    sw_mat4 proj = sw_mat4_perspective(SW_PI / 2, 1, 1, 100);
    sw_mat4 vp = sw_mat4_mul(&proj, &view);
    return sw_frustum_from_matrix(&vp);
}

static void test_frustum_planes_are_normalised(void)
{
    sw_frustum f = test_frustum();
    for (int i = 0; i < 6; i++)
        SW_CHECK_NEAR(sw_v3_length(f.planes[i].n), 1, 1e-12);
    /* The near plane is z = 9 facing -z: distance of the origin is 9. */
    int found = 0;
    for (int i = 0; i < 6; i++)
        if (fabs(f.planes[i].n.z + 1) < 1e-12 && fabs(f.planes[i].d - 9) < 1e-9)
            found = 1;
    SW_CHECK(found);
}

static void test_frustum_culls_boxes(void)
{
    sw_frustum f = test_frustum();
    sw_box inside = box_of(-1, -1, -1, 1, 1, 1);
    sw_box behind = box_of(-1, -1, 11, 1, 1, 12);
    sw_box left = box_of(-30, -1, -1, -20, 1, 1);   /* at depth 10 the view ends at |x| = 10 */
    sw_box beyond_far = box_of(-1, -1, -200, 1, 1, -95); /* far plane at z = -90 */
    sw_box across_far = box_of(-1, -1, -200, 1, 1, -85);
    sw_box on_near = box_of(-0.5, -0.5, 8, 0.5, 0.5, 9.5);
    sw_box on_side = box_of(5, -1, -1, 15, 1, 1);
    sw_box empty = sw_box_empty();
    SW_CHECK(sw_frustum_test_box(&f, &inside) == SW_CULL_INSIDE);
    SW_CHECK(sw_frustum_test_box(&f, &behind) == SW_CULL_OUTSIDE);
    SW_CHECK(sw_frustum_test_box(&f, &left) == SW_CULL_OUTSIDE);
    SW_CHECK(sw_frustum_test_box(&f, &beyond_far) == SW_CULL_OUTSIDE);
    SW_CHECK(sw_frustum_test_box(&f, &across_far) == SW_CULL_INTERSECTS);
    SW_CHECK(sw_frustum_test_box(&f, &on_near) == SW_CULL_INTERSECTS);
    SW_CHECK(sw_frustum_test_box(&f, &on_side) == SW_CULL_INTERSECTS);
    SW_CHECK(sw_frustum_test_box(&f, &empty) == SW_CULL_OUTSIDE);
}

/* Where a box can be seen: a floor the eye stands over from depth 2 on (its
 * corners reach behind the eye, so their nearest depth is -10); a box off
 * to the side nowhere; one round the eye at once; one in front at its face. */
static void test_box_visible_min_depth(void)
{
    sw_frustum f = test_frustum();
    sw_vec3 eye = sw_v3(0, 0, 10), fwd = sw_v3(0, 0, -1);
    sw_box floor_box = box_of(-100, -3, -100, 100, -2, 20);
    sw_box left = box_of(-30, -1, -1, -20, 1, 1);
    sw_box round_eye = box_of(-1, -1, 9, 1, 1, 11);
    sw_box inside = box_of(-1, -1, -1, 1, 1, 1);
    SW_CHECK_NEAR(sw_box_visible_min_depth(&floor_box, &f, eye, fwd), 2, 1e-9);
    SW_CHECK(isinf(sw_box_visible_min_depth(&left, &f, eye, fwd)));
    SW_CHECK(sw_box_visible_min_depth(&round_eye, &f, eye, fwd) == 0);
    SW_CHECK_NEAR(sw_box_visible_min_depth(&inside, &f, eye, fwd), 9, 1e-9);
    sw_box empty = sw_box_empty();
    SW_CHECK(isinf(sw_box_visible_min_depth(&empty, &f, eye, fwd)));
    /* Random boxes against points sampled in them: never above the nearest
     * sample inside the sides (it bounds what is seen), and within a
     * sample step of it. */
    uint32_t seed = 7;
    for (int t = 0; t < 300; t++) {
        double c[6];
        for (int k = 0; k < 6; k++) {
            seed = seed * 1664525u + 1013904223u;
            c[k] = (seed >> 8) / 16777216.0 * 40 - 20;
        }
        sw_box b = box_of(fmin(c[0], c[3]), fmin(c[1], c[4]), fmin(c[2], c[5]), fmax(c[0], c[3]),
                          fmax(c[1], c[4]), fmax(c[2], c[5]));
        double got = sw_box_visible_min_depth(&b, &f, eye, fwd), sampled = INFINITY, step = 0;
        const int n = 24;
        for (int i = 0; i <= n; i++)
            for (int j = 0; j <= n; j++)
                for (int k = 0; k <= n; k++) {
                    sw_vec3 d = sw_v3_sub(b.max, b.min);
                    sw_vec3 p = sw_v3(b.min.x + d.x * i / n, b.min.y + d.y * j / n,
                                      b.min.z + d.z * k / n);
                    step = sw_v3_length(d) / n;
                    int in = 1;
                    for (int q = 0; q < 4; q++)
                        in &= sw_v3_dot(f.planes[q].n, p) + f.planes[q].d >= 0;
                    if (in)
                        sampled = fmin(sampled, sw_v3_dot(sw_v3_sub(p, eye), fwd));
                }
        if (isinf(sampled))
            continue; /* nothing sampled inside: a sliver, or none */
        SW_CHECK_MSG(got <= sampled + 1e-9 && got >= sampled - 2 * step - 1e-9,
                     "box %d: %g against sampled %g (step %g)", t, got, sampled, step);
    }
}

static void test_box_distance(void)
{
    sw_box b = box_of(0, 0, 0, 1, 2, 3);
    SW_CHECK_NEAR(sw_box_distance(&b, sw_v3(0.5, 1, 1)), 0, 0);
    SW_CHECK_NEAR(sw_box_distance(&b, sw_v3(-3, 1, 1)), 3, 1e-15);
    SW_CHECK_NEAR(sw_box_distance(&b, sw_v3(4, 6, 3)), 5, 1e-15); /* (3, 4, 0) off the corner */
    SW_CHECK_NEAR(sw_box_distance(&b, sw_v3(-1, -2, 5)), 3, 1e-15); /* (1, 2, 2) */
}

static void test_box_accumulates(void)
{
    sw_box b = sw_box_empty();
    SW_CHECK(sw_box_is_empty(&b));
    SW_CHECK(sw_box_diagonal(&b) == 0);
    sw_box_add_point(&b, sw_v3(1, 2, 3));
    SW_CHECK(!sw_box_is_empty(&b));
    sw_box other = box_of(-1, 0, 0, 0, 0, 1);
    sw_box_add_box(&b, &other);
    sw_box e = sw_box_empty();
    sw_box_add_box(&b, &e);
    SW_CHECK(b.min.x == -1 && b.min.y == 0 && b.min.z == 0);
    SW_CHECK(b.max.x == 1 && b.max.y == 2 && b.max.z == 3);
    SW_CHECK_NEAR(sw_box_diagonal(&b), sqrt(4 + 4 + 9), 1e-15);
    sw_vec3 c = sw_box_center(&b);
    SW_CHECK(c.x == 0 && c.y == 1 && c.z == 1.5);
}

static void test_vectors(void)
{
    sw_vec3 n = sw_v3_normalize(sw_v3(3, 0, 4));
    SW_CHECK_NEAR(n.x, 0.6, 1e-15);
    SW_CHECK_NEAR(n.z, 0.8, 1e-15);
    sw_vec3 z = sw_v3_normalize(sw_v3(0, 0, 0));
    SW_CHECK(z.x == 0 && z.y == 0 && z.z == 0);
    sw_vec3 c = sw_v3_cross(sw_v3(1, 0, 0), sw_v3(0, 1, 0));
    SW_CHECK(c.x == 0 && c.y == 0 && c.z == 1);
    sw_vec3 l = sw_v3_lerp(sw_v3(1, 1, 1), sw_v3(3, 5, 7), 1);
    SW_CHECK(l.x == 3 && l.y == 5 && l.z == 7);
}

/* Inside the segment the perpendicular distance, beyond it the nearer end,
 * a degenerate segment its point. */
static void test_segment_distance(void)
{
    sw_vec3 a = sw_v3(0, 0, 0), b = sw_v3(4, 0, 0);
    SW_CHECK_NEAR(sw_v3_segment_distance(sw_v3(1, 3, 0), a, b), 3.0, 1e-12);
    SW_CHECK_NEAR(sw_v3_segment_distance(sw_v3(7, 4, 0), a, b), 5.0, 1e-12);
    SW_CHECK_NEAR(sw_v3_segment_distance(sw_v3(-3, 0, 4), a, b), 5.0, 1e-12);
    SW_CHECK_NEAR(sw_v3_segment_distance(sw_v3(2, 0, 0), a, b), 0.0, 1e-12);
    SW_CHECK_NEAR(sw_v3_segment_distance(sw_v3(0, 3, 4), a, a), 5.0, 1e-12);
}

int main(void)
{
    SW_RUN(test_look_at_matches_hand_computed);
    SW_RUN(test_perspective_matches_hand_computed);
    SW_RUN(test_mat4_mul_and_rotate);
    SW_RUN(test_frustum_planes_are_normalised);
    SW_RUN(test_frustum_culls_boxes);
    SW_RUN(test_box_visible_min_depth);
    SW_RUN(test_box_distance);
    SW_RUN(test_box_accumulates);
    SW_RUN(test_vectors);
    SW_RUN(test_segment_distance);
    return sw_test_finish();
}
