/* SPDX-License-Identifier: MIT */
#include "sw_pack_merge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_pack_move.h"

/* The merged arrays, by kind, with their record sizes and counts. */
enum { M_PARTS, M_PATCHES, M_CONTROL, M_ADJACENCY, M_SURFACES, M_TRIM_LOOPS, M_TRIM_CURVES,
       M_TRIM_DATA, M_DOMAINS, M_MASKS, M_VERTICES, M_SLOTS, M_LOOPS, M_EDGES, M_COLLAPSES,
       M_SLOT_REFS, M_SURFACE_LOOPS, M_LEVELS, M_SURFACE_LEVELS, M_LEVEL_VERTICES,
       M_LEVEL_INDICES, M_CHAINS, M_CHAIN_POINTS, M_SUPERS, M_MEMBERS, M_SUPER_OF,
       M_PART_LEVELS, M_PIECE_LEVELS, M_PIECE_OF, M_PL_VERTICES, M_PL_INDICES, M_PROTOTYPES,
       M_NOTES, M_COUNT };
_Static_assert(M_COUNT <= 40, "sw_pack_merged.arrays");

/* Each input has the groups the first has. */
static sw_status check_inputs(const sw_pack *packs, uint32_t count, sw_error *err)
{
    if (count == 0)
        return sw_error_set(err, SW_ERR_ARG, "merge: no pack to merge");
    for (uint32_t k = 0; k < count; k++) {
        const sw_pack *p = &packs[k], *f = &packs[0];
        if (p->instances)
            return sw_error_set(err, SW_ERR_FORMAT, "merge: input %u places parts of its own "
                                "(merge the packs it was made from instead)", (unsigned)k);
        const struct { const char *what; int here, there; } groups[] = {
            { "trimmed surfaces", !!p->surfaces, !!f->surfaces },
            { "a Seam Graph", !!p->seam_header, !!f->seam_header },
            { "static levels", !!p->levels_header, !!f->levels_header },
            { "super-surfaces", !!p->supers.supers, !!f->supers.supers },
            { "part levels", !!p->part_levels.levels, !!f->part_levels.levels } };
        for (size_t g = 0; g < sizeof groups / sizeof *groups; g++)
            if (groups[g].here != groups[g].there)
                return sw_error_set(err, SW_ERR_FORMAT, "merge: input %u %s %s, input 0 %s",
                                    (unsigned)k, groups[g].here ? "has" : "lacks",
                                    groups[g].what, groups[g].there ? "has" : "does not");
        if (p->meta->units != f->meta->units)
            return sw_error_set(err, SW_ERR_FORMAT, "merge: input %u is in units %u, input 0 in "
                                "%u", (unsigned)k, (unsigned)p->meta->units,
                                (unsigned)f->meta->units);
    }
    return SW_OK;
}

static sw_status take(sw_pack_merged *m, int a, uint64_t n, size_t size, sw_error *err)
{
    m->arrays[a] = calloc((size_t)n + 1, size);
    return m->arrays[a] ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "merge: out of memory");
}

