/* SPDX-License-Identifier: MIT */
/* The placed scene of an instanced pack (sw_pack_instances.h): counts,
 * bytes and the expansion. The checks are in sw_pack_validate_instances.c. */
#include "sw_pack_instances.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sw_pack_move.h"
#include "sw_seam_fronts.h"
#include "sw_walk_memory.h"

void sw_instance_place(const float t[16], const float p[3], float out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = (float)((double)t[r] * p[0] + (double)t[4 + r] * p[1] + (double)t[8 + r] * p[2] +
                         (double)t[12 + r]);
}

double sw_instance_scale(const float t[16])
{
    double s = 0;
    for (int c = 0; c < 3; c++)
        s += sqrt((double)t[4 * c] * t[4 * c] + (double)t[4 * c + 1] * t[4 * c + 1] +
                  (double)t[4 * c + 2] * t[4 * c + 2]);
    return s / 3;
}

void sw_pack_space_counts(const sw_pack *p, uint64_t t[SW_SPACE_COUNT])
{
    const uint64_t v[SW_SPACE_COUNT] = {
        p->meta->part_count, p->meta->patch_count, p->meta->control_count,
        p->meta->adjacency_count, p->surface_count, p->trim_loop_count, p->trim_curve_count,
        p->trim_data_count, p->trim_mask_count, p->seam.original_count, p->seam.collapse_count,
        p->seam.slot_count, p->seam.loop_count, p->seam.edge_count, p->seam.slot_ref_count,
        p->levels.level_count, p->levels.vertex_count, p->levels.index_count,
        p->levels.chain_count, p->levels.chain_point_count, p->supers.super_count,
        p->supers.members ? p->surface_count : 0, p->part_levels.piece_count,
        p->part_levels.level_count, p->part_levels.vertex_count, p->part_levels.index_count };
    memcpy(t, v, sizeof v);
}

void sw_pack_placed_counts(const sw_pack_prototype *prototypes, const sw_pack_instance *instances,
                           uint32_t instance_count, uint64_t counts[SW_SPACE_COUNT])
{
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        counts[s] = 0;
    for (uint32_t i = 0; i < instance_count; i++)
        for (int s = 0; s < SW_SPACE_COUNT; s++)
            counts[s] += prototypes[instances[i].prototype].count[s];
}

/* Spaces the placed scene shares with the prototypes (parametric or local
 * to a level; for the runtime also the levels' vertices and the patches'
 * control points, placed as they are read): their indices are left as
 * they are. */
static int shared_space(int s, int runtime)
{
    if (runtime && (s == SW_SPACE_LEVEL_VERTICES || s == SW_SPACE_PART_LEVEL_VERTICES ||
                    s == SW_SPACE_CONTROL))
        return 1;
    return s == SW_SPACE_TRIM_LOOPS || s == SW_SPACE_TRIM_CURVES || s == SW_SPACE_TRIM_DATA ||
           s == SW_SPACE_TRIM_MASKS || s == SW_SPACE_LEVEL_INDICES || s == SW_SPACE_LEVEL_CHAINS ||
           s == SW_SPACE_LEVEL_CHAIN_POINTS || s == SW_SPACE_PART_LEVEL_INDICES;
}

/* The arrays of the placed scene, each n records of size bytes. */
enum { A_META, A_SEAM, A_LEVELS, A_PARTS, A_TRANSFORMS, A_PATCHES, A_CONTROL, A_ADJACENCY,
       A_SURFACES, A_DOMAINS, A_VERTICES, A_SLOTS, A_LOOPS, A_EDGES, A_COLLAPSES, A_SLOT_REFS,
       A_SURFACE_LOOPS, A_LEVEL_RECORDS, A_SURFACE_LEVELS, A_LEVEL_VERTICES, A_SUPERS,
       A_MEMBERS, A_SUPER_OF, A_PART_LEVELS, A_PIECE_LEVELS, A_PIECE_OF, A_PL_VERTICES,
       A_STORED_SURFACE, A_COUNT };

