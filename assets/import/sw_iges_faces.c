/* SPDX-License-Identifier: MIT */
/* Faces as the IGES reader collects them before they go into the model:
 * a surface and its trimming loops in the surface's parameter space, loops
 * closed across small gaps, natural boundaries, parameter curves mapped from
 * the entity's parameterisation or computed from model-space curves by point
 * inversion (sw_pcurve). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

void iges_face_free(iges_face *f)
{
    iges_surface_free(&f->surface);
    for (int i = 0; i < f->loop_count; i++) {
        iges_curves_free(&f->loops[i].curves);
        free(f->loops[i].computed);
    }
    free(f->loops);
    if (f->ps_ready)
        sw_pcurve_surface_free(&f->ps);
    memset(f, 0, sizeof *f);
}

void iges_faces_free(iges_faces *list)
{
    for (int i = 0; i < list->count; i++)
        iges_face_free(&list->items[i]);
    free(list->items);
    memset(list, 0, sizeof *list);
}

sw_status iges_faces_push(iges_reader *r, iges_faces *list, iges_face *f)
{
    if (f->ps_ready) {
        sw_pcurve_surface_free(&f->ps);   /* only needed while reading the face */
        f->ps_ready = 0;
    }
    if (list->count == list->cap) {
        int cap = list->cap ? 2 * list->cap : 16;
        iges_face *bigger = realloc(list->items, (size_t)cap * sizeof *bigger);
        if (!bigger) {
            iges_face_free(f);
            return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory for faces",
                                r->file);
        }
        list->items = bigger, list->cap = cap;
    }
    list->items[list->count++] = *f;
    memset(f, 0, sizeof *f);
    return SW_OK;
}

static sw_vec3 curve_end(const iges_curve *c, int at_end)
{
    const double *p = c->ctrl + (at_end ? (size_t)(c->count - 1) * 4 : 0);
    return sw_v3(p[0], p[1], 0);
}

/* Bridges the gaps between consecutive curves (collapsed edges at poles
 * have no curve in some files) with parameter-space lines. */
static sw_status close_gaps(iges_reader *r, const iges_face *f, iges_curves *in, int **computed)
{
    const iges_surface *s = &f->surface;
    double eps = 1e-9 * (s->knots_u[s->count_u] - s->knots_u[s->degree_u] +
                         s->knots_v[s->count_v] - s->knots_v[s->degree_v]);
    iges_curves out = {0};
    int *flags = calloc((size_t)in->count * 2 + 1, sizeof *flags);
    sw_status st = flags ? SW_OK : sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory",
                                                r->file);
    int n = in->count;
    sw_vec3 first = curve_end(&in->items[0], 0);
    for (int i = 0; st == SW_OK && i < n; i++) {
        sw_vec3 a = curve_end(&in->items[i], 1);
        sw_vec3 b = i + 1 < n ? curve_end(&in->items[i + 1], 0) : first;
        flags[out.count] = (*computed) ? (*computed)[i] : 0;
        st = iges_curves_push(r, &out, &in->items[i]);
        if (st == SW_OK && sw_v3_length(sw_v3_sub(a, b)) > eps) {
            iges_curve line;
            st = iges_curve_line(r, &line, a, b, 0.0, 1.0);
            if (st == SW_OK)
                st = iges_curves_push(r, &out, &line);
        }
    }
    for (int i = 0; i < n; i++)
        if (in->items[i].knots)
            iges_curve_free(&in->items[i]);
    in->count = 0;
    iges_curves_free(in);
    free(*computed);
    *computed = flags;
    *in = out;
    if (st != SW_OK) {
        iges_curves_free(in);
        free(*computed);
        *computed = NULL;
    }
    return st;
}

sw_status iges_face_add_loop(iges_reader *r, iges_face *f, iges_curves *curves,
                             const int *computed, int outer)
{
    int *flags = calloc((size_t)curves->count + 1, sizeof *flags);
    if (!flags) {
        iges_curves_free(curves);
        return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory", r->file);
    }
    if (computed)
        memcpy(flags, computed, (size_t)curves->count * sizeof *flags);
    if (curves->count == 0) {
        free(flags);
        return iges_fail_entity(r, f->entity, SW_ERR_FORMAT,
                                "expected a trimming loop with curves, found none");
    }
    sw_status st = close_gaps(r, f, curves, &flags);
    if (st == SW_OK && f->loop_count == f->loop_cap) {
        int cap = f->loop_cap ? 2 * f->loop_cap : 4;
        iges_loop *bigger = realloc(f->loops, (size_t)cap * sizeof *bigger);
        if (!bigger)
            st = sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory", r->file);
        else
            f->loops = bigger, f->loop_cap = cap;
    }
    if (st != SW_OK) {
        iges_curves_free(curves);
        free(flags);
        return st;
    }
    f->loops[f->loop_count++] = (iges_loop){*curves, flags, outer};
    memset(curves, 0, sizeof *curves);
    return SW_OK;
}

