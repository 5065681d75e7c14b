/* SPDX-License-Identifier: MIT */
/* Part levels: each piece's source welded, simplified toward rising
 * bounds, measured both ways, its normals chosen per corner from the
 * source's, its area shaded wrong measured (sw_part_levels_build.h). */
#include "sw_part_levels_build.h"

#include <float.h>
#include <math.h>
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_grow.h"
#include "sw_mesh_distance.h"
#include "sw_part_mesh.h"
#include "sw_part_pieces.h"
#include "sw_part_source.h"

/* 1 when a triangle of m->dest[0 .. n) faces against the source around
 * all three of its corners (each corner's source triangles' summed
 * normal more than 60 degrees off): a fold. meshoptimizer rejects a
 * collapse that turns a triangle over, but on flat ground of many pieces
 * it still folded a triangle over its neighbour (a quarter of a paving
 * stone, 125 mm, under its measured error). Sliver triangles across a
 * thin curved part face every way at their corners and are not folds. */
static int folds(const sw_part_mesh *m, const double *vn, size_t n)
{
    int fold = 0;
    for (size_t t = 0; t < n && !fold; t += 3) {
        double nt[3];
        sw_part_face_normal(m->wpos + 3 * (size_t)m->dest[t], m->wpos + 3 * (size_t)m->dest[t + 1],
                            m->wpos + 3 * (size_t)m->dest[t + 2], nt);
        double lt = sqrt(nt[0] * nt[0] + nt[1] * nt[1] + nt[2] * nt[2]);
        int against = 0;
        for (int c = 0; c < 3 && lt > 0; c++) {
            const double *v = vn + 3 * (size_t)m->dest[t + c];
            double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            against += lv > 0 && nt[0] * v[0] + nt[1] * v[1] + nt[2] * v[2] < -0.5 * lt * lv;
        }
        fold = against == 3;
    }
    return fold;
}

/* Per welded vertex, the summed normals (by area) of the source triangles
 * around it, for folds(); NULL when out of memory. */
static double *source_vertex_normals(const sw_part_mesh *m)
{
    double *vn = calloc(3 * (size_t)m->wcount + 3, sizeof *vn);
    for (uint32_t t = 0; vn && t < m->icount; t += 3) {
        double f[3];
        sw_part_face_normal(m->wpos + 3 * (size_t)m->idx[t], m->wpos + 3 * (size_t)m->idx[t + 1],
                            m->wpos + 3 * (size_t)m->idx[t + 2], f);
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                vn[3 * (size_t)m->idx[t + c] + k] += f[k];
    }
    return vn;
}

/* One piece's levels at one front, being made. */
typedef struct piece_job {
    uint32_t piece, front;
    int cut;                      /* its part is cut: border locked, source kept first */
    double min_bound;             /* no level made for a finer bound (its front's) */
    double *vertex_normals;       /* cut: source_vertex_normals, made once a piece */
    const sw_part_levels_options *opt;
    sw_part_levels_report *r;
    sw_mesh_view source;
    sw_mesh_grid *source_grid;
    float last_error;
    uint32_t last_indices, kept;
} piece_job;

/* The level in m->dest[0 .. n) with its measured error appended to o as
 * the job's next level: 1 kept, 0 left out (too large), -1 out of memory. */
static int keep_level(sw_part_mesh *m, sw_part_level_arrays *o, piece_job *j, size_t n, float error)
{
    uint32_t first_vertex = 0, first_index = o->index_count;
    int made = sw_part_level_emit(m, j->source_grid, o, (uint32_t)n, &first_vertex);
    sw_part_level *l = sw_grow(o->levels, &o->cap_l, (size_t)o->level_count + 1, sizeof *l);
    if (made == 0 || !l)
        return -1;
    o->levels = l;
    if (made < 0) {
        o->vertex_count = first_vertex;
        j->r->too_large++;
        return 0;
    }
    o->index_count += (uint32_t)n;
    sw_part_level *kept = &o->levels[o->level_count++];
    *kept = (sw_part_level){ j->piece, error, first_vertex, o->vertex_count - first_vertex,
                             first_index, (uint32_t)n, 0, j->front };
    kept->shading_side = (float)sw_part_level_shaded_side(m, j->source_grid, o, kept);
    j->r->triangles[j->kept++] += n / 3;
    j->last_error = error, j->last_indices = (uint32_t)n;
    return 1;
}

