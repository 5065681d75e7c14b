/* SPDX-License-Identifier: MIT */
/* The static levels the pack tool makes (assets/super/sw_levels_build.h),
 * checked by what they must be, not by how they were made:
 * - every level's triangles re-measured against the exact surface at
 *   random points (not the builder's grid): within its stored error (plus
 *   the sewing offset the stored error leaves out, and a twentieth for
 *   points the grid did not reach);
 * - errors rise over a surface's levels; levels are no finer than asked;
 * - the border chains: one per loop of the surface (empty only for a hole),
 *   each once round its loop in slot order, every point a border vertex of
 *   the level's mesh (an edge used by one triangle), every border vertex
 *   in a chain;
 * - a chain point that is a seam vertex of the level's state stands at
 *   that vertex's position bit for bit.
 * Without arguments, on packs built here (a plane trimmed by a square with
 * a round hole, a bicubic bump); with pack files as arguments, on those
 * too (CTest passes the built teaset and a generated showroom). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_shapes.h"
#include "sw_levels_build.h"
#include "sw_pack_write.h"
#include "sw_seam_sew.h"
#include "sw_seam_simplify.h"
#include "sw_surface_at.h"
#include "sw_test.h"
#include "pack_file.h"

/* Border edges of a level: 1 when directed edge a-b is used once and its
 * reverse not at all. */
static int border_edge(const uint16_t *idx, uint32_t n, uint32_t a, uint32_t b)
{
    int fwd = 0, back = 0;
    for (uint32_t t = 0; t + 2 < n; t += 3)
        for (int k = 0; k < 3; k++) {
            fwd += idx[t + k] == a && idx[t + (k + 1) % 3] == b;
            back += idx[t + k] == b && idx[t + (k + 1) % 3] == a;
        }
    return fwd + back == 1;
}

static double random_error(const sw_pack *pack, const sw_level *l, const sw_levels *lv,
                           const sw_trim_patch *patches, uint32_t count, const float *uvs)
{
    double worst = 0;
    const uint16_t *idx = lv->indices + l->first_index;
    const sw_level_vertex *v = lv->vertices + l->first_vertex;
    (void)pack;
    for (uint32_t t = 0; t + 2 < l->index_count; t += 3)
        for (int k = 0; k < 6; k++) {
            double a = sw_test_random(), b = sw_test_random();
            if (a + b > 1)
                a = 1 - a, b = 1 - b;
            double w[3] = { a, b, 1 - a - b }, p[3] = { 0 }, uv[2] = { 0 };
            for (int j = 0; j < 3; j++) {
                for (int c = 0; c < 3; c++)
                    p[c] += w[j] * v[idx[t + j]].p[c];
                for (int c = 0; c < 2; c++)
                    uv[c] += w[j] * uvs[2 * idx[t + j] + c];
            }
            sw_vec3 s = sw_surface_at(patches, count, uv[0], uv[1]);
            worst = fmax(worst, sqrt((p[0] - s.x) * (p[0] - s.x) + (p[1] - s.y) * (p[1] - s.y) +
                                     (p[2] - s.z) * (p[2] - s.z)));
        }
    return worst;
}

