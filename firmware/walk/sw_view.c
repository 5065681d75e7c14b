/* SPDX-License-Identifier: MIT */
#include "sw_view.h"

#include <math.h>

double sw_view_depth(const sw_view *v, sw_vec3 p)
{
    return sw_v3_dot(sw_v3_sub(p, v->eye), v->forward);
}

static void box_depth_range(const sw_view *v, const sw_box *b, double *lo, double *hi)
{
    sw_box_depth_range(b, v->eye, v->forward, lo, hi);
}

/* The nearest near plane the depth buffer affords: with far / near = F a
 * depth buffer of b bits resolves about depth^2 F / (far 2^b) near the far
 * plane; F = 2000 kept 16 bits usable, so 24 bits afford 256 times as much. */
static double near_floor(double far_z, int depth_bits)
{
    int extra = depth_bits > 16 ? depth_bits - 16 : 0;
    return far_z / (2000.0 * exp2(extra));
}

static void set_clip(sw_view *v, double near_z, double far_z)
{
    v->near_z = near_z;
    v->far_z = far_z;
    v->proj = sw_mat4_perspective(v->fovy_rad, (double)v->width / v->height, near_z, far_z);
    v->view_proj = sw_mat4_mul(&v->proj, &v->view);
    v->frustum = sw_frustum_from_matrix(&v->view_proj);
}

sw_view sw_view_make(const sw_camera_pose *pose, double fovy_rad, int width, int height,
                     const sw_box *model_box)
{
    return sw_view_make_depth(pose, fovy_rad, width, height, model_box, 16);
}

sw_view sw_view_make_depth(const sw_camera_pose *pose, double fovy_rad, int width, int height,
                           const sw_box *model_box, int depth_bits)
{
    sw_view v;
    v.eye = pose->eye;
    v.forward = sw_v3_normalize(sw_v3_sub(pose->target, pose->eye));
    v.fovy_rad = fovy_rad;
    v.width = width;
    v.height = height;
    v.px_per_unit = height / (2.0 * tan(0.5 * fovy_rad));
    double lo, hi;
    box_depth_range(&v, model_box, &lo, &hi);
    double far_z = hi > 0 ? hi * 1.01 : 1.0;
    v.view = sw_mat4_look_at(pose->eye, pose->target, pose->up);
    set_clip(&v, fmax(lo * 0.99, near_floor(far_z, depth_bits)), far_z);
    return v;
}

sw_view sw_view_fit_depth(const sw_view *v, double nearest, double farthest, int depth_bits)
{
    sw_view fitted = *v;
    if (!(nearest <= farthest) || !(farthest > 0))
        return fitted;
    double far_z = fmin(farthest * 1.01, v->far_z);
    double near_z = fmax(nearest * 0.99, near_floor(far_z, depth_bits));
    if (near_z >= far_z)
        return fitted;
    set_clip(&fitted, near_z, far_z);
    return fitted;
}

double sw_view_box_min_depth(const sw_view *v, const sw_box *box)
{
    double lo, hi;
    box_depth_range(v, box, &lo, &hi);
    return lo > v->near_z ? lo : v->near_z;
}

double sw_view_error_world(const sw_view *v, double error_px, double depth)
{
    return error_px * depth / v->px_per_unit;
}
