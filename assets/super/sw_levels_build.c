/* SPDX-License-Identifier: MIT */
/* The static levels of a pack's surfaces (sw_levels_build.h): the front
 * moved level by level, every surface tessellated inside its loops there,
 * its border read back as chains, its error measured; then the levels
 * ordered by surface and the ones that are no coarser dropped. */
#include "sw_levels_build.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sw_levels_border.h"
#include "sw_levels_measure.h"
#include "sw_seam_select.h"
#include "sw_seam_surface.h"
#include "sw_surface_at.h"
#include "sw_trim_tess.h"
#include "sw_walk_memory.h"

/* A level as made, before the levels are ordered by surface: its mesh,
 * chains and points are in its worker's arrays. */
typedef struct made_level {
    uint32_t surface, rank, worker;
    float error, made_bound;
    uint32_t first_vertex, vertex_count, first_index, index_count;
    uint32_t first_chain, chain_count;
} made_level;

typedef struct grow {
    void *data;
    size_t count, capacity, size;
} grow;

/* Room for more items at the end of g; NULL when out of memory. */
static void *grow_by(grow *g, size_t more)
{
    if (g->count + more > g->capacity) {
        size_t cap = g->capacity ? g->capacity : 1024;
        while (cap < g->count + more)
            cap *= 2;
        void *p = realloc(g->data, cap * g->size);
        if (!p)
            return NULL;
        g->data = p, g->capacity = cap;
    }
    void *at = (char *)g->data + g->count * g->size;
    g->count += more;
    return at;
}

struct builder;

/* What a worker makes one surface's level with, and the levels it made
 * (sw_parts_take_items: a rank's surfaces are shared out among as many
 * workers as the runner runs at once). Which worker made a level changes
 * nothing in the levels: assemble() orders them by surface and rank. */
typedef struct level_worker {
    const struct builder *b;
    uint32_t index;
    sw_levels_report report;          /* its counts, added to the build's after */
    uint32_t failed;                  /* the surface it failed on (UINT32_MAX: none) */
    sw_error err;
    void *scratch_block;
    sw_arena scratch;
    sw_seam_point *seam_points;       /* the surface's loops, in surface-loop order */
    uint32_t *slots, *ids;
    float *loop_uvs;
    uint32_t *loop_at, *loop_len;     /* per loop of the surface: into the above */
    uint8_t *loop_vanished;
    sw_trim_point *points;            /* the tessellator's loops: outer, then holes */
    uint32_t *loop_first, *tess_loop; /* tessellated loop k is surface loop tess_loop[k] */
    sw_trim_patch *patches;
    float *positions, *normals, *uvs;
    uint32_t *out_ids;
    uint16_t *indices;
    sw_strip_point *chain_points;
    uint32_t *chain_first;
    grow made, vertices, vertex_uvs, index_data, chains, points_out;
} level_worker;

/* The build: what every worker reads (the fronts, the surfaces' sizes,
 * written between ranks only) and the workers. alive[s] is written during
 * a rank by the worker making surface s alone. */
typedef struct builder {
    const sw_pack *pack;
    sw_levels_options opt;
    sw_levels_report *report;
    sw_seam_select sel;
    sw_seam_select finest;            /* sel with every original shown: the sewn polylines */
    uint32_t *finest_shown;
    void *select_block;
    size_t scratch_bytes;             /* the tessellator's, a worker */
    uint32_t max_points, max_patches, max_loops;
    level_worker *workers;
    uint32_t worker_count;
    double *size, *sew_offset;        /* per surface */
    double *noise;                    /* per surface: below this, float positions differ by
                                         rounding alone (levels no finer than that are equal) */
    uint8_t *alive;                   /* per surface: its outer loop has not vanished */
    float *bounds;
} builder;

/* The box diagonal of surface s's patches. */
static double surface_size(const sw_pack *pack, uint32_t s)
{
    const sw_pack_surface *sf = &pack->surfaces[s];
    double d = 0;
    for (int k = 0; k < 3; k++) {
        float lo = INFINITY, hi = -INFINITY;
        for (uint32_t i = sf->first_patch; i < sf->first_patch + sf->patch_count; i++) {
            lo = fminf(lo, pack->patches[i].box_min[k]);
            hi = fmaxf(hi, pack->patches[i].box_max[k]);
        }
        d += hi > lo ? ((double)hi - lo) * ((double)hi - lo) : 0;
    }
    return sqrt(d);
}

