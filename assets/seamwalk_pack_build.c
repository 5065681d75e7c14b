/* SPDX-License-Identifier: MIT */
/* seamwalk-pack build's pipeline from the model to the pack on disk
 * (seamwalk_pack_build.h). */
#include "seamwalk_pack_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack.h"
#include "sw_pack_import_notes.h"
#include "sw_pack_verify_tess.h"
#include "sw_pack_write.h"
#include "sw_parts_threads.h"
#include "sw_seam_reroot.h"
#include "sw_seam_simplify.h"
#include "sw_up_axis.h"

/* The simplifier's view of the exact surfaces (sw_seam_runs.h). */
static void model_point(void *ctx, uint32_t surface, double u, double v, double out[3])
{
    const sw_model *model = ctx;
    sw_nurbs_surface view = sw_model_surface_view(&model->surfaces[surface]);
    u = fmin(fmax(u, view.knots_u[view.degree_u]), view.knots_u[view.count_u]);
    v = fmin(fmax(v, view.knots_v[view.degree_v]), view.knots_v[view.count_v]);
    sw_vec3 p = sw_nurbs_surface_point(&view, u, v);
    out[0] = p.x, out[1] = p.y, out[2] = p.z;
}

/* The sewn seams of model; a surface whose loops are too long for one draw
 * is cut into pieces in model (sw_seam_split.h) and the model sewn again. */
static sw_status sew(const build_options *o, sw_model *model, sw_seam_host *seams,
                     seam_summary *summary, sw_error *err)
{
    sw_seam_options opt = { .tolerance = o->seam_tolerance };
    sw_status st = sw_seam_sew_model(model, &opt, seams, &summary->sewing, err);
    if (st != SW_OK)
        return st;
    sw_model split;
    sw_model_init(&split);
    st = sw_seam_split_long(model, seams, &split, &summary->split, err);
    if (st == SW_OK && summary->split.cut > 0) {
        sw_model_free(model);
        *model = split;
        sw_seam_host_free(seams);
        return sw_seam_sew_model(model, &opt, seams, &summary->sewing, err);
    }
    sw_model_free(&split);
    return st;
}

static sw_status build_seams(const build_options *o, progress_context *pc, sw_model *model,
                             sw_seam_host *seams, seam_summary *summary, sw_error *err)
{
    sw_pack_tool_progress(pc, "sewing seams", 0.0);
    memset(summary, 0, sizeof *summary);
    sw_status st = sew(o, model, seams, summary, err);
    if (st == SW_OK) {
        sw_pack_tool_progress(pc, "simplifying seams", 0.0);
        double t0 = sw_pack_tool_now_s();
        const sw_seam_surface_eval eval = { model_point, (void *)model };
        st = sw_seam_simplify_on(seams, &eval, err);
        summary->simplify_s = sw_pack_tool_now_s() - t0;
        summary->collapses = seams->collapse_count;
    }
    if (st != SW_OK)
        sw_error_prefix(err, "seam graph");
    return st;
}

/* The inputs' file names (no folders) for the import notes; NULL when out
 * of memory. */
static const char **input_names(const build_options *o)
{
    const char **names = calloc((size_t)o->input_count + 1, sizeof *names);
    for (int i = 0; names && i < o->input_count; i++)
        names[i] = sw_pack_tool_base_name(o->inputs[i]);
    return names;
}

/* The static levels and the super-surfaces of a pack (sw_levels_build.h,
 * sw_cluster.h), made from the pack as the runtime reads it; the clusters
 * are capped by the levels' triangles, so they come second. */
typedef struct derived {
    sw_levels_built levels;
    sw_clusters_built clusters;
    sw_part_levels_built part_levels;
} derived;

