/* SPDX-License-Identifier: MIT */
/* sw_model: surfaces split into Bezier patches that reproduce the NURBS,
 * reversal, restriction of patches to the trims with conservative masks,
 * part transforms, viewpoints, Bezier inputs as one-patch surfaces, and
 * failures that leave the model unchanged. */
#include <string.h>

#include "model_shapes.h"
#include "sw_test.h"
#include "sw_model_trims.h"
#include "sw_trim.h"

typedef struct counts {
    size_t parts, surfaces, loops, curves, patches, viewpoints;
} counts;

static counts model_counts(const sw_model *m)
{
    return (counts){m->part_count, m->surface_count, m->loop_count,
                    m->curve_count, m->patch_count, m->viewpoint_count};
}

static int same_counts(counts a, counts b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Random bicubic surface with spans_u x spans_v spans (random interior knots,
 * one of them doubled), control points in [-1, 1]^3, weights in [0.5, 2]. */
typedef struct random_surface {
    double ku[16], kv[16], ctrl[12 * 12 * 4];
    sw_nurbs_surface s;
} random_surface;

static void random_surface_init(random_surface *r, int spans_u, int spans_v)
{
    int nu = shape_knots(r->ku, 3, spans_u, 2.0), nv = shape_knots(r->kv, 3, spans_v, 1.0);
    for (int i = 4; i < nu; i++)
        r->ku[i] += 0.3 * (sw_test_random() - 0.5) * 2.0 / spans_u;
    for (int k = 0; k < nu * nv; k++) {
        for (int c = 0; c < 3; c++)
            r->ctrl[4 * k + c] = 2 * sw_test_random() - 1;
        r->ctrl[4 * k + 3] = 0.5 + 1.5 * sw_test_random();
    }
    r->s = (sw_nurbs_surface){3, 3, nu, nv, r->ku, r->kv, r->ctrl};
}

/* The surface's point at (u, v) through the model's patches: the patch whose
 * domain holds (u, v), evaluated at the local parameters. 0 if none. */
static int model_point(const sw_model *m, size_t surface, double u, double v, sw_surface_point *out)
{
    const sw_model_surface *s = &m->surfaces[surface];
    for (size_t i = s->first_patch; i < s->first_patch + s->patch_count; i++) {
        const double *d = m->patches[i].domain;
        if (u < d[0] || u > d[1] || v < d[2] || v > d[3])
            continue;
        sw_bezier_patch p = sw_model_patch_view(&m->patches[i]);
        sw_bezier_eval(&p, (u - d[0]) / (d[1] - d[0]), (v - d[2]) / (d[3] - d[2]), SW_EVAL_FIRST,
                       out);
        return 1;
    }
    return 0;
}

/* 4 x 3 spans give 12 patches, tiling the domain, each equal to the NURBS. */
static void test_add_surface_splits_into_matching_patches(void)
{
    random_surface r;
    random_surface_init(&r, 4, 3);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_begin_part(&m, "body", NULL, &err) == SW_OK);
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, NULL, 0, &err) == SW_OK);
    SW_CHECK(m.surface_count == 1 && m.patch_count == 12 && m.parts[0].patch_count == 12);
    SW_CHECK(m.parts[0].surface_count == 1 && m.surfaces[0].patch_count == 12);
    SW_CHECK(m.surfaces[0].rational == 1 && m.surfaces[0].loop_count == 0);
    SW_CHECK(m.surfaces[0].domain[0] == 0 && m.surfaces[0].domain[1] == 2.0);
    for (size_t i = 0; i < m.patch_count; i++)
        SW_CHECK(m.patches[i].surface == 0 && m.patches[i].part == 0 && !m.patches[i].masked);
    double worst = 0;
    int found = 1;
    for (int s = 0; s < 500; s++) {
        double u = 2 * sw_test_random(), v = sw_test_random();
        sw_surface_point q;
        found &= model_point(&m, 0, u, v, &q);
        worst = fmax(worst, sw_v3_length(sw_v3_sub(q.p, sw_nurbs_surface_point(&r.s, u, v))));
    }
    SW_CHECK(found);
    SW_CHECK_MSG(worst < 1e-12, "patch points off the NURBS by %g", worst);
    sw_model_free(&m);
}

/* A trim loop: a circle of radius 0.2 at (1.1, 0.5) in the random surface's
 * domain [0, 2] x [0, 1]. */
