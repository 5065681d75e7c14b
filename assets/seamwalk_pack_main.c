/* SPDX-License-Identifier: MIT */
/* seamwalk-pack: the host tool that turns model files into packs and looks
 * inside packs. Commands: build, info, verify, keygen, sign, gen (usage below). Exit status:
 * 0 success, 1 failure (one line on stderr naming the file), 2 usage error.
 * A failed build never leaves a partial or damaged output file: the pack is
 * written through sw_write_file_atomic only after everything succeeded.
 * Warnings (entities an importer skipped) are printed after a successful
 * build; --strict makes them failures. */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sw_gen_showroom.h"
#include "sw_import.h"
#include "sw_import_iges.h"
#include "sw_import_occt.h"
#include "sw_model.h"
#include "sw_pack.h"
#include "sw_pack_info.h"
#include "sw_pack_sign.h"
#include "sw_pack_verify_tess.h"
#include "sw_parts_threads.h"
#include "sw_progress.h"
#include "sw_scene.h"
#include "sw_text_scan.h"
#include "sw_up_axis.h"
#include "sw_up_inputs.h"

#include "seamwalk_pack_build.h"
#include "seamwalk_pack_parts.h"
#include "sw_pack_write.h"

static const char usage_text[] =
    "usage: seamwalk-pack build INPUT... -o OUT.swpack [--quiet] [--strict]\n"
    "                           [--iges-reader native|occt] [--seam-tolerance MM]\n"
    "                           [--closest-mm MM] [--up x|y|z|-x|-y|-z]\n"
    "                           [--cut-patches N] [--threads N] [--copies]\n"
    "       seamwalk-pack build-part SCENE.ini --prototype K -o PART.swpack [build options]\n"
    "       seamwalk-pack merge SCENE.ini PART.swpack... -o OUT.swpack [--up AXIS] [--quiet]\n"
    "       seamwalk-pack ninja SCENE.ini -o build.ninja [--pack OUT.swpack] [-- BUILD OPTIONS]\n"
    "       seamwalk-pack info [--json] PACK\n"
    "       seamwalk-pack verify PACK [--key KEYS.pub]\n"
    "       seamwalk-pack keygen -o PREFIX\n"
    "       seamwalk-pack sign PACK --key PREFIX.key --version N --name NAME [-o OUT]\n"
    "       seamwalk-pack gen showroom --patches N -o SCENE.ini [--part FILE]... [--seed S]\n"
    "                                  [--catalog N]\n"
    "       seamwalk-pack --help | --version\n"
    "INPUT: a Newell listing (.txt), Bezier patch text (.bpt), IGES (.igs, .iges),\n"
    "STEP (.stp, .step) or a scene (.ini). Each file becomes one part named after\n"
    "it; a scene adds its parts. IGES is read by the native reader unless\n"
    "--iges-reader occt; STEP always through OpenCASCADE. --strict: entities an\n"
    "importer would skip are errors. --quiet: no progress bar, no summary.\n"
    "--seam-tolerance: how far apart trims may be and still be sewn into one seam\n"
    "(default: the file's model tolerance, at least 1e-5 of its smallest part's size\n"
    "and 1e-6 of the whole model's).\n"
    "--closest-mm: the nearest a walk brings the eye to a surface; the Seam Graph\n"
    "keeps the levels views from there on need, no finer (default: a hundredth of\n"
    "the model's or placed scene's size). Closer views are drawn at that level and\n"
    "counted (the walk's clamped surfaces).\n"
    "--up: the model axis that points up (default: z for STEP and IGES, y for .txt\n"
    "and .bpt, a scene's up_axis or y; inputs that differ: the first's, warned).\n"
    "--cut-patches: parts of more patches are cut into pieces with levels of their\n"
    "own, drawn apart far away (default 4096; 0: none cut).\n"
    "--threads: threads that convert STEP and IGES faces and make the static and\n"
    "part levels (default: the machine's cores; 0 or 1: none besides the tool's\n"
    "own; at most 64). The pack's bytes are the same whatever the count.\n"
    "A scene given alone is packed as placed parts: each file or generated object\n"
    "it names is sewn, simplified and stored once, in its own frame, and placed\n"
    "where its parts are (a pack of version 2). --copies: store every part as a\n"
    "copy of its own (still placed: one copy per placement).\n"
    "build-part packs one prototype of a scene (0-based, in the order the scene first\n"
    "names each file or object) as build does; merge places the scene's prototypes'\n"
    "packs, given in that order, into the pack build would write, byte for byte;\n"
    "ninja writes a build.ninja that runs build-part for each prototype and merge.\n";