/* The largest coordinate of surface s's patch boxes. */
static double surface_magnitude(const sw_pack *pack, uint32_t s)
{
    const sw_pack_surface *sf = &pack->surfaces[s];
    double m = 0;
    for (uint32_t i = sf->first_patch; i < sf->first_patch + sf->patch_count; i++)
        for (int k = 0; k < 3; k++)
            m = fmax(m, fmax(fabs(pack->patches[i].box_min[k]), fabs(pack->patches[i].box_max[k])));
    return m;
}

static void *take(size_t n, size_t size, int *failed)
{
    void *p = malloc((n + 1) * size);
    *failed |= p == NULL;
    return p;
}

/* Worker w's scratch, sized for b's largest surface; 0 when out of memory. */
static int worker_open(level_worker *w, const builder *b, uint32_t index)
{
    size_t v = SW_WALK_VERTICES, mp = b->max_points, ml = b->max_loops;
    int failed = 0;
    *w = (level_worker){ .b = b, .index = index, .failed = UINT32_MAX };
    w->scratch_block = take(b->scratch_bytes, 1, &failed);
    w->seam_points = take(mp, sizeof *w->seam_points, &failed);
    w->slots = take(mp, sizeof *w->slots, &failed);
    w->ids = take(mp, sizeof *w->ids, &failed);
    w->loop_uvs = take(2 * mp, sizeof *w->loop_uvs, &failed);
    w->loop_at = take(ml, sizeof *w->loop_at, &failed);
    w->loop_len = take(ml, sizeof *w->loop_len, &failed);
    w->loop_vanished = take(ml, 1, &failed);
    w->points = take(mp, sizeof *w->points, &failed);
    w->loop_first = take(ml + 1, sizeof *w->loop_first, &failed);
    w->tess_loop = take(ml, sizeof *w->tess_loop, &failed);
    w->patches = take(b->max_patches, sizeof *w->patches, &failed);
    w->positions = take(3 * v, sizeof(float), &failed);
    w->normals = take(3 * v, sizeof(float), &failed);
    w->uvs = take(2 * v, sizeof(float), &failed);
    w->out_ids = take(v, sizeof *w->out_ids, &failed);
    w->indices = take(SW_WALK_INDICES, sizeof *w->indices, &failed);
    w->chain_points = take(v, sizeof *w->chain_points, &failed);
    w->chain_first = take(ml + 1, sizeof *w->chain_first, &failed);
    if (!failed)
        sw_arena_init(&w->scratch, w->scratch_block, b->scratch_bytes);
    w->made.size = sizeof(made_level), w->vertices.size = sizeof(sw_level_vertex);
    w->vertex_uvs.size = 2 * sizeof(float);
    w->index_data.size = sizeof(uint16_t), w->chains.size = sizeof(sw_level_chain);
    w->points_out.size = sizeof(sw_strip_point);
    return !failed;
}

static void worker_close(level_worker *w)
{
    void *blocks[] = { w->scratch_block, w->seam_points, w->slots, w->ids, w->loop_uvs,
                       w->loop_at, w->loop_len, w->loop_vanished, w->points, w->loop_first,
                       w->tess_loop, w->patches, w->positions, w->normals, w->uvs, w->out_ids,
                       w->indices, w->chain_points, w->chain_first, w->made.data,
                       w->vertices.data, w->vertex_uvs.data, w->index_data.data,
                       w->chains.data, w->points_out.data };
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

/* The largest surface's points, loops and patches, and the tessellator's
 * scratch for it. */
static void measure_largest(builder *b)
{
    const sw_pack *pack = b->pack;
    const sw_seam_graph *g = &pack->seam;
    int degree = 1;
    for (uint32_t i = 0; i < pack->meta->patch_count; i++) {
        degree = pack->patches[i].degree_u > degree ? pack->patches[i].degree_u : degree;
        degree = pack->patches[i].degree_v > degree ? pack->patches[i].degree_v : degree;
    }
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t points = 0, loops = g->surface_loops[s + 1] - g->surface_loops[s];
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            points += g->loops[l].slot_count;
        b->max_points = points > b->max_points ? points : b->max_points;
        b->max_loops = loops > b->max_loops ? loops : b->max_loops;
        uint32_t p = pack->surfaces[s].patch_count;
        b->max_patches = p > b->max_patches ? p : b->max_patches;
    }
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    b->scratch_bytes = sw_trim_tess_scratch_bytes(b->max_patches, b->max_points, degree, &opt);
}

