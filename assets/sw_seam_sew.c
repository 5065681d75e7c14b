/* The model's original Seam Graph: flatten, then sew (sw_seam_sew.h). */
#include "sw_seam_sew.h"

#include <math.h>
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

double sw_seam_default_tolerance(const sw_model *model, const sw_seam_options *opt)
{
    if (opt && opt->tolerance > 0)
        return opt->tolerance;
    sw_box box = sw_model_box(model);
    double diag = sw_box_is_empty(&box) ? 0 : sw_box_diagonal(&box);
    if (!(model->model_tolerance > 0))
        return diag > 0 ? 1e-5 * diag : 1e-3;
    return fmax((double)model->model_tolerance, 1e-5 * diag);
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
            .tolerance = tol, .unproven_pieces = poly.unproven, .inserted = counts.inserted,
            .flatten_s = t1 - t0, .sew_s = t2 - t1};
    sw_seam_polylines_free(&poly);
    return st;
}