sw_status iges_face_add_domain_loop(iges_reader *r, iges_face *f)
{
    const iges_surface *s = &f->surface;
    double u0 = s->knots_u[s->degree_u], u1 = s->knots_u[s->count_u];
    double v0 = s->knots_v[s->degree_v], v1 = s->knots_v[s->count_v];
    sw_vec3 c[4] = {sw_v3(u0, v0, 0), sw_v3(u1, v0, 0), sw_v3(u1, v1, 0), sw_v3(u0, v1, 0)};
    iges_curves loop = {0};
    sw_status st = SW_OK;
    for (int i = 0; i < 4 && st == SW_OK; i++) {
        iges_curve line;
        st = iges_curve_line(r, &line, c[i], c[(i + 1) % 4], 0.0, 1.0);
        if (st == SW_OK)
            st = iges_curves_push(r, &loop, &line);
    }
    if (st != SW_OK) {
        iges_curves_free(&loop);
        return st;
    }
    return iges_face_add_loop(r, f, &loop, NULL, 1);
}

static sw_status face_ps(iges_reader *r, iges_face *f)
{
    if (f->ps_ready)
        return SW_OK;
    sw_nurbs_surface v = iges_surface_view(&f->surface);
    sw_status st = sw_pcurve_surface_init(&f->ps, &v, r->err);
    if (st != SW_OK) {
        sw_error_prefix(r->err, "%s: D line %d", r->file, iges_de(f->entity));
        return st;
    }
    f->ps_ready = 1;
    return SW_OK;
}

static int model_point(void *user, double t, sw_vec3 *p, double uv[2])
{
    const iges_curve *c = user;
    sw_nurbs_curve v = iges_curve_view(c);
    *p = sw_nurbs_curve_point(&v, t);
    (void)uv;
    return 0;
}

/* The first knot after t where the curve may have a corner (a knot of
 * multiplicity at least its degree), or its end. */
static double next_corner(const iges_curve *c, double t)
{
    double end = c->knots[c->count];
    for (int k = c->degree + 1; k < c->count; k++) {
        if (!(c->knots[k] > t) || c->knots[k] >= end)
            continue;
        int mult = 1;
        while (k + mult < c->count + c->degree + 1 && c->knots[k + mult] == c->knots[k])
            mult++;
        if (mult >= c->degree)
            return c->knots[k];
    }
    return end;
}

/* The tolerance a face's parameter curves are fitted within: the file's
 * (or the option's), but never below what the fit can reach on this face.
 * Files state resolutions like 1e-8 that point inversion on a surface of
 * revolution cannot meet (1.2e-7 on a real impeller); a millionth of the
 * face's size is far below what anyone sees and well above double rounding. */
enum { IGES_FIT_RELATIVE_INV = 1000000 };
static double fit_tolerance(const iges_reader *r, const iges_face *f)
{
    const iges_surface *s = &f->surface;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < s->count_u * s->count_v; i++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], s->ctrl[4 * i + k]), hi[k] = fmax(hi[k], s->ctrl[4 * i + k]);
    double size = 0;
    for (int k = 0; k < 3; k++)
        size = fmax(size, hi[k] - lo[k]);
    return fmax(r->tol, size / IGES_FIT_RELATIVE_INV);
}

/* A trim with no parameter curve within the tolerance: its face cannot be
 * used, the file can (the face is skipped and counted, an error when
 * strict; the message keeps the D line and the distances). */
static sw_status fit_failed(iges_reader *r, int entity, sw_status st)
{
    if (st != SW_ERR_RANGE)
        return st;
    r->unsupported_type = r->ents[entity].type;
    r->unsupported_why = "no parameter curve within tolerance";
    return SW_ERR_UNSUPPORTED;
}

/* A fit result as one of our curves (taking its arrays). */
static sw_status take_fit(iges_reader *r, sw_pcurve_result *fit, iges_curves *out)
{
    iges_curve c = {fit->degree, fit->count, fit->knots, fit->ctrl,
                    fit->max_gap + fit->max_error};
    fit->knots = fit->ctrl = NULL;
    return iges_curves_push(r, out, &c);
}

