/* SPDX-License-Identifier: MIT */
/* Camera path files: parsing, errors with file:line, interpolation through
 * the keys, smoothness, and the orbit. */
#include <string.h>

#include "sw_camera_path.h"
#include "sw_test.h"

static sw_status parse(const char *text, sw_camera_key *keys, size_t cap, sw_camera_path *p,
                       sw_error *err)
{
    return sw_camera_path_parse(text, strlen(text), "walk.path", keys, cap, p, err);
}

static const char *three_keys = "# a walk\n"
                                "0  0 1 10   0 0 0   0 1 0\n"
                                "\n"
                                "2  10 1 0   0 0 0   0 1 0  # quarter turn\n"
                                "3  0 1 -10  0 0 0   0 1 0\n";

static void test_parses_keys_and_skips_comments(void)
{
    sw_camera_key keys[8];
    sw_camera_path p;
    sw_error err;
    SW_CHECK(sw_camera_path_count_keys(three_keys, strlen(three_keys)) == 3);
    SW_CHECK(parse(three_keys, keys, 8, &p, &err) == SW_OK);
    SW_CHECK(p.key_count == 3);
    SW_CHECK(keys[1].time_s == 2.0 && keys[1].eye.x == 10.0 && keys[2].eye.z == -10.0);
    SW_CHECK(sw_camera_path_start(&p) == 0.0 && sw_camera_path_end(&p) == 3.0);
}

static void test_interpolation_passes_through_keys_and_holds_outside(void)
{
    sw_camera_key keys[8];
    sw_camera_path p;
    SW_CHECK(parse(three_keys, keys, 8, &p, NULL) == SW_OK);
    for (size_t k = 0; k < 3; k++) {
        sw_camera_pose pose = sw_camera_path_at(&p, keys[k].time_s);
        SW_CHECK_NEAR(pose.eye.x, keys[k].eye.x, 1e-12);
        SW_CHECK_NEAR(pose.eye.z, keys[k].eye.z, 1e-12);
    }
    sw_camera_pose before = sw_camera_path_at(&p, -5), after = sw_camera_path_at(&p, 50);
    SW_CHECK(before.eye.z == 10.0 && after.eye.z == -10.0);
}

static void test_interpolation_is_continuous_in_velocity(void)
{
    sw_camera_key keys[8];
    sw_camera_path p;
    SW_CHECK(parse(three_keys, keys, 8, &p, NULL) == SW_OK);
    double h = 1e-6;
    sw_vec3 l0 = sw_camera_path_at(&p, 2 - 2 * h).eye, l1 = sw_camera_path_at(&p, 2 - h).eye;
    sw_vec3 r0 = sw_camera_path_at(&p, 2 + h).eye, r1 = sw_camera_path_at(&p, 2 + 2 * h).eye;
    double vl = (l1.z - l0.z) / h, vr = (r1.z - r0.z) / h;
    SW_CHECK_NEAR(vl, vr, 1e-3 * (fabs(vl) + 1));
    sw_camera_pose mid = sw_camera_path_at(&p, 1.0);
    SW_CHECK_NEAR(sw_v3_length(mid.up), 1.0, 1e-12);
}

static void expect_error(const char *text, const char *fragment)
{
    sw_camera_key keys[4];
    sw_camera_path p;
    sw_error err = { SW_OK, "" };
    sw_status st = parse(text, keys, 4, &p, &err);
    SW_CHECK_MSG(st != SW_OK, "accepted: %s", text);
    SW_CHECK_MSG(strstr(err.message, fragment) != NULL, "message '%s' lacks '%s'", err.message,
                 fragment);
}

static void test_malformed_paths_name_line_and_problem(void)
{
    expect_error("", "no key frames");
    expect_error("# only a comment\n", "no key frames");
    expect_error("0 0 0 1 0 0 0 0 1\n", "walk.path:1: expected 10 numbers");
    expect_error("0 0 0 1 0 0 0 0 1 0 7\n", "found more than 10");
    expect_error("\n0 0 0 1 0 0 0 0 1 zero\n", "walk.path:2: expected numbers");
    expect_error("0 0 0 1 0 0 0 0 1 0\n0 0 0 2 0 0 0 0 1 0\n", "walk.path:2: time 0 does not");
    expect_error("0 1 1 1 1 1 1 0 1 0\n", "same point");
    expect_error("0 0 0 1 0 0 0 0 0 1\n", "parallel");
    expect_error("0 0 0 1 0 0 0 0 1 nan\n", "expected numbers");
    expect_error("0 0 0 1e999 0 0 0 0 1 0\n", "expected numbers");
    const char *five = "0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 0 0 0 1 0\n2 0 0 1 0 0 0 0 1 0\n"
                       "3 0 0 1 0 0 0 0 1 0\n4 0 0 1 0 0 0 0 1 0\n";
    expect_error(five, "more than 4 key frames");
}

