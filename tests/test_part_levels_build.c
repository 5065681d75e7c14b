/* SPDX-License-Identifier: MIT */
/* The part levels the pack tool makes (assets/super/sw_part_levels_build.h),
 * checked against what they stand for, not against how they were made:
 * - points at random (u, v) on every untrimmed surface of the part, on the
 *   exact surface (sw_surface_at), lie within the level's stored error of
 *   its triangles (the builder measured against the mesh it simplified
 *   from, on a grid; this measures from the surfaces themselves);
 * - random points on the level's triangles lie within its error (and a
 *   quarter, for the builder's sampling) of the mesh it was simplified
 *   from (the part's finest static levels joined at one front,
 *   sw_part_source.h) plus that mesh's own error;
 * - over a piece's levels at one front the triangles fall and the errors
 *   rise, and each level has fewer triangles than the mesh it was
 *   simplified from (the first level of a cut part's piece at a front is
 *   that mesh itself);
 * - the area of each level shaded wrong, its normals more than 40 degrees
 *   from every normal of the finest levels within its error (random points,
 *   where the builder took a grid at 30 degrees on its own welded mesh), is
 *   within its stored shading side.
 * - the pieces of a cut part meet: at each front, the pieces' levels chosen
 *   at random leave open exactly the edges the pieces' sources leave open
 *   together (compared as position pairs, bit for bit), so no border moved.
 * - a piece's finest level (of a part not cut) is within a quarter of the
 *   piece's size, the coarsest bound the builder aims at by default: a
 *   finest level past it is one no view can use (a flat plate's first try
 *   cut a corner off, half its size), and the piece is drawn surface by
 *   surface however far away it is.
 * Trimmed surfaces are left out of the first check (a random (u, v) may
 * fall in a hole); the second covers them. Takes pack files (CTest passes
 * the built teaset, thin sheets and a courtyard cut into pieces) and fails on one
 * without part levels; with --cut, also on one without a cut part. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_mesh_distance.h"
#include "sw_part_pieces.h"
#include "sw_part_source.h"
#include "sw_pack.h"
#include "sw_surface_at.h"
#include "sw_test.h"
#include "pack_file.h"
#include "sw_trim_tess.h"

typedef struct mesh {
    float *pos;
    uint32_t *idx, nv, ni;
    float *nrm;    /* 3 per vertex: the source's normals */
} mesh;

static mesh level_mesh(const sw_part_levels *pl, const sw_part_level *l)
{
    mesh m = { malloc(3 * sizeof(float) * l->vertex_count),
               malloc(sizeof(uint32_t) * l->index_count), l->vertex_count, l->index_count, NULL };
    for (uint32_t i = 0; i < l->vertex_count; i++)
        memcpy(m.pos + 3 * i, pl->vertices[l->first_vertex + i].p, 3 * sizeof(float));
    for (uint32_t i = 0; i < l->index_count; i++)
        m.idx[i] = pl->indices[l->first_index + i];
    return m;
}

/* The surfaces a level stands for: piece g's, or with whole a part number
 * the whole of that part's (a cut part's levels of itself whole). */
static int stands_for(const sw_pack *pack, uint32_t s, uint32_t g, uint32_t whole)
{
    return whole != UINT32_MAX ? pack->surfaces[s].part == whole
                               : pack->part_levels.piece_of[s] == g;
}

/* The source of what a level stands for (sw_part_source.h: the surfaces'
 * static levels joined at one front, the mesh its levels were simplified
 * from) as one mesh; *error the largest of its surfaces' errors;
 * *finest_tris its triangles. */
