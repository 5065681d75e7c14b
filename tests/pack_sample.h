/* SPDX-License-Identifier: MIT */
/* Shared by the pack tests (test_pack.c: the reader; test_pack_write.c: the
 * writer): a small pack built by hand, header and table access for making
 * faulty packs with valid checksums, and a scratch directory for files.
 * Include after sw_test.h. */
#ifndef PACK_SAMPLE_H
#define PACK_SAMPLE_H

#include <dirent.h>
#include <errno.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>
#include <xxhash.h>

#include "sw_pack.h"
#include "sw_pack_write.h"

/* ---- a small pack built by hand: 2 parts, 3 patches, 1 adjacency ----
 * and every optional section: surface 0 (part 0, patches 0..1, domain
 * [0, 2] x [0, 1]) trimmed by an outer rectangle (a degree-1 curve) and an
 * inner circle (a rational quadratic, computed); surface 1 (part 1, patch 2)
 * untrimmed; one mask, one viewpoint, two part transforms. */

enum { SAMPLE_CONTROL = 16 + 9 + 16, SAMPLE_SECTIONS = 13 };
/* TRIM_DATA: the rectangle's 7 knots and 5 points, the circle's 12 knots
 * and 9 points. */
enum { RECT_AT = 0, CIRCLE_AT = 7 + 5 * 3, SAMPLE_TRIM_DATA = CIRCLE_AT + 12 + 9 * 3 };

typedef struct sample {
    sw_pack_meta meta;
    sw_pack_part parts[2];
    sw_pack_patch patches[3];
    float control[SAMPLE_CONTROL * 4];
    sw_pack_adjacency adjacency[1];
    sw_pack_surface surfaces[2];
    sw_pack_trim_loop loops[2];
    sw_pack_trim_curve curves[2];
    float trim_data[SAMPLE_TRIM_DATA];
    sw_pack_patch_domain domains[3];
    sw_pack_trim_mask masks[1];
    sw_pack_viewpoint viewpoints[1];
    float transforms[2 * 16];
    int bezier_only;   /* 1: serialise without the optional sections */
} sample;

static inline void set_grid(float *ctrl, int du, int dv, float x0, float z_bump, float w_mid)
{
    for (int j = 0; j <= dv; j++)
        for (int i = 0; i <= du; i++) {
            float *c = &ctrl[(j * (du + 1) + i) * 4];
            c[0] = x0 + (float)i / (float)du;
            c[1] = (float)j / (float)dv;
            c[2] = (i > 0 && i < du && j > 0 && j < dv) ? z_bump : 0.0f;
            c[3] = (i == du / 2 && j == dv / 2) ? w_mid : 1.0f;
        }
}

/* Patch boxes from their control points, META's box from the patches. */
static inline void fit_boxes(sample *s)
{
    for (int p = 0; p < 3; p++) {
        sw_pack_patch *pp = &s->patches[p];
        int n = (pp->degree_u + 1) * (pp->degree_v + 1);
        for (int k = 0; k < 3; k++) {
            pp->box_min[k] = pp->box_max[k] = s->control[pp->first_control * 4 + k];
            for (int i = 1; i < n; i++) {
                float v = s->control[(pp->first_control + i) * 4 + k];
                pp->box_min[k] = v < pp->box_min[k] ? v : pp->box_min[k];
                pp->box_max[k] = v > pp->box_max[k] ? v : pp->box_max[k];
            }
            s->meta.box_min[k] = p == 0 || pp->box_min[k] < s->meta.box_min[k] ? pp->box_min[k]
                                                                               : s->meta.box_min[k];
            s->meta.box_max[k] = p == 0 || pp->box_max[k] > s->meta.box_max[k] ? pp->box_max[k]
                                                                               : s->meta.box_max[k];
        }
    }
}

