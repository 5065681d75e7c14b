/* SPDX-License-Identifier: MIT */
/* Branch and bound per surface and per axis direction: a Bezier sub-patch's
 * control points bound its points from above (convex hull property, weights
 * positive), points evaluated inside the trims bound the answer from below,
 * and sub-patches are split until their upper bound is within the tolerance
 * of the best point found or they are flat within it.
 *
 * The lower bound starts at the surface points of the trim polyline's
 * vertices: they lie on the true trimming curves, so on the face, and on a
 * trimmed face the extreme is usually on its boundary. Without them the
 * search only learnt the boundary's extreme from samples of ever smaller
 * sub-patches straddling it (the hammer's 45 faces: 41 s, now well under
 * a second). */
#include "sw_trim_box.h"

#include <math.h>
#include <stdlib.h>

#include "sw_model_trims.h"
#include "sw_trim.h"

enum { MAX_DEPTH = 24, STACK = 4 * MAX_DEPTH + 8 };

typedef struct sub_rect { double s0, s1, t0, t1; int depth; } sub_rect;

typedef struct search {
    const sw_model_patch *patch;
    const sw_trim_polyline *poly;   /* NULL: untrimmed */
    sw_vec3 dir;
    double tolerance;
    double best;                    /* max of dir . S over points known inside */
    double bound;                   /* max over accepted flat sub-patches */
} search;

static double along(sw_vec3 d, sw_vec3 p) { return sw_v3_dot(d, p); }

/* Surface parameters of local patch parameters (s, t) in [0,1]^2. */
static void surface_uv(const sw_model_patch *p, double s, double t, double *u, double *v)
{
    *u = p->domain[0] + s * (p->domain[1] - p->domain[0]);
    *v = p->domain[2] + t * (p->domain[3] - p->domain[2]);
}

static int inside(const search *q, double s, double t)
{
    double u, v;
    surface_uv(q->patch, s, t, &u, &v);
    return !q->poly || sw_trim_point_inside(q->poly, u, v);
}

static sw_trim_coverage classify(const search *q, const sub_rect *r)
{
    if (!q->poly)
        return SW_TRIM_INSIDE;
    double box[4];
    surface_uv(q->patch, r->s0, r->t0, &box[0], &box[2]);
    surface_uv(q->patch, r->s1, r->t1, &box[1], &box[3]);
    return sw_trim_box_classify(q->poly, box);
}

/* Samples the sub-patch's corners and centre that lie inside the trims
 * (all of them when the sub-patch is wholly inside). */
static void sample(search *q, const sw_bezier_patch *whole, const sub_rect *r,
                   sw_trim_coverage coverage)
{
    const double s[5] = { r->s0, r->s1, r->s0, r->s1, 0.5 * (r->s0 + r->s1) };
    const double t[5] = { r->t0, r->t0, r->t1, r->t1, 0.5 * (r->t0 + r->t1) };
    for (int k = 0; k < 5; k++) {
        if (coverage != SW_TRIM_INSIDE && !inside(q, s[k], t[k]))
            continue;
        sw_surface_point sp;
        sw_bezier_eval(whole, s[k], t[k], SW_EVAL_POINT, &sp);
        q->best = fmax(q->best, along(q->dir, sp.p));
    }
}

static void hull_range(const search *q, const sw_bezier_patch *sub, double *lo, double *hi)
{
    size_t n = (size_t)(sub->degree_u + 1) * (size_t)(sub->degree_v + 1);
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        const double *c = sub->ctrl + 4 * i;
        double x = along(q->dir, sw_v3(c[0], c[1], c[2]));
        *lo = fmin(*lo, x);
        *hi = fmax(*hi, x);
    }
}

static void split(sub_rect *stack, int *top, const sub_rect *r)
{
    double sm = 0.5 * (r->s0 + r->s1), tm = 0.5 * (r->t0 + r->t1);
    int d = r->depth + 1;
    stack[(*top)++] = (sub_rect){ r->s0, sm, r->t0, tm, d };
    stack[(*top)++] = (sub_rect){ sm, r->s1, r->t0, tm, d };
    stack[(*top)++] = (sub_rect){ r->s0, sm, tm, r->t1, d };
    stack[(*top)++] = (sub_rect){ sm, r->s1, tm, r->t1, d };
}