static void array_sizes(const uint64_t c[SW_SPACE_COUNT], int runtime, uint64_t n[A_COUNT],
                        uint64_t size[A_COUNT])
{
    const uint64_t surfaces = c[SW_SPACE_SURFACES];
    const uint64_t counts[A_COUNT] = {
        1, 1, 1, c[SW_SPACE_PARTS], c[SW_SPACE_PARTS], c[SW_SPACE_PATCHES], c[SW_SPACE_CONTROL],
        c[SW_SPACE_ADJACENCY], surfaces, c[SW_SPACE_PATCHES],
        c[SW_SPACE_SEAM_ORIGINALS] + c[SW_SPACE_SEAM_COLLAPSES], c[SW_SPACE_SEAM_SLOTS],
        c[SW_SPACE_SEAM_LOOPS], c[SW_SPACE_SEAM_EDGES], c[SW_SPACE_SEAM_COLLAPSES],
        c[SW_SPACE_SEAM_SLOT_REFS], surfaces + 1, c[SW_SPACE_LEVELS], surfaces + 1,
        c[SW_SPACE_LEVEL_VERTICES], c[SW_SPACE_SUPERS], c[SW_SPACE_SUPER_MEMBERS], surfaces,
        c[SW_SPACE_PART_LEVELS], c[SW_SPACE_PIECES] + 1, surfaces, c[SW_SPACE_PART_LEVEL_VERTICES],
        surfaces };
    const uint64_t bytes[A_COUNT] = {
        sizeof(sw_pack_meta), sizeof(sw_pack_seam), sizeof(sw_pack_levels), sizeof(sw_pack_part),
        16 * sizeof(float), sizeof(sw_pack_patch), 4 * sizeof(float), sizeof(sw_pack_adjacency),
        sizeof(sw_pack_surface), sizeof(sw_pack_patch_domain), sizeof(sw_seam_vertex),
        sizeof(sw_seam_slot), sizeof(sw_seam_loop), sizeof(sw_seam_edge),
        sizeof(sw_seam_collapse), sizeof(uint32_t), sizeof(uint32_t), sizeof(sw_level),
        sizeof(uint32_t), sizeof(sw_level_vertex), sizeof(sw_super_surface), sizeof(uint32_t),
        sizeof(uint32_t), sizeof(sw_part_level), sizeof(uint32_t), sizeof(uint32_t),
        sizeof(sw_level_vertex), sizeof(uint32_t) };
    for (int a = 0; a < A_COUNT; a++)
        n[a] = counts[a], size[a] = bytes[a];
    /* The runtime's: the levels' vertices, the static levels' records, the
     * patches' domains and control points shared (a surface's stored one
     * named instead), and what the walk never reads (the seam edges, the
     * patches' adjacency, the super-surfaces) left out; the tools' name no
     * stored surface. */
    if (runtime)
        n[A_LEVEL_VERTICES] = 0, n[A_PL_VERTICES] = 0, n[A_CONTROL] = 0, n[A_EDGES] = 0,
        n[A_ADJACENCY] = 0, n[A_LEVEL_RECORDS] = 0, n[A_SURFACE_LEVELS] = 0, n[A_DOMAINS] = 0,
        n[A_SUPERS] = 0, n[A_MEMBERS] = 0, n[A_SUPER_OF] = 0;
    else
        n[A_STORED_SURFACE] = 0;
}

/* The seam arrays a placed scene leaves to the walk's fronts
 * (sw_seam_fronts.h: per instance, they read the prototypes' graphs): the
 * vertices, slots, collapses and slot references; its loops stay. */
static int left_to_fronts(int a)
{
    return a == A_VERTICES || a == A_SLOTS || a == A_COLLAPSES || a == A_SLOT_REFS;
}

static uint64_t expand_bytes(const uint64_t counts[SW_SPACE_COUNT], int runtime, int seam_left)
{
    uint64_t n[A_COUNT], size[A_COUNT], total = 0;
    array_sizes(counts, runtime, n, size);
    for (int a = 0; seam_left && a < A_COUNT; a++)
        n[a] = left_to_fronts(a) ? 0 : n[a];
    for (int a = 0; a < A_COUNT; a++)
        total += sw_arena_worst_case(n[a] * size[a] + 1, 64);
    return total;
}

uint64_t sw_pack_expand_bytes(const uint64_t counts[SW_SPACE_COUNT])
{
    return expand_bytes(counts, 0, 0);
}

uint64_t sw_pack_expand_shared_bytes(const uint64_t counts[SW_SPACE_COUNT])
{
    return expand_bytes(counts, 1, 0);
}

/* 1 when the walk's fronts read a placed pack's seams per instance, so
 * its placed scene leaves them out. */
static int seams_left(int graph, const sw_walk_placed *placed)
{
    int each = 0;
    if (graph)
        sw_seam_fronts_bytes(placed->prototypes, placed->prototype_count, placed->instances,
                             placed->instance_count, &each);
    return each;
}

