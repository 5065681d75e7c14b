/* SPDX-License-Identifier: MIT */
/* Vectors, 4x4 matrices, axis-aligned boxes and the view frustum, in double.
 * Used by the geometry code on both sides and by the runtime's camera; the
 * renderer converts matrices to float at upload (sw_mat4_to_float). */
#ifndef SW_MATH_H
#define SW_MATH_H

#define SW_PI 3.14159265358979323846

typedef struct sw_vec3 { double x, y, z; } sw_vec3;
typedef struct sw_vec4 { double x, y, z, w; } sw_vec4;

/* Column-major, as GL expects: element (row r, column c) is m[c * 4 + r]. */
typedef struct sw_mat4 { double m[16]; } sw_mat4;

typedef struct sw_box { sw_vec3 min, max; } sw_box;

/* Six planes, inward normals: a point p is inside when dot(n, p) + d >= 0 for all. */
typedef struct sw_plane { sw_vec3 n; double d; } sw_plane;
typedef struct sw_frustum { sw_plane planes[6]; } sw_frustum;

typedef enum sw_cull { SW_CULL_OUTSIDE = 0, SW_CULL_INTERSECTS = 1, SW_CULL_INSIDE = 2 } sw_cull;

/* fmax and fmin inlined, with their answers (NaN: the other operand):
 * GCC calls libm's for them unless told NaN cannot occur, which this code
 * cannot be (it checks for NaN), and a pack build's error measures call
 * them in their innermost loops. */
static inline double sw_max(double a, double b) { return a >= b || b != b ? a : b; }
static inline double sw_min(double a, double b) { return a <= b || b != b ? a : b; }

sw_vec3 sw_v3(double x, double y, double z);
sw_vec3 sw_v3_add(sw_vec3 a, sw_vec3 b);
sw_vec3 sw_v3_sub(sw_vec3 a, sw_vec3 b);
sw_vec3 sw_v3_scale(sw_vec3 a, double s);
sw_vec3 sw_v3_lerp(sw_vec3 a, sw_vec3 b, double t);
double sw_v3_dot(sw_vec3 a, sw_vec3 b);
sw_vec3 sw_v3_cross(sw_vec3 a, sw_vec3 b);
double sw_v3_length(sw_vec3 a);
/* Distance from p to the segment a-b (to a when a == b). */
double sw_v3_segment_distance(sw_vec3 p, sw_vec3 a, sw_vec3 b);
/* a / |a|; the zero vector stays zero. */
sw_vec3 sw_v3_normalize(sw_vec3 a);

sw_mat4 sw_mat4_identity(void);
sw_mat4 sw_mat4_mul(const sw_mat4 *a, const sw_mat4 *b); /* a * b */
sw_vec4 sw_mat4_mul_v4(const sw_mat4 *m, sw_vec4 v);
sw_vec3 sw_mat4_transform_point(const sw_mat4 *m, sw_vec3 p); /* w = 1, divided by w' */
sw_mat4 sw_mat4_translate(sw_vec3 t);
sw_mat4 sw_mat4_scale(sw_vec3 s);
sw_mat4 sw_mat4_rotate(sw_vec3 axis, double angle_rad);
/* Right-handed look-at (camera looks down -z in eye space), as gluLookAt. */
sw_mat4 sw_mat4_look_at(sw_vec3 eye, sw_vec3 target, sw_vec3 up);
/* As gluPerspective: fovy in radians, depth mapped to [-1, 1]. */
sw_mat4 sw_mat4_perspective(double fovy_rad, double aspect, double near_z, double far_z);
void sw_mat4_to_float(const sw_mat4 *m, float out[16]);

sw_box sw_box_empty(void);                 /* min = +inf, max = -inf */
void sw_box_add_point(sw_box *box, sw_vec3 p);
void sw_box_add_box(sw_box *box, const sw_box *other);
int sw_box_is_empty(const sw_box *box);
sw_vec3 sw_box_center(const sw_box *box);
double sw_box_diagonal(const sw_box *box);
/* Distance from p to the nearest point of the box; 0 when p is inside. */
double sw_box_distance(const sw_box *box, sw_vec3 p);
/* The smallest and largest of dot(corner - eye, forward) over the box's 8
 * corners: its depth range along a view direction. One function for every
 * caller, so the culling hierarchy and the loops it replaces agree bit for
 * bit (core/sw_cull_tree.h). */
void sw_box_depth_range(const sw_box *box, sw_vec3 eye, sw_vec3 forward, double *lo, double *hi);

/* The smallest depth dot(p - eye, forward) over the points p of the box
 * inside the frustum's four side planes (planes 0-3; near and far are not
 * applied): where the box can be seen at all. INFINITY when no point of
 * the box is inside them; 0 when the eye is in the box. Exact up to
 * rounding: the smallest value lies at a vertex of the clipped box, and
 * every such vertex but the frustum's apex (the eye) is a vertex of a face
 * of the box clipped by the planes. */
double sw_box_visible_min_depth(const sw_box *box, const sw_frustum *f, sw_vec3 eye,
                                sw_vec3 forward);

/* Planes of the clip volume of view_proj (Gribb/Hartmann), normalised. */
sw_frustum sw_frustum_from_matrix(const sw_mat4 *view_proj);
sw_cull sw_frustum_test_box(const sw_frustum *f, const sw_box *box);

#endif