static sw_status take_all(sw_pack_merged *m, const uint64_t t[SW_SPACE_COUNT], uint32_t count,
                          uint64_t notes, sw_error *err)
{
    const uint64_t s = t[SW_SPACE_SURFACES];
    const struct { uint64_t n; size_t size; } want[M_COUNT] = {
        { t[SW_SPACE_PARTS], sizeof(sw_pack_part) }, { t[SW_SPACE_PATCHES], sizeof(sw_pack_patch) },
        { t[SW_SPACE_CONTROL], 4 * sizeof(float) },
        { t[SW_SPACE_ADJACENCY], sizeof(sw_pack_adjacency) }, { s, sizeof(sw_pack_surface) },
        { t[SW_SPACE_TRIM_LOOPS], sizeof(sw_pack_trim_loop) },
        { t[SW_SPACE_TRIM_CURVES], sizeof(sw_pack_trim_curve) },
        { t[SW_SPACE_TRIM_DATA], sizeof(float) },
        { t[SW_SPACE_PATCHES], sizeof(sw_pack_patch_domain) },
        { t[SW_SPACE_TRIM_MASKS], sizeof(sw_pack_trim_mask) },
        { t[SW_SPACE_SEAM_ORIGINALS] + t[SW_SPACE_SEAM_COLLAPSES], sizeof(sw_seam_vertex) },
        { t[SW_SPACE_SEAM_SLOTS], sizeof(sw_seam_slot) },
        { t[SW_SPACE_SEAM_LOOPS], sizeof(sw_seam_loop) },
        { t[SW_SPACE_SEAM_EDGES], sizeof(sw_seam_edge) },
        { t[SW_SPACE_SEAM_COLLAPSES], sizeof(sw_seam_collapse) },
        { t[SW_SPACE_SEAM_SLOT_REFS], sizeof(uint32_t) }, { s + 1, sizeof(uint32_t) },
        { t[SW_SPACE_LEVELS], sizeof(sw_level) }, { s + 1, sizeof(uint32_t) },
        { t[SW_SPACE_LEVEL_VERTICES], sizeof(sw_level_vertex) },
        { t[SW_SPACE_LEVEL_INDICES], sizeof(uint16_t) },
        { t[SW_SPACE_LEVEL_CHAINS], sizeof(sw_level_chain) },
        { t[SW_SPACE_LEVEL_CHAIN_POINTS], sizeof(sw_strip_point) },
        { t[SW_SPACE_SUPERS], sizeof(sw_super_surface) },
        { t[SW_SPACE_SUPER_MEMBERS], sizeof(uint32_t) }, { s, sizeof(uint32_t) },
        { t[SW_SPACE_PART_LEVELS], sizeof(sw_part_level) },
        { t[SW_SPACE_PIECES] + 1, sizeof(uint32_t) }, { s, sizeof(uint32_t) },
        { t[SW_SPACE_PART_LEVEL_VERTICES], sizeof(sw_level_vertex) },
        { t[SW_SPACE_PART_LEVEL_INDICES], sizeof(uint16_t) },
        { count, sizeof(sw_pack_prototype) }, { notes, sizeof(sw_pack_import_note) } };
    sw_status st = SW_OK;
    for (int a = 0; st == SW_OK && a < M_COUNT; a++)
        st = take(m, a, want[a].n, want[a].size, err);
    return st;
}

#define AT(m, array, type, base, space) ((type *)(m)->arrays[array] + (base)[space])

static void move_model(sw_pack_merged *m, const sw_pack *p, const sw_pack_move *mv,
                       const uint64_t *b)
{
    const sw_pack_meta *pm = p->meta;
    sw_pack_move_parts(mv, p->parts, pm->part_count, AT(m, M_PARTS, sw_pack_part, b, SW_SPACE_PARTS));
    memcpy((float *)m->arrays[M_CONTROL] + 4 * b[SW_SPACE_CONTROL], p->control,
           (size_t)pm->control_count * 4 * sizeof(float));
    sw_pack_move_patches(mv, p->patches, pm->patch_count, p->control, 1,
                         AT(m, M_PATCHES, sw_pack_patch, b, SW_SPACE_PATCHES));
    if (p->adjacency)
        sw_pack_move_adjacency(mv, p->adjacency, pm->adjacency_count,
                               AT(m, M_ADJACENCY, sw_pack_adjacency, b, SW_SPACE_ADJACENCY));
    if (!p->surfaces)
        return;
    sw_pack_move_surfaces(mv, p->surfaces, p->surface_count,
                          AT(m, M_SURFACES, sw_pack_surface, b, SW_SPACE_SURFACES));
    sw_pack_move_patch_domains(mv, p->patch_domains, pm->patch_count,
                               AT(m, M_DOMAINS, sw_pack_patch_domain, b, SW_SPACE_PATCHES));
    if (p->trim_loops)
        sw_pack_move_trim_loops(mv, p->trim_loops, p->trim_loop_count,
                                AT(m, M_TRIM_LOOPS, sw_pack_trim_loop, b, SW_SPACE_TRIM_LOOPS));
    if (p->trim_curves)
        sw_pack_move_trim_curves(mv, p->trim_curves, p->trim_curve_count,
                                 AT(m, M_TRIM_CURVES, sw_pack_trim_curve, b,
                                    SW_SPACE_TRIM_CURVES));
    if (p->trim_data)
        memcpy(AT(m, M_TRIM_DATA, float, b, SW_SPACE_TRIM_DATA), p->trim_data,
               (size_t)p->trim_data_count * sizeof(float));
    if (p->trim_masks)
        memcpy(AT(m, M_MASKS, sw_pack_trim_mask, b, SW_SPACE_TRIM_MASKS), p->trim_masks,
               (size_t)p->trim_mask_count * sizeof(sw_pack_trim_mask));
}

