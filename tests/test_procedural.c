/* SPDX-License-Identifier: MIT */
/* Specification of the procedural objects (sw_procedural.h): announced patch
 * counts, exact shapes (plane, surface of revolution, sweep), exact circular
 * trims, closed loops, orientation, determinism and parameter checks. The
 * surfaces are checked with core's reference NURBS evaluation; the last cases
 * check what sw_proc_add puts into a model. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sw_procedural.h"
#include "sw_test.h"

static sw_proc_params params(sw_proc_kind kind, int segments, int holes, uint64_t seed)
{
    sw_proc_params p = sw_proc_defaults(kind);
    p.segments = segments;
    p.holes = holes;
    p.seed = seed;
    return p;
}

static int build(const sw_proc_params *p, sw_proc_shape *shape)
{
    sw_error err = {0};
    sw_status st = sw_proc_build(p, shape, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return st == SW_OK;
}

static size_t shape_patches(const sw_proc_shape *shape)
{
    size_t n = 0;
    for (size_t s = 0; s < shape->surface_count; s++) {
        sw_nurbs_bezier_sizes z = sw_nurbs_surface_bezier_sizes(&shape->surfaces[s]);
        n += (size_t)z.pieces_u * (size_t)z.pieces_v;
    }
    return n;
}

/* Parameter ranges of a surface: the clamped ends of its knot vectors. */
static void surface_domain(const sw_nurbs_surface *s, double d[4])
{
    d[0] = s->knots_u[0];
    d[1] = s->knots_u[s->count_u + s->degree_u];
    d[2] = s->knots_v[0];
    d[3] = s->knots_v[s->count_v + s->degree_v];
}

static sw_vec3 normal_at(const sw_nurbs_surface *s, double u, double v)
{
    double d[4], h = 1e-6;
    surface_domain(s, d);
    double hu = h * (d[1] - d[0]), hv = h * (d[3] - d[2]);
    sw_vec3 du = sw_v3_sub(sw_nurbs_surface_point(s, u + hu, v), sw_nurbs_surface_point(s, u - hu, v));
    sw_vec3 dv = sw_v3_sub(sw_nurbs_surface_point(s, u, v + hv), sw_nurbs_surface_point(s, u, v - hv));
    return sw_v3_normalize(sw_v3_cross(du, dv));
}

static void patch_counts_are_announced_for_every_kind_and_size(void)
{
    static const int segments[] = {1, 2, 3, 7, 16, SW_PROC_MAX_SEGMENTS};
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        for (size_t k = 0; k < sizeof segments / sizeof segments[0]; k++) {
            sw_proc_params p = params((sw_proc_kind)kind, segments[k], kind == SW_PROC_VASE ? 0 : 2, 5);
            sw_proc_shape shape;
            if (!build(&p, &shape))
                continue;
            SW_CHECK_MSG(shape_patches(&shape) == sw_proc_patch_count(&p),
                         "%s segments %d: %zu patches, announced %zu", sw_proc_kind_name(p.kind),
                         p.segments, shape_patches(&shape), sw_proc_patch_count(&p));
            sw_proc_shape_free(&shape);
        }
    }
    sw_proc_params plate = params(SW_PROC_PLATE, 5, 0, 1), vase = params(SW_PROC_VASE, 5, 0, 1),
                   rail = params(SW_PROC_RAIL, 5, 0, 1);
    SW_CHECK(sw_proc_patch_count(&plate) == 25);
    SW_CHECK(sw_proc_patch_count(&vase) == 21);
    SW_CHECK(sw_proc_patch_count(&rail) == 20);
}

static void every_surface_and_curve_passes_the_nurbs_checks(void)
{
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        sw_proc_params p = sw_proc_defaults((sw_proc_kind)kind);
        p.holes = kind == SW_PROC_PLATE ? SW_PROC_MAX_PLATE_HOLES
                  : kind == SW_PROC_RAIL ? SW_PROC_MAX_RAIL_SLOTS
                                         : 0;
        sw_proc_shape shape;
        if (!build(&p, &shape))
            continue;
        sw_error err = {0};
        for (size_t s = 0; s < shape.surface_count; s++)
            SW_CHECK_MSG(sw_nurbs_surface_check(&shape.surfaces[s], &err) == SW_OK, "%s",
                         err.message);
        for (size_t c = 0; c < shape.curve_count; c++)
            SW_CHECK_MSG(sw_nurbs_curve_check(&shape.curves[c], &err) == SW_OK, "%s",
                         err.message);
        sw_proc_shape_free(&shape);
    }
}

