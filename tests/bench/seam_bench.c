/* SPDX-License-Identifier: MIT */
/* seam_bench: the original Seam Graph (flatten + sew, sw_seam_sew.h) of CAD
 * files: time per stage, peak memory, and the report's counts, as a table and
 * one JSON line per model. Newell listings (.txt) by the Newell importer,
 * IGES (.igs, .iges) by the native importer, STEP (.stp, .step) through
 * OpenCASCADE. Run one file per process for a clean peak-memory figure
 * (ru_maxrss is the process's peak, including the import).
 *
 * --check also measures the flattened polylines against the exact trims:
 * every trim curve sampled at 200 points, mapped through its surface, and its
 * largest distance to the loop's 3D polyline reported as a fraction of the
 * tolerance (the flattener promises at most 1).
 *
 *   seam_bench [--tolerance MM] [--check] FILE...
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>

#include "sw_import_iges.h"
#include "sw_import_newell.h"
#include "sw_import_occt.h"
#include "sw_math.h"
#include "sw_seam_flatten.h"
#include "sw_seam_sew.h"

static int has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n >= e && strcasecmp(path + n - e, ext) == 0;
}

static sw_status import(const char *path, sw_model *model, sw_error *err)
{
    sw_import_options io = {0};
    sw_import_report ir;
    if (has_ext(path, ".txt"))
        return sw_import_newell_file(path, model, err);
    if (has_ext(path, ".igs") || has_ext(path, ".iges"))
        return sw_import_iges_file(path, &io, model, &ir, err);
    return sw_import_occt_file(path, &io, model, &ir, err);
}

static double seg_dist(const double *p, const double *a, const double *b)
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

/* Largest distance of a sampled trim curve of surface s's loop l from its
 * polyline. Untrimmed surfaces' domain rectangles are exact by construction
 * (straight in (u, v)) and sampled too, as four lines. */
static double loop_error(const sw_model *m, const sw_seam_polylines *pl, size_t s, size_t l)
{
    const sw_model_surface *surf = &m->surfaces[s];
    sw_nurbs_surface sv = sw_model_surface_view(surf);
    const double *d = surf->domain;
    size_t first = pl->loop_start[l], end = pl->loop_start[l + 1], li = l - pl->surface_loops[s];
    size_t curves = surf->loop_count ? m->loops[surf->first_loop + li].curve_count : 4;
    double worst = 0;
    for (size_t c = 0; c < curves; c++) {
        sw_nurbs_curve cv = {0};
        if (surf->loop_count)
            cv = sw_model_curve_view(&m->curves[m->loops[surf->first_loop + li].first_curve + c]);
        for (int i = 0; i <= 200; i++) {
            double x = i / 200.0, u, v;
            if (surf->loop_count) {
                double t0 = cv.knots[cv.degree], t1 = cv.knots[cv.count];
                sw_vec3 q = sw_nurbs_curve_point(&cv, t0 + (t1 - t0) * x);
                u = q.x, v = q.y;
            } else {
                const double cu[5] = {d[0], d[1], d[1], d[0], d[0]}, cw[5] = {d[2], d[2], d[3], d[3], d[2]};
                u = cu[c] + x * (cu[c + 1] - cu[c]), v = cw[c] + x * (cw[c + 1] - cw[c]);
            }
            sw_vec3 p = sw_nurbs_surface_point(&sv, fmin(fmax(u, d[0]), d[1]), fmin(fmax(v, d[2]), d[3]));
            double q[3] = {p.x, p.y, p.z}, best = INFINITY;
            for (size_t k = first; k < end; k++)
                best = fmin(best, seg_dist(q, pl->p + 3 * k, pl->p + 3 * (k + 1 < end ? k + 1 : first)));
            worst = fmax(worst, best);
        }
    }
    return worst;
}

static double polyline_error(const sw_model *m, double tol)
{
    sw_seam_polylines pl;
    sw_error err;
    if (sw_seam_flatten_model(m, tol, &pl, &err) != SW_OK)
        return -1;
    double worst = 0;
    for (size_t s = 0; s < m->surface_count; s++)
        for (size_t l = pl.surface_loops[s]; l < pl.surface_loops[s + 1]; l++)
            worst = fmax(worst, loop_error(m, &pl, s, l));
    sw_seam_polylines_free(&pl);
    return worst / tol;
}

static size_t host_bytes(const sw_seam_host *h)
{
    return h->vertex_count * sizeof *h->vertices + h->slot_count * sizeof *h->slots +
           h->loop_count * sizeof *h->loops + h->edge_count * sizeof *h->edges +
           h->slot_ref_count * sizeof *h->slot_refs + (h->surface_count + 1) * sizeof(uint32_t);
}

int main(int argc, char **argv)
{
    sw_seam_options opt = {0};
    int failures = 0, check = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--check") == 0) {
            check = 1;
            continue;
        }
        if (strcmp(argv[i], "--tolerance") == 0 && i + 1 < argc) {
            opt.tolerance = atof(argv[++i]);
            continue;
        }
        sw_model model;
        sw_model_init(&model);
        sw_error err = {0};
        sw_seam_host host;
        sw_seam_report r;
        sw_status st = import(argv[i], &model, &err);
        if (st == SW_OK)
            st = sw_seam_sew_model(&model, &opt, &host, &r, &err);
        if (st != SW_OK) {
            fprintf(stderr, "%s: %s\n", argv[i], err.message);
            failures++;
            sw_model_free(&model);
            continue;
        }
        double error = check ? polyline_error(&model, r.tolerance) : -1;
        if (check)
            printf("%-24s sampled polyline error %.3f of the tolerance\n",
                   strrchr(argv[i], '/') ? strrchr(argv[i], '/') + 1 : argv[i], error);
        struct rusage ru;
        getrusage(RUSAGE_SELF, &ru);
        const char *name = strrchr(argv[i], '/') ? strrchr(argv[i], '/') + 1 : argv[i];
        printf("%-24s surfaces %6zu loops %6zu vertices %8zu edges %8zu seams %8zu free %6zu "
               "nonmanifold %4zu tol %.3g flatten %.3f s sew %.3f s graph %.2f MB peak %.1f MB\n",
               name, model.surface_count, r.loops, r.boundary_vertices, r.boundary_edges, r.seams,
               r.free_edges, r.nonmanifold_edges, r.tolerance, r.flatten_s, r.sew_s,
               host_bytes(&host) / 1e6, ru.ru_maxrss / 1024.0);
        printf("{\"model\":\"%s\",\"surfaces\":%zu,\"loops\":%zu,\"vertices\":%zu,\"edges\":%zu,"
               "\"seams\":%zu,\"free_edges\":%zu,\"nonmanifold_edges\":%zu,\"inserted\":%zu,"
               "\"unproven_pieces\":%zu,\"tolerance_mm\":%g,\"flatten_s\":%.4f,\"sew_s\":%.4f,"
               "\"graph_bytes\":%zu,\"peak_rss_kb\":%ld,\"error_of_tolerance\":%.4f}\n",
               name, model.surface_count, r.loops, r.boundary_vertices, r.boundary_edges, r.seams,
               r.free_edges, r.nonmanifold_edges, r.inserted, r.unproven_pieces, r.tolerance,
               r.flatten_s, r.sew_s, host_bytes(&host), ru.ru_maxrss, error);
        sw_seam_host_free(&host);
        sw_model_free(&model);
    }
    return failures ? 1 : 0;
}