/* What the simplifier keeps of a piece's borders: a cut part's are locked
 * whole (its pieces meet there); another's rim may move, or have its
 * corners held (sw_part_rim.h). */
typedef enum { KEEP_NONE, KEEP_CORNERS } border_keep;

/* One simplification into m->dest: toward target_error (meshoptimizer's
 * relative units), stopping at target_indices (0: as far as the error
 * allows), keeping the border as asked. Its index count; 0 when it is not
 * a fifth smaller than the last level, or folds (counted). */
static size_t simplify_once(sw_part_mesh *m, piece_job *j, size_t target_indices,
                            float target_error, border_keep keep)
{
    const sw_part_rim *rim = &m->rim;
    int held = keep == KEEP_CORNERS && !j->cut;
    unsigned lock = j->cut ? meshopt_SimplifyLockBorder : 0;
    size_t n = meshopt_simplify(m->dest, held ? rim->idx : m->idx, m->icount,
                                held ? rim->pos : m->wpos, held ? rim->vertex_count : m->wcount,
                                3 * sizeof(float), target_indices, target_error, lock, NULL);
    sw_part_rim_unmap(rim, m->wcount, m->dest, held ? n : 0);
    if (n == 0 || n > 0.8 * j->last_indices) {
        j->r->not_smaller++;
        return 0;
    }
    if (j->cut && (!j->vertex_normals || folds(m, j->vertex_normals, n))) {
        j->r->folded++;
        return 0;
    }
    return n;
}

/* The measured error of m->dest[0 .. n) (above), sampled at a spacing
 * fine enough for bound; negative when out of memory. */
static double measured_error(sw_part_mesh *m, piece_job *j, size_t n, double bound)
{
    sw_mesh_view lod = { m->wpos, m->dest, m->wcount, (uint32_t)n };
    sw_mesh_grid *lod_grid = sw_mesh_grid_make(&lod);
    if (!lod_grid)
        return -1;
    double spacing = 2 * bound;
    double d = fmax(sw_mesh_distance(&lod, j->source_grid, spacing),
                    sw_mesh_distance(&j->source, lod_grid, spacing));
    sw_mesh_grid_free(lod_grid);
    return d + m->error;
}

/* A rim vertex is held where the rim turns by more than 45 degrees. */
#define RIM_CORNER_COS 0.70710678

/* meshoptimizer's simplification toward bound keeping the border as
 * asked, in m->dest: its index count (0: none; -1 out of memory), its
 * measured error in *error, within the bound or not. */
static long long simplify_toward(sw_part_mesh *m, piece_job *j, double bound, double scale,
                                 border_keep keep, double *error)
{
    size_t n = simplify_once(m, j, 0, (float)((bound - m->error) / scale), keep);
    double e = n ? measured_error(m, j, n, bound) : 0;
    if (e < 0)
        return -1;
    *error = e;
    return (long long)n;
}

/* The level for bound into m->dest: its index count (0: none; -1 out of
 * memory), its error in *error. A part's open rim (a sheet's edge, a hole
 * in it) is where meshoptimizer's estimate fails most: moving a rim vertex
 * along the rim cuts a corner off, tens of times the bound. When the
 * simplification is not within the bound, it is made again with the rim's
 * corners held; when neither is within, the one nearer the bound is kept,
 * over it, as a level for coarser views (a flat plate's first cut a corner
 * off, hundreds of times the bound, where the held one was 1.5 times it;
 * keeping the first left the plate no level a view could use). (Searching
 * the index count for the coarsest level within each bound was tried:
 * levels then spend the whole bound, and the showroom walk's pictures
 * differed from the reference's past their limit at fewer triangles.
 * Locking the whole border found nothing more within.) */
static long long simplify_within(sw_part_mesh *m, piece_job *j, double bound, double scale,
                                 double *error)
{
    long long n = simplify_toward(m, j, bound, scale, KEEP_NONE, error);
    if (n > 0 && *error > bound && !j->cut) {
        memcpy(m->aside, m->dest, (size_t)n * sizeof *m->dest);   /* the first, kept */
        double e = 0;
        long long k = simplify_toward(m, j, bound, scale, KEEP_CORNERS, &e);
        if (k < 0)
            return -1;
        if (k > 0 && (e <= bound || e < *error))
            n = k, *error = e;
        else   /* the first is nearer */
            memcpy(m->dest, m->aside, (size_t)n * sizeof *m->dest);
    }
    j->r->over_bound += n > 0 && *error > bound;
    return n;
}