static void move_seam(sw_pack_merged *m, const sw_pack *p, const sw_pack_move *mv,
                      const uint64_t *b)
{
    const sw_seam_graph *g = &p->seam;
    sw_seam_vertex *v = m->arrays[M_VERTICES];
    sw_pack_move_seam_vertices(mv, g->vertices, g->original_count,
                               v + b[SW_SPACE_SEAM_ORIGINALS]);
    sw_pack_move_seam_vertices(mv, g->vertices + g->original_count, g->collapse_count,
                               v + mv->dst_originals + b[SW_SPACE_SEAM_COLLAPSES]);
    sw_pack_move_seam_slots(mv, g->slots, g->slot_count,
                            AT(m, M_SLOTS, sw_seam_slot, b, SW_SPACE_SEAM_SLOTS));
    sw_pack_move_seam_loops(mv, g->loops, g->loop_count,
                            AT(m, M_LOOPS, sw_seam_loop, b, SW_SPACE_SEAM_LOOPS));
    sw_pack_move_seam_edges(mv, g->edges, g->edge_count,
                            AT(m, M_EDGES, sw_seam_edge, b, SW_SPACE_SEAM_EDGES));
    sw_pack_move_seam_collapses(mv, g->collapses, g->collapse_count,
                                AT(m, M_COLLAPSES, sw_seam_collapse, b, SW_SPACE_SEAM_COLLAPSES));
    sw_pack_move_indices(mv, SW_SPACE_SEAM_SLOTS, g->slot_refs, g->slot_ref_count,
                         AT(m, M_SLOT_REFS, uint32_t, b, SW_SPACE_SEAM_SLOT_REFS));
    sw_pack_move_indices(mv, SW_SPACE_SEAM_LOOPS, g->surface_loops, g->surface_count,
                         AT(m, M_SURFACE_LOOPS, uint32_t, b, SW_SPACE_SURFACES));
}

static void move_levels(sw_pack_merged *m, const sw_pack *p, const sw_pack_move *mv,
                        const uint64_t *b)
{
    const sw_levels *l = &p->levels;
    if (p->levels_header) {
        sw_pack_move_levels(mv, l->levels, l->level_count,
                            AT(m, M_LEVELS, sw_level, b, SW_SPACE_LEVELS));
        sw_pack_move_indices(mv, SW_SPACE_LEVELS, l->surface_levels, l->surface_count,
                             AT(m, M_SURFACE_LEVELS, uint32_t, b, SW_SPACE_SURFACES));
        sw_pack_move_level_vertices(mv, l->vertices, l->vertex_count,
                                    AT(m, M_LEVEL_VERTICES, sw_level_vertex, b,
                                       SW_SPACE_LEVEL_VERTICES));
        memcpy(AT(m, M_LEVEL_INDICES, uint16_t, b, SW_SPACE_LEVEL_INDICES), l->indices,
               (size_t)l->index_count * sizeof(uint16_t));
        sw_pack_move_level_chains(mv, l->chains, l->chain_count,
                                  AT(m, M_CHAINS, sw_level_chain, b, SW_SPACE_LEVEL_CHAINS));
        memcpy(AT(m, M_CHAIN_POINTS, sw_strip_point, b, SW_SPACE_LEVEL_CHAIN_POINTS),
               l->chain_points, (size_t)l->chain_point_count * sizeof(sw_strip_point));
    }
    const sw_supers *su = &p->supers;
    if (su->supers) {
        sw_pack_move_supers(mv, su->supers, su->super_count,
                            AT(m, M_SUPERS, sw_super_surface, b, SW_SPACE_SUPERS));
        sw_pack_move_indices(mv, SW_SPACE_SURFACES, su->members, su->surface_count,
                             AT(m, M_MEMBERS, uint32_t, b, SW_SPACE_SUPER_MEMBERS));
        sw_pack_move_indices(mv, SW_SPACE_SUPERS, su->super_of, su->surface_count,
                             AT(m, M_SUPER_OF, uint32_t, b, SW_SPACE_SURFACES));
    }
    const sw_part_levels *pl = &p->part_levels;
    if (pl->levels) {
        sw_pack_move_part_levels(mv, pl->levels, pl->level_count,
                                 AT(m, M_PART_LEVELS, sw_part_level, b, SW_SPACE_PART_LEVELS));
        sw_pack_move_indices(mv, SW_SPACE_PART_LEVELS, pl->piece_levels, pl->piece_count,
                             AT(m, M_PIECE_LEVELS, uint32_t, b, SW_SPACE_PIECES));
        sw_pack_move_indices(mv, SW_SPACE_PIECES, pl->piece_of, pl->surface_count,
                             AT(m, M_PIECE_OF, uint32_t, b, SW_SPACE_SURFACES));
        sw_pack_move_level_vertices(mv, pl->vertices, pl->vertex_count,
                                    AT(m, M_PL_VERTICES, sw_level_vertex, b,
                                       SW_SPACE_PART_LEVEL_VERTICES));
        memcpy(AT(m, M_PL_INDICES, uint16_t, b, SW_SPACE_PART_LEVEL_INDICES), pl->indices,
               (size_t)pl->index_count * sizeof(uint16_t));
    }
}