static inline void set_trim_curves(sample *s)
{
    static const float rect[7 + 5 * 3] = {
        0, 0, 1, 2, 3, 4, 4,
        0.1f, 0.1f, 1, 1.9f, 0.1f, 1, 1.9f, 0.9f, 1, 0.1f, 0.9f, 1, 0.1f, 0.1f, 1 };
    /* A full circle of radius 0.2 about (1, 0.5): four rational quarter arcs. */
    static const float circle[12 + 9 * 3] = {
        0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4,
        1.2f, 0.5f, 1, 1.2f, 0.7f, 0.70710678f, 1.0f, 0.7f, 1, 0.8f, 0.7f, 0.70710678f,
        0.8f, 0.5f, 1, 0.8f, 0.3f, 0.70710678f, 1.0f, 0.3f, 1, 1.2f, 0.3f, 0.70710678f,
        1.2f, 0.5f, 1 };
    memcpy(&s->trim_data[RECT_AT], rect, sizeof rect);
    memcpy(&s->trim_data[CIRCLE_AT], circle, sizeof circle);
    s->curves[0] = (sw_pack_trim_curve){ .first_float = RECT_AT, .count = 5, .degree = 1 };
    s->curves[1] = (sw_pack_trim_curve){ .first_float = CIRCLE_AT, .count = 9, .degree = 2,
                                         .flags = SW_TRIM_RATIONAL | SW_TRIM_COMPUTED };
    s->loops[0] = (sw_pack_trim_loop){ .first_curve = 0, .curve_count = 1, .flags = SW_LOOP_OUTER };
    s->loops[1] = (sw_pack_trim_loop){ .first_curve = 1, .curve_count = 1 };
}

static inline void set_trim_sections(sample *s)
{
    set_trim_curves(s);
    s->surfaces[0] = (sw_pack_surface){ .part = 0, .first_patch = 0, .patch_count = 2,
                                        .first_loop = 0, .loop_count = 2,
                                        .domain = { 0, 2, 0, 1 } };
    s->surfaces[1] = (sw_pack_surface){ .part = 1, .first_patch = 2, .patch_count = 1,
                                        .domain = { 0, 1, 0, 1 } };
    s->domains[0] = (sw_pack_patch_domain){ .surface = 0, .mask = 0, .domain = { 0, 1, 0, 1 } };
    s->domains[1] = (sw_pack_patch_domain){ .surface = 0, .mask = SW_MASK_NONE,
                                            .domain = { 1, 2, 0, 1 } };
    s->domains[2] = (sw_pack_patch_domain){ .surface = 1, .mask = SW_MASK_NONE,
                                            .domain = { 0, 1, 0, 1 } };
    for (int j = 0; j < 32; j++)
        s->masks[0].rows[j] = j >= 3 && j <= 28 ? 0xFFFFFFF8u : 0; /* inside the rectangle */
    s->viewpoints[0] = (sw_pack_viewpoint){ .name = "front", .eye = { 1, 0.5f, 3 },
                                            .target = { 1, 0.5f, 0 }, .up = { 0, 1, 0 },
                                            .fov_deg = 50 };
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < 16; k++)
            s->transforms[p * 16 + k] = k % 5 == 0 ? 1.0f : 0.0f;
    s->transforms[16 + 12] = 1.0f; /* part 1 moved by +1 along x */
}

static inline void make_sample(sample *s)
{
    memset(s, 0, sizeof *s);
    s->meta = (sw_pack_meta){ .part_count = 2, .patch_count = 3, .control_count = SAMPLE_CONTROL,
                              .adjacency_count = 1, .units = SW_UNITS_MILLIMETRE,
                              .model_tolerance = 0.01f };
    s->parts[0] = (sw_pack_part){ .first_patch = 0, .patch_count = 2,
                                  .color = { 0.8f, 0.1f, 0.1f, 1.0f }, .name = "body" };
    s->parts[1] = (sw_pack_part){ .first_patch = 2, .patch_count = 1,
                                  .color = { 0.2f, 0.2f, 0.9f, 0.5f }, .name = "lid \xc3\xa9" };
    s->patches[0] = (sw_pack_patch){ .first_control = 0, .degree_u = 3, .degree_v = 3,
                                     .part = 0, .d2_bound = { 1.0f, 0.5f, 2.0f } };
    s->patches[1] = (sw_pack_patch){ .first_control = 16, .degree_u = 2, .degree_v = 2,
                                     .flags = SW_PATCH_RATIONAL, .part = 0,
                                     .d2_bound = { 3.0f, 0.0f, 1.5f } };
    s->patches[2] = (sw_pack_patch){ .first_control = 25, .degree_u = 3, .degree_v = 3,
                                     .part = 1, .d2_bound = { 0.25f, 0.25f, 0.25f } };
    set_grid(&s->control[0], 3, 3, 0.0f, 0.3f, 1.0f);
    set_grid(&s->control[16 * 4], 2, 2, 0.0f, 0.5f, 0.7071f);
    set_grid(&s->control[25 * 4], 3, 3, 1.0f, -0.2f, 1.0f);
    s->adjacency[0] = (sw_pack_adjacency){ .patch_a = 0, .patch_b = 2, .edge_a = SW_EDGE_U1,
                                           .edge_b = SW_EDGE_U0 };
    fit_boxes(s);
    set_trim_sections(s);
}

