/* SPDX-License-Identifier: MIT */
/* One frame's view: camera matrices, frustum, clip planes fitted to the model,
 * and the screen-space error rule. Computed once per frame by the frame loop;
 * pure math, no GL. */
#ifndef SW_VIEW_H
#define SW_VIEW_H

#include "sw_camera_path.h"
#include "sw_math.h"

typedef struct sw_view {
    sw_vec3 eye, forward;         /* forward: unit view direction */
    sw_mat4 view, proj, view_proj;
    sw_frustum frustum;
    double near_z, far_z;
    double fovy_rad;
    int width, height;
    /* Pixels covered by one unit of length at eye-space depth 1: an object of
     * size s at depth z spans s * px_per_unit / z pixels. */
    double px_per_unit;
} sw_view;

/* Near and far are fitted to model_box so a 16-bit depth buffer keeps its
 * precision: far just past the farthest box corner, near at the nearest
 * corner's depth but never below far / 2000. The camera's up is pose->up
 * (the orbit's is the pack's up axis); no model-to-world rotation is
 * applied, so the frustum, the culling and the error measure all work in
 * the pack's coordinates, the ones that are drawn. */
sw_view sw_view_make(const sw_camera_pose *pose, double fovy_rad, int width, int height,
                     const sw_box *model_box);

/* The same for a depth buffer of depth_bits (16 or more): near never below
 * far / (2000 * 2^(depth_bits - 16)), each bit past 16 doubling the depth
 * range the buffer resolves as well as 16 bits did 2000. */
sw_view sw_view_make_depth(const sw_camera_pose *pose, double fovy_rad, int width, int height,
                           const sw_box *model_box, int depth_bits);

/* v with near and far fitted to what the frame draws: the nearest depth of
 * a drawn box and its farthest corner (the seam walk's visible surfaces,
 * sw_seam_depth.h), with the same margins and near floor as
 * sw_view_make_depth. Far never grows past v's, so nothing culled against
 * v's frustum comes back. v itself when the range is empty or invalid. */
sw_view sw_view_fit_depth(const sw_view *v, double nearest, double farthest, int depth_bits);

/* Eye-space depth of p (distance along forward). */
double sw_view_depth(const sw_view *v, sw_vec3 p);

/* Smallest eye-space depth of the box's corners, clamped to near_z: every
 * visible point of the box is at least this deep. */
double sw_view_box_min_depth(const sw_view *v, const sw_box *box);

/* The object-space error that projects to error_px pixels at depth (paper
 * 004, section 6.1: half a pixel by default). The paper uses the Euclidean
 * distance to the box; we use eye-space depth, which is what perspective
 * divides by, so the bound also holds off the view axis. */
double sw_view_error_world(const sw_view *v, double error_px, double depth);

#endif
