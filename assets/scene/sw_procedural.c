/* SPDX-License-Identifier: MIT */
/* Procedural trimmed NURBS objects (sw_procedural.h). Every shape is built
 * from exact constructions: control points at Greville abscissae (so a
 * B-spline reproduces a linear map exactly), circles as 9-point rational
 * quadratics (The NURBS Book, 7.5), revolution as the tensor product of a
 * profile with that circle (7.6), and the translational sweep as the tensor
 * product of a path with a section (sums of control points). Angles that are
 * multiples of 90 degrees come from a table, not cos/sin, so circles are exact
 * to the last bit of their radius. */
#include "sw_procedural.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- kinds and parameters --------------------------------------------- */

static const char *const kind_names[] = {NULL, "plate", "vase", "rail"};

const char *sw_proc_kind_name(sw_proc_kind kind)
{
    return kind >= SW_PROC_PLATE && kind <= SW_PROC_RAIL ? kind_names[kind] : NULL;
}

int sw_proc_kind_from_name(const char *name, sw_proc_kind *kind)
{
    for (int k = SW_PROC_PLATE; name && k <= SW_PROC_RAIL; k++) {
        if (strcmp(name, kind_names[k]) == 0) {
            *kind = (sw_proc_kind)k;
            return 1;
        }
    }
    return 0;
}

sw_proc_params sw_proc_defaults(sw_proc_kind kind)
{
    switch (kind) {
    case SW_PROC_PLATE:
        return (sw_proc_params){kind, 1000.0, 0.0, 4, 4, 1};
    case SW_PROC_VASE:
        return (sw_proc_params){kind, 300.0, 600.0, 0, 6, 1};
    case SW_PROC_RAIL:
    default:
        return (sw_proc_params){SW_PROC_RAIL, 1600.0, 120.0, 3, 12, 1};
    }
}

unsigned sw_proc_params_used(sw_proc_kind kind)
{
    unsigned all = SW_PROC_USES_SIZE | SW_PROC_USES_HEIGHT | SW_PROC_USES_SEGMENTS |
                   SW_PROC_USES_SEED;
    return kind == SW_PROC_VASE ? all : all | SW_PROC_USES_HOLES;
}

sw_status sw_proc_check(const sw_proc_params *p, sw_error *err)
{
    const char *kind = sw_proc_kind_name(p->kind);
    if (!kind)
        return sw_error_set(err, SW_ERR_ARG, "unknown procedural kind %d", (int)p->kind);
    if (!(p->size_mm >= 1.0 && p->size_mm <= SW_PROC_MAX_SIZE_MM))
        return sw_error_set(err, SW_ERR_RANGE, "%s: size %g mm outside 1..%g", kind, p->size_mm,
                            SW_PROC_MAX_SIZE_MM);
    double min_height = p->kind == SW_PROC_PLATE ? 0.0 : 1.0;
    if (!(p->height_mm >= min_height && p->height_mm <= SW_PROC_MAX_SIZE_MM))
        return sw_error_set(err, SW_ERR_RANGE, "%s: height %g mm outside %g..%g", kind,
                            p->height_mm, min_height, SW_PROC_MAX_SIZE_MM);
    if (p->segments < 1 || p->segments > SW_PROC_MAX_SEGMENTS)
        return sw_error_set(err, SW_ERR_RANGE, "%s: segments %d outside 1..%d", kind,
                            p->segments, SW_PROC_MAX_SEGMENTS);
    int max_holes = p->kind == SW_PROC_PLATE  ? SW_PROC_MAX_PLATE_HOLES
                    : p->kind == SW_PROC_RAIL ? SW_PROC_MAX_RAIL_SLOTS
                                              : 0;
    if (p->holes < 0 || p->holes > max_holes)
        return sw_error_set(err, SW_ERR_RANGE, "%s: holes %d outside 0..%d", kind, p->holes,
                            max_holes);
    return SW_OK;
}

