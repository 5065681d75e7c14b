/* SPDX-License-Identifier: MIT */
/* The sewing driver (sw_sew.h): per-vertex loops and arc lengths, then the
 * three steps of sw_sew_internal.h in order. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_sew_internal.h"

sw_status sw_sew_polylines(const sw_seam_polylines *poly, double tolerance, sw_seam_host *out,
                           sw_sew_counts *counts, sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "sw_sew_polylines: out is NULL");
    memset(out, 0, sizeof *out);
    if (counts)
        memset(counts, 0, sizeof *counts);
    if (!poly || !(tolerance > 0) || !isfinite(tolerance))
        return sw_error_set(err, SW_ERR_ARG, "sw_sew_polylines: poly is NULL or tolerance %g is "
                                             "not a positive number", tolerance);
    if (poly->vertex_count >= UINT32_MAX / 4 || poly->surface_count >= UINT32_MAX)
        return sw_error_set(err, SW_ERR_RANGE, "sewing: %zu vertices, at most %u fit a Seam Graph",
                            poly->vertex_count, UINT32_MAX / 4 - 1);
    sew_state s = {.poly = poly, .tol = tolerance, .err = err};
    for (size_t v = 0; poly->gap && v < poly->vertex_count; v++)
        s.max_gap = fmax(s.max_gap, poly->gap[v]);
    s.vertex_loop = malloc((poly->vertex_count + 1) * sizeof *s.vertex_loop);
    sw_status st = s.vertex_loop ? SW_OK
                                 : sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory");
    s.arc = malloc((poly->vertex_count + 1) * sizeof *s.arc);
    if (st == SW_OK && !s.arc)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory");
    for (size_t l = 0; st == SW_OK && l < poly->loop_count; l++)
        for (size_t v = poly->loop_start[l]; v < poly->loop_start[l + 1]; v++) {
            s.vertex_loop[v] = (uint32_t)l;
            const double *p = poly->p + 3 * v, *q = poly->p + 3 * (v > poly->loop_start[l] ? v - 1 : v);
            s.arc[v] = (v > poly->loop_start[l] ? s.arc[v - 1] : 0.0) +
                       sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                            (p[2] - q[2]) * (p[2] - q[2]));
        }
    if (st == SW_OK)
        st = sew_project(&s);
    if (st == SW_OK)
        st = sew_intervals(&s);
    if (st == SW_OK)
        st = sew_merge(&s, out, counts);
    if (counts) {
        counts->projections = s.match_count;
        counts->intervals = s.intervals;
    }
    free(s.vertex_loop);
    free(s.arc);
    free(s.matches);
    free(s.joins);
    if (st != SW_OK)
        sw_seam_host_free(out);
    return st;
}