/* Each loop is closed head to tail, exactly (shared end points are computed
 * from the same numbers). */
static void loops_are_closed_head_to_tail(void)
{
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        sw_proc_params p = params((sw_proc_kind)kind, 3, kind == SW_PROC_VASE ? 0 : 5, 11);
        sw_proc_shape shape;
        if (!build(&p, &shape))
            continue;
        SW_CHECK(shape.total_loops == (kind == SW_PROC_VASE ? 1u : 6u));
        for (size_t l = 0; l < shape.total_loops; l++) {
            const sw_model_loop_input *loop = &shape.loops[l];
            SW_CHECK(loop->outer == (l == 0));
            for (size_t c = 0; c < loop->curve_count; c++) {
                const sw_nurbs_curve *a = &loop->curves[c];
                const sw_nurbs_curve *b = &loop->curves[(c + 1) % loop->curve_count];
                const double *end = a->ctrl + 4 * (a->count - 1);
                SW_CHECK(end[0] == b->ctrl[0] && end[1] == b->ctrl[1]);
            }
        }
        sw_proc_shape_free(&shape);
    }
}

/* Plate parameters are millimetres: (u, v) is at (u - size/2, height,
 * size/2 - v); every point is on the plane y = height. */
static void plate_points_lie_on_its_plane_at_their_parameters(void)
{
    sw_proc_params p = params(SW_PROC_PLATE, 5, 4, 3);
    p.size_mm = 800.0;
    p.height_mm = 740.0;
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    const sw_nurbs_surface *s = &shape.surfaces[0];
    double max_off = 0.0, max_map = 0.0;
    for (int k = 0; k < 400; k++) {
        double u = 800.0 * sw_test_random(), v = 800.0 * sw_test_random();
        sw_vec3 q = sw_nurbs_surface_point(s, u, v);
        max_off = fmax(max_off, fabs(q.y - 740.0));
        max_map = fmax(max_map, fmax(fabs(q.x - (u - 400.0)), fabs(q.z - (400.0 - v))));
    }
    SW_CHECK_NEAR(max_off, 0.0, 1e-9 * 740.0);
    SW_CHECK_NEAR(max_map, 0.0, 1e-9 * 800.0);
    SW_CHECK(normal_at(s, 123.0, 456.0).y > 0.999999);
    sw_proc_shape_free(&shape);
}

/* Hole trims are exact circles in parameter space (and so on the plate),
 * inside the plate and apart from each other. */
static void plate_holes_are_exact_circles_inside_the_plate(void)
{
    sw_proc_params p = params(SW_PROC_PLATE, 4, 9, 77);
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    SW_CHECK(shape.circle_count == 9 && shape.total_loops == 10);
    double worst = 0.0;
    for (size_t h = 0; h < shape.circle_count; h++) {
        const double *c = shape.circles + 3 * h;
        const sw_model_loop_input *loop = &shape.loops[1 + h];
        SW_CHECK(loop->curve_count == 1 && !loop->outer);
        for (int k = 0; k <= 1000; k++) {
            sw_vec3 q = sw_nurbs_curve_point(&loop->curves[0], k / 1000.0);
            worst = fmax(worst, fabs(hypot(q.x - c[0], q.y - c[1]) - c[2]) / c[2]);
        }
        SW_CHECK(c[0] - c[2] > 0.0 && c[0] + c[2] < p.size_mm);
        SW_CHECK(c[1] - c[2] > 0.0 && c[1] + c[2] < p.size_mm);
        for (size_t o = 0; o < h; o++) {
            const double *d = shape.circles + 3 * o;
            SW_CHECK(hypot(c[0] - d[0], c[1] - d[1]) > c[2] + d[2]);
        }
    }
    /* rounding only: the centres are hundreds of millimetres from the origin */
    SW_CHECK_MSG(worst <= 1e-12, "relative radius error %g", worst);
    /* no hole can swallow a whole patch (the model would drop it) */
    for (size_t h = 0; h < shape.circle_count; h++)
        SW_CHECK(shape.circles[3 * h + 2] < 0.5 * p.size_mm / p.segments);
    sw_proc_shape_free(&shape);
}