uint64_t sw_pack_expand_runtime_bytes(int graph, const sw_walk_placed *placed)
{
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(placed->prototypes, placed->instances, placed->instance_count, counts);
    return expand_bytes(counts, 1, seams_left(graph, placed));
}

uint64_t sw_pack_instanced_runtime_bytes(const sw_seam_graph *stored,
                                         const sw_pack_surface *surfaces,
                                         const sw_walk_placed *placed)
{
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(placed->prototypes, placed->instances, placed->instance_count, counts);
    if (counts[SW_SPACE_PATCHES] > UINT32_MAX)
        return UINT64_MAX;
    uint64_t walk = stored ? sw_walk_arena_bytes_placed(stored, surfaces, placed) : 0;
    uint64_t bytes = sw_pack_runtime_bytes(walk);
    uint64_t expand = sw_pack_expand_runtime_bytes(stored != NULL, placed);
    return bytes > UINT64_MAX - expand ? UINT64_MAX : bytes + expand;
}

uint64_t sw_pack_runtime_bytes_of(const sw_pack *pack)
{
    const sw_seam_graph *g = pack->seam_header ? &pack->seam : NULL;
    if (!pack->instances)
        return sw_pack_runtime_bytes(g ? sw_walk_arena_bytes(g, pack->surfaces) : 0);
    const sw_walk_placed placed = { pack->prototypes, pack->prototype_count, pack->instances,
                                    pack->instance_count, pack->patches };
    return sw_pack_instanced_runtime_bytes(g, pack->surfaces, &placed);
}

void sw_pack_runtime_pools(const sw_pack *pack, sw_runtime_pools *out)
{
    const sw_seam_graph *g = pack->seam_header ? &pack->seam : NULL;
    if (!pack->instances) {
        out->alignment = SW_PACK_ALIGN;
        out->placed = 0;
        sw_walk_pools(g, pack->surfaces, out->walk);
        return;
    }
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, counts);
    out->alignment = SW_PACK_ALIGN;
    const sw_walk_placed placed = { pack->prototypes, pack->prototype_count, pack->instances,
                                    pack->instance_count, pack->patches };
    out->placed = sw_pack_expand_runtime_bytes(g != NULL, &placed);
    if (g)
        sw_walk_pools_placed(g, pack->surfaces, &placed, out->walk);
    else
        memset(out->walk, 0, sizeof out->walk);
}

int sw_runtime_pool_list(const sw_runtime_pools *p, const char *names[SW_RUNTIME_POOL_COUNT],
                         uint64_t bytes[SW_RUNTIME_POOL_COUNT])
{
    const char *fixed[2] = { "alignment", "placed scene" };
    const uint64_t sizes[2] = { p->alignment, p->placed };
    int n = 0;
    for (int i = 0; i < 2; i++)
        names[n] = fixed[i], bytes[n++] = sizes[i];
    for (int i = 0; i < SW_WALK_POOL_COUNT; i++)
        names[n] = sw_walk_pool_names[i], bytes[n++] = p->walk[i];
    return n;
}

/* The placed scene's arrays, taken from the arena. */
typedef struct placed {
    void *a[A_COUNT];
    uint64_t n[A_COUNT];
    uint64_t at[SW_SPACE_COUNT];   /* records written so far per space */
    int runtime;                   /* the runtime's (array_sizes says what that leaves out) */
    int seam_left;                 /* the seams left to the walk's fronts (left_to_fronts) */
} placed;

static sw_status take_arrays(placed *d, const uint64_t counts[SW_SPACE_COUNT], sw_arena *arena,
                             sw_error *err)
{
    uint64_t size[A_COUNT];
    array_sizes(counts, d->runtime, d->n, size);
    for (int a = 0; a < A_COUNT; a++) {
        uint64_t n = d->seam_left && left_to_fronts(a) ? 0 : d->n[a];
        d->a[a] = sw_arena_alloc(arena, (size_t)(n * size[a] + 1), 64);
        if (!d->a[a])
            return sw_error_set(err, SW_ERR_NO_MEMORY, "the placed scene: the arena is short "
                                "(%llu bytes needed)",
                                (unsigned long long)expand_bytes(counts, d->runtime,
                                                                 d->seam_left));
    }
    return SW_OK;
}

int sw_instance_moves(const float *t)
{
    int moved = 0;
    for (int k = 0; t && k < 16; k++)
        moved |= t[k] != (k % 5 == 0 ? 1.0f : 0.0f);
    return moved;
}