/* A piece of a few triangles (asked with no bound on the error, fewer can
 * come out as none at all: a sheet collapses to nothing). */
#define COARSEST_INDICES 24

/* The coarsest simplification of a few triangles, kept as the last level
 * when it is a fifth smaller than the last and its error rises: for views
 * where the whole piece spans a few pixels, past the last bound. 0 when out
 * of memory. */
static int keep_coarsest(sw_part_mesh *m, sw_part_level_arrays *o, piece_job *j, double bound)
{
    size_t n = simplify_once(m, j, COARSEST_INDICES, FLT_MAX, KEEP_NONE);
    double e = n ? measured_error(m, j, n, bound) : 0;
    if (e < 0)
        return 0;
    if (n == 0 || !((float)e > j->last_error))
        return 1;
    return keep_level(m, o, j, n, (float)e) >= 0;
}

/* The job's levels toward rising bounds, kept as the header says. */
static sw_status build_piece(sw_part_mesh *m, sw_part_level_arrays *o, piece_job *j, sw_error *err)
{
    uint32_t *dest = sw_grow(m->dest, &m->cap_d, m->icount + 1, sizeof *m->dest);
    if (dest)
        m->dest = dest;
    uint32_t *aside = sw_grow(m->aside, &m->cap_a, m->icount + 1, sizeof *m->aside);
    if (aside)
        m->aside = aside;
    if (!dest || !aside)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    double size = sw_part_mesh_size(m), scale = meshopt_simplifyScale(m->wpos, m->wcount, 12);
    j->source = (sw_mesh_view){ m->wpos, m->idx, m->wcount, m->icount };
    j->source_grid = sw_mesh_grid_make(&j->source);
    if (!j->source_grid)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: grid");
    j->vertex_normals = j->cut ? source_vertex_normals(m) : NULL;
    const sw_part_tris tris = { m->wpos, m->idx, m->wcount, m->icount };
    if (!j->cut && !sw_part_rim_hold_corners(&m->rim, &tris, RIM_CORNER_COS)) {
        sw_mesh_grid_free(j->source_grid);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    }
    j->last_error = 0, j->last_indices = m->icount, j->kept = 0;
    int room = 1;
    if (scale > 0 && j->cut) {   /* the source itself: a level at this front */
        memcpy(m->dest, m->idx, m->icount * sizeof *m->idx);
        room = keep_level(m, o, j, m->icount, (float)fmax(m->error, FLT_MIN)) >= 0;
    }
    for (uint32_t k = 0; room && scale > 0 && k < j->opt->count; k++) {
        double bound = size * j->opt->finest * pow(j->opt->step, k);
        if (bound <= 2 * m->error || bound < j->min_bound)
            continue;   /* the source is not that much closer to the surfaces, or the
                           front's border holds the level coarser than that anyway */
        double measured = 0;
        long long n = simplify_within(m, j, bound, scale, &measured);
        if (n < 0) {
            room = 0;
            break;
        }
        if (n == 0)
            continue;
        float error = (float)measured;
        if (!(error > j->last_error)) {
            j->r->not_smaller++;
            continue;
        }
        room = keep_level(m, o, j, (size_t)n, error) >= 0;
        j->r->worst_over_bound = fmax(j->r->worst_over_bound, error / bound);
    }
    if (room && scale > 0 && j->kept > 0)
        room = keep_coarsest(m, o, j, size * j->opt->finest * pow(j->opt->step, j->opt->count));
    sw_mesh_grid_free(j->source_grid);
    free(j->vertex_normals);
    if (!room)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    j->r->source_triangles += j->kept ? m->icount / 3 : 0;
    j->r->levels += j->kept;
    return SW_OK;
}

/* The meshes the pieces are simplified from: each surface's finest level at
 * its own front (for a part not cut: it has no border), and the surfaces
 * of cut parts at each of the fronts their pieces share. */
typedef struct piece_sources {
    sw_part_source finest, front[SW_PART_LEVEL_FRONTS];
    int cut_any;
} piece_sources;

