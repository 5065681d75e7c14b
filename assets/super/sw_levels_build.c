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

/* A level as made, before the levels are ordered by surface. */
typedef struct made_level {
    uint32_t surface, rank;
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

typedef struct builder {
    const sw_pack *pack;
    sw_levels_options opt;
    sw_levels_report *report;
    sw_seam_select sel;
    sw_seam_select finest;            /* sel with every original shown: the sewn polylines */
    uint32_t *finest_shown;
    void *select_block, *scratch_block;
    sw_arena scratch;
    uint32_t max_points, max_patches, max_loops;
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
    double *size, *sew_offset;        /* per surface */
    double *noise;                    /* per surface: below this, float positions differ by
                                         rounding alone (levels no finer than that are equal) */
    uint8_t *alive;                   /* per surface: its outer loop has not vanished */
    float *bounds;
    grow made, vertices, vertex_uvs, index_data, chains, points_out;
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

static sw_status builder_open(builder *b, const sw_pack *pack, sw_error *err)
{
    const sw_seam_graph *g = &pack->seam;
    int degree = 1, failed = 0;
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
    size_t scratch = sw_trim_tess_scratch_bytes(b->max_patches, b->max_points, degree, &opt);
    size_t select = sw_seam_select_arena_bytes(g), mp = b->max_points, ml = b->max_loops;
    size_t v = SW_WALK_VERTICES, n = g->surface_count;
    b->select_block = take(select, 1, &failed);
    b->scratch_block = take(scratch, 1, &failed);
    b->seam_points = take(mp, sizeof *b->seam_points, &failed);
    b->slots = take(mp, sizeof *b->slots, &failed);
    b->ids = take(mp, sizeof *b->ids, &failed);
    b->loop_uvs = take(2 * mp, sizeof *b->loop_uvs, &failed);
    b->loop_at = take(ml, sizeof *b->loop_at, &failed);
    b->loop_len = take(ml, sizeof *b->loop_len, &failed);
    b->loop_vanished = take(ml, 1, &failed);
    b->points = take(mp, sizeof *b->points, &failed);
    b->loop_first = take(ml + 1, sizeof *b->loop_first, &failed);
    b->tess_loop = take(ml, sizeof *b->tess_loop, &failed);
    b->patches = take(b->max_patches, sizeof *b->patches, &failed);
    b->positions = take(3 * v, sizeof(float), &failed);
    b->normals = take(3 * v, sizeof(float), &failed);
    b->uvs = take(2 * v, sizeof(float), &failed);
    b->out_ids = take(v, sizeof *b->out_ids, &failed);
    b->indices = take(SW_WALK_INDICES, sizeof *b->indices, &failed);
    b->chain_points = take(v, sizeof *b->chain_points, &failed);
    b->chain_first = take(ml + 1, sizeof *b->chain_first, &failed);
    b->size = take(n, sizeof *b->size, &failed);
    b->sew_offset = take(n, sizeof *b->sew_offset, &failed);
    b->noise = take(n, sizeof *b->noise, &failed);
    b->alive = take(n, 1, &failed);
    b->finest_shown = take(g->original_count, sizeof *b->finest_shown, &failed);
    b->bounds = take(n, sizeof *b->bounds, &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory for %u surfaces",
                            (unsigned)n);
    sw_arena_init(&b->scratch, b->scratch_block, scratch);
    sw_arena select_arena;
    sw_arena_init(&select_arena, b->select_block, select);
    b->made.size = sizeof(made_level), b->vertices.size = sizeof(sw_level_vertex);
    b->vertex_uvs.size = 2 * sizeof(float);
    b->index_data.size = sizeof(uint16_t), b->chains.size = sizeof(sw_level_chain);
    b->points_out.size = sizeof(sw_strip_point);
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
    void *blocks[] = { b->select_block, b->scratch_block, b->seam_points, b->slots, b->ids,
                       b->loop_uvs, b->loop_at, b->loop_len, b->loop_vanished, b->points,
                       b->loop_first, b->tess_loop, b->patches, b->positions, b->normals,
                       b->uvs, b->out_ids, b->indices, b->chain_points, b->chain_first,
                       b->size, b->sew_offset, b->noise, b->alive, b->finest_shown, b->bounds,
                       b->made.data, b->vertices.data, b->vertex_uvs.data, b->index_data.data,
                       b->chains.data, b->points_out.data };
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

/* Each surface's size and sewing offset; surfaces with no size or no
 * loops get no level. */
static void measure_surfaces(builder *b)
{
    const sw_seam_graph *g = &b->pack->seam;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t count = 0;
        b->size[s] = surface_size(b->pack, s);
        b->noise[s] = 8 * FLT_EPSILON * surface_magnitude(b->pack, s);
        b->sew_offset[s] = 0;
        b->alive[s] = b->size[s] > 0 && g->surface_loops[s + 1] > g->surface_loops[s] &&
                      sw_trim_patches_from_pack(b->pack, s, b->patches, b->max_patches, &count,
                                                NULL) == SW_OK;
        for (uint32_t l = g->surface_loops[s]; b->alive[s] && l < g->surface_loops[s + 1]; l++)
            b->sew_offset[s] = fmax(b->sew_offset[s],
                                    sw_seam_sewing_offset(g, &g->loops[l], b->patches, count));
    }
}

/* Surface s's loops at the front, each with its slots; 0 when an outer
 * loop vanished. Then the tessellator's loops: outer ones first, then the
 * holes that have not vanished (as the walk gives them, sw_seam_surface.h),
 * or the outer ones alone (with_holes 0). */
static int gather(builder *b, const sw_seam_select *front, uint32_t s, float pin)
{
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t at = 0, first = g->surface_loops[s];
    for (uint32_t l = first; l < g->surface_loops[s + 1]; l++) {
        uint32_t count = 0;
        int vanished = 0;
        /* Cannot fail: l is in range and the buffers hold the surface's slots. */
        sw_seam_select_loop_slots(front, l, pin, b->seam_points + at, b->slots + at,
                                  b->max_points - at, &count, &vanished, NULL);
        if (vanished && (g->loops[l].flags & SW_SEAM_LOOP_OUTER))
            return 0;
        /* A hole the front has closed is kept as sewn: the walk shows it
         * wherever its neighbours are drawn finer, and a level without it
         * would cover it there. */
        if (vanished)
            sw_seam_select_loop_slots(&b->finest, l, pin, b->seam_points + at, b->slots + at,
                                      b->max_points - at, &count, &vanished, NULL);
        b->loop_at[l - first] = at, b->loop_len[l - first] = count;
        b->loop_vanished[l - first] = (uint8_t)vanished;
        for (uint32_t i = at; i < at + count; i++) {
            b->ids[i] = b->seam_points[i].vertex;
            memcpy(b->loop_uvs + 2 * i, b->seam_points[i].uv, 2 * sizeof(float));
        }
        at += count;
    }
    return 1;
}

static sw_trim_loops tess_loops(builder *b, uint32_t s, int with_holes)
{
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t first = g->surface_loops[s], k = 0, total = 0;
    b->loop_first[0] = 0;
    for (int holes = 0; holes < 1 + with_holes; holes++)
        for (uint32_t l = first; l < g->surface_loops[s + 1]; l++) {
            uint32_t i = l - first;
            if ((!(g->loops[l].flags & SW_SEAM_LOOP_OUTER)) != holes || b->loop_vanished[i])
                continue;
            for (uint32_t j = 0; j < b->loop_len[i]; j++) {
                const sw_seam_point *sp = &b->seam_points[b->loop_at[i] + j];
                sw_trim_point *tp = &b->points[total + j];
                memcpy(tp->uv, sp->uv, sizeof tp->uv);
                memcpy(tp->p, g->vertices[sp->vertex].p, sizeof tp->p);
                tp->id = sp->vertex;
            }
            total += b->loop_len[i];
            b->tess_loop[k] = i;
            b->loop_first[++k] = total;
        }
    return (sw_trim_loops){ b->points, b->loop_first, k };
}

/* Surface s tessellated at bound inside its gathered loops; with
 * drop_holes, SW_ERR_FORMAT retried without its holes. */
static sw_status tessellate(builder *b, uint32_t s, double bound, int drop_holes,
                            sw_trim_loops *loops, sw_trim_tess_result *t)
{
    uint32_t count = 0;
    sw_trim_patches_from_pack(b->pack, s, b->patches, b->max_patches, &count, NULL);
    sw_trim_tess_buffers out = { b->positions, b->normals, b->uvs, b->out_ids, b->indices,
                                 SW_WALK_VERTICES, SW_WALK_INDICES, 0 };
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    *loops = tess_loops(b, s, 1);
    sw_status st = sw_trim_tess(b->patches, count, loops, bound, &opt, &b->scratch, &out, t,
                                NULL);
    if (st == SW_ERR_FORMAT && drop_holes) {
        sw_trim_loops outer = tess_loops(b, s, 0);
        if (outer.loop_count < loops->loop_count) {
            *loops = outer;
            st = sw_trim_tess(b->patches, count, loops, bound, &opt, &b->scratch, &out, t, NULL);
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
static sw_status keep(builder *b, uint32_t s, uint32_t rank, float error,
                      const sw_trim_tess_result *t, const sw_trim_loops *loops, sw_error *err)
{
    const sw_seam_graph *g = &b->pack->seam;
    uint32_t loop_count = g->surface_loops[s + 1] - g->surface_loops[s];
    made_level m = { s, rank, error, (float)level_bound(b, s, rank), (uint32_t)b->vertices.count,
                     t->vertex_count,
                     (uint32_t)b->index_data.count, t->index_count, (uint32_t)b->chains.count,
                     loop_count };
    uint32_t chain_total = b->chain_first[loops->loop_count];
    made_level *mp = grow_by(&b->made, 1);
    sw_level_vertex *v = grow_by(&b->vertices, t->vertex_count);
    float *uv = grow_by(&b->vertex_uvs, t->vertex_count);
    uint16_t *idx = grow_by(&b->index_data, t->index_count);
    sw_level_chain *ch = grow_by(&b->chains, loop_count);
    size_t points_at = b->points_out.count;
    sw_strip_point *pts = grow_by(&b->points_out, chain_total);
    if (!mp || !v || !uv || !idx || !ch || !pts)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    *mp = m;
    for (uint32_t i = 0; i < t->vertex_count; i++) {
        memcpy(v[i].p, b->positions + 3 * i, sizeof v[i].p);
        for (int a = 0; a < 3; a++)
            v[i].normal[a] = snorm8(b->normals[3 * i + a]);
        v[i].normal[3] = 0;
    }
    memcpy(uv, b->uvs, 2 * sizeof(float) * t->vertex_count);
    memcpy(idx, b->indices, t->index_count * sizeof *idx);
    memcpy(pts, b->chain_points, chain_total * sizeof *pts);
    memset(ch, 0, loop_count * sizeof *ch);
    for (uint32_t k = 0; k < loops->loop_count; k++)
        ch[b->tess_loop[k]] = (sw_level_chain){ (uint32_t)points_at + b->chain_first[k],
                                                b->chain_first[k + 1] - b->chain_first[k] };
    return SW_OK;
}


/* Surface s's level of this rank at the current front, kept when it
 * tessellates, its border reads back and its error is measured. */
static sw_status make_level(builder *b, uint32_t s, uint32_t rank, sw_error *err)
{
    const sw_seam_graph *g = &b->pack->seam;
    double bound = level_bound(b, s, rank);
    float pin = (float)(bound * SW_SEAM_SHARE);
    if (!gather(b, &b->sel, s, pin)) {
        b->alive[s] = 0;
        b->report->vanished++;
        return SW_OK;
    }
    sw_trim_loops loops;
    sw_trim_tess_result t;
    sw_status st = tessellate(b, s, bound, 0, &loops, &t);
    /* A hole whose coarse polyline crosses another loop: the loops as sewn
     * (which do not cross) rather than a level without the hole, which
     * would cover it wherever the walk shows it. */
    if (st == SW_ERR_FORMAT) {
        gather(b, &b->finest, s, pin);
        st = tessellate(b, s, bound, 1, &loops, &t);
    }
    b->report->too_large += st == SW_ERR_RANGE;
    b->report->refused += st != SW_OK && st != SW_ERR_RANGE;
    if (st != SW_OK)
        return st == SW_ERR_NO_MEMORY ? sw_error_set(err, st, "levels: tessellator scratch")
                                      : SW_OK;
    uint32_t first = g->surface_loops[s];
    sw_border_loop *bl = malloc(((size_t)loops.loop_count + 1) * sizeof *bl);
    if (!bl)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    for (uint32_t k = 0; k < loops.loop_count; k++) {
        uint32_t i = b->tess_loop[k];
        bl[k] = (sw_border_loop){ b->ids + b->loop_at[i], b->loop_uvs + 2 * b->loop_at[i],
                                  b->slots + b->loop_at[i], b->loop_len[i],
                                  g->loops[first + i].slot_count };
    }
    const sw_border_mesh mesh = { b->out_ids, b->uvs, b->indices, t.vertex_count,
                                  t.index_count };
    sw_error why = { 0 };
    st = sw_levels_border(&mesh, bl, loops.loop_count, b->chain_points, b->chain_first, &why);
    free(bl);
    if (st == SW_ERR_NO_MEMORY)
        return sw_error_set(err, st, "%s", why.message);
    if (st != SW_OK) {
        b->report->bad_border++;
        return SW_OK;
    }
    uint32_t count = 0;
    sw_trim_patches_from_pack(b->pack, s, b->patches, b->max_patches, &count, NULL);
    double measured = sw_levels_measure(b->patches, count, b->positions, b->uvs, b->indices,
                                        t.index_count, b->opt.samples);
    double error = fmax(b->noise[s], measured - b->sew_offset[s]);
    b->report->worst_over_bound = fmax(b->report->worst_over_bound, error / bound);
    return keep(b, s, rank, (float)error, &t, &loops, err);
}

/* Every living surface's level of this rank: the front moved for each
 * surface's seams to their share of its bound first. */
static sw_status make_rank(builder *b, uint32_t rank, sw_error *err)
{
    uint32_t n = b->pack->seam.surface_count;
    for (uint32_t s = 0; s < n; s++)
        b->bounds[s] = b->alive[s] ? (float)(level_bound(b, s, rank) * SW_SEAM_SHARE) : 1e30f;
    sw_seam_update_result r;
    sw_status st = sw_seam_select_update(&b->sel, b->bounds, 0, &r, err);
    for (uint32_t s = 0; st == SW_OK && s < n; s++)
        if (b->alive[s])
            st = make_level(b, s, rank, err);
    return st;
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

/* The levels kept, in surface order, copied into out's own arrays. */
static sw_status assemble(builder *b, sw_levels_built *out, sw_error *err)
{
    made_level *m = b->made.data;
    uint32_t n = b->pack->seam.surface_count, total = 0, at = 0;
    if (b->made.count > 1)   /* none made: m is NULL, which qsort may not take */
        qsort(m, b->made.count, sizeof *m, by_surface_then_rank);
    size_t verts = 0, idx = 0, chains = 0, points = 0;
    uint32_t *first = calloc((size_t)n + 2, sizeof *first);
    if (!first)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    for (uint32_t s = 0; s < n; s++) {
        uint32_t end = at;
        while (end < b->made.count && m[end].surface == s)
            end++;
        uint32_t kept = rising(m + at, end - at, b->report);
        memmove(m + total, m + at, kept * sizeof *m);
        for (uint32_t i = total; i < total + kept; i++) {
            verts += m[i].vertex_count, idx += m[i].index_count, chains += m[i].chain_count;
            b->report->triangles[i - total] += m[i].index_count / 3;
        }
        b->report->with_levels += kept > 0;
        total += kept, at = end;
        first[s + 1] = total;
    }
    const sw_level_chain *all_chains = b->chains.data;
    for (uint32_t i = 0; i < total; i++)
        for (uint32_t c = 0; c < m[i].chain_count; c++)
            points += all_chains[m[i].first_chain + c].point_count;
    out->levels = malloc(((size_t)total + 1) * sizeof *out->levels);
    out->vertices = malloc((verts + 1) * sizeof *out->vertices);
    out->uvs = malloc((verts + 1) * 2 * sizeof *out->uvs);
    out->indices = malloc((idx + 1) * sizeof *out->indices);
    out->chains = malloc((chains + 1) * sizeof *out->chains);
    out->chain_points = malloc((points + 1) * sizeof *out->chain_points);
    out->surface_levels = first;
    if (!out->levels || !out->vertices || !out->uvs || !out->indices || !out->chains ||
        !out->chain_points)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "levels: out of memory");
    sw_levels *v = &out->view;
    *v = (sw_levels){ .levels = out->levels, .surface_levels = first, .vertices = out->vertices,
                      .indices = out->indices, .chains = out->chains,
                      .chain_points = out->chain_points, .surface_count = n };
    for (uint32_t i = 0; i < total; i++) {
        const made_level *l = &m[i];
        out->levels[i] = (sw_level){ l->surface, l->error, v->vertex_count, l->vertex_count,
                                     v->index_count, l->index_count, v->chain_count,
                                     l->made_bound };
        memcpy(out->vertices + v->vertex_count,
               (const sw_level_vertex *)b->vertices.data + l->first_vertex,
               l->vertex_count * sizeof *out->vertices);
        memcpy(out->uvs + 2 * (size_t)v->vertex_count,
               (const float *)b->vertex_uvs.data + 2 * (size_t)l->first_vertex,
               2 * sizeof(float) * l->vertex_count);
        memcpy(out->indices + v->index_count, (const uint16_t *)b->index_data.data + l->first_index,
               l->index_count * sizeof *out->indices);
        v->vertex_count += l->vertex_count, v->index_count += l->index_count;
        for (uint32_t c = 0; c < l->chain_count; c++) {
            sw_level_chain ch = all_chains[l->first_chain + c];
            memcpy(out->chain_points + v->chain_point_count,
                   (const sw_strip_point *)b->points_out.data + ch.first_point,
                   ch.point_count * sizeof *out->chain_points);
            out->chains[v->chain_count++] = (sw_level_chain){ v->chain_point_count,
                                                              ch.point_count };
            v->chain_point_count += ch.point_count;
        }
    }
    v->level_count = total;
    b->report->levels = total;
    return SW_OK;
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