/* The levels', clusters' and part levels' views (s: the surfaces). */
static void fill_derived(sw_pack_merged *m, const sw_pack *first, const uint64_t *t, uint32_t s)
{
    sw_pack_contents *c = &m->contents;
    if (first->levels_header) {
        m->levels = (sw_levels){
            .levels = m->arrays[M_LEVELS], .surface_levels = m->arrays[M_SURFACE_LEVELS],
            .vertices = m->arrays[M_LEVEL_VERTICES], .indices = m->arrays[M_LEVEL_INDICES],
            .chains = m->arrays[M_CHAINS], .chain_points = m->arrays[M_CHAIN_POINTS],
            .level_count = (uint32_t)t[SW_SPACE_LEVELS],
            .vertex_count = (uint32_t)t[SW_SPACE_LEVEL_VERTICES],
            .index_count = (uint32_t)t[SW_SPACE_LEVEL_INDICES],
            .chain_count = (uint32_t)t[SW_SPACE_LEVEL_CHAINS],
            .chain_point_count = (uint32_t)t[SW_SPACE_LEVEL_CHAIN_POINTS], .surface_count = s };
        c->levels = &m->levels;
    }
    if (first->supers.supers) {
        m->supers = (sw_supers){ .supers = m->arrays[M_SUPERS], .members = m->arrays[M_MEMBERS],
                                 .super_of = m->arrays[M_SUPER_OF],
                                 .super_count = (uint32_t)t[SW_SPACE_SUPERS],
                                 .surface_count = s };
        c->supers = &m->supers;
    }
    if (first->part_levels.levels) {
        m->part_levels = (sw_part_levels){
            .levels = m->arrays[M_PART_LEVELS], .piece_levels = m->arrays[M_PIECE_LEVELS],
            .piece_of = m->arrays[M_PIECE_OF], .vertices = m->arrays[M_PL_VERTICES],
            .indices = m->arrays[M_PL_INDICES], .level_count = (uint32_t)t[SW_SPACE_PART_LEVELS],
            .vertex_count = (uint32_t)t[SW_SPACE_PART_LEVEL_VERTICES],
            .index_count = (uint32_t)t[SW_SPACE_PART_LEVEL_INDICES],
            .piece_count = (uint32_t)t[SW_SPACE_PIECES], .surface_count = s };
        c->part_levels = &m->part_levels;
    }
}