void sw_pack_level_vertices(const sw_pack *pack, uint32_t s, const sw_level *rec,
                            sw_level_vertex *out)
{
    const sw_level_vertex *src = pack->levels.vertices + rec->first_vertex;
    const float *t = pack->level_vertices_local
                         ? pack->part_transforms + 16 * (size_t)pack->surfaces[s].part : NULL;
    const sw_pack_move place = { .transform = sw_instance_moves(t) ? t : NULL,
                                 .scale = sw_instance_moves(t) ? sw_instance_scale(t) : 1 };
    sw_pack_move_level_vertices(&place, src, rec->vertex_count, out);
}

void sw_pack_surface_levels(const sw_pack *pack, uint32_t s, uint32_t *first, uint32_t *end)
{
    const uint32_t *by_surface = pack->stored_surface ? pack->stored_surface_levels
                                                      : pack->levels.surface_levels;
    *first = *end = 0;
    if (!by_surface || s >= pack->levels.surface_count)
        return;
    uint32_t at = pack->stored_surface ? pack->stored_surface[s] : s;
    *first = by_surface[at], *end = by_surface[at + 1];
}

const sw_pack_patch_domain *sw_pack_domain_of(const sw_pack *pack, uint32_t s, uint32_t i)
{
    if (!pack->stored_surface)
        return pack->patch_domains ? &pack->patch_domains[pack->surfaces[s].first_patch + i]
                                   : NULL;
    const sw_pack_surface *own = &pack->stored_surfaces[pack->stored_surface[s]];
    return &pack->stored_domains[own->first_patch + i];
}

sw_level sw_pack_level(const sw_pack *pack, uint32_t s, uint32_t k)
{
    sw_level rec = pack->levels.levels[k];
    if (!pack->stored_surface)
        return rec;
    const float *t = pack->part_transforms + 16 * (size_t)pack->surfaces[s].part;
    if (sw_instance_moves(t)) {   /* sw_pack_move_levels' arithmetic: the same floats */
        double scale = sw_instance_scale(t);
        rec.error = (float)(rec.error * scale);
        rec.made_bound = (float)(rec.made_bound * scale);
    }
    rec.surface = s;
    return rec;
}

const float *sw_pack_patch_control(const sw_pack *pack, uint32_t i, float *room)
{
    const sw_pack_patch *p = &pack->patches[i];
    const float *src = pack->control + 4 * (size_t)p->first_control;
    if (!pack->control_local)
        return src;
    const float *t = pack->part_transforms + 16 * (size_t)p->part;
    if (!sw_instance_moves(t))
        return src;
    const sw_pack_move place = { .transform = t };   /* points: no length to scale */
    sw_pack_move_control(&place, src, (uint32_t)(p->degree_u + 1) * (p->degree_v + 1), room);
    return room;
}

/* The move of prototype p to where instance inst's copy goes. */
static sw_pack_move move_for(const sw_pack *pack, const placed *d, const sw_pack_prototype *p,
                             const sw_pack_instance *inst)
{
    int moved = sw_instance_moves(inst->transform);
    sw_pack_move m = { .src_originals = pack->seam.original_count,
                       .dst_originals = (uint32_t)d->n[A_VERTICES] -
                                        (uint32_t)d->n[A_COLLAPSES],
                       .transform = moved ? inst->transform : NULL,
                       .scale = moved ? sw_instance_scale(inst->transform) : 1 };
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        m.shift[s] = shared_space(s, d->runtime) ? 0
                                                     : (int64_t)d->at[s] - (int64_t)p->first[s];
    return m;
}

void sw_instance_part_name(const char *instance, const char *part, char out[56])
{
    char name[56];
    if (part[0])
        snprintf(name, sizeof name, "%.27s/%.27s", instance, part);
    else
        snprintf(name, sizeof name, "%.55s", instance);
    memcpy(out, name, sizeof name);
}

static void name_parts(const sw_pack_instance *inst, const sw_pack_part *from, uint32_t n,
                       sw_pack_part *to, float *transforms)
{
    for (uint32_t k = 0; k < n; k++) {
        memcpy(to[k].color, inst->color, sizeof to[k].color);
        sw_instance_part_name(inst->name, from[k].name, to[k].name);
        memcpy(&transforms[16 * (size_t)k], inst->transform, 16 * sizeof(float));
    }
}

#define AT(d, array, type, space) ((type *)(d)->a[array] + (d)->at[space])

