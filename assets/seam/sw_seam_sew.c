/* SPDX-License-Identifier: MIT */
/* The model's original Seam Graph: flatten, then sew (sw_seam_sew.h). */
#include "sw_seam_sew.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_seam_flatten.h"
#include "sw_sew.h"

static double now_s(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The box diagonal of the smallest part that has patches (of the whole model
 * when there are no parts, or no memory to tell them apart): a showroom's
 * tolerance must not follow the hall's size, or its small parts would be
 * sewn shut. 0 when empty. */
static double smallest_part_size(const sw_model *model)
{
    sw_box *boxes = model->part_count ? malloc(model->part_count * sizeof *boxes) : NULL;
    double smallest = INFINITY;
    for (size_t part = 0; boxes && part < model->part_count; part++)
        boxes[part] = sw_box_empty();
    for (size_t i = 0; boxes && i < model->patch_count; i++) {
        const sw_model_patch *patch = &model->patches[i];
        size_t n = (size_t)(patch->degree_u + 1) * (size_t)(patch->degree_v + 1);
        for (size_t k = 0; patch->part < model->part_count && k < n; k++)
            sw_box_add_point(&boxes[patch->part], sw_v3(patch->ctrl[4 * k], patch->ctrl[4 * k + 1],
                                                         patch->ctrl[4 * k + 2]));
    }
    for (size_t part = 0; boxes && part < model->part_count; part++)
        if (!sw_box_is_empty(&boxes[part]))
            smallest = fmin(smallest, sw_box_diagonal(&boxes[part]));
    free(boxes);
    if (isfinite(smallest))
        return smallest;
    sw_box box = sw_model_box(model);
    return sw_box_is_empty(&box) ? 0 : sw_box_diagonal(&box);
}

double sw_seam_default_tolerance(const sw_model *model, const sw_seam_options *opt)
{
    if (opt && opt->tolerance > 0)
        return opt->tolerance;
    sw_box box = sw_model_box(model);
    double whole = sw_box_is_empty(&box) ? 0 : sw_box_diagonal(&box);
    /* Below a millionth of the model, float positions no longer tell the
     * two sides of a seam apart. */
    double floats = 1e-6 * whole;
    /* A file that states its tolerance is taken at its word: where its faces
     * meet less closely, each trim's gap (its edge tolerance) widens the
     * sewing there, not everywhere. A file that states none (Newell, .bpt)
     * is sewn at 1e-5 of its smallest part. */
    if (model->model_tolerance > 0)
        return fmax((double)model->model_tolerance, floats);
    double floor = fmax(1e-5 * smallest_part_size(model), floats);
    return floor > 0 ? floor : 1e-3;
}

/* The diagonal of the box of vertices [from, to) of poly. */
static double box_size(const sw_seam_polylines *poly, size_t from, size_t to)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t v = from; v < to; v++)
        for (int i = 0; i < 3; i++)
            lo[i] = fmin(lo[i], poly->p[3 * v + i]), hi[i] = fmax(hi[i], poly->p[3 * v + i]);
    if (to <= from)
        return 0;
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/* Trim gaps held to SW_SEAM_GAP_CAP of the model's box and of their own
 * surface's loops' box: a file's edge tolerance says how far the edge may
 * stray from the faces, and a border is sewn within it; but shape healing
 * left edges of printer parts at 3.4 and 6 mm on 70 and 41 mm parts, and
 * their vertices were sewn into every border within that (one into a
 * circle 390 times, 3.7 mm off), folding the faces' loops; and a threaded
 * hole 3 mm across in a 350 mm printer bed, its edges that loose, had its
 * helix sewn onto itself across the turns (816 points of its loop onto one
 * vertex), which the model's cap alone allowed. OpenCASCADE sews those
 * files at the pack's tolerance. The caps keep what real files need (the
 * boxed sphere's gaps reach 3.4e-3 of its size, and it sews shut only with
 * them). Loops are stored surface by surface. Returns the vertices held. */
static size_t hold_gaps(sw_seam_polylines *poly)
{
    if (!poly->gap || poly->vertex_count == 0)
        return 0;
    double model_cap = SW_SEAM_GAP_CAP * box_size(poly, 0, poly->vertex_count);
    size_t held = 0;
    for (size_t s = 0; s < poly->surface_count; s++) {
        size_t from = poly->loop_start[poly->surface_loops[s]];
        size_t to = poly->loop_start[poly->surface_loops[s + 1]];
        float cap = (float)fmin(model_cap, SW_SEAM_GAP_CAP * box_size(poly, from, to));
        for (size_t v = from; v < to; v++)
            if (poly->gap[v] > cap)
                poly->gap[v] = cap, held++;
    }
    return held;
}

sw_status sw_seam_sew_model(const sw_model *model, const sw_seam_options *opt, sw_seam_host *out,
                            sw_seam_report *report, sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_sew_model: out is NULL");
    memset(out, 0, sizeof *out);
    if (report)
        memset(report, 0, sizeof *report);
    if (!model)
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_sew_model: model is NULL");
    if (opt && (!(opt->tolerance >= 0) || !isfinite(opt->tolerance)))
        return sw_error_set(err, SW_ERR_ARG, "sw_seam_sew_model: tolerance %g: expected >= 0 "
                                             "(0: the model's)", opt->tolerance);
    double tol = sw_seam_default_tolerance(model, opt);
    double t0 = now_s();
    sw_seam_polylines poly;
    sw_status st = sw_seam_flatten_model(model, tol, &poly, err);
    size_t gaps_held = st == SW_OK ? hold_gaps(&poly) : 0;
    double t1 = now_s();
    sw_sew_counts counts = {0};
    if (st == SW_OK)
        st = sw_sew_polylines(&poly, tol, out, &counts, err);
    double t2 = now_s();
    if (st == SW_OK && report)
        *report = (sw_seam_report){
            .loops = out->loop_count, .boundary_vertices = out->vertex_count,
            .boundary_edges = out->edge_count, .seams = counts.seams,
            .free_edges = counts.free_edges, .nonmanifold_edges = counts.nonmanifold_edges,
            .tolerance = tol, .unproven_pieces = poly.unproven, .clamped = poly.clamped,
            .gaps_held = gaps_held,
            .inserted = counts.inserted,
            .flatten_s = t1 - t0, .sew_s = t2 - t1};
    sw_seam_polylines_free(&poly);
    return st;
}