/* The views of the merged arrays, as the writer takes them. */
static void fill_contents(sw_pack_merged *m, const sw_pack *first, const uint64_t *t,
                          uint32_t count, float tolerance)
{
    sw_pack_contents *c = &m->contents;
    uint32_t s = (uint32_t)t[SW_SPACE_SURFACES];
    c->meta = m->meta;
    c->parts = m->arrays[M_PARTS];
    c->patches = m->arrays[M_PATCHES];
    c->control = m->arrays[M_CONTROL];
    c->adjacency = m->arrays[M_ADJACENCY];
    if (first->surfaces) {
        c->surfaces = m->arrays[M_SURFACES], c->surface_count = s;
        c->trim_loops = m->arrays[M_TRIM_LOOPS];
        c->trim_loop_count = (uint32_t)t[SW_SPACE_TRIM_LOOPS];
        c->trim_curves = m->arrays[M_TRIM_CURVES];
        c->trim_curve_count = (uint32_t)t[SW_SPACE_TRIM_CURVES];
        c->trim_data = m->arrays[M_TRIM_DATA];
        c->trim_data_count = (uint32_t)t[SW_SPACE_TRIM_DATA];
        c->patch_domains = m->arrays[M_DOMAINS];
        c->trim_masks = m->arrays[M_MASKS];
        c->trim_mask_count = (uint32_t)t[SW_SPACE_TRIM_MASKS];
    }
    if (first->seam_header) {
        uint32_t o = (uint32_t)t[SW_SPACE_SEAM_ORIGINALS], k = (uint32_t)t[SW_SPACE_SEAM_COLLAPSES];
        m->seam = (sw_seam_graph){
            .vertices = m->arrays[M_VERTICES], .slots = m->arrays[M_SLOTS],
            .loops = m->arrays[M_LOOPS], .edges = m->arrays[M_EDGES],
            .collapses = m->arrays[M_COLLAPSES], .slot_refs = m->arrays[M_SLOT_REFS],
            .surface_loops = m->arrays[M_SURFACE_LOOPS], .vertex_count = o + k,
            .original_count = o, .slot_count = (uint32_t)t[SW_SPACE_SEAM_SLOTS],
            .loop_count = (uint32_t)t[SW_SPACE_SEAM_LOOPS],
            .edge_count = (uint32_t)t[SW_SPACE_SEAM_EDGES], .collapse_count = k,
            .slot_ref_count = (uint32_t)t[SW_SPACE_SEAM_SLOT_REFS], .surface_count = s,
            .tolerance = tolerance };
        c->seam = &m->seam;
    }
    fill_derived(m, first, t, s);
    c->prototypes = m->arrays[M_PROTOTYPES];
    c->prototype_count = count;
}

/* META of the merged pack: its counts, the box of all prototypes, the
 * loosest tolerance. */
static void merge_meta(sw_pack_merged *m, const sw_pack *packs, uint32_t count,
                       const uint64_t *t)
{
    sw_pack_meta *meta = &m->meta;
    *meta = *packs[0].meta;
    meta->part_count = (uint32_t)t[SW_SPACE_PARTS];
    meta->patch_count = (uint32_t)t[SW_SPACE_PATCHES];
    meta->control_count = (uint32_t)t[SW_SPACE_CONTROL];
    meta->adjacency_count = (uint32_t)t[SW_SPACE_ADJACENCY];
    for (uint32_t k = 1; k < count; k++) {
        const sw_pack_meta *pm = packs[k].meta;
        for (int a = 0; a < 3; a++) {
            meta->box_min[a] = fminf(meta->box_min[a], pm->box_min[a]);
            meta->box_max[a] = fmaxf(meta->box_max[a], pm->box_max[a]);
        }
        meta->model_tolerance = fmaxf(meta->model_tolerance, pm->model_tolerance);
    }
}