static sw_status build_derived(const sw_pack *pack, const sw_part_levels_options *plo, derived *d,
                               seam_summary *summary, sw_error *err)
{
    memset(d, 0, sizeof *d);
    const sw_levels_options lo = { .runner = plo->runner };
    sw_status st = sw_levels_build(pack, &lo, &d->levels, &summary->levels, err);
    if (st == SW_OK)
        st = sw_cluster_pack(pack, &d->levels.view, NULL, &d->clusters, &summary->clusters, err);
    if (st == SW_OK)
        st = sw_part_levels_build(pack, &d->levels.view, plo, &d->part_levels,
                                  &summary->part_levels, err);
    if (st != SW_OK) {
        sw_levels_built_free(&d->levels);
        sw_clusters_built_free(&d->clusters);
    }
    return st;
}

/* The pack in *bytes again, with its static levels and super-surfaces. */
static sw_status add_levels(sw_pack_contents *contents, const sw_part_levels_options *plo,
                            uint8_t **bytes, size_t *size,
                            seam_summary *summary, sw_error *err)
{
    sw_pack pack;
    sw_status st = sw_pack_open_memory(*bytes, *size, &pack, err);
    if (st != SW_OK) {
        sw_error_prefix(err, "the pack as written");
        return st;
    }
    derived d;
    st = build_derived(&pack, plo, &d, summary, err);
    if (st != SW_OK)
        return st;
    uint8_t *with = NULL;
    size_t with_size = 0;
    contents->levels = &d.levels.view;
    contents->supers = &d.clusters.view;
    contents->part_levels = &d.part_levels.view;
    st = sw_pack_serialize(contents, &with, &with_size, err);
    contents->levels = NULL;
    contents->supers = NULL;
    contents->part_levels = NULL;
    sw_levels_built_free(&d.levels);
    sw_clusters_built_free(&d.clusters);
    sw_part_levels_built_free(&d.part_levels);
    /* Read back as the runtime will: a pack the reader refuses is not
     * written. */
    if (st == SW_OK && (st = sw_pack_open_memory(with, with_size, &pack, err)) != SW_OK)
        sw_error_prefix(err, "the pack with its static levels and super-surfaces");
    if (st != SW_OK) {
        free(with);
        return st;
    }
    free(*bytes);
    *bytes = with, *size = with_size;
    return SW_OK;
}

/* The pack as verify reads it: a surface refused at one of its seam states
 * would be a hole in the walk, so such a pack is not written. The error
 * names the surface's part and its place there as well as its number. */
static sw_status verify_before_writing(const uint8_t *bytes, size_t size, const sw_model *model,
                                       uint8_t *failed, sw_error *err)
{
    sw_pack pack;
    sw_pack_tess_report tess = { .first_failed = UINT32_MAX };
    sw_status st = sw_pack_open_memory(bytes, size, &pack, err);
    if (st == SW_OK)
        st = sw_pack_verify_tessellation_marks(&pack, failed, &tess, err);
    if (st == SW_OK)
        return SW_OK;
    if (tess.first_failed < model->surface_count) {
        const sw_model_surface *s = &model->surfaces[tess.first_failed];
        const sw_model_part *part = &model->parts[s->part];
        sw_error_prefix(err, "not written, verify would refuse the pack: part '%s', its surface "
                        "%zu of %zu", part->name, tess.first_failed - part->first_surface + 1,
                        part->surface_count);
    } else {
        sw_error_prefix(err, "not written, verify would refuse the pack");
    }
    return st;
}

sw_status sw_pack_tool_check_not_empty(const build_options *o, const sw_model *model,
                                       const sw_import_report *reports, sw_error *err)
{
    if (model->patch_count > 0)
        return SW_OK;
    for (int i = 0; i < o->input_count; i++) {
        const sw_import_tally *t = &reports[i].unsupported;
        if (t->total > 0)
            return sw_error_set(err, SW_ERR_FORMAT, "%s: nothing to draw: every surface was left "
                                "out (%zu skipped, the first: %s)", o->inputs[i], t->total,
                                t->kinds ? t->kind[0] : "of a kind not named");
    }
    return sw_error_set(err, SW_ERR_FORMAT, "%s%s: nothing to draw: no surface in the input%s",
                        o->inputs[0], o->input_count > 1 ? " ..." : "",
                        o->input_count > 1 ? "s" : "");
}