size_t sw_proc_patch_count(const sw_proc_params *p)
{
    size_t s = (size_t)p->segments;
    switch (p->kind) {
    case SW_PROC_PLATE:
        return s * s;
    case SW_PROC_VASE:
        return 4 * s + 1;
    case SW_PROC_RAIL:
        return SW_PROC_RAIL_SECTION_SPANS * s;
    }
    return 0;
}

/* ---- storage ------------------------------------------------------------ */

void sw_proc_shape_free(sw_proc_shape *shape)
{
    if (!shape)
        return;
    for (size_t i = 0; i < shape->block_count; i++)
        free(shape->blocks[i]);
    free(shape->blocks);
    memset(shape, 0, sizeof *shape);
}

/* Zeroed memory owned by the shape; NULL when out of memory. */
static void *shape_alloc(sw_proc_shape *shape, size_t count, size_t elem_size)
{
    if (shape->block_count == shape->block_capacity) {
        size_t cap = shape->block_capacity ? shape->block_capacity * 2 : 16;
        void **bigger = realloc(shape->blocks, cap * sizeof *bigger);
        if (!bigger)
            return NULL;
        shape->blocks = bigger;
        shape->block_capacity = cap;
    }
    void *p = calloc(count ? count : 1, elem_size);
    if (p)
        shape->blocks[shape->block_count++] = p;
    return p;
}

static double *alloc_doubles(sw_proc_shape *shape, size_t count)
{
    return shape_alloc(shape, count, sizeof(double));
}

/* Reserves the loop and curve arrays once: loop inputs point into curves. */
static int reserve_loops(sw_proc_shape *shape, size_t loops, size_t curves)
{
    shape->loops = shape_alloc(shape, loops, sizeof *shape->loops);
    shape->curves = shape_alloc(shape, curves, sizeof *shape->curves);
    shape->circles = alloc_doubles(shape, 3 * (loops + 1));
    return shape->loops && shape->curves && shape->circles;
}

