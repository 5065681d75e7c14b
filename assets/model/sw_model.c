/* SPDX-License-Identifier: MIT */
/* The host-side model (sw_model.h): growable arrays of parts, surfaces,
 * loops, trim curves, Bezier patches and viewpoints. A surface is built
 * completely on the side (a "staged" surface) and only then appended, so a
 * failure leaves the model as it was. */
#include "sw_model.h"

#include "sw_trim.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Parts that nobody named or coloured get this neutral grey. */
static const float default_color[4] = {0.8f, 0.8f, 0.8f, 1.0f};

void sw_model_init(sw_model *model)
{
    memset(model, 0, sizeof *model);
}

void sw_model_free(sw_model *model)
{
    if (!model)
        return;
    for (size_t i = 0; i < model->patch_count; i++)
        free(model->patches[i].ctrl);
    for (size_t i = 0; i < model->surface_count; i++) {
        free(model->surfaces[i].knots_u);
        free(model->surfaces[i].knots_v);
        free(model->surfaces[i].ctrl);
    }
    for (size_t i = 0; i < model->curve_count; i++) {
        free(model->curves[i].knots);
        free(model->curves[i].ctrl);
    }
    free(model->patches);
    free(model->surfaces);
    free(model->loops);
    free(model->curves);
    free(model->parts);
    free(model->viewpoints);
    sw_model_init(model);
}

/* Makes room for `extra` more elements of elem_size bytes in the array whose
 * pointer is at array_ptr (any object pointer type: read and written with
 * memcpy, so no aliasing through void **), doubling the capacity so that n
 * appends cost O(n) copies. */
static sw_status reserve(void *array_ptr, size_t *capacity, size_t count, size_t extra,
                         size_t elem_size, const char *what, sw_error *err)
{
    if (extra > SIZE_MAX / elem_size - count)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "too many %s (%zu)", what, count);
    if (count + extra <= *capacity)
        return SW_OK;
    size_t wanted = *capacity ? *capacity : 16;
    while (wanted < count + extra)
        wanted = wanted > SIZE_MAX / elem_size / 2 ? count + extra : wanted * 2;
    void *array;
    memcpy(&array, array_ptr, sizeof array);
    void *bigger = realloc(array, wanted * elem_size);
    if (!bigger)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory growing %s to %zu", what,
                            wanted);
    memcpy(array_ptr, &bigger, sizeof bigger);
    *capacity = wanted;
    return SW_OK;
}