static int usage_error(const char *fmt, const char *arg)
{
    return sw_usage_error("seamwalk-pack", fmt, arg);
}

static int fail(const sw_error *err)
{
    fprintf(stderr, "seamwalk-pack: %s\n", err->message);
    return 1;
}

double sw_pack_tool_now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ---- build -------------------------------------------------------------- */

enum input_kind { INPUT_SCENE, INPUT_IGES, INPUT_STEP, INPUT_OTHER };

const char *sw_pack_tool_base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static enum input_kind kind_of(const char *path)
{
    const char *dot = strrchr(sw_pack_tool_base_name(path), '.');
    if (sw_scene_is_scene_path(path))
        return INPUT_SCENE;
    if (dot && (strcasecmp(dot, ".igs") == 0 || strcasecmp(dot, ".iges") == 0))
        return INPUT_IGES;
    if (dot && (strcasecmp(dot, ".stp") == 0 || strcasecmp(dot, ".step") == 0))
        return INPUT_STEP;
    return INPUT_OTHER;
}

/* The part name for a model file: its base name without the extension. */
static void part_name_for(const char *path, char name[56])
{
    const char *base = sw_pack_tool_base_name(path);
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (len > 55)
        len = 55;
    memcpy(name, base, len);
    name[len] = '\0';
}

void sw_pack_tool_progress(void *user, const char *stage, double fraction)
{
    progress_context *c = user;
    char label[160];
    snprintf(label, sizeof label, "%s%s%s", c->prefix, stage && *stage ? ": " : "",
             stage ? stage : "");
    if (c->importing)
        sw_progress_update(&c->bar, label, fraction,
                           (double)(c->model->surface_count - c->surfaces_before), "faces");
    else
        sw_progress_update(&c->bar, label, fraction,
                           strcmp(stage, "patches") == 0
                               ? fraction * (double)c->model->patch_count : -1.0,
                           "patches");
}

/* OpenCASCADE makes one part per leaf product of the file's assembly tree
 * (placed where the assembly puts it). The file is still what the user
 * named: a single product takes the file's name, several get it as a
 * prefix, and each gets the next default colour like any other file. */
static void name_occt_parts(sw_model *model, size_t first, const char *path)
{
    char stem[56];
    part_name_for(path, stem);
    size_t added = model->part_count - first;
    for (size_t p = first; p < model->part_count; p++) {
        sw_model_part *part = &model->parts[p];
        char joined[2 * sizeof part->name]; /* cut to the name's 55 bytes below */
        snprintf(joined, sizeof joined, "%s/%s", stem, part->name);
        memcpy(part->name, added == 1 ? stem : joined, sizeof part->name - 1);
        part->name[sizeof part->name - 1] = '\0';
        sw_scene_default_color(p, part->color);
    }
}

/* The native IGES reader's read of path into a part of its own; *again set
 * (with why) when it left out every surface, of kinds it does not take (IGES
 * 108 bounded planes), and OpenCASCADE's reader, built in, may take them:
 * the empty part is dropped for that read. */
static sw_status import_iges_native(const char *path, const char *name, const float color[4],
                                    const sw_import_options *opts, sw_model *model,
                                    sw_import_report *report, int *again, char *why,
                                    size_t why_size, sw_error *err)
{
    size_t surfaces = model->surface_count;
    sw_status st = sw_model_begin_part(model, name, color, err);
    if (st == SW_OK)
        st = sw_import_iges_file(path, opts, model, report, err);
    *again = st == SW_OK && model->surface_count == surfaces && report->unsupported.total > 0 &&
             sw_import_occt_available();
    if (*again) {
        snprintf(why, why_size, "read by OpenCASCADE: no surface natively (%.24s)",
                 report->unsupported.kinds ? report->unsupported.kind[0] : "");
        model->part_count--;
    }
    return st;
}