/* Seeded splitmix64: the same seed gives the same object on every host. */
static uint64_t rng_next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double rng_range(uint64_t *state, double lo, double hi)
{
    double unit = (double)(rng_next(state) >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * unit;
}

/* ---- knots and curves ------------------------------------------------- */

/* A clamped knot vector of degree p with `spans` equal spans on [a, b]. */
static double *uniform_knots(sw_proc_shape *shape, int p, int spans, double a, double b)
{
    double *k = alloc_doubles(shape, (size_t)(spans + 2 * p + 1));
    if (!k)
        return NULL;
    for (int i = 0; i <= p; i++) {
        k[i] = a;
        k[spans + p + i] = b;
    }
    for (int i = 1; i < spans; i++)
        k[p + i] = a + (b - a) * i / spans;
    return k;
}

/* Greville abscissa i: the parameter where control point i "sits"; placing
 * coordinates there makes the B-spline reproduce a linear function. */
static double greville(const double *knots, int p, int i)
{
    double sum = 0.0;
    for (int k = 1; k <= p; k++)
        sum += knots[i + k];
    return sum / p;
}

/* Starts a new loop whose curves follow. */
static void begin_loop(sw_proc_shape *shape, int outer)
{
    shape->loops[shape->total_loops++] = (sw_model_loop_input){
        .curves = shape->curves + shape->curve_count,
        .outer = outer,
    };
}

/* Appends a curve to the current loop. */
static void add_curve(sw_proc_shape *shape, int degree, int count, const double *knots,
                      const double *ctrl)
{
    shape->curves[shape->curve_count++] =
        (sw_nurbs_curve){.degree = degree, .count = count, .knots = knots, .ctrl = ctrl};
    shape->loops[shape->total_loops - 1].curve_count++;
}

static int add_line(sw_proc_shape *shape, double u0, double v0, double u1, double v1)
{
    double *k = alloc_doubles(shape, 4), *c = alloc_doubles(shape, 8);
    if (!k || !c)
        return 0;
    k[2] = k[3] = 1.0;
    const double pts[8] = {u0, v0, 0, 1, u1, v1, 0, 1};
    memcpy(c, pts, sizeof pts);
    add_curve(shape, 1, 2, k, c);
    return 1;
}

/* Unit directions at multiples of 90 degrees, exactly. */
static const double quarter_dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

/* An elliptic arc of `quarters` quarter arcs from direction first_quarter,
 * counter-clockwise in (u, v): the rational quadratic of the circle mapped by
 * the axis-aligned affine map (c, r). Middle points are the tangent corners
 * with weight cos 45 deg. */
static int add_arc(sw_proc_shape *shape, double cu, double cv, double ru, double rv,
                   int first_quarter, int quarters)
{
    int count = 2 * quarters + 1;
    double *k = alloc_doubles(shape, (size_t)count + 3), *c = alloc_doubles(shape, 4 * (size_t)count);
    if (!k || !c)
        return 0;
    k[count] = k[count + 1] = k[count + 2] = 1.0;
    for (int q = 1; q < quarters; q++)
        k[1 + 2 * q] = k[2 + 2 * q] = (double)q / quarters;
    for (int i = 0; i < count; i++) {
        const double *a = quarter_dir[(first_quarter + i / 2) % 4];
        double du = a[0], dv = a[1], w = 1.0;
        if (i % 2) {
            const double *b = quarter_dir[(first_quarter + i / 2 + 1) % 4];
            du += b[0];
            dv += b[1];
            w = sqrt(0.5);
        }
        double *p = c + 4 * i;
        p[0] = cu + ru * du;
        p[1] = cv + rv * dv;
        p[3] = w;
    }
    add_curve(shape, 2, count, k, c);
    return 1;
}

static int add_circle_loop(sw_proc_shape *shape, double cu, double cv, double r, int outer)
{
    begin_loop(shape, outer);
    double *rec = shape->circles + 3 * shape->circle_count++;
    rec[0] = cu;
    rec[1] = cv;
    rec[2] = r;
    return add_arc(shape, cu, cv, r, r, 0, 4);
}

static int add_rectangle_loop(sw_proc_shape *shape, double u0, double v0, double u1, double v1)
{
    begin_loop(shape, 1);
    return add_line(shape, u0, v0, u1, v0) && add_line(shape, u1, v0, u1, v1) &&
           add_line(shape, u1, v1, u0, v1) && add_line(shape, u0, v1, u0, v0);
}

/* A slot: straight sides from ua to ub at cv -+ rv, half-elliptic ends of
 * radii (ru, rv) centred on ua and ub; head to tail. */
static int add_slot_loop(sw_proc_shape *shape, double ua, double ub, double cv, double ru,
                         double rv)
{
    begin_loop(shape, 0);
    return add_line(shape, ua, cv - rv, ub, cv - rv) && add_arc(shape, ub, cv, ru, rv, 3, 2) &&
           add_line(shape, ub, cv + rv, ua, cv + rv) && add_arc(shape, ua, cv, ru, rv, 1, 2);
}

/* ---- surfaces ---------------------------------------------------------- */

/* Starts surface number shape->surface_count with its control net; loops
 * added after it belong to it. */
static double *begin_surface(sw_proc_shape *shape, int du, int dv, int nu, int nv,
                             const double *ku, const double *kv)
{
    double *ctrl = alloc_doubles(shape, 4 * (size_t)nu * (size_t)nv);
    if (!ctrl || !ku || !kv)
        return NULL;
    size_t s = shape->surface_count++;
    shape->surfaces[s] = (sw_nurbs_surface){
        .degree_u = du, .degree_v = dv, .count_u = nu, .count_v = nv,
        .knots_u = ku, .knots_v = kv, .ctrl = ctrl,
    };
    shape->first_loop[s] = shape->total_loops;
    return ctrl;
}

/* Closes the loop count of the last surface begun. */
static void end_surface(sw_proc_shape *shape)
{
    size_t s = shape->surface_count - 1;
    shape->loop_count[s] = shape->total_loops - shape->first_loop[s];
}

static void set_point(double *ctrl, int nu, int i, int j, double x, double y, double z, double w)
{
    double *p = ctrl + 4 * ((size_t)j * (size_t)nu + (size_t)i);
    p[0] = x;
    p[1] = y;
    p[2] = z;
    p[3] = w;
}

/* ---- plate -------------------------------------------------------------- */

/* Holes on a g x g grid of cells, each a circle of seeded radius and centre
 * at least a tenth of a cell away from its cell's edges, so holes never touch
 * each other or the plate's boundary. A radius under half a patch's side
 * keeps every patch partly on the plate: the model drops patches wholly
 * outside the face, and the announced count must hold. */
static int plate_holes(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng)
{
    int g = 1;
    while (g * g < p->holes)
        g++;
    double cell = p->size_mm / g, patch = p->size_mm / p->segments;
    for (int k = 0; k < p->holes; k++) {
        double r = fmin(cell * rng_range(rng, 0.12, 0.3), 0.45 * patch);
        double slack = 0.4 * cell - r;
        double cu = cell * (k % g + 0.5) + rng_range(rng, -slack, slack);
        double cv = cell * (k / g + 0.5) + rng_range(rng, -slack, slack);
        if (!add_circle_loop(shape, cu, cv, r, 0))
            return 0;
    }
    return 1;
}

/* Parameters are millimetres: (u, v) lies at (u - size/2, height, size/2 - v),
 * so du x dv = x x (-z) = +y. */
static int build_plate(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng)
{
    int s = p->segments, n = s + 3;
    double w = p->size_mm;
    if (!reserve_loops(shape, 1 + (size_t)p->holes, 4 + (size_t)p->holes))
        return 0;
    double *k = uniform_knots(shape, 3, s, 0.0, w);
    double *ctrl = begin_surface(shape, 3, 3, n, n, k, k);
    if (!ctrl)
        return 0;
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++)
            set_point(ctrl, n, i, j, greville(k, 3, i) - 0.5 * w, p->height_mm,
                      0.5 * w - greville(k, 3, j), 1.0);
    }
    if (!add_rectangle_loop(shape, 0.0, 0.0, w, w) || !plate_holes(shape, p, rng))
        return 0;
    end_surface(shape);
    return 1;
}