static void place_model(const sw_pack *pack, placed *d, const sw_pack_prototype *p,
                        const sw_pack_instance *inst, const sw_pack_move *m)
{
    uint32_t parts = p->count[SW_SPACE_PARTS];
    sw_pack_part *to = AT(d, A_PARTS, sw_pack_part, SW_SPACE_PARTS);
    sw_pack_move_parts(m, &pack->parts[p->first[SW_SPACE_PARTS]], parts, to);
    name_parts(inst, &pack->parts[p->first[SW_SPACE_PARTS]], parts, to,
               (float *)d->a[A_TRANSFORMS] + 16 * d->at[SW_SPACE_PARTS]);
    if (!d->runtime)
        sw_pack_move_control(m, &pack->control[4 * (size_t)p->first[SW_SPACE_CONTROL]],
                             p->count[SW_SPACE_CONTROL],
                             (float *)d->a[A_CONTROL] + 4 * d->at[SW_SPACE_CONTROL]);
    /* The runtime reads no second-derivative bound: the boxes alone. */
    sw_pack_move_patches(m, &pack->patches[p->first[SW_SPACE_PATCHES]],
                         p->count[SW_SPACE_PATCHES], pack->control, !d->runtime,
                         AT(d, A_PATCHES, sw_pack_patch, SW_SPACE_PATCHES));
    if (pack->adjacency && d->n[A_ADJACENCY])
        sw_pack_move_adjacency(m, pack->adjacency + p->first[SW_SPACE_ADJACENCY],
                               p->count[SW_SPACE_ADJACENCY],
                               AT(d, A_ADJACENCY, sw_pack_adjacency, SW_SPACE_ADJACENCY));
    if (!pack->surfaces)
        return;
    uint32_t *stored = d->n[A_STORED_SURFACE] ? AT(d, A_STORED_SURFACE, uint32_t, SW_SPACE_SURFACES)
                                               : NULL;
    for (uint32_t s = 0; stored && s < p->count[SW_SPACE_SURFACES]; s++)
        stored[s] = p->first[SW_SPACE_SURFACES] + s;
    sw_pack_move_surfaces(m, &pack->surfaces[p->first[SW_SPACE_SURFACES]],
                          p->count[SW_SPACE_SURFACES],
                          AT(d, A_SURFACES, sw_pack_surface, SW_SPACE_SURFACES));
    if (!d->runtime)   /* the runtime reads the prototypes': sw_pack_domain_of */
        sw_pack_move_patch_domains(m, &pack->patch_domains[p->first[SW_SPACE_PATCHES]],
                                   p->count[SW_SPACE_PATCHES],
                                   AT(d, A_DOMAINS, sw_pack_patch_domain, SW_SPACE_PATCHES));
}

static void place_seam(const sw_pack *pack, placed *d, const sw_pack_prototype *p,
                       const sw_pack_move *m)
{
    const sw_seam_graph *g = &pack->seam;
    sw_pack_move_seam_loops(m, g->loops + p->first[SW_SPACE_SEAM_LOOPS],
                            p->count[SW_SPACE_SEAM_LOOPS],
                            AT(d, A_LOOPS, sw_seam_loop, SW_SPACE_SEAM_LOOPS));
    sw_pack_move_indices(m, SW_SPACE_SEAM_LOOPS, g->surface_loops + p->first[SW_SPACE_SURFACES],
                         p->count[SW_SPACE_SURFACES],
                         AT(d, A_SURFACE_LOOPS, uint32_t, SW_SPACE_SURFACES));
    if (d->seam_left)
        return;
    sw_seam_vertex *v = d->a[A_VERTICES];
    uint64_t originals = d->n[A_VERTICES] - d->n[A_COLLAPSES];
    sw_pack_move_seam_vertices(m, &g->vertices[p->first[SW_SPACE_SEAM_ORIGINALS]],
                               p->count[SW_SPACE_SEAM_ORIGINALS],
                               v + d->at[SW_SPACE_SEAM_ORIGINALS]);
    sw_pack_move_seam_vertices(m, &g->vertices[g->original_count + p->first[SW_SPACE_SEAM_COLLAPSES]],
                               p->count[SW_SPACE_SEAM_COLLAPSES],
                               v + originals + d->at[SW_SPACE_SEAM_COLLAPSES]);
    sw_pack_move_seam_slots(m, g->slots + p->first[SW_SPACE_SEAM_SLOTS],
                            p->count[SW_SPACE_SEAM_SLOTS],
                            AT(d, A_SLOTS, sw_seam_slot, SW_SPACE_SEAM_SLOTS));
    if (d->n[A_EDGES])
        sw_pack_move_seam_edges(m, g->edges + p->first[SW_SPACE_SEAM_EDGES],
                                p->count[SW_SPACE_SEAM_EDGES],
                                AT(d, A_EDGES, sw_seam_edge, SW_SPACE_SEAM_EDGES));
    sw_pack_move_seam_collapses(m, g->collapses + p->first[SW_SPACE_SEAM_COLLAPSES],
                                p->count[SW_SPACE_SEAM_COLLAPSES],
                                AT(d, A_COLLAPSES, sw_seam_collapse, SW_SPACE_SEAM_COLLAPSES));
    sw_pack_move_indices(m, SW_SPACE_SEAM_SLOTS, g->slot_refs + p->first[SW_SPACE_SEAM_SLOT_REFS],
                         p->count[SW_SPACE_SEAM_SLOT_REFS],
                         AT(d, A_SLOT_REFS, uint32_t, SW_SPACE_SEAM_SLOT_REFS));
}