/* Every vase point is at the profile's radius from the y axis, at the
 * profile's height (1e-9 relative), and the normal points away from the axis. */
static void vase_points_lie_at_the_profile_radius(void)
{
    sw_proc_params p = params(SW_PROC_VASE, 7, 0, 2024);
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    const sw_nurbs_surface *body = &shape.surfaces[0];
    double worst_r = 0.0, worst_y = 0.0;
    for (int k = 0; k < 2000; k++) {
        double u = sw_test_random(), v = sw_test_random();
        sw_vec3 q = sw_nurbs_surface_point(body, u, v);
        sw_vec3 prof = sw_nurbs_curve_point(&shape.profile, u);
        worst_r = fmax(worst_r, fabs(hypot(q.x, q.z) - prof.x) / prof.x);
        worst_y = fmax(worst_y, fabs(q.y - prof.y) / p.height_mm);
        SW_CHECK(prof.x >= 0.2 * 0.5 * p.size_mm && prof.x <= 0.5 * p.size_mm);
    }
    SW_CHECK_MSG(worst_r <= 1e-9, "radius off by %g relative", worst_r);
    SW_CHECK_MSG(worst_y <= 1e-9, "height off by %g relative", worst_y);
    /* y(u) = height * u exactly by the Greville placement */
    SW_CHECK_NEAR(sw_nurbs_curve_point(&shape.profile, 0.3).y, 0.3 * p.height_mm, 1e-9 * p.height_mm);
    sw_vec3 q = sw_nurbs_surface_point(body, 0.4, 0.1), n = normal_at(body, 0.4, 0.1);
    SW_CHECK(sw_v3_dot(n, sw_v3_normalize(sw_v3(q.x, 0.0, q.z))) > 0.5);
    sw_proc_shape_free(&shape);
}

/* The base closes the bottom: a plane at y = 0 facing down, trimmed by an
 * exact circle of the profile's bottom radius. */
static void vase_base_is_a_trimmed_disc_under_the_body(void)
{
    sw_proc_params p = params(SW_PROC_VASE, 3, 0, 9);
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    SW_CHECK(shape.surface_count == 2 && shape.loop_count[0] == 0 && shape.loop_count[1] == 1);
    const sw_nurbs_surface *base = &shape.surfaces[1];
    double r = sw_nurbs_curve_point(&shape.profile, 0.0).x;
    SW_CHECK(shape.circle_count == 1 && shape.circles[2] == r);
    const sw_nurbs_curve *rim = &shape.loops[shape.first_loop[1]].curves[0];
    for (int k = 0; k <= 64; k++) {
        sw_vec3 t = sw_nurbs_curve_point(rim, k / 64.0);
        sw_vec3 q = sw_nurbs_surface_point(base, t.x, t.y);
        SW_CHECK_NEAR(hypot(q.x, q.z), r, 1e-12 * r);
        SW_CHECK(q.y == 0.0);
    }
    SW_CHECK(normal_at(base, 0.0, 0.0).y < -0.999999);
    sw_proc_shape_free(&shape);
}

/* Every rail point is path(u) + section(v): the translational sweep. */
static void rail_points_lie_on_the_sweep(void)
{
    sw_proc_params p = params(SW_PROC_RAIL, 9, 3, 42);
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    const sw_nurbs_surface *s = &shape.surfaces[0];
    double worst = 0.0;
    for (int k = 0; k < 2000; k++) {
        double u = sw_test_random(), v = sw_test_random();
        sw_vec3 q = sw_nurbs_surface_point(s, u, v);
        sw_vec3 want = sw_v3_add(sw_nurbs_curve_point(&shape.path, u),
                                 sw_nurbs_curve_point(&shape.profile, v));
        worst = fmax(worst, sw_v3_length(sw_v3_sub(q, want)));
    }
    SW_CHECK_MSG(worst <= 1e-9 * p.size_mm, "off the sweep by %g mm", worst);
    /* the path runs along x over the whole length; the section stands on y = 0 */
    SW_CHECK_NEAR(sw_nurbs_curve_point(&shape.path, 0.0).x, -0.5 * p.size_mm, 1e-9);
    SW_CHECK_NEAR(sw_nurbs_curve_point(&shape.path, 1.0).x, 0.5 * p.size_mm, 1e-9);
    SW_CHECK(sw_nurbs_curve_point(&shape.profile, 0.0).y == 0.0);
    SW_CHECK(normal_at(s, 0.5, 0.5).y > 0.9);
    sw_proc_shape_free(&shape);
}

