/* SPDX-License-Identifier: MIT */
/* Specification of the OpenCASCADE importer (sw_import_occt.h): every shared
 * STEP file imports with the faces its description gives, its trims close on
 * their surfaces, and the imported geometry covers what OCCT itself measures
 * (sw_occt_measure.h); IGES reads through the same path; malformed files give
 * one clean line naming the file. Built without OCCT, the same program checks
 * the "built without STEP support" message instead.
 * Usage: test_import_occt SHARED_MODELS_DIR SCRATCH_DIR [--truncations] */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "sw_import_occt.h"
#include "sw_occt_measure.h"
#include "sw_model.h"
#include "sw_test.h"

static const char *shared_dir;
static const char *scratch_dir;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const char *model_path(const char *name)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", shared_dir, name);
    return path;
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static void check_error(sw_status st, const sw_error *err, sw_status want, const char *piece1,
                        const char *piece2)
{
    SW_CHECK_MSG(st == want, "status %s, want %s (%s)", sw_status_name(st), sw_status_name(want),
                 err->message);
    SW_CHECK_MSG(strstr(err->message, piece1) != NULL, "'%s' not in '%s'", piece1, err->message);
    if (piece2)
        SW_CHECK_MSG(strstr(err->message, piece2) != NULL, "'%s' not in '%s'", piece2,
                     err->message);
    SW_CHECK_MSG(strchr(err->message, '\n') == NULL, "more than one line: '%s'", err->message);
}

/* ---- sampling the imported model ----------------------------------------- */

enum { CURVE_SAMPLES = 24, GRID = 48 };

static sw_vec3 curve_uv(const sw_model_trim_curve *c, double s)
{
    sw_nurbs_curve view = sw_model_curve_view(c);
    double t0 = view.knots[view.degree], t1 = view.knots[view.count];
    return sw_nurbs_curve_point(&view, t0 + (t1 - t0) * s);
}

/* The surface's loops as one closed uv polygon each, CURVE_SAMPLES per curve. */
typedef struct polygons {
    double *uv;        /* 2 per vertex */
    size_t *start;     /* loop k is vertices start[k] .. start[k + 1] - 1 */
    size_t loops;
} polygons;

static polygons sample_loops(const sw_model *m, const sw_model_surface *s)
{
    polygons p = {0};
    size_t vertices = 0;
    for (size_t l = 0; l < s->loop_count; l++)
        vertices += m->loops[s->first_loop + l].curve_count * CURVE_SAMPLES;
    p.uv = malloc((vertices + 1) * 2 * sizeof *p.uv);
    p.start = malloc((s->loop_count + 1) * sizeof *p.start);
    size_t n = 0;
    for (size_t l = 0; l < s->loop_count; l++) {
        const sw_model_loop *loop = &m->loops[s->first_loop + l];
        p.start[l] = n;
        for (size_t c = 0; c < loop->curve_count; c++)
            for (int k = 0; k < CURVE_SAMPLES; k++) {
                sw_vec3 uv = curve_uv(&m->curves[loop->first_curve + c], (double)k / CURVE_SAMPLES);
                p.uv[2 * n] = uv.x, p.uv[2 * n + 1] = uv.y;
                n++;
            }
    }
    p.start[s->loop_count] = n;
    p.loops = s->loop_count;
    return p;
}

/* Even-odd over all loops, as sw_model.h defines inside. */
static int inside(const polygons *p, double u, double v)
{
    int in = 0;
    for (size_t l = 0; l < p->loops; l++) {
        size_t a = p->start[l], b = p->start[l + 1];
        for (size_t i = a, j = b - 1; i < b; j = i++) {
            double ui = p->uv[2 * i], vi = p->uv[2 * i + 1];
            double uj = p->uv[2 * j], vj = p->uv[2 * j + 1];
            if ((vi > v) != (vj > v) && u < ui + (uj - ui) * (v - vi) / (vj - vi))
                in = !in;
        }
    }
    return in;
}