/* ---- a Seam Graph for the sample's two surfaces, built by hand ----
 * Surface 0 is the unit square (0..1)² at z = 0, with a triangular hole;
 * surface 1 the square (1..2) x (0..1) beside it, sewn to it along x = 1
 * (vertices 1, 6, 2 sit in slots of both). Then four collapses: 6 into 2
 * (vertex 10), 8 into 7 (11), 9 into 11 (12: the hole is gone), 3 into 10
 * (13). Surface 0's (u, v) is (2x, y) (its domain is [0, 2] x [0, 1]),
 * surface 1's (x - 1, y). */

enum { SEAM_ORIGINAL = 10, SEAM_COLLAPSES = 4, SEAM_VERTICES = 14, SEAM_SLOTS = 13,
       SEAM_LOOPS = 3, SEAM_EDGES = 11 };

typedef struct sample_seam {
    sw_seam_vertex vertices[SEAM_VERTICES];
    sw_seam_slot slots[SEAM_SLOTS];
    sw_seam_loop loops[SEAM_LOOPS];
    sw_seam_edge edges[SEAM_EDGES];
    sw_seam_collapse collapses[SEAM_COLLAPSES];
    uint32_t slot_refs[SEAM_SLOTS];
    uint32_t surface_loops[2 + 1 + 1]; /* one spare, for tests that claim 3 surfaces */
    sw_seam_graph graph;               /* views of the arrays above */
} sample_seam;

static inline void set_seam_vertices(sample_seam *g)
{
    static const float p[SEAM_VERTICES][3] = {
        { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 2, 1, 0 },
        { 1, 0.5f, 0 }, { 0.3f, 0.3f, 0 }, { 0.6f, 0.3f, 0 }, { 0.45f, 0.6f, 0 },
        { 1, 1, 0 }, { 0.3f, 0.3f, 0 }, { 0.3f, 0.3f, 0 }, { 1, 1, 0 } };
    static const uint32_t child[SEAM_VERTICES] = { SW_SEAM_NONE, SW_SEAM_NONE, 10, 13,
                                                   SW_SEAM_NONE, SW_SEAM_NONE, 10, 11, 11, 12,
                                                   13, 12, SW_SEAM_NONE, SW_SEAM_NONE };
    static const float error[SEAM_VERTICES] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                0.25f, 0.3f, 0.3f, 1.0f };
    /* Slot references per original vertex: 0 | 1 8 | 3 11 | 4 | 9 | 10 | 2 12 | 5 | 7 | 6 */
    static const uint32_t first[SEAM_ORIGINAL] = { 0, 1, 3, 5, 6, 7, 8, 10, 11, 12 };
    static const uint32_t count[SEAM_ORIGINAL] = { 1, 2, 2, 1, 1, 1, 2, 1, 1, 1 };
    static const uint32_t refs[SEAM_SLOTS] = { 0, 1, 8, 3, 11, 4, 9, 10, 2, 12, 5, 7, 6 };
    for (int i = 0; i < SEAM_VERTICES; i++) {
        int original = i < SEAM_ORIGINAL;
        g->vertices[i] = (sw_seam_vertex){ .p = { p[i][0], p[i][1], p[i][2] }, .child = child[i],
                                           .error = error[i],
                                           .first_slot_ref = original ? first[i] : 0,
                                           .slot_ref_count = original ? count[i] : 0 };
    }
    memcpy(g->slot_refs, refs, sizeof refs);
    static const sw_seam_collapse collapses[SEAM_COLLAPSES] = {
        { 6, 2, 0.25f }, { 8, 7, 0.3f }, { 9, 11, 0.2f }, { 3, 10, 1.0f } };
    memcpy(g->collapses, collapses, sizeof collapses);
}

