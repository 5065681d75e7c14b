/* SPDX-License-Identifier: MIT */
/* Tessellation benchmark: seamwalk's uniform bicubic grid against GLU's NURBS
 * tessellator, on the Newell teaset and on a grid of random bicubic patches,
 * at the same object-space tolerance (a fraction of the model's size).
 *
 * Both sides produce positions and normals, and both are timed for the whole
 * work from control points to triangles. seamwalk: the second-derivative
 * bounds (sw_bezier_second_deriv_bounds), sw_tess_segments_for_error and
 * sw_tess_grid per patch. The pack builder stores the bounds, so the runtime
 * never computes them: a second line gives seamwalk's time without them,
 * labelled as such. GLU (bench_glu.h): GLU_NURBS_TESSELLATOR mode with
 * GLU_OBJECT_PARAMETRIC_ERROR sampling, triangles counted in the callbacks.
 *
 * Each side's achieved error is measured, outside the timed runs and
 * independently of its own claims (bench_error.h): every output triangle's
 * vertices, edge midpoints and centroid against the exact patch at the same
 * (u, v); seamwalk's (u, v) come from the grid, GLU's from a texture-coordinate
 * map holding the identity that rides along in a separate, untimed run (whose
 * triangle count must equal the timed one's). GLU's tolerance is not a bound
 * on its measured error (up to 3.5x it here), so a third line gives GLU at
 * the GLU_PARAMETRIC_TOLERANCE a search (bench_glu_tune, untimed) found to
 * meet seamwalk's measured error, timed there: the ratio at equal error.
 * Each error is also given to the nearest surface point: where the two
 * differ much (slivers along a patch's collapsed edge, whose (u, v) slip but
 * whose points lie on the surface) the same-(u, v) one, which the search
 * uses, overstates what is seen.
 *
 * Each repeat runs the four (seamwalk whole, seamwalk with stored bounds,
 * GLU, GLU at equal error) once in turn, so that load from elsewhere on the
 * machine falls on all of them alike.
 *
 * Usage: tess_bench [--quick] [--repeats N] [--json FILE] [--samples DIR]
 * Prints figures; never fails on timing, only when a side cannot run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_error.h"
#include "bench_glu.h"
#include "sw_bezier.h"
#include "sw_egl_headless.h"
#include "sw_import_newell.h"
#include "sw_model.h"
#include "sw_tess.h"

#ifndef SW_SAMPLES_DIR
#define SW_SAMPLES_DIR "assets/samples"
#endif

enum { MAX_REPEATS = 31, MAX_RESULTS = 16 };

/* One bicubic patch in both forms the two tessellators take. */
typedef struct bench_patch {
    float ctrl[64];            /* sw_bezier_patch layout: (j * 4 + i) * 4 + xyzw */
    sw_deriv_bounds bounds;    /* for the stored-bounds line only */
} bench_patch;

typedef struct bench_model {
    const char *name;
    bench_patch *patches;
    size_t count;
    double size;               /* control-box diagonal: tolerances are fractions of it */
} bench_model;

typedef struct timing {
    double median_s, min_s, max_s;
    uint64_t triangles, normals, capped;
    double error;              /* measured max error (bench_error.h), at the same (u, v) */
    double error_nearest;      /* the same, to the nearest surface point */
} timing;

typedef struct result {
    const char *model;
    size_t patches;
    double size, tol_rel, tol_abs;
    timing sw, glu;
    timing sw_stored;          /* seamwalk with the bounds precomputed, as packs store them */
    timing glu_eq;             /* GLU at the tolerance that meets seamwalk's measured error */
    double glu_eq_tol;
    int glu_eq_tries;
} result;

typedef struct options {
    int quick, repeats;
    const char *json_path;
    const char *samples;
} options;

/* ---- models ---------------------------------------------------------------- */

static int add_patch(bench_model *m, const double *ctrl, sw_error *err)
{
    bench_patch *p = &m->patches[m->count];
    for (int k = 0; k < 64; k++)
        p->ctrl[k] = (float)ctrl[k];
    /* Bounds of the float patch, the one both tessellators see. */
    double exact[64];
    sw_bezier_patchf pf = { 3, 3, 0, p->ctrl };
    sw_bezier_patch pd = sw_bezier_patch_from_float(&pf, exact);
    if (sw_bezier_second_deriv_bounds(&pd, &p->bounds, err) != SW_OK)
        return 0;
    m->count++;
    return 1;
}