static mesh finest_mesh(const sw_part_source *src, const sw_pack *pack, uint32_t g,
                        uint32_t whole, double *error, uint32_t *finest_tris)
{
    mesh m = { NULL, NULL, 0, 0, NULL };
    *error = 0;
    for (uint32_t s = 0; s < src->surface_count; s++) {
        if (!stands_for(pack, s, g, whole) || isnan(src->error[s]))
            continue;
        *error = fmax(*error, src->error[s]);
        uint32_t v0 = src->surface_vertices[s], nv = src->surface_vertices[s + 1] - v0;
        uint32_t i0 = src->surface_indices[s], ni = src->surface_indices[s + 1] - i0;
        m.pos = realloc(m.pos, 3 * sizeof(float) * (m.nv + nv));
        m.idx = realloc(m.idx, sizeof(uint32_t) * (m.ni + ni));
        m.nrm = realloc(m.nrm, 3 * sizeof(float) * (m.nv + nv));
        memcpy(m.pos + 3 * (size_t)m.nv, src->positions + 3 * (size_t)v0, 3 * sizeof(float) * nv);
        memcpy(m.nrm + 3 * (size_t)m.nv, src->normals + 3 * (size_t)v0, 3 * sizeof(float) * nv);
        for (uint32_t i = 0; i < ni; i++)
            m.idx[m.ni + i] = src->indices[i0 + i] - v0 + m.nv;
        m.nv += nv, m.ni += ni;
    }
    *finest_tris = m.ni / 3;
    return m;
}

/* The largest distance from random points on the untrimmed surfaces a
 * level stands for to grid's mesh. */
static double surface_to_level(const sw_pack *pack, uint32_t g, uint32_t whole,
                               const sw_mesh_grid *grid)
{
    double worst = 0;
    sw_trim_patch patches[4096];
    for (uint32_t s = 0; s < pack->surface_count; s++) {
        const sw_pack_surface *sf = &pack->surfaces[s];
        uint32_t count = 0;
        if (!stands_for(pack, s, g, whole) || sf->loop_count > 0 ||
            sw_trim_patches_from_pack(pack, s, patches, 4096, &count, NULL) != SW_OK)
            continue;
        for (int k = 0; k < 200; k++) {
            double u = sf->domain[0] + sw_test_random() * (sf->domain[1] - sf->domain[0]);
            double v = sf->domain[2] + sw_test_random() * (sf->domain[3] - sf->domain[2]);
            sw_vec3 x = sw_surface_at(patches, count, u, v);
            const double q[3] = { x.x, x.y, x.z };
            worst = fmax(worst, sw_mesh_grid_distance(grid, q));
        }
    }
    return worst;
}

/* The largest distance from random points on the level's triangles to
 * grid's mesh. */
static double level_to_mesh(const mesh *level, const sw_mesh_grid *grid)
{
    double worst = 0;
    for (uint32_t t = 0; t + 2 < level->ni; t += 3)
        for (int k = 0; k < 8; k++) {
            double a = sw_test_random(), b = sw_test_random();
            if (a + b > 1)
                a = 1 - a, b = 1 - b;
            double w[3] = { a, b, 1 - a - b }, q[3] = { 0, 0, 0 };
            for (int j = 0; j < 3; j++)
                for (int c = 0; c < 3; c++)
                    q[c] += w[j] * level->pos[3 * level->idx[t + j] + c];
            worst = fmax(worst, sw_mesh_grid_distance(grid, q));
        }
    return worst;
}

/* The unit normal weights w blend from snorm8 corner normals q. */
static void blend(const int8_t *q[3], const double w[3], double n[3])
{
    for (int k = 0; k < 3; k++)
        n[k] = w[0] * q[0][k] + w[1] * q[1][k] + w[2] * q[2][k];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3 && len > 0; k++)
        n[k] /= len;
}

typedef struct best_cos {
    const mesh *finest;
    double normal[3], best;
} best_cos;

static int visit(void *ctx, const sw_mesh_point *at)
{
    best_cos *b = ctx;
    double n[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            n[c] += at->weights[k] * b->finest->nrm[3 * b->finest->idx[3 * at->triangle + k] + c];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0)
        b->best = fmax(b->best, fabs(n[0] * b->normal[0] + n[1] * b->normal[1] +
                                     n[2] * b->normal[2]) / len);
    return 0;
}

/* The side of a square as large as the level's area whose shading normal
 * lies more than 40 degrees from every normal of the finest levels within
 * the level's error, from 8 random points inside each triangle. */