#define RESERVE(model, array, one, extra, err)                                             \
    reserve(&(model)->array, &(model)->one##_capacity, (model)->one##_count,       \
            (extra), sizeof *(model)->array, #array, (err))

sw_status sw_model_begin_part(sw_model *model, const char *name, const float color[4],
                              sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_begin_part: model is NULL");
    sw_status st = RESERVE(model, parts, part, 1, err);
    if (st != SW_OK)
        return st;
    sw_model_part *part = &model->parts[model->part_count++];
    memset(part, 0, sizeof *part);
    /* Truncation is the documented contract: pack part names are 56 bytes. */
    size_t len = name ? strnlen(name, sizeof part->name - 1) : 0;
    if (len)
        memcpy(part->name, name, len);
    memcpy(part->color, color ? color : default_color, sizeof part->color);
    sw_mat4 identity = sw_mat4_identity();
    memcpy(part->transform, identity.m, sizeof part->transform);
    part->first_patch = model->patch_count;
    part->first_surface = model->surface_count;
    return SW_OK;
}

/* A surface with everything it owns, built before it joins the model. Loop
 * first_curve and patch indices are local until staged_commit. */
typedef struct staged {
    sw_model_surface surface;
    sw_model_trim_curve *curves;
    size_t curve_count;
    sw_model_loop *loops;
    size_t loop_count;
    sw_model_patch *patches;
    size_t patch_count;
} staged;

static void staged_free(staged *s)
{
    free(s->surface.knots_u);
    free(s->surface.knots_v);
    free(s->surface.ctrl);
    for (size_t i = 0; i < s->curve_count; i++) {
        free(s->curves[i].knots);
        free(s->curves[i].ctrl);
    }
    for (size_t i = 0; i < s->patch_count; i++)
        free(s->patches[i].ctrl);
    free(s->curves);
    free(s->loops);
    free(s->patches);
    memset(s, 0, sizeof *s);
}

/* Appends the staged surface to the current part (starting an unnamed part
 * if there is none). All room is reserved first, so the model changes only
 * once nothing can fail; the staged arrays' contents then belong to it. */
static sw_status staged_commit(sw_model *model, staged *s, sw_error *err)
{
    sw_status st = RESERVE(model, parts, part, 1, err);
    if (st == SW_OK)
        st = RESERVE(model, surfaces, surface, 1, err);
    if (st == SW_OK)
        st = RESERVE(model, loops, loop, s->loop_count, err);
    if (st == SW_OK)
        st = RESERVE(model, curves, curve, s->curve_count, err);
    if (st == SW_OK)
        st = RESERVE(model, patches, patch, s->patch_count, err);
    if (st == SW_OK && model->part_count == 0)
        st = sw_model_begin_part(model, "", NULL, err);
    if (st != SW_OK) {
        staged_free(s);
        return st;
    }
    size_t part = model->part_count - 1, surface = model->surface_count;
    for (size_t i = 0; i < s->loop_count; i++) {
        s->loops[i].first_curve += model->curve_count;
        model->loops[model->loop_count + i] = s->loops[i];
    }
    for (size_t i = 0; i < s->patch_count; i++) {
        s->patches[i].part = part;
        s->patches[i].surface = surface;
        model->patches[model->patch_count + i] = s->patches[i];
    }
    if (s->curve_count)
        memcpy(model->curves + model->curve_count, s->curves, s->curve_count * sizeof *s->curves);
    s->surface.part = part;
    s->surface.first_loop = model->loop_count;
    s->surface.loop_count = s->loop_count;
    s->surface.first_patch = model->patch_count;
    s->surface.patch_count = s->patch_count;
    model->surfaces[model->surface_count++] = s->surface;
    model->loop_count += s->loop_count;
    model->curve_count += s->curve_count;
    model->patch_count += s->patch_count;
    model->parts[part].patch_count += s->patch_count;
    model->parts[part].surface_count++;
    free(s->curves);
    free(s->loops);
    free(s->patches);
    memset(s, 0, sizeof *s);
    return SW_OK;
}

static double *copy_doubles(const double *src, size_t n)
{
    double *dst = malloc((n ? n : 1) * sizeof *dst);
    if (dst && n)
        memcpy(dst, src, n * sizeof *dst);
    return dst;
}

static int any_weight_not_one(const double *ctrl, size_t points)
{
    for (size_t k = 0; k < points; k++)
        if (ctrl[4 * k + 3] != 1.0)
            return 1;
    return 0;
}

/* Rejects what would make an invalid pack later, so every importer gets the
 * same checks even if it forgot one. */
static sw_status check_patch(int degree_u, int degree_v, int rational, const double *ctrl,
                             sw_error *err)
{
    if (degree_u < 1 || degree_u > SW_BEZIER_MAX_DEGREE || degree_v < 1 ||
        degree_v > SW_BEZIER_MAX_DEGREE)
        return sw_error_set(err, SW_ERR_RANGE, "patch degree %d x %d out of range 1..%d",
                            degree_u, degree_v, SW_BEZIER_MAX_DEGREE);
    if (!ctrl)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_patch: ctrl is NULL");
    size_t points = (size_t)(degree_u + 1) * (size_t)(degree_v + 1);
    for (size_t k = 0; k < points; k++) {
        const double *p = ctrl + 4 * k;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return sw_error_set(err, SW_ERR_RANGE, "control point %zu is not finite", k);
        if (rational && !(isfinite(p[3]) && p[3] > 0.0))
            return sw_error_set(err, SW_ERR_RANGE,
                                "control point %zu has weight %g; weights must be > 0", k, p[3]);
    }
    return SW_OK;
}

/* A Bezier patch is a surface of one span with knots 0^(n+1) 1^(n+1). */
static double *bezier_knots(int degree)
{
    double *k = malloc(2 * (size_t)(degree + 1) * sizeof *k);
    for (int i = 0; k && i <= degree; i++) {
        k[i] = 0.0;
        k[degree + 1 + i] = 1.0;
    }
    return k;
}

sw_status sw_model_add_patch(sw_model *model, int degree_u, int degree_v, int rational,
                             const double *ctrl, sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_patch: model is NULL");
    sw_status st = check_patch(degree_u, degree_v, rational, ctrl, err);
    if (st != SW_OK)
        return st;
    size_t doubles = 4 * (size_t)(degree_u + 1) * (size_t)(degree_v + 1);
    staged s = {0};
    s.patches = calloc(1, sizeof *s.patches);
    s.surface.ctrl = copy_doubles(ctrl, doubles);
    double *patch_ctrl = copy_doubles(ctrl, doubles);
    s.surface.knots_u = bezier_knots(degree_u);
    s.surface.knots_v = bezier_knots(degree_v);
    if (s.patches)
        s.patches[s.patch_count++].ctrl = patch_ctrl;
    else
        free(patch_ctrl);
    if (!s.patches || !patch_ctrl || !s.surface.ctrl || !s.surface.knots_u || !s.surface.knots_v) {
        staged_free(&s);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying a patch");
    }
    for (size_t k = 3; !rational && k < doubles; k += 4)
        s.surface.ctrl[k] = patch_ctrl[k] = 1.0;
    s.surface.degree_u = s.patches[0].degree_u = degree_u;
    s.surface.degree_v = s.patches[0].degree_v = degree_v;
    s.surface.count_u = degree_u + 1;
    s.surface.count_v = degree_v + 1;
    s.surface.rational = s.patches[0].rational = rational ? 1 : 0;
    double unit[4] = {0, 1, 0, 1};
    memcpy(s.surface.domain, unit, sizeof unit);
    memcpy(s.patches[0].domain, unit, sizeof unit);
    return staged_commit(model, &s, err);
}

static sw_status check_input(const sw_nurbs_surface *surface, const sw_model_loop_input *loops,
                             size_t loop_count, sw_error *err)
{
    if (!surface || (loop_count && !loops))
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_surface: surface or loops is NULL");
    sw_status st = sw_nurbs_surface_check(surface, err);
    for (size_t l = 0; st == SW_OK && l < loop_count; l++) {
        if (loops[l].curve_count == 0 || !loops[l].curves)
            return sw_error_set(err, SW_ERR_FORMAT, "trim loop %zu has no curves", l);
        for (size_t c = 0; st == SW_OK && c < loops[l].curve_count; c++) {
            st = sw_nurbs_curve_check(&loops[l].curves[c], err);
            if (st != SW_OK)
                sw_error_prefix(err, "trim loop %zu, curve %zu", l, c);
        }
    }
    return st;
}

/* Copies the surface and its trims into s (nothing shared with the caller). */
static sw_status stage_copy(staged *s, const sw_nurbs_surface *in, const sw_model_loop_input *loops,
                            size_t loop_count, sw_error *err)
{
    sw_model_surface *o = &s->surface;
    size_t points = (size_t)in->count_u * (size_t)in->count_v;
    o->degree_u = in->degree_u, o->degree_v = in->degree_v;
    o->count_u = in->count_u, o->count_v = in->count_v;
    o->knots_u = copy_doubles(in->knots_u, (size_t)(in->count_u + in->degree_u + 1));
    o->knots_v = copy_doubles(in->knots_v, (size_t)(in->count_v + in->degree_v + 1));
    o->ctrl = copy_doubles(in->ctrl, 4 * points);
    o->rational = any_weight_not_one(in->ctrl, points);
    size_t curves = 0;
    for (size_t l = 0; l < loop_count; l++)
        curves += loops[l].curve_count;
    s->loops = calloc(loop_count + 1, sizeof *s->loops);
    s->curves = calloc(curves + 1, sizeof *s->curves);
    if (!o->knots_u || !o->knots_v || !o->ctrl || !s->loops || !s->curves)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying a surface");
    for (size_t l = 0; l < loop_count; l++) {
        s->loops[l] = (sw_model_loop){s->curve_count, loops[l].curve_count, loops[l].outer};
        s->loop_count++;
        for (size_t c = 0; c < loops[l].curve_count; c++) {
            const sw_nurbs_curve *src = &loops[l].curves[c];
            sw_model_trim_curve *dst = &s->curves[s->curve_count++];
            dst->degree = src->degree, dst->count = src->count;
            dst->computed = loops[l].computed ? loops[l].computed[c] != 0 : 0;
            dst->gap = loops[l].gaps && loops[l].gaps[c] > 0 ? loops[l].gaps[c] : 0.0;
            dst->edge = loops[l].edges ? loops[l].edges[c] : 0;
            dst->knots = copy_doubles(src->knots, (size_t)(src->count + src->degree + 1));
            dst->ctrl = copy_doubles(src->ctrl, 4 * (size_t)src->count);
            if (!dst->knots || !dst->ctrl)
                return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying trims");
            /* Trims live in the (u, v) plane; a stray z would only confuse. */
            for (int k = 0; k < src->count; k++)
                dst->ctrl[4 * k + 2] = 0.0;
        }
    }
    return SW_OK;
}

/* Mirrors u (u -> u0 + u1 - u) so du x dv flips: knots reversed and
 * reflected, control columns reversed, trim u coordinates reflected. The
 * geometry and the trimmed region are unchanged as point sets. */
static void stage_reverse(staged *s)
{
    sw_model_surface *o = &s->surface;
    int nk = o->count_u + o->degree_u + 1;
    double a = o->knots_u[0], b = o->knots_u[nk - 1];
    for (int i = 0, j = nk - 1; i <= j; i++, j--) {
        double ki = o->knots_u[i], kj = o->knots_u[j];
        o->knots_u[i] = a + b - kj;
        o->knots_u[j] = a + b - ki;
    }
    for (int row = 0; row < o->count_v; row++) {
        double *r = o->ctrl + (size_t)row * (size_t)o->count_u * 4;
        for (int i = 0, j = o->count_u - 1; i < j; i++, j--)
            for (int k = 0; k < 4; k++) {
                double t = r[4 * i + k];
                r[4 * i + k] = r[4 * j + k];
                r[4 * j + k] = t;
            }
    }
    for (size_t c = 0; c < s->curve_count; c++)
        for (int k = 0; k < s->curves[c].count; k++)
            s->curves[c].ctrl[4 * k] = a + b - s->curves[c].ctrl[4 * k];
    o->reversed = 1;
}

/* Knot insertion into Bezier patches, each with its rectangle of the domain. */
static sw_status stage_split(staged *s, sw_error *err)
{
    sw_nurbs_surface view = sw_model_surface_view(&s->surface);
    sw_nurbs_bezier_sizes sizes = sw_nurbs_surface_bezier_sizes(&view);
    size_t count = (size_t)sizes.pieces_u * (size_t)sizes.pieces_v;
    size_t per = 4 * (size_t)(view.degree_u + 1) * (size_t)(view.degree_v + 1);
    double *ctrl = malloc(sizes.ctrl_doubles * sizeof *ctrl);
    double *params = malloc(sizes.param_doubles * sizeof *params);
    s->patches = calloc(count, sizeof *s->patches);
    sw_status st = SW_OK;
    if (!ctrl || !params || !s->patches)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory splitting a surface");
    if (st == SW_OK)
        st = sw_nurbs_surface_to_bezier(&view, ctrl, params, err);
    for (size_t b = 0; st == SW_OK && b < (size_t)sizes.pieces_v; b++) {
        for (size_t a = 0; st == SW_OK && a < (size_t)sizes.pieces_u; a++) {
            sw_model_patch *p = &s->patches[s->patch_count];
            p->ctrl = copy_doubles(ctrl + (b * (size_t)sizes.pieces_u + a) * per, per);
            if (!p->ctrl) {
                st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying patches");
                break;
            }
            s->patch_count++;
            p->degree_u = view.degree_u, p->degree_v = view.degree_v;
            p->rational = any_weight_not_one(p->ctrl, per / 4);
            p->domain[0] = params[2 * a], p->domain[1] = params[2 * a + 1];
            p->domain[2] = params[2 * (size_t)sizes.pieces_u + 2 * b];
            p->domain[3] = params[2 * (size_t)sizes.pieces_u + 2 * b + 1];
        }
    }
    free(ctrl);
    free(params);
    return st;
}

/* Flattens the staged trims. The polyline tolerance is far below a mask cell
 * (1/32 of the smallest patch side) so masks stay tight, and below 1e-5 of
 * the domain so the restricted domains lose nothing visible. */
static sw_status stage_polyline(const staged *s, sw_trim_polyline *poly, sw_error *err)
{
    const double *d = s->surface.domain;
    double extent = fmax(d[1] - d[0], d[3] - d[2]), smallest = extent;
    for (size_t i = 0; i < s->patch_count; i++) {
        const double *pd = s->patches[i].domain;
        smallest = fmin(smallest, fmin(pd[1] - pd[0], pd[3] - pd[2]));
    }
    double tol = fmin(1e-5 * extent, smallest / 32 / 16);
    sw_model_loop_input *in = calloc(s->loop_count, sizeof *in);
    sw_nurbs_curve *views = calloc(s->curve_count, sizeof *views);
    sw_status st = SW_OK;
    if (!in || !views)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for trim views");
    for (size_t l = 0; st == SW_OK && l < s->loop_count; l++) {
        const sw_model_loop *loop = &s->loops[l];
        in[l] = (sw_model_loop_input){.curves = views + loop->first_curve,
                                      .curve_count = loop->curve_count, .outer = loop->outer};
        for (size_t c = 0; c < loop->curve_count; c++)
            views[loop->first_curve + c] = sw_model_curve_view(&s->curves[loop->first_curve + c]);
    }
    if (st == SW_OK)
        st = sw_trim_polyline_build(in, s->loop_count, tol, 1e-2 * extent, poly, err);
    free(in);
    free(views);
    return st;
}

/* Shrinks patch p to rect (within its domain) by de Casteljau subdivision. */
static sw_status shrink_patch(sw_model_patch *p, const double rect[4], sw_error *err)
{
    const double *d = p->domain;
    if (rect[0] == d[0] && rect[1] == d[1] && rect[2] == d[2] && rect[3] == d[3])
        return SW_OK;
    double *ctrl = malloc(4 * (size_t)(p->degree_u + 1) * (size_t)(p->degree_v + 1) * sizeof *ctrl);
    if (!ctrl)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory shrinking a patch");
    double wu = d[1] - d[0], wv = d[3] - d[2];
    sw_bezier_patch view = sw_model_patch_view(p);
    sw_bezier_subpatch(&view, (rect[0] - d[0]) / wu, (rect[1] - d[0]) / wu, (rect[2] - d[2]) / wv,
                       (rect[3] - d[2]) / wv, ctrl);
    free(p->ctrl);
    p->ctrl = ctrl;
    memcpy(p->domain, rect, sizeof p->domain);
    return SW_OK;
}

/* Keeps the patches that touch the trimmed face, shrunk to the trims' box,
 * with their masks (compacting s->patches in place). */
static sw_status stage_restrict(staged *s, sw_error *err)
{
    sw_trim_polyline poly;
    sw_status st = stage_polyline(s, &poly, err);
    size_t kept = 0;
    for (size_t i = 0; st == SW_OK && i < s->patch_count; i++) {
        sw_model_patch p = s->patches[i];
        double rect[4] = {fmax(p.domain[0], poly.box[0]), fmin(p.domain[1], poly.box[1]),
                          fmax(p.domain[2], poly.box[2]), fmin(p.domain[3], poly.box[3])};
        sw_trim_coverage cover = SW_TRIM_OUTSIDE;
        if (rect[0] < rect[1] && rect[2] < rect[3])
            cover = sw_trim_mask(&poly, rect, p.mask);
        if (cover == SW_TRIM_OUTSIDE) {
            free(p.ctrl);
            continue;
        }
        /* A mask of all ones filters nothing (trims along the domain's border). */
        uint32_t all = 0xFFFFFFFFu;
        for (int j = 0; j < 32; j++)
            all &= p.mask[j];
        p.masked = cover == SW_TRIM_PARTIAL && all != 0xFFFFFFFFu;
        st = shrink_patch(&p, rect, err);
        s->patches[kept++] = p;
        /* On failure the unvisited patches stay listed so staged_free frees them. */
        for (size_t j = i + 1; st != SW_OK && j < s->patch_count; j++)
            s->patches[kept++] = s->patches[j];
    }
    if (st == SW_OK || kept)
        s->patch_count = kept;
    sw_trim_polyline_free(&poly);
    if (st != SW_OK)
        return st;
    if (kept == 0)
        return sw_error_set(err, SW_ERR_FORMAT,
                            "the trim loops enclose no part of the surface's domain "
                            "[%g, %g] x [%g, %g]", s->surface.domain[0], s->surface.domain[1],
                            s->surface.domain[2], s->surface.domain[3]);
    return SW_OK;
}

sw_status sw_model_add_surface(sw_model *model, const sw_nurbs_surface *surface, int reversed,
                               const sw_model_loop_input *loops, size_t loop_count,
                               sw_error *err)
{
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_surface: model is NULL");
    sw_status st = check_input(surface, loops, loop_count, err);
    if (st != SW_OK)
        return st;
    staged s = {0};
    st = stage_copy(&s, surface, loops, loop_count, err);
    if (st == SW_OK && reversed)
        stage_reverse(&s);
    const sw_model_surface *o = &s.surface;
    if (st == SW_OK) {
        double d[4] = {o->knots_u[o->degree_u], o->knots_u[o->count_u],
                       o->knots_v[o->degree_v], o->knots_v[o->count_v]};
        memcpy(s.surface.domain, d, sizeof d);
        st = stage_split(&s, err);
    }
    if (st == SW_OK && loop_count)
        st = stage_restrict(&s, err);
    if (st != SW_OK) {
        staged_free(&s);
        return st;
    }
    return staged_commit(model, &s, err);
}

static void transform_points(double *ctrl, size_t points, const sw_mat4 *m)
{
    for (size_t k = 0; k < points; k++) {
        double *c = ctrl + 4 * k;
        sw_vec3 q = sw_mat4_transform_point(m, sw_v3(c[0], c[1], c[2]));
        c[0] = q.x;
        c[1] = q.y;
        c[2] = q.z;
    }
}

void sw_model_transform_part(sw_model *model, size_t part, const sw_mat4 *m)
{
    if (!model || !m || part >= model->part_count)
        return;
    sw_model_part *p = &model->parts[part];
    for (size_t i = p->first_patch; i < p->first_patch + p->patch_count; i++) {
        sw_model_patch *patch = &model->patches[i];
        transform_points(patch->ctrl, (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1),
                         m);
    }
    /* Trim gaps are lengths: they scale with the placement's mean scale. */
    const double *a = m->m;
    double det = a[0] * (a[5] * a[10] - a[9] * a[6]) - a[4] * (a[1] * a[10] - a[9] * a[2]) +
                 a[8] * (a[1] * a[6] - a[5] * a[2]);
    double scale = cbrt(fabs(det));
    for (size_t i = p->first_surface; i < p->first_surface + p->surface_count; i++) {
        sw_model_surface *s = &model->surfaces[i];
        transform_points(s->ctrl, (size_t)s->count_u * (size_t)s->count_v, m);
        for (size_t l = s->first_loop; l < s->first_loop + s->loop_count; l++)
            for (size_t c = 0; c < model->loops[l].curve_count; c++)
                model->curves[model->loops[l].first_curve + c].gap *= scale;
    }
    sw_mat4 before;
    memcpy(before.m, p->transform, sizeof before.m);
    sw_mat4 after = sw_mat4_mul(m, &before);
    memcpy(p->transform, after.m, sizeof p->transform);
}

sw_status sw_model_add_viewpoint(sw_model *model, const sw_model_viewpoint *view, sw_error *err)
{
    if (!model || !view)
        return sw_error_set(err, SW_ERR_ARG, "sw_model_add_viewpoint: model or view is NULL");
    sw_model_viewpoint v = *view;
    v.name[sizeof v.name - 1] = '\0';
    for (size_t i = 0; i < model->viewpoint_count; i++)
        if (strcmp(model->viewpoints[i].name, v.name) == 0)
            return sw_error_set(err, SW_ERR_FORMAT, "viewpoint \"%s\" is defined twice", v.name);
    sw_status st = RESERVE(model, viewpoints, viewpoint, 1, err);
    if (st != SW_OK)
        return st;
    model->viewpoints[model->viewpoint_count++] = v;
    return SW_OK;
}

sw_bezier_patch sw_model_patch_view(const sw_model_patch *patch)
{
    return (sw_bezier_patch){
        .degree_u = patch->degree_u,
        .degree_v = patch->degree_v,
        .rational = patch->rational,
        .ctrl = patch->ctrl,
    };
}

sw_nurbs_surface sw_model_surface_view(const sw_model_surface *surface)
{
    return (sw_nurbs_surface){
        .degree_u = surface->degree_u,
        .degree_v = surface->degree_v,
        .count_u = surface->count_u,
        .count_v = surface->count_v,
        .knots_u = surface->knots_u,
        .knots_v = surface->knots_v,
        .ctrl = surface->ctrl,
    };
}

sw_nurbs_curve sw_model_curve_view(const sw_model_trim_curve *curve)
{
    return (sw_nurbs_curve){
        .degree = curve->degree,
        .count = curve->count,
        .knots = curve->knots,
        .ctrl = curve->ctrl,
    };
}

/* The box of the control points: it contains every patch (convex hull), which
 * is what culling and camera placement need. */
sw_box sw_model_box(const sw_model *model)
{
    sw_box box = sw_box_empty();
    for (size_t i = 0; model && i < model->patch_count; i++) {
        const sw_model_patch *patch = &model->patches[i];
        size_t n = (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1);
        for (size_t k = 0; k < n; k++) {
            const double *c = patch->ctrl + 4 * k;
            sw_box_add_point(&box, sw_v3(c[0], c[1], c[2]));
        }
    }
    return box;
}
