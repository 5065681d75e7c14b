/* Trimmed tessellation benchmark: sw_trim_tess (paper 004, section 6.3: the
 * binary trees with the proven bound, clipped by the loops) against the
 * project's uniform grid (sw_tess_segments_for_error + sw_tess_grid per
 * patch) at the same object-space error, on three surfaces:
 * - bump-4x4: a bicubic bump cut into 4 x 4 patches, untrimmed (its loop is
 *   the domain rectangle),
 * - bump-holes: the same surface inside a disc with two round holes,
 * - cylinder: a rational quarter cylinder (one biquadratic-by-linear patch).
 * Seams are sampled finely enough that their own chords stay within the
 * error, as the Seam Graph's level of detail would choose them, and carry the
 * surface's positions. The grid does not trim: its triangle count is given
 * for the whole patches and for the grid cells whose centre lies inside the
 * loops (what a perfect trim of the grid would keep).
 *
 * Usage: trim_tess_bench [--quick] [--repeats N] [--json FILE]
 * Prints figures (median, min, max over the repeats); never fails on timing,
 * only when a tessellation fails. */
#define _GNU_SOURCE /* clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_bezier.h"
#include "sw_tess.h"
#include "sw_trim_tess.h"
#include "trim_tess_shapes.h"

enum { MAX_REPEATS = 31, MAX_PATCHES = 16, MAX_POINTS = 16384, MAX_LOOPS = 4 };

typedef struct surface {
    const char *name;
    sw_trim_patch patches[MAX_PATCHES];
    float ctrl[MAX_PATCHES][64];
    sw_deriv_bounds bounds[MAX_PATCHES];
    uint32_t count;
    double size; /* control-box diagonal: errors are fractions of it */
} surface;

typedef struct trims {
    sw_trim_point *pts;
    uint32_t first[MAX_LOOPS + 1];
    uint32_t count, n;
} trims;

typedef struct stats {
    double median_s, min_s, max_s;
    uint64_t triangles, vertices;
} stats;

typedef struct result {
    const char *model;
    double tol_rel, tol_abs;
    uint32_t seam_points;
    stats trim, grid;
    uint64_t grid_inside_triangles;
    double trim_bound;
    uint32_t capped;
} result;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void summarise(double *s, int n, stats *t)
{
    qsort(s, (size_t)n, sizeof *s, cmp_double);
    t->min_s = s[0], t->max_s = s[n - 1];
    t->median_s = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

/* ---- surfaces ------------------------------------------------------------------ */

static void finish_surface(surface *s)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < s->count; i++) {
        const sw_bezier_patchf *pf = &s->patches[i].patch;
        double d[4 * 16 * 16];
        sw_bezier_patch p = sw_bezier_patch_from_float(pf, d);
        sw_bezier_second_deriv_bounds(&p, &s->bounds[i], NULL);
        for (int c = 0; c < (pf->degree_u + 1) * (pf->degree_v + 1); c++)
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], pf->ctrl[4 * c + k]), hi[k] = fmax(hi[k], pf->ctrl[4 * c + k]);
    }
    s->size = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

static void make_bump(surface *s, int k)
{
    s->count = shape_bump(k, s->patches, s->ctrl);
    finish_surface(s);
}

static void make_cylinder(surface *s)
{
    s->count = shape_cylinder(s->patches, s->ctrl);
    finish_surface(s);
}

static sw_vec3 eval_at(const surface *s, double u, double v)
{
    const sw_trim_patch *p = &s->patches[0];
    for (uint32_t i = 0; i < s->count; i++) {
        const float *d = s->patches[i].domain;
        if (u >= d[0] && u <= d[1] && v >= d[2] && v <= d[3]) {
            p = &s->patches[i];
            break;
        }
    }
    double ctrl[4 * 16 * 16];
    sw_bezier_patch d = sw_bezier_patch_from_float(&p->patch, ctrl);
    sw_surface_point q;
    double a = (u - p->domain[0]) / (p->domain[1] - p->domain[0]);
    double b = (v - p->domain[2]) / (p->domain[3] - p->domain[2]);
    sw_bezier_eval(&d, fmin(fmax(a, 0), 1), fmin(fmax(b, 0), 1), SW_EVAL_POINT, &q);
    return q.p;
}

