/* SPDX-License-Identifier: MIT */
/* Camera paths for walks: timed key frames read from a text file, interpolated
 * smoothly, and the orbit around a model. Called by the runtime at start-up
 * (parsing, into caller memory) and every frame (evaluation, no allocation).
 *
 * Path file format (text, UTF-8/ASCII):
 *   - '#' starts a comment to the end of the line; blank lines are ignored;
 *   - every other line is one key frame of ten numbers separated by spaces or
 *     tabs:  time_s  eye_x eye_y eye_z  target_x target_y target_z  up_x up_y up_z
 *   - times strictly increase; at least one key; eye != target; up not zero and
 *     not parallel to the view direction;
 *   - at most SW_CAMERA_PATH_MAX_KEYS keys.
 * Between keys, eye and target follow Catmull-Rom splines with tangents
 * from the neighbouring keys scaled for uneven spacing (C1 in time), and up is
 * interpolated the same way and renormalised. Before the first key and after
 * the last the camera holds still.
 *
 * Frame: eye, target and up are world coordinates, which are the pack's model
 * coordinates as stored (millimetres); the pack's up axis (sw_up_axis.h) does
 * not rotate them. For a z-up pack (a STEP or IGES part) give up = 0 0 1. */
#ifndef SW_CAMERA_PATH_H
#define SW_CAMERA_PATH_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_math.h"

#define SW_CAMERA_PATH_MAX_KEYS 100000

typedef struct sw_camera_key {
    double time_s;
    sw_vec3 eye, target, up;
} sw_camera_key;

typedef struct sw_camera_path {
    sw_camera_key *keys;   /* caller-owned */
    size_t key_count;
} sw_camera_path;

typedef struct sw_camera_pose {
    sw_vec3 eye, target, up;
} sw_camera_pose;

/* Number of key lines in text (an upper bound when the text is malformed), so
 * the caller can size the key array before parsing. */
size_t sw_camera_path_count_keys(const char *text, size_t size);

/* Parses text (not NUL-terminated) into keys[0..capacity). file_name is used
 * in messages ("walk.path:7: expected 10 numbers, found 9"). */
sw_status sw_camera_path_parse(const char *text, size_t size, const char *file_name,
                               sw_camera_key *keys, size_t capacity, sw_camera_path *out,
                               sw_error *err);

double sw_camera_path_start(const sw_camera_path *path);
double sw_camera_path_end(const sw_camera_path *path);
sw_camera_pose sw_camera_path_at(const sw_camera_path *path, double time_s);

/* The world's directions for the orbit: up, and two horizontal ones, right
 * and front (right x up = front), where the orbit starts. */
typedef struct sw_camera_frame {
    sw_vec3 right, up, front;
} sw_camera_frame;

/* The frame for a unit axis-aligned up (sw_up_axis_vector): y up gives
 * right +x, front +z; z up (CAD) right +x, front -y, the usual front view;
 * every other frame is the y-up one rotated so that +y lands on up. */
sw_camera_frame sw_camera_frame_for_up(sw_vec3 up);

/* A circle around box's centre, 25 degrees above the horizon (the plane
 * across frame->up), starting on frame->front, at one distance for the
 * whole circle: the nearest at which every corner of the box is in view from
 * every point of it, plus 8%. The camera's up is frame->up. turn in [0, 1)
 * is the fraction of the revolution. */
sw_camera_pose sw_camera_orbit_in(const sw_box *box, const sw_camera_frame *frame,
                                  double fovy_rad, double aspect, double turn);

/* The orbit with y up (sw_camera_orbit_in with sw_camera_frame_for_up(+y)). */
sw_camera_pose sw_camera_orbit(const sw_box *box, double fovy_rad, double aspect, double turn);

#endif
