/* SPDX-License-Identifier: MIT */
/* Navigation (sw_nav.h). Walk and orbit keep angles, not matrices, so the
 * state is small and steps are exact functions of their inputs. A
 * direction from yaw y and pitch p is cos p (cos y A + sin y R) + sin p U
 * with U the pack's up, R the frame's right and A = U x R. */
#include "sw_nav.h"

#include <math.h>

#define DEG (SW_PI / 180.0)

static uint32_t bit(sw_kiosk_action a) { return 1u << a; }

static sw_vec3 direction(const sw_nav *n, double yaw, double pitch)
{
    sw_vec3 h = sw_v3_add(sw_v3_scale(n->ahead, cos(yaw)), sw_v3_scale(n->frame.right, sin(yaw)));
    return sw_v3_add(sw_v3_scale(h, cos(pitch)), sw_v3_scale(n->frame.up, sin(pitch)));
}

static void angles_of(const sw_nav *n, sw_vec3 d, double *yaw, double *pitch)
{
    d = sw_v3_normalize(d);
    double u = sw_v3_dot(d, n->frame.up);
    *pitch = asin(u < -1 ? -1 : u > 1 ? 1 : u);
    *yaw = atan2(sw_v3_dot(d, n->frame.right), sw_v3_dot(d, n->ahead));
}

static double clamp(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }

/* The lowest the eye may go: the box's lowest corner along up, plus the
 * eye height. */
static double floor_height(const sw_nav *n)
{
    double lo = INFINITY;
    for (int c = 0; c < 8; c++) {
        sw_vec3 k = sw_v3(c & 1 ? n->box.max.x : n->box.min.x, c & 2 ? n->box.max.y : n->box.min.y,
                          c & 4 ? n->box.max.z : n->box.min.z);
        lo = fmin(lo, sw_v3_dot(k, n->frame.up));
    }
    return lo + n->p.eye_height_mm;
}

static sw_camera_pose home_pose(const sw_nav *n)
{
    if (n->view_count) {
        const sw_pack_viewpoint *v = &n->views[0];
        return (sw_camera_pose){sw_v3(v->eye[0], v->eye[1], v->eye[2]),
                                sw_v3(v->target[0], v->target[1], v->target[2]),
                                sw_v3_normalize(sw_v3(v->up[0], v->up[1], v->up[2]))};
    }
    return sw_camera_orbit_in(&n->box, &n->frame, n->p.fovy_rad, n->p.aspect, 0.0);
}

static sw_camera_pose view_pose(const sw_nav *n, int i)
{
    if (n->view_count == 0)
        return home_pose(n);
    const sw_pack_viewpoint *v = &n->views[i];
    return (sw_camera_pose){sw_v3(v->eye[0], v->eye[1], v->eye[2]),
                            sw_v3(v->target[0], v->target[1], v->target[2]),
                            sw_v3_normalize(sw_v3(v->up[0], v->up[1], v->up[2]))};
}

/* Walk from a pose: its eye and direction (the pose's own up is not kept:
 * walking is always upright). */
static void enter_walk(sw_nav *n, const sw_camera_pose *pose)
{
    n->mode = SW_NAV_MODE_WALK;
    n->eye = pose->eye;
    angles_of(n, sw_v3_sub(pose->target, pose->eye), &n->yaw, &n->pitch);
    n->pitch = clamp(n->pitch, -80 * DEG, 80 * DEG);
    n->v_move = n->v_strafe = n->v_turn = n->v_look = 0;
}

static void enter_orbit(sw_nav *n, const sw_camera_pose *pose)
{
    n->mode = SW_NAV_MODE_ORBIT;
    n->centre = n->view >= 0 && n->view_count ? view_pose(n, n->view).target
                                              : sw_box_center(&n->box);
    sw_vec3 off = sw_v3_sub(pose->eye, n->centre);
    n->radius = fmax(sw_v3_length(off), 1e-3);
    angles_of(n, off, &n->azimuth, &n->elevation);
    n->elevation = clamp(n->elevation, -85 * DEG, 85 * DEG);
    n->v_move = n->v_strafe = n->v_turn = n->v_look = 0;
}

