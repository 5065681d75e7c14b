/* SPDX-License-Identifier: MIT */
/* sw_normal_cone: a patch's cone holds every normal of the patch (sampled
 * densely, random degrees, shapes and weights), narrower cones are caught
 * by the same sampling, planes and collapsed edges get narrow cones, a
 * patch bent past a half-space gets the full sphere, unions hold both
 * cones, and the back-face test never calls a patch back-facing that shows
 * its front anywhere to the eye. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_bezier.h"
#include "sw_normal_cone.h"
#include "sw_test.h"

enum { SAMPLES = 41, MAX_CTRL = 4 * 16 * 16 };

static double g_scratch[32768];

static unsigned g_seed = 12345;
static double uniform(double lo, double hi)
{
    g_seed = g_seed * 1103515245u + 12345u;
    return lo + (hi - lo) * ((g_seed >> 8) & 0xFFFFFF) / (double)0xFFFFFF;
}

typedef struct test_patch {
    float ctrl[MAX_CTRL];
    sw_bezier_patchf f;
} test_patch;

/* A height field over the unit square, bent by amplitude, turned by a
 * random rotation and moved far from the origin; weights in [1/w, w]. */
static void make_patch(test_patch *t, int du, int dv, double amplitude, double weight_range)
{
    sw_vec3 axis = sw_v3_normalize(sw_v3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    sw_mat4 r = sw_mat4_rotate(axis, uniform(0, 2 * SW_PI));
    sw_vec3 offset = sw_v3(uniform(-1000, 1000), uniform(-1000, 1000), uniform(-1000, 1000));
    for (int j = 0; j <= dv; j++)
        for (int i = 0; i <= du; i++) {
            sw_vec3 p = sw_v3((double)i / du, (double)j / dv, amplitude * uniform(-1, 1));
            p = sw_v3_add(sw_mat4_transform_point(&r, p), offset);
            float *c = t->ctrl + 4 * (j * (du + 1) + i);
            c[0] = (float)p.x, c[1] = (float)p.y, c[2] = (float)p.z;
            c[3] = weight_range > 1 ? (float)exp(uniform(-1, 1) * log(weight_range)) : 1.0f;
        }
    t->f = (sw_bezier_patchf){ du, dv, weight_range > 1, t->ctrl };
}

/* The largest angle between axis and a sampled normal of the patch
 * (cross(P_u, P_v); where it vanishes, the evaluator's limit normal). */
static double widest_sampled(const sw_bezier_patchf *f, sw_vec3 axis)
{
    static double ctrl[MAX_CTRL];
    sw_bezier_patch p = sw_bezier_patch_from_float(f, ctrl);
    double widest = 0;
    for (int j = 0; j < SAMPLES; j++)
        for (int i = 0; i < SAMPLES; i++) {
            sw_surface_point q;
            sw_bezier_eval(&p, (double)i / (SAMPLES - 1), (double)j / (SAMPLES - 1),
                           SW_EVAL_FIRST, &q);
            sw_vec3 n = sw_v3_cross(q.du, q.dv);
            if (sw_v3_length(n) < 1e-12 * sw_v3_length(q.du) * sw_v3_length(q.dv) + 1e-300)
                n = q.normal;
            double a = atan2(sw_v3_length(sw_v3_cross(axis, n)), sw_v3_dot(axis, n));
            widest = fmax(widest, a);
        }
    return widest;
}

static void test_plane_gets_its_normal(void)
{
    const float ctrl[16] = { 0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1 };
    const sw_bezier_patchf f = { 1, 1, 0, ctrl };
    sw_normal_cone c = sw_normal_cone_of_patch(&f, g_scratch);
    SW_CHECK(c.half_angle < 1e-9);
    SW_CHECK_NEAR(c.axis.z, 1.0, 1e-12); /* P_u = x, P_v = y: x cross y = +z */
}

/* Every sampled normal within the cone, over random patches of degrees 1..6
 * with weights up to 4:1 either way; and most of them get a cone at all. */
static void test_cone_holds_every_sampled_normal(void)
{
    static test_patch t;
    int cones = 0, total = 0, worst_fail = 0;
    for (int k = 0; k < 400; k++) {
        int du = 1 + k % 6, dv = 1 + (k / 6) % 4;
        make_patch(&t, du, dv, k % 3 == 0 ? 0.05 : 0.25, k % 2 ? 4.0 : 1.0);
        sw_normal_cone c = sw_normal_cone_of_patch(&t.f, g_scratch);
        total++;
        if (c.half_angle >= SW_CONE_FULL)
            continue;
        cones++;
        double widest = widest_sampled(&t.f, c.axis);
        if (!(widest <= c.half_angle + 1e-9) && worst_fail++ < 5)
            SW_CHECK_MSG(0, "patch %d (degrees %d, %d): a normal %.6f rad off the axis, cone %.6f",
                         k, du, dv, widest, c.half_angle);
    }
    SW_CHECK(worst_fail == 0);
    SW_CHECK_MSG(cones > total / 2, "only %d of %d patches got a cone", cones, total);
}

/* The sampling is dense enough to catch a cone that is too narrow: the
 * same cones at half their angle leave sampled normals out on nearly every
 * curved patch (what the check above would report). */
static void test_narrower_cone_is_caught(void)
{
    static test_patch t;
    int caught = 0, cones = 0;
    for (int k = 0; k < 100; k++) {
        make_patch(&t, 3, 3, 0.25, k % 2 ? 4.0 : 1.0);
        sw_normal_cone c = sw_normal_cone_of_patch(&t.f, g_scratch);
        if (c.half_angle >= SW_CONE_FULL)
            continue;
        cones++;
        caught += widest_sampled(&t.f, c.axis) > 0.5 * c.half_angle;
    }
    SW_CHECK_MSG(cones >= 50 && caught >= cones * 9 / 10, "%d of %d narrowed cones caught",
                 caught, cones);
}

/* A patch curving through a half turn (a C in x, z: its tangent turns from
 * +x to -x) has normals in opposite directions: no cone. */
static void test_half_turn_gets_the_full_sphere(void)
{
    float ctrl[4 * 8];
    const double x[4] = { 0, 2, 2, 0 }, z[4] = { 0, 0, 2, 2 };
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 4; i++) {
            float *c = ctrl + 4 * (j * 4 + i);
            c[0] = (float)x[i], c[1] = (float)j, c[2] = (float)z[i], c[3] = 1;
        }
    const sw_bezier_patchf f = { 3, 1, 0, ctrl };
    sw_normal_cone c = sw_normal_cone_of_patch(&f, g_scratch);
    SW_CHECK(c.half_angle >= SW_CONE_FULL);
}