/* Slots are closed stadiums on the top of the rail, apart from each other. */
static void rail_slots_sit_on_the_top_and_do_not_overlap(void)
{
    sw_proc_params p = params(SW_PROC_RAIL, 6, 4, 8);
    sw_proc_shape shape;
    if (!build(&p, &shape))
        return;
    double prev_max_u = 0.0;
    for (size_t l = 1; l < shape.total_loops; l++) {
        const sw_model_loop_input *loop = &shape.loops[l];
        SW_CHECK(loop->curve_count == 4);
        double min_u = 1, max_u = 0, min_v = 1, max_v = 0;
        for (size_t c = 0; c < loop->curve_count; c++) {
            for (int k = 0; k <= 32; k++) {
                sw_vec3 t = sw_nurbs_curve_point(&loop->curves[c], k / 32.0);
                min_u = fmin(min_u, t.x), max_u = fmax(max_u, t.x);
                min_v = fmin(min_v, t.y), max_v = fmax(max_v, t.y);
            }
        }
        SW_CHECK(min_u > prev_max_u && min_v > 0.25 && max_v < 0.75);
        prev_max_u = max_u;
    }
    SW_CHECK(prev_max_u < 1.0);
    sw_proc_shape_free(&shape);
}

static int same_shape(const sw_proc_shape *a, const sw_proc_shape *b)
{
    if (a->surface_count != b->surface_count || a->curve_count != b->curve_count)
        return 0;
    for (size_t s = 0; s < a->surface_count; s++) {
        size_t n = 4 * (size_t)a->surfaces[s].count_u * (size_t)a->surfaces[s].count_v;
        if (memcmp(a->surfaces[s].ctrl, b->surfaces[s].ctrl, n * sizeof(double)) != 0)
            return 0;
    }
    for (size_t c = 0; c < a->curve_count; c++) {
        if (memcmp(a->curves[c].ctrl, b->curves[c].ctrl, 4 * (size_t)a->curves[c].count * 8))
            return 0;
    }
    return 1;
}

static void the_seed_decides_everything(void)
{
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        sw_proc_params p = params((sw_proc_kind)kind, 4, kind == SW_PROC_VASE ? 0 : 3, 100);
        sw_proc_shape a, b, c;
        if (!build(&p, &a))
            continue;
        build(&p, &b);
        p.seed = 101;
        build(&p, &c);
        SW_CHECK(same_shape(&a, &b));
        SW_CHECK(!same_shape(&a, &c));
        sw_proc_shape_free(&a);
        sw_proc_shape_free(&b);
        sw_proc_shape_free(&c);
    }
}

