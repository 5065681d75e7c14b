/* SPDX-License-Identifier: MIT */
/* seamwalk-pack build of a scene as placed parts (seamwalk_pack_build.h):
 * each prototype packed on its own, in its own frame, then the packs
 * merged and placed (assets/pack/sw_pack_merge.h). */
#include "seamwalk_pack_build.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_import_notes.h"
#include "sw_pack_instances.h"
#include "sw_pack_merge.h"
#include "sw_pack_sections.h"
#include "sw_pack_write.h"

/* The placed scene's box diagonal: every prototype's box moved by each of
 * its placements. */
static double placed_diagonal(const sw_scene_plan *plan)
{
    sw_box all = sw_box_empty();
    for (size_t i = 0; i < plan->placement_count; i++) {
        const sw_scene_placement *pl = &plan->placements[i];
        sw_box b = sw_model_box(&plan->prototypes[pl->prototype]);
        if (sw_box_is_empty(&b))
            continue;
        for (int c = 0; c < 8; c++) {
            const float p[3] = { (float)(c & 1 ? b.max.x : b.min.x),
                                 (float)(c & 2 ? b.max.y : b.min.y),
                                 (float)(c & 4 ? b.max.z : b.min.z) };
            float q[3];
            sw_instance_place(pl->transform, p, q);
            sw_box_add_point(&all, sw_v3(q[0], q[1], q[2]));
        }
    }
    return sw_box_is_empty(&all) ? 0 : sw_box_diagonal(&all);
}

/* Prototype k's sewing tolerance, in its own units: the model's own
 * (sw_seam_default_tolerance), never finer than a millionth of the whole
 * scene where it is placed largest (or than --seam-tolerance, in the
 * scene's units), which is what the scene sewn as one model was held to. */
/* The largest scale prototype k is placed at (1 when it is not placed); a
 * copy's is its source's (sw_scene_placement.prototype_scale). */
static double largest_scale(const sw_scene_plan *plan, size_t k)
{
    double scale = 0;
    for (size_t i = 0; i < plan->placement_count; i++)
        if (plan->placements[i].prototype == k)
            scale = fmax(scale, plan->placements[i].prototype_scale);
    return scale > 0 ? scale : 1;
}

static double prototype_tolerance(const build_options *o, const sw_scene_plan *plan, size_t k,
                                  double scene_floor)
{
    double scale = largest_scale(plan, k);
    if (o->seam_tolerance > 0)
        return o->seam_tolerance / scale;
    return fmax(sw_seam_default_tolerance(&plan->prototypes[k], NULL), scene_floor / scale);
}

/* The name of prototype k's first placement, for messages. */
static const char *first_placement(const sw_scene_plan *plan, size_t k)
{
    for (size_t i = 0; i < plan->placement_count; i++)
        if (plan->placements[i].prototype == k)
            return plan->placements[i].name;
    return "";
}

/* one's figures added to sum; its tolerance in the scene's units (scale:
 * the largest its prototype is placed at). */