/* ---- vase --------------------------------------------------------------- */

static double smoothstep(double x)
{
    return x * x * (3.0 - 2.0 * x);
}

/* The profile's radius as a fraction of the widest, at height fraction t:
 * foot, belly, neck and lip at seeded heights and widths, all >= 0.25. */
typedef struct vase_form {
    double foot, belly_t, neck_t, neck, lip;
} vase_form;

static double vase_radius(const vase_form *f, double t)
{
    if (t < f->belly_t)
        return f->foot + (1.0 - f->foot) * smoothstep(t / f->belly_t);
    if (t < f->neck_t)
        return 1.0 + (f->neck - 1.0) * smoothstep((t - f->belly_t) / (f->neck_t - f->belly_t));
    return f->neck + (f->lip - f->neck) * smoothstep((t - f->neck_t) / (1.0 - f->neck_t));
}

/* The profile (r, y, 0): y at the Greville abscissae, so y(u) = height * u. */
static int vase_profile(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng,
                        const double *ku)
{
    vase_form f = {
        .foot = rng_range(rng, 0.45, 0.7),
        .belly_t = rng_range(rng, 0.3, 0.55),
        .neck_t = rng_range(rng, 0.72, 0.88),
        .neck = rng_range(rng, 0.25, 0.45),
        .lip = rng_range(rng, 0.4, 0.65),
    };
    int n = p->segments + 3;
    double *c = alloc_doubles(shape, 4 * (size_t)n);
    if (!c)
        return 0;
    for (int i = 0; i < n; i++) {
        double t = greville(ku, 3, i);
        c[4 * i] = 0.5 * p->size_mm * vase_radius(&f, t);
        c[4 * i + 1] = p->height_mm * t;
        c[4 * i + 3] = 1.0;
    }
    shape->profile = (sw_nurbs_curve){.degree = 3, .count = n, .knots = ku, .ctrl = c};
    return 1;
}