static sw_status import_cad(const build_options *o, const char *path, enum input_kind kind,
                            const sw_import_options *opts, sw_model *model,
                            sw_import_report *report, sw_error *err)
{
    char name[56], why[SW_IMPORT_KIND_CHARS] = "";
    float color[4];
    part_name_for(path, name);
    sw_scene_default_color(model->part_count, color);
    int again = 0;
    if (kind == INPUT_IGES && !o->iges_occt) {
        sw_status st = import_iges_native(path, name, color, opts, model, report, &again, why,
                                          sizeof why, err);
        if (!again)
            return st;
    }
    size_t first = model->part_count;
    sw_status st = sw_import_occt_file(path, opts, model, report, err);
    if (st == SW_OK && model->part_count == first) /* nothing in it: still its part */
        st = sw_model_begin_part(model, name, color, err);
    if (st == SW_OK)
        name_occt_parts(model, first, path);
    if (again)
        sw_import_report_harmless(report, why);   /* told, not a reason to refuse */
    return st;
}

/* --strict: an importer that skipped entities, or read the file despite
 * messages about it, fails the build here. */
static sw_status check_strict(const char *path, const sw_import_report *r, sw_error *err)
{
    if (r->unsupported.total > 0)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "%s: %zu unsupported entities (%s%s) and "
                            "--strict is set", path, r->unsupported.total,
                            r->unsupported.kinds ? r->unsupported.kind[0] : "unknown kind",
                            r->unsupported.kinds > 1 ? ", ..." : "");
    size_t told = sw_import_report_strict_messages(r);
    if (told > 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: %s (%zu message%s about the file, and "
                            "--strict is set)", path, r->first_message, told,
                            told > 1 ? "s" : "");
    return SW_OK;
}

static sw_status add_input(const build_options *o, int i, progress_context *pc, sw_model *model,
                           sw_import_report *report, sw_error *err)
{
    const char *path = o->inputs[i];
    enum input_kind kind = kind_of(path);
    /* OpenCASCADE's faces converted on o->threads, as the levels are made. */
    sw_parts_threads threads;
    sw_parts_runner runner = sw_parts_threads_runner(&threads, o->threads > 1 ? o->threads - 1 : 0);
    sw_import_options opts = { .strict = o->strict, .progress = sw_pack_tool_progress,
                               .progress_user = pc, .runner = o->threads > 1 ? &runner : NULL };
    snprintf(pc->prefix, sizeof pc->prefix, "importing %s", sw_pack_tool_base_name(path));
    pc->surfaces_before = model->surface_count;
    pc->importing = 1;
    sw_status st;
    if (kind == INPUT_SCENE) {
        st = sw_scene_load_with(path, &opts, report, model, err);
    } else if (kind == INPUT_OTHER) {
        char name[56];
        float color[4];
        part_name_for(path, name);
        sw_scene_default_color(model->part_count, color);
        st = sw_model_begin_part(model, name, color, err);
        if (st == SW_OK)
            st = sw_scene_import_file(path, model, err);
    } else {
        st = import_cad(o, path, kind, &opts, model, report, err);
    }
    if (st == SW_OK && o->strict)
        st = check_strict(path, report, err);
    /* The pack keeps one tolerance: the loosest any source was modelled to. */
    if (st == SW_OK && report->model_tolerance_mm > model->model_tolerance)
        model->model_tolerance = (float)report->model_tolerance_mm;
    return st;
}

/* build-part: prototype o->prototype of the plan, packed as build packs
 * it, written as a pack of its own (version 1) for merge. */
static sw_status build_one_prototype(const build_options *o, progress_context *pc,
                                     sw_scene_plan *plan, seam_summary *seams,
                                     size_t *bytes_out, size_t *parts, size_t *patches,
                                     sw_error *err)
{
    if ((size_t)o->prototype >= plan->prototype_count)
        return sw_error_set(err, SW_ERR_ARG, "%s: --prototype %ld, the scene has %zu (0 to %zu)",
                            o->inputs[0], o->prototype, plan->prototype_count,
                            plan->prototype_count - 1);
    size_t k = (size_t)o->prototype;
    uint8_t *bytes = NULL;
    *parts = plan->prototypes[k].part_count, *patches = plan->prototypes[k].patch_count;
    sw_status st = sw_pack_tool_pack_prototype(o, pc, plan, k, &bytes, bytes_out, seams, err);
    if (st == SW_OK)
        st = sw_write_file_atomic(o->out_path, bytes, *bytes_out, err);
    free(bytes);
    return st;
}