static inline void set_seam_boundaries(sample_seam *g)
{
    static const sw_seam_slot slots[SEAM_SLOTS] = {
        /* surface 0, outer: (0,0) (1,0) (1,0.5) (1,1) (0,1) */
        { 0, { 0, 0 } }, { 1, { 2, 0 } }, { 6, { 2, 0.5f } }, { 2, { 2, 1 } }, { 3, { 0, 1 } },
        /* surface 0, the hole, clockwise */
        { 7, { 0.6f, 0.3f } }, { 9, { 0.9f, 0.6f } }, { 8, { 1.2f, 0.3f } },
        /* surface 1, outer: (1,0) (2,0) (2,1) (1,1) (1,0.5) */
        { 1, { 0, 0 } }, { 4, { 1, 0 } }, { 5, { 1, 1 } }, { 2, { 0, 1 } }, { 6, { 0, 0.5f } } };
    memcpy(g->slots, slots, sizeof slots);
    g->loops[0] = (sw_seam_loop){ .surface = 0, .first_slot = 0, .slot_count = 5,
                                  .flags = SW_SEAM_LOOP_OUTER };
    g->loops[1] = (sw_seam_loop){ .surface = 0, .first_slot = 5, .slot_count = 3 };
    g->loops[2] = (sw_seam_loop){ .surface = 1, .first_slot = 8, .slot_count = 5,
                                  .flags = SW_SEAM_LOOP_OUTER };
    static const sw_seam_edge edges[SEAM_EDGES] = {
        { 0, 1 }, { 1, 6 }, { 2, 6 }, { 2, 3 }, { 0, 3 }, { 7, 9 }, { 8, 9 }, { 7, 8 },
        { 1, 4 }, { 4, 5 }, { 2, 5 } };
    memcpy(g->edges, edges, sizeof edges);
    g->surface_loops[0] = 0;
    g->surface_loops[1] = 2;
    g->surface_loops[2] = 3;
}

/* The graph's views and counts; call again after moving the struct. */
static inline void view_sample_seam(sample_seam *g)
{
    g->graph = (sw_seam_graph){
        .vertices = g->vertices, .slots = g->slots, .loops = g->loops, .edges = g->edges,
        .collapses = g->collapses, .slot_refs = g->slot_refs, .surface_loops = g->surface_loops,
        .vertex_count = SEAM_VERTICES, .original_count = SEAM_ORIGINAL,
        .slot_count = SEAM_SLOTS, .loop_count = SEAM_LOOPS, .edge_count = SEAM_EDGES,
        .collapse_count = SEAM_COLLAPSES, .slot_ref_count = SEAM_SLOTS, .surface_count = 2,
        .tolerance = 0.001f };
}

static inline void make_sample_seam(sample_seam *g)
{
    memset(g, 0, sizeof *g);
    set_seam_vertices(g);
    set_seam_boundaries(g);
    view_sample_seam(g);
}

/* ---- static levels over that graph, built by hand ----
 * Surface 0 (loop 0, outer, 5 slots; loop 1, the hole, 3) has one level:
 * its square in 2 triangles, the hole vanished (an empty chain). Surface 1
 * (loop 2, outer, 5 slots) has two: its square in 2 triangles, then one
 * triangle. Chain points stand at their slot: t is the slot's place in
 * its loop. 15 indices: LEVEL_INDICES is 30 bytes, no multiple of 4. */

enum { LEVELS_LEVELS = 3, LEVELS_VERTICES = 11, LEVELS_INDICES = 15, LEVELS_CHAINS = 4,
       LEVELS_POINTS = 11 };