static void start_transition(sw_nav *n, sw_camera_pose to, int attract)
{
    n->from = sw_nav_pose(n);
    n->to = to;
    /* The walk's target is a point far ahead; bring it to the destination's
     * distance so the glide turns the view evenly instead of swinging it. */
    double reach = sw_v3_length(sw_v3_sub(to.target, to.eye));
    sw_vec3 dir = sw_v3_normalize(sw_v3_sub(n->from.target, n->from.eye));
    n->from.target = sw_v3_add(n->from.eye, sw_v3_scale(dir, reach));
    n->after_orbit = n->mode == SW_NAV_MODE_ORBIT ||
                     (n->mode == SW_NAV_MODE_TRANSITION && n->after_orbit);
    n->mode = SW_NAV_MODE_TRANSITION;
    n->attract = attract;
    n->t = 0;
}

void sw_nav_init(sw_nav *n, const sw_nav_params *p, const sw_camera_frame *frame,
                 const sw_box *box, const sw_pack_viewpoint *views, uint32_t view_count)
{
    *n = (sw_nav){.p = *p, .frame = *frame, .box = *box, .views = views,
                  .view_count = view_count, .view = view_count ? 0 : -1};
    n->ahead = sw_v3_cross(frame->up, frame->right);
    sw_camera_pose home = home_pose(n);
    if (p->start_orbit)
        enter_orbit(n, &home);
    else
        enter_walk(n, &home);
}

/* Moves rate towards target by at most full / accel_s per second. */
static double ramp(double rate, double target, double full, const sw_nav *n, double dt)
{
    double step = full / n->p.accel_s * dt;
    return rate + clamp(target - rate, -step, step);
}

static void step_walk(sw_nav *n, const sw_nav_input *in, double dt)
{
    double speed = n->p.walk_speed_mm_s, turn = n->p.turn_speed_deg_s * DEG;
    n->v_move = ramp(n->v_move, in->move * speed, speed, n, dt);
    n->v_strafe = ramp(n->v_strafe, in->strafe * speed, speed, n, dt);
    n->v_turn = ramp(n->v_turn, in->turn * turn, turn, n, dt);
    n->v_look = ramp(n->v_look, in->look * turn, turn, n, dt);
    n->yaw = remainder(n->yaw + n->v_turn * dt, 2 * SW_PI);
    n->pitch = clamp(n->pitch + n->v_look * dt, -80 * DEG, 80 * DEG);
    sw_vec3 fwd = direction(n, n->yaw, 0), side = direction(n, n->yaw + SW_PI / 2, 0);
    n->eye = sw_v3_add(n->eye, sw_v3_add(sw_v3_scale(fwd, n->v_move * dt),
                                         sw_v3_scale(side, n->v_strafe * dt)));
    double below = floor_height(n) - sw_v3_dot(n->eye, n->frame.up);
    if (below > 0)
        n->eye = sw_v3_add(n->eye, sw_v3_scale(n->frame.up, below));
}

static void step_orbit(sw_nav *n, const sw_nav_input *in, double dt)
{
    double rate = n->p.orbit_speed_deg_s * DEG;
    n->v_turn = ramp(n->v_turn, in->turn * rate, rate, n, dt);
    n->v_look = ramp(n->v_look, in->look * rate, rate, n, dt);
    n->v_move = ramp(n->v_move, in->move, 1.0, n, dt);
    /* Turning right carries the camera to its right around the product. */
    n->azimuth = remainder(n->azimuth - n->v_turn * dt, 2 * SW_PI);
    n->elevation = clamp(n->elevation + n->v_look * dt, -85 * DEG, 85 * DEG);
    /* Forward halves the distance in a second at full deflection. */
    n->radius = fmax(n->radius * exp2(-n->v_move * dt), 1.0);
}

static void land(sw_nav *n)
{
    if (n->after_orbit)
        enter_orbit(n, &n->to);
    else
        enter_walk(n, &n->to);
}

static void step_transition(sw_nav *n, double dt)
{
    n->t += dt;
    if (n->t < n->p.transition_s)
        return;
    if (!n->attract) {
        land(n);
        return;
    }
    n->mode = SW_NAV_MODE_ATTRACT; /* hold the viewpoint */
    n->t = 0;
}

static void step_attract(sw_nav *n, double dt)
{
    n->t += dt;
    if (n->view_count == 0) { /* no viewpoints: a slow orbit */
        n->azimuth = remainder(n->azimuth + n->p.orbit_speed_deg_s * DEG * dt, 2 * SW_PI);
        return;
    }
    if (n->t >= n->p.attract_hold_s) {
        n->view = (n->view + 1) % (int)n->view_count;
        start_transition(n, view_pose(n, n->view), 1);
    }
}