/* A scene given alone, as placed parts (sw_pack_tool_pack_scene). */
static sw_status build_scene(const build_options *o, sw_import_report *report,
                             seam_summary *seams, size_t *bytes_out, size_t *parts,
                             size_t *patches, sw_error *err)
{
    const char *path = o->inputs[0];
    sw_model empty;
    sw_model_init(&empty);
    progress_context pc = { .model = &empty };
    sw_progress_init(&pc.bar, stderr, o->quiet);
    sw_parts_threads threads;
    sw_parts_runner runner = sw_parts_threads_runner(&threads, o->threads > 1 ? o->threads - 1 : 0);
    sw_import_options opts = { .strict = o->strict, .progress = sw_pack_tool_progress,
                               .progress_user = &pc, .runner = o->threads > 1 ? &runner : NULL };
    snprintf(pc.prefix, sizeof pc.prefix, "importing %s", sw_pack_tool_base_name(path));
    pc.importing = 1;
    sw_scene_plan plan;
    sw_status st = sw_scene_plan_load(path, &opts, report, &plan, err);
    if (st == SW_OK && o->strict)
        st = check_strict(path, report, err);
    if (st == SW_OK && o->copies)
        st = sw_scene_plan_copies(&plan, err);
    if (st == SW_OK) {
        sw_progress_clear(&pc.bar);
        int32_t up = sw_up_input_default(path, plan.views.up_axis);
        plan.views.up_axis = sw_up_inputs_choose(o->inputs, &up, 1, o->up_axis, stderr);
        sw_scene_plan_placed(&plan, parts, patches);
        if (*patches == 0)
            st = sw_pack_tool_check_not_empty(o, &empty, report, err);
    }
    if (st == SW_OK && o->part_mode)
        st = build_one_prototype(o, &pc, &plan, seams, bytes_out, parts, patches, err);
    else if (st == SW_OK)
        st = sw_pack_tool_pack_scene(o, &pc, &plan, seams, bytes_out, err);
    sw_scene_plan_free(&plan);
    sw_model_free(&empty);
    sw_progress_clear(&pc.bar);
    return st;
}

static sw_status build_pack(const build_options *o, sw_model *model, sw_import_report *reports,
                            seam_summary *seams, size_t *bytes_out, sw_error *err)
{
    progress_context pc = { .model = model };
    sw_progress_init(&pc.bar, stderr, o->quiet);
    sw_status st = SW_OK;
    int32_t *up_defaults = calloc((size_t)o->input_count + 1, sizeof *up_defaults);
    if (!up_defaults)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory");
    for (int i = 0; st == SW_OK && i < o->input_count; i++) {
        model->up_axis = 0; /* what this input's scene says, if it is one */
        st = add_input(o, i, &pc, model, &reports[i], err);
        up_defaults[i] = sw_up_input_default(o->inputs[i], model->up_axis);
    }
    if (st == SW_OK) {
        sw_progress_clear(&pc.bar); /* a warning must not share the bar's line */
        model->up_axis = sw_up_inputs_choose(o->inputs, up_defaults, o->input_count, o->up_axis,
                                           stderr);
        st = sw_pack_tool_check_not_empty(o, model, reports, err);
    }
    if (st == SW_OK) {
        st = sw_pack_tool_pack(o, &pc, model, reports, seams, bytes_out, err);
    }
    free(up_defaults);
    sw_progress_clear(&pc.bar);
    return st;
}

/* One line per kind, its count and what was done, on stderr. */
static void print_tally(const char *name, const sw_import_tally *t, const char *done)
{
    size_t listed = 0;
    for (size_t k = 0; k < t->kinds && k < SW_IMPORT_KINDS; k++) {
        fprintf(stderr, "warning: %s: %zu x ", name, t->count[k]);
        /* the kinds quote OpenCASCADE's words about a file, which may
         * carry the file's bytes */
        sw_fput_escaped(stderr, t->kind[k], SIZE_MAX);
        fprintf(stderr, " %s\n", done);
        listed += t->count[k];
    }
    if (t->total > listed)
        fprintf(stderr, "warning: %s: %zu of other kinds %s\n", name, t->total - listed, done);
}

/* Skipped entities and tolerated messages, per input. */
static void print_warnings(const build_options *o, const sw_import_report *reports)
{
    for (int i = 0; i < o->input_count; i++) {
        const char *name = sw_pack_tool_base_name(o->inputs[i]);
        print_tally(name, &reports[i].unsupported, "skipped");
        print_tally(name, &reports[i].messages, "(read past)");
    }
}