typedef struct measured {
    sw_box box;            /* of surface points inside the trims and on them */
    double area_mm2;       /* midpoint rule on a GRID x GRID lattice of the domain */
    double worst_join_mm;  /* largest 3D gap between consecutive trim curves */
    size_t reversed;       /* surfaces that were reversed */
    int max_degree_u, max_degree_v;
} measured;

static double cell_area(const sw_nurbs_surface *s, double u, double v, double du, double dv)
{
    sw_vec3 p = sw_nurbs_surface_point(s, u, v);
    sw_vec3 pu = sw_nurbs_surface_point(s, u + 1e-3 * du, v);
    sw_vec3 pv = sw_nurbs_surface_point(s, u, v + 1e-3 * dv);
    sw_vec3 a = sw_v3_sub(pu, p), b = sw_v3_sub(pv, p);
    return sw_v3_length(sw_v3_cross(a, b)) * 1e6;
}

static void measure_surface(const sw_model *m, const sw_model_surface *s, measured *out)
{
    sw_nurbs_surface view = sw_model_surface_view(s);
    polygons p = sample_loops(m, s);
    const double *d = s->domain;
    for (size_t i = 0; i < p.start[p.loops]; i++)
        sw_box_add_point(&out->box, sw_nurbs_surface_point(&view, p.uv[2 * i], p.uv[2 * i + 1]));
    double du = (d[1] - d[0]) / GRID, dv = (d[3] - d[2]) / GRID;
    for (int j = 0; j < GRID; j++)
        for (int i = 0; i < GRID; i++) {
            double u = d[0] + (i + 0.5) * du, v = d[2] + (j + 0.5) * dv;
            if (p.loops && !inside(&p, u, v))
                continue;
            sw_box_add_point(&out->box, sw_nurbs_surface_point(&view, u, v));
            out->area_mm2 += cell_area(&view, u, v, du, dv);
        }
    free(p.uv);
    free(p.start);
}

/* The 3D gap between each trim curve's end and the next one's start. */
static double worst_join(const sw_model *m, const sw_model_surface *s)
{
    sw_nurbs_surface view = sw_model_surface_view(s);
    double worst = 0.0;
    for (size_t l = 0; l < s->loop_count; l++) {
        const sw_model_loop *loop = &m->loops[s->first_loop + l];
        for (size_t c = 0; c < loop->curve_count; c++) {
            const sw_model_trim_curve *a = &m->curves[loop->first_curve + c];
            const sw_model_trim_curve *b = &m->curves[loop->first_curve + (c + 1) % loop->curve_count];
            sw_vec3 ea = curve_uv(a, 1.0), sb = curve_uv(b, 0.0);
            sw_vec3 pa = sw_nurbs_surface_point(&view, ea.x, ea.y);
            sw_vec3 pb = sw_nurbs_surface_point(&view, sb.x, sb.y);
            double gap = sw_v3_length(sw_v3_sub(pa, pb));
            if (gap > worst)
                worst = gap;
        }
    }
    return worst;
}

static measured measure_model(const sw_model *m)
{
    measured out = {.box = sw_box_empty()};
    for (size_t i = 0; i < m->surface_count; i++) {
        const sw_model_surface *s = &m->surfaces[i];
        measure_surface(m, s, &out);
        double join = worst_join(m, s);
        if (join > out.worst_join_mm)
            out.worst_join_mm = join;
        out.reversed += s->reversed != 0;
        if (s->degree_u > out.max_degree_u)
            out.max_degree_u = s->degree_u;
        if (s->degree_v > out.max_degree_v)
            out.max_degree_v = s->degree_v;
    }
    return out;
}

/* ---- the shared files ------------------------------------------------------ */

typedef struct import_case {
    const char *name;
    size_t faces;          /* as the file's description (SOURCES.md) gives them */
} import_case;

/* Face counts from ../shared/models/SOURCES.md, checked against OCCT's own
 * count below; the screw's description gives none, OCCT counts 10. */
static const import_case step_files[] = {
    {"occt_linkrods.step", 37}, {"occt_screw.step", 10},     {"nist_mbe_pmi_1.stp", 113},
    {"nist_mbe_pmi_4.stp", 495}, {"nist_mbe_pmi_11.stp", 10}, {"axom_boxed_sphere.step", 192},
};