/* The fronts and the per-surface arrays, and a worker for each surface
 * the runner makes at once. */
static sw_status builder_open(builder *b, const sw_pack *pack, sw_error *err)
{
    const sw_seam_graph *g = &pack->seam;
    int failed = 0;
    measure_largest(b);
    size_t select = sw_seam_select_arena_bytes(g), n = g->surface_count;
    b->select_block = take(select, 1, &failed);
    b->size = take(n, sizeof *b->size, &failed);
    b->sew_offset = take(n, sizeof *b->sew_offset, &failed);
    b->noise = take(n, sizeof *b->noise, &failed);
    b->alive = take(n, 1, &failed);
    b->finest_shown = take(g->original_count, sizeof *b->finest_shown, &failed);
    b->bounds = take(n, sizeof *b->bounds, &failed);
    b->worker_count = sw_parts_at_once(b->opt.runner);
    if (b->worker_count > n)
        b->worker_count = n ? (uint32_t)n : 1;
    b->workers = calloc(b->worker_count, sizeof *b->workers);
    failed |= !b->workers;
    for (uint32_t i = 0; !failed && i < b->worker_count; i++)
        failed |= !worker_open(&b->workers[i], b, i);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory for %u surfaces",
                            (unsigned)n);
    sw_arena select_arena;
    sw_arena_init(&select_arena, b->select_block, select);
    sw_status st = sw_seam_select_init_checked(&b->sel, g, &select_arena, err);
    if (st == SW_OK) {
        b->finest = b->sel;
        for (uint32_t o = 0; o < g->original_count; o++)
            b->finest_shown[b->sel.leaf_lo[o]] = o;
        b->finest.shown = b->finest_shown;
    }
    return st;
}

static void builder_close(builder *b)
{
    void *blocks[] = { b->select_block, b->size, b->sew_offset, b->noise, b->alive,
                       b->finest_shown, b->bounds, b->workers };
    for (uint32_t i = 0; b->workers && i < b->worker_count; i++)
        worker_close(&b->workers[i]);
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

/* Each surface's size and sewing offset; surfaces with no size or no
 * loops get no level. */
static void measure_surfaces(builder *b)
{
    const sw_seam_graph *g = &b->pack->seam;
    sw_trim_patch *patches = b->workers[0].patches;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t count = 0;
        b->size[s] = surface_size(b->pack, s);
        b->noise[s] = 8 * FLT_EPSILON * surface_magnitude(b->pack, s);
        b->sew_offset[s] = 0;
        b->alive[s] = b->size[s] > 0 && g->surface_loops[s + 1] > g->surface_loops[s] &&
                      sw_trim_patches_from_pack(b->pack, s, patches, b->max_patches, &count,
                                                NULL) == SW_OK;
        for (uint32_t l = g->surface_loops[s]; b->alive[s] && l < g->surface_loops[s + 1]; l++)
            b->sew_offset[s] = fmax(b->sew_offset[s],
                                    sw_seam_sewing_offset(g, &g->loops[l], patches, count));
    }
}

/* Surface s's loops at the front, each with its slots; 0 when an outer
 * loop vanished. Then the tessellator's loops: outer ones first, then the
 * holes that have not vanished (as the walk gives them, sw_seam_surface.h),
 * or the outer ones alone (with_holes 0). */
static int gather(level_worker *w, const sw_seam_select *front, uint32_t s, float pin)
{
    const builder *b = w->b;
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t at = 0, first = g->surface_loops[s];
    for (uint32_t l = first; l < g->surface_loops[s + 1]; l++) {
        uint32_t count = 0;
        int vanished = 0;
        /* Cannot fail: l is in range and the buffers hold the surface's slots. */
        sw_seam_select_loop_slots(front, l, pin, w->seam_points + at, w->slots + at,
                                  b->max_points - at, &count, &vanished, NULL);
        if (vanished && (g->loops[l].flags & SW_SEAM_LOOP_OUTER))
            return 0;
        /* A hole the front has closed is kept as sewn: the walk shows it
         * wherever its neighbours are drawn finer, and a level without it
         * would cover it there. */
        if (vanished)
            sw_seam_select_loop_slots(&b->finest, l, pin, w->seam_points + at, w->slots + at,
                                      b->max_points - at, &count, &vanished, NULL);
        w->loop_at[l - first] = at, w->loop_len[l - first] = count;
        w->loop_vanished[l - first] = (uint8_t)vanished;
        for (uint32_t i = at; i < at + count; i++) {
            w->ids[i] = w->seam_points[i].vertex;
            memcpy(w->loop_uvs + 2 * i, w->seam_points[i].uv, 2 * sizeof(float));
        }
        at += count;
    }
    return 1;
}