/* Body: u up the profile, v around the y axis from +x towards +z, so
 * du x dv points away from the axis. The weights depend on v only, so every
 * point of the surface is at exactly the profile's radius from the axis. */
static int vase_body(sw_proc_shape *shape, const double *ku)
{
    const sw_nurbs_curve *prof = &shape->profile;
    double *kv = alloc_doubles(shape, 12);
    if (!kv)
        return 0;
    static const double quarters[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    memcpy(kv, quarters, sizeof quarters);
    double *ctrl = begin_surface(shape, 3, 2, prof->count, 9, ku, kv);
    if (!ctrl)
        return 0;
    for (int j = 0; j < 9; j++) {
        const double *a = quarter_dir[(j / 2) % 4], *b = quarter_dir[(j / 2 + 1) % 4];
        double cx = a[0], cz = a[1], w = 1.0;
        if (j % 2) {
            cx += b[0];
            cz += b[1];
            w = sqrt(0.5);
        }
        for (int i = 0; i < prof->count; i++) {
            const double *q = prof->ctrl + 4 * i;
            set_point(ctrl, prof->count, i, j, q[0] * cx, q[1], q[0] * cz, w);
        }
    }
    end_surface(shape);
    return 1;
}

/* Base: a bilinear square in y = 0 whose parameters are (x, z), facing down
 * (x x z = -y), trimmed by the circle of the profile's bottom radius. */
static int vase_base(sw_proc_shape *shape)
{
    double r = shape->profile.ctrl[0], a = 1.125 * r;
    double *k = alloc_doubles(shape, 4);
    if (!k)
        return 0;
    k[0] = k[1] = -a;
    k[2] = k[3] = a;
    double *ctrl = begin_surface(shape, 1, 1, 2, 2, k, k);
    if (!ctrl)
        return 0;
    for (int j = 0; j < 2; j++) {
        for (int i = 0; i < 2; i++)
            set_point(ctrl, 2, i, j, k[1 + i], 0.0, k[1 + j], 1.0);
    }
    if (!add_circle_loop(shape, 0.0, 0.0, r, 1))
        return 0;
    end_surface(shape);
    return 1;
}

static int build_vase(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng)
{
    double *ku = uniform_knots(shape, 3, p->segments, 0.0, 1.0);
    return ku && reserve_loops(shape, 1, 1) && vase_profile(shape, p, rng, ku) &&
           vase_body(shape, ku) && vase_base(shape);
}

/* ---- rail --------------------------------------------------------------- */

/* The path (x, 0, z): x at the Greville abscissae (x(u) = size * (u - 1/2)),
 * z a seeded gentle wave, small enough that the section, which keeps its
 * orientation (a translational sweep), stays nearly square to the path. */
static int rail_path(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng,
                     const double *ku)
{
    double amp = p->size_mm * rng_range(rng, 0.02, 0.06);
    double freq = rng_range(rng, 0.5, 1.5), phase = rng_range(rng, 0.0, 2.0 * SW_PI);
    int n = p->segments + 3;
    double *c = alloc_doubles(shape, 4 * (size_t)n);
    if (!c)
        return 0;
    for (int i = 0; i < n; i++) {
        double t = greville(ku, 3, i);
        c[4 * i] = p->size_mm * (t - 0.5);
        c[4 * i + 2] = amp * sin(2.0 * SW_PI * freq * t + phase);
        c[4 * i + 3] = 1.0;
    }
    shape->path = (sw_nurbs_curve){.degree = 3, .count = n, .knots = ku, .ctrl = c};
    return 1;
}

/* The section (0, y, z): an arch `height` tall and wide, from the +z foot over
 * the top to the -z foot, so du x dv = x x (-z) = +y on top. */
static int rail_section(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng,
                        const double *kv)
{
    double h = p->height_mm, w = 0.5 * h, shoulder = rng_range(rng, 0.6, 0.8);
    const double yz[6][2] = {{0, w},          {shoulder * h, w},      {h, 0.5 * w},
                             {h, -0.5 * w},   {shoulder * h, -w},     {0, -w}};
    double *c = alloc_doubles(shape, 24);
    if (!c)
        return 0;
    for (int j = 0; j < 6; j++) {
        c[4 * j + 1] = yz[j][0];
        c[4 * j + 2] = yz[j][1];
        c[4 * j + 3] = 1.0;
    }
    shape->profile = (sw_nurbs_curve){.degree = 2, .count = 6, .knots = kv, .ctrl = c};
    return 1;
}

/* Slots on the top (v around 1/2), one per 1/holes of the length. */
static int rail_slots(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng)
{
    double n = p->holes, ru = 0.1 / n;
    for (int k = 0; k < p->holes; k++) {
        double cv = 0.5 + rng_range(rng, -0.04, 0.04), rv = rng_range(rng, 0.05, 0.08);
        if (!add_slot_loop(shape, (k + 0.2) / n + ru, (k + 0.8) / n - ru, cv, ru, rv))
            return 0;
    }
    return 1;
}

static int build_rail(sw_proc_shape *shape, const sw_proc_params *p, uint64_t *rng)
{
    double *ku = uniform_knots(shape, 3, p->segments, 0.0, 1.0);
    double *kv = uniform_knots(shape, 2, SW_PROC_RAIL_SECTION_SPANS, 0.0, 1.0);
    if (!ku || !kv || !reserve_loops(shape, 1 + (size_t)p->holes, 4 + 4 * (size_t)p->holes) ||
        !rail_path(shape, p, rng, ku) || !rail_section(shape, p, rng, kv))
        return 0;
    const sw_nurbs_curve *path = &shape->path, *sec = &shape->profile;
    double *ctrl = begin_surface(shape, 3, 2, path->count, sec->count, ku, kv);
    if (!ctrl)
        return 0;
    for (int j = 0; j < sec->count; j++) {
        for (int i = 0; i < path->count; i++) {
            const double *a = path->ctrl + 4 * i, *b = sec->ctrl + 4 * j;
            set_point(ctrl, path->count, i, j, a[0] + b[0], a[1] + b[1], a[2] + b[2], 1.0);
        }
    }
    if (!add_rectangle_loop(shape, 0.0, 0.0, 1.0, 1.0) || !rail_slots(shape, p, rng))
        return 0;
    end_surface(shape);
    return 1;
}

/* ---- entry points ------------------------------------------------------- */

sw_status sw_proc_build(const sw_proc_params *params, sw_proc_shape *shape, sw_error *err)
{
    if (!params || !shape)
        return sw_error_set(err, SW_ERR_ARG, "sw_proc_build: NULL argument");
    memset(shape, 0, sizeof *shape);
    sw_status st = sw_proc_check(params, err);
    if (st != SW_OK)
        return st;
    shape->params = *params;
    /* Different kinds from one seed should not share their random draws. */
    uint64_t rng = params->seed ^ (0xD1B54A32D192ED03ull * (uint64_t)params->kind);
    int ok = params->kind == SW_PROC_PLATE  ? build_plate(shape, params, &rng)
             : params->kind == SW_PROC_VASE ? build_vase(shape, params, &rng)
                                            : build_rail(shape, params, &rng);
    if (!ok) {
        sw_proc_shape_free(shape);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory building a %s",
                            sw_proc_kind_name(params->kind));
    }
    return SW_OK;
}

sw_status sw_proc_add(sw_model *model, const sw_proc_params *params, sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_proc_add: model is NULL");
    sw_proc_shape shape;
    sw_status st = sw_proc_build(params, &shape, err);
    for (size_t s = 0; st == SW_OK && s < shape.surface_count; s++)
        st = sw_model_add_surface(model, &shape.surfaces[s], 0, shape.loops + shape.first_loop[s],
                                  shape.loop_count[s], err);
    sw_proc_shape_free(&shape);
    return st;
}