static const import_case iges_files[] = {
    {"occt_hammer.iges", 45}, {"occt_bearing.iges", 213},
};

/* The imported model covers what OCCT measures: every sampled point of the
 * trimmed faces lies in OCCT's tight box (within tolerance: trims that ran
 * past their face would leave it), the samples reach the box's sides, and the
 * trimmed area agrees with OCCT's. */
static void check_against_occt(const char *name, const sw_model *m, const measured *got,
                               const sw_occt_measure *occt)
{
    sw_box box = got->box;
    double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
    double dx = occt->box_max[0] - occt->box_min[0], dy = occt->box_max[1] - occt->box_min[1];
    double dz = occt->box_max[2] - occt->box_min[2];
    double diagonal = sqrt(dx * dx + dy * dy + dz * dz);
    double tight = (double)m->model_tolerance + 1e-4 * diagonal;
    double loose = 0.02 * diagonal;
    for (int k = 0; k < 3; k++) {
        SW_CHECK_MSG(lo[k] >= occt->box_min[k] - tight && hi[k] <= occt->box_max[k] + tight,
                     "%s axis %d: samples [%g, %g] leave OCCT's box [%g, %g]", name, k, lo[k],
                     hi[k], occt->box_min[k], occt->box_max[k]);
        SW_CHECK_MSG(lo[k] <= occt->box_min[k] + loose && hi[k] >= occt->box_max[k] - loose,
                     "%s axis %d: samples [%g, %g] fall short of OCCT's box [%g, %g]", name, k,
                     lo[k], hi[k], occt->box_min[k], occt->box_max[k]);
    }
    SW_CHECK_MSG(fabs(got->area_mm2 - occt->area_mm2) <= 0.03 * occt->area_mm2,
                 "%s: trimmed area %g mm^2, OCCT %g mm^2", name, got->area_mm2, occt->area_mm2);
}

