/* seam_bench: the original Seam Graph (flatten + sew, sw_seam_sew.h) of CAD
 * files: time per stage, peak memory, and the report's counts, as a table and
 * one JSON line per model. Newell listings (.txt) by the Newell importer,
 * IGES (.igs, .iges) by the native importer, STEP (.stp, .step) through
 * OpenCASCADE. Run one file per process for a clean peak-memory figure
 * (ru_maxrss is the process's peak, including the import).
 *
 *   seam_bench [--tolerance MM] FILE...
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>

#include "sw_import_iges.h"
#include "sw_import_newell.h"
#include "sw_import_occt.h"
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

static size_t host_bytes(const sw_seam_host *h)
{
    return h->vertex_count * sizeof *h->vertices + h->slot_count * sizeof *h->slots +
           h->loop_count * sizeof *h->loops + h->edge_count * sizeof *h->edges +
           h->slot_ref_count * sizeof *h->slot_refs + (h->surface_count + 1) * sizeof(uint32_t);
}

int main(int argc, char **argv)
{
    sw_seam_options opt = {0};
    int failures = 0;
    for (int i = 1; i < argc; i++) {
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
               "\"graph_bytes\":%zu,\"peak_rss_kb\":%ld}\n",
               name, model.surface_count, r.loops, r.boundary_vertices, r.boundary_edges, r.seams,
               r.free_edges, r.nonmanifold_edges, r.inserted, r.unproven_pieces, r.tolerance,
               r.flatten_s, r.sew_s, host_bytes(&host), ru.ru_maxrss);
        sw_seam_host_free(&host);
        sw_model_free(&model);
    }
    return failures ? 1 : 0;
}
