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
 * - over a part's levels the triangles fall and the errors rise, and each
 *   level has far fewer triangles than the part's finest static levels;
 * - the area of each level shaded wrong, its normals more than 40 degrees
 *   from every normal of the finest levels within its error (random points,
 *   where the builder took a grid at 30 degrees on its own welded mesh), is
 *   within its stored shading side.
 * Trimmed surfaces are left out of the first check (a random (u, v) may
 * fall in a hole); the second covers them. Takes pack files (CTest passes
 * the built teaset) and fails on one without part levels. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_mesh_distance.h"
#include "sw_part_source.h"
#include "sw_pack.h"
#include "sw_surface_at.h"
#include "sw_test.h"
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

/* Part p's source (sw_part_source.h: its surfaces' finest static levels
 * joined at one front, the mesh its levels were simplified from) as one
 * mesh; *error the largest of its surfaces' errors; *finest_tris its
 * triangles. */
static mesh finest_mesh(const sw_part_source *src, const sw_pack *pack, uint32_t p,
                        double *error, uint32_t *finest_tris)
{
    mesh m = { NULL, NULL, 0, 0, NULL };
    *error = 0;
    for (uint32_t s = 0; s < src->surface_count; s++) {
        if (pack->surfaces[s].part != p || isnan(src->error[s]))
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

/* The largest distance from random points on part p's untrimmed surfaces
 * to grid's mesh. */
static double surface_to_level(const sw_pack *pack, uint32_t p, const sw_mesh_grid *grid)
{
    double worst = 0;
    sw_trim_patch patches[4096];
    for (uint32_t s = 0; s < pack->surface_count; s++) {
        const sw_pack_surface *sf = &pack->surfaces[s];
        uint32_t count = 0;
        if (sf->part != p || sf->loop_count > 0 ||
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

static void check_part(const sw_pack *pack, const sw_part_source *src, uint32_t p)
{
    const sw_part_levels *pl = &pack->part_levels;
    double finest_error = 0;
    uint32_t finest_tris = 0;
    mesh finest = finest_mesh(src, pack, p, &finest_error, &finest_tris);
    sw_mesh_view fv = { finest.pos, finest.idx, finest.nv, finest.ni };
    sw_mesh_grid *fgrid = sw_mesh_grid_make(&fv);
    SW_CHECK(fgrid != NULL);
    uint32_t last_tris = finest_tris;
    for (uint32_t i = pl->part_levels[p]; fgrid && i < pl->part_levels[p + 1]; i++) {
        const sw_part_level *l = &pl->levels[i];
        mesh m = level_mesh(pl, l);
        sw_mesh_view lv = { m.pos, m.idx, m.nv, m.ni };
        sw_mesh_grid *grid = sw_mesh_grid_make(&lv);
        /* The builder samples each triangle on a grid at twice the level's
         * target apart; a peak between its points (the middle of a hole a
         * coarse level covers over) can be missed by up to a quarter. */
        double slack = 1.25 * l->error + 1e-6;
        double from_surface = surface_to_level(pack, p, grid);
        double from_level = level_to_mesh(&m, fgrid);
        SW_CHECK_MSG(from_surface <= slack, "part %u level %u: a surface point %g from it, "
                     "error %g", p, i, from_surface, (double)l->error);
        SW_CHECK_MSG(from_level <= slack + finest_error, "part %u level %u: a point of it %g "
                     "from the finest levels (error %g), its error %g", p, i, from_level,
                     finest_error, (double)l->error);
        SW_CHECK_MSG(l->index_count / 3 < last_tris, "part %u level %u: %u triangles, not "
                     "fewer than %u", p, i, l->index_count / 3, last_tris);
        last_tris = l->index_count / 3;
        double side = shaded_wrong_side(pl, l, &finest, fgrid);
        SW_CHECK_MSG(side <= 2 * l->shading_side + 0.25 * l->error, "part %u level %u: %g "
                     "a side shaded wrong, %g stored (error %g)", p, i, side,
                     (double)l->shading_side, (double)l->error);
        sw_mesh_grid_free(grid);
        free(m.pos), free(m.idx);
    }
    sw_mesh_grid_free(fgrid);
    free(finest.pos), free(finest.idx), free(finest.nrm);
}

static void check_pack_file(const char *path)
{
    size_t size = 0;
    uint8_t *bytes = sw_test_read_file(path, &size);
    if (!bytes)
        return;
    sw_pack pack;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s",
                 err.message);
    SW_CHECK_MSG(pack.part_levels.level_count > 0, "%s: no part levels", path);
    sw_part_source src;
    SW_CHECK_MSG(sw_part_source_build(&pack, &pack.levels, &src, &err) == SW_OK, "%s",
                 err.message);
    for (uint32_t p = 0; p < pack.part_levels.part_count; p++)
        check_part(&pack, &src, p);
    sw_part_source_free(&src);
    free(bytes);
}

int main(int argc, char **argv)
{
    SW_CHECK_MSG(argc > 1, "usage: test_part_levels_build PACK...");
    for (int i = 1; i < argc; i++)
        check_pack_file(argv[i]);
    return sw_test_finish();
}