static sw_status build_sources(const sw_pack *pack, const sw_levels *levels,
                               const uint8_t *cut, piece_sources *ps, sw_error *err)
{
    memset(ps, 0, sizeof *ps);
    sw_status st = sw_part_source_build(pack, levels, NULL, &ps->finest, err);
    uint32_t n = pack->surface_count;
    for (uint32_t p = 0; p < pack->meta->part_count; p++)
        ps->cut_any |= cut[p];
    if (st != SW_OK || !ps->cut_any)
        return st;
    float *bound = malloc(((size_t)n + 1) * sizeof *bound);
    double *diagonal = malloc(((size_t)pack->meta->part_count + 1) * sizeof *diagonal);
    if (!bound || !diagonal)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    for (uint32_t p = 0; st == SW_OK && p < pack->meta->part_count; p++)
        diagonal[p] = cut[p] ? sw_part_diagonal(pack, p) : 0;
    for (uint32_t f = 0; st == SW_OK && f < SW_PART_LEVEL_FRONTS; f++) {
        for (uint32_t s = 0; s < n; s++) {
            uint32_t p = pack->surfaces[s].part;
            bound[s] = cut[p] ? (float)sw_part_level_front_bound(diagonal[p], f) : 0.0f;
        }
        st = sw_part_source_build(pack, levels, bound, &ps->front[f], err);
    }
    free(bound);
    free(diagonal);
    return st;
}

static void free_sources(piece_sources *ps)
{
    sw_part_source_free(&ps->finest);
    for (uint32_t f = 0; f < SW_PART_LEVEL_FRONTS; f++)
        sw_part_source_free(&ps->front[f]);
}

/* Piece g of the part whose surfaces are [first, end), at every front it
 * is made at; cut_diagonal: the part's diagonal when it is cut, else -1. A
 * cut part's first piece also keeps the part's levels of itself whole. */
static sw_status build_one_piece(sw_part_mesh *m, sw_part_level_arrays *o, const sw_levels *levels,
                                 const uint32_t *piece_of, const piece_sources *ps,
                                 double cut_diagonal, uint32_t g, uint32_t first, uint32_t end,
                                 const sw_part_levels_options *opt, sw_part_levels_report *r,
                                 sw_error *err)
{
    uint32_t before = o->level_count;
    int cut = cut_diagonal >= 0;
    sw_status st = SW_OK;
    for (uint32_t f = 0; st == SW_OK && f < (cut ? SW_PART_LEVEL_FRONTS : 1u); f++) {
        const sw_part_source *src = cut ? &ps->front[f] : &ps->finest;
        int got = sw_part_mesh_gather(m, levels, piece_of, src, g, first, end);
        r->incomplete += got < 0;
        piece_job j = { .piece = g, .front = f, .cut = cut, .opt = opt, .r = r,
                        .min_bound = f ? sw_part_level_front_bound(cut_diagonal, f) : 0 };
        if (got == 0 || (got > 0 && (!sw_part_mesh_weld(m) || !sw_part_mesh_orient(m))))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
        else if (got > 0 && m->icount > 0)
            st = build_piece(m, o, &j, err);
    }
    if (st == SW_OK && cut && g == piece_of[first]) {   /* the whole part, far away */
        int got = sw_part_mesh_gather(m, levels, piece_of, &ps->finest, SW_PART_MESH_ALL, first,
                                      end);
        piece_job j = { .piece = g, .front = SW_PART_LEVEL_WHOLE, .opt = opt, .r = r };
        if (got == 0 || (got > 0 && (!sw_part_mesh_weld(m) || !sw_part_mesh_orient(m))))
            st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
        else if (got > 0 && m->icount > 0)
            st = build_piece(m, o, &j, err);
    }
    r->with_levels += o->level_count > before;
    return st;
}

/* One piece to make: piece g of the part whose surfaces are [first, end). */
typedef struct piece_task {
    uint32_t part, g, first, end;
} piece_task;

/* A worker's own: the mesh it simplifies in, its counts, its failure. */
typedef struct piece_worker {
    sw_part_mesh m;
    sw_part_levels_report r;
    uint32_t failed;   /* the task that failed (UINT32_MAX: none) */
    sw_error err;
} piece_worker;

/* The pieces made by workers (sw_parts_take_items, as many as the runner
 * runs at once). One worker appends each piece's levels to the output in
 * turn; more make each piece's into arrays of its own, made[task], joined
 * in piece order after the run: the bytes are the same whichever worker
 * made which piece, and when (build_threads compares the two ways). */
