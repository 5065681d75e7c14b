/* SPDX-License-Identifier: MIT */
#include "sw_math.h"

#include <math.h>

sw_vec3 sw_v3(double x, double y, double z)
{
    sw_vec3 r = {x, y, z};
    return r;
}

sw_vec3 sw_v3_add(sw_vec3 a, sw_vec3 b) { return sw_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
sw_vec3 sw_v3_sub(sw_vec3 a, sw_vec3 b) { return sw_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
sw_vec3 sw_v3_scale(sw_vec3 a, double s) { return sw_v3(a.x * s, a.y * s, a.z * s); }
double sw_v3_dot(sw_vec3 a, sw_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double sw_v3_length(sw_vec3 a) { return sqrt(sw_v3_dot(a, a)); }

double sw_v3_segment_distance(sw_vec3 p, sw_vec3 a, sw_vec3 b)
{
    sw_vec3 ab = sw_v3_sub(b, a);
    double len2 = sw_v3_dot(ab, ab);
    double t = len2 > 0 ? sw_v3_dot(sw_v3_sub(p, a), ab) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return sw_v3_length(sw_v3_sub(p, sw_v3_add(a, sw_v3_scale(ab, t))));
}

sw_vec3 sw_v3_lerp(sw_vec3 a, sw_vec3 b, double t)
{
    /* (1 - t) a + t b rather than a + t (b - a): exact at both ends. */
    return sw_v3((1 - t) * a.x + t * b.x, (1 - t) * a.y + t * b.y, (1 - t) * a.z + t * b.z);
}

sw_vec3 sw_v3_cross(sw_vec3 a, sw_vec3 b)
{
    return sw_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

sw_vec3 sw_v3_normalize(sw_vec3 a)
{
    double len = sw_v3_length(a);
    if (!(len > 0))
        return sw_v3(0, 0, 0);
    return sw_v3_scale(a, 1.0 / len);
}

sw_mat4 sw_mat4_identity(void)
{
    sw_mat4 r = {{0}};
    r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1;
    return r;
}

sw_mat4 sw_mat4_mul(const sw_mat4 *a, const sw_mat4 *b)
{
    sw_mat4 r;
    for (int c = 0; c < 4; c++) {
        for (int row = 0; row < 4; row++) {
            double s = 0;
            for (int k = 0; k < 4; k++)
                s += a->m[k * 4 + row] * b->m[c * 4 + k];
            r.m[c * 4 + row] = s;
        }
    }
    return r;
}

sw_vec4 sw_mat4_mul_v4(const sw_mat4 *m, sw_vec4 v)
{
    const double *a = m->m;
    sw_vec4 r;
    r.x = a[0] * v.x + a[4] * v.y + a[8] * v.z + a[12] * v.w;
    r.y = a[1] * v.x + a[5] * v.y + a[9] * v.z + a[13] * v.w;
    r.z = a[2] * v.x + a[6] * v.y + a[10] * v.z + a[14] * v.w;
    r.w = a[3] * v.x + a[7] * v.y + a[11] * v.z + a[15] * v.w;
    return r;
}

sw_vec3 sw_mat4_transform_point(const sw_mat4 *m, sw_vec3 p)
{
    sw_vec4 h = {p.x, p.y, p.z, 1};
    sw_vec4 r = sw_mat4_mul_v4(m, h);
    return sw_v3(r.x / r.w, r.y / r.w, r.z / r.w);
}

sw_mat4 sw_mat4_translate(sw_vec3 t)
{
    sw_mat4 r = sw_mat4_identity();
    r.m[12] = t.x;
    r.m[13] = t.y;
    r.m[14] = t.z;
    return r;
}

sw_mat4 sw_mat4_scale(sw_vec3 s)
{
    sw_mat4 r = sw_mat4_identity();
    r.m[0] = s.x;
    r.m[5] = s.y;
    r.m[10] = s.z;
    return r;
}

/* Counter-clockwise about axis (right-hand rule), the matrix of glRotate. */
sw_mat4 sw_mat4_rotate(sw_vec3 axis, double angle_rad)
{
    sw_vec3 a = sw_v3_normalize(axis);
    double c = cos(angle_rad), s = sin(angle_rad), k = 1 - c;
    sw_mat4 r = sw_mat4_identity();
    r.m[0] = a.x * a.x * k + c;
    r.m[1] = a.y * a.x * k + a.z * s;
    r.m[2] = a.z * a.x * k - a.y * s;
    r.m[4] = a.x * a.y * k - a.z * s;
    r.m[5] = a.y * a.y * k + c;
    r.m[6] = a.z * a.y * k + a.x * s;
    r.m[8] = a.x * a.z * k + a.y * s;
    r.m[9] = a.y * a.z * k - a.x * s;
    r.m[10] = a.z * a.z * k + c;
    return r;
}

sw_mat4 sw_mat4_look_at(sw_vec3 eye, sw_vec3 target, sw_vec3 up)
{
    sw_vec3 f = sw_v3_normalize(sw_v3_sub(target, eye));
    sw_vec3 s = sw_v3_normalize(sw_v3_cross(f, up));
    sw_vec3 u = sw_v3_cross(s, f);
    sw_mat4 r = sw_mat4_identity();
    /* Rows s, u, -f: the eye basis; then the eye moved to the origin. */
    r.m[0] = s.x;
    r.m[4] = s.y;
    r.m[8] = s.z;
    r.m[1] = u.x;
    r.m[5] = u.y;
    r.m[9] = u.z;
    r.m[2] = -f.x;
    r.m[6] = -f.y;
    r.m[10] = -f.z;
    r.m[12] = -sw_v3_dot(s, eye);
    r.m[13] = -sw_v3_dot(u, eye);
    r.m[14] = sw_v3_dot(f, eye);
    return r;
}

sw_mat4 sw_mat4_perspective(double fovy_rad, double aspect, double near_z, double far_z)
{
    double f = 1.0 / tan(fovy_rad * 0.5);
    sw_mat4 r = {{0}};
    r.m[0] = f / aspect;
    r.m[5] = f;
    r.m[10] = (far_z + near_z) / (near_z - far_z);
    r.m[11] = -1;
    r.m[14] = 2 * far_z * near_z / (near_z - far_z);
    return r;
}

void sw_mat4_to_float(const sw_mat4 *m, float out[16])
{
    for (int i = 0; i < 16; i++)
        out[i] = (float)m->m[i];
}

sw_box sw_box_empty(void)
{
    sw_box b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    return b;
}

void sw_box_add_point(sw_box *box, sw_vec3 p)
{
    box->min.x = sw_min(box->min.x, p.x);
    box->min.y = sw_min(box->min.y, p.y);
    box->min.z = sw_min(box->min.z, p.z);
    box->max.x = sw_max(box->max.x, p.x);
    box->max.y = sw_max(box->max.y, p.y);
    box->max.z = sw_max(box->max.z, p.z);
}

void sw_box_add_box(sw_box *box, const sw_box *other)
{
    if (sw_box_is_empty(other))
        return;
    sw_box_add_point(box, other->min);
    sw_box_add_point(box, other->max);
}

void sw_box_depth_range(const sw_box *b, sw_vec3 eye, sw_vec3 forward, double *lo, double *hi)
{
    /* Each axis' term (c - eye) * forward is monotone in c and so is their
     * sum, rounding included: the corner taking each axis' smaller term
     * gives exactly the smallest of the 8 corners' values, the other
     * corner the largest (two dot products instead of eight). */
    sw_vec3 near_c = sw_v3(forward.x >= 0 ? b->min.x : b->max.x, forward.y >= 0 ? b->min.y : b->max.y,
                           forward.z >= 0 ? b->min.z : b->max.z);
    sw_vec3 far_c = sw_v3(forward.x >= 0 ? b->max.x : b->min.x, forward.y >= 0 ? b->max.y : b->min.y,
                          forward.z >= 0 ? b->max.z : b->min.z);
    *lo = sw_v3_dot(sw_v3_sub(near_c, eye), forward);
    *hi = sw_v3_dot(sw_v3_sub(far_c, eye), forward);
}

/* Polygon in[0 .. n) clipped to the side of plane p where dot(n, x) + d >= 0,
 * into out; returns its vertex count (at most n + 1). */
static int clip_polygon(const sw_vec3 *in, int n, const sw_plane *p, sw_vec3 *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        sw_vec3 a = in[i], b = in[(i + 1) % n];
        double da = sw_v3_dot(p->n, a) + p->d, db = sw_v3_dot(p->n, b) + p->d;
        if (da >= 0)
            out[m++] = a;
        if ((da >= 0) != (db >= 0))
            out[m++] = sw_v3_lerp(a, b, da / (da - db));
    }
    return m;
}

double sw_box_visible_min_depth(const sw_box *box, const sw_frustum *f, sw_vec3 eye,
                                sw_vec3 forward)
{
    if (sw_box_is_empty(box))
        return INFINITY;
    if (eye.x >= box->min.x && eye.x <= box->max.x && eye.y >= box->min.y &&
        eye.y <= box->max.y && eye.z >= box->min.z && eye.z <= box->max.z)
        return 0.0;
    /* A box inside all four sides clips to itself: its nearest corner,
     * found as sw_box_depth_range finds it (most boxes of a far view). */
    int inside = 1;
    for (int i = 0; i < 4 && inside; i++) {
        const sw_plane *p = &f->planes[i];
        sw_vec3 c = sw_v3(p->n.x >= 0 ? box->min.x : box->max.x,
                          p->n.y >= 0 ? box->min.y : box->max.y,
                          p->n.z >= 0 ? box->min.z : box->max.z);
        inside = sw_v3_dot(p->n, c) + p->d >= 0;
    }
    if (inside) {
        double near_depth, far_depth;
        sw_box_depth_range(box, eye, forward, &near_depth, &far_depth);
        return near_depth;
    }
    const double lo[3] = { box->min.x, box->min.y, box->min.z };
    const double hi[3] = { box->max.x, box->max.y, box->max.z };
    double best = INFINITY;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            /* The face at lo or hi on axis, its corners in order round it. */
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            sw_vec3 poly[2][8];
            for (int k = 0; k < 4; k++) {
                double c[3];
                c[axis] = side ? hi[axis] : lo[axis];
                c[a] = (k == 1 || k == 2) ? hi[a] : lo[a];
                c[b] = (k >= 2) ? hi[b] : lo[b];
                poly[0][k] = sw_v3(c[0], c[1], c[2]);
            }
            int n = 4, cur = 0;
            for (int i = 0; i < 4 && n > 0; i++, cur ^= 1)
                n = clip_polygon(poly[cur], n, &f->planes[i], poly[cur ^ 1]);
            for (int k = 0; k < n; k++)
                best = fmin(best, sw_v3_dot(sw_v3_sub(poly[cur][k], eye), forward));
        }
    return best;
}

int sw_box_is_empty(const sw_box *box)
{
    return !(box->min.x <= box->max.x && box->min.y <= box->max.y && box->min.z <= box->max.z);
}

sw_vec3 sw_box_center(const sw_box *box) { return sw_v3_lerp(box->min, box->max, 0.5); }

double sw_box_diagonal(const sw_box *box)
{
    if (sw_box_is_empty(box))
        return 0;
    return sw_v3_length(sw_v3_sub(box->max, box->min));
}

double sw_box_distance(const sw_box *box, sw_vec3 p)
{
    double dx = fmax(fmax(box->min.x - p.x, p.x - box->max.x), 0);
    double dy = fmax(fmax(box->min.y - p.y, p.y - box->max.y), 0);
    double dz = fmax(fmax(box->min.z - p.z, p.z - box->max.z), 0);
    return sqrt(dx * dx + dy * dy + dz * dz);
}

static sw_plane plane_from_rows(const sw_mat4 *m, int row, double sign)
{
    /* Row r of a column-major matrix is m[r], m[4 + r], m[8 + r], m[12 + r]. */
    const double *a = m->m;
    double nx = a[3] + sign * a[row], ny = a[7] + sign * a[4 + row];
    double nz = a[11] + sign * a[8 + row], d = a[15] + sign * a[12 + row];
    double len = sqrt(nx * nx + ny * ny + nz * nz);
    double inv = len > 0 ? 1.0 / len : 0;
    sw_plane p = {{nx * inv, ny * inv, nz * inv}, d * inv};
    return p;
}

/* Gribb & Hartmann, "Fast extraction of viewing frustum planes": clip-space
 * -w <= x, y, z <= w becomes row3 +- row_k in world space. */
sw_frustum sw_frustum_from_matrix(const sw_mat4 *view_proj)
{
    sw_frustum f;
    for (int k = 0; k < 3; k++) {
        f.planes[2 * k] = plane_from_rows(view_proj, k, 1);
        f.planes[2 * k + 1] = plane_from_rows(view_proj, k, -1);
    }
    return f;
}

sw_cull sw_frustum_test_box(const sw_frustum *f, const sw_box *box)
{
    if (sw_box_is_empty(box))
        return SW_CULL_OUTSIDE;
    sw_cull result = SW_CULL_INSIDE;
    for (int i = 0; i < 6; i++) {
        const sw_plane *p = &f->planes[i];
        /* The box corner farthest along the normal decides "outside", the
         * nearest one decides "partly outside". */
        sw_vec3 far_c = sw_v3(p->n.x >= 0 ? box->max.x : box->min.x,
                              p->n.y >= 0 ? box->max.y : box->min.y,
                              p->n.z >= 0 ? box->max.z : box->min.z);
        sw_vec3 near_c = sw_v3(p->n.x >= 0 ? box->min.x : box->max.x,
                               p->n.y >= 0 ? box->min.y : box->max.y,
                               p->n.z >= 0 ? box->min.z : box->max.z);
        if (sw_v3_dot(p->n, far_c) + p->d < 0)
            return SW_CULL_OUTSIDE;
        if (sw_v3_dot(p->n, near_c) + p->d < 0)
            result = SW_CULL_INTERSECTS;
    }
    return result;
}
