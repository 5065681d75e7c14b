/* SPDX-License-Identifier: MIT */
/* Packs of placed parts (core/sw_pack_instances.h, assets/pack/sw_pack_merge.h):
 * packs built apart merged into prototypes, placed by instances, read back
 * and expanded into the scene the walk draws; the expansion checked against
 * the prototypes point by point and, independently, by writing the
 * expanded view out as an ordinary pack and reading it back with every rule
 * of the reader; and every rule of the two sections refused with its
 * message. */
#include <math.h>
#include <sodium.h>
#include <stdlib.h>
#include <string.h>

#include "sw_test.h"

#include "pack_sample.h"
#include "sw_pack_instances.h"
#include "sw_pack_move.h"
#include "sw_pack_merge.h"
#include "sw_pack_sign.h"
#include "sw_pack_signature.h"
#include "sw_pack_write.h"
#include "sw_seam_check.h"
#include "sw_seam_fronts.h"
#include "sw_trim_tess.h"

/* The sample with every group (pack_sample.h), serialised. */
static uint8_t *full_sample(size_t *size)
{
    sample_levels l;
    sample_supers k;
    sample_part_levels pl;
    make_sample_levels(&l);
    make_sample_supers(&k);
    make_sample_part_levels(&pl);
    return serialize_sample_all(&l.view, &k.view, &pl.view, size);
}

/* A rotation of angle about z, scale s, then a translation. */
static void similarity(float t[16], double angle, double s, float tx, float ty, float tz)
{
    memset(t, 0, 16 * sizeof *t);
    double c = cos(angle) * s, n = sin(angle) * s;
    t[0] = (float)c, t[1] = (float)n, t[4] = (float)-n, t[5] = (float)c, t[10] = (float)s;
    t[12] = tx, t[13] = ty, t[14] = tz, t[15] = 1;
}

static sw_pack_instance instance(uint32_t prototype, double angle, double s, float tx,
                                 const char *name)
{
    sw_pack_instance i = { .prototype = prototype, .color = { 0.5f, 0.25f, 1, 1 } };
    similarity(i.transform, angle, s, tx, 2, -3);
    snprintf(i.name, sizeof i.name, "%s", name);
    return i;
}

enum { PLACED = 3 };

/* Two prototypes (the sample twice, opened from its bytes) placed three
 * times, serialised into *out. */
static sw_status placed_sample(const sw_pack_instance *inst, uint32_t n, uint8_t **out,
                               size_t *out_size, sw_error *err)
{
    size_t size = 0;
    uint8_t *bytes = full_sample(&size);
    sw_pack packs[2];
    sw_status st = sw_pack_open_memory(bytes, size, &packs[0], err);
    packs[1] = packs[0];
    sw_pack_merged m;
    if (st == SW_OK)
        st = sw_pack_merge(packs, 2, inst, n, &m, err);
    if (st == SW_OK) {
        st = sw_pack_serialize(&m.contents, out, out_size, err);
        sw_pack_merged_free(&m);
    }
    free(bytes);
    return st;
}

static void three(sw_pack_instance inst[PLACED])
{
    inst[0] = instance(0, 0, 1, 0, "first");
    inst[1] = instance(1, 0.7, 2.5, 10, "second");
    inst[2] = instance(0, -1.9, 0.25, -4, "third");
}

/* The expanded view as an ordinary pack's contents. */
static sw_pack_contents contents_of(const sw_pack *p)
{
    return (sw_pack_contents){
        .meta = *p->meta, .parts = p->parts, .patches = p->patches, .control = p->control,
        .adjacency = p->adjacency, .surfaces = p->surfaces, .surface_count = p->surface_count,
        .trim_loops = p->trim_loops, .trim_loop_count = p->trim_loop_count,
        .trim_curves = p->trim_curves, .trim_curve_count = p->trim_curve_count,
        .trim_data = p->trim_data, .trim_data_count = p->trim_data_count,
        .patch_domains = p->patch_domains, .trim_masks = p->trim_masks,
        .trim_mask_count = p->trim_mask_count, .part_transforms = p->part_transforms,
        .seam = &p->seam, .levels = &p->levels, .supers = &p->supers,
        .part_levels = &p->part_levels };
}

/* The sample placed by inst (PLACED of them), opened from its bytes
 * (*bytes: free them after the pack). */
static void open_placed(const sw_pack_instance *inst, uint8_t **bytes, sw_pack *pack)
{
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK_MSG(placed_sample(inst, PLACED, bytes, &size, &err) == SW_OK, "%s", err.message);
    SW_CHECK_MSG(sw_pack_open_memory(*bytes, size, pack, &err) == SW_OK, "%s", err.message);
}