static void measure_size(bench_model *m)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (size_t i = 0; i < m->count; i++)
        for (int c = 0; c < 16; c++)
            for (int k = 0; k < 3; k++) {
                double x = m->patches[i].ctrl[c * 4 + k];
                lo[k] = x < lo[k] ? x : lo[k];
                hi[k] = x > hi[k] ? x : hi[k];
            }
    m->size = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/* The teaset through the project's importer; 0 (and a note) when the sample
 * files are not there, so the random grid still runs. */
static int load_teaset(const char *dir, bench_model *m)
{
    static const char *const files[3] = { "teapot.txt", "teacup.txt", "teaspoon.txt" };
    sw_model model;
    sw_model_init(&model);
    sw_error err = { 0 };
    for (int f = 0; f < 3; f++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, files[f]);
        if (sw_model_begin_part(&model, files[f], NULL, &err) != SW_OK ||
            sw_import_newell_file(path, &model, &err) != SW_OK) {
            printf("teaset: skipped (%s)\n", err.message);
            sw_model_free(&model);
            return 0;
        }
    }
    m->name = "teaset";
    m->patches = calloc(model.patch_count, sizeof *m->patches);
    m->count = 0;
    int ok = m->patches != NULL;
    for (size_t i = 0; ok && i < model.patch_count; i++)
        ok = add_patch(m, model.patches[i].ctrl, &err);
    sw_model_free(&model);
    if (!ok) {
        printf("teaset: skipped (%s)\n", err.message[0] ? err.message : "out of memory");
        free(m->patches);
        return 0;
    }
    measure_size(m);
    return 1;
}

/* g x g unit cells, one bicubic per cell: x, y on the cell's 4 x 4 lattice,
 * z random in [-0.5, 0.5] (xorshift, fixed seed, so every run is the same). */