/* A flat patch whose v = 0 edge is one point (a fan around it, as at a
 * sphere's pole): the coefficients there are exactly zero and prove
 * nothing, so the cone comes from the others and stays narrow; it holds
 * the limit normal at the collapsed edge too. The same with a rational
 * curved pole. */
static void test_collapsed_edge_keeps_a_cone(void)
{
    float ctrl[4 * 9];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            float *c = ctrl + 4 * (j * 3 + i);
            double r = j / 2.0, a = i * 0.4;
            c[0] = (float)(r * cos(a)), c[1] = (float)(r * sin(a)), c[2] = 0, c[3] = 1;
        }
    const sw_bezier_patchf f = { 2, 2, 0, ctrl };
    sw_normal_cone c = sw_normal_cone_of_patch(&f, g_scratch);
    SW_CHECK(c.half_angle < 1e-6);
    SW_CHECK_NEAR(fabs(c.axis.z), 1.0, 1e-9);
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            float *p = ctrl + 4 * (j * 3 + i);
            p[2] = (float)(0.3 * (j / 2.0) * (j / 2.0) + 0.05 * i);
            p[3] = (float)(1.0 + 0.5 * ((i + j) % 2));
        }
    const sw_bezier_patchf g = { 2, 2, 1, ctrl };
    c = sw_normal_cone_of_patch(&g, g_scratch);
    SW_CHECK(c.half_angle < SW_CONE_FULL);
    SW_CHECK(widest_sampled(&g, c.axis) <= c.half_angle + 1e-9);
}

/* Directions on the rim of a cone, around its axis. */
static sw_vec3 rim(const sw_normal_cone *c, double azimuth)
{
    sw_vec3 helper = fabs(c->axis.x) < 0.9 ? sw_v3(1, 0, 0) : sw_v3(0, 1, 0);
    sw_vec3 e1 = sw_v3_normalize(sw_v3_cross(c->axis, helper)), e2 = sw_v3_cross(c->axis, e1);
    sw_vec3 side = sw_v3_add(sw_v3_scale(e1, cos(azimuth)), sw_v3_scale(e2, sin(azimuth)));
    return sw_v3_add(sw_v3_scale(c->axis, cos(c->half_angle)),
                     sw_v3_scale(side, sin(c->half_angle)));
}