/* Depth-first, so the stack holds at most 3 siblings per level. */
static void maximise_patch(search *q)
{
    double ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    sw_bezier_patch whole = sw_model_patch_view(q->patch);
    sub_rect stack[STACK];
    int top = 0;
    stack[top++] = (sub_rect){ 0, 1, 0, 1, 0 };
    while (top > 0) {
        sub_rect r = stack[--top];
        sw_trim_coverage coverage = classify(q, &r);
        if (coverage == SW_TRIM_OUTSIDE)
            continue;
        sw_bezier_subpatch(&whole, r.s0, r.s1, r.t0, r.t1, ctrl);
        sw_bezier_patch sub = { whole.degree_u, whole.degree_v, whole.rational, ctrl };
        double lo, hi;
        hull_range(q, &sub, &lo, &hi);
        if (hi <= fmax(q->best, q->bound) + q->tolerance)
            continue;
        sample(q, &whole, &r, coverage);
        if (hi - lo <= q->tolerance || r.depth >= MAX_DEPTH) {
            q->bound = fmax(q->bound, hi); /* flat and touching the face: hi is near a real point */
            continue;
        }
        split(stack, &top, &r);
    }
}

/* Raises best[d] (directions as in surface_extremes) to the surface points
 * of every polyline vertex, clamped into the domain (trims may stray an ulp
 * outside it). */
static void seed_from_trims(const sw_model_surface *s, const sw_trim_polyline *poly,
                            const double (*dirs)[3], double best[6])
{
    sw_nurbs_surface view = sw_model_surface_view(s);
    size_t n = poly->loop_start[poly->loop_count];
    for (size_t k = 0; k < n; k++) {
        double u = fmin(fmax(poly->points[2 * k], s->domain[0]), s->domain[1]);
        double v = fmin(fmax(poly->points[2 * k + 1], s->domain[2]), s->domain[3]);
        sw_vec3 p = sw_nurbs_surface_point(&view, u, v);
        for (int d = 0; d < 6; d++)
            best[d] = fmax(best[d], along(sw_v3(dirs[d][0], dirs[d][1], dirs[d][2]), p));
    }
}

static sw_status surface_extremes(const sw_model *model, size_t si, double tol, sw_box *box,
                                  sw_error *err)
{
    const sw_model_surface *s = &model->surfaces[si];
    sw_trim_polyline poly = { 0 };
    double uv_tol = 1e-7 * fmax(s->domain[1] - s->domain[0], s->domain[3] - s->domain[2]);
    if (s->loop_count) {
        sw_status st = sw_trim_polyline_from_model(model, si, uv_tol, &poly, err);
        if (st != SW_OK)
            return st;
    }
    static const double dirs[6][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
                                       { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } };
    double best[6] = { -INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY };
    if (s->loop_count)
        seed_from_trims(s, &poly, dirs, best);
    for (int d = 0; d < 6; d++) {
        search q = { NULL, s->loop_count ? &poly : NULL, sw_v3(dirs[d][0], dirs[d][1], dirs[d][2]),
                     tol, best[d], -INFINITY };
        for (size_t p = s->first_patch; p < s->first_patch + s->patch_count; p++) {
            q.patch = &model->patches[p];
            maximise_patch(&q);
        }
        double m = fmax(q.best, q.bound);
        if (!isfinite(m))
            continue;
        double *lo = &box->min.x, *hi = &box->max.x;
        if (d < 3)
            hi[d] = fmax(hi[d], m);
        else
            lo[d - 3] = fmin(lo[d - 3], -m);
    }
    sw_trim_polyline_free(&poly);
    return SW_OK;
}

sw_status sw_model_trimmed_box(const sw_model *model, size_t first_surface, size_t count,
                               double tolerance_mm, sw_box *out, sw_error *err)
{
    if (count == 0) {
        first_surface = 0;
        count = model->surface_count;
    }
    if (first_surface > model->surface_count || count > model->surface_count - first_surface)
        return sw_error_set(err, SW_ERR_ARG, "surfaces %zu..%zu beyond the model's %zu",
                            first_surface, first_surface + count, model->surface_count);
    if (!(tolerance_mm > 0))
        return sw_error_set(err, SW_ERR_ARG, "tolerance must be positive, got %g", tolerance_mm);
    *out = sw_box_empty();
    for (size_t i = first_surface; i < first_surface + count; i++) {
        sw_status st = surface_extremes(model, i, tolerance_mm, out, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}