static void test_merge_expand_and_read_back(void)
{
    sw_pack_instance inst[PLACED];
    three(inst);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_pack pack;
    open_placed(inst, &bytes, &pack);
    SW_CHECK(pack.header->version == SW_PACK_VERSION_INSTANCED);
    SW_CHECK(pack.prototype_count == 2 && pack.instance_count == PLACED);
    SW_CHECK(pack.meta->part_count == 4 && pack.surface_count == 4);
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack.prototypes, pack.instances, pack.instance_count, counts);
    size_t arena_bytes = (size_t)sw_pack_expand_bytes(counts);
    void *block = malloc(arena_bytes);
    sw_arena arena;
    sw_arena_init(&arena, block, arena_bytes);
    sw_pack placed;
    SW_CHECK_MSG(sw_pack_expand(&pack, &arena, &placed, &err) == SW_OK, "%s", err.message);
    SW_CHECK(arena.used <= arena_bytes);
    SW_CHECK(placed.meta->part_count == 6 && placed.surface_count == 6);
    SW_CHECK(placed.instances == NULL && placed.prototypes == NULL);
    /* Each placed control point is its prototype's, moved. */
    const uint32_t per = pack.prototypes[0].count[SW_SPACE_CONTROL];
    for (uint32_t i = 0; i < PLACED; i++)
        for (uint32_t c = 0; c < per; c++) {
            float want[3];
            sw_instance_place(inst[i].transform, &pack.control[4 * c], want);
            const float *got = &placed.control[4 * ((size_t)i * per + c)];
            SW_CHECK(got[0] == want[0] && got[1] == want[1] && got[2] == want[2]);
            SW_CHECK(got[3] == pack.control[4 * c + 3]);
        }
    /* Names and colours are the instances'; a prototype of two parts names
     * both after its instance. */
    SW_CHECK(strcmp(placed.parts[2].name, "second/") == 0 ||
             strncmp(placed.parts[2].name, "second/", 7) == 0);
    SW_CHECK(placed.parts[4].color[2] == 1.0f);
    /* Errors scale with the instance. */
    const sw_seam_graph *g = &placed.seam, *pg = &pack.seam;
    uint32_t made = pg->collapse_count / 2;
    SW_CHECK(fabsf(g->vertices[g->original_count + made].error -
                   pg->vertices[pg->original_count].error * 2.5f) <=
             1e-6f * (1 + pg->vertices[pg->original_count].error));
    SW_CHECK(sw_seam_graph_check(g, &err) == SW_OK);
    /* The sewing tolerance is each prototype's at its instance's scale:
     * the largest, not the stored graph's largest at the largest scale. */
    SW_CHECK(pack.prototypes[1].seam_tolerance == pg->tolerance);
    SW_CHECK_NEAR(g->tolerance, pg->tolerance * 2.5, 1e-6 * pg->tolerance);
    /* Independently: the expanded view written as an ordinary pack passes
     * every rule of the reader. */
    sw_pack_contents c = contents_of(&placed);
    uint8_t *flat = NULL;
    size_t flat_size = 0;
    SW_CHECK_MSG(sw_pack_serialize(&c, &flat, &flat_size, &err) == SW_OK, "%s", err.message);
    sw_pack again;
    SW_CHECK_MSG(sw_pack_open_memory(flat, flat_size, &again, &err) == SW_OK, "%s", err.message);
    free(flat);
    free(block);
    free(bytes);
}

/* The runtime's placed scene (shared) against the copying expansion
 * (whole): no control point copied, every patch's placed as read
 * (sw_pack_patch_control, sw_trim_patches_placed) the same floats as the
 * copy's, and the boxes made from them the same. */
