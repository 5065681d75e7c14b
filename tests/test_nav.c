/* SPDX-License-Identifier: MIT */
/* Navigation (sw_nav.h) with scripted inputs against golden poses worked
 * out by hand: at 30 Hz with accel_s 0.4 a speed ramps in 12 frames of
 * 1/12 each, so one second at full stick covers (78/12 + 18) / 30 of a
 * second's full-speed distance (1225 mm at 1500 mm/s), and letting go
 * glides 275 mm more. The pack is z-up: yaw 0 looks along +y. */
#include <math.h>
#include <string.h>

#include "sw_nav.h"
#include "sw_test.h"

static const double dt = 1.0 / 30;
static sw_pack_viewpoint views[3];
static sw_nav nav;

static void start(int view_count, int orbit)
{
    static const float eyes[3][3] = {{0, -5000, 1600}, {5000, 0, 1600}, {0, 5000, 3000}};
    static const float targets[3][3] = {{0, 0, 1600}, {0, 0, 1600}, {0, 0, 0}};
    for (int i = 0; i < 3; i++) {
        memset(&views[i], 0, sizeof views[i]);
        memcpy(views[i].eye, eyes[i], sizeof eyes[i]);
        memcpy(views[i].target, targets[i], sizeof targets[i]);
        views[i].up[2] = 1;
    }
    sw_nav_params p = {.walk_speed_mm_s = 1500, .turn_speed_deg_s = 90,
                       .orbit_speed_deg_s = 30, .accel_s = 0.4, .eye_height_mm = 1600,
                       .attract_timeout_s = 10, .attract_hold_s = 2, .transition_s = 1.5,
                       .fovy_rad = 45 * SW_PI / 180, .aspect = 1.6, .start_orbit = orbit};
    sw_camera_frame f = sw_camera_frame_for_up(sw_v3(0, 0, 1));
    sw_box box = {sw_v3(-1000, -1000, 0), sw_v3(1000, 1000, 2000)};
    sw_nav_init(&nav, &p, &f, &box, views, (uint32_t)view_count);
}

static void run(sw_nav_input in, int frames)
{
    in.activity = in.move != 0 || in.turn != 0 || in.look != 0 || in.strafe != 0 ||
                  in.actions != 0;
    for (int i = 0; i < frames; i++) {
        sw_nav_step(&nav, &in, dt);
        in.actions = 0;  /* an action fires once */
    }
}

static void near_v(sw_vec3 a, double x, double y, double z, double tol)
{
    SW_CHECK_NEAR(a.x, x, tol);
    SW_CHECK_NEAR(a.y, y, tol);
    SW_CHECK_NEAR(a.z, z, tol);
}

static uint32_t act(sw_kiosk_action a) { return 1u << a; }

static void walk_ramps_up_and_glides_to_a_stop(void)
{
    start(3, 0);
    near_v(sw_nav_pose(&nav).eye, 0, -5000, 1600, 1e-9);  /* home: viewpoint 0 */
    run((sw_nav_input){.move = 1}, 30);
    near_v(sw_nav_pose(&nav).eye, 0, -5000 + 1225, 1600, 1e-6);
    run((sw_nav_input){0}, 30);
    near_v(sw_nav_pose(&nav).eye, 0, -5000 + 1500, 1600, 1e-6);
    SW_CHECK(nav.v_move == 0);
}

static void turning_and_strafing(void)
{
    start(3, 0);
    run((sw_nav_input){.turn = 1}, 30);
    double yaw = 90 * (78.0 / 12 + 18) / 30 * SW_PI / 180;  /* 73.5 degrees */
    SW_CHECK_NEAR(nav.yaw, yaw, 1e-9);
    sw_camera_pose p = sw_nav_pose(&nav);
    near_v(p.target, 1000 * sin(yaw), -5000 + 1000 * cos(yaw), 1600, 1e-6);
    start(3, 0);
    run((sw_nav_input){.strafe = 1}, 30);
    near_v(sw_nav_pose(&nav).eye, 1225, -5000, 1600, 1e-6);  /* right is +x */
}

static void looking_is_clamped_and_walking_stays_level(void)
{
    start(3, 0);
    run((sw_nav_input){.look = -1}, 90);   /* far past 80 degrees down */
    SW_CHECK_NEAR(nav.pitch, -80 * SW_PI / 180, 1e-12);
    run((sw_nav_input){.move = 1, .look = -1}, 30);
    near_v(sw_nav_pose(&nav).eye, 0, -5000 + 1225, 1600, 1e-6);
}

static void the_floor_holds_the_eye_up(void)
{
    start(3, 0);
    views[0].eye[2] = 500;                 /* a viewpoint below eye height */
    sw_nav_init(&nav, &nav.p, &nav.frame, &nav.box, views, 3);
    run((sw_nav_input){.move = 1}, 1);
    SW_CHECK_NEAR(sw_nav_pose(&nav).eye.z, 1600, 1e-9);
}

