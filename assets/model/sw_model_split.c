/* SPDX-License-Identifier: MIT */
/* Surfaces copied whole or in pieces (sw_model_split.h). */
#include "sw_model_split.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A surface as sw_model_add_patch makes it: untrimmed, one span on [0,1]^2. */
static int is_bezier_input(const sw_model_surface *s)
{
    return s->loop_count == 0 && s->count_u == s->degree_u + 1 &&
           s->count_v == s->degree_v + 1 && s->knots_u[0] == 0.0 && s->knots_v[0] == 0.0 &&
           s->knots_u[s->count_u] == 1.0 && s->knots_v[s->count_v] == 1.0;
}

/* s's geometry (already oriented: the stored surface is the
 * reparameterised one) with the loops given, into to's current part. */
static sw_status add_with_loops(sw_model *to, const sw_model_surface *s,
                                const sw_model_trim_curve *curves, const sw_model_loop *loops,
                                size_t loop_count, sw_error *err)
{
    size_t count = 0;
    for (size_t l = 0; l < loop_count; l++)
        count += loops[l].curve_count;
    sw_model_loop_input *in = calloc(loop_count + 1, sizeof *in);
    sw_nurbs_curve *views = calloc(count + 1, sizeof *views);
    int *computed = calloc(count + 1, sizeof *computed);
    double *gaps = calloc(count + 1, sizeof *gaps);
    uint32_t *edges = calloc(count + 1, sizeof *edges);
    sw_status st = SW_OK;
    if (!in || !views || !computed || !gaps || !edges)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory copying a surface");
    for (size_t l = 0, k = 0; st == SW_OK && l < loop_count; l++) {
        in[l] = (sw_model_loop_input){.curves = views + k, .computed = computed + k,
                                      .curve_count = loops[l].curve_count, .outer = loops[l].outer,
                                      .gaps = gaps + k, .edges = edges + k};
        for (size_t c = 0; c < loops[l].curve_count; c++, k++) {
            const sw_model_trim_curve *curve = &curves[loops[l].first_curve + c];
            views[k] = sw_model_curve_view(curve);
            computed[k] = curve->computed;
            gaps[k] = curve->gap;
            edges[k] = curve->edge;
        }
    }
    if (st == SW_OK) {
        sw_nurbs_surface view = sw_model_surface_view(s);
        st = sw_model_add_surface(to, &view, 0, in, loop_count, err);
    }
    if (st == SW_OK)
        to->surfaces[to->surface_count - 1].reversed = s->reversed;
    free(in);
    free(views);
    free(computed);
    free(gaps);
    free(edges);
    return st;
}

sw_status sw_model_copy_surface(const sw_model *from, size_t s, sw_model *to, sw_error *err)
{
    const sw_model_surface *surface = &from->surfaces[s];
    if (is_bezier_input(surface))
        return sw_model_add_patch(to, surface->degree_u, surface->degree_v, surface->rational,
                                  surface->ctrl, err);
    return add_with_loops(to, surface, from->curves, from->loops + surface->first_loop,
                          surface->loop_count, err);
}

sw_status sw_model_cut_surface(const sw_model *model, size_t s, int axis, const double *at,
                               size_t count, sw_trim_set *pieces, sw_error *err)
{
    const double *d = model->surfaces[s].domain;
    /* Crossings closer than this to a curve's end are refused: a billionth
     * of the domain, far above rounding and far below any real feature. */
    double tol = 1e-9 * fmax(fabs(d[1] - d[0]), fabs(d[3] - d[2]));
    sw_trim_set rest = {0};
    sw_status st = sw_trim_set_of_surface(model, s, &rest, err);
    for (size_t i = 0; st == SW_OK && i < count; i++) {
        sw_trim_set high = {0};
        st = sw_trim_clip(&rest, axis, at[i], tol, &pieces[i], &high, err);
        sw_trim_set_free(&rest);
        rest = high;
    }
    if (st == SW_OK)
        pieces[count] = rest;
    else
        sw_trim_set_free(&rest);
    for (size_t i = 0; st != SW_OK && i <= count; i++)
        sw_trim_set_free(&pieces[i]);
    return st;
}

static sw_status copy_part(const sw_model *in, size_t p, const sw_model_cut *cuts,
                           size_t cut_count, size_t *next_cut, sw_model *out, sw_error *err)
{
    const sw_model_part *part = &in->parts[p];
    sw_status st = sw_model_begin_part(out, part->name, part->color, err);
    if (st == SW_OK)
        memcpy(out->parts[out->part_count - 1].transform, part->transform,
               sizeof part->transform);
    for (size_t i = 0; st == SW_OK && i < part->surface_count; i++) {
        size_t s = part->first_surface + i;
        while (*next_cut < cut_count && cuts[*next_cut].surface < s)
            ++*next_cut;
        if (*next_cut == cut_count || cuts[*next_cut].surface != s) {
            st = sw_model_copy_surface(in, s, out, err);
            continue;
        }
        const sw_model_cut *c = &cuts[*next_cut];
        for (size_t k = 0; st == SW_OK && k < c->piece_count; k++)
            if (c->pieces[k].loop_count > 0)
                st = add_with_loops(out, &in->surfaces[s], c->pieces[k].curves,
                                    c->pieces[k].loops, c->pieces[k].loop_count, err);
    }
    return st;
}

sw_status sw_model_split(const sw_model *in, const sw_model_cut *cuts, size_t cut_count,
                         sw_model *out, sw_error *err)
{
    sw_status st = SW_OK;
    size_t next_cut = 0;
    for (size_t p = 0; st == SW_OK && p < in->part_count; p++)
        st = copy_part(in, p, cuts, cut_count, &next_cut, out, err);
    for (size_t v = 0; st == SW_OK && v < in->viewpoint_count; v++)
        st = sw_model_add_viewpoint(out, &in->viewpoints[v], err);
    out->model_tolerance = in->model_tolerance;
    out->up_axis = in->up_axis;
    return st;
}