static void control_placed_as_copied(const sw_pack *shared, const sw_pack *whole)
{
    SW_CHECK(shared->control_local && !whole->control_local);
    SW_CHECK(shared->meta->patch_count == whole->meta->patch_count);
    uint32_t differ = 0, moved = 0;
    float room[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    for (uint32_t i = 0; i < shared->meta->patch_count; i++) {
        const sw_pack_patch *ps = &shared->patches[i], *pw = &whole->patches[i];
        size_t points = (size_t)(ps->degree_u + 1) * (ps->degree_v + 1);
        const float *c = sw_pack_patch_control(shared, i, room);
        differ += memcmp(c, whole->control + 4 * (size_t)pw->first_control,
                         4 * points * sizeof(float)) != 0;
        differ += memcmp(ps->box_min, pw->box_min, sizeof ps->box_min) != 0 ||
                  memcmp(ps->box_max, pw->box_max, sizeof ps->box_max) != 0;
        moved += c == room;
    }
    SW_CHECK_MSG(differ == 0 && moved > 0, "%u of %u patches placed otherwise (%u moved)", differ,
                 shared->meta->patch_count, moved);
    /* The super-surfaces, which the walk does not read, are left out. */
    SW_CHECK(whole->supers.super_count > 0 && shared->supers.super_count == 0 &&
             !shared->supers.supers && !shared->supers.super_of);
    /* The domains are the prototypes' too, read through the surface. */
    SW_CHECK(!shared->patch_domains && whole->patch_domains);
    differ = 0;
    for (uint32_t s = 0; s < shared->surface_count; s++)
        for (uint32_t i = 0; i < shared->surfaces[s].patch_count; i++)
            differ += memcmp(sw_pack_domain_of(shared, s, i)->domain,
                             whole->patch_domains[whole->surfaces[s].first_patch + i].domain,
                             sizeof whole->patch_domains[0].domain) != 0;
    SW_CHECK_MSG(differ == 0, "%u patches' domains differ", differ);
    /* A surface's patches as the walk's maker reads them: from the room,
     * and refused without one (never the prototype's points unplaced). */
    uint32_t s = shared->surfaces[0].patch_count ? 0 : 1, count = 0;
    sw_trim_patch patches[64];
    float control[4 * 64 * 16];
    const sw_trim_patch_room fits = { patches, 64, control, 64 * 16 };
    SW_CHECK(shared->surfaces[s].patch_count <= 64);
    SW_CHECK(sw_trim_patches_placed(shared, s, &fits, &count, NULL) == SW_OK);
    for (uint32_t k = 0; k < count; k++) {
        const sw_pack_patch *pw = &whole->patches[shared->surfaces[s].first_patch + k];
        size_t points = (size_t)(pw->degree_u + 1) * (pw->degree_v + 1);
        SW_CHECK(memcmp(patches[k].patch.ctrl, whole->control + 4 * (size_t)pw->first_control,
                        4 * points * sizeof(float)) == 0);
    }
    sw_error err = { 0 };
    SW_CHECK(sw_trim_patches_from_pack(shared, s, patches, 64, &count, &err) == SW_ERR_NO_MEMORY &&
             strstr(err.message, "placed as they are read"));
    const sw_trim_patch_room short_room = { patches, 64, control, 1 };
    SW_CHECK(sw_trim_patches_placed(shared, s, &short_room, &count, NULL) == SW_ERR_NO_MEMORY);
}

/* The runtime's expansion shares the static and part levels' vertices
 * with the prototypes, and places them as the stand-ins and the GL thread
 * read them (sw_pack_level_vertices, the part's transform): the same
 * floats as the tools' expansion copies; it takes less arena. */
static void test_shared_levels_place_as_copied(void)
{
    sw_pack_instance inst[PLACED];
    three(inst);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    sw_pack pack;
    open_placed(inst, &bytes, &pack);
    SW_CHECK(pack.levels.level_count > 0 && pack.levels.vertex_count > 0);
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack.prototypes, pack.instances, pack.instance_count, counts);
    size_t whole_bytes = (size_t)sw_pack_expand_bytes(counts);
    size_t shared_bytes = (size_t)sw_pack_expand_shared_bytes(counts);
    SW_CHECK_MSG(shared_bytes + counts[SW_SPACE_LEVEL_VERTICES] * sizeof(sw_level_vertex) <=
                     whole_bytes + 64, "shared %zu, whole %zu", shared_bytes, whole_bytes);
    void *a = malloc(whole_bytes), *b = malloc(shared_bytes);
    sw_arena wa, sa;
    sw_arena_init(&wa, a, whole_bytes);
    sw_arena_init(&sa, b, shared_bytes);
    sw_pack whole, shared;
    SW_CHECK(sw_pack_expand(&pack, &wa, &whole, &err) == SW_OK && !whole.level_vertices_local);
    SW_CHECK_MSG(sw_pack_expand_shared(&pack, &sa, &shared, &err) == SW_OK, "%s", err.message);
    SW_CHECK(shared.level_vertices_local && shared.levels.vertices == pack.levels.vertices);
    /* The static levels' records are the prototypes' (a surface names its
     * stored one), not copied per instance. */
    SW_CHECK(shared.levels.levels == pack.levels.levels && !shared.levels.surface_levels &&
             shared.stored_surface && !whole.stored_surface);
    SW_CHECK(shared.levels.level_count == pack.levels.level_count &&
             whole.levels.level_count > pack.levels.level_count);
    /* What the walk never reads is left out; the rest of the graph is the
     * copying expansion's. */
    SW_CHECK(whole.seam.edge_count > 0 && whole.meta->adjacency_count > 0);
    SW_CHECK(shared.seam.edge_count == 0 && !shared.seam.edges &&
             shared.meta->adjacency_count == 0 && !shared.adjacency);
    SW_CHECK(shared.seam.vertex_count == whole.seam.vertex_count &&
             memcmp(shared.seam.vertices, whole.seam.vertices,
                    whole.seam.vertex_count * sizeof *whole.seam.vertices) == 0 &&
             memcmp(shared.seam.slots, whole.seam.slots,
                    whole.seam.slot_count * sizeof *whole.seam.slots) == 0);
    uint32_t compared = 0, differ = 0, scaled = 0;
    sw_level_vertex out[256];
    for (uint32_t s = 0; s < shared.surface_count; s++) {
        uint32_t fs, es, fw, ew;
        sw_pack_surface_levels(&shared, s, &fs, &es);
        sw_pack_surface_levels(&whole, s, &fw, &ew);
        SW_CHECK(es - fs == ew - fw && es > fs);
        for (uint32_t j = 0; j < es - fs && j < ew - fw; j++) {
            const sw_level rs = sw_pack_level(&shared, s, fs + j);
            const sw_level *rw = &whole.levels.levels[fw + j];
            /* the placed record's every field but where its vertices are */
            SW_CHECK(rs.surface == rw->surface && rs.error == rw->error &&
                     rs.made_bound == rw->made_bound && rs.vertex_count == rw->vertex_count &&
                     rs.first_index == rw->first_index && rs.index_count == rw->index_count &&
                     rs.first_chain == rw->first_chain);
            scaled += rs.error != shared.levels.levels[fs + j].error;
            if (rs.vertex_count > 256)
                continue;
            sw_pack_level_vertices(&shared, s, &rs, out);
            differ += memcmp(out, whole.levels.vertices + rw->first_vertex,
                             rs.vertex_count * sizeof *out) != 0;
            compared++;
        }
    }
    SW_CHECK_MSG(compared > 0 && differ == 0 && scaled > 0,
                 "%u of %u levels placed otherwise (%u scaled)", differ, compared, scaled);
    /* The part levels' too, placed by their piece's part's transform (the
     * GL thread's model matrix does it on the unit). */
    SW_CHECK(shared.part_levels.vertices == pack.part_levels.vertices &&
             shared.part_levels.level_count == whole.part_levels.level_count);
    compared = differ = 0;
    for (uint32_t s = 0; s < shared.surface_count; s++) {
        uint32_t g = shared.part_levels.piece_of[s], part = shared.surfaces[s].part;
        for (uint32_t k = shared.part_levels.piece_levels[g];
             k < shared.part_levels.piece_levels[g + 1]; k++) {
            const sw_part_level *ls = &shared.part_levels.levels[k];
            const sw_part_level *lw = &whole.part_levels.levels[k];
            if (ls->vertex_count > 256)
                continue;
            const float *t = shared.part_transforms + 16 * (size_t)part;
            const sw_pack_move place = { .transform = t, .scale = sw_instance_scale(t) };
            sw_pack_move_level_vertices(&place, shared.part_levels.vertices + ls->first_vertex,
                                        ls->vertex_count, out);
            for (uint32_t v = 0; v < ls->vertex_count; v++)
                for (int c = 0; c < 3; c++)
                    differ += fabsf(out[v].p[c] - whole.part_levels.vertices[lw->first_vertex + v].p[c]) >
                              1e-6f * (1 + fabsf(out[v].p[c]));
            compared++;
        }
    }
    SW_CHECK_MSG(compared > 0 && differ == 0, "%u coordinates of %u part levels placed otherwise",
                 differ, compared);
    control_placed_as_copied(&shared, &whole);
    free(a);
    free(b);
    free(bytes);
}