/* ---- seams ---------------------------------------------------------------------- */

/* A parameter-space curve: a polygon (the rectangle) or a circle. */
typedef struct curve {
    int circle;
    double cu, cv, r, dir;      /* circle: centre, radius, +1 / -1 */
    double u0, u1, v0, v1;      /* rectangle */
} curve;

static void curve_at(const curve *c, double t, double *u, double *v)
{
    if (c->circle) {
        *u = c->cu + c->r * cos(2 * M_PI * t * c->dir), *v = c->cv + c->r * sin(2 * M_PI * t * c->dir);
        return;
    }
    double s = 4 * t - floor(4 * t);
    int side = (int)floor(4 * t) % 4;
    double du = c->u1 - c->u0, dv = c->v1 - c->v0;
    const double pu[4] = {c->u0 + s * du, c->u1, c->u1 - s * du, c->u0};
    const double pv[4] = {c->v0, c->v0 + s * dv, c->v1, c->v1 - s * dv};
    *u = pu[side], *v = pv[side];
}

/* n points (a multiple of 4), doubled until every chord's midpoint is
 * within tol of the surface point at the curve's midpoint. */
static uint32_t seam_count(const surface *s, const curve *c, double tol)
{
    for (uint32_t n = 16; n <= MAX_POINTS / MAX_LOOPS; n *= 2) {
        double worst = 0;
        for (uint32_t k = 0; k < n; k++) {
            double ua, va, ub, vb, um, vm;
            curve_at(c, (double)k / n, &ua, &va);
            curve_at(c, (double)(k + 1) / n, &ub, &vb);
            curve_at(c, (k + 0.5) / n, &um, &vm);
            sw_vec3 a = eval_at(s, ua, va), b = eval_at(s, ub, vb), m = eval_at(s, um, vm);
            worst = fmax(worst, sw_v3_length(sw_v3_sub(m, sw_v3_scale(sw_v3_add(a, b), 0.5))));
        }
        if (worst <= tol)
            return n;
    }
    return MAX_POINTS / MAX_LOOPS;
}

static void add_loop(trims *t, const surface *s, const curve *c, double tol)
{
    uint32_t n = seam_count(s, c, tol);
    for (uint32_t k = 0; k < n; k++) {
        double u, v;
        curve_at(c, (double)k / n, &u, &v);
        sw_trim_point *p = &t->pts[t->n];
        p->uv[0] = (float)u, p->uv[1] = (float)v;
        sw_vec3 q = eval_at(s, p->uv[0], p->uv[1]);
        p->p[0] = (float)q.x, p->p[1] = (float)q.y, p->p[2] = (float)q.z;
        p->id = t->n++;
    }
    t->first[++t->count] = t->n;
}

static int in_loops(const trims *t, double u, double v)
{
    int in = 0;
    for (uint32_t k = 0; k < t->count; k++)
        for (uint32_t i = t->first[k]; i < t->first[k + 1]; i++) {
            uint32_t j = i + 1 < t->first[k + 1] ? i + 1 : t->first[k];
            const float *a = t->pts[i].uv, *b = t->pts[j].uv;
            if ((a[1] > v) != (b[1] > v) && a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) > u)
                in ^= 1;
        }
    return in;
}

/* ---- the two tessellators ----------------------------------------------------------- */

typedef struct buffers {
    float *pos, *nrm;
    uint16_t *idx;
    sw_vertex *verts;
    void *scratch;
    size_t scratch_bytes;
} buffers;

static int time_trim(const surface *s, const trims *t, double tol, int repeats, buffers *b,
                     result *r)
{
    double samples[MAX_REPEATS];
    sw_trim_loops loops = {t->pts, t->first, t->count};
    for (int k = 0; k < repeats; k++) {
        sw_arena a;
        sw_arena_init(&a, b->scratch, b->scratch_bytes);
        sw_trim_tess_buffers out = {b->pos, b->nrm, NULL, NULL, b->idx, 65536, 6 * 65536, 0};
        sw_trim_tess_result res;
        sw_error e = {0};
        double t0 = now_s();
        sw_status st = sw_trim_tess(s->patches, s->count, &loops, tol, NULL, &a, &out, &res, &e);
        samples[k] = now_s() - t0;
        if (st != SW_OK) {
            fprintf(stderr, "%s at %g: %s\n", s->name, tol, e.message);
            return 0;
        }
        r->trim.triangles = res.index_count / 3, r->trim.vertices = res.vertex_count;
        r->trim_bound = res.error_bound, r->capped = res.capped_count;
    }
    summarise(samples, repeats, &r->trim);
    return 1;
}