static sw_trim_loops tess_loops(level_worker *w, uint32_t s, int with_holes)
{
    const builder *b = w->b;
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t first = g->surface_loops[s], k = 0, total = 0;
    w->loop_first[0] = 0;
    for (int holes = 0; holes < 1 + with_holes; holes++)
        for (uint32_t l = first; l < g->surface_loops[s + 1]; l++) {
            uint32_t i = l - first;
            if ((!(g->loops[l].flags & SW_SEAM_LOOP_OUTER)) != holes || w->loop_vanished[i])
                continue;
            for (uint32_t j = 0; j < w->loop_len[i]; j++) {
                const sw_seam_point *sp = &w->seam_points[w->loop_at[i] + j];
                sw_trim_point *tp = &w->points[total + j];
                memcpy(tp->uv, sp->uv, sizeof tp->uv);
                memcpy(tp->p, g->vertices[sp->vertex].p, sizeof tp->p);
                tp->id = sp->vertex;
            }
            total += w->loop_len[i];
            w->tess_loop[k] = i;
            w->loop_first[++k] = total;
        }
    return (sw_trim_loops){ w->points, w->loop_first, k };
}

/* Surface s tessellated at bound inside its gathered loops; with
 * drop_holes, SW_ERR_FORMAT retried without its holes. */
static sw_status tessellate(level_worker *w, uint32_t s, double bound, int drop_holes,
                            sw_trim_loops *loops, sw_trim_tess_result *t)
{
    const builder *b = w->b;
    uint32_t count = 0;
    sw_trim_patches_from_pack(b->pack, s, w->patches, b->max_patches, &count, NULL);
    sw_trim_tess_buffers out = { w->positions, w->normals, w->uvs, w->out_ids, w->indices,
                                 SW_WALK_VERTICES, SW_WALK_INDICES, 0, NULL, 0 };
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    *loops = tess_loops(w, s, 1);
    sw_status st = sw_trim_tess(w->patches, count, loops, bound, &opt, &w->scratch, &out, t,
                                NULL);
    if (st == SW_ERR_FORMAT && drop_holes) {
        sw_trim_loops outer = tess_loops(w, s, 0);
        if (outer.loop_count < loops->loop_count) {
            *loops = outer;
            st = sw_trim_tess(w->patches, count, loops, bound, &opt, &w->scratch, &out, t, NULL);
        }
    }
    return st;
}

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

static double level_bound(const builder *b, uint32_t s, uint32_t rank)
{
    return b->size[s] * b->opt.finest * pow(b->opt.step, rank);
}

/* The made mesh, its chains (in the surface's loop order; a loop left out
 * of the tessellation has none) and its record into the growing arrays. */
static sw_status keep(level_worker *w, uint32_t s, uint32_t rank, float error,
                      const sw_trim_tess_result *t, const sw_trim_loops *loops, sw_error *err)
{
    const builder *b = w->b;
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t loop_count = g->surface_loops[s + 1] - g->surface_loops[s];
    made_level m = { s, rank, w->index, error, (float)level_bound(b, s, rank),
                     (uint32_t)w->vertices.count, t->vertex_count, (uint32_t)w->index_data.count,
                     t->index_count, (uint32_t)w->chains.count, loop_count };
    uint32_t chain_total = w->chain_first[loops->loop_count];
    made_level *mp = grow_by(&w->made, 1);
    sw_level_vertex *v = grow_by(&w->vertices, t->vertex_count);
    float *uv = grow_by(&w->vertex_uvs, t->vertex_count);
    uint16_t *idx = grow_by(&w->index_data, t->index_count);
    sw_level_chain *ch = grow_by(&w->chains, loop_count);
    size_t points_at = w->points_out.count;
    sw_strip_point *pts = grow_by(&w->points_out, chain_total);
    if (!mp || !v || !uv || !idx || !ch || !pts)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    *mp = m;
    for (uint32_t i = 0; i < t->vertex_count; i++) {
        memcpy(v[i].p, w->positions + 3 * i, sizeof v[i].p);
        for (int a = 0; a < 3; a++)
            v[i].normal[a] = snorm8(w->normals[3 * i + a]);
        v[i].normal[3] = 0;
    }
    memcpy(uv, w->uvs, 2 * sizeof(float) * t->vertex_count);
    memcpy(idx, w->indices, t->index_count * sizeof *idx);
    memcpy(pts, w->chain_points, chain_total * sizeof *pts);
    memset(ch, 0, loop_count * sizeof *ch);
    for (uint32_t k = 0; k < loops->loop_count; k++)
        ch[w->tess_loop[k]] = (sw_level_chain){ (uint32_t)points_at + w->chain_first[k],
                                                w->chain_first[k + 1] - w->chain_first[k] };
    return SW_OK;
}