/* A loop point of the fronts and of the expanded select differ. */
static int points_differ(const sw_trim_loops *a, const sw_trim_loops *b)
{
    if (a->loop_count != b->loop_count)
        return 1;
    for (uint32_t i = 0; i <= a->loop_count; i++)
        if (a->loop_first[i] != b->loop_first[i])
            return 1;
    for (uint32_t i = 0; i < a->loop_first[a->loop_count]; i++)
        if (a->points[i].id != b->points[i].id ||
            memcmp(a->points[i].p, b->points[i].p, sizeof a->points[i].p) ||
            memcmp(a->points[i].uv, b->points[i].uv, sizeof a->points[i].uv))
            return 1;
    return 0;
}

/* What differs between the fronts and the select over the expanded scene
 * after an update for bound: vertices on one front and not the other,
 * originals showing another vertex, surfaces changed in one only, surfaces
 * whose loops differ (ids, positions, parameters). */
static uint64_t fronts_differ(sw_seam_fronts *f, sw_seam_select *sel, const float *bound,
                              sw_seam_surface_buffers *ba, sw_seam_surface_buffers *bb)
{
    sw_seam_update_result r;
    SW_CHECK(sw_seam_fronts_update(f, bound, &r, NULL) == SW_OK && r.complete);
    SW_CHECK(sw_seam_select_update(sel, bound, 0, &r, NULL) == SW_OK);
    const sw_seam_graph *g = &sel->graph;
    uint64_t differ = f->active_count != sel->active_count;
    for (uint32_t v = 0; v < g->vertex_count; v++) {
        uint32_t k = sw_seam_fronts_instance_at(f, v);
        differ += f->front[k].active[sw_seam_fronts_local(f, k, v)] != sel->active[v];
    }
    for (uint32_t o = 0; o < g->original_count; o++)
        differ += sw_seam_fronts_shown(f, NULL, o) != sel->shown[sel->leaf_lo[o]];
    for (uint32_t s = 0; s < g->surface_count; s++) {
        differ += sw_seam_fronts_surface_changed(f, s) != sw_seam_select_surface_changed(sel, s);
        sw_trim_loops la, lb;
        uint32_t oa = 0, ob = 0;
        int ka = sw_seam_fronts_surface_loops(f, s, 0.0f, ba, &la, &oa);
        int kb = sw_seam_surface_loops(sel, s, 0.0f, bb, &lb, &ob);
        differ += ka != kb || oa != ob || (ka && points_differ(&la, &lb));
    }
    sw_seam_fronts_clear_changed(f);
    sw_seam_select_clear_changed(sel);
    return differ;
}

/* The fronts of placed pack (one per instance over its prototype's
 * graph) against one select over its expanded scene, frames updates of
 * bounds drawn at random from the graph's errors: what differs. */