static void begin_attract(sw_nav *n)
{
    if (n->view_count == 0) {
        sw_camera_pose pose = sw_nav_pose(n);
        enter_orbit(n, &pose);
        n->mode = SW_NAV_MODE_ATTRACT;
        n->attract = 1;
        return;
    }
    n->view = (n->view + 1) % (int)n->view_count;
    start_transition(n, view_pose(n, n->view), 1);
}

static void stop_attract(sw_nav *n)
{
    sw_camera_pose pose = sw_nav_pose(n);
    n->attract = 0;
    if (n->view_count == 0) {
        n->mode = SW_NAV_MODE_ORBIT;
        return;
    }
    enter_walk(n, &pose);
}

static void do_actions(sw_nav *n, uint32_t a)
{
    int count = (int)n->view_count;
    if (a & bit(SW_ACTION_ATTRACT)) {
        begin_attract(n);
        return;
    }
    if (a & bit(SW_ACTION_HOME)) {
        n->view = count ? 0 : -1;
        start_transition(n, home_pose(n), 0);
    } else if (a & (bit(SW_ACTION_NEXT_VIEW) | bit(SW_ACTION_PREV_VIEW))) {
        int d = a & bit(SW_ACTION_NEXT_VIEW) ? 1 : -1;
        n->view = count ? ((n->view < 0 ? 0 : n->view) + d + count) % count : -1;
        start_transition(n, view_pose(n, n->view < 0 ? 0 : n->view), 0);
    }
    if (a & bit(SW_ACTION_TOGGLE_MODE)) {
        sw_camera_pose pose = sw_nav_pose(n);
        if (n->mode == SW_NAV_MODE_ORBIT)
            enter_walk(n, &pose);
        else if (n->mode == SW_NAV_MODE_WALK)
            enter_orbit(n, &pose);
        else
            n->after_orbit = !n->after_orbit;
    }
}

void sw_nav_step(sw_nav *n, const sw_nav_input *in, double dt)
{
    int in_attract = n->attract;
    if (in->activity) {
        n->idle_s = 0;
        if (in_attract) {
            stop_attract(n);
            return; /* the input that ends the tour does nothing else */
        }
    } else {
        n->idle_s += dt;
    }
    /* idle_s is a sum of frame times: allow its rounding so that 300 frames
     * of 1/30 s are 10 s. */
    if (!in_attract && n->p.attract_timeout_s > 0 &&
        n->idle_s >= n->p.attract_timeout_s - 1e-9) {
        begin_attract(n);
        return;
    }
    if (in->actions)
        do_actions(n, in->actions);
    switch (n->mode) {
    case SW_NAV_MODE_WALK: step_walk(n, in, dt); break;
    case SW_NAV_MODE_ORBIT: step_orbit(n, in, dt); break;
    case SW_NAV_MODE_TRANSITION: step_transition(n, dt); break;
    case SW_NAV_MODE_ATTRACT: step_attract(n, dt); break;
    }
}

static sw_camera_pose orbit_pose(const sw_nav *n);

sw_camera_pose sw_nav_pose(const sw_nav *n)
{
    switch (n->mode) {
    case SW_NAV_MODE_WALK: {
        sw_vec3 d = direction(n, n->yaw, n->pitch);
        return (sw_camera_pose){n->eye, sw_v3_add(n->eye, sw_v3_scale(d, 1000.0)), n->frame.up};
    }
    case SW_NAV_MODE_TRANSITION: {
        double s = clamp(n->t / n->p.transition_s, 0, 1);
        s = s * s * (3 - 2 * s);
        sw_vec3 up = sw_v3_normalize(sw_v3_lerp(n->from.up, n->to.up, s));
        if (sw_v3_length(up) < 0.5)
            up = n->frame.up;
        return (sw_camera_pose){sw_v3_lerp(n->from.eye, n->to.eye, s),
                                sw_v3_lerp(n->from.target, n->to.target, s), up};
    }
    case SW_NAV_MODE_ATTRACT:
        if (n->view_count)
            return n->to;
        return orbit_pose(n); /* no viewpoints: the slow orbit */
    case SW_NAV_MODE_ORBIT:
    default:
        return orbit_pose(n);
    }
}

static sw_camera_pose orbit_pose(const sw_nav *n)
{
    {
        sw_vec3 eye = sw_v3_add(n->centre, sw_v3_scale(direction(n, n->azimuth, n->elevation),
                                                       n->radius));
        return (sw_camera_pose){eye, n->centre, n->frame.up};
    }
}

const char *sw_nav_mode_name(sw_nav_mode mode)
{
    static const char *const names[] = {"walk", "orbit", "transition", "attract"};
    return (unsigned)mode < 4 ? names[mode] : "?";
}
