/* SPDX-License-Identifier: MIT */
/* Showroom scenes: an INI file that places parts (model files or generated
 * objects) and named viewpoints in one sw_model. Host only; called by
 * seamwalk-pack build, the showroom generator and the fuzz target. The format
 * in full (assets/SCENE_FORMAT.md says the same with examples):
 *
 *   up_axis = z            ; before any section, optional: the model axis that
 *                          ; points up (x, y, z, -x, -y, -z; default y), into
 *                          ; model->up_axis; not rotated, the camera turns
 *   [part teapot]          ; one section per part; the name is the part's
 *   file = teapot.txt      ; a model file, relative to the scene's folder, or
 *   generate = vase        ; a procedural object: plate, vase or rail
 *   units = in             ; mm (default), cm, m, in or ft: the unit of a
 *                          ; unitless file (.txt, .bpt); an error for .igs,
 *                          ; .iges, .stp, .step (they carry units) and for
 *                          ; generated parts (millimetres)
 *   translate = 0 0 0      ; millimetres, default 0 0 0
 *   rotate = 0 1 0 90      ; axis x y z (not zero), angle in degrees
 *   scale = 1              ; s, or sx sy sz (none zero)
 *   color = 0.8 0.3 0.2    ; linear RGB in 0..1, optional alpha
 *   ; generated parts only (sw_procedural.h says what each kind reads):
 *   size = 300             ; mm: plate side, vase widest diameter, rail length
 *   height = 600           ; mm: plate height above the floor, vase height,
 *                          ;     rail section height
 *   holes = 4              ; plate: circular holes, rail: slots (not vase)
 *   segments = 6           ; B-spline spans: plate per side, vase profile,
 *                          ;     rail path
 *   seed = 7               ; 0 .. 2^64-1; the same seed, the same object
 *
 *   [view entrance]        ; a named viewpoint (sw_model_add_viewpoint)
 *   eye = 0 1600 -5000     ; required, millimetres in the scene
 *   target = 0 800 0       ; required, not equal to eye
 *   up = 0 1 0             ; optional, default 0 1 0, not along eye->target
 *   fov = 60               ; optional: vertical field of view in degrees,
 *                          ; 0 < fov < 180; absent: the runtime's default
 *
 * A part has exactly one of file and generate. File types go by extension,
 * case-insensitive: .txt Newell listing, .bpt Bezier patch text, .igs/.iges
 * IGES (native reader), .stp/.step STEP (OpenCASCADE). Everything in the model
 * is millimetres: a part's points are mapped by units, then scale, then
 * rotate, then translate. Size parameters out of range (sw_proc_check) and
 * parameters a kind does not take are errors at their line.
 *
 * Comments start with ';' or '#' at the start of a line, or ';' after a blank
 * inside a line. Unknown sections and keys, repeated keys, parts or views
 * (parts and views are named separately), a section without keys, indented
 * (continuation) lines and lines longer than 198 bytes are errors naming
 * file:line; so are errors inside part files ("s.ini:3: part 'a': a.bpt:5:3:
 * ..."). Names are at most 44 bytes, because inih keeps only 49 bytes of a
 * section name. At least one part is required. */
#ifndef SW_SCENE_H
#define SW_SCENE_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_import.h"
#include "sw_model.h"

/* Loads the scene at path, adding one part per [part] section to the model
 * (more if an importer splits a file into several) and one viewpoint per
 * [view]. Relative file names resolve against the scene file's folder. On
 * failure the model may hold the parts loaded before the error; the caller
 * frees it. options (NULL: defaults) go to the IGES and STEP importers;
 * report (may be NULL) sums their reports over the files read. A file named
 * by several parts is read once and copied. */
sw_status sw_scene_load_with(const char *path, const sw_import_options *options,
                             sw_import_report *report, sw_model *model, sw_error *err);
sw_status sw_scene_load(const char *path, sw_model *model, sw_error *err);