static void test_reversal_flips_normals_and_keeps_region(void)
{
    random_surface r;
    random_surface_init(&r, 3, 2);
    shape_circle c;
    shape_circle_init(&c, 1.1, 0.5, 0.2, 0);
    sw_model_loop_input loop = {.curves = &c.curve, .curve_count = 1, .outer = 1};
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, &loop, 1, &err) == SW_OK);
    SW_CHECK(sw_model_add_surface(&m, &r.s, 1, &loop, 1, &err) == SW_OK);
    SW_CHECK(m.surfaces[1].reversed == 1 && m.surfaces[0].reversed == 0);
    sw_trim_polyline before, after;
    SW_CHECK(sw_trim_polyline_from_model(&m, 0, 1e-6, &before, &err) == SW_OK);
    SW_CHECK(sw_trim_polyline_from_model(&m, 1, 1e-6, &after, &err) == SW_OK);
    int flipped = 1, same_point = 1, region_kept = 1, samples = 0;
    for (int s = 0; s < 400; s++) {
        double u = 0.85 + 0.5 * sw_test_random(), v = 0.25 + 0.5 * sw_test_random();
        if (!sw_trim_point_inside(&before, u, v))
            continue;
        samples++;
        sw_surface_point a, b;
        if (!model_point(&m, 0, u, v, &a) || !model_point(&m, 1, 2.0 - u, v, &b)) {
            region_kept = 0;
            continue;
        }
        region_kept &= sw_trim_point_inside(&after, 2.0 - u, v);
        same_point &= sw_v3_length(sw_v3_sub(a.p, b.p)) < 1e-12;
        flipped &= sw_v3_dot(a.normal, b.normal) < -1 + 1e-9;
    }
    SW_CHECK(samples > 100);
    SW_CHECK(flipped && same_point && region_kept);
    sw_trim_polyline_free(&before);
    sw_trim_polyline_free(&after);
    sw_model_free(&m);
}

/* A plane [0, 4] x [0, 3] of 4 x 3 bilinear patches trimmed to a disc of
 * radius 0.3 at (2.0, 1.5): only the two patches either side of u = 2 touch
 * it and are clipped to the disc's box; every disc point is in a set mask
 * cell; cells well outside the disc (the box's corners) are clear. */
static void test_restriction_keeps_patches_touching_the_disc(void)
{
    shape_plane plane;
    shape_plane_init(&plane, 1, 4, 3, 4, 3);
    shape_circle c;
    shape_circle_init(&c, 2.0, 1.5, 0.3, 0);
    sw_model_loop_input loop = {.curves = &c.curve, .curve_count = 1, .outer = 1};
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, &loop, 1, &err) == SW_OK);
    SW_CHECK_MSG(m.patch_count == 2, "%zu patches kept", m.patch_count);
    for (size_t i = 0; i < m.patch_count; i++) {
        const sw_model_patch *p = &m.patches[i];
        SW_CHECK(p->masked == 1);
        SW_CHECK(p->domain[0] >= 1.7 - 1e-4 && p->domain[1] <= 2.3 + 1e-4);
        SW_CHECK(p->domain[2] >= 1.2 - 1e-4 && p->domain[3] <= 1.8 + 1e-4);
        SW_CHECK(p->domain[1] - p->domain[0] < 0.31 && p->domain[3] - p->domain[2] < 0.61);
        int far_set = 0, far_cells = 0;
        double w = (p->domain[1] - p->domain[0]) / 32, h = (p->domain[3] - p->domain[2]) / 32;
        for (int j = 0; j < 32; j++)
            for (int k = 0; k < 32; k++) {
                double cu = p->domain[0] + (k + 0.5) * w, cv = p->domain[2] + (j + 0.5) * h;
                if (hypot(cu - 2.0, cv - 1.5) > 0.3 + hypot(w, h)) {
                    far_cells++;
                    far_set += p->mask[j] >> k & 1u;
                }
            }
        SW_CHECK(far_cells > 50 && far_set == 0);
    }
    int missed = 0, off_plane = 0;
    for (int s = 0; s < 20000; s++) {
        double a = 2 * SW_PI * sw_test_random(), rr = 0.3 * sqrt(sw_test_random());
        double u = 2.0 + rr * cos(a), v = 1.5 + rr * sin(a);
        int covered = 0;
        for (size_t i = 0; i < m.patch_count && !covered; i++) {
            const double *d = m.patches[i].domain;
            if (u < d[0] || u > d[1] || v < d[2] || v > d[3])
                continue;
            int ci = (int)fmin(31, 32 * (u - d[0]) / (d[1] - d[0]));
            int cj = (int)fmin(31, 32 * (v - d[2]) / (d[3] - d[2]));
            covered = m.patches[i].mask[cj] >> ci & 1u;
        }
        missed += !covered;
        sw_surface_point q;
        if (model_point(&m, 0, u, v, &q))
            off_plane += fabs(q.p.x - u) + fabs(q.p.y - v) > 1e-12;
    }
    SW_CHECK_MSG(missed == 0, "%d disc points not covered by a set mask bit", missed);
    SW_CHECK(off_plane == 0);
    sw_model_free(&m);
}