/* The pack in *bytes (replacing what is there) from contents and the seams
 * as they are now; with_levels adds the static levels, super-surfaces and
 * part levels to it. */
static sw_status serialize_seams(sw_pack_contents *contents, const sw_seam_host *seams,
                                 progress_context *pc, uint8_t **bytes, size_t *size,
                                 sw_error *err)
{
    sw_seam_graph view = sw_seam_host_view(seams);
    contents->seam = &view;
    free(*bytes);
    *bytes = NULL;
    sw_pack_tool_progress(pc, "serialising", 0.0);
    sw_status st = sw_pack_serialize(contents, bytes, size, err);
    contents->seam = NULL;
    return st;
}

static sw_status with_levels(sw_pack_contents *contents, const sw_seam_host *seams,
                             const sw_part_levels_options *plo, progress_context *pc,
                             uint8_t **bytes, size_t *size, seam_summary *summary, sw_error *err)
{
    sw_seam_graph view = sw_seam_host_view(seams);
    contents->seam = &view;
    sw_pack_tool_progress(pc, "static levels, super-surfaces", 0.0);
    sw_status st = add_levels(contents, plo, bytes, size, summary, err);
    contents->seam = NULL;
    return st;
}

double sw_pack_tool_seam_floor(double closest_mm)
{
    return closest_mm * SW_CLOSEST_BOUND_PER_MM;
}

double sw_pack_tool_default_closest_mm(double diagonal)
{
    return diagonal / 100;
}

enum { REPAIR_ROUNDS = 6 };

/* The graph the pack stores: full's hierarchy cut at the build's seam
 * floor (sw_seam_reroot.h), into *cut (replacing it). full stays whole: a
 * repair round pins and simplifies it again, then cuts it again. */
static sw_status cut_at_floor(const build_options *o, const sw_seam_host *full,
                              sw_seam_host *cut, seam_summary *summary, sw_error *err)
{
    sw_seam_host_free(cut);
    sw_status st = sw_seam_host_copy(full, cut, err);
    if (st == SW_OK)
        st = sw_seam_reroot(cut, (float)o->seam_floor, &summary->reroot, err);
    summary->seam_floor = o->seam_floor;
    return st;
}

/* The pack serialised and verified as `verify` will: a surface refused at
 * one of its seam states keeps its seams whole (their vertices pinned, the
 * seams simplified again), round after round while that changes something
 * (REPAIR_ROUNDS at most); one still refused fails the build. The levels,
 * most of a build's time and no part of what verify tessellates, are made
 * once, on the seams that verified (each round made them again: a fetched
 * arm part took past 300 s in six rounds of them). */
static sw_status pack_verified(const build_options *o, progress_context *pc,
                               const sw_model *model, sw_pack_contents *contents,
                               sw_seam_host *seams, seam_summary *summary, uint8_t **bytes,
                               size_t *size, sw_error *err)
{
    uint8_t *pinned = calloc((size_t)seams->original_count + 1, 1);
    uint8_t *failed = calloc((size_t)seams->surface_count + 1, 1);
    sw_status st = pinned && failed ? SW_OK : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    const sw_seam_surface_eval eval = { model_point, (void *)model };
    sw_seam_host cut = { 0 };
    for (int round = 0; st == SW_OK; round++) {
        st = cut_at_floor(o, seams, &cut, summary, err);
        if (st == SW_OK)
            st = serialize_seams(contents, &cut, pc, bytes, size, err);
        if (st != SW_OK)
            break;
        sw_pack_tool_progress(pc, "verifying", 0.0);
        memset(failed, 0, (size_t)seams->surface_count + 1);
        st = verify_before_writing(*bytes, *size, model, failed, err);
        if (st != SW_ERR_FORMAT || round == REPAIR_ROUNDS)
            break;
        uint32_t newly = sw_seam_pin_surfaces(seams, failed, pinned);
        if (newly == 0)
            break;
        summary->pinned_surfaces += newly;
        sw_pack_tool_progress(pc, "keeping seams whole", 0.0);
        st = sw_seam_simplify_pinned(seams, &eval, pinned, err);
        summary->collapses = seams->collapse_count;
    }
    if (st == SW_OK)
        st = with_levels(contents, &cut, &o->part_levels, pc, bytes, size, summary, err);
    sw_seam_host_free(&cut);
    free(pinned);
    free(failed);
    return st;
}