static void add_summary(seam_summary *sum, const seam_summary *one, double scale)
{
    sw_seam_report *a = &sum->sewing;
    const sw_seam_report *b = &one->sewing;
    a->loops += b->loops, a->boundary_vertices += b->boundary_vertices;
    a->boundary_edges += b->boundary_edges, a->seams += b->seams;
    a->free_edges += b->free_edges, a->nonmanifold_edges += b->nonmanifold_edges;
    a->tolerance = fmax(a->tolerance, b->tolerance * scale);
    a->unproven_pieces += b->unproven_pieces, a->clamped += b->clamped;
    a->gaps_held += b->gaps_held, a->inserted += b->inserted;
    a->flatten_s += b->flatten_s, a->sew_s += b->sew_s;
    sum->collapses += one->collapses, sum->simplify_s += one->simplify_s;
    sum->pinned_surfaces += one->pinned_surfaces;
    sum->seam_floor = fmax(sum->seam_floor, one->seam_floor * scale);
    sw_seam_reroot_report *cut = &sum->reroot;
    const sw_seam_reroot_report *its = &one->reroot;
    cut->applied += its->applied, cut->kept += its->kept;
    cut->originals_before += its->originals_before, cut->originals_after += its->originals_after;
    cut->slots_before += its->slots_before, cut->slots_after += its->slots_after;
    sum->split.cut += one->split.cut, sum->split.pieces += one->split.pieces;
    sum->split.uncut += one->split.uncut;
    sw_levels_report *l = &sum->levels;
    const sw_levels_report *m = &one->levels;
    l->surfaces += m->surfaces, l->with_levels += m->with_levels, l->levels += m->levels;
    l->refused += m->refused, l->too_large += m->too_large, l->bad_border += m->bad_border;
    l->not_finer += m->not_finer, l->vanished += m->vanished, l->seconds += m->seconds;
    for (int r = 0; r < (int)SW_LEVELS_MAX; r++)
        l->triangles[r] += m->triangles[r];
    l->worst_over_bound = fmax(l->worst_over_bound, m->worst_over_bound);
    sw_cluster_report *c = &sum->clusters;
    c->surfaces += one->clusters.surfaces, c->clusters += one->clusters.clusters;
    c->merged += one->clusters.merged, c->wide_alone += one->clusters.wide_alone;
    c->capped += one->clusters.capped, c->seconds += one->clusters.seconds;
    sw_part_levels_report *p = &sum->part_levels;
    const sw_part_levels_report *q = &one->part_levels;
    p->parts += q->parts, p->pieces += q->pieces, p->cut_parts += q->cut_parts;
    p->with_levels += q->with_levels, p->levels += q->levels, p->incomplete += q->incomplete;
    p->not_smaller += q->not_smaller, p->folded += q->folded, p->over_bound += q->over_bound;
    p->too_large += q->too_large, p->source_triangles += q->source_triangles;
    for (int r = 0; r < (int)SW_PART_LEVELS_MAX; r++)
        p->triangles[r] += q->triangles[r];
    p->worst_over_bound = fmax(p->worst_over_bound, q->worst_over_bound);
    p->seconds += q->seconds;
}

/* The placed scene's floors, in its units: the sewing's (a millionth of
 * its size) and the seam hierarchy's (the bound at --closest-mm, or at a
 * hundredth of its size). Made once: the scene's size reads every
 * placement's prototype, and made per prototype it made a scene's build
 * quadratic in its size. */
typedef struct scene_floors {
    double sewing, seam;
} scene_floors;

static scene_floors floors_of(const build_options *o, const sw_scene_plan *plan)
{
    double diagonal = placed_diagonal(plan);
    scene_floors f = { 1e-6 * diagonal,
                       sw_pack_tool_seam_floor(o->closest_mm > 0
                                                   ? o->closest_mm
                                                   : sw_pack_tool_default_closest_mm(diagonal)) };
    return f;
}

/* The prototypes' packing, shared by the threads that run it. */
typedef struct proto_jobs {
    const build_options *o;
    sw_scene_plan *plan;
    scene_floors floors;
    uint32_t inner_threads;      /* each prototype's own --threads */
    size_t *order;               /* prototypes, largest first */
    atomic_size_t next;
    uint8_t **bytes;
    size_t *sizes;
    seam_summary *summaries;
    sw_status *status;
    sw_error *errors;
} proto_jobs;

/* Prototype k packed on threads threads, at its tolerance (within the
 * placed scene's floors), with what its file's import said. */
static sw_status pack_prototype(const build_options *o, progress_context *pc,
                                sw_scene_plan *plan, size_t k, const scene_floors *floors,
                                uint32_t threads, uint8_t **bytes, size_t *size,
                                seam_summary *summary, sw_error *err)
{
    build_options ok = *o;
    ok.seam_tolerance = prototype_tolerance(o, plan, k, floors->sewing);
    ok.seam_floor = floors->seam / largest_scale(plan, k);
    ok.threads = threads;
    sw_model *m = &plan->prototypes[k];
    m->up_axis = plan->views.up_axis;
    pc->model = m;
    const char *name = plan->sources[k] ? sw_pack_tool_base_name(plan->sources[k]) : "generated";
    sw_pack_import_note *notes = NULL;
    uint32_t note_count = 0;
    sw_status st = sw_pack_notes_from_reports(&name, &plan->reports[k], 1, &notes, &note_count,
                                              err);
    if (st == SW_OK)
        st = sw_pack_tool_pack_bytes(&ok, pc, m, notes, note_count, summary, bytes, size, err);
    free(notes);
    return st;
}