/* A ring trim (outer square, inner hole) drops the patches that lie wholly
 * in the hole and leaves patches wholly in the face unmasked, even along the
 * outer loop (which lies on the domain's boundary). */
static void test_restriction_drops_patch_in_hole(void)
{
    shape_plane plane;
    shape_plane_init(&plane, 1, 6, 6, 6, 6);
    shape_rect outer;
    shape_rect_init(&outer, 0, 6, 0, 6);
    shape_circle hole;
    shape_circle_init(&hole, 3.0, 3.0, 1.9, 1);
    sw_model_loop_input loops[2] = {{.curves = outer.curves, .curve_count = 4, .outer = 1},
                                    {.curves = &hole.curve, .curve_count = 1}};
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_add_surface(&m, &plane.surface, 0, loops, 2, &err) == SW_OK);
    /* The four unit patches around (3, 3) are within 1.42 of it: inside the hole. */
    SW_CHECK_MSG(m.patch_count == 32, "%zu patches", m.patch_count);
    int corner_unmasked = 0;
    for (size_t i = 0; i < m.patch_count; i++) {
        const double *d = m.patches[i].domain;
        SW_CHECK(!(d[0] >= 2 && d[1] <= 4 && d[2] >= 2 && d[3] <= 4));
        if (d[0] == 0 && d[2] == 0)
            corner_unmasked = !m.patches[i].masked;
    }
    SW_CHECK(corner_unmasked);
    sw_model_free(&m);
}

/* Translation then rotation: surfaces and patches move, the part records
 * R * T, another part stays put. */
static void test_transform_part_moves_surfaces_and_composes(void)
{
    random_surface r;
    random_surface_init(&r, 2, 2);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_begin_part(&m, "a", NULL, &err) == SW_OK);
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, NULL, 0, &err) == SW_OK);
    SW_CHECK(sw_model_begin_part(&m, "b", NULL, &err) == SW_OK);
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, NULL, 0, &err) == SW_OK);
    sw_mat4 t = sw_mat4_translate(sw_v3(1, 2, 3)), rot = sw_mat4_rotate(sw_v3(0, 0, 1), 0.7);
    sw_model_transform_part(&m, 0, &t);
    sw_model_transform_part(&m, 0, &rot);
    sw_mat4 both = sw_mat4_mul(&rot, &t);
    double worst = 0;
    for (int k = 0; k < 16; k++)
        worst = fmax(worst, fabs(m.parts[0].transform[k] - both.m[k]));
    SW_CHECK(worst < 1e-15);
    SW_CHECK(m.parts[1].transform[12] == 0 && m.parts[1].transform[0] == 1);
    sw_nurbs_surface moved = sw_model_surface_view(&m.surfaces[0]);
    sw_nurbs_surface still = sw_model_surface_view(&m.surfaces[1]);
    double off = 0;
    for (int s = 0; s < 100; s++) {
        double u = 2 * sw_test_random(), v = sw_test_random();
        sw_vec3 want = sw_mat4_transform_point(&both, sw_nurbs_surface_point(&r.s, u, v));
        sw_surface_point q;
        model_point(&m, 0, u, v, &q);
        off = fmax(off, sw_v3_length(sw_v3_sub(q.p, want)));
        off = fmax(off, sw_v3_length(sw_v3_sub(sw_nurbs_surface_point(&moved, u, v), want)));
        off = fmax(off, sw_v3_length(sw_v3_sub(sw_nurbs_surface_point(&still, u, v),
                                                sw_nurbs_surface_point(&r.s, u, v))));
    }
    SW_CHECK_MSG(off < 1e-12, "off by %g", off);
    sw_model_free(&m);
}

static void test_viewpoint_names_unique(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_model_viewpoint v = {.name = "front", .eye = {0, 0, 5}, .up = {0, 1, 0}, .fov_deg = 40};
    SW_CHECK(sw_model_add_viewpoint(&m, &v, &err) == SW_OK);
    SW_CHECK(sw_model_add_viewpoint(&m, &v, &err) == SW_ERR_FORMAT);
    SW_CHECK(strstr(err.message, "front") != NULL);
    memset(v.name, 'x', sizeof v.name); /* not terminated: truncated to 47 bytes */
    SW_CHECK(sw_model_add_viewpoint(&m, &v, &err) == SW_OK);
    SW_CHECK(m.viewpoint_count == 2 && strlen(m.viewpoints[1].name) == 47);
    SW_CHECK(m.viewpoints[0].fov_deg == 40 && m.viewpoints[0].eye[2] == 5);
    SW_CHECK(sw_model_add_viewpoint(&m, &v, &err) == SW_ERR_FORMAT && m.viewpoint_count == 2);
    sw_model_free(&m);
}