sw_status sw_pack_tool_pack_bytes(const build_options *o, progress_context *pc, sw_model *model,
                                  const sw_pack_import_note *notes, uint32_t note_count,
                                  seam_summary *summary, uint8_t **bytes, size_t *size,
                                  sw_error *err)
{
    snprintf(pc->prefix, sizeof pc->prefix, "packing");
    pc->importing = 0;
    sw_pack_progress progress = { sw_pack_tool_progress, pc };
    sw_pack_contents contents;
    sw_seam_host seams = { 0 };
    *bytes = NULL;
    *size = 0;
    /* The levels made on o->threads (sw_levels_options, sw_part_levels_options). */
    sw_parts_threads threads;
    sw_parts_runner runner = sw_parts_threads_runner(&threads, o->threads > 1 ? o->threads - 1 : 0);
    build_options with = *o;
    with.part_levels.runner = o->threads > 1 ? &runner : NULL;
    sw_status st = build_seams(o, pc, model, &seams, summary, err);
    if (st == SW_OK)
        st = sw_pack_contents_from_model_progress(model, &progress, &contents, err);
    if (st == SW_OK) {
        contents.import_notes = notes;
        contents.import_note_count = note_count;
        const sw_pack_orientation orientation = { .up_axis = model->up_axis };
        contents.orientation = sw_up_axis_valid(model->up_axis) ? &orientation : NULL;
        st = pack_verified(&with, pc, model, &contents, &seams, summary, bytes, size, err);
        sw_pack_contents_free(&contents);
    }
    sw_seam_host_free(&seams);
    if (st != SW_OK) {
        free(*bytes);
        *bytes = NULL;
    }
    return st;
}

sw_status sw_pack_tool_notes(const build_options *o, const sw_import_report *reports,
                             sw_pack_import_note **notes, uint32_t *note_count, sw_error *err)
{
    const char **names = input_names(o);
    sw_status st = names ? sw_pack_notes_from_reports(names, reports, (size_t)o->input_count,
                                                      notes, note_count, err)
                         : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    free(names);
    return st;
}

sw_status sw_pack_tool_pack(const build_options *o, progress_context *pc, sw_model *model,
                            const sw_import_report *reports, seam_summary *seam_summary_out,
                            size_t *bytes_out, sw_error *err)
{
    uint8_t *bytes = NULL;
    sw_pack_import_note *notes = NULL;
    uint32_t note_count = 0;
    build_options with = *o;
    sw_box box = sw_model_box(model);
    with.seam_floor = sw_pack_tool_seam_floor(
        o->closest_mm > 0 ? o->closest_mm
                          : sw_pack_tool_default_closest_mm(sw_box_is_empty(&box)
                                                                ? 0 : sw_box_diagonal(&box)));
    sw_status st = sw_pack_tool_notes(o, reports, &notes, &note_count, err);
    if (st == SW_OK)
        st = sw_pack_tool_pack_bytes(&with, pc, model, notes, note_count, seam_summary_out,
                                     &bytes, bytes_out, err);
    free(notes);
    if (st == SW_OK) {
        sw_pack_tool_progress(pc, "writing", 0.0);
        st = sw_write_file_atomic(o->out_path, bytes, *bytes_out, err); /* names the path */
    }
    free(bytes);
    return st;
}