static void time_grid(const surface *s, const trims *t, double tol, int repeats, buffers *b,
                      result *r)
{
    double samples[MAX_REPEATS];
    uint64_t tris = 0, verts = 0, inside = 0;
    for (int k = 0; k < repeats; k++) {
        tris = verts = 0;
        double t0 = now_s();
        for (uint32_t i = 0; i < s->count; i++) {
            uint32_t nu, nv;
            sw_tess_segments_for_error(&s->bounds[i], tol, &nu, &nv);
            sw_tess_grid(&s->patches[i].patch, nu, nv, 0, b->verts, b->idx);
            tris += 2ull * nu * nv, verts += (uint64_t)(nu + 1) * (nv + 1);
        }
        samples[k] = now_s() - t0;
    }
    for (uint32_t i = 0; i < s->count; i++) {
        uint32_t nu, nv;
        sw_tess_segments_for_error(&s->bounds[i], tol, &nu, &nv);
        const float *d = s->patches[i].domain;
        for (uint32_t bj = 0; bj < nv; bj++)
            for (uint32_t ai = 0; ai < nu; ai++)
                inside += 2 * in_loops(t, d[0] + (d[1] - d[0]) * (ai + 0.5) / nu,
                                       d[2] + (d[3] - d[2]) * (bj + 0.5) / nv);
    }
    r->grid.triangles = tris, r->grid.vertices = verts;
    r->grid_inside_triangles = inside;
    summarise(samples, repeats, &r->grid);
}

static double ktri_per_s(const stats *t)
{
    return t->median_s > 0 ? (double)t->triangles / t->median_s * 1e-3 : 0.0;
}

static void print_result(const result *r)
{
    printf("%s, error %.0e of size = %.4g, %u seam points\n", r->model, r->tol_rel, r->tol_abs,
           r->seam_points);
    printf("  trim      triangles %8llu  vertices %6llu  median %.6f s (min %.6f .. max %.6f)  "
           "%9.1f ktri/s  bound %.3g%s\n",
           (unsigned long long)r->trim.triangles, (unsigned long long)r->trim.vertices,
           r->trim.median_s, r->trim.min_s, r->trim.max_s, ktri_per_s(&r->trim), r->trim_bound,
           r->capped ? "  [capped cells]" : "");
    printf("  grid      triangles %8llu  vertices %6llu  median %.6f s (min %.6f .. max %.6f)  "
           "%9.1f ktri/s  (cells inside the loops: %llu triangles)\n",
           (unsigned long long)r->grid.triangles, (unsigned long long)r->grid.vertices,
           r->grid.median_s, r->grid.min_s, r->grid.max_s, ktri_per_s(&r->grid),
           (unsigned long long)r->grid_inside_triangles);
    printf("  ratio trim/grid: triangles %.3f (vs grid cells inside %.3f), time %.2f\n",
           r->grid.triangles ? (double)r->trim.triangles / (double)r->grid.triangles : 0,
           r->grid_inside_triangles ? (double)r->trim.triangles / (double)r->grid_inside_triangles
                                    : 0,
           r->grid.median_s > 0 ? r->trim.median_s / r->grid.median_s : 0);
}

static void json_stats(FILE *f, const char *name, const stats *t, const char *tail)
{
    fprintf(f, "      \"%s\": {\"triangles\": %llu, \"vertices\": %llu, \"median_s\": %.9f, "
            "\"min_s\": %.9f, \"max_s\": %.9f, \"ktri_per_s\": %.3f}%s\n", name,
            (unsigned long long)t->triangles, (unsigned long long)t->vertices, t->median_s,
            t->min_s, t->max_s, ktri_per_s(t), tail);
}