/* Bezier inputs: one untrimmed surface of one patch on [0, 1]^2 each. */
static void test_add_patch_is_a_one_patch_surface(void)
{
    double ctrl[4 * 4 * 4];
    for (int k = 0; k < 16; k++) {
        ctrl[4 * k] = k % 4, ctrl[4 * k + 1] = k / 4, ctrl[4 * k + 2] = sw_test_random();
        ctrl[4 * k + 3] = 7; /* ignored: not rational */
    }
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_add_patch(&m, 3, 3, 0, ctrl, &err) == SW_OK);
    SW_CHECK(sw_model_add_patch(&m, 3, 3, 0, ctrl, &err) == SW_OK);
    SW_CHECK(m.part_count == 1 && m.surface_count == 2 && m.patch_count == 2);
    SW_CHECK(m.patches[1].surface == 1 && m.surfaces[1].first_patch == 1);
    SW_CHECK(m.patches[0].domain[1] == 1 && m.patches[0].domain[3] == 1 && !m.patches[0].masked);
    SW_CHECK(m.surfaces[0].rational == 0 && m.patches[0].ctrl[3] == 1.0);
    sw_nurbs_surface s = sw_model_surface_view(&m.surfaces[0]);
    SW_CHECK(sw_nurbs_surface_check(&s, &err) == SW_OK);
    sw_bezier_patch p = sw_model_patch_view(&m.patches[0]);
    sw_surface_point q;
    sw_bezier_eval(&p, 0.3, 0.8, SW_EVAL_POINT, &q);
    SW_CHECK(sw_v3_length(sw_v3_sub(q.p, sw_nurbs_surface_point(&s, 0.3, 0.8))) < 1e-14);
    sw_model_free(&m);
}

/* Bad knots, a bad trim weight, an unclosed loop and trims outside the
 * domain: each fails with a message naming it and changes nothing. */
static void test_failures_leave_model_unchanged(void)
{
    random_surface r;
    random_surface_init(&r, 2, 2);
    shape_circle c;
    shape_circle_init(&c, 1.0, 0.5, 0.2, 0);
    sw_model_loop_input loop = {.curves = &c.curve, .curve_count = 1, .outer = 1};
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, &loop, 1, &err) == SW_OK);
    counts before = model_counts(&m);
    r.ku[5] = 5.0; /* after the last knot: not monotonic */
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, NULL, 0, &err) != SW_OK);
    SW_CHECK(strstr(err.message, "knot") != NULL && same_counts(before, model_counts(&m)));
    random_surface_init(&r, 2, 2);
    c.ctrl[4 * 3 + 3] = 0; /* a zero weight in the trim */
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, &loop, 1, &err) == SW_ERR_RANGE);
    SW_CHECK(strstr(err.message, "trim loop 0, curve 0") != NULL);
    SW_CHECK(same_counts(before, model_counts(&m)));
    shape_rect open;
    shape_rect_init(&open, 0.5, 1.5, 0.2, 0.8);
    sw_model_loop_input three = {.curves = open.curves, .curve_count = 3, .outer = 1};
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, &three, 1, &err) == SW_ERR_FORMAT);
    SW_CHECK(strstr(err.message, "not closed") != NULL && same_counts(before, model_counts(&m)));
    shape_circle away;
    shape_circle_init(&away, 5.0, 5.0, 0.2, 0);
    sw_model_loop_input far = {.curves = &away.curve, .curve_count = 1, .outer = 1};
    SW_CHECK(sw_model_add_surface(&m, &r.s, 0, &far, 1, &err) == SW_ERR_FORMAT);
    SW_CHECK(strstr(err.message, "enclose no part") != NULL);
    SW_CHECK(same_counts(before, model_counts(&m)));
    SW_CHECK(sw_model_add_patch(&m, 0, 3, 0, r.ctrl, &err) == SW_ERR_RANGE);
    SW_CHECK(same_counts(before, model_counts(&m)));
    sw_model_free(&m);
}

int main(void)
{
    SW_RUN(test_add_surface_splits_into_matching_patches);
    SW_RUN(test_reversal_flips_normals_and_keeps_region);
    SW_RUN(test_restriction_keeps_patches_touching_the_disc);
    SW_RUN(test_restriction_drops_patch_in_hole);
    SW_RUN(test_transform_part_moves_surfaces_and_composes);
    SW_RUN(test_viewpoint_names_unique);
    SW_RUN(test_add_patch_is_a_one_patch_surface);
    SW_RUN(test_failures_leave_model_unchanged);
    return sw_test_finish();
}