static void print_summary(const build_options *o, size_t parts, size_t patches,
                          const sw_import_report *reports, const seam_summary *seams,
                          size_t bytes, double seconds)
{
    for (int i = 0; i < o->input_count; i++) {
        if (reports[i].pcurves_reprojected > 0)
            printf("seamwalk-pack: %s: %zu parameter curves projected again from their edges "
                   "(the conversion's strayed)\n", sw_pack_tool_base_name(o->inputs[i]),
                   reports[i].pcurves_reprojected);
        if (reports[i].pcurves_computed > 0)
            printf("seamwalk-pack: %s: %zu parameter curves computed from model-space curves\n",
                   sw_pack_tool_base_name(o->inputs[i]), reports[i].pcurves_computed);
        if (reports[i].faces_moved > 0)
            printf("seamwalk-pack: %s: %zu closed faces converted a period along (OpenCASCADE's "
                   "conversion failed where they were)\n", sw_pack_tool_base_name(o->inputs[i]),
                   reports[i].faces_moved);
        if (reports[i].faces_unrolled > 0)
            printf("seamwalk-pack: %s: %zu faces over more than their surface's period put on "
                   "a surface of their own range\n", sw_pack_tool_base_name(o->inputs[i]),
                   reports[i].faces_unrolled);
    }
    const sw_seam_report *r = &seams->sewing;
    printf("seamwalk-pack: seams: %zu boundary vertices, %zu edges (%zu sewn, %zu free, %zu "
           "non-manifold), tolerance %g; %" PRIu32 " collapses; sewing %.2f s, simplifying "
           "%.2f s\n", r->boundary_vertices, r->boundary_edges, r->seams, r->free_edges,
           r->nonmanifold_edges, r->tolerance, seams->collapses, r->flatten_s + r->sew_s,
           seams->simplify_s);
    const sw_seam_reroot_report *cut = &seams->reroot;
    if (seams->seam_floor > 0)
        printf("seamwalk-pack: seams: levels down to %g mm (the bound of a view %g mm away): %"
               PRIu32 " collapses applied, %" PRIu32 " kept so that no loop vanishes; original "
               "vertices %" PRIu32 " -> %" PRIu32 ", slots %" PRIu32 " -> %" PRIu32 "\n",
               seams->seam_floor, seams->seam_floor / SW_CLOSEST_BOUND_PER_MM, cut->applied,
               cut->kept, cut->originals_before, cut->originals_after, cut->slots_before,
               cut->slots_after);
    if (seams->split.cut > 0 || seams->split.uncut > 0)
        printf("seamwalk-pack: seams: %" PRIu32 " surfaces cut into %" PRIu32 " pieces, %" PRIu32
               " left whole: their loops held more than %d points (one draw shows 65536 "
               "vertices)\n", seams->split.cut, seams->split.pieces, seams->split.uncut,
               SW_SEAM_SPLIT_POINTS);
    if (seams->pinned_surfaces > 0)
        printf("seamwalk-pack: seams: kept whole on %" PRIu32 " surfaces that would not "
               "tessellate simplified\n", seams->pinned_surfaces);
    if (r->clamped > 0)
        printf("seamwalk-pack: seams: %zu trim points outside their surface's domain put on its "
               "border\n", r->clamped);
    if (r->gaps_held > 0)
        printf("seamwalk-pack: seams: %zu trim vertices sewn within %g of the model's size, not "
               "their edges' wider tolerance\n", r->gaps_held, SW_SEAM_GAP_CAP);
    const sw_levels_report *l = &seams->levels;
    printf("seamwalk-pack: static levels: %" PRIu32 " of %" PRIu32 " surfaces, %" PRIu32
           " levels, triangles by rank %" PRIu64 " %" PRIu64 " %" PRIu64 " %" PRIu64
           "; left out: %" PRIu32 " refused, %" PRIu32 " over 65536 vertices, %" PRIu32
           " with a border not one chain per loop; %.2f s\n", l->with_levels, l->surfaces,
           l->levels, l->triangles[0], l->triangles[1], l->triangles[2], l->triangles[3],
           l->refused, l->too_large, l->bad_border, l->seconds);
    const sw_cluster_report *k = &seams->clusters;
    printf("seamwalk-pack: super-surfaces: %" PRIu32 " of %" PRIu32 " surfaces (%" PRIu32
           " small ones merged, %" PRIu32 " alone wider than alpha, %" PRIu32 " stopped by a "
           "cap); %.2f s\n", k->clusters, k->surfaces, k->merged, k->wide_alone, k->capped,
           k->seconds);
    const sw_part_levels_report *pl = &seams->part_levels;
    printf("seamwalk-pack: part levels: %" PRIu32 " of %" PRIu32 " pieces (%" PRIu32 " parts, %"
           PRIu32 " cut into pieces), %" PRIu32 " levels from %" PRIu64 " source triangles, "
           "triangles by rank %" PRIu64 " %" PRIu64 " %" PRIu64 " %" PRIu64 "; left out: %" PRIu32
           " pieces with a surface without a level, %" PRIu32 " bounds with nothing found within, %" PRIu32
           " tries not smaller, %" PRIu32 " folded, %" PRIu32 " over 65536 vertices; worst error "
           "over bound %.2f; %.2f s\n",
           pl->with_levels, pl->pieces, pl->parts, pl->cut_parts, pl->levels,
           pl->source_triangles, pl->triangles[0], pl->triangles[1], pl->triangles[2],
           pl->triangles[3], pl->incomplete, pl->over_bound, pl->not_smaller, pl->folded, pl->too_large,
           pl->worst_over_bound, pl->seconds);
    printf("seamwalk-pack: %zu parts, %zu patches, %zu bytes -> %s (%.2f s, %" PRIu32
           " thread%s)\n", parts, patches, bytes, o->out_path, seconds,
           o->threads > 1 ? o->threads : 1, o->threads > 1 ? "s" : "");
}

