/* SPDX-License-Identifier: MIT */
#include "sw_model_trims.h"

#include <math.h>
#include <stdlib.h>

sw_status sw_trim_polyline_from_model(const sw_model *model, size_t surface, double tolerance,
                                      sw_trim_polyline *out, sw_error *err)
{
    if (!model || surface >= model->surface_count)
        return sw_error_set(err, SW_ERR_ARG, "sw_trim_polyline_from_model: no surface %zu",
                            surface);
    const sw_model_surface *s = &model->surfaces[surface];
    size_t curves = 0;
    for (size_t l = 0; l < s->loop_count; l++)
        curves += model->loops[s->first_loop + l].curve_count;
    sw_model_loop_input *in = calloc(s->loop_count + 1, sizeof *in);
    sw_nurbs_curve *views = calloc(curves + 1, sizeof *views);
    sw_status st = SW_OK;
    if (!in || !views)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory for trim views");
    for (size_t l = 0, k = 0; st == SW_OK && l < s->loop_count; l++) {
        const sw_model_loop *loop = &model->loops[s->first_loop + l];
        in[l] = (sw_model_loop_input){.curves = views + k, .curve_count = loop->curve_count,
                                      .outer = loop->outer};
        for (size_t c = 0; c < loop->curve_count; c++)
            views[k++] = sw_model_curve_view(&model->curves[loop->first_curve + c]);
    }
    if (st == SW_OK)
        st = sw_trim_polyline_build(in, s->loop_count, tolerance, -1, out, err);
    free(in);
    free(views);
    return st;
}

sw_status sw_trim_model_surface_area(const sw_model *model, size_t surface, double rel_tol,
                                     double *area_out, sw_error *err)
{
    if (!model || surface >= model->surface_count || !area_out || !(rel_tol >= 1e-12))
        return sw_error_set(err, SW_ERR_ARG, "sw_trim_model_surface_area: bad argument");
    const sw_model_surface *s = &model->surfaces[surface];
    sw_nurbs_surface view = sw_model_surface_view(s);
    if (s->loop_count == 0)
        return sw_trim_area(&view, NULL, rel_tol, area_out, err);
    /* The chords cut off about tolerance x perimeter of parameter area, a
     * relative error near tolerance x perimeter / area: an eighth of rel_tol
     * times the domain size keeps that below rel_tol for faces that are not
     * slivers. */
    double extent = fmax(s->domain[1] - s->domain[0], s->domain[3] - s->domain[2]);
    sw_trim_polyline poly;
    sw_status st = sw_trim_polyline_from_model(model, surface, rel_tol * extent / 8, &poly, err);
    if (st != SW_OK)
        return st;
    st = sw_trim_area(&view, &poly, rel_tol / 8, area_out, err);
    sw_trim_polyline_free(&poly);
    return st;
}