static uint64_t fronts_against_expanded(const sw_pack *pack, int frames, int per_instance,
                                        uint32_t *fronts)
{
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, counts);
    size_t expand = (size_t)sw_pack_expand_bytes(counts);   /* every seam array copied */
    sw_arena ea;
    void *eb = malloc(expand);
    sw_arena_init(&ea, eb, expand);
    sw_pack placed;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_pack_expand(pack, &ea, &placed, &err) == SW_OK, "%s", err.message);
    const sw_seam_graph *g = &placed.seam;
    size_t fb = per_instance < 0 ? sw_seam_fronts_arena_bytes(pack)
                                 : sw_seam_fronts_layout_bytes(pack->prototypes,
                                                               pack->prototype_count,
                                                               pack->instances,
                                                               pack->instance_count,
                                                               per_instance);
    size_t sb = sw_seam_select_arena_bytes(g);
    void *fm = malloc(fb), *sm = malloc(sb);
    sw_arena fa, sa;
    sw_arena_init(&fa, fm, fb);
    sw_arena_init(&sa, sm, sb);
    sw_seam_fronts f;
    sw_seam_select sel;
    sw_status st = per_instance < 0
                       ? sw_seam_fronts_init(&f, pack, g, &fa, &err)
                       : sw_seam_fronts_init_layout(&f, pack, g, per_instance, &fa, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    SW_CHECK(fa.peak <= fb);
    *fronts = f.count;
    /* The placed graph read through the fronts, from the prototypes'
     * graphs and the instances: the expansion's very floats. */
    uint64_t differ = 0;
    for (uint32_t v = 0; v < g->vertex_count; v++) {
        float p[3];
        sw_seam_fronts_position(&f, v, p);
        differ += memcmp(p, g->vertices[v].p, sizeof p) != 0;
        differ += sw_seam_fronts_error(&f, v) != g->vertices[v].error;
        float within = g->vertices[v].error * 1.5f + 1e-3f;
        uint32_t x = v;
        while (g->vertices[x].child != SW_SEAM_NONE &&
               g->vertices[g->vertices[x].child].error <= within)
            x = g->vertices[x].child;
        differ += sw_seam_fronts_ancestor_within(&f, v, within) != x;
    }
    for (uint32_t s = 0; s < g->surface_count; s++) {
        float worst = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            for (uint32_t k = 0; k < g->loops[l].slot_count; k++) {
                uint32_t o = g->slots[g->loops[l].first_slot + k].vertex;
                differ += sw_seam_fronts_slot_vertex(&f, l, k) != o;
                worst = fmaxf(worst, g->vertices[o].error);
            }
        differ += sw_seam_fronts_loop_error(&f, s) != worst;
    }
    SW_CHECK(sw_seam_select_init_checked(&sel, g, &sa, NULL) == SW_OK);
    float *bound = malloc((g->surface_count + 1) * sizeof *bound), top = 0;
    for (uint32_t v = 0; v < g->vertex_count; v++)
        top = fmaxf(top, g->vertices[v].error);
    sw_seam_point *sp = malloc(2 * (g->slot_count + 1) * sizeof *sp);
    sw_trim_point *tp = malloc(2 * (g->slot_count + 1) * sizeof *tp);
    uint32_t *first = malloc(2 * (g->loop_count + 1) * sizeof *first);
    sw_seam_surface_buffers ba = { sp, tp, first, g->slot_count + 1 };
    sw_seam_surface_buffers bb = { sp + g->slot_count + 1, tp + g->slot_count + 1,
                                   first + g->loop_count + 1, g->slot_count + 1 };
    for (int frame = 0; frame < frames; frame++) {
        for (uint32_t s = 0; s < g->surface_count; s++)
            bound[s] = top * (float)exp2(-12.0 * sw_test_random());
        differ += fronts_differ(&f, &sel, bound, &ba, &bb);
    }
    free(first), free(tp), free(sp), free(bound);
    free(sm), free(fm), free(eb);
    return differ;
}

/* The seam fronts of the runtime (sw_seam_fronts.h), one per instance over
 * its prototype's graph, move as one select over the expanded scene: the
 * same front, the same loops, at the instances' scales (1, 2.5, 0.25),
 * in less memory. */
static void test_fronts_move_as_the_expanded_select(void)
{
    sw_pack_instance inst[PLACED];
    three(inst);
    uint8_t *bytes = NULL;
    sw_pack pack;
    open_placed(inst, &bytes, &pack);
    uint32_t fronts = 0;
    uint64_t differ = fronts_against_expanded(&pack, 50, 1, &fronts);
    SW_CHECK_MSG(differ == 0, "%llu differences", (unsigned long long)differ);
    SW_CHECK_MSG(fronts == PLACED, "%u fronts: not one per instance", fronts);
    /* A scene this small repeats too little to gain: one front over the
     * placed graph takes fewer bytes, and is the one chosen. */
    int each = 1;
    size_t least = sw_seam_fronts_bytes(pack.prototypes, pack.prototype_count, pack.instances,
                                        pack.instance_count, &each);
    SW_CHECK(!each && least == sw_seam_fronts_layout_bytes(pack.prototypes, pack.prototype_count,
                                                           pack.instances, pack.instance_count,
                                                           0));
    SW_CHECK(fronts_against_expanded(&pack, 5, -1, &fronts) == 0 && fronts == 1);
    free(bytes);
}