/* Level l's chains as the header says; 0 problems expected. */
static uint32_t chain_problems(const sw_pack *pack, const sw_levels *lv, const sw_level *l)
{
    const sw_seam_graph *g = &pack->seam;
    uint32_t s = l->surface, problems = 0, in_chains = 0;
    const uint16_t *idx = lv->indices + l->first_index;
    uint32_t loops = g->surface_loops[s + 1] - g->surface_loops[s];
    for (uint32_t i = 0; i < loops; i++) {
        const sw_seam_loop *loop = &g->loops[g->surface_loops[s] + i];
        const sw_level_chain *c = &lv->chains[l->first_chain + i];
        const sw_strip_point *p = lv->chain_points + c->first_point;
        if (c->point_count == 0) {
            problems += (loop->flags & SW_SEAM_LOOP_OUTER) != 0;
            continue;
        }
        problems += !sw_border_chain_valid(p, c->point_count, (float)loop->slot_count);
        for (uint32_t k = 0; k < c->point_count; k++) {
            uint32_t a = p[k].vertex, b = p[(k + 1) % c->point_count].vertex;
            problems += a >= l->vertex_count;
            problems += c->point_count > 2 && !border_edge(idx, l->index_count, a, b);
        }
        in_chains += c->point_count;
    }
    /* every border edge's start is in a chain: count border edges */
    uint32_t border = 0;
    for (uint32_t t = 0; t + 2 < l->index_count; t += 3)
        for (int k = 0; k < 3; k++)
            border += border_edge(idx, l->index_count, idx[t + k], idx[t + (k + 1) % 3]);
    problems += border != in_chains;
    return problems;
}

/* The largest coordinate of level l's vertices. */
static double magnitude(const sw_levels *lv, const sw_level *l)
{
    double m = 0;
    for (uint32_t i = 0; i < l->vertex_count; i++)
        for (int c = 0; c < 3; c++)
            m = fmax(m, fabs(lv->vertices[l->first_vertex + i].p[c]));
    return m;
}

typedef struct totals {
    uint32_t levels, chain_problems, not_rising, over_stored;
    double worst_ratio;     /* re-measured over stored + sewing offset */
} totals;

static void check_levels(const sw_pack *pack, const sw_levels_built *built, totals *t)
{
    const sw_levels *lv = &built->view;
    const sw_seam_graph *g = &pack->seam;
    sw_trim_patch *patches = malloc(4096 * sizeof *patches);
    for (uint32_t s = 0; s < lv->surface_count; s++) {
        uint32_t count = 0;
        sw_trim_patches_from_pack(pack, s, patches, 4096, &count, NULL);
        double sew = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            sew = fmax(sew, sw_seam_sewing_offset(g, &g->loops[l], patches, count));
        for (uint32_t k = lv->surface_levels[s]; k < lv->surface_levels[s + 1]; k++) {
            const sw_level *l = &lv->levels[k];
            t->levels++;
            t->not_rising += k > lv->surface_levels[s] && !(l->error > lv->levels[k - 1].error);
            t->chain_problems += l->surface != s || chain_problems(pack, lv, l) != 0;
            double again = random_error(pack, l, lv, patches, count,
                                        built->uvs + 2 * (size_t)l->first_vertex);
            /* Positions are floats: a few of their ulps are no error of the level. */
            double allowed = 1.05 * (l->error + sew) + 8 * FLT_EPSILON * magnitude(lv, l);
            t->over_stored += again > allowed;
            t->worst_ratio = fmax(t->worst_ratio, again / (l->error + sew + 1e-30));
        }
    }
    free(patches);
}

/* Builds pack's levels, checks them (t) and prints the report (r). */
static void check_pack(const sw_pack *pack, const char *path, totals *tp, sw_levels_report *rp)
{
    sw_levels_built built;
    sw_levels_report r;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_levels_build(pack, NULL, &built, &r, &err) == SW_OK, "%s", err.message);
    totals t = { 0 };
    check_levels(pack, &built, &t);
    printf("  %s: %u surfaces, %u with levels, %u levels (triangles by rank %llu %llu %llu "
           "%llu), refused %u, too large %u, bad border %u, not finer %u, vanished %u; "
           "worst error over bound %.3g; re-measured over stored %.3g; %.2f s\n",
           path, r.surfaces, r.with_levels, r.levels, (unsigned long long)r.triangles[0],
           (unsigned long long)r.triangles[1], (unsigned long long)r.triangles[2],
           (unsigned long long)r.triangles[3], r.refused, r.too_large, r.bad_border,
           r.not_finer, r.vanished, r.worst_over_bound, t.worst_ratio, r.seconds);
    SW_CHECK(t.levels == r.levels);
    SW_CHECK_MSG(t.chain_problems == 0, "%u levels with chain problems", t.chain_problems);
    SW_CHECK_MSG(t.not_rising == 0, "%u levels not rising", t.not_rising);
    SW_CHECK_MSG(t.over_stored == 0, "%u levels re-measured over their stored error",
                 t.over_stored);
    sw_levels_built_free(&built);
    *tp = t, *rp = r;
}