/* Surface s's level of this rank at the current front, kept when it
 * tessellates, its border reads back and its error is measured. */
static sw_status make_level(level_worker *w, uint32_t s, uint32_t rank, sw_error *err)
{
    const builder *b = w->b;
    const sw_seam_graph *g = &b->pack->seam;
    double bound = level_bound(b, s, rank);
    float pin = (float)(bound * SW_SEAM_SHARE);
    if (!gather(w, &b->sel, s, pin)) {
        b->alive[s] = 0;
        w->report.vanished++;
        return SW_OK;
    }
    sw_trim_loops loops;
    sw_trim_tess_result t;
    sw_status st = tessellate(w, s, bound, 0, &loops, &t);
    /* A hole whose coarse polyline crosses another loop: the loops as sewn
     * (which do not cross) rather than a level without the hole, which
     * would cover it wherever the walk shows it. */
    if (st == SW_ERR_FORMAT) {
        gather(w, &b->finest, s, pin);
        st = tessellate(w, s, bound, 1, &loops, &t);
    }
    w->report.too_large += st == SW_ERR_RANGE;
    w->report.refused += st != SW_OK && st != SW_ERR_RANGE;
    if (st != SW_OK)
        return st == SW_ERR_NO_MEMORY ? sw_error_set(err, st, "levels: tessellator scratch")
                                      : SW_OK;
    uint32_t first = g->surface_loops[s];
    sw_border_loop *bl = malloc(((size_t)loops.loop_count + 1) * sizeof *bl);
    if (!bl)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    for (uint32_t k = 0; k < loops.loop_count; k++) {
        uint32_t i = w->tess_loop[k];
        bl[k] = (sw_border_loop){ w->ids + w->loop_at[i], w->loop_uvs + 2 * w->loop_at[i],
                                  w->slots + w->loop_at[i], w->loop_len[i],
                                  g->loops[first + i].slot_count };
    }
    const sw_border_mesh mesh = { w->out_ids, w->uvs, w->indices, t.vertex_count,
                                  t.index_count };
    sw_error why = { 0 };
    st = sw_levels_border(&mesh, bl, loops.loop_count, w->chain_points, w->chain_first, &why);
    free(bl);
    if (st == SW_ERR_NO_MEMORY)
        return sw_error_set(err, st, "%s", why.message);
    if (st != SW_OK) {
        w->report.bad_border++;
        return SW_OK;
    }
    uint32_t count = 0;
    sw_trim_patches_from_pack(b->pack, s, w->patches, b->max_patches, &count, NULL);
    double measured = sw_levels_measure(w->patches, count, w->positions, w->uvs, w->indices,
                                        t.index_count, b->opt.samples);
    double error = fmax(b->noise[s], measured - b->sew_offset[s]);
    w->report.worst_over_bound = fmax(w->report.worst_over_bound, error / bound);
    return keep(w, s, rank, (float)error, &t, &loops, err);
}

/* One rank's surfaces, shared out among the workers. */
typedef struct rank_run {
    builder *b;
    uint32_t rank;
} rank_run;

static int make_surface(void *arg, uint32_t worker, uint32_t s)
{
    const rank_run *run = arg;
    level_worker *w = &run->b->workers[worker];
    if (!run->b->alive[s] || make_level(w, s, run->rank, &w->err) == SW_OK)
        return 1;
    w->failed = s;
    return 0;
}

/* Every living surface's level of this rank: the front moved for each
 * surface's seams to their share of its bound first. The error is the
 * first failed surface's, whichever worker made it. */