static void pack_one(proto_jobs *j, size_t k, progress_context *pc)
{
    j->status[k] = pack_prototype(j->o, pc, j->plan, k, &j->floors, j->inner_threads,
                                  &j->bytes[k], &j->sizes[k], &j->summaries[k], &j->errors[k]);
}

sw_status sw_pack_tool_pack_prototype(const build_options *o, progress_context *pc,
                                      sw_scene_plan *plan, size_t k, uint8_t **bytes,
                                      size_t *size, seam_summary *summary, sw_error *err)
{
    scene_floors floors = floors_of(o, plan);
    sw_status st = pack_prototype(o, pc, plan, k, &floors, o->threads, bytes, size, summary, err);
    if (st == SW_OK) {
        summary->sewing.tolerance *= largest_scale(plan, k);
        summary->seam_floor *= largest_scale(plan, k);
    }
    return st;
}

static void *pack_worker(void *arg)
{
    proto_jobs *j = arg;
    sw_model none;
    sw_model_init(&none);
    progress_context pc = { .model = &none };
    sw_progress_init(&pc.bar, stderr, 1); /* the main thread's bar counts prototypes */
    for (size_t i; (i = atomic_fetch_add(&j->next, 1)) < j->plan->prototype_count;)
        pack_one(j, j->order[i], &pc);
    return NULL;
}

typedef struct sized { size_t patches, k; } sized;

static int larger_first(const void *a, const void *b)
{
    const sized *x = a, *y = b;
    return x->patches != y->patches ? (x->patches < y->patches) - (x->patches > y->patches)
                                    : (x->k > y->k) - (x->k < y->k);
}

/* The prototypes by size, largest first (ties in scene order). */
static sw_status order_by_size(const sw_scene_plan *plan, size_t *order, sw_error *err)
{
    size_t n = plan->prototype_count;
    sized *s = calloc(n + 1, sizeof *s);
    if (!s)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    for (size_t k = 0; k < n; k++)
        s[k] = (sized){ plan->prototypes[k].patch_count, k };
    qsort(s, n, sizeof *s, larger_first);
    for (size_t k = 0; k < n; k++)
        order[k] = s[k].k;
    free(s);
    return SW_OK;
}

/* Every prototype packed apart into bytes[k], on o->threads threads: the
 * largest first, one thread each (or all of them for one prototype). Each
 * pack is the same bytes on any count, so the whole is too; a failure is
 * reported for the first failing prototype in scene order. */
static sw_status pack_prototypes(const build_options *o, progress_context *pc,
                                 sw_scene_plan *plan, seam_summary *summary, uint8_t **bytes,
                                 size_t *sizes, sw_error *err)
{
    size_t n = plan->prototype_count;
    uint32_t threads = o->threads > 1 ? o->threads : 1;
    if (threads > n)
        threads = (uint32_t)n;
    proto_jobs j = { .o = o, .plan = plan, .floors = floors_of(o, plan),
                     .inner_threads = threads > 1 ? 1 : o->threads, .bytes = bytes,
                     .sizes = sizes, .order = calloc(n + 1, sizeof(size_t)),
                     .summaries = calloc(n + 1, sizeof(seam_summary)),
                     .status = calloc(n + 1, sizeof(sw_status)),
                     .errors = calloc(n + 1, sizeof(sw_error)) };
    atomic_init(&j.next, 0);
    pthread_t *tids = calloc(threads + 1, sizeof *tids);
    sw_status st = j.order && j.summaries && j.status && j.errors && tids
                       ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    if (st == SW_OK)
        st = order_by_size(plan, j.order, err);
    if (st == SW_OK) {
        snprintf(pc->prefix, sizeof pc->prefix, "packing %zu prototypes", n);
        sw_pack_tool_progress(pc, "sewing, simplifying, levels", 0.0);
        uint32_t started = 1;
        while (started < threads && pthread_create(&tids[started], NULL, pack_worker, &j) == 0)
            started++;
        for (size_t i; (i = atomic_fetch_add(&j.next, 1)) < n;)
            pack_one(&j, j.order[i], pc);
        for (uint32_t t = 1; t < started; t++)
            pthread_join(tids[t], NULL);
    }
    for (size_t k = 0; st == SW_OK && k < n; k++) {
        if (j.status[k] == SW_OK) {
            add_summary(summary, &j.summaries[k], largest_scale(plan, k));
            continue;
        }
        *err = j.errors[k];
        st = j.status[k];
        sw_error_prefix(err, "prototype %zu of %zu (first placed as '%s')", k + 1, n,
                        first_placement(plan, k));
    }
    free(j.order);
    free(j.summaries);
    free(j.status);
    free(j.errors);
    free(tids);
    return st;
}

