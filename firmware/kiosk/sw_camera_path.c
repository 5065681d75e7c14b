/* SPDX-License-Identifier: MIT */
#include "sw_camera_path.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct line_cursor {
    const char *text;
    size_t size, pos;
    size_t line_no;
} line_cursor;

/* Next line without its comment, as [*begin, *end); 0 at the end of text. */
static int next_line(line_cursor *c, const char **begin, const char **end)
{
    if (c->pos >= c->size)
        return 0;
    const char *start = c->text + c->pos;
    const char *stop = memchr(start, '\n', c->size - c->pos);
    size_t len = stop ? (size_t)(stop - start) : c->size - c->pos;
    c->pos += len + (stop ? 1 : 0);
    c->line_no++;
    const char *hash = memchr(start, '#', len);
    *begin = start;
    *end = hash ? hash : start + len;
    return 1;
}

static int is_space(char ch) { return ch == ' ' || ch == '\t' || ch == '\r'; }

static int is_blank(const char *b, const char *e)
{
    for (; b < e; b++)
        if (!is_space(*b))
            return 0;
    return 1;
}

size_t sw_camera_path_count_keys(const char *text, size_t size)
{
    line_cursor c = { text, size, 0, 0 };
    const char *b, *e;
    size_t n = 0;
    while (next_line(&c, &b, &e))
        n += !is_blank(b, e);
    return n;
}

/* Reads up to max numbers from [b, e) into out; returns how many, or -1 when a
 * token is not a finite number. strtod needs a terminated string, so each
 * token is copied into a bounded buffer first. */
static int parse_numbers(const char *b, const char *e, double *out, int max)
{
    int n = 0;
    while (b < e) {
        while (b < e && is_space(*b))
            b++;
        if (b == e)
            break;
        const char *tok = b;
        while (b < e && !is_space(*b))
            b++;
        char buf[64];
        size_t len = (size_t)(b - tok);
        if (len >= sizeof buf || n == max)
            return n == max ? max + 1 : -1;
        memcpy(buf, tok, len);
        buf[len] = '\0';
        char *stop;
        double v = strtod(buf, &stop);
        if (*stop != '\0' || !isfinite(v))
            return -1;
        out[n++] = v;
    }
    return n;
}

static sw_status check_key(const sw_camera_key *k, const char *file, size_t line, sw_error *err)
{
    sw_vec3 dir = sw_v3_sub(k->target, k->eye);
    if (sw_v3_length(dir) == 0.0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: eye and target are the same point",
                            file, line);
    sw_vec3 side = sw_v3_cross(sw_v3_normalize(dir), sw_v3_normalize(k->up));
    if (sw_v3_length(side) < 1e-6)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "%s:%zu: up must be non-zero and not parallel to the view direction",
                            file, line);
    return SW_OK;
}

sw_status sw_camera_path_parse(const char *text, size_t size, const char *file_name,
                               sw_camera_key *keys, size_t capacity, sw_camera_path *out,
                               sw_error *err)
{
    line_cursor c = { text, size, 0, 0 };
    const char *b, *e;
    size_t n = 0;
    while (next_line(&c, &b, &e)) {
        if (is_blank(b, e))
            continue;
        double v[10];
        int got = parse_numbers(b, e, v, 10);
        if (got < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "%s:%zu: expected numbers, found text",
                                file_name, c.line_no);
        if (got != 10)
            return sw_error_set(err, SW_ERR_FORMAT,
                                "%s:%zu: expected 10 numbers (time eye target up), found %s%d",
                                file_name, c.line_no, got > 10 ? "more than " : "",
                                got > 10 ? 10 : got);
        if (n == capacity || n == SW_CAMERA_PATH_MAX_KEYS)
            return sw_error_set(err, SW_ERR_RANGE, "%s:%zu: more than %zu key frames", file_name,
                                c.line_no, capacity < SW_CAMERA_PATH_MAX_KEYS ? capacity
                                                                            : (size_t)SW_CAMERA_PATH_MAX_KEYS);
        sw_camera_key k = { v[0], sw_v3(v[1], v[2], v[3]), sw_v3(v[4], v[5], v[6]),
                            sw_v3(v[7], v[8], v[9]) };
        if (n > 0 && !(k.time_s > keys[n - 1].time_s))
            return sw_error_set(err, SW_ERR_FORMAT,
                                "%s:%zu: time %g does not increase (previous key at %g)",
                                file_name, c.line_no, k.time_s, keys[n - 1].time_s);
        sw_status st = check_key(&k, file_name, c.line_no, err);
        if (st != SW_OK)
            return st;
        keys[n++] = k;
    }
    if (n == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: no key frames (expected lines of 10 numbers)",
                            file_name);
    out->keys = keys;
    out->key_count = n;
    return SW_OK;
}

double sw_camera_path_start(const sw_camera_path *path) { return path->keys[0].time_s; }
double sw_camera_path_end(const sw_camera_path *path)
{
    return path->keys[path->key_count - 1].time_s;
}

/* Cubic Hermite on [t1, t2] with Catmull-Rom tangents that account for uneven
 * key spacing: m_k = (p_{k+1} - p_{k-1}) / (t_{k+1} - t_{k-1}), one-sided at
 * the ends. Gives a C1 path in time, so the speed does not jump at keys. */
static sw_vec3 hermite(sw_vec3 p0, sw_vec3 p1, sw_vec3 p2, sw_vec3 p3, double t0, double t1,
                       double t2, double t3, double s)
{
    double h = t2 - t1;
    sw_vec3 m1 = sw_v3_scale(sw_v3_sub(p2, p0), h / (t2 - t0));
    sw_vec3 m2 = sw_v3_scale(sw_v3_sub(p3, p1), h / (t3 - t1));
    double s2 = s * s, s3 = s2 * s;
    double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
    double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    return sw_v3_add(sw_v3_add(sw_v3_scale(p1, h00), sw_v3_scale(m1, h10)),
                     sw_v3_add(sw_v3_scale(p2, h01), sw_v3_scale(m2, h11)));
}