/* The same from size bytes of text (need not be NUL-terminated). file_name is
 * used in messages; relative part files resolve against base_dir (NULL or ""
 * for the working directory). */
sw_status sw_scene_load_memory_with(const char *text, size_t size, const char *file_name,
                                    const char *base_dir, const sw_import_options *options,
                                    sw_import_report *report, sw_model *model, sw_error *err);
sw_status sw_scene_load_memory(const char *text, size_t size, const char *file_name,
                               const char *base_dir, sw_model *model, sw_error *err);

/* Imports one model file into the model's current part, chosen by extension
 * (case-insensitive): .txt, .bpt, .igs/.iges, .stp/.step; others give
 * SW_ERR_UNSUPPORTED. Unitless files are taken as millimetres. report (may be
 * NULL) gets the importer's report added to it. */
sw_status sw_scene_import_file_with(const char *path, const sw_import_options *options,
                                    sw_import_report *report, sw_model *model, sw_error *err);
sw_status sw_scene_import_file(const char *path, sw_model *model, sw_error *err);

/* The same scene as parts stored once and placed (core/sw_pack_instances.h,
 * sw_scene_plan.c): each file or generated object the scene names is one
 * prototype, whatever the number of parts naming it, loaded once in its own
 * frame (its file's millimetres; a part's scale is left to its placement
 * when it is uniform and applied to the prototype when it is not, so such
 * a part shares only with parts of the same scales); each [part] is one
 * placement of it: the units, the uniform scale, the rotation and the
 * translation as one similarity transform, its colour and its name. */
typedef struct sw_scene_placement {
    size_t prototype;
    float transform[16];        /* column-major, as sw_pack_instance.transform */
    double scale;               /* the transform's uniform scale */
    double prototype_scale;     /* the largest scale its prototype is placed at: its copies
                                   (seamwalk-pack build --copies) keep it, and with it the
                                   prototype's sewing tolerance */
    float color[4];
    char name[56];
} sw_scene_placement;

typedef struct sw_scene_plan {
    sw_model *prototypes;       /* prototype_count models (empty when not imported) */
    size_t prototype_count;
    char **sources;             /* each prototype's file, NULL for a generated object */
    sw_import_report *reports;  /* each prototype's import (zero for a generated object or
                                   a file another prototype read first) */
    sw_scene_placement *placements;
    size_t placement_count;
    sw_model views;             /* the scene's viewpoints and up axis; no parts */
} sw_scene_plan;

/* Loads the scene at path as a plan (errors as sw_scene_load_with's);
 * report (may be NULL) gets the imports' reports summed. The caller frees
 * the plan with sw_scene_plan_free, also after a failure. */
sw_status sw_scene_plan_load(const char *path, const sw_import_options *options,
                             sw_import_report *report, sw_scene_plan *plan, sw_error *err);

/* The same without importing anything: the prototypes (their sources),
 * the placements and the views, for merging packs built apart and writing
 * build files (the prototype models stay empty). */
sw_status sw_scene_plan_read(const char *path, sw_scene_plan *plan, sw_error *err);
void sw_scene_plan_free(sw_scene_plan *plan);

/* The parts and patches the plan places, all placements together. */
void sw_scene_plan_placed(const sw_scene_plan *plan, size_t *parts, size_t *patches);

/* The plan made one prototype per placement (a copy of its prototype's
 * parts, with its file's import told once): the scene stored as copies,
 * placed all the same (seamwalk-pack build --copies). */
sw_status sw_scene_plan_copies(sw_scene_plan *plan, sw_error *err);

/* 1 when path names a scene (.ini), 0 otherwise. */
int sw_scene_is_scene_path(const char *path);

/* The colour a part gets when nothing says otherwise: a small palette of
 * distinct, muted colours, cycling with index. */
void sw_scene_default_color(size_t index, float out[4]);

#endif