static double shaded_wrong_side(const sw_part_levels *pl, const sw_part_level *l,
                                const mesh *finest, const sw_mesh_grid *fgrid)
{
    double area = 0;
    for (uint32_t t = 0; t + 2 < l->index_count; t += 3) {
        const sw_level_vertex *v[3];
        const int8_t *q[3];
        for (int j = 0; j < 3; j++)
            v[j] = &pl->vertices[l->first_vertex + pl->indices[l->first_index + t + j]],
            q[j] = v[j]->normal;
        int off = 0;
        for (int k = 0; k < 8; k++) {
            double a = sw_test_random(), b = sw_test_random();
            if (a + b > 1)
                a = 1 - a, b = 1 - b;
            double w[3] = { a, b, 1 - a - b }, x[3] = { 0, 0, 0 };
            for (int j = 0; j < 3; j++)
                for (int c = 0; c < 3; c++)
                    x[c] += w[j] * v[j]->p[c];
            best_cos bc = { finest, { 0, 0, 0 }, 0 };
            blend(q, w, bc.normal);
            sw_mesh_point at;
            double reach = fmax(sw_mesh_grid_nearest(fgrid, x, &at), l->error);
            visit(&bc, &at);   /* the nearest itself: at reach it may round out of it */
            sw_mesh_grid_within(fgrid, x, reach, visit, &bc);
            off += bc.best < cos(40.0 / 180.0 * 3.14159265358979);
        }
        double e1[3], e2[3];
        for (int c = 0; c < 3; c++)
            e1[c] = (double)v[1]->p[c] - v[0]->p[c], e2[c] = (double)v[2]->p[c] - v[0]->p[c];
        double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0] };
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * off / 8;
    }
    return sqrt(area);
}

static double mesh_diagonal(const mesh *m)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t v = 0; v < m->nv; v++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], m->pos[3 * v + k]), hi[k] = fmax(hi[k], m->pos[3 * v + k]);
    double d = 0;
    for (int k = 0; m->nv > 0 && k < 3; k++)
        d += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(d);
}

/* Piece g's levels at front f, against src (the source at that front);
 * for f SW_PART_LEVEL_WHOLE, its part's levels of itself whole. */
static void check_piece(const sw_pack *pack, const sw_part_source *src, uint32_t g, uint32_t f,
                        int cut)
{
    const sw_part_levels *pl = &pack->part_levels;
    double finest_error = 0;
    uint32_t finest_tris = 0, whole = UINT32_MAX;
    for (uint32_t s = 0; f == SW_PART_LEVEL_WHOLE && s < pack->surface_count; s++)
        whole = pl->piece_of[s] == g ? pack->surfaces[s].part : whole;
    mesh finest = finest_mesh(src, pack, g, whole, &finest_error, &finest_tris);
    sw_mesh_view fv = { finest.pos, finest.idx, finest.nv, finest.ni };
    sw_mesh_grid *fgrid = sw_mesh_grid_make(&fv);
    SW_CHECK(fgrid != NULL);
    uint32_t last_tris = finest_tris + (cut ? 1 : 0);   /* a cut piece's first is its source */
    int first = !cut && f == 0;
    double size = mesh_diagonal(&finest);
    for (uint32_t i = pl->piece_levels[g]; fgrid && i < pl->piece_levels[g + 1]; i++) {
        const sw_part_level *l = &pl->levels[i];
        if (l->front != f)
            continue;
        SW_CHECK_MSG(!first || l->error <= 0.25 * size, "piece %u: its finest level's error %g, "
                     "past a quarter of its size %g", g, (double)l->error, size);
        first = 0;
        mesh m = level_mesh(pl, l);
        sw_mesh_view lv = { m.pos, m.idx, m.nv, m.ni };
        sw_mesh_grid *grid = sw_mesh_grid_make(&lv);
        /* The builder samples each triangle on a grid at twice the level's
         * target apart; a peak between its points (the middle of a hole a
         * coarse level covers over) can be missed by up to a quarter. */
        double slack = 1.25 * l->error + 1e-6;
        double from_surface = surface_to_level(pack, g, whole, grid);
        double from_level = level_to_mesh(&m, fgrid);
        SW_CHECK_MSG(from_surface <= slack, "piece %u front %u level %u: a surface point %g from "
                     "it, error %g", g, f, i, from_surface, (double)l->error);
        SW_CHECK_MSG(from_level <= slack + finest_error, "piece %u front %u level %u: a point of "
                     "it %g from its source (error %g), its error %g", g, f, i, from_level,
                     finest_error, (double)l->error);
        SW_CHECK_MSG(l->index_count / 3 < last_tris, "piece %u front %u level %u: %u triangles, "
                     "not fewer than %u", g, f, i, l->index_count / 3, last_tris);
        last_tris = l->index_count / 3;
        double side = shaded_wrong_side(pl, l, &finest, fgrid);
        SW_CHECK_MSG(side <= 2 * l->shading_side + 0.25 * l->error, "piece %u front %u level %u: "
                     "%g a side shaded wrong, %g stored (error %g)", g, f, i, side,
                     (double)l->shading_side, (double)l->error);
        sw_mesh_grid_free(grid);
        free(m.pos), free(m.idx);
    }
    sw_mesh_grid_free(fgrid);
    free(finest.pos), free(finest.idx), free(finest.nrm);
}