sw_status iges_compute_pcurves(iges_reader *r, iges_face *f, const iges_curves *model,
                               iges_curves *out, int entity)
{
    sw_status st = face_ps(r, f);
    for (int i = 0; st == SW_OK && i < model->count; i++) {
        const iges_curve *c = &model->items[i];
        /* One fit per smooth piece, as for mapped trims. */
        for (double t0 = c->knots[c->degree]; st == SW_OK && t0 < c->knots[c->count];) {
            double t1 = next_corner(c, t0);
            sw_pcurve_target tg = {model_point, (void *)c, t0, t1};
            sw_pcurve_result fit;
            st = sw_pcurve_fit(&f->ps, &tg, fit_tolerance(r, f), &fit, r->err);
            if (st != SW_OK) {
                sw_error_prefix(r->err, "%s: D line %d (type %d): model-space curve %d", r->file,
                                iges_de(entity), r->ents[entity].type, i + 1);
                return fit_failed(r, entity, st);
            }
            st = take_fit(r, &fit, out);
            t0 = t1;
        }
        if (st == SW_OK && r->report)
            r->report->pcurves_computed++;
    }
    return st;
}

/* A 120's trims are written in (t, angle); ours runs along the rational arc
 * pieces: map exactly at samples and refit within the tolerance. */
typedef struct angle_trim {
    const iges_curve *c;
    const iges_face *f;
} angle_trim;

static int angle_point(void *user, double t, sw_vec3 *p, double uv[2])
{
    const angle_trim *a = user;
    sw_nurbs_curve v = iges_curve_view(a->c);
    sw_vec3 q = sw_nurbs_curve_point(&v, t);
    const iges_surface *s = &a->f->surface;
    double ang = q.y < s->angle_start ? s->angle_start : q.y > s->angle_end ? s->angle_end : q.y;
    uv[0] = q.x;   /* mapped already */
    uv[1] = iges_arc_param(s->angle_start, s->angle_end, ang);
    sw_surface_point sp;
    sw_pcurve_surface_eval(&a->f->ps, uv[0], uv[1], SW_EVAL_POINT, &sp);
    *p = sp.p;
    return 1;
}

sw_status iges_map_trims(iges_reader *r, iges_face *f, iges_curves *trims, int entity)
{
    const iges_surface *s = &f->surface;
    for (int i = 0; i < trims->count; i++) {
        iges_curve *c = &trims->items[i];
        for (int k = 0; k < c->count; k++) {
            double *q = c->ctrl + 4 * k;
            q[0] = s->map_u[0] + s->map_u[1] * q[0];
            q[1] = s->angle_v ? q[1] : s->map_v[0] + s->map_v[1] * q[1];
            q[2] = 0;
        }
    }
    if (!s->angle_v)
        return SW_OK;
    sw_status st = face_ps(r, f);
    iges_curves mapped = {0};
    for (int i = 0; st == SW_OK && i < trims->count; i++) {
        iges_curve *c = &trims->items[i];
        angle_trim a = {c, f};
        /* One fit per smooth piece: a fit across a corner (a polyline
         * trim's) rounds it off by more than any tolerance. */
        double t0 = c->knots[c->degree], end = c->knots[c->count];
        while (st == SW_OK && t0 < end) {
            double t1 = next_corner(c, t0);
            sw_pcurve_target tg = {angle_point, &a, t0, t1};
            sw_pcurve_result fit;
            st = sw_pcurve_fit(&f->ps, &tg, fit_tolerance(r, f), &fit, r->err);
            if (st != SW_OK) {
                sw_error_prefix(r->err, "%s: D line %d (type %d): trim on a surface of revolution",
                                r->file, iges_de(entity), r->ents[entity].type);
                st = fit_failed(r, entity, st);
            } else
                st = take_fit(r, &fit, &mapped);
            t0 = t1;
        }
    }
    iges_curves_free(trims);
    *trims = mapped;
    if (st != SW_OK)
        iges_curves_free(trims);
    return st;
}

/* ---- loops under construction ------------------------------------- */

sw_status iges_loop_take(iges_reader *r, iges_loop_build *lb, iges_curves *group, int computed)
{
    int need = lb->curves.count + group->count;
    if (need > lb->cap) {
        int cap = need * 2;
        int *bigger = realloc(lb->flags, (size_t)cap * sizeof *bigger);
        if (!bigger) {
            iges_curves_free(group);
            return sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory", r->file);
        }
        lb->flags = bigger, lb->cap = cap;
    }
    for (int i = lb->curves.count; i < need; i++)
        lb->flags[i] = computed;
    return iges_curves_append(r, &lb->curves, group);
}

sw_status iges_loop_finish(iges_reader *r, iges_face *f, iges_loop_build *lb, sw_status st,
                             int outer)
{
    if (st == SW_OK)
        st = iges_face_add_loop(r, f, &lb->curves, lb->flags, outer);
    iges_curves_free(&lb->curves);
    free(lb->flags);
    memset(lb, 0, sizeof *lb);
    return st;
}