typedef struct sample_levels {
    sw_level levels[LEVELS_LEVELS];
    uint32_t surface_levels[2 + 1 + 1]; /* one spare, for tests that claim 3 surfaces */
    sw_level_vertex vertices[LEVELS_VERTICES];
    uint16_t indices[LEVELS_INDICES];
    sw_level_chain chains[LEVELS_CHAINS];
    sw_strip_point points[LEVELS_POINTS];
    sw_levels view;                     /* views of the arrays above */
} sample_levels;

static inline void set_level_meshes(sample_levels *l)
{
    static const float p[LEVELS_VERTICES][2] = {
        { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 },   /* surface 0, the square */
        { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 },   /* surface 1, the square */
        { 1, 0 }, { 2, 0 }, { 2, 1 } };           /* surface 1, one triangle */
    for (int i = 0; i < LEVELS_VERTICES; i++)
        l->vertices[i] = (sw_level_vertex){ .p = { p[i][0], p[i][1], 0 }, .normal = { 0, 0, 127 } };
    static const uint16_t indices[LEVELS_INDICES] = { 0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3, 0, 1, 2 };
    memcpy(l->indices, indices, sizeof indices);
    l->levels[0] = (sw_level){ .surface = 0, .error = 0.01f, .first_vertex = 0, .vertex_count = 4,
                               .first_index = 0, .index_count = 6, .first_chain = 0 };
    l->levels[1] = (sw_level){ .surface = 1, .error = 0.005f, .first_vertex = 4, .vertex_count = 4,
                               .first_index = 6, .index_count = 6, .first_chain = 2 };
    l->levels[2] = (sw_level){ .surface = 1, .error = 0.02f, .first_vertex = 8, .vertex_count = 3,
                               .first_index = 12, .index_count = 3, .first_chain = 3 };
    l->surface_levels[0] = 0;
    l->surface_levels[1] = 1;
    l->surface_levels[2] = 3;
}

static inline void set_level_chains(sample_levels *l)
{
    /* Level 0's square stands at loop 0's slots 0, 1, 3, 4 ((0,0) (1,0)
     * (1,1) (0,1)); surface 1's at loop 2's slots 0..3. */
    static const sw_strip_point points[LEVELS_POINTS] = {
        { 0, 0 }, { 1, 1 }, { 2, 3 }, { 3, 4 },
        { 0, 0 }, { 1, 1 }, { 2, 2 }, { 3, 3 },
        { 0, 0 }, { 1, 1 }, { 2, 2 } };
    memcpy(l->points, points, sizeof points);
    l->chains[0] = (sw_level_chain){ .first_point = 0, .point_count = 4 };
    l->chains[1] = (sw_level_chain){ .first_point = 4, .point_count = 0 }; /* the hole, gone */
    l->chains[2] = (sw_level_chain){ .first_point = 4, .point_count = 4 };
    l->chains[3] = (sw_level_chain){ .first_point = 8, .point_count = 3 };
}

/* The levels' views and counts; call again after moving the struct. */
static inline void view_sample_levels(sample_levels *l)
{
    l->view = (sw_levels){ .levels = l->levels, .surface_levels = l->surface_levels,
                           .vertices = l->vertices, .indices = l->indices, .chains = l->chains,
                           .chain_points = l->points, .level_count = LEVELS_LEVELS,
                           .vertex_count = LEVELS_VERTICES, .index_count = LEVELS_INDICES,
                           .chain_count = LEVELS_CHAINS, .chain_point_count = LEVELS_POINTS,
                           .surface_count = 2 };
}

static inline void make_sample_levels(sample_levels *l)
{
    memset(l, 0, sizeof *l);
    set_level_meshes(l);
    set_level_chains(l);
    view_sample_levels(l);
}

/* ---- the sample's super-surfaces: one per surface (each its own part),
 * surface 0 (the bumped grid) in a 20-degree cone round +z, surface 1 in
 * none (span pi, zero axis) ---- */
typedef struct sample_supers {
    sw_super_surface supers[2];
    uint32_t members[2];
    uint32_t super_of[2];
    sw_supers view;
} sample_supers;

/* The view; call again after moving the struct or changing the counts. */
static inline void view_sample_supers(sample_supers *k, uint32_t super_count)
{
    k->view = (sw_supers){ .supers = k->supers, .members = k->members, .super_of = k->super_of,
                           .super_count = super_count, .surface_count = 2 };
}