static void place_levels(const sw_pack *pack, placed *d, const sw_pack_prototype *p,
                         const sw_pack_move *m)
{
    const sw_levels *l = &pack->levels;
    if (l->levels && !d->runtime) {   /* the runtime shares them: sw_pack_level */
        sw_pack_move_levels(m, l->levels + p->first[SW_SPACE_LEVELS], p->count[SW_SPACE_LEVELS],
                            AT(d, A_LEVEL_RECORDS, sw_level, SW_SPACE_LEVELS));
        sw_pack_move_indices(m, SW_SPACE_LEVELS, l->surface_levels + p->first[SW_SPACE_SURFACES],
                             p->count[SW_SPACE_SURFACES],
                             AT(d, A_SURFACE_LEVELS, uint32_t, SW_SPACE_SURFACES));
        sw_pack_move_level_vertices(m, l->vertices + p->first[SW_SPACE_LEVEL_VERTICES],
                                    p->count[SW_SPACE_LEVEL_VERTICES],
                                    AT(d, A_LEVEL_VERTICES, sw_level_vertex,
                                       SW_SPACE_LEVEL_VERTICES));
    }
    const sw_supers *su = &pack->supers;
    if (su->supers && !d->runtime) {
        sw_pack_move_supers(m, su->supers + p->first[SW_SPACE_SUPERS], p->count[SW_SPACE_SUPERS],
                            AT(d, A_SUPERS, sw_super_surface, SW_SPACE_SUPERS));
        sw_pack_move_indices(m, SW_SPACE_SURFACES, su->members + p->first[SW_SPACE_SUPER_MEMBERS],
                             p->count[SW_SPACE_SUPER_MEMBERS],
                             AT(d, A_MEMBERS, uint32_t, SW_SPACE_SUPER_MEMBERS));
        sw_pack_move_indices(m, SW_SPACE_SUPERS, su->super_of + p->first[SW_SPACE_SURFACES],
                             p->count[SW_SPACE_SURFACES],
                             AT(d, A_SUPER_OF, uint32_t, SW_SPACE_SURFACES));
    }
    const sw_part_levels *pl = &pack->part_levels;
    if (pl->levels) {
        sw_pack_move_part_levels(m, pl->levels + p->first[SW_SPACE_PART_LEVELS],
                                 p->count[SW_SPACE_PART_LEVELS],
                                 AT(d, A_PART_LEVELS, sw_part_level, SW_SPACE_PART_LEVELS));
        sw_pack_move_indices(m, SW_SPACE_PART_LEVELS, pl->piece_levels + p->first[SW_SPACE_PIECES],
                             p->count[SW_SPACE_PIECES],
                             AT(d, A_PIECE_LEVELS, uint32_t, SW_SPACE_PIECES));
        sw_pack_move_indices(m, SW_SPACE_PIECES, pl->piece_of + p->first[SW_SPACE_SURFACES],
                             p->count[SW_SPACE_SURFACES],
                             AT(d, A_PIECE_OF, uint32_t, SW_SPACE_SURFACES));
        if (!d->runtime)
            sw_pack_move_level_vertices(m, pl->vertices + p->first[SW_SPACE_PART_LEVEL_VERTICES],
                                        p->count[SW_SPACE_PART_LEVEL_VERTICES],
                                        AT(d, A_PL_VERTICES, sw_level_vertex,
                                           SW_SPACE_PART_LEVEL_VERTICES));
    }
}