/* --threads' default: the machine's cores. */
static uint32_t online_cores(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return cores > 1 ? (uint32_t)(cores < 64 ? cores : 64) : 1;
}

/* Parses build's arguments into o; returns 0 or the usage exit status. */
static int parse_build(int argc, char **argv, build_options *o)
{
    o->threads = online_cores();
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-o") == 0) {
            if (i + 1 == argc || o->out_path)
                return usage_error("build: %s needs exactly one OUT.swpack", "-o");
            o->out_path = argv[++i];
        } else if (strcmp(a, "--iges-reader") == 0) {
            const char *r = i + 1 < argc ? argv[++i] : "";
            if (strcmp(r, "native") != 0 && strcmp(r, "occt") != 0)
                return usage_error("build: --iges-reader takes native or occt, not '%s'", r);
            o->iges_occt = strcmp(r, "occt") == 0;
        } else if (strcmp(a, "--seam-tolerance") == 0) {
            const char *t = i + 1 < argc ? argv[++i] : "";
            char *end;
            o->seam_tolerance = strtod(t, &end);
            if (end == t || *end != '\0' || !(o->seam_tolerance > 0) ||
                !(o->seam_tolerance < 1e30))
                return usage_error("build: --seam-tolerance takes a length in mm > 0, not '%s'",
                                   t);
        } else if (strcmp(a, "--closest-mm") == 0) {
            const char *t = i + 1 < argc ? argv[++i] : "";
            char *end;
            o->closest_mm = strtod(t, &end);
            if (end == t || *end != '\0' || !(o->closest_mm > 0) || !(o->closest_mm < 1e30))
                return usage_error("build: --closest-mm takes a length in mm > 0, not '%s'", t);
        } else if (strcmp(a, "--cut-patches") == 0) {
            const char *t = i + 1 < argc ? argv[++i] : "";
            char *end;
            unsigned long n = strtoul(t, &end, 10);
            if (end == t || *end != '\0' || t[0] == '-' || n > UINT32_MAX)
                return usage_error("build: --cut-patches takes a patch count (0: none cut), "
                                   "not '%s'", t);
            o->part_levels.cut_patches = n ? (uint32_t)n : UINT32_MAX;
        } else if (strcmp(a, "--threads") == 0) {
            const char *t = i + 1 < argc ? argv[++i] : "";
            char *end;
            unsigned long n = strtoul(t, &end, 10);
            if (end == t || *end != '\0' || t[0] == '-')
                return usage_error("build: --threads takes a thread count, not '%s'", t);
            o->threads = n < 64 ? (uint32_t)n : 64;
        } else if (strcmp(a, "--up") == 0) {
            const char *u = i + 1 < argc ? argv[++i] : "";
            if (!sw_up_axis_parse(u, &o->up_axis))
                return usage_error("build: --up takes x, y, z, -x, -y or -z, not '%s'", u);
        } else if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
        } else if (strcmp(a, "--copies") == 0) {
            o->copies = 1;
        } else if (o->part_mode && strcmp(a, "--prototype") == 0) {
            const char *t = i + 1 < argc ? argv[++i] : "";
            char *end;
            o->prototype = strtol(t, &end, 10);
            if (end == t || *end != '\0' || o->prototype < 0)
                return usage_error("build-part: --prototype takes a prototype's number from 0, "
                                   "not '%s'", t);
        } else if (strcmp(a, "--strict") == 0) {
            o->strict = 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("build: unknown option '%s'", a);
        } else {
            o->inputs[o->input_count++] = a;
        }
    }
    if (!o->out_path || o->input_count == 0)
        return usage_error("build: %s", !o->out_path ? "missing -o OUT.swpack" : "no INPUT");
    if (o->part_mode && (o->input_count != 1 || kind_of(o->inputs[0]) != INPUT_SCENE ||
                         o->prototype < 0 || o->copies))
        return usage_error("build-part: %s", "takes one SCENE.ini and --prototype K");
    return 0;
}