/* Placed at the identity, a prototype's copy is its records, moved in the
 * index spaces only. */
static void test_identity_is_a_copy(void)
{
    sw_pack_instance inst[2] = { instance(0, 0, 1, 0, "a"), instance(1, 0, 1, 0, "b") };
    for (int i = 0; i < 2; i++)
        similarity(inst[i].transform, 0, 1, 0, 0, 0);
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_error err = { 0 };
    SW_CHECK_MSG(placed_sample(inst, 2, &bytes, &size, &err) == SW_OK, "%s", err.message);
    sw_pack pack, placed;
    SW_CHECK(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK);
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack.prototypes, pack.instances, pack.instance_count, counts);
    size_t arena_bytes = (size_t)sw_pack_expand_bytes(counts);
    void *block = malloc(arena_bytes);
    sw_arena arena;
    sw_arena_init(&arena, block, arena_bytes);
    SW_CHECK(sw_pack_expand(&pack, &arena, &placed, &err) == SW_OK);
    SW_CHECK(memcmp(placed.control, pack.control,
                    (size_t)pack.meta->control_count * 4 * sizeof(float)) == 0);
    SW_CHECK(memcmp(placed.seam.slots, pack.seam.slots,
                    (size_t)pack.seam.slot_count * sizeof(sw_seam_slot)) == 0);
    SW_CHECK(memcmp(placed.seam.collapses, pack.seam.collapses,
                    (size_t)pack.seam.collapse_count * sizeof(sw_seam_collapse)) == 0);
    SW_CHECK(memcmp(placed.levels.vertices, pack.levels.vertices,
                    (size_t)pack.levels.vertex_count * sizeof(sw_level_vertex)) == 0);
    for (uint32_t p = 0; p < pack.meta->patch_count; p++)
        SW_CHECK(memcmp(&placed.patches[p], &pack.patches[p], sizeof(sw_pack_patch)) == 0);
    /* The fronts per instance copy as the expansion does (a transform that
     * moves nothing is not applied: -0.0 stays -0.0). */
    SW_CHECK(!sw_instance_moves(inst[0].transform) && !sw_instance_moves(NULL));
    uint32_t fronts = 0;
    SW_CHECK(fronts_against_expanded(&pack, 5, 1, &fronts) == 0 && fronts == 2);
    free(block);
    free(bytes);
}

/* A pack of placed parts signed: its header still counts the placed scene,
 * and a unit's checks pass. */
static void test_signed_placed_pack(void)
{
    sw_pack_instance inst[PLACED];
    three(inst);
    uint8_t *bytes = NULL, *out = NULL, pk[32], sk[64];
    size_t size = 0, out_size = 0;
    sw_error err = { 0 };
    SW_CHECK(placed_sample(inst, PLACED, &bytes, &size, &err) == SW_OK);
    SW_CHECK(sodium_init() >= 0);
    crypto_sign_keypair(pk, sk);
    sw_sign_request req = { sk, 3, "placed" };
    SW_CHECK_MSG(sw_pack_sign_bytes(bytes, size, &req, &out, &out_size, &err) == SW_OK, "%s",
                 err.message);
    sw_pack pack;
    const sw_pack_signature *sig;
    sw_trusted_keys keys = { .count = 1 };
    memcpy(keys.keys[0], pk, 32);
    SW_CHECK_MSG(sw_pack_open_memory(out, out_size, &pack, &err) == SW_OK, "%s", err.message);
    SW_CHECK(pack.instance_count == PLACED);
    SW_CHECK_MSG(sw_pack_check_signature(&pack, &keys, &sig, &err) == SW_OK, "%s", err.message);
    free(out);
    free(bytes);
}

/* ---- refused packs -------------------------------------------------------- */

static sw_pack_instance *instances_at(uint8_t *bytes)
{
    int e = entry_of(bytes, SW_SECTION_INSTANCES);
    return (sw_pack_instance *)(bytes + table_of(bytes)[e].offset);
}

static sw_pack_prototype *prototypes_at(uint8_t *bytes)
{
    int e = entry_of(bytes, SW_SECTION_PROTOTYPES);
    return (sw_pack_prototype *)(bytes + table_of(bytes)[e].offset);
}

typedef void (*fault)(uint8_t *bytes);

/* The sample placed three times, serialised (checksums valid). */
static uint8_t *three_placed(size_t *size)
{
    sw_pack_instance inst[PLACED];
    three(inst);
    uint8_t *bytes = NULL;
    sw_error err = { 0 };
    SW_CHECK_MSG(placed_sample(inst, PLACED, &bytes, size, &err) == SW_OK, "%s", err.message);
    return bytes;
}