typedef struct pieces_run {
    const sw_pack *pack;
    const sw_levels *levels;
    const uint32_t *piece_of;
    const uint8_t *cut;
    const piece_sources *ps;
    const sw_part_levels_options *opt;
    const piece_task *tasks;
    sw_part_level_arrays *out;
    sw_part_level_arrays *made;   /* NULL: one worker, straight into out */
    uint32_t *kept;               /* levels kept per task */
    piece_worker *workers;
    uint32_t task_count, worker_count;
} pieces_run;

static int make_piece(void *arg, uint32_t worker, uint32_t t)
{
    pieces_run *run = arg;
    piece_worker *w = &run->workers[worker];
    const piece_task *k = &run->tasks[t];
    sw_part_level_arrays *into = run->made ? &run->made[t] : run->out;
    uint32_t before = into->level_count;
    double diagonal = run->cut[k->part] ? sw_part_diagonal(run->pack, k->part) : -1;
    sw_status st = build_one_piece(&w->m, into, run->levels, run->piece_of, run->ps, diagonal,
                                   k->g, k->first, k->end, run->opt, &w->r, &w->err);
    run->kept[t] = into->level_count - before;
    w->failed = st == SW_OK ? w->failed : t;
    return st == SW_OK;
}

/* Part by part (a run of surfaces), its pieces first .. end, at most
 * `pieces` in all; NULL when out of memory. */
static piece_task *list_pieces(const sw_pack *pack, const uint32_t *piece_of, uint32_t pieces,
                               uint32_t *count)
{
    piece_task *tasks = malloc(((size_t)pieces + 1) * sizeof *tasks);
    *count = 0;
    for (uint32_t s = 0, e; tasks && s < pack->surface_count; s = e) {
        uint32_t part = pack->surfaces[s].part, first = piece_of[s], end = first + 1;
        for (e = s; e < pack->surface_count && pack->surfaces[e].part == part; e++)
            end = piece_of[e] + 1 > end ? piece_of[e] + 1 : end;
        for (uint32_t g = first; g < end && *count < pieces; g++)
            tasks[(*count)++] = (piece_task){ part, g, s, e };
    }
    return tasks;
}

static void add_report(sw_part_levels_report *to, const sw_part_levels_report *r)
{
    to->with_levels += r->with_levels, to->levels += r->levels, to->incomplete += r->incomplete;
    to->not_smaller += r->not_smaller, to->folded += r->folded, to->over_bound += r->over_bound;
    to->too_large += r->too_large, to->source_triangles += r->source_triangles;
    for (uint32_t k = 0; k < SW_PART_LEVELS_MAX; k++)
        to->triangles[k] += r->triangles[k];
    to->worst_over_bound = fmax(to->worst_over_bound, r->worst_over_bound);
}

/* The workers' counts added to r; the error of the first piece that
 * failed, whichever worker made it. */
static sw_status end_run(pieces_run *run, sw_part_levels_report *r, sw_error *err)
{
    uint32_t failed = UINT32_MAX;
    for (uint32_t w = 0; w < run->worker_count; w++) {
        piece_worker *k = &run->workers[w];
        if (k->failed < failed)
            failed = k->failed, *err = k->err;
        add_report(r, &k->r);
        sw_part_mesh_free(&k->m);
    }
    return failed == UINT32_MAX ? SW_OK : err->status;
}