static void test_unterminated_last_line_is_read(void)
{
    const char text[] = "0 0 0 5 0 0 0 0 1 0"; /* no newline */
    sw_camera_key keys[2];
    sw_camera_path p;
    SW_CHECK(sw_camera_path_parse(text, sizeof text - 1, "x", keys, 2, &p, NULL) == SW_OK);
    SW_CHECK(p.key_count == 1 && keys[0].eye.z == 5.0);
}

static void test_orbit_sees_whole_box_from_constant_distance(void)
{
    sw_box box = { sw_v3(-1, -2, -3), sw_v3(3, 2, 1) };
    sw_vec3 c = sw_box_center(&box);
    double fovy = 45 * SW_PI / 180, aspect = 16.0 / 9.0, d0 = -1;
    for (int i = 0; i < 16; i++) {
        sw_camera_pose pose = sw_camera_orbit(&box, fovy, aspect, i / 16.0);
        double d = sw_v3_length(sw_v3_sub(pose.eye, c));
        SW_CHECK_NEAR(d, d0 < 0 ? d : d0, 1e-9); /* the same distance all round */
        d0 = d;
        SW_CHECK(pose.eye.y > c.y);               /* looks down at the model */
        sw_mat4 view = sw_mat4_look_at(pose.eye, pose.target, pose.up);
        sw_mat4 proj = sw_mat4_perspective(fovy, aspect, 0.01, 100);
        sw_mat4 vp = sw_mat4_mul(&proj, &view);
        for (int k = 0; k < 8; k++) {             /* every corner projects inside */
            sw_vec4 q = sw_mat4_mul_v4(&vp, (sw_vec4){ k & 1 ? 3 : -1, k & 2 ? 2 : -2,
                                                       k & 4 ? 1 : -3, 1 });
            SW_CHECK(q.w > 0 && fabs(q.x / q.w) <= 1 && fabs(q.y / q.w) <= 1);
        }
    }
    sw_camera_pose a = sw_camera_orbit(&box, fovy, 1.0, 0.0), b = sw_camera_orbit(&box, fovy, 1.0, 0.5);
    SW_CHECK_NEAR(a.eye.x - c.x, -(b.eye.x - c.x), 1e-9);
    SW_CHECK_NEAR(a.eye.z - c.z, -(b.eye.z - c.z), 1e-9);
    /* For a flat showroom-like box, nearer than fitting the bounding sphere,
     * which would leave the model small in the picture. */
    sw_box flat = { sw_v3(-2, 0, -1), sw_v3(2, 0.5, 1) };
    sw_camera_pose f = sw_camera_orbit(&flat, fovy, aspect, 0.0);
    double sphere = 0.5 * sw_box_diagonal(&flat) / sin(fovy / 2);
    SW_CHECK(sw_v3_length(sw_v3_sub(f.eye, sw_box_center(&flat))) < 0.9 * sphere);
}

static void check_near_v3(sw_vec3 a, sw_vec3 b, double tol)
{
    SW_CHECK_NEAR(a.x, b.x, tol);
    SW_CHECK_NEAR(a.y, b.y, tol);
    SW_CHECK_NEAR(a.z, b.z, tol);
}

static void test_orbit_frames_are_turned_y_up_frames(void)
{
    const sw_vec3 ups[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 },
                             { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    for (int i = 0; i < 6; i++) {
        sw_camera_frame f = sw_camera_frame_for_up(ups[i]);
        check_near_v3(f.up, ups[i], 0);
        SW_CHECK_NEAR(sw_v3_length(f.right), 1, 1e-15);
        SW_CHECK_NEAR(sw_v3_length(f.front), 1, 1e-15);
        SW_CHECK(sw_v3_dot(f.right, f.up) == 0 && sw_v3_dot(f.front, f.up) == 0 &&
                 sw_v3_dot(f.right, f.front) == 0);
        check_near_v3(sw_v3_cross(f.right, f.up), f.front, 0); /* right-handed */
    }
    sw_camera_frame y = sw_camera_frame_for_up(sw_v3(0, 1, 0));
    check_near_v3(y.right, sw_v3(1, 0, 0), 0);
    check_near_v3(y.front, sw_v3(0, 0, 1), 0);
    sw_camera_frame z = sw_camera_frame_for_up(sw_v3(0, 0, 1));
    check_near_v3(z.right, sw_v3(1, 0, 0), 0);
    check_near_v3(z.front, sw_v3(0, -1, 0), 0); /* CAD's front view looks along +y */
}

/* Height / width of box's eight corners as the pose sees them. */
static double projected_aspect(const sw_box *box, sw_camera_pose pose, double fovy, double aspect)
{
    sw_mat4 view = sw_mat4_look_at(pose.eye, pose.target, pose.up);
    sw_mat4 proj = sw_mat4_perspective(fovy, aspect, 0.01, 1000);
    sw_mat4 vp = sw_mat4_mul(&proj, &view);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int k = 0; k < 8; k++) {
        sw_vec4 q = sw_mat4_mul_v4(&vp, (sw_vec4){ k & 1 ? box->max.x : box->min.x,
                                                   k & 2 ? box->max.y : box->min.y,
                                                   k & 4 ? box->max.z : box->min.z, 1 });
        double x = q.x / q.w * aspect, y = q.y / q.w;
        x0 = fmin(x0, x), x1 = fmax(x1, x), y0 = fmin(y0, y), y1 = fmax(y1, y);
    }
    return (y1 - y0) / (x1 - x0);
}