static void test_union_holds_both(void)
{
    int failures = 0;
    for (int k = 0; k < 500; k++) {
        sw_normal_cone a = { sw_v3_normalize(sw_v3(uniform(-1, 1), uniform(-1, 1), 1)),
                             uniform(0, 0.6) };
        sw_normal_cone b = { sw_v3_normalize(sw_v3(uniform(-1, 1), uniform(-1, 1), 1)),
                             uniform(0, 0.6) };
        sw_normal_cone u = sw_normal_cone_union(&a, &b);
        if (u.half_angle >= SW_CONE_FULL)
            continue;
        for (int r = 0; r < 32; r++) {
            sw_vec3 d = rim(r % 2 ? &a : &b, r * 0.4);
            failures += acos(fmin(1, sw_v3_dot(d, u.axis))) > u.half_angle + 1e-9;
        }
    }
    SW_CHECK(failures == 0);
    sw_normal_cone e = sw_normal_cone_empty(), one = { sw_v3(0, 0, 1), 0.2 };
    sw_normal_cone u = sw_normal_cone_union(&e, &one);
    SW_CHECK(u.half_angle == 0.2 && u.axis.z == 1);
}

static void test_plane_faces_away_from_below_only(void)
{
    const sw_normal_cone up = { sw_v3(0, 0, 1), 0 };
    const sw_box box = { sw_v3(0, 0, 0), sw_v3(1, 1, 0) };
    SW_CHECK(sw_normal_cone_back_facing(&up, &box, sw_v3(0.5, 0.5, -3), 0.05) == 1);
    SW_CHECK(sw_normal_cone_back_facing(&up, &box, sw_v3(0.5, 0.5, 3), 0.05) == 0);
    SW_CHECK(sw_normal_cone_back_facing(&up, &box, sw_v3(0.5, 0.5, 0), 0.05) == 0);
    /* Grazing: below the plane, but within the margin of its edge-on view. */
    SW_CHECK(sw_normal_cone_back_facing(&up, &box, sw_v3(40, 0.5, -1), 0.05) == 0);
    SW_CHECK(sw_normal_cone_back_facing(&up, &box, sw_v3(40, 0.5, -1), 0) == 1);
    const sw_normal_cone full = { sw_v3(0, 0, 0), 2 * SW_CONE_FULL };
    SW_CHECK(sw_normal_cone_back_facing(&full, &box, sw_v3(0.5, 0.5, -3), 0) == 0);
}

/* Random curved patches and eyes: back-facing only when every sampled
 * point's normal faces away from the eye; and some eyes do see only backs. */
static void test_back_facing_is_never_wrong(void)
{
    static test_patch t;
    static double ctrl[MAX_CTRL];
    int said = 0, wrong = 0;
    for (int k = 0; k < 200; k++) {
        make_patch(&t, 3, 2, 0.2, k % 2 ? 3.0 : 1.0);
        sw_normal_cone c = sw_normal_cone_of_patch(&t.f, g_scratch);
        sw_bezier_patch p = sw_bezier_patch_from_float(&t.f, ctrl);
        sw_box box = sw_bezier_control_box(&p);
        sw_vec3 centre = sw_box_center(&box);
        for (int e = 0; e < 20; e++) {
            sw_vec3 eye = sw_v3_add(centre, sw_v3(uniform(-6, 6), uniform(-6, 6), uniform(-6, 6)));
            if (!sw_normal_cone_back_facing(&c, &box, eye, 0))
                continue;
            said++;
            for (int j = 0; j < 17; j++)
                for (int i = 0; i < 17; i++) {
                    sw_surface_point q;
                    sw_bezier_eval(&p, i / 16.0, j / 16.0, SW_EVAL_FIRST, &q);
                    wrong += sw_v3_dot(sw_v3_cross(q.du, q.dv), sw_v3_sub(eye, q.p)) >= 0;
                }
        }
    }
    SW_CHECK(wrong == 0);
    SW_CHECK_MSG(said > 200, "only %d eyes saw backs only", said);
}

int main(void)
{
    SW_RUN(test_plane_gets_its_normal);
    SW_RUN(test_cone_holds_every_sampled_normal);
    SW_RUN(test_narrower_cone_is_caught);
    SW_RUN(test_half_turn_gets_the_full_sphere);
    SW_RUN(test_collapsed_edge_keeps_a_cone);
    SW_RUN(test_union_holds_both);
    SW_RUN(test_plane_faces_away_from_below_only);
    SW_RUN(test_back_facing_is_never_wrong);
    return sw_test_finish();
}