static sw_status build_all(const sw_pack *pack, const sw_levels *levels, const uint32_t *piece_of,
                           const uint8_t *cut, const piece_sources *ps,
                           const sw_part_levels_options *opt, sw_part_level_arrays *o,
                           uint32_t *piece_levels, sw_part_levels_report *r, sw_error *err)
{
    pieces_run run = { pack, levels, piece_of, cut, ps, opt, NULL, o, NULL, NULL, NULL, 0, 0 };
    piece_task *tasks = list_pieces(pack, piece_of, r->pieces, &run.task_count);
    run.tasks = tasks;
    run.worker_count = sw_parts_at_once(opt->runner);
    if (run.worker_count > run.task_count)
        run.worker_count = run.task_count ? run.task_count : 1;
    if (run.worker_count > 1)
        run.made = calloc((size_t)run.task_count + 1, sizeof *run.made);
    run.kept = calloc((size_t)run.task_count + 1, sizeof *run.kept);
    run.workers = calloc(run.worker_count, sizeof *run.workers);
    sw_status st = tasks && run.kept && run.workers && (run.made || run.worker_count == 1)
                       ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    for (uint32_t w = 0; st == SW_OK && w < run.worker_count; w++)
        run.workers[w].failed = UINT32_MAX;
    if (st == SW_OK) {
        sw_parts_take_items(opt->runner, run.worker_count, make_piece, &run, run.task_count);
        st = end_run(&run, r, err);
    }
    uint32_t made = 0;   /* levels of the pieces so far */
    for (uint32_t t = 0; st == SW_OK && t < run.task_count; t++) {
        made += run.kept[t];
        piece_levels[tasks[t].g + 1] = made;
    }
    if (st == SW_OK && run.made && !sw_part_level_arrays_join(o, run.made, run.task_count))
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    for (uint32_t t = 0; run.made && t < run.task_count; t++)
        sw_part_level_arrays_free(&run.made[t]);
    free(run.made);
    free(run.kept);
    free(run.workers);
    free(tasks);
    return st;
}

/* The pieces, and which parts are cut (more than one piece). */
static sw_status cut_parts(const sw_pack *pack, const sw_part_levels_options *opt,
                           sw_part_levels_built *out, uint8_t **cut, sw_part_levels_report *r,
                           sw_error *err)
{
    out->piece_of = malloc(((size_t)pack->surface_count + 1) * sizeof *out->piece_of);
    *cut = calloc((size_t)pack->meta->part_count + 1, 1);
    if (!out->piece_of || !*cut)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    sw_part_pieces_options po = { opt->cut_patches, opt->piece_patches };
    sw_status st = sw_part_pieces(pack, &po, out->piece_of, &r->pieces, err);
    for (uint32_t s = 1; st == SW_OK && s < pack->surface_count; s++)
        if (out->piece_of[s] != out->piece_of[s - 1] &&
            pack->surfaces[s].part == pack->surfaces[s - 1].part)
            (*cut)[pack->surfaces[s].part] = 1;
    for (uint32_t p = 0; st == SW_OK && p < pack->meta->part_count; p++)
        r->cut_parts += (*cut)[p];
    return st;
}

sw_status sw_part_levels_build(const sw_pack *pack, const sw_levels *levels,
                               const sw_part_levels_options *opt, sw_part_levels_built *out,
                               sw_part_levels_report *report, sw_error *err)
{
    memset(out, 0, sizeof *out);
    memset(report, 0, sizeof *report);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    sw_part_levels_options o = opt ? *opt : (sw_part_levels_options){ 0 };
    o.finest = o.finest > 0 ? o.finest : 1.0 / 512;
    o.step = o.step > 1 ? o.step : 2.0;
    o.count = o.count ? (o.count < SW_PART_LEVELS_MAX - 2 ? o.count : SW_PART_LEVELS_MAX - 2)
                      : 8;
    report->parts = pack->meta->part_count;
    uint8_t *cut = NULL;
    piece_sources ps;
    memset(&ps, 0, sizeof ps);
    sw_status st = cut_parts(pack, &o, out, &cut, report, err);
    if (st == SW_OK)
        st = build_sources(pack, levels, cut, &ps, err);
    sw_part_level_arrays arrays = { 0 };
    if (st == SW_OK) {
        out->piece_levels = calloc((size_t)report->pieces + 1, sizeof *out->piece_levels);
        st = out->piece_levels ? build_all(pack, levels, out->piece_of, cut, &ps, &o, &arrays,
                                           out->piece_levels, report, err)
                               : sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory");
    }
    free_sources(&ps);
    free(cut);
    out->levels = arrays.levels, out->vertices = arrays.vertices, out->indices = arrays.indices;
    out->view = (sw_part_levels){ out->levels, out->piece_levels, out->piece_of, out->vertices,
                                  out->indices, arrays.level_count, arrays.vertex_count,
                                  arrays.index_count, report->pieces, pack->surface_count };
    if (st != SW_OK)
        sw_part_levels_built_free(out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    report->seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    return st;
}

void sw_part_levels_built_free(sw_part_levels_built *b)
{
    free(b->levels);
    free(b->piece_levels);
    free(b->piece_of);
    free(b->vertices);
    free(b->indices);
    memset(b, 0, sizeof *b);
}
