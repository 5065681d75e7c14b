/* The view: the screen-space error rule and the clip planes. */
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

int main(void)
{
    SW_RUN(test_error_world_projects_to_requested_pixels);
    SW_RUN(test_clip_planes_enclose_the_model);
    SW_RUN(test_box_min_depth_is_nearest_corner_clamped_to_near);
    return sw_test_finish();
}