static int make_random_grid(int g, bench_model *m)
{
    uint64_t state = 0x2545F4914F6CDD1Dull;
    m->name = "random-grid";
    m->patches = calloc((size_t)g * (size_t)g, sizeof *m->patches);
    m->count = 0;
    if (!m->patches)
        return 0;
    sw_error err = { 0 };
    for (int cy = 0; cy < g; cy++)
        for (int cx = 0; cx < g; cx++) {
            double ctrl[64];
            for (int j = 0; j < 4; j++)
                for (int i = 0; i < 4; i++) {
                    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
                    double r = (double)((state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
                    double *c = ctrl + (j * 4 + i) * 4;
                    c[0] = cx + i / 3.0;
                    c[1] = cy + j / 3.0;
                    c[2] = r - 0.5;
                    c[3] = 1.0;
                }
            if (!add_patch(m, ctrl, &err)) {
                fprintf(stderr, "random grid: %s\n", err.message);
                free(m->patches);
                m->patches = NULL;
                return 0;
            }
        }
    measure_size(m);
    return 1;
}

/* ---- seamwalk -------------------------------------------------------------- */

typedef struct sw_buffers {
    sw_vertex *verts;
    uint16_t *indices;
} sw_buffers;

/* The bounds from the float patch, the one both tessellators see. */
static sw_deriv_bounds patch_bounds(const bench_patch *p)
{
    double exact[64];
    sw_bezier_patchf pf = {3, 3, 0, p->ctrl};
    sw_bezier_patch pd = sw_bezier_patch_from_float(&pf, exact);
    sw_deriv_bounds b = {0, 0, 0};
    sw_bezier_second_deriv_bounds(&pd, &b, NULL); /* checked when the model was made */
    return b;
}

/* One run over the model; stored_bounds 0 computes each patch's bounds as
 * part of the work, 1 takes the ones add_patch computed. */
static void run_seamwalk(const bench_model *m, double tol, int stored_bounds, const sw_buffers *b,
                         timing *t)
{
    uint64_t tris = 0, capped = 0, normals = 0;
    for (size_t i = 0; i < m->count; i++) {
        const bench_patch *p = &m->patches[i];
        sw_deriv_bounds bounds = stored_bounds ? p->bounds : patch_bounds(p);
        uint32_t nu, nv;
        capped += !sw_tess_segments_for_error(&bounds, tol, &nu, &nv);
        sw_bezier_patchf pf = { 3, 3, 0, p->ctrl };
        sw_tess_grid(&pf, nu, nv, 0, b->verts, b->indices);
        tris += 2ull * nu * nv;
        normals += (uint64_t)(nu + 1) * (nv + 1);   /* one per grid vertex */
    }
    t->triangles = tris;
    t->normals = normals;
    t->capped = capped;
}

/* Both measured errors of one triangle of patch pf into the running maxima. */
static void measure_triangle(const sw_bezier_patchf *pf, const float p[3][3],
                             const float uv[3][2], int nearest, double worst[2])
{
    static const double unit[4] = {0, 1, 0, 1};
    worst[0] = fmax(worst[0], bench_triangle_error(p, uv, bench_patchf_at, pf));
    if (nearest)
        worst[1] = bench_triangle_error_nearest(p, uv, bench_patchf_at, pf, unit, worst[1]);
}

/* Vertex k of an nu x nv grid sits at (k mod (nu + 1), k div (nu + 1)). */
static void grid_error(const sw_bezier_patchf *pf, uint32_t nu, uint32_t nv,
                       const sw_buffers *b, double worst[2])
{
    for (uint32_t t = 0; t < 2 * nu * nv; t++) {
        float p[3][3], uv[3][2];
        for (int k = 0; k < 3; k++) {
            uint32_t v = b->indices[3 * t + (uint32_t)k];
            memcpy(p[k], b->verts[v].pos, sizeof p[k]);
            uv[k][0] = (float)(v % (nu + 1)) / (float)nu;
            uv[k][1] = (float)(v / (nu + 1)) / (float)nv;
        }
        measure_triangle(pf, p, uv, 1, worst);
    }
}

static void measure_seamwalk(const bench_model *m, double tol, const sw_buffers *b, timing *t)
{
    double worst[2] = {0, 0};
    for (size_t i = 0; i < m->count; i++) {
        sw_deriv_bounds bounds = patch_bounds(&m->patches[i]);
        uint32_t nu, nv;
        sw_tess_segments_for_error(&bounds, tol, &nu, &nv);
        sw_bezier_patchf pf = {3, 3, 0, m->patches[i].ctrl};
        sw_tess_grid(&pf, nu, nv, 0, b->verts, b->indices);
        grid_error(&pf, nu, nv, b, worst);
    }
    t->error = worst[0], t->error_nearest = worst[1];
}

/* ---- GLU ------------------------------------------------------------------- */

/* A Bezier patch is a NURBS patch with knots {0,0,0,0,1,1,1,1}. Our layout
 * steps 4 floats along u and 16 along v; GL_MAP2_VERTEX_3 reads x, y, z.
 * tex_uv: also the identity map for capturing runs (NULL: none). */
static void glu_patch(GLUnurbs *nurb, const bench_patch *p, GLfloat *tex_uv)
{
    static GLfloat knots[8] = { 0, 0, 0, 0, 1, 1, 1, 1 };
    gluBeginSurface(nurb);
    if (tex_uv)
        gluNurbsSurface(nurb, 8, knots, 8, knots, 2, 8, tex_uv, 4, 4, GL_MAP2_TEXTURE_COORD_2);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4, 16, (GLfloat *)p->ctrl, 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
}

static void run_glu(const bench_model *m, GLUnurbs *nurb)
{
    for (size_t i = 0; i < m->count; i++)
        glu_patch(nurb, &m->patches[i], NULL);
}

/* The patch GLU is tessellating in a capturing run and the worst errors yet
 * (the nearest-point one only when asked: it costs ten times more). */
typedef struct glu_probe {
    const bench_patch *patch;
    int nearest;
    double worst[2];
} glu_probe;

static void probe_triangle(void *user, const float p[3][3], const float uv[3][2])
{
    glu_probe *probe = user;
    sw_bezier_patchf pf = {3, 3, 0, probe->patch->ctrl};
    measure_triangle(&pf, p, uv, probe->nearest, probe->worst);
}

/* GLU's triangles and measured errors at tol: NULL, else GLU's problem. */
static const char *glu_errors(const bench_model *m, double tol, int nearest, uint64_t *tris,
                              double error[2])
{
    /* The identity in Bernstein form: control point (i, j) at (i/3, j/3). */
    GLfloat tex[32];
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            tex[(j * 4 + i) * 2] = (GLfloat)i / 3, tex[(j * 4 + i) * 2 + 1] = (GLfloat)j / 3;
    glu_probe probe = {NULL, nearest, {0, 0}};
    bench_glu g;
    if (!bench_glu_open(&g, tol, probe_triangle, &probe))
        return "gluNewNurbsRenderer failed";
    for (size_t i = 0; i < m->count; i++) {
        probe.patch = &m->patches[i];
        glu_patch(g.nurb, probe.patch, tex);
    }
    const char *problem = bench_glu_problem(&g);
    *tris = g.triangles, error[0] = probe.worst[0], error[1] = probe.worst[1];
    bench_glu_close(&g);
    return problem;
}

/* bench_glu_measure_fn on a const bench_model *: the same-(u, v) error only. */
static const char *glu_error_at(const void *model, double tol, uint64_t *tris, double *error)
{
    double e[2];
    const char *problem = glu_errors(model, tol, 0, tris, e);
    *error = e[0];
    return problem;
}

/* The measured error of the timed runs' t (at tol): 0 and a message when
 * GLU fails or the capturing run gives another triangle count. */
static int measure_glu(const bench_model *m, double tol, timing *t)
{
    uint64_t tris = 0;
    double e[2] = {0, 0};
    const char *problem = glu_errors(m, tol, 1, &tris, e);
    t->error = e[0], t->error_nearest = e[1];
    if (!problem && tris != t->triangles)
        problem = "the capturing run's triangle count differs from the timed runs'";
    if (problem)
        fprintf(stderr, "%s: GLU: %s\n", m->name, problem);
    return !problem;
}

/* ---- measurement ------------------------------------------------------------ */

static void put_spread(double *samples, int n, timing *t)
{
    bench_spread sp = bench_summarise(samples, n);
    t->median_s = sp.median_s, t->min_s = sp.min_s, t->max_s = sp.max_s;
}

/* One timed GLU run at tol into t's counts and *seconds; 0 and a message
 * when GLU fails. */
static int glu_once(const bench_model *m, double tol, timing *t, double *seconds)
{
    bench_glu g;
    if (!bench_glu_open(&g, tol, NULL, NULL)) {
        fprintf(stderr, "gluNewNurbsRenderer failed\n");
        return 0;
    }
    double t0 = bench_now_s();
    run_glu(m, g.nurb);
    *seconds = bench_now_s() - t0;
    const char *problem = bench_glu_problem(&g);
    bench_glu_close(&g);
    if (problem) {
        fprintf(stderr, "%s: GLU: %s\n", m->name, problem);
        return 0;
    }
    t->triangles = g.triangles, t->normals = g.normals, t->capped = 0;
    return 1;
}

/* The four runs in turn, repeats rounds: load from elsewhere on the machine
 * falls on all of them alike, so their ratios hold up under it. */
static int time_sides(const bench_model *m, int repeats, const sw_buffers *b, result *r)
{
    double s[4][MAX_REPEATS];
    for (int k = 0; k < repeats; k++) {
        double t0 = bench_now_s();
        run_seamwalk(m, r->tol_abs, 0, b, &r->sw);
        s[0][k] = bench_now_s() - t0;
        t0 = bench_now_s();
        run_seamwalk(m, r->tol_abs, 1, b, &r->sw_stored);
        s[1][k] = bench_now_s() - t0;
        if (!glu_once(m, r->tol_abs, &r->glu, &s[2][k]) ||
            !glu_once(m, r->glu_eq_tol, &r->glu_eq, &s[3][k]))
            return 0;
    }
    put_spread(s[0], repeats, &r->sw);
    put_spread(s[1], repeats, &r->sw_stored);
    put_spread(s[2], repeats, &r->glu);
    put_spread(s[3], repeats, &r->glu_eq);
    return 1;
}

static double mtri_per_s(const timing *t)
{
    return t->median_s > 0 ? (double)t->triangles / t->median_s * 1e-6 : 0.0;
}

static void print_timing(const char *name, const timing *t, double tol)
{
    printf("  %-9s triangles %10llu  median %.6f s (min %.6f .. max %.6f)  %8.2f Mtri/s"
           "  measured error %.3g (%.2f x tolerance; to the nearest point %.3g)",
           name, (unsigned long long)t->triangles, t->median_s, t->min_s, t->max_s,
           mtri_per_s(t), t->error, t->error / tol, t->error_nearest);
    if (t->capped)
        printf("  [%llu patches capped at %u segments]", (unsigned long long)t->capped,
               SW_TESS_MAX_SEGMENTS);
    printf("\n");
}

static void print_result(const result *r)
{
    printf("%s (%zu patches, size %.4g), tolerance %.0e of size = %.4g\n", r->model, r->patches,
           r->size, r->tol_rel, r->tol_abs);
    print_timing("seamwalk", &r->sw, r->tol_abs);
    print_timing("glu", &r->glu, r->tol_abs);
    double mt = mtri_per_s(&r->glu) > 0 ? mtri_per_s(&r->sw) / mtri_per_s(&r->glu) : 0.0;
    double tr = r->glu.triangles ? (double)r->sw.triangles / (double)r->glu.triangles : 0.0;
    double ti = r->glu.median_s > 0 ? r->sw.median_s / r->glu.median_s : 0.0;
    printf("  ratio seamwalk/GLU: Mtri/s %.2f, triangles %.2f, time %.3f"
           "  (measured error: seamwalk %.3g, GLU %.3g)\n",
           mt, tr, ti, r->sw.error, r->glu.error);
    const timing *eq = &r->glu_eq;
    printf("  glu at seamwalk's measured error (tolerance %.3g, %d tried): triangles %llu  "
           "median %.6f s (min %.6f .. max %.6f)  %.2f Mtri/s  measured error %.3g (nearest "
           "point %.3g); ratio seamwalk/GLU: time %.3f, time per triangle %.3f\n",
           r->glu_eq_tol, r->glu_eq_tries, (unsigned long long)eq->triangles, eq->median_s,
           eq->min_s, eq->max_s, mtri_per_s(eq), eq->error, eq->error_nearest,
           eq->median_s > 0 ? r->sw.median_s / eq->median_s : 0.0,
           mtri_per_s(&r->sw) > 0 ? mtri_per_s(eq) / mtri_per_s(&r->sw) : 0.0);
    const timing *st = &r->sw_stored;
    printf("  bounds precomputed (as packs store them, not the whole work): seamwalk median "
           "%.6f s (min %.6f .. max %.6f)  %8.2f Mtri/s, time ratio to GLU %.3f\n",
           st->median_s, st->min_s, st->max_s, mtri_per_s(st),
           r->glu.median_s > 0 ? st->median_s / r->glu.median_s : 0.0);
}

/* ---- JSON ------------------------------------------------------------------ */

static void json_timing(FILE *f, const char *name, const timing *t, int last)
{
    fprintf(f,
            "      \"%s\": {\"triangles\": %llu, \"median_s\": %.9f, \"min_s\": %.9f, "
            "\"max_s\": %.9f, \"mtri_per_s\": %.4f, \"capped_patches\": %llu, "
            "\"measured_error\": %.9g, \"measured_error_nearest\": %.9g}%s\n",
            name, (unsigned long long)t->triangles, t->median_s, t->min_s, t->max_s,
            mtri_per_s(t), (unsigned long long)t->capped, t->error, t->error_nearest,
            last ? "" : ",");
}

static int write_json(const char *path, const options *o, const char *renderer, const result *r,
                      int n)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        return 0;
    }
    fprintf(f, "{\n  \"benchmark\": \"tess_bench\",\n  \"quick\": %s,\n  \"repeats\": %d,\n",
            o->quick ? "true" : "false", o->repeats);
    fprintf(f, "  \"gl_renderer\": \"%s\",\n  \"results\": [\n", renderer);
    for (int i = 0; i < n; i++) {
        double glu_rate = mtri_per_s(&r[i].glu);
        fprintf(f, "    {\n      \"model\": \"%s\", \"patches\": %zu, \"size\": %.9g,\n",
                r[i].model, r[i].patches, r[i].size);
        fprintf(f, "      \"tolerance_rel\": %.3g, \"tolerance_abs\": %.9g,\n", r[i].tol_rel,
                r[i].tol_abs);
        json_timing(f, "seamwalk", &r[i].sw, 0);
        json_timing(f, "glu", &r[i].glu, 0);
        json_timing(f, "seamwalk_bounds_precomputed", &r[i].sw_stored, 0);
        json_timing(f, "glu_at_equal_error", &r[i].glu_eq, 0);
        fprintf(f, "      \"glu_at_equal_error_tolerance\": %.9g, \"glu_tolerances_tried\": %d,\n",
                r[i].glu_eq_tol, r[i].glu_eq_tries);
        fprintf(f, "      \"ratio_mtri_per_s\": %.4f, \"ratio_time\": %.4f\n    }%s\n",
                glu_rate > 0 ? mtri_per_s(&r[i].sw) / glu_rate : 0.0,
                r[i].glu.median_s > 0 ? r[i].sw.median_s / r[i].glu.median_s : 0.0,
                i + 1 < n ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
    int ok = !ferror(f);
    ok = (fclose(f) == 0) && ok;
    if (!ok)
        fprintf(stderr, "%s: write failed\n", path);
    return ok;
}

/* ---- main ------------------------------------------------------------------ */

static int parse_options(int argc, char **argv, options *o)
{
    *o = (options){ .repeats = 0, .samples = SW_SAMPLES_DIR };
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            o->quick = 1;
        else if (!strcmp(argv[i], "--json") && i + 1 < argc)
            o->json_path = argv[++i];
        else if (!strcmp(argv[i], "--samples") && i + 1 < argc)
            o->samples = argv[++i];
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc)
            o->repeats = atoi(argv[++i]);
        else {
            fprintf(stderr,
                    "usage: %s [--quick] [--repeats N] [--json FILE] [--samples DIR]\n", argv[0]);
            return 0;
        }
    }
    if (!o->repeats)
        o->repeats = o->quick ? 3 : 7;
    if (o->repeats < 1 || o->repeats > MAX_REPEATS) {
        fprintf(stderr, "--repeats must be 1..%d\n", MAX_REPEATS);
        return 0;
    }
    return 1;
}