static void import_and_check(const import_case *c)
{
    const char *path = model_path(c->name);
    sw_occt_measure occt;
    sw_error err = {0};
    SW_CHECK_MSG(sw_occt_measure_file(path, &occt, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(occt.faces == c->faces, "%s: OCCT counts %zu faces, the description %zu",
                 c->name, occt.faces, c->faces);

    sw_model m;
    sw_model_init(&m);
    sw_import_report report;
    double t0 = now_s();
    sw_status st = sw_import_occt_file(path, NULL, &m, &report, &err);
    double seconds = now_s() - t0;
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK_MSG(report.faces == c->faces && m.surface_count == c->faces,
                 "%s: %zu faces imported (%zu surfaces), want %zu", c->name, report.faces,
                 m.surface_count, c->faces);
    for (size_t k = 0; k < report.unsupported.kinds; k++)
        SW_CHECK_MSG(strcmp(report.unsupported.kind[k], "OCCT face") != 0, "%s: %zu faces skipped",
                     c->name, report.unsupported.count[k]);
    SW_CHECK(m.part_count >= 1);

    measured got = measure_model(&m);
    SW_CHECK(got.max_degree_u <= SW_BEZIER_MAX_DEGREE && got.max_degree_v <= SW_BEZIER_MAX_DEGREE);
    SW_CHECK_MSG(got.worst_join_mm <= 0.01 + 10.0 * (double)m.model_tolerance,
                 "%s: trim curves gap by %g mm in 3D", c->name, got.worst_join_mm);
    check_against_occt(c->name, &m, &got, &occt);
    printf("  %-24s %4zu faces %2zu parts %5zu pcurves computed %4zu reversed deg<=(%d,%d) "
           "units %g mm tol %g mm box [%.4g %.4g %.4g]..[%.4g %.4g %.4g] area %.6g (OCCT %.6g) "
           "join %.2g mm %.2f s\n",
           c->name, report.faces, m.part_count, report.pcurves_computed, got.reversed,
           got.max_degree_u, got.max_degree_v, report.units_to_mm, report.model_tolerance_mm,
           got.box.min.x, got.box.min.y, got.box.min.z, got.box.max.x, got.box.max.y,
           got.box.max.z, got.area_mm2, occt.area_mm2, got.worst_join_mm, seconds);
    sw_model_free(&m);
}

static void every_shared_step_file_imports_and_matches_occt(void)
{
    for (size_t i = 0; i < sizeof step_files / sizeof step_files[0]; i++)
        import_and_check(&step_files[i]);
}

static void shared_iges_files_read_through_occt_too(void)
{
    for (size_t i = 0; i < sizeof iges_files / sizeof iges_files[0]; i++)
        import_and_check(&iges_files[i]);
}

/* The linkrods' description: B-spline faces up to degree (6, 10). */
static void linkrods_keeps_its_high_degrees(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_import_occt_file(model_path("occt_linkrods.step"), NULL, &m, NULL, &err) == SW_OK);
    measured got = measure_model(&m);
    int high = got.max_degree_u > got.max_degree_v ? got.max_degree_u : got.max_degree_v;
    SW_CHECK_MSG(high == 10, "highest degree %d, want 10", high);
    sw_model_free(&m);
}

/* The NIST parts carry no p-curves at all: every trim is computed. */
static void nist_trims_are_all_computed(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_import_report report;
    SW_CHECK(sw_import_occt_file(model_path("nist_mbe_pmi_11.stp"), NULL, &m, &report, &err) ==
             SW_OK);
    SW_CHECK_MSG(report.pcurves_computed == m.curve_count && m.curve_count > 0,
                 "%zu computed of %zu", report.pcurves_computed, m.curve_count);
    for (size_t i = 0; i < m.curve_count; i++)
        SW_CHECK(m.curves[i].computed == 1);
    sw_model_free(&m);
}

/* The boxed sphere is in centimetres; the model is in millimetres. */
static void centimetres_become_millimetres(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_import_report report;
    SW_CHECK(sw_import_occt_file(model_path("axom_boxed_sphere.step"), NULL, &m, &report, &err) ==
             SW_OK);
    SW_CHECK_NEAR(report.units_to_mm, 10.0, 0.0);
    SW_CHECK_NEAR(report.model_tolerance_mm, 0.1, 1e-12);   /* 0.01 cm */
    SW_CHECK_NEAR(m.model_tolerance, 0.1, 1e-7);
    sw_model_free(&m);
}

/* OCCT 7.6 transfers nothing from this file (its directory entries give
 * wrong parameter line counts, which OCCT reports as syntax errors in the D
 * section and bad entities); the importer refuses it with the first of those
 * instead of returning an empty model. The native IGES reader is the one that reads it. */
static void gpucast_teapot_is_empty_to_occt(void)
{
    const char *path = model_path("gpucast_teapot.igs");
    sw_occt_measure occt;
    sw_error err = {0};
    SW_CHECK(sw_occt_measure_file(path, &occt, &err) == SW_OK);
    SW_CHECK_MSG(occt.faces == 0, "OCCT now reads %zu faces: update this test", occt.faces);
    sw_model m;
    sw_model_init(&m);
    /* Which of OCCT's fails comes first varies with what the process read
     * before; all point into the directory (D) section. */
    check_error(sw_import_occt_file(path, NULL, &m, NULL, &err), &err, SW_ERR_FORMAT, path, " D");
    SW_CHECK(m.surface_count == 0);
    sw_model_free(&m);
}

/* ---- malformed input --------------------------------------------------------- */

static char *read_whole(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *data = malloc((size_t)n + 1);
    *size = fread(data, 1, (size_t)n, f);
    data[*size] = '\0';
    fclose(f);
    return data;
}

static const char *write_scratch(const char *name, const char *data, size_t size)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", scratch_dir, name);
    FILE *f = fopen(path, "wb");
    SW_CHECK_MSG(f != NULL, "cannot write %s", path);
    if (f) {
        fwrite(data, 1, size, f);
        fclose(f);
    }
    return path;
}

/* Imports a malformed file: a clean error naming it, nothing in the model. */
static void check_rejected(const char *path, const char *piece)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_status st = sw_import_occt_file(path, NULL, &m, NULL, &err);
    check_error(st, &err, SW_ERR_FORMAT, path, piece);
    sw_model_free(&m);
}