static sw_status instances_of(const sw_scene_plan *plan, sw_pack_instance **out, sw_error *err)
{
    sw_pack_instance *inst = calloc(plan->placement_count + 1, sizeof *inst);
    if (!inst)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    for (size_t i = 0; i < plan->placement_count; i++) {
        const sw_scene_placement *pl = &plan->placements[i];
        inst[i].prototype = (uint32_t)pl->prototype;
        memcpy(inst[i].color, pl->color, sizeof inst[i].color);
        memcpy(inst[i].transform, pl->transform, sizeof inst[i].transform);
        sw_pack_copy_name(inst[i].name, sizeof inst[i].name, pl->name);
    }
    *out = inst;
    return SW_OK;
}

sw_status sw_pack_tool_place(const sw_scene_plan *plan, uint8_t *const *bytes,
                             const size_t *sizes, uint8_t **out, size_t *out_size, sw_error *err)
{
    size_t n = plan->prototype_count;
    sw_pack *packs = calloc(n + 1, sizeof *packs);
    sw_pack_viewpoint *views = calloc(plan->views.viewpoint_count + 1, sizeof *views);
    sw_pack_instance *inst = NULL;
    sw_status st = packs && views ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    for (size_t k = 0; st == SW_OK && k < n; k++)
        if ((st = sw_pack_open_memory(bytes[k], sizes[k], &packs[k], err)) != SW_OK)
            sw_error_prefix(err, "prototype %zu of %zu", k + 1, n);
    if (st == SW_OK)
        st = sw_pack_viewpoints_from_model(&plan->views, views, err);
    if (st == SW_OK)
        st = instances_of(plan, &inst, err);
    sw_pack_merged merged;
    if (st == SW_OK)
        st = sw_pack_merge(packs, (uint32_t)n, inst, (uint32_t)plan->placement_count, &merged,
                           err);
    if (st == SW_OK) {
        sw_pack_contents *c = &merged.contents;
        c->viewpoints = views;
        c->viewpoint_count = (uint32_t)plan->views.viewpoint_count;
        const sw_pack_orientation orientation = { .up_axis = plan->views.up_axis };
        c->orientation = &orientation;
        st = sw_pack_serialize(c, out, out_size, err);
        sw_pack_merged_free(&merged);
    }
    sw_pack check;
    if (st == SW_OK && (st = sw_pack_open_memory(*out, *out_size, &check, err)) != SW_OK)
        sw_error_prefix(err, "the merged pack");
    free(packs);
    free(views);
    free(inst);
    return st;
}

sw_status sw_pack_tool_pack_scene(const build_options *o, progress_context *pc,
                                  sw_scene_plan *plan, seam_summary *summary, size_t *bytes_out,
                                  sw_error *err)
{
    size_t n = plan->prototype_count;
    uint8_t **bytes = calloc(n + 1, sizeof *bytes), *out = NULL;
    size_t *sizes = calloc(n + 1, sizeof *sizes);
    memset(summary, 0, sizeof *summary);
    sw_status st = bytes && sizes ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    if (st == SW_OK)
        st = pack_prototypes(o, pc, plan, summary, bytes, sizes, err);
    if (st == SW_OK) {
        sw_pack_tool_progress(pc, "placing", 0.0);
        st = sw_pack_tool_place(plan, bytes, sizes, &out, bytes_out, err);
    }
    if (st == SW_OK) {
        sw_pack_tool_progress(pc, "writing", 0.0);
        st = sw_write_file_atomic(o->out_path, out, *bytes_out, err);
    }
    for (size_t k = 0; bytes && k < n; k++)
        free(bytes[k]);
    free(bytes);
    free(sizes);
    free(out);
    return st;
}