static size_t find_segment(const sw_camera_path *path, double t)
{
    size_t lo = 0, hi = path->key_count - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (path->keys[mid].time_s <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

sw_camera_pose sw_camera_path_at(const sw_camera_path *path, double t)
{
    const sw_camera_key *k = path->keys;
    size_t n = path->key_count;
    if (n == 1 || t <= k[0].time_s)
        return (sw_camera_pose){ k[0].eye, k[0].target, k[0].up };
    if (t >= k[n - 1].time_s)
        return (sw_camera_pose){ k[n - 1].eye, k[n - 1].target, k[n - 1].up };
    size_t i = find_segment(path, t);
    const sw_camera_key *a = &k[i > 0 ? i - 1 : i], *b = &k[i], *c = &k[i + 1];
    const sw_camera_key *d = &k[i + 2 < n ? i + 2 : i + 1];
    double s = (t - b->time_s) / (c->time_s - b->time_s);
    /* At the ends the missing neighbour is the key itself: a one-sided tangent. */
    double ta = a == b ? b->time_s : a->time_s, td = d == c ? c->time_s : d->time_s;
    sw_camera_pose pose;
    pose.eye = hermite(a->eye, b->eye, c->eye, d->eye, ta, b->time_s, c->time_s, td, s);
    pose.target = hermite(a->target, b->target, c->target, d->target, ta, b->time_s, c->time_s,
                          td, s);
    pose.up = sw_v3_normalize(hermite(a->up, b->up, c->up, d->up, ta, b->time_s, c->time_s, td, s));
    return pose;
}

sw_camera_frame sw_camera_frame_for_up(sw_vec3 up)
{
    /* x stays "right" unless it is the up axis; then right = up x z, so that
     * every frame is the y-up one turned (right x up = front, right-handed). */
    sw_vec3 right = fabs(up.x) > 0.5 ? sw_v3_normalize(sw_v3_cross(up, sw_v3(0, 0, 1)))
                                     : sw_v3(1, 0, 0);
    return (sw_camera_frame){ right, up, sw_v3_cross(right, up) };
}

/* Unit vector from the centre toward the camera at this azimuth. For the
 * y-up frame exactly (sin az cos el, sin el, cos az cos el): the other terms
 * add zeros. */
static sw_vec3 orbit_direction(const sw_camera_frame *f, double azimuth, double elevation)
{
    sw_vec3 across = sw_v3_scale(f->right, cos(elevation) * sin(azimuth));
    sw_vec3 above = sw_v3_scale(f->up, sin(elevation));
    sw_vec3 ahead = sw_v3_scale(f->front, cos(elevation) * cos(azimuth));
    return sw_v3_add(sw_v3_add(across, above), ahead);
}

/* Smallest distance from the centre, along dir, at which all eight box corners
 * lie inside the view: a corner at (a, b) across and c toward the camera is
 * seen when |a| <= (d - c) tan(half_x) and |b| <= (d - c) tan(half_y). Tighter
 * than fitting the bounding sphere, which leaves flat scenes small. */
static double fit_distance(const sw_box *box, sw_vec3 world_up, sw_vec3 dir, double tan_x,
                           double tan_y)
{
    sw_vec3 centre = sw_box_center(box);
    sw_vec3 right = sw_v3_normalize(sw_v3_cross(world_up, dir));
    sw_vec3 up = sw_v3_cross(dir, right);
    double d = 0;
    for (int i = 0; i < 8; i++) {
        sw_vec3 corner = sw_v3(i & 1 ? box->max.x : box->min.x, i & 2 ? box->max.y : box->min.y,
                               i & 4 ? box->max.z : box->min.z);
        sw_vec3 rel = sw_v3_sub(corner, centre);
        double a = fabs(sw_v3_dot(rel, right)), b = fabs(sw_v3_dot(rel, up));
        double need = sw_v3_dot(rel, dir) + fmax(a / tan_x, b / tan_y);
        d = fmax(d, need);
    }
    return d;
}

sw_camera_pose sw_camera_orbit(const sw_box *box, double fovy_rad, double aspect, double turn)
{
    const sw_camera_frame y_up = sw_camera_frame_for_up(sw_v3(0, 1, 0));
    return sw_camera_orbit_in(box, &y_up, fovy_rad, aspect, turn);
}

sw_camera_pose sw_camera_orbit_in(const sw_box *box, const sw_camera_frame *frame,
                                  double fovy_rad, double aspect, double turn)
{
    const double elevation = 25.0 * SW_PI / 180.0, samples = 64;
    double tan_y = tan(0.5 * fovy_rad), tan_x = tan_y * aspect;
    /* One distance for the whole revolution, so the camera circles steadily:
     * the largest fit over the orbit, plus a margin. */
    double distance = 0;
    for (int k = 0; k < samples; k++)
        distance = fmax(distance, fit_distance(box, frame->up,
                                               orbit_direction(frame, 2 * SW_PI * k / samples,
                                                               elevation),
                                               tan_x, tan_y));
    distance = fmax(distance * 1.08, 1e-6 * (1 + sw_box_diagonal(box)));
    sw_vec3 centre = sw_box_center(box);
    sw_vec3 eye = sw_v3_add(centre, sw_v3_scale(orbit_direction(frame, 2 * SW_PI * turn,
                                                                elevation),
                                                distance));
    return (sw_camera_pose){ eye, centre, frame->up };
}