/* Cut at half its size, nist_mbe_pmi_11.stp ends in "#2" after the
 * complete #266. */
static void truncated_step_names_the_last_entity(void)
{
    size_t size;
    char *data = read_whole(model_path("nist_mbe_pmi_11.stp"), &size);
    SW_CHECK(data != NULL);
    if (!data)
        return;
    check_rejected(write_scratch("cut.stp", data, size / 2), "truncated: ends after #266");
    free(data);
}

/* The first CARTESIAN_POINT's coordinate list replaced by `list`, written
 * to the scratch folder; its #id in id. */
static const char *nist11_with_bad_point(const char *name, const char *list, char *id, size_t id_size)
{
    size_t size;
    char *data = read_whole(model_path("nist_mbe_pmi_11.stp"), &size);
    SW_CHECK(data != NULL);
    if (!data)
        return NULL;
    const char *key = "CARTESIAN_POINT('',";
    char *point = strstr(data, key);
    char *hash = point;
    while (hash > data && *hash != '#')
        hash--;
    snprintf(id, id_size, "%.*s", (int)strcspn(hash, " ="), hash);
    char *list_start = point + strlen(key), *list_end = strstr(list_start, ")") + 1;
    size_t head = (size_t)(list_start - data), tail = size - (size_t)(list_end - data);
    char *out = malloc(head + strlen(list) + tail);
    memcpy(out, data, head);
    memcpy(out + head, list, strlen(list));
    memcpy(out + head + strlen(list), list_end, tail);
    const char *path = write_scratch(name, out, head + strlen(list) + tail);
    free(out);
    free(data);
    return path;
}

/* A string where a CARTESIAN_POINT wants a number: OCCT's check names the
 * entity exactly (and would crash transferring it). */
static void bad_entity_names_its_id(void)
{
    char id[32];
    const char *path = nist11_with_bad_point("bad-entity.stp", "('a',0.,0.)", id, sizeof id);
    if (path)
        check_rejected(path, id);
}

/* A syntax error: OCCT's parser gives a line (sometimes a line or two off),
 * so the message says which entity it is near. */
static void syntax_error_names_a_nearby_entity(void)
{
    char id[32];
    const char *path = nist11_with_bad_point("syntax.stp", "(1.,2.,3.", id, sizeof id);
    if (path)
        check_rejected(path, "near #");
}

static void not_step_at_all_is_a_clean_error(void)
{
    const char text[] = "this is not ISO 10303-21\n";
    check_rejected(write_scratch("text.step", text, sizeof text - 1), "text.step");
}

static void missing_file_and_unknown_extension(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    char path[1024];
    snprintf(path, sizeof path, "%s/no-such-file.step", scratch_dir);
    check_error(sw_import_occt_file(path, NULL, &m, NULL, &err), &err, SW_ERR_IO, path, NULL);
    check_error(sw_import_occt_file("model.obj", NULL, &m, NULL, &err), &err, SW_ERR_ARG,
                "model.obj", "STEP");
    SW_CHECK(m.surface_count == 0 && m.part_count == 0);
    sw_model_free(&m);
}

/* Every shared STEP file cut at 20 evenly spaced points: each cut is refused
 * with one line naming the file, never a crash or a partial model. Then the
 * same cuts with the trailer put back, so OCCT's parser and transfer see the
 * broken entity: the result is a clean error or, where the cut left a
 * consistent model, an import; never a crash. */
static void check_cut(const char *data, size_t size, size_t cut, int k, int *imported)
{
    char name[64];
    snprintf(name, sizeof name, "cut%d.step", k);
    check_rejected(write_scratch(name, data, cut), "truncated");

    static const char trailer[] = "\nENDSEC;\nEND-ISO-10303-21;\n";
    char *copy = malloc(cut + sizeof trailer);
    memcpy(copy, data, cut);
    memcpy(copy + cut, trailer, sizeof trailer);
    snprintf(name, sizeof name, "cut%d-closed.step", k);
    const char *path = write_scratch(name, copy, cut + sizeof trailer - 1);
    free(copy);
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    sw_status st = sw_import_occt_file(path, NULL, &m, NULL, &err);
    if (st == SW_OK)
        (*imported)++;
    else
        check_error(st, &err, SW_ERR_FORMAT, path, NULL);
    sw_model_free(&m);
    (void)size;
}