/* The headers of the placed scene: its counts, and its box. */
static void fill_headers(const sw_pack *pack, placed *d, float tolerance)
{
    sw_pack_meta *meta = d->a[A_META];
    *meta = *pack->meta;
    meta->part_count = (uint32_t)d->n[A_PARTS];
    meta->patch_count = (uint32_t)d->n[A_PATCHES];
    meta->control_count = d->runtime ? pack->meta->control_count : (uint32_t)d->n[A_CONTROL];
    meta->adjacency_count = (uint32_t)d->n[A_ADJACENCY];
    sw_pack_patches_box(d->a[A_PATCHES], 0, meta->patch_count, meta->box_min, meta->box_max);
    if (pack->seam_header) {
        sw_pack_seam *s = d->a[A_SEAM];
        *s = *pack->seam_header;
        s->original_count = (uint32_t)(d->n[A_VERTICES] - d->n[A_COLLAPSES]);
        s->vertex_count = (uint32_t)d->n[A_VERTICES];
        s->slot_count = (uint32_t)d->n[A_SLOTS];
        s->loop_count = (uint32_t)d->n[A_LOOPS];
        s->edge_count = (uint32_t)d->n[A_EDGES];
        s->collapse_count = (uint32_t)d->n[A_COLLAPSES];
        s->slot_ref_count = (uint32_t)d->n[A_SLOT_REFS];
        s->surface_count = (uint32_t)d->n[A_SURFACES];
        s->tolerance = tolerance;
    }
    if (pack->levels_header) {
        sw_pack_levels *l = d->a[A_LEVELS];
        *l = *pack->levels_header;
        l->level_count = d->runtime ? pack->levels.level_count : (uint32_t)d->n[A_LEVEL_RECORDS];
        l->vertex_count = d->runtime ? pack->levels.vertex_count
                                          : (uint32_t)d->n[A_LEVEL_VERTICES];
        l->surface_count = (uint32_t)d->n[A_SURFACES];
    }
}

/* The view of the placed arrays, over the pack's shared ones. */
static void fill_view(const sw_pack *pack, const placed *d, sw_pack *out)
{
    *out = *pack;
    out->prototypes = NULL, out->prototype_count = 0;
    out->instances = NULL, out->instance_count = 0;
    out->meta = d->a[A_META];
    out->parts = d->a[A_PARTS];
    out->part_transforms = d->a[A_TRANSFORMS];
    out->level_vertices_local = d->runtime;
    out->patches = d->a[A_PATCHES];
    out->control = d->runtime ? pack->control : d->a[A_CONTROL];
    out->control_local = d->runtime;
    if (d->runtime && pack->surfaces) {
        out->stored_surface = d->a[A_STORED_SURFACE];
        out->stored_surface_levels = pack->levels.surface_levels;
        out->stored_surfaces = pack->surfaces;
        out->stored_domains = pack->patch_domains;
    }
    out->adjacency = d->n[A_ADJACENCY] ? d->a[A_ADJACENCY] : NULL;
    uint32_t surfaces = (uint32_t)d->n[A_SURFACES];
    if (pack->surfaces) {
        out->surfaces = d->a[A_SURFACES];
        out->surface_count = surfaces;
        out->patch_domains = d->runtime ? NULL : d->a[A_DOMAINS];   /* sw_pack_domain_of */
    }
    if (pack->seam_header) {
        const sw_pack_seam *h = d->a[A_SEAM];
        out->seam_header = h;
        int left = d->seam_left;
        out->seam = (sw_seam_graph){
            .vertices = left ? NULL : d->a[A_VERTICES], .slots = left ? NULL : d->a[A_SLOTS],
            .loops = d->a[A_LOOPS], .edges = h->edge_count ? d->a[A_EDGES] : NULL,
            .collapses = left ? NULL : d->a[A_COLLAPSES],
            .slot_refs = left ? NULL : d->a[A_SLOT_REFS],
            .surface_loops = d->a[A_SURFACE_LOOPS], .vertex_count = h->vertex_count,
            .original_count = h->original_count, .slot_count = h->slot_count,
            .loop_count = h->loop_count, .edge_count = h->edge_count,
            .collapse_count = h->collapse_count, .slot_ref_count = h->slot_ref_count,
            .surface_count = h->surface_count, .tolerance = h->tolerance };
    }
    if (pack->levels_header) {
        out->levels_header = d->a[A_LEVELS];
        /* The runtime's share the stored records: sw_pack_surface_levels. */
        out->levels.levels = d->runtime ? pack->levels.levels : d->a[A_LEVEL_RECORDS];
        out->levels.surface_levels = d->runtime ? NULL : d->a[A_SURFACE_LEVELS];
        out->levels.vertices = d->runtime ? pack->levels.vertices : d->a[A_LEVEL_VERTICES];
        out->levels.level_count = d->runtime ? pack->levels.level_count
                                             : (uint32_t)d->n[A_LEVEL_RECORDS];
        out->levels.vertex_count = d->runtime ? pack->levels.vertex_count
                                                   : (uint32_t)d->n[A_LEVEL_VERTICES];
        out->levels.surface_count = surfaces;
    }
    if (d->runtime)   /* the walk reads no super-surface */
        out->supers = (sw_supers){ 0 };
    else if (pack->supers.supers)
        out->supers = (sw_supers){ .supers = d->a[A_SUPERS], .members = d->a[A_MEMBERS],
                                   .super_of = d->a[A_SUPER_OF],
                                   .super_count = (uint32_t)d->n[A_SUPERS],
                                   .surface_count = surfaces };
    if (pack->part_levels.levels) {
        out->part_levels.levels = d->a[A_PART_LEVELS];
        out->part_levels.piece_levels = d->a[A_PIECE_LEVELS];
        out->part_levels.piece_of = d->a[A_PIECE_OF];
        out->part_levels.vertices = d->runtime ? pack->part_levels.vertices
                                                    : d->a[A_PL_VERTICES];
        out->part_levels.level_count = (uint32_t)d->n[A_PART_LEVELS];
        out->part_levels.vertex_count = d->runtime ? pack->part_levels.vertex_count
                                                        : (uint32_t)d->n[A_PL_VERTICES];
        out->part_levels.piece_count = (uint32_t)(d->n[A_PIECE_LEVELS] - 1);
        out->part_levels.surface_count = surfaces;
    }
}