/* The inputs' counts together, each within a 32-bit index; their notes. */
static sw_status merged_totals(const sw_pack *packs, uint32_t count, uint64_t total[SW_SPACE_COUNT],
                               uint64_t *notes, sw_error *err)
{
    *notes = 0;
    for (uint32_t k = 0; k < count; k++) {
        uint64_t n[SW_SPACE_COUNT];
        sw_pack_space_counts(&packs[k], n);
        for (int s = 0; s < SW_SPACE_COUNT; s++)
            total[s] += n[s];
        *notes += packs[k].import_note_count;
    }
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        if (total[s] >= UINT32_MAX)
            return sw_error_set(err, SW_ERR_RANGE, "merge: %llu records of one kind, past a "
                                "32-bit index", (unsigned long long)total[s]);
    if (total[SW_SPACE_SEAM_ORIGINALS] + total[SW_SPACE_SEAM_COLLAPSES] >= SW_SEAM_NONE)
        return sw_error_set(err, SW_ERR_RANGE, "merge: more seam vertices than a 32-bit index "
                            "holds");
    return SW_OK;
}

/* Input k's records after the inputs' before it (base, moved on past
 * them), its runs recorded as prototype k. */
static void merge_one(sw_pack_merged *out, const sw_pack *p, uint32_t k, const uint64_t *total,
                      uint64_t *base)
{
    sw_pack_move mv = { .src_originals = p->seam.original_count,
                        .dst_originals = (uint32_t)total[SW_SPACE_SEAM_ORIGINALS], .scale = 1 };
    sw_pack_prototype *proto = (sw_pack_prototype *)out->arrays[M_PROTOTYPES] + k;
    uint64_t n[SW_SPACE_COUNT];
    sw_pack_space_counts(p, n);
    for (int s = 0; s < SW_SPACE_COUNT; s++) {
        mv.shift[s] = (int64_t)base[s];
        proto->first[s] = (uint32_t)base[s];
        proto->count[s] = (uint32_t)n[s];
    }
    proto->seam_tolerance = p->seam_header ? p->seam.tolerance : 0;
    move_model(out, p, &mv, base);
    if (p->seam_header)
        move_seam(out, p, &mv, base);
    move_levels(out, p, &mv, base);
    if (p->import_notes)
        memcpy((sw_pack_import_note *)out->arrays[M_NOTES] + out->contents.import_note_count,
               p->import_notes, (size_t)p->import_note_count * sizeof *p->import_notes);
    out->contents.import_note_count += p->import_note_count;
    for (int s = 0; s < SW_SPACE_COUNT; s++)
        base[s] += n[s];
}

sw_status sw_pack_merge(const sw_pack *packs, uint32_t count, const sw_pack_instance *instances,
                        uint32_t instance_count, sw_pack_merged *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    uint64_t total[SW_SPACE_COUNT] = { 0 }, base[SW_SPACE_COUNT] = { 0 }, notes = 0;
    sw_status st = check_inputs(packs, count, err);
    if (st == SW_OK)
        st = merged_totals(packs, count, total, &notes, err);
    if (st == SW_OK)
        st = take_all(out, total, count, notes, err);
    if (st != SW_OK) {
        sw_pack_merged_free(out);
        return st;
    }
    float tolerance = 0;
    for (uint32_t k = 0; k < count; k++) {
        merge_one(out, &packs[k], k, total, base);
        tolerance = fmaxf(tolerance, packs[k].seam.tolerance);
    }
    uint32_t s = (uint32_t)total[SW_SPACE_SURFACES];
    ((uint32_t *)out->arrays[M_SURFACE_LOOPS])[s] = (uint32_t)total[SW_SPACE_SEAM_LOOPS];
    ((uint32_t *)out->arrays[M_SURFACE_LEVELS])[s] = (uint32_t)total[SW_SPACE_LEVELS];
    ((uint32_t *)out->arrays[M_PIECE_LEVELS])[total[SW_SPACE_PIECES]] =
        (uint32_t)total[SW_SPACE_PART_LEVELS];
    merge_meta(out, packs, count, total);
    uint32_t note_count = out->contents.import_note_count;
    fill_contents(out, &packs[0], total, count, tolerance);
    out->contents.import_notes = note_count ? out->arrays[M_NOTES] : NULL;
    out->contents.import_note_count = note_count;
    out->contents.instances = instances;
    out->contents.instance_count = instance_count;
    return SW_OK;
}

void sw_pack_merged_free(sw_pack_merged *m)
{
    for (int a = 0; a < M_COUNT; a++)
        free(m->arrays[a]);
    memset(m, 0, sizeof *m);
}