static sw_status make_rank(builder *b, uint32_t rank, sw_error *err)
{
    uint32_t n = b->pack->seam.surface_count, failed = UINT32_MAX;
    for (uint32_t s = 0; s < n; s++)
        b->bounds[s] = b->alive[s] ? (float)(level_bound(b, s, rank) * SW_SEAM_SHARE) : 1e30f;
    sw_seam_update_result r;
    sw_status st = sw_seam_select_update(&b->sel, b->bounds, 0, &r, err);
    if (st != SW_OK)
        return st;
    rank_run run = { b, rank };
    sw_parts_take_items(b->opt.runner, b->worker_count, make_surface, &run, n);
    for (uint32_t i = 0; i < b->worker_count; i++)
        if (b->workers[i].failed < failed)
            failed = b->workers[i].failed, *err = b->workers[i].err;
    return failed == UINT32_MAX ? SW_OK : err->status;
}

static int by_surface_then_rank(const void *pa, const void *pb)
{
    const made_level *a = pa, *b = pb;
    if (a->surface != b->surface)
        return a->surface < b->surface ? -1 : 1;
    return a->rank < b->rank ? -1 : a->rank > b->rank;
}

/* A surface's made levels m[0 .. count), coarsest last, reduced to those
 * whose error rises: a level no worse than the ones before it takes their
 * place. Returns how many are left, at the front. */
static uint32_t rising(made_level *m, uint32_t count, sw_levels_report *report)
{
    uint32_t kept = 0;
    for (uint32_t i = 0; i < count; i++) {
        while (kept > 0 && m[i].error <= m[kept - 1].error) {
            kept--;
            report->not_finer++;
        }
        if (kept < SW_LEVELS_MAX)
            m[kept++] = m[i];
    }
    return kept;
}

/* What a worker counted, added to the build's report. */
static void add_counts(sw_levels_report *to, const sw_levels_report *r)
{
    to->refused += r->refused, to->too_large += r->too_large, to->bad_border += r->bad_border;
    to->vanished += r->vanished;
    to->worst_over_bound = fmax(to->worst_over_bound, r->worst_over_bound);
}

/* Every worker's made levels in one array, ordered by surface and rank
 * (no two alike), so that which worker made which does not show; NULL when
 * out of memory. */
static made_level *all_made(const builder *b, size_t *count)
{
    size_t n = 0;
    for (uint32_t i = 0; i < b->worker_count; i++)
        n += b->workers[i].made.count;
    made_level *m = malloc((n + 1) * sizeof *m);
    *count = 0;
    for (uint32_t i = 0; m && i < b->worker_count; i++) {
        const grow *made = &b->workers[i].made;
        if (made->count)   /* none made: data is NULL, which memcpy may not take */
            memcpy(m + *count, made->data, made->count * sizeof *m);
        *count += made->count;
    }
    if (m && *count > 1)
        qsort(m, *count, sizeof *m, by_surface_then_rank);
    return m;
}

/* Level l appended to out's arrays (view v), from its worker's. */
static void copy_level(const builder *b, const made_level *l, sw_levels_built *out, sw_levels *v)
{
    const level_worker *w = &b->workers[l->worker];
    out->levels[v->level_count++] = (sw_level){ l->surface, l->error, v->vertex_count,
                                                l->vertex_count, v->index_count, l->index_count,
                                                v->chain_count, l->made_bound };
    memcpy(out->vertices + v->vertex_count,
           (const sw_level_vertex *)w->vertices.data + l->first_vertex,
           l->vertex_count * sizeof *out->vertices);
    memcpy(out->uvs + 2 * (size_t)v->vertex_count,
           (const float *)w->vertex_uvs.data + 2 * (size_t)l->first_vertex,
           2 * sizeof(float) * l->vertex_count);
    memcpy(out->indices + v->index_count, (const uint16_t *)w->index_data.data + l->first_index,
           l->index_count * sizeof *out->indices);
    v->vertex_count += l->vertex_count, v->index_count += l->index_count;
    for (uint32_t c = 0; c < l->chain_count; c++) {
        sw_level_chain ch = ((const sw_level_chain *)w->chains.data)[l->first_chain + c];
        memcpy(out->chain_points + v->chain_point_count,
               (const sw_strip_point *)w->points_out.data + ch.first_point,
               ch.point_count * sizeof *out->chain_points);
        out->chains[v->chain_count++] = (sw_level_chain){ v->chain_point_count, ch.point_count };
        v->chain_point_count += ch.point_count;
    }
}