/* GLU's tolerance searched (untimed) so that its measured error is at most
 * seamwalk's. */
static int tune_glu(const bench_model *m, result *r)
{
    const char *problem = bench_glu_tune(glu_error_at, m, r->tol_abs, r->sw.error,
                                         &r->glu_eq_tol, &r->glu_eq_tries);
    if (problem)
        fprintf(stderr, "%s at %g: GLU: %s\n", m->name, r->tol_abs, problem);
    return !problem;
}

static int bench_model_all(const bench_model *m, const options *o, const sw_buffers *b,
                           result *out, int *n)
{
    static const double full[] = { 1e-2, 1e-3, 1e-4 };
    static const double quick[] = { 1e-2 };
    const double *tols = o->quick ? quick : full;
    int count = o->quick ? 1 : 3;
    for (int k = 0; k < count && *n < MAX_RESULTS; k++) {
        result *r = &out[(*n)++];
        *r = (result){ .model = m->name, .patches = m->count, .size = m->size,
                       .tol_rel = tols[k], .tol_abs = tols[k] * m->size };
        measure_seamwalk(m, r->tol_abs, b, &r->sw);
        if (!tune_glu(m, r) || !time_sides(m, o->repeats, b, r))
            return 0;
        if (!r->sw.triangles || !r->glu.triangles) {
            fprintf(stderr, "%s: a tessellator produced no triangles\n", m->name);
            return 0;
        }
        r->sw_stored.error = r->sw.error; /* the same triangles */
        r->sw_stored.error_nearest = r->sw.error_nearest;
        if (!measure_glu(m, r->tol_abs, &r->glu) || !measure_glu(m, r->glu_eq_tol, &r->glu_eq))
            return 0;
        print_result(r);
    }
    return 1;
}

