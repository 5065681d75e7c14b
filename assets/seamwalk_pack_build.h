/* SPDX-License-Identifier: MIT */
/* seamwalk-pack build, from the imported model to a verified pack on disk
 * (seamwalk_pack_build.c): the trims sewn and the seams simplified, the
 * pack serialised with its static levels, super-surfaces and part levels,
 * verified as `verify` will (a surface refused keeps its seams whole,
 * round after round), then written atomically. The command line, the
 * importing and the summary are seamwalk_pack_main.c's. Host only:
 * allocates. */
#ifndef SEAMWALK_PACK_BUILD_H
#define SEAMWALK_PACK_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "sw_cluster.h"
#include "sw_error.h"
#include "sw_import.h"
#include "sw_levels_build.h"
#include "sw_model.h"
#include "sw_pack.h"
#include "sw_part_levels_build.h"
#include "sw_progress.h"
#include "sw_scene.h"
#include "sw_seam_reroot.h"
#include "sw_seam_sew.h"
#include "sw_seam_split.h"

typedef struct build_options {
    const char *out_path;
    const char **inputs;
    int input_count;
    int quiet, strict, iges_occt;
    int copies;                 /* --copies: a scene's parts stored one copy per placement */
    int part_mode;              /* build-part: one prototype of a scene (prototype) */
    long prototype;
    double seam_tolerance;      /* 0: sw_seam_default_tolerance */
    double closest_mm;          /* --closest-mm: the nearest a view comes to a surface;
                                   0: sw_pack_tool_default_closest_mm */
    double seam_floor;          /* the seam hierarchy's finest error, model units: the bound
                                   at closest_mm (sw_pack_tool_seam_floor); 0: none */
    sw_part_levels_options part_levels;   /* --cut-patches */
    uint32_t threads;           /* --threads: make the levels on (0 or 1: this one alone) */
    int32_t up_axis;            /* --up (sw_up_axis.h); 0: by the inputs (sw_up_inputs.h) */
} build_options;

/* What the progress callbacks need to label a stage and count its rate:
 * faces are the surfaces the importer added so far, patches the fraction of
 * the model's. */
typedef struct progress_context {
    sw_progress bar;
    const sw_model *model;
    char prefix[80];            /* "importing hammer.iges" or "packing" */
    size_t surfaces_before;
    int importing;
} progress_context;

/* The Seam Graph (paper 004, sections 4-5): the trims flattened and sewn
 * across surfaces, then the collapse hierarchy over the seams. */
typedef struct seam_summary {
    sw_seam_report sewing;
    uint32_t collapses;
    double simplify_s;
    sw_levels_report levels;
    sw_cluster_report clusters;
    sw_part_levels_report part_levels;
    uint32_t pinned_surfaces;   /* whose seams were kept whole so that they tessellate */
    sw_seam_split_report split; /* surfaces cut: their loops too long for one draw */
    double seam_floor;          /* the finest seam error kept, model units (0: all) */
    sw_seam_reroot_report reroot; /* the collapses no view undoes, applied for good */
} seam_summary;

/* The bound a view closest_mm away asks for (model units are millimetres):
 * half a pixel of a 1080-row display with the runtime's 45-degree field
 * of view (its defaults, --max-error-px and --fov-deg). A unit that shows
 * more rows, or a view that comes closer, asks for finer: the runtime draws
 * the floor there and counts the surfaces it clamped. */
#define SW_CLOSEST_BOUND_PER_MM 3.8352e-4
double sw_pack_tool_seam_floor(double closest_mm);

/* Where the option is not given: a hundredth of the model's (or the
 * placed scene's) diagonal, diagonal in millimetres. */
double sw_pack_tool_default_closest_mm(double diagonal);

/* The build's progress line (a sw_progress callback; user: a
 * progress_context). */
void sw_pack_tool_progress(void *user, const char *stage, double fraction);

/* Seconds on a monotonic clock. */
double sw_pack_tool_now_s(void);

/* The file name of path without its folders. */
const char *sw_pack_tool_base_name(const char *path);

/* A model with nothing to draw makes a pack the runtime refuses: the build
 * fails instead, saying what was left out (SW_ERR_FORMAT). */
sw_status sw_pack_tool_check_not_empty(const build_options *o, const sw_model *model,
                                       const sw_import_report *reports, sw_error *err);

/* The model packed and verified into *bytes (malloc'd, *size bytes), with
 * the notes given (not owned), the sewing, levels and repairs counted in
 * *summary. */
sw_status sw_pack_tool_pack_bytes(const build_options *o, progress_context *pc, sw_model *model,
                                  const sw_pack_import_note *notes, uint32_t note_count,
                                  seam_summary *summary, uint8_t **bytes, size_t *size,
                                  sw_error *err);

/* The import notes of the inputs' reports (malloc'd). */
sw_status sw_pack_tool_notes(const build_options *o, const sw_import_report *reports,
                             sw_pack_import_note **notes, uint32_t *note_count, sw_error *err);

/* A scene as placed parts (version 2, seamwalk_pack_scene.c): each of
 * plan's prototypes packed and verified on its own, in its own frame and
 * at its own tolerance, then merged, placed, read back and written to
 * o->out_path; the summary sums the prototypes'. */
sw_status sw_pack_tool_pack_scene(const build_options *o, progress_context *pc,
                                  sw_scene_plan *plan, seam_summary *summary, size_t *bytes_out,
                                  sw_error *err);

/* Its steps, for building parts apart (seamwalk_pack_parts.c): prototype k
 * packed as the whole build packs it, the same bytes (its import's notes
 * in it, the summary's tolerance in the scene's units); and the packs of
 * every prototype, in order, merged and placed as plan says, read back. */
sw_status sw_pack_tool_pack_prototype(const build_options *o, progress_context *pc,
                                      sw_scene_plan *plan, size_t k, uint8_t **bytes,
                                      size_t *size, seam_summary *summary, sw_error *err);
sw_status sw_pack_tool_place(const sw_scene_plan *plan, uint8_t *const *bytes,
                             const size_t *sizes, uint8_t **out, size_t *out_size, sw_error *err);

/* The model packed, verified and written to o->out_path, the sewing,
 * levels and repairs counted in *summary, the bytes written in
 * *bytes_out. */
sw_status sw_pack_tool_pack(const build_options *o, progress_context *pc, sw_model *model,
                            const sw_import_report *reports, seam_summary *summary,
                            size_t *bytes_out, sw_error *err);

#endif