static void check_pack_file(const char *path)
{
    sw_pack pack;
    uint8_t *bytes = sw_test_open_pack_file(path, &pack);
    if (!bytes)
        return;
    totals t = { 0 };
    sw_levels_report r;
    check_pack(&pack, path, &t, &r);
    free(bytes);
}
/* A bicubic surface over [0, 3] x [0, 2] bumped up by height (a plane for
 * 0), trimmed by a square with a round hole, packed with its Seam Graph as
 * seamwalk-pack build packs it. *bytes is malloc'd. */
static sw_status pack_bump(double height, uint8_t **bytes, size_t *size, sw_error *err)
{
    shape_plane plane;
    shape_plane_init(&plane, 3, 3, 2, 3, 2);
    int nu = plane.surface.count_u, nv = plane.surface.count_v;
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            double *c = plane.ctrl + (j * nu + i) * 4;
            c[2] = height * sin(3.14159265 * c[0] / 3) * sin(3.14159265 * c[1] / 2);
        }
    shape_rect outer;
    shape_rect_init(&outer, 0.2, 2.8, 0.2, 1.8);
    shape_circle hole;
    shape_circle_init(&hole, 1.5, 1.0, 0.4, 1);
    sw_model_loop_input loops[2] = { { outer.curves, NULL, 4, 1, NULL, NULL},
                                     { &hole.curve, NULL, 1, 0, NULL, NULL} };
    sw_model m;
    sw_model_init(&m);
    sw_seam_host seams = { 0 };
    sw_pack_contents contents;
    sw_status st = sw_model_add_surface(&m, &plane.surface, 0, loops, 2, err);
    if (st == SW_OK)
        st = sw_seam_sew_model(&m, NULL, &seams, NULL, err);
    if (st == SW_OK)
        st = sw_seam_simplify(&seams, err);
    if (st == SW_OK)
        st = sw_pack_contents_from_model(&m, &contents, err);
    if (st == SW_OK) {
        sw_seam_graph view = sw_seam_host_view(&seams);
        contents.seam = &view;
        st = sw_pack_serialize(&contents, bytes, size, err);
        sw_pack_contents_free(&contents);
    }
    sw_seam_host_free(&seams);
    sw_model_free(&m);
    return st;
}

/* The bump: levels at every rank, errors rising, each within the bound it
 * was made for and re-measured within it; the hole has a chain in every
 * level. A plane: one level (every coarser one is as exact and replaces
 * it). */
static void test_a_bump_and_a_plane(void)
{
    const double heights[2] = { 0.5, 0.0 };
    for (int c = 0; c < 2; c++) {
        uint8_t *bytes = NULL;
        size_t size = 0;
        sw_error err = { 0 };
        SW_CHECK_MSG(pack_bump(heights[c], &bytes, &size, &err) == SW_OK, "%s", err.message);
        sw_pack pack;
        SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
        totals t = { 0 };
        sw_levels_report r;
        check_pack(&pack, "bump", &t, &r);
        SW_CHECK(r.surfaces == 1 && r.with_levels == 1 && r.bad_border == 0 && r.refused == 0);
        SW_CHECK(r.worst_over_bound <= 1.0);
        SW_CHECK_MSG(c == 0 ? r.levels == 4 : r.levels == 1, "%u levels", r.levels);
        free(bytes);
    }
}

int main(int argc, char **argv)
{
    SW_RUN(test_a_bump_and_a_plane);
    for (int i = 1; i < argc; i++)
        check_pack_file(argv[i]);
    return sw_test_finish();
}