int main(int argc, char **argv)
{
    options o;
    if (!parse_options(argc, argv, &o))
        return 2;
    sw_egl_headless egl;
    sw_error err = { 0 };
    if (sw_egl_headless_init(&egl, SW_GL_API_DESKTOP, 16, 16, &err) != SW_OK) {
        fprintf(stderr, "tess_bench: %s\n", err.message);
        return 1;
    }
    printf("tess_bench: GL_RENDERER %s, %d repeats, median and min..max of them%s\n",
           egl.renderer, o.repeats, o.quick ? " (quick)" : "");
    sw_buffers b = {
        .verts = malloc(sizeof(sw_vertex) * 65536),
        .indices = malloc(sizeof(uint16_t) * 6 * SW_TESS_MAX_SEGMENTS * SW_TESS_MAX_SEGMENTS),
    };
    bench_model models[2] = { 0 };
    int model_count = 0;
    if (load_teaset(o.samples, &models[model_count]))
        model_count++;
    int ok = b.verts && b.indices && make_random_grid(o.quick ? 2 : 16, &models[model_count]);
    model_count += ok;
    result results[MAX_RESULTS];
    int n = 0;
    for (int i = 0; ok && i < model_count; i++)
        ok = bench_model_all(&models[i], &o, &b, results, &n);
    if (ok && o.json_path)
        ok = write_json(o.json_path, &o, egl.renderer, results, n);
    for (int i = 0; i < model_count; i++)
        free(models[i].patches);
    free(b.verts);
    free(b.indices);
    sw_egl_headless_destroy(&egl);
    return ok ? 0 : 1;
}