static inline void make_sample_supers(sample_supers *k)
{
    memset(k, 0, sizeof *k);
    k->supers[0] = (sw_super_surface){ .first_member = 0, .member_count = 1, .part = 0,
                                       .span = 0.35f, .axis = { 0, 0, 1 } };
    k->supers[1] = (sw_super_surface){ .first_member = 1, .member_count = 1, .part = 1,
                                       .span = 3.14159265f };
    k->members[0] = 0, k->members[1] = 1;
    k->super_of[0] = 0, k->super_of[1] = 1;
    view_sample_supers(k, 2);
}

/* Part levels for the sample's two parts, one piece each (its surface):
 * part 0 two levels (a square of two triangles, then one triangle), part 1
 * none. */
typedef struct sample_part_levels {
    sw_part_level levels[2];
    uint32_t part_levels[4];      /* 3 used; room for a test's extra piece */
    uint32_t piece_of[2];
    sw_level_vertex vertices[7];
    uint16_t indices[9];
    sw_part_levels view;
} sample_part_levels;

static inline void view_sample_part_levels(sample_part_levels *k)
{
    k->view = (sw_part_levels){ k->levels, k->part_levels, k->piece_of, k->vertices, k->indices,
                                2, 7, 9, 2, 2 };
}

static inline void make_sample_part_levels(sample_part_levels *k)
{
    memset(k, 0, sizeof *k);
    const float square[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
    for (int i = 0; i < 7; i++) {
        memcpy(k->vertices[i].p, square[i < 4 ? i : i - 4], sizeof k->vertices[i].p);
        k->vertices[i].normal[2] = 127;
    }
    const uint16_t idx[9] = { 0, 1, 2, 0, 2, 3, 0, 1, 2 };
    memcpy(k->indices, idx, sizeof idx);
    k->levels[0] = (sw_part_level){ .piece = 0, .error = 0.1f, .first_vertex = 0,
                                    .vertex_count = 4, .first_index = 0, .index_count = 6 };
    k->levels[1] = (sw_part_level){ .piece = 0, .error = 0.4f, .first_vertex = 4,
                                    .vertex_count = 3, .first_index = 6, .index_count = 3 };
    k->part_levels[0] = 0, k->part_levels[1] = 2, k->part_levels[2] = 2;
    k->piece_of[0] = 0, k->piece_of[1] = 1;
    view_sample_part_levels(k);
}

static inline sw_pack_contents sample_contents(const sample *s)
{
    sw_pack_contents c = { .meta = s->meta, .parts = s->parts, .patches = s->patches,
                           .control = s->control, .adjacency = s->adjacency };
    if (s->bezier_only)
        return c;
    c.surfaces = s->surfaces;
    c.surface_count = 2;
    c.trim_loops = s->loops;
    c.trim_loop_count = 2;
    c.trim_curves = s->curves;
    c.trim_curve_count = 2;
    c.trim_data = s->trim_data;
    c.trim_data_count = SAMPLE_TRIM_DATA;
    c.patch_domains = s->domains;
    c.trim_masks = s->masks;
    c.trim_mask_count = 1;
    c.viewpoints = s->viewpoints;
    c.viewpoint_count = 1;
    c.part_transforms = s->transforms;
    return c;
}

/* Serialised sample; malloc'd, so 8-byte aligned as the reader requires. */
static inline uint8_t *serialize_sample(const sample *s, size_t *size)
{
    sw_pack_contents c = sample_contents(s);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_status st = sw_pack_serialize(&c, &bytes, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return bytes;
}

/* The sample with its Seam Graph, the levels l and the super-surfaces k
 * (each NULL: none), serialised; malloc'd. */
/* The sample with its graph, the levels l, clusters k and part levels pl
 * (each NULL: none), serialised; malloc'd. */
static inline uint8_t *serialize_sample_all(const sw_levels *l, const sw_supers *k,
                                            const sw_part_levels *pl, size_t *size)
{
    sample s;
    sample_seam g;
    make_sample(&s);
    make_sample_seam(&g);
    sw_pack_contents c = sample_contents(&s);
    c.seam = &g.graph;
    c.levels = l;
    c.supers = k;
    c.part_levels = pl;
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_status st = sw_pack_serialize(&c, &bytes, size, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    return bytes;
}

static inline uint8_t *serialize_sample_with(const sw_levels *l, const sw_supers *k,
                                             size_t *size)
{
    return serialize_sample_all(l, k, NULL, size);
}

static inline sw_pack_header *header_of(uint8_t *bytes) { return (sw_pack_header *)bytes; }
static inline sw_pack_section *table_of(uint8_t *bytes) { return (sw_pack_section *)(bytes + 64); }

/* Recomputes the header checksum after a test edited the header or table,
 * so the check under test is the one that fires. */
static inline void reseal(uint8_t *bytes)
{
    sw_pack_header *h = header_of(bytes);
    h->header_checksum = 0;
    h->header_checksum = XXH3_64bits(bytes, 64 + (size_t)h->section_count * 32);
}

/* Every section's checksum recomputed, then the header's: after a test
 * edited sections' bytes, the check under test is the one that fires. */
static inline void reseal_all(uint8_t *bytes)
{
    for (uint32_t i = 0; i < header_of(bytes)->section_count; i++) {
        sw_pack_section *e = &table_of(bytes)[i];
        e->checksum = XXH3_64bits(bytes + e->offset, (size_t)e->size);
    }
    reseal(bytes);
}

/* Index of the table entry of type in bytes, or -1. */
static inline int entry_of(uint8_t *bytes, uint32_t type)
{
    for (uint32_t i = 0; i < header_of(bytes)->section_count; i++)
        if (table_of(bytes)[i].type == type)
            return (int)i;
    return -1;
}


/* ---- forward compatibility ---- */

/* Adds a 64-byte section of type 99 at the end. The sample's table of 13
 * entries ends at byte 480 and its first section starts at 512, so a 14th
 * entry fits without moving anything (and a 6th after a Bezier-only table). */
static inline uint8_t *add_unknown_section(const uint8_t *bytes, size_t size, size_t *new_size)
{
    size_t at = (size + 63) / 64 * 64;
    *new_size = at + 64;
    uint8_t *out = calloc(1, *new_size);
    memcpy(out, bytes, size);
    for (int i = 0; i < 64; i++)
        out[at + i] = (uint8_t)(0xA0 + i);
    sw_pack_header *h = header_of(out);
    table_of(out)[h->section_count] = (sw_pack_section){
        .type = 99, .offset = at, .size = 64, .checksum = XXH3_64bits(out + at, 64) };
    h->section_count++;
    h->total_size = *new_size;
    h->runtime_bytes = sw_pack_runtime_bytes(0); /* the sample has no graph */
    reseal(out);
    return out;
}


/* ---- files ---- */

/* Each program fills in the X with mkdtemp before using scratch(). */
static char scratch_dir[] = "/tmp/test_pack-XXXXXX";

static inline const char *scratch(const char *name)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%.200s", scratch_dir, name);
    return path;
}

static inline void write_plain(const char *path, const void *bytes, size_t size)
{
    FILE *f = fopen(path, "wb");
    SW_CHECK_MSG(f && fwrite(bytes, 1, size, f) == size, "%s", path);
    if (f)
        fclose(f);
}

/* Whole file into a malloc'd buffer; NULL when it cannot be read. */
static inline char *read_plain(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    *size = fread(buf, 1, 1 << 20, f);
    fclose(f);
    return buf;
}

static inline int file_holds(const char *path, const char *text)
{
    size_t n = 0;
    char *buf = read_plain(path, &n);
    int same = buf && n == strlen(text) && memcmp(buf, text, n) == 0;
    free(buf);
    return same;
}

/* Files in the scratch directory whose names contain ".tmp-". */
static inline int leftover_temp_files(void)
{
    int n = 0;
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strstr(e->d_name, ".tmp-") != NULL;
    if (d)
        closedir(d);
    return n;
}


static inline void remove_scratch(void)
{
    DIR *d = opendir(scratch_dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (e->d_name[0] != '.' && unlink(scratch(e->d_name)) != 0 && errno == EISDIR)
            rmdir(scratch(e->d_name));
    if (d)
        closedir(d);
    rmdir(scratch_dir);
}

#endif