/* The levels kept, in surface order, copied into out's own arrays. */
static sw_status assemble(builder *b, sw_levels_built *out, sw_error *err)
{
    size_t made = 0;
    made_level *m = all_made(b, &made);
    uint32_t n = b->pack->seam.surface_count, total = 0, at = 0;
    size_t verts = 0, idx = 0, chains = 0, points = 0;
    uint32_t *first = calloc((size_t)n + 2, sizeof *first);
    out->surface_levels = first;
    if (!first || !m) {
        free(m);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    }
    for (uint32_t s = 0; s < n; s++) {
        uint32_t end = at;
        while (end < made && m[end].surface == s)
            end++;
        uint32_t kept = rising(m + at, end - at, b->report);
        memmove(m + total, m + at, kept * sizeof *m);
        for (uint32_t i = total; i < total + kept; i++) {
            verts += m[i].vertex_count, idx += m[i].index_count, chains += m[i].chain_count;
            b->report->triangles[i - total] += m[i].index_count / 3;
            const sw_level_chain *of = b->workers[m[i].worker].chains.data;
            for (uint32_t c = 0; c < m[i].chain_count; c++)
                points += of[m[i].first_chain + c].point_count;
        }
        b->report->with_levels += kept > 0;
        total += kept, at = end;
        first[s + 1] = total;
    }
    out->levels = malloc(((size_t)total + 1) * sizeof *out->levels);
    out->vertices = malloc((verts + 1) * sizeof *out->vertices);
    out->uvs = malloc((verts + 1) * 2 * sizeof *out->uvs);
    out->indices = malloc((idx + 1) * sizeof *out->indices);
    out->chains = malloc((chains + 1) * sizeof *out->chains);
    out->chain_points = malloc((points + 1) * sizeof *out->chain_points);
    sw_status st = SW_OK;
    if (!out->levels || !out->vertices || !out->uvs || !out->indices || !out->chains ||
        !out->chain_points)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    sw_levels *v = &out->view;
    *v = (sw_levels){ .levels = out->levels, .surface_levels = first, .vertices = out->vertices,
                      .indices = out->indices, .chains = out->chains,
                      .chain_points = out->chain_points, .surface_count = n };
    for (uint32_t i = 0; st == SW_OK && i < total; i++)
        copy_level(b, &m[i], out, v);
    free(m);
    b->report->levels = total;
    return st;
}

sw_status sw_levels_build(const sw_pack *pack, const sw_levels_options *opt,
                          sw_levels_built *out, sw_levels_report *report, sw_error *err)
{
    memset(out, 0, sizeof *out);
    memset(report, 0, sizeof *report);
    if (!pack->seam_header || !pack->surfaces)
        return sw_error_set(err, SW_ERR_ARG, "levels: the pack has no Seam Graph");
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    builder b = { .pack = pack, .report = report };
    b.opt = opt ? *opt : (sw_levels_options){ 0 };
    b.opt.finest = b.opt.finest > 0 ? b.opt.finest : 4e-3;
    b.opt.step = b.opt.step > 1 ? b.opt.step : 4.0;
    b.opt.count = b.opt.count ? (b.opt.count < SW_LEVELS_MAX ? b.opt.count : SW_LEVELS_MAX) : 4;
    b.opt.samples = b.opt.samples ? b.opt.samples : 8;
    report->surfaces = pack->seam.surface_count;
    sw_status st = builder_open(&b, pack, err);
    if (st == SW_OK)
        measure_surfaces(&b);
    for (uint32_t rank = 0; st == SW_OK && rank < b.opt.count; rank++)
        st = make_rank(&b, rank, err);
    for (uint32_t i = 0; st == SW_OK && i < b.worker_count; i++)
        add_counts(report, &b.workers[i].report);
    if (st == SW_OK)
        st = assemble(&b, out, err);
    builder_close(&b);
    if (st != SW_OK)
        sw_levels_built_free(out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    report->seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    return st;
}

void sw_levels_built_free(sw_levels_built *b)
{
    free(b->levels);
    free(b->surface_levels);
    free(b->vertices);
    free(b->uvs);
    free(b->indices);
    free(b->chains);
    free(b->chain_points);
    memset(b, 0, sizeof *b);
}
