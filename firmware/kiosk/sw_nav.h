/* SPDX-License-Identifier: MIT */
/* Navigation: turns one frame's input intents into the
 * camera pose. Called once per frame by the input step (sw_kiosk.h) after
 * the devices were polled. Pure and deterministic: no clock, no allocation;
 * the same inputs and time steps give the same poses, which is what lets a
 * recorded input timeline replay to golden poses.
 *
 * Modes:
 *  - walk: move forward/back and strafe in the horizontal plane (the plane
 *    across the pack's up axis), turn about up, look up/down (pitch within
 *    +-80 degrees). Speeds ramp to the stick's target at full speed per
 *    accel_s seconds, both up and down, so a released stick glides to a
 *    stop. The eye never goes below the floor: the model box's lowest
 *    point along up plus eye_height_mm.
 *  - orbit: around the current product's centre (the current viewpoint's
 *    target after next/previous/home, else the model box's centre): turn
 *    swings the azimuth, look the elevation (+-85 degrees), move zooms.
 *  - transition: next/previous viewpoint and home glide to that
 *    viewpoint's pose in transition_s (smoothstep on eye and target), then
 *    walk on from it. Home is viewpoint 0, or the orbit's start pose when
 *    the pack has no viewpoints.
 *  - attract: after attract_timeout_s without input (0: never), or on the
 *    attract action, tour the viewpoints (transition, hold attract_hold_s,
 *    next) or, without viewpoints, orbit slowly. The first input of any
 *    device ends it where it is and is otherwise ignored. */
#ifndef SW_NAV_H
#define SW_NAV_H

#include <stdint.h>

#include "sw_camera_path.h"
#include "sw_kiosk_config.h"
#include "sw_pack.h"

typedef struct sw_nav_params {
    double walk_speed_mm_s, turn_speed_deg_s, orbit_speed_deg_s;
    double accel_s;             /* seconds from rest to full speed; > 0 */
    double eye_height_mm;
    double attract_timeout_s;   /* 0: no attract mode on idle */
    double attract_hold_s;
    double transition_s;        /* > 0 */
    double fovy_rad, aspect;    /* for the orbit's distance */
    int start_orbit;
} sw_nav_params;

/* One frame's input. Axes in [-1, 1]: move forward +, strafe right +, turn
 * right +, look up +. actions: bit (1u << sw_kiosk_action) for each
 * discrete action fired this frame (next_view, prev_view, home,
 * toggle_mode, attract). activity: any device saw any input this frame. */
typedef struct sw_nav_input {
    float move, strafe, turn, look;
    uint32_t actions;
    int activity;
} sw_nav_input;

typedef enum sw_nav_mode {
    SW_NAV_MODE_WALK, SW_NAV_MODE_ORBIT, SW_NAV_MODE_TRANSITION, SW_NAV_MODE_ATTRACT
} sw_nav_mode;

typedef struct sw_nav {
    sw_nav_params p;
    sw_camera_frame frame;
    sw_vec3 ahead;              /* cross(up, right): yaw 0 looks along it */
    sw_box box;
    const sw_pack_viewpoint *views;
    uint32_t view_count;
    sw_nav_mode mode;
    int attract;                /* the transition is part of the tour */
    sw_vec3 eye;                /* walk */
    double yaw, pitch;
    double v_move, v_strafe, v_turn, v_look;  /* current rates, ramped */
    sw_vec3 centre;             /* orbit */
    double radius, azimuth, elevation;
    sw_camera_pose from, to;    /* transition */
    double t;                   /* seconds into the transition or the hold */
    int after_orbit;            /* a transition lands in orbit rather than walk */
    int view;                   /* current viewpoint, -1: none */
    double idle_s;
} sw_nav;

void sw_nav_init(sw_nav *nav, const sw_nav_params *p, const sw_camera_frame *frame,
                 const sw_box *box, const sw_pack_viewpoint *views, uint32_t view_count);

void sw_nav_step(sw_nav *nav, const sw_nav_input *in, double dt_s);

sw_camera_pose sw_nav_pose(const sw_nav *nav);

const char *sw_nav_mode_name(sw_nav_mode mode);

#endif