static int write_json(const char *path, int quick, int repeats, const result *r, int n)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        return 0;
    }
    fprintf(f, "{\n  \"benchmark\": \"trim_tess_bench\",\n  \"quick\": %s,\n  \"repeats\": %d,\n"
            "  \"results\": [\n", quick ? "true" : "false", repeats);
    for (int i = 0; i < n; i++) {
        fprintf(f, "    {\"model\": \"%s\", \"error_rel\": %g, \"error_abs\": %.9g, "
                "\"seam_points\": %u, \"trim_bound\": %.9g, \"capped\": %u,\n", r[i].model,
                r[i].tol_rel, r[i].tol_abs, r[i].seam_points, r[i].trim_bound, r[i].capped);
        json_stats(f, "trim", &r[i].trim, ",");
        json_stats(f, "grid", &r[i].grid, ",");
        fprintf(f, "      \"grid_inside_triangles\": %llu}%s\n",
                (unsigned long long)r[i].grid_inside_triangles, i + 1 < n ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
    return fclose(f) == 0;
}

/* ---- main ----------------------------------------------------------------------------- */

static int run_model(surface *s, int holes, double tol_rel, int repeats, buffers *b, trims *t,
                     result *r)
{
    double tol = tol_rel * s->size;
    t->count = 0, t->n = 0, t->first[0] = 0;
    /* The seams' own chord error: a tenth of the bound, as the paper's LOD
     * keeps the trims' error below the patches'. */
    if (holes) {
        curve outer = {1, 0.5, 0.5, 0.45, 1, 0, 0, 0, 0};
        curve h1 = {1, 0.35, 0.4, 0.12, -1, 0, 0, 0, 0}, h2 = {1, 0.65, 0.62, 0.1, -1, 0, 0, 0, 0};
        add_loop(t, s, &outer, 0.1 * tol);
        add_loop(t, s, &h1, 0.1 * tol);
        add_loop(t, s, &h2, 0.1 * tol);
    } else {
        curve rect = {0, 0, 0, 0, 0, 0, 1, 0, 1};
        add_loop(t, s, &rect, 0.1 * tol);
    }
    r->model = s->name, r->tol_rel = tol_rel, r->tol_abs = tol, r->seam_points = t->n;
    if (!time_trim(s, t, tol, repeats, b, r))
        return 0;
    time_grid(s, t, tol, repeats, b, r);
    print_result(r);
    return 1;
}

int main(int argc, char **argv)
{
    int quick = 0, repeats = 7;
    const char *json = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1, repeats = 3;
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc)
            repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--json") && i + 1 < argc)
            json = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--quick] [--repeats N] [--json FILE]\n", argv[0]);
            return 2;
        }
    }
    repeats = repeats < 1 ? 1 : repeats > MAX_REPEATS ? MAX_REPEATS : repeats;
    static surface models[3];
    make_bump(&models[0], 4), models[0].name = "bump-4x4";
    make_bump(&models[1], 4), models[1].name = "bump-holes";
    make_cylinder(&models[2]), models[2].name = "cylinder";
    buffers b;
    b.pos = malloc(sizeof(float) * 3 * 65536), b.nrm = malloc(sizeof(float) * 3 * 65536);
    b.idx = malloc(sizeof(uint16_t) * 6 * 65536);
    b.verts = malloc(sizeof(sw_vertex) * 65536);
    b.scratch_bytes = sw_trim_tess_scratch_bytes(MAX_PATCHES, MAX_POINTS, 3, NULL);
    b.scratch = malloc(b.scratch_bytes);
    trims t;
    t.pts = malloc(sizeof(sw_trim_point) * MAX_POINTS);
    if (!b.pos || !b.nrm || !b.idx || !b.verts || !b.scratch || !t.pts) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    const double tols[3] = {1e-2, 1e-3, 1e-4};
    result results[9];
    int n = 0, ok = 1;
    printf("trim_tess_bench: %d repeats, scratch %zu bytes\n", repeats, b.scratch_bytes);
    for (int m = 0; m < 3 && ok; m++)
        for (int k = 0; k < (quick ? 2 : 3) && ok; k++)
            ok = run_model(&models[m], m == 1, tols[k], repeats, &b, &t, &results[n++]);
    if (ok && json)
        ok = write_json(json, quick, repeats, results, n);
    free(b.pos), free(b.nrm), free(b.idx), free(b.verts), free(b.scratch), free(t.pts);
    return ok ? 0 : 1;
}