static void out_of_range_parameters_are_named(void)
{
    static const struct {
        sw_proc_kind kind;
        double size, height;
        int holes, segments;
        const char *piece;
    } cases[] = {
        {SW_PROC_PLATE, 0.5, 0, 0, 1, "plate: size 0.5 mm outside 1.."},
        {SW_PROC_PLATE, 1e6, 0, 0, 1, "size"},
        {SW_PROC_PLATE, 100, -1, 0, 1, "plate: height -1 mm outside 0.."},
        {SW_PROC_VASE, 100, 0, 0, 1, "vase: height 0 mm outside 1.."},
        {SW_PROC_VASE, 100, 100, 1, 1, "vase: holes 1 outside 0..0"},
        {SW_PROC_RAIL, 100, 100, 17, 1, "rail: holes 17 outside 0..16"},
        {SW_PROC_PLATE, 100, 0, 65, 1, "plate: holes 65 outside 0..64"},
        {SW_PROC_RAIL, 100, 100, 0, 0, "rail: segments 0 outside 1..64"},
        {SW_PROC_PLATE, 100, 0, 0, 65, "segments 65"},
        {SW_PROC_PLATE, NAN, 0, 0, 1, "size nan"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sw_proc_params p = {cases[k].kind, cases[k].size, cases[k].height, cases[k].holes,
                            cases[k].segments, 1};
        sw_error err = {0};
        sw_proc_shape shape;
        SW_CHECK(sw_proc_build(&p, &shape, &err) == SW_ERR_RANGE);
        SW_CHECK_MSG(strstr(err.message, cases[k].piece) != NULL, "'%s' not in '%s'",
                     cases[k].piece, err.message);
        SW_CHECK(shape.surface_count == 0 && shape.blocks == NULL);
    }
    sw_proc_kind kind;
    SW_CHECK(sw_proc_kind_from_name("vase", &kind) && kind == SW_PROC_VASE);
    SW_CHECK(!sw_proc_kind_from_name("Vase", &kind) && !sw_proc_kind_from_name("", &kind));
    SW_CHECK(sw_proc_params_used(SW_PROC_VASE) == (sw_proc_params_used(SW_PROC_PLATE) &
                                                  ~(unsigned)SW_PROC_USES_HOLES));
}

/* Patches the model holds after adding the object to an empty part. */
static size_t added_patches(const sw_proc_params *p)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_status st = sw_model_begin_part(&m, "obj", NULL, &err);
    if (st == SW_OK)
        st = sw_proc_add(&m, p, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    size_t n = m.patch_count;
    sw_model_free(&m);
    return n;
}

/* What the model receives: the announced patches, one surface per shape
 * surface with its loops, in the current part. */
static void adding_to_a_model_gives_the_announced_patches(void)
{
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        sw_proc_params p = params((sw_proc_kind)kind, 5, kind == SW_PROC_VASE ? 0 : 2, 3);
        SW_CHECK(added_patches(&p) == sw_proc_patch_count(&p));
    }
    /* many small patches under big holes and slots: none is trimmed away */
    for (uint64_t seed = 1; seed <= 40; seed++) {
        sw_proc_params plate = params(SW_PROC_PLATE, 3 + (int)(seed % 14), 1 + (int)(seed % 9), seed);
        sw_proc_params rail = params(SW_PROC_RAIL, 8 + (int)seed, (int)(seed % 17), seed);
        SW_CHECK_MSG(added_patches(&plate) == sw_proc_patch_count(&plate), "plate seed %llu",
                     (unsigned long long)seed);
        SW_CHECK_MSG(added_patches(&rail) == sw_proc_patch_count(&rail), "rail seed %llu",
                     (unsigned long long)seed);
    }
}

/* The loops and surfaces the model holds after sw_proc_add. */
static void adding_to_a_model_keeps_surfaces_and_loops(void)
{
    for (int kind = SW_PROC_PLATE; kind <= SW_PROC_RAIL; kind++) {
        sw_proc_params p = params((sw_proc_kind)kind, 5, kind == SW_PROC_VASE ? 0 : 2, 3);
        sw_model m;
        sw_model_init(&m);
        sw_error err = {0};
        SW_CHECK(sw_model_begin_part(&m, "obj", NULL, &err) == SW_OK);
        sw_status st = sw_proc_add(&m, &p, &err);
        SW_CHECK_MSG(st == SW_OK, "%s", err.message);
        SW_CHECK_MSG(m.patch_count == sw_proc_patch_count(&p), "%s: %zu patches, announced %zu",
                     sw_proc_kind_name(p.kind), m.patch_count, sw_proc_patch_count(&p));
        SW_CHECK(m.part_count == 1 && m.parts[0].patch_count == m.patch_count);
        SW_CHECK(m.surface_count == (kind == SW_PROC_VASE ? 2u : 1u));
        SW_CHECK(m.loop_count == (kind == SW_PROC_VASE ? 1u : 3u));
        sw_model_free(&m);
    }
}

int main(void)
{
    SW_RUN(patch_counts_are_announced_for_every_kind_and_size);
    SW_RUN(every_surface_and_curve_passes_the_nurbs_checks);
    SW_RUN(loops_are_closed_head_to_tail);
    SW_RUN(plate_points_lie_on_its_plane_at_their_parameters);
    SW_RUN(plate_holes_are_exact_circles_inside_the_plate);
    SW_RUN(vase_points_lie_at_the_profile_radius);
    SW_RUN(vase_base_is_a_trimmed_disc_under_the_body);
    SW_RUN(rail_points_lie_on_the_sweep);
    SW_RUN(rail_slots_sit_on_the_top_and_do_not_overlap);
    SW_RUN(the_seed_decides_everything);
    SW_RUN(out_of_range_parameters_are_named);
    SW_RUN(adding_to_a_model_gives_the_announced_patches);
    SW_RUN(adding_to_a_model_keeps_surfaces_and_loops);
    return sw_test_finish();
}