static void expect_refused(fault f, const char *message, const char *what)
{
    size_t size = 0;
    sw_error err = { 0 };
    uint8_t *bytes = three_placed(&size);
    f(bytes);
    reseal_all(bytes);
    sw_pack pack;
    sw_status st = sw_pack_open_memory(bytes, size, &pack, &err);
    SW_CHECK_MSG(st != SW_OK, "%s: accepted", what);
    SW_CHECK_MSG(strstr(err.message, message) != NULL, "%s: '%s', expected '%s'", what,
                 err.message, message);
    free(bytes);
}

static void bad_prototype(uint8_t *b) { instances_at(b)[1].prototype = 2; }
static void bad_flags(uint8_t *b) { instances_at(b)[0].flags = 1; }
static void bad_color(uint8_t *b) { instances_at(b)[2].color[1] = 1.5f; }
static void bad_name(uint8_t *b) { memset(instances_at(b)[0].name, 'x', 56); }
static void shear(uint8_t *b) { instances_at(b)[1].transform[4] += 0.5f; }
static void mirror(uint8_t *b) { instances_at(b)[1].transform[10] *= -1; }
static void zero_scale(uint8_t *b)
{
    float *t = instances_at(b)[0].transform;
    for (int k = 0; k < 12; k++)
        t[k] = 0;
}
static void not_finite(uint8_t *b) { instances_at(b)[2].transform[13] = NAN; }
static void last_row(uint8_t *b) { instances_at(b)[2].transform[7] = 0.5f; }
static void too_far(uint8_t *b) { instances_at(b)[0].transform[12] = 1e30f; }
static void gap(uint8_t *b) { prototypes_at(b)[1].first[SW_SPACE_PATCHES] += 1; }
static void short_run(uint8_t *b) { prototypes_at(b)[1].count[SW_SPACE_LEVEL_VERTICES] -= 1; }
static void no_parts(uint8_t *b)
{
    sw_pack_prototype *p = prototypes_at(b);
    p[1].first[SW_SPACE_PARTS] = 4, p[0].count[SW_SPACE_PARTS] = 4, p[1].count[SW_SPACE_PARTS] = 0;
}
/* Prototype 1's first level draws prototype 0's vertices (the same count):
 * whole to the reader's other rules, not its own. */
static void cross_reference(uint8_t *b)
{
    int e = entry_of(b, SW_SECTION_LEVEL_RECORDS);
    sw_level *levels = (sw_level *)(b + table_of(b)[e].offset);
    levels[prototypes_at(b)[1].first[SW_SPACE_LEVELS]].first_vertex = 0;
}
/* A sewing tolerance of 1e10 placed at a scale of 1e9: an error past the
 * walk's doubles' comfort, though every coordinate stays small. */
static void huge_error(uint8_t *b)
{
    int e = entry_of(b, SW_SECTION_SEAM);
    ((sw_pack_seam *)(b + table_of(b)[e].offset))->tolerance = 1e10f;
    similarity(instances_at(b)[1].transform, 0.7, 1e9, 10, 2, -3);
}
static void loose(uint8_t *b) { prototypes_at(b)[0].seam_tolerance *= 2; }
static void runtime_bytes(uint8_t *b) { header_of(b)->runtime_bytes -= 64; }
static void old_version(uint8_t *b) { header_of(b)->version = SW_PACK_VERSION; }
static void no_instances(uint8_t *b)
{
    table_of(b)[entry_of(b, SW_SECTION_INSTANCES)].type = 200;   /* unknown: skipped */
}

static void test_refused(void)
{
    expect_refused(bad_prototype, "INSTANCES[1].prototype: 2, expected < 2", "prototype");
    expect_refused(bad_flags, "INSTANCES[0].flags", "flags");
    expect_refused(bad_color, "INSTANCES[2].color[1]", "colour");
    expect_refused(bad_name, "INSTANCES[0].name: not NUL-terminated", "name");
    expect_refused(shear, "INSTANCES[1].transform: expected a rotation", "shear");
    expect_refused(mirror, "INSTANCES[1].transform: expected a rotation", "mirror");
    expect_refused(zero_scale, "INSTANCES[0].transform: expected a rotation", "zero scale");
    expect_refused(not_finite, "INSTANCES[2].transform[13]", "NaN");
    expect_refused(last_row, "INSTANCES[2].transform: its last row", "last row");
    expect_refused(too_far, "INSTANCES[0]: places points", "too far");
    expect_refused(gap, "PROTOTYPES[1]: its patches start at", "gap");
    expect_refused(short_run, "PROTOTYPES: the runs of level vertices end", "short run");
    expect_refused(no_parts, "PROTOTYPES[1]: no part", "no parts");
    expect_refused(cross_reference, "first_vertex of prototype 1's levels record", "cross");
    expect_refused(loose, "PROTOTYPES[0]: seam_tolerance", "tolerance");
    expect_refused(huge_error, "INSTANCES[1]: scales an error of", "error scaled");
    expect_refused(runtime_bytes, "header.runtime_bytes: ", "runtime bytes short");
    expect_refused(old_version, "header.version: 1 with PROTOTYPES and INSTANCES", "version");
    expect_refused(no_instances, "PROTOTYPES without INSTANCES", "alone");
}

/* A header asking more than this runtime takes (a pack written when the
 * runtime took more) still opens; its pools add up to what this runtime
 * takes, not to the header's value. */