void iges_reverse_group(iges_curves *g)
{
    for (int i = 0; i < g->count / 2; i++) {
        iges_curve t = g->items[i];
        g->items[i] = g->items[g->count - 1 - i];
        g->items[g->count - 1 - i] = t;
    }
    for (int i = 0; i < g->count; i++)
        iges_curve_reverse(&g->items[i]);
}

/* Parameter curves of a model-space curve entity, computed by inversion;
 * outer is the transform of the entities above it (144/143 and 142/141). */
sw_status iges_computed_group(iges_reader *r, iges_face *f, int curve, const sw_mat4 *outer,
                                int owner, iges_curves *out)
{
    iges_curves model = {0};
    sw_status st = iges_read_curve(r, curve, &model);
    for (int i = 0; st == SW_OK && i < model.count; i++)
        iges_curve_transform(&model.items[i], outer);
    if (st == SW_OK)
        st = iges_compute_pcurves(r, f, &model, out, owner);
    iges_curves_free(&model);
    return st;
}

/* Parameter curves as written, mapped into the surface's parameters. An
 * unsupported curve type leaves SW_ERR_UNSUPPORTED for the caller to fall
 * back on the model-space curve. */
sw_status iges_written_group(iges_reader *r, iges_face *f, int curve, int owner,
                               iges_curves *out)
{
    sw_status st = iges_read_curve(r, curve, out);
    if (st == SW_OK)
        st = iges_map_trims(r, f, out, owner);
    if (st != SW_OK)
        iges_curves_free(out);
    return st;
}


/* ---- how far written trims stray from their model-space curves --------- */

enum { GAP_SAMPLES = 129 };

/* The model-space curves as a polyline of GAP_SAMPLES points each. */
static sw_vec3 *sample_model(const iges_curves *model, size_t *n)
{
    sw_vec3 *pts = malloc(((size_t)model->count * GAP_SAMPLES + 1) * sizeof *pts);
    *n = 0;
    for (int i = 0; pts && i < model->count; i++) {
        const iges_curve *c = &model->items[i];
        sw_nurbs_curve v = iges_curve_view(c);
        double t0 = c->knots[c->degree], t1 = c->knots[c->count];
        for (int k = 0; k < GAP_SAMPLES; k++)
            pts[(*n)++] = sw_nurbs_curve_point(&v, t0 + (t1 - t0) * k / (GAP_SAMPLES - 1));
    }
    return pts;
}

static double polyline_distance(const sw_vec3 *pts, size_t n, sw_vec3 p)
{
    double best = INFINITY;
    for (size_t k = 0; k + 1 < n; k++)
        best = fmin(best, sw_v3_segment_distance(p, pts[k], pts[k + 1]));
    return n == 1 ? sw_v3_length(sw_v3_sub(p, pts[0])) : best;
}

sw_status iges_measure_gap(iges_reader *r, iges_face *f, int model_curve, const sw_mat4 *m,
                           iges_curves *uv)
{
    iges_curves model = {0};
    if (iges_read_curve(r, model_curve, &model) != SW_OK) {
        r->err->status = SW_OK;   /* the written trims stand; no gap known */
        return SW_OK;
    }
    for (int i = 0; i < model.count; i++)
        iges_curve_transform(&model.items[i], m);
    size_t n = 0;
    sw_vec3 *pts = sample_model(&model, &n);
    sw_status st = pts ? face_ps(r, f) : sw_error_set(r->err, SW_ERR_NO_MEMORY, "%s: out of memory",
                                                     r->file);
    double gap = 0;
    for (int i = 0; st == SW_OK && n > 0 && i < uv->count; i++) {
        const iges_curve *c = &uv->items[i];
        sw_nurbs_curve v = iges_curve_view(c);
        double t0 = c->knots[c->degree], t1 = c->knots[c->count];
        for (int k = 0; k < GAP_SAMPLES; k++) {
            sw_vec3 q = sw_nurbs_curve_point(&v, t0 + (t1 - t0) * k / (GAP_SAMPLES - 1));
            sw_surface_point on;
            sw_pcurve_surface_eval(&f->ps, q.x, q.y, SW_EVAL_POINT, &on);
            gap = fmax(gap, polyline_distance(pts, n, on.p));
        }
    }
    for (int i = 0; st == SW_OK && i < uv->count; i++)
        uv->items[i].gap = fmax(uv->items[i].gap, gap);
    free(pts);
    iges_curves_free(&model);
    return st;
}