static void test_z_up_orbit_circles_z_and_shows_a_tall_box_tall(void)
{
    sw_box tall = { sw_v3(-1, -1, 0), sw_v3(1, 1, 8) }; /* a post standing on z = 0 */
    sw_vec3 c = sw_box_center(&tall);
    sw_camera_frame z = sw_camera_frame_for_up(sw_v3(0, 0, 1));
    double fovy = 45 * SW_PI / 180, aspect = 4.0 / 3.0, d = -1;
    for (int i = 0; i < 16; i++) {
        sw_camera_pose pose = sw_camera_orbit_in(&tall, &z, fovy, aspect, i / 16.0);
        check_near_v3(pose.up, sw_v3(0, 0, 1), 0);
        sw_vec3 rel = sw_v3_sub(pose.eye, c);
        double dist = sw_v3_length(rel);
        d = d < 0 ? dist : d;
        SW_CHECK_NEAR(dist, d, 1e-9);                              /* one circle */
        SW_CHECK_NEAR(rel.z, d * sin(25 * SW_PI / 180), 1e-9);     /* 25 degrees above */
        SW_CHECK(projected_aspect(&tall, pose, fovy, aspect) > 2); /* standing */
    }
    sw_camera_pose start = sw_camera_orbit_in(&tall, &z, fovy, aspect, 0);
    SW_CHECK(start.eye.y < c.y && fabs(start.eye.x - c.x) < 1e-9); /* from the front */
    /* The y-up orbit, the old view of every STEP part: from the side the
     * post lies across the picture. */
    sw_camera_pose side = sw_camera_orbit(&tall, fovy, aspect, 0.25);
    SW_CHECK(projected_aspect(&tall, side, fovy, aspect) < 0.5);
}

/* The y-up orbit is the one before packs had an up axis: from +z, turning
 * toward +x, 25 degrees above the xz plane. */
static void test_y_up_orbit_is_unchanged(void)
{
    sw_box box = { sw_v3(-1, -2, -3), sw_v3(3, 2, 1) };
    sw_vec3 c = sw_box_center(&box);
    const double el = 25 * SW_PI / 180;
    for (int i = 0; i < 8; i++) {
        double az = 2 * SW_PI * i / 8.0;
        sw_camera_pose a = sw_camera_orbit(&box, 0.8, 1.5, i / 8.0);
        sw_vec3 rel = sw_v3_sub(a.eye, c);
        double d = sw_v3_length(rel);
        check_near_v3(rel, sw_v3_scale(sw_v3(cos(el) * sin(az), sin(el), cos(el) * cos(az)), d),
                      1e-12 * d);
        check_near_v3(a.up, sw_v3(0, 1, 0), 0);
        check_near_v3(a.target, c, 0);
    }
}

int main(void)
{
    SW_RUN(test_parses_keys_and_skips_comments);
    SW_RUN(test_interpolation_passes_through_keys_and_holds_outside);
    SW_RUN(test_interpolation_is_continuous_in_velocity);
    SW_RUN(test_malformed_paths_name_line_and_problem);
    SW_RUN(test_unterminated_last_line_is_read);
    SW_RUN(test_orbit_sees_whole_box_from_constant_distance);
    SW_RUN(test_orbit_frames_are_turned_y_up_frames);
    SW_RUN(test_z_up_orbit_circles_z_and_shows_a_tall_box_tall);
    SW_RUN(test_y_up_orbit_is_unchanged);
    return sw_test_finish();
}