static sw_status expand(const sw_pack *pack, int runtime, sw_arena *arena, sw_pack *out,
                        sw_error *err)
{
    if (!pack->instances) {
        *out = *pack;
        return SW_OK;
    }
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, counts);
    const sw_walk_placed wp = { pack->prototypes, pack->prototype_count, pack->instances,
                                pack->instance_count, pack->patches };
    placed d = { .runtime = runtime,
                 .seam_left = runtime && seams_left(pack->seam_header != NULL, &wp) };
    sw_status st = take_arrays(&d, counts, arena, err);
    if (st != SW_OK)
        return st;
    float tolerance = 0;
    for (uint32_t i = 0; i < pack->instance_count; i++) {
        const sw_pack_instance *inst = &pack->instances[i];
        const sw_pack_prototype *p = &pack->prototypes[inst->prototype];
        sw_pack_move m = move_for(pack, &d, p, inst);
        place_model(pack, &d, p, inst, &m);
        if (pack->seam_header)
            place_seam(pack, &d, p, &m);
        place_levels(pack, &d, p, &m);
        float t = (float)(p->seam_tolerance * m.scale);
        tolerance = t > tolerance ? t : tolerance;
        for (int s = 0; s < SW_SPACE_COUNT; s++)
            d.at[s] += shared_space(s, runtime) ? 0 : p->count[s];
    }
    ((uint32_t *)d.a[A_SURFACE_LOOPS])[d.n[A_SURFACES]] = (uint32_t)d.n[A_LOOPS];
    if (!runtime)
        ((uint32_t *)d.a[A_SURFACE_LEVELS])[d.n[A_SURFACES]] = (uint32_t)d.n[A_LEVEL_RECORDS];
    ((uint32_t *)d.a[A_PIECE_LEVELS])[d.n[A_PIECE_LEVELS] - 1] = (uint32_t)d.n[A_PART_LEVELS];
    fill_headers(pack, &d, tolerance);
    fill_view(pack, &d, out);
    return SW_OK;
}

sw_status sw_pack_expand(const sw_pack *pack, sw_arena *arena, sw_pack *out, sw_error *err)
{
    return expand(pack, 0, arena, out, err);
}

sw_status sw_pack_expand_shared(const sw_pack *pack, sw_arena *arena, sw_pack *out,
                                sw_error *err)
{
    return expand(pack, 1, arena, out, err);
}