/* An edge by its ends' positions, bit for bit, the smaller end first. */
typedef struct edge_key {
    float a[3], b[3];
} edge_key;

static int edge_cmp(const void *x, const void *y)
{
    return memcmp(x, y, sizeof(edge_key));
}

static void add_edges(edge_key **e, size_t *n, const sw_part_levels *pl, const sw_part_level *l)
{
    *e = realloc(*e, (*n + l->index_count) * sizeof **e);
    for (uint32_t t = 0; t < l->index_count; t += 3)
        for (int k = 0; k < 3; k++) {
            const float *p = pl->vertices[l->first_vertex +
                                          pl->indices[l->first_index + t + k]].p;
            const float *q = pl->vertices[l->first_vertex +
                                          pl->indices[l->first_index + t + (k + 1) % 3]].p;
            edge_key k2;
            int swap = memcmp(p, q, 3 * sizeof(float)) > 0;
            memcpy(k2.a, swap ? q : p, sizeof k2.a), memcpy(k2.b, swap ? p : q, sizeof k2.b);
            (*e)[(*n)++] = k2;
        }
}

/* The edges used once in e[0 .. n), sorted, moved to its front; their count. */
static size_t open_edges(edge_key *e, size_t n)
{
    qsort(e, n, sizeof *e, edge_cmp);
    size_t out = 0;
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i; j < n && edge_cmp(&e[i], &e[j]) == 0; j++)
            ;
        if (j - i == 1)
            e[out++] = e[i];
    }
    return out;
}

/* Cut part p's pieces [a, b) at front f: their first levels (the sources)
 * and, five times, a level of each at random leave the same edges open. */
static void check_borders(const sw_pack *pack, uint32_t a, uint32_t b, uint32_t f)
{
    const sw_part_levels *pl = &pack->part_levels;
    edge_key *ref = NULL;
    size_t nref = 0;
    for (uint32_t g = a; g < b; g++)
        for (uint32_t i = pl->piece_levels[g]; i < pl->piece_levels[g + 1]; i++)
            if (pl->levels[i].front == f) {
                add_edges(&ref, &nref, pl, &pl->levels[i]);
                break;
            }
    nref = open_edges(ref, nref);
    for (int round = 0; round < 5; round++) {
        edge_key *e = NULL;
        size_t n = 0;
        for (uint32_t g = a; g < b; g++) {
            uint32_t at[SW_PART_LEVELS_MAX], count = 0;
            for (uint32_t i = pl->piece_levels[g]; i < pl->piece_levels[g + 1]; i++)
                if (pl->levels[i].front == f && count < SW_PART_LEVELS_MAX)
                    at[count++] = i;
            if (count)
                add_edges(&e, &n, pl, &pl->levels[at[(uint32_t)(sw_test_random() * count) % count]]);
        }
        n = open_edges(e, n);
        SW_CHECK_MSG(n == nref && memcmp(e, ref, n * sizeof *e) == 0, "front %u round %d: %zu "
                     "open edges with levels at random, %zu with the sources", f, round, n, nref);
        free(e);
    }
    free(ref);
}