static void truncations_give_clean_errors(void)
{
    for (size_t i = 0; i < sizeof step_files / sizeof step_files[0]; i++) {
        size_t size;
        char *data = read_whole(model_path(step_files[i].name), &size);
        SW_CHECK(data != NULL);
        int imported = 0;
        for (int k = 1; data && k <= 20; k++)
            check_cut(data, size, size * (size_t)k / 21, k, &imported);
        printf("  %-24s 20 cuts refused; with the trailer restored %d imported, %d refused\n",
               step_files[i].name, imported, 20 - imported);
        free(data);
    }
}

/* ---- progress ----------------------------------------------------------------- */

typedef struct progress_log {
    int calls;
    double last;
    int backwards;
} progress_log;

static void log_progress(void *user, const char *stage, double fraction)
{
    progress_log *log = user;
    (void)stage;
    log->calls++;
    if (fraction < 0.0 || fraction > 1.0)
        log->backwards++;
    log->last = fraction;
}

static void progress_is_reported_and_ends_at_one(void)
{
    progress_log log = {0};
    sw_import_options options = {.progress = log_progress, .progress_user = &log};
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    SW_CHECK(sw_import_occt_file(model_path("nist_mbe_pmi_1.stp"), &options, &m, NULL, &err) ==
             SW_OK);
    SW_CHECK_MSG(log.calls >= 3, "%d progress calls", log.calls);
    SW_CHECK(log.backwards == 0);
    SW_CHECK_NEAR(log.last, 1.0, 0.0);
    sw_model_free(&m);
}

/* ---- without OpenCASCADE ----------------------------------------------------------- */

static void without_occt_step_gives_the_install_hint(void)
{
    sw_model m;
    sw_model_init(&m);
    sw_error err = {0};
    check_error(sw_import_occt_file("part.step", NULL, &m, NULL, &err), &err, SW_ERR_UNSUPPORTED,
                "part.step: built without STEP support", "libocct-data-exchange-dev");
    sw_occt_measure occt;
    check_error(sw_occt_measure_file("part.igs", &occt, &err), &err, SW_ERR_UNSUPPORTED,
                "part.igs: built without STEP support", NULL);
    sw_model_free(&m);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: test_import_occt SHARED_MODELS_DIR SCRATCH_DIR [--truncations]\n");
        return 2;
    }
    shared_dir = argv[1];
    scratch_dir = argv[2];
#ifdef SW_HAVE_OCCT
    SW_CHECK(sw_import_occt_available() == 1);
#else
    SW_CHECK(sw_import_occt_available() == 0);
#endif
    if (!sw_import_occt_available()) {
        SW_RUN(without_occt_step_gives_the_install_hint);
        return sw_test_finish();
    }
    if (!file_exists(model_path("SOURCES.md"))) {
        printf("SKIP: %s is absent\n", shared_dir);
        return 77;
    }
    mkdir(scratch_dir, 0777);
    if (argc > 3 && strcmp(argv[3], "--truncations") == 0) {
        SW_RUN(truncations_give_clean_errors);
        return sw_test_finish();
    }
    SW_RUN(every_shared_step_file_imports_and_matches_occt);
    SW_RUN(shared_iges_files_read_through_occt_too);
    SW_RUN(linkrods_keeps_its_high_degrees);
    SW_RUN(nist_trims_are_all_computed);
    SW_RUN(centimetres_become_millimetres);
    SW_RUN(gpucast_teapot_is_empty_to_occt);
    SW_RUN(truncated_step_names_the_last_entity);
    SW_RUN(bad_entity_names_its_id);
    SW_RUN(syntax_error_names_a_nearby_entity);
    SW_RUN(not_step_at_all_is_a_clean_error);
    SW_RUN(missing_file_and_unknown_extension);
    SW_RUN(progress_is_reported_and_ends_at_one);
    return sw_test_finish();
}