/* The output, checked before a build that may take minutes: not a
 * directory, and its folder takes a new file (a probe created beside it,
 * as the final write's temporary will be, and removed). */
static sw_status check_output(const char *path, sw_error *err)
{
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return sw_error_set(err, SW_ERR_ARG, "%s: a directory, expected the pack's file name "
                            "(-o)", path);
    char probe[4200];
    if (snprintf(probe, sizeof probe, "%s.tmp-XXXXXX", path) >= (int)sizeof probe)
        return sw_error_set(err, SW_ERR_ARG, "%.200s...: the output's name is too long", path);
    int fd = mkstemp(probe);
    if (fd < 0) {
        int e = errno;
        const char *slash = strrchr(path, '/');
        int dir_len = slash ? (int)(slash - path) : 1;
        return sw_error_set(err, SW_ERR_IO, "%s: cannot write there (%.*s: %s); nothing was built",
                            path, dir_len, slash ? (slash == path ? "/" : path) : ".",
                            strerror(e));
    }
    close(fd);
    unlink(probe);
    return SW_OK;
}

static int cmd_build(int argc, char **argv, int part_mode)
{
    build_options o = { .inputs = calloc((size_t)argc + 1, sizeof(char *)),
                        .part_mode = part_mode, .prototype = -1 };
    sw_import_report *reports = calloc((size_t)argc + 1, sizeof *reports);
    if (!o.inputs || !reports) {
        free(o.inputs);
        free(reports);
        return fail(&(sw_error){SW_ERR_NO_MEMORY, "out of memory"});
    }
    int rc = parse_build(argc, argv, &o);
    sw_error out_err = {0};
    if (rc == 0 && check_output(o.out_path, &out_err) != SW_OK)
        rc = fail(&out_err);
    if (rc == 0) {
        sw_model model;
        sw_model_init(&model);
        sw_error err = {0};
        size_t bytes = 0;
        double t0 = sw_pack_tool_now_s();
        seam_summary seams = { 0 };
        size_t parts = 0, patches = 0;
        int placed = o.input_count == 1 && kind_of(o.inputs[0]) == INPUT_SCENE;
        sw_status st = placed ? build_scene(&o, reports, &seams, &bytes, &parts, &patches, &err)
                              : build_pack(&o, &model, reports, &seams, &bytes, &err);
        if (!placed)
            parts = model.part_count, patches = model.patch_count;
        if (st == SW_OK) {
            print_warnings(&o, reports);
            if (!o.quiet)
                print_summary(&o, parts, patches, reports, &seams, bytes,
                              sw_pack_tool_now_s() - t0);
        }
        rc = st == SW_OK ? 0 : fail(&err);
        sw_model_free(&model);
    }
    free(o.inputs);
    free(reports);
    return rc;
}

/* ---- reading a pack --------------------------------------------------- */