/* Part by part (a run of surfaces [s, *e)): its pieces [*first, *end). */
static void next_part(const sw_pack *pack, uint32_t s, uint32_t *e, uint32_t *first,
                      uint32_t *end)
{
    const sw_part_levels *pl = &pack->part_levels;
    *first = pl->piece_of[s], *end = *first + 1;
    for (*e = s; *e < pack->surface_count && pack->surfaces[*e].part == pack->surfaces[s].part;
         (*e)++)
        *end = pl->piece_of[*e] + 1 > *end ? pl->piece_of[*e] + 1 : *end;
}

/* Every piece's levels at every front, against its source made again
 * here, and each cut part's borders; the number of cut parts. */
static int check_pieces(const sw_pack *pack)
{
    sw_error err = { 0 };
    sw_part_source src;
    SW_CHECK_MSG(sw_part_source_build(pack, &pack->levels, NULL, &src, &err) == SW_OK, "%s",
                 err.message);
    int cut_parts = 0;
    float *diagonal = calloc(pack->surface_count + 1, sizeof *diagonal);
    for (uint32_t s = 0, e, first, end; s < pack->surface_count; s = e) {
        next_part(pack, s, &e, &first, &end);
        double d = sw_part_diagonal(pack, pack->surfaces[s].part);
        for (uint32_t k = s; end - first > 1 && k < e; k++)
            diagonal[k] = (float)d;
        cut_parts += end - first > 1;
        for (uint32_t g = first; end - first == 1 && g < end; g++)
            check_piece(pack, &src, g, 0, 0);
        if (end - first > 1)   /* the cut part's levels of itself whole, on its first piece */
            check_piece(pack, &src, first, SW_PART_LEVEL_WHOLE, 0);
    }
    sw_part_source_free(&src);
    float *at = calloc(pack->surface_count + 1, sizeof *at);
    for (uint32_t f = 0; cut_parts && f < SW_PART_LEVEL_FRONTS; f++) {
        for (uint32_t s = 0; s < pack->surface_count; s++)
            at[s] = diagonal[s] > 0 ? (float)sw_part_level_front_bound(diagonal[s], f) : 0.0f;
        SW_CHECK_MSG(sw_part_source_build(pack, &pack->levels, at, &src, &err) == SW_OK, "%s",
                     err.message);
        for (uint32_t s = 0, e, first, end; s < pack->surface_count; s = e) {
            next_part(pack, s, &e, &first, &end);
            for (uint32_t g = first; end - first > 1 && g < end; g++)
                check_piece(pack, &src, g, f, 1);
            if (end - first > 1)
                check_borders(pack, first, end, f);
        }
        sw_part_source_free(&src);
    }
    free(at);
    free(diagonal);
    return cut_parts;
}

/* A pack of placed parts is checked as placed: its prototypes, built
 * apart, overlap where they were modelled, and the sources made again
 * from them together would weld one to another. */
static void check_pack_file(const char *path, int want_cut)
{
    sw_pack pack;
    void *placed;
    uint8_t *bytes = sw_test_open_placed_pack(path, &pack, &placed);
    if (!bytes)
        return;
    SW_CHECK_MSG(pack.part_levels.level_count > 0, "%s: no part levels", path);
    int cut = pack.part_levels.level_count > 0 ? check_pieces(&pack) : 0;
    SW_CHECK_MSG(!want_cut || cut > 0, "%s: no part cut into pieces", path);
    free(placed);
    free(bytes);
}

int main(int argc, char **argv)
{
    int want_cut = argc > 1 && strcmp(argv[1], "--cut") == 0;
    SW_CHECK_MSG(argc > 1 + want_cut, "usage: test_part_levels_build [--cut] PACK...");
    for (int i = 1 + want_cut; i < argc; i++)
        check_pack_file(argv[i], want_cut);
    return sw_test_finish();
}
