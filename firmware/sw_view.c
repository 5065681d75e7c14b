#include "sw_view.h"

#include <math.h>

double sw_view_depth(const sw_view *v, sw_vec3 p)
{
    return sw_v3_dot(sw_v3_sub(p, v->eye), v->forward);
}

static void box_depth_range(const sw_view *v, const sw_box *b, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < 8; i++) {
        sw_vec3 c = sw_v3(i & 1 ? b->max.x : b->min.x, i & 2 ? b->max.y : b->min.y,
                          i & 4 ? b->max.z : b->min.z);
        double d = sw_view_depth(v, c);
        *lo = d < *lo ? d : *lo;
        *hi = d > *hi ? d : *hi;
    }
}

sw_view sw_view_make(const sw_camera_pose *pose, double fovy_rad, int width, int height,
                     const sw_box *model_box)
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
    v.far_z = hi > 0 ? hi * 1.01 : 1.0;
    v.near_z = lo * 0.99;
    if (v.near_z < v.far_z / 2000.0)
        v.near_z = v.far_z / 2000.0;
    v.view = sw_mat4_look_at(pose->eye, pose->target, pose->up);
    v.proj = sw_mat4_perspective(fovy_rad, (double)width / height, v.near_z, v.far_z);
    v.view_proj = sw_mat4_mul(&v.proj, &v.view);
    v.frustum = sw_frustum_from_matrix(&v.view_proj);
    return v;
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