/* Reads and validates the pack at path; *bytes must be freed by the caller.
 * malloc's alignment (16 on the hosts we build on) meets the reader's 8. */
static sw_status open_pack(const char *path, char **bytes, sw_pack *pack, sw_error *err)
{
    size_t size;
    sw_status st = sw_read_whole_file(path, bytes, &size, err);
    if (st != SW_OK)
        return st;
    st = sw_pack_open_memory(*bytes, size, pack, err);
    if (st != SW_OK)
        sw_error_prefix(err, "%s", path);
    return st;
}

static int cmd_info(int argc, char **argv)
{
    int json = 0;
    const char *path = NULL;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (argv[i][0] == '-' && argv[i][1] != '\0')
            return usage_error("info: unknown option '%s'", argv[i]);
        else if (path)
            return usage_error("info: more than one PACK ('%s')", argv[i]);
        else
            path = argv[i];
    }
    if (!path)
        return usage_error("info: %s", "missing PACK");
    char *bytes = NULL;
    sw_pack pack;
    sw_error err = {0};
    if (open_pack(path, &bytes, &pack, &err) != SW_OK) {
        free(bytes);
        return fail(&err);
    }
    sw_status st = sw_pack_print_info(stdout, path, &pack, json, &err);
    free(bytes);
    return st == SW_OK ? 0 : fail(&err);
}

/* ---- verify --------------------------------------------------------------- */

static int cmd_verify(int argc, char **argv)
{
    if (argc > 1)   /* verify PACK --key KEYS: also the signature (sw_pack_sign.h) */
        return sw_pack_cmd_verify_signed(argc, argv);
    if (argc != 1 || (argv[0][0] == '-' && argv[0][1] != '\0'))
        return usage_error("verify: %s", "expected exactly one PACK");
    char *bytes = NULL;
    sw_pack pack;
    sw_error err = {0};
    sw_status st = open_pack(argv[0], &bytes, &pack, &err);
    sw_pack_tess_report tess;
    if (st == SW_OK) {
        st = sw_pack_verify_tessellation(&pack, &tess, &err);
        if (st != SW_OK)
            sw_error_prefix(&err, "%s", argv[0]);
    }
    if (st == SW_OK)
        printf("%s: ok (%" PRIu32 " patches, %" PRIu64 " bytes; %" PRIu32 " surfaces tessellate "
               "at %" PRIu32 " seam states from the finest to the coarsest drawn, %" PRIu32
               " tessellations, %" PRIu32 " without their holes, %" PRIu32 " with slits cut)\n",
               argv[0], pack.meta->patch_count, pack.header->total_size, tess.surfaces,
               tess.states, tess.checks, tess.holes_filled, tess.untangled);
    free(bytes);
    return st == SW_OK ? 0 : fail(&err);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return usage_error("%s", "missing command");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        puts("seamwalk-pack " SW_VERSION);
        return fflush(stdout) == 0 ? 0 : 1;
    }
    int rc;
    if (strcmp(cmd, "build") == 0)
        rc = cmd_build(argc - 2, argv + 2, 0);
    else if (strcmp(cmd, "build-part") == 0)
        rc = cmd_build(argc - 2, argv + 2, 1);
    else if (strcmp(cmd, "merge") == 0)
        rc = sw_pack_cmd_merge(argc - 2, argv + 2);
    else if (strcmp(cmd, "ninja") == 0)
        rc = sw_pack_cmd_ninja(argc - 2, argv + 2);
    else if (strcmp(cmd, "info") == 0)
        rc = cmd_info(argc - 2, argv + 2);
    else if (strcmp(cmd, "verify") == 0)
        rc = cmd_verify(argc - 2, argv + 2);
    else if (strcmp(cmd, "keygen") == 0)
        rc = sw_pack_cmd_keygen(argc - 2, argv + 2);
    else if (strcmp(cmd, "sign") == 0)
        rc = sw_pack_cmd_sign(argc - 2, argv + 2);
    else if (strcmp(cmd, "gen") == 0)
        rc = sw_pack_cmd_gen(argc - 2, argv + 2);
    else
        return usage_error("unknown command '%s'", cmd);
    /* A full disk or closed pipe on stdout is a failure, not a silent success. */
    if (fflush(stdout) != 0 && rc == 0) {
        fprintf(stderr, "seamwalk-pack: cannot write to standard output\n");
        rc = 1;
    }
    return rc;
}