static void next_and_previous_viewpoints_glide(void)
{
    start(3, 0);
    run((sw_nav_input){.actions = act(SW_ACTION_NEXT_VIEW)}, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_TRANSITION && nav.view == 1);
    nav.t = 0.75 - dt;                     /* to the middle: smoothstep(0.5) = 0.5 */
    run((sw_nav_input){0}, 1);
    near_v(sw_nav_pose(&nav).eye, 2500, -2500, 1600, 1e-6);
    run((sw_nav_input){0}, 23);
    SW_CHECK(nav.mode == SW_NAV_MODE_WALK);
    sw_camera_pose p = sw_nav_pose(&nav);
    near_v(p.eye, 5000, 0, 1600, 1e-6);
    near_v(p.target, 4000, 0, 1600, 1e-6);  /* looking at viewpoint 1's target */
    run((sw_nav_input){.actions = act(SW_ACTION_PREV_VIEW)}, 1);
    SW_CHECK(nav.view == 0);
    run((sw_nav_input){.actions = act(SW_ACTION_PREV_VIEW)}, 1);
    SW_CHECK(nav.view == 2);               /* wraps around */
    run((sw_nav_input){0}, 60);
    near_v(sw_nav_pose(&nav).eye, 0, 5000, 3000, 1e-6);
    run((sw_nav_input){.actions = act(SW_ACTION_HOME)}, 60);
    near_v(sw_nav_pose(&nav).eye, 0, -5000, 1600, 1e-6);
    SW_CHECK(nav.view == 0);
}

static void attract_tours_after_idle_and_stops_at_input(void)
{
    start(3, 0);
    run((sw_nav_input){0}, 299);
    SW_CHECK(nav.mode == SW_NAV_MODE_WALK);  /* 9.97 s idle */
    run((sw_nav_input){0}, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_TRANSITION && nav.attract && nav.view == 1);
    run((sw_nav_input){0}, 46);              /* 1.5 s transition, then holding */
    SW_CHECK(nav.mode == SW_NAV_MODE_ATTRACT);
    near_v(sw_nav_pose(&nav).eye, 5000, 0, 1600, 1e-9);
    run((sw_nav_input){0}, 60);              /* 2 s hold: on to viewpoint 2 */
    SW_CHECK(nav.mode == SW_NAV_MODE_TRANSITION && nav.view == 2);
    run((sw_nav_input){0}, 10);
    sw_camera_pose before = sw_nav_pose(&nav);
    run((sw_nav_input){.actions = act(SW_ACTION_NEXT_VIEW)}, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_WALK && !nav.attract && nav.view == 2);
    near_v(sw_nav_pose(&nav).eye, before.eye.x, before.eye.y, before.eye.z, 1e-9);
    run((sw_nav_input){.actions = act(SW_ACTION_ATTRACT)}, 1);
    SW_CHECK(nav.attract && nav.view == 0);  /* on demand, from where it was */
}

static void orbit_around_the_current_product(void)
{
    start(3, 0);
    run((sw_nav_input){.actions = act(SW_ACTION_TOGGLE_MODE)}, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_ORBIT);
    near_v(nav.centre, 0, 0, 1600, 1e-9);    /* viewpoint 0's target */
    run((sw_nav_input){.turn = 1}, 60);
    sw_camera_pose p = sw_nav_pose(&nav);
    SW_CHECK_NEAR(sw_v3_length(sw_v3_sub(p.eye, nav.centre)), 5000, 1e-6);
    double swung = 30 * (78.0 / 12 + 48) / 30;  /* degrees in 2 s with the ramp */
    SW_CHECK_NEAR(atan2(p.eye.x, -p.eye.y) * 180 / SW_PI, swung, 1e-6); /* to the right */
    run((sw_nav_input){.move = 1}, 30);       /* zooms in */
    SW_CHECK(nav.radius < 5000 * 0.65 && nav.radius > 5000 * 0.5);
}

static void no_viewpoints_means_orbit_home_and_a_slow_orbit_tour(void)
{
    start(0, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_ORBIT && nav.view == -1);
    run((sw_nav_input){0}, 300);
    SW_CHECK(nav.mode == SW_NAV_MODE_ATTRACT);
    double az = nav.azimuth;
    run((sw_nav_input){0}, 30);
    SW_CHECK_NEAR(remainder(nav.azimuth - az, 2 * SW_PI), 30 * SW_PI / 180, 1e-9);
    run((sw_nav_input){.turn = 1}, 1);
    SW_CHECK(nav.mode == SW_NAV_MODE_ORBIT);
}

static void the_same_script_gives_the_same_poses(void)
{
    sw_camera_pose a[200], b[200];
    for (int pass = 0; pass < 2; pass++) {
        start(3, 0);
        for (int f = 0; f < 200; f++) {
            sw_nav_input in = {.move = (float)sin(f * 0.1), .turn = (float)cos(f * 0.07),
                               .look = f % 50 < 10 ? 0.5f : 0, .activity = 1};
            if (f == 120)
                in.actions = act(SW_ACTION_NEXT_VIEW);
            sw_nav_step(&nav, &in, dt);
            (pass ? b : a)[f] = sw_nav_pose(&nav);
        }
    }
    SW_CHECK(memcmp(a, b, sizeof a) == 0);
}

int main(void)
{
    SW_RUN(walk_ramps_up_and_glides_to_a_stop);
    SW_RUN(turning_and_strafing);
    SW_RUN(looking_is_clamped_and_walking_stays_level);
    SW_RUN(the_floor_holds_the_eye_up);
    SW_RUN(next_and_previous_viewpoints_glide);
    SW_RUN(attract_tours_after_idle_and_stops_at_input);
    SW_RUN(orbit_around_the_current_product);
    SW_RUN(no_viewpoints_means_orbit_home_and_a_slow_orbit_tour);
    SW_RUN(the_same_script_gives_the_same_poses);
    return sw_test_finish();
}
