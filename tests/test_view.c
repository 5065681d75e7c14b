/* SPDX-License-Identifier: MIT */
/* The view: the screen-space error rule and the clip planes. */
#include <math.h>

#include "sw_test.h"
#include "sw_view.h"

static sw_view make_view(int h)
{
    sw_camera_pose pose = { sw_v3(0, 0, 10), sw_v3(0, 0, 0), sw_v3(0, 1, 0) };
    sw_box box = { sw_v3(-1, -1, -1), sw_v3(1, 1, 1) };
    return sw_view_make(&pose, 60 * SW_PI / 180, h * 16 / 9, h, &box);
}

static void test_error_world_projects_to_requested_pixels(void)
{
    sw_view v = make_view(720);
    double e = sw_view_error_world(&v, 0.5, 9.0);
    /* A segment of length e at depth 9, across the view axis, spans 0.5 px:
     * project its two ends through the real matrices. */
    sw_vec4 a = sw_mat4_mul_v4(&v.view_proj, (sw_vec4){ 0, 0, 1, 1 });
    sw_vec4 b = sw_mat4_mul_v4(&v.view_proj, (sw_vec4){ 0, e, 1, 1 });
    double pixels = (b.y / b.w - a.y / a.w) * 0.5 * v.height;
    SW_CHECK_NEAR(pixels, 0.5, 1e-9);
    SW_CHECK_NEAR(sw_view_error_world(&v, 0.5, 18.0), 2 * e, 1e-15);
}

static void test_clip_planes_enclose_the_model(void)
{
    sw_view v = make_view(480);
    SW_CHECK(v.near_z <= 9.0 && v.near_z > 0);
    SW_CHECK(v.far_z >= 11.0);
    sw_box box = { sw_v3(-1, -1, -1), sw_v3(1, 1, 1) };
    SW_CHECK(sw_frustum_test_box(&v.frustum, &box) != SW_CULL_OUTSIDE);
    sw_box behind = { sw_v3(-1, -1, 20), sw_v3(1, 1, 22) };
    SW_CHECK(sw_frustum_test_box(&v.frustum, &behind) == SW_CULL_OUTSIDE);
}

static void test_box_min_depth_is_nearest_corner_clamped_to_near(void)
{
    sw_view v = make_view(480);
    sw_box box = { sw_v3(-1, -1, -1), sw_v3(1, 1, 1) };
    SW_CHECK_NEAR(sw_view_box_min_depth(&v, &box), 9.0, 1e-12);
    sw_box around_eye = { sw_v3(-1, -1, 9), sw_v3(1, 1, 11) };
    SW_CHECK(sw_view_box_min_depth(&v, &around_eye) == v.near_z);
}

static void test_near_floor_follows_the_depth_bits(void)
{
    /* The eye inside the box: near falls to its floor, far / 2000 at 16
     * bits, 256 times nearer at 24. */
    sw_camera_pose pose = { sw_v3(0, 0, 0), sw_v3(0, 0, -1), sw_v3(0, 1, 0) };
    sw_box box = { sw_v3(-100, -100, -100), sw_v3(100, 100, 100) };
    sw_view v16 = sw_view_make_depth(&pose, 1.0, 640, 480, &box, 16);
    sw_view v24 = sw_view_make_depth(&pose, 1.0, 640, 480, &box, 24);
    SW_CHECK_NEAR(v16.near_z, v16.far_z / 2000.0, 1e-12);
    SW_CHECK_NEAR(v24.near_z, v24.far_z / (2000.0 * 256), 1e-12);
    sw_view old = sw_view_make(&pose, 1.0, 640, 480, &box);
    SW_CHECK(old.near_z == v16.near_z && old.far_z == v16.far_z);
}

static void test_fit_depth_narrows_to_what_is_drawn(void)
{
    sw_view v = make_view(480);
    sw_view fit = sw_view_fit_depth(&v, 9.5, 10.5, 24);
    SW_CHECK_NEAR(fit.near_z, 9.5 * 0.99, 1e-12);
    SW_CHECK_NEAR(fit.far_z, 10.5 * 1.01, 1e-12);
    /* the projection and the frustum follow the planes */
    sw_box in = { sw_v3(-0.1, -0.1, -0.4), sw_v3(0.1, 0.1, 0.4) };
    sw_box behind_far = { sw_v3(-0.1, -0.1, -0.99), sw_v3(0.1, 0.1, -0.8) };
    SW_CHECK(sw_frustum_test_box(&fit.frustum, &in) != SW_CULL_OUTSIDE);
    SW_CHECK(sw_frustum_test_box(&fit.frustum, &behind_far) == SW_CULL_OUTSIDE);
    sw_vec4 c = sw_mat4_mul_v4(&fit.view_proj, (sw_vec4){ 0, 0, 0, 1 });
    SW_CHECK(fabs(c.z / c.w) < 1.0 && fabs(c.w - 10.0) < 1e-9);
    /* the pixels do not move: x and y of the projection are the same */
    sw_vec4 a = sw_mat4_mul_v4(&v.view_proj, (sw_vec4){ 0.3, 0.2, 0, 1 });
    sw_vec4 b = sw_mat4_mul_v4(&fit.view_proj, (sw_vec4){ 0.3, 0.2, 0, 1 });
    SW_CHECK_NEAR(a.x / a.w, b.x / b.w, 1e-12);
    SW_CHECK_NEAR(a.y / a.w, b.y / b.w, 1e-12);
}

static void test_fit_depth_keeps_the_floor_and_never_grows_far(void)
{
    sw_view v = make_view(480);
    sw_view close = sw_view_fit_depth(&v, 1e-9, 10.5, 16);
    SW_CHECK_NEAR(close.near_z, close.far_z / 2000.0, 1e-12);
    sw_view farther = sw_view_fit_depth(&v, 9.5, 1e6, 24);
    SW_CHECK(farther.far_z == v.far_z);
    sw_view empty = sw_view_fit_depth(&v, INFINITY, -INFINITY, 24);
    SW_CHECK(empty.near_z == v.near_z && empty.far_z == v.far_z);
    sw_view nan = sw_view_fit_depth(&v, NAN, 10, 24);
    SW_CHECK(nan.near_z == v.near_z && nan.far_z == v.far_z);
}

int main(void)
{
    SW_RUN(test_error_world_projects_to_requested_pixels);
    SW_RUN(test_clip_planes_enclose_the_model);
    SW_RUN(test_box_min_depth_is_nearest_corner_clamped_to_near);
    SW_RUN(test_near_floor_follows_the_depth_bits);
    SW_RUN(test_fit_depth_narrows_to_what_is_drawn);
    SW_RUN(test_fit_depth_keeps_the_floor_and_never_grows_far);
    return sw_test_finish();
}