static void test_runtime_bytes_more(void)
{
    size_t size = 0;
    sw_error err = { 0 };
    uint8_t *bytes = three_placed(&size);
    uint64_t exact = header_of(bytes)->runtime_bytes;
    header_of(bytes)->runtime_bytes = exact + (1u << 20);
    reseal_all(bytes);
    sw_pack pack;
    SW_CHECK_MSG(sw_pack_open_memory(bytes, size, &pack, &err) == SW_OK, "%s", err.message);
    sw_runtime_pools pools;
    sw_pack_runtime_pools(&pack, &pools);
    const char *names[SW_RUNTIME_POOL_COUNT];
    uint64_t pool[SW_RUNTIME_POOL_COUNT], sum = 0;
    for (int i = 0, n = sw_runtime_pool_list(&pools, names, pool); i < n; i++)
        sum += pool[i];
    SW_CHECK_MSG(sum == exact, "pools %llu, the exact runtime_bytes %llu",
                 (unsigned long long)sum, (unsigned long long)exact);
    free(bytes);
}

/* Inputs the merge cannot join are named. */
static void test_merge_refuses(void)
{
    size_t size = 0, plain_size = 0;
    uint8_t *bytes = full_sample(&size);
    sample s;
    make_sample(&s);
    uint8_t *plain = serialize_sample(&s, &plain_size);
    sw_pack packs[2];
    sw_error err = { 0 };
    SW_CHECK(sw_pack_open_memory(bytes, size, &packs[0], &err) == SW_OK);
    SW_CHECK(sw_pack_open_memory(plain, plain_size, &packs[1], &err) == SW_OK);
    sw_pack_instance one = instance(0, 0, 1, 0, "x");
    sw_pack_merged m;
    SW_CHECK(sw_pack_merge(packs, 2, &one, 1, &m, &err) != SW_OK);
    SW_CHECK_MSG(strstr(err.message, "input 1 lacks a Seam Graph") != NULL, "%s", err.message);
    free(plain);
    free(bytes);
}

/* test_pack_instances PACK [--each]: the fronts against the expanded
 * select on a placed pack from a file (a generated showroom), 20 updates;
 * exits 1 on a difference. The fronts in the layout the walk takes, or
 * with --each one per instance whatever the walk takes (a small scene
 * repeats too little for the walk to take them). */
static int fronts_of_file(const char *path, int each)
{
    FILE *in = fopen(path, "rb");
    if (!in || fseek(in, 0, SEEK_END) != 0) {
        fprintf(stderr, "%s: cannot read\n", path);
        return 2;
    }
    long size = ftell(in);
    rewind(in);
    void *data = aligned_alloc(64, ((size_t)size + 63) / 64 * 64);
    size_t got = fread(data, 1, (size_t)size, in);
    fclose(in);
    sw_pack pack;
    sw_error err = { 0 };
    if (got != (size_t)size || sw_pack_open_memory(data, got, &pack, &err) != SW_OK ||
        !pack.instances || !pack.seam_header) {
        fprintf(stderr, "%s: not a placed pack with a Seam Graph: %s\n", path, err.message);
        return 2;
    }
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack.prototypes, pack.instances, pack.instance_count, counts);
    sw_seam_graph placed = { .vertex_count = (uint32_t)(counts[SW_SPACE_SEAM_ORIGINALS] +
                                                        counts[SW_SPACE_SEAM_COLLAPSES]),
                             .original_count = (uint32_t)counts[SW_SPACE_SEAM_ORIGINALS],
                             .slot_count = (uint32_t)counts[SW_SPACE_SEAM_SLOTS],
                             .collapse_count = (uint32_t)counts[SW_SPACE_SEAM_COLLAPSES],
                             .surface_count = (uint32_t)counts[SW_SPACE_SURFACES] };
    printf("%s: %u instances of %u prototypes; fronts %zu bytes, one select over the "
           "expanded scene %zu\n", path, pack.instance_count, pack.prototype_count,
           sw_seam_fronts_arena_bytes(&pack), sw_seam_select_arena_bytes(&placed));
    uint32_t fronts = 0;
    uint64_t differ = fronts_against_expanded(&pack, 20, each ? 1 : -1, &fronts);
    printf("%u fronts; %llu differences\n", fronts, (unsigned long long)differ);
    free(data);
    return differ != 0 || sw_test_failures != 0 ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc > 3 || (argc == 3 && strcmp(argv[2], "--each") != 0)) {
        fprintf(stderr, "usage: test_pack_instances [PACK [--each]]\n");
        return 2;
    }
    if (argc > 1)
        return fronts_of_file(argv[1], argc == 3);
    SW_RUN(test_merge_expand_and_read_back);
    SW_RUN(test_shared_levels_place_as_copied);
    SW_RUN(test_identity_is_a_copy);
    SW_RUN(test_fronts_move_as_the_expanded_select);
    SW_RUN(test_signed_placed_pack);
    SW_RUN(test_refused);
    SW_RUN(test_runtime_bytes_more);
    SW_RUN(test_merge_refuses);
    return sw_test_finish();
}
