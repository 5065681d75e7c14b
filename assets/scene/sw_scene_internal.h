/* SPDX-License-Identifier: MIT */
/* What the two halves of the scene reader share: sw_scene.c reads lines,
 * drives inih and loads parts; sw_scene_keys.c understands sections and keys
 * and checks each section once the whole file is read. Internal to assets/. */
#ifndef SW_SCENE_INTERNAL_H
#define SW_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_import.h"
#include "sw_model.h"
#include "sw_procedural.h"

enum { SCENE_NAME_MAX = 44, SCENE_SECTION_MAX = 49, SCENE_PATH_MAX = 4096 };

/* Keys of a [part], by bit number; key_line[k] is where key k was given. */
enum scene_part_key {
    PK_FILE,
    PK_GENERATE,
    PK_TRANSLATE,
    PK_ROTATE,
    PK_SCALE,
    PK_COLOR,
    PK_UNITS,
    PK_SIZE,
    PK_HEIGHT,
    PK_HOLES,
    PK_SEGMENTS,
    PK_SEED,
    PK_COUNT
};

/* Keys of a [view]. */
enum scene_view_key { VK_EYE, VK_TARGET, VK_UP, VK_FOV, VK_COUNT };

typedef struct scene_part {
    char name[SCENE_NAME_MAX + 1];
    char file[256];             /* as written; inih lines are shorter */
    long line;                  /* of the section header */
    long key_line[PK_COUNT];    /* 0: not given */
    double translate[3], axis[3], angle_deg, scale[3];
    double units_to_mm;         /* 1 unless `units` says otherwise */
    float color[4];
    sw_proc_params proc;        /* kind 0 unless `generate` */
} scene_part;

typedef struct scene_view {
    char name[SCENE_NAME_MAX + 1];
    long line;
    long key_line[VK_COUNT];
    double eye[3], target[3], up[3], fov_deg;
} scene_view;

typedef struct scene_state {
    const char *text;
    size_t size, pos;
    const char *file_name;
    long line;                  /* of the line inih is working on */
    long pending_section;       /* line of a header no key has followed yet, or 0 */
    char section[64];           /* inih's name of the section being filled */
    int section_kind;           /* index into the section table of the section being filled */
    scene_part *parts;
    size_t part_count, part_capacity;
    scene_view *views;
    size_t view_count, view_capacity;
    int32_t up_axis;            /* the scene's up_axis (sw_up_axis.h), if given: */
    long up_axis_line;          /* where; 0: not given */
    sw_error *err;
    long error_line;            /* 0 while no error is recorded */
    sw_status status;           /* of the recorded error */
} scene_state;

/* Record the first error at the current line, at the header of the section
 * being started, or at a given line; all return 0 (inih's "failed"). */
int scene_fail(scene_state *st, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int section_fail(scene_state *st, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int scene_fail_at(scene_state *st, long line, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Section kinds by their first word: "[part NAME]", "[view NAME]". */
typedef struct scene_section_kind {
    const char *word;
    int (*begin)(scene_state *st, const char *name);
    int (*key)(scene_state *st, const char *name, const char *value);
} scene_section_kind;

/* A key before the first section: only up_axis (the model's up axis). */
int scene_top_key(scene_state *st, const char *name, const char *value);

extern const scene_section_kind scene_section_kinds[];
extern const size_t scene_section_kind_count;

/* Checks every section once the file is read (required keys, keys that do
 * not go together); 0 after recording an error. */
int scene_check_sections(scene_state *st);

/* The extension of path's last component, including the dot, or "". */
const char *scene_extension(const char *path);

/* 1 when the file's format declares its own units (IGES, STEP). */
int scene_file_has_units(const char *path);

/* Part files read once per scene load (sw_scene_cache.c): a showroom names
 * one file for many parts, and STEP or IGES import costs far more than
 * copying surfaces. Each file is imported into a model of its own, then
 * copied into the scene's model for every part that names it. */
typedef struct scene_cache_entry {
    char *path;
    sw_model model;
} scene_cache_entry;

typedef struct scene_cache {
    scene_cache_entry *entries;
    size_t count, capacity;
} scene_cache;

void scene_cache_free(scene_cache *cache);

/* Runs inih over st->text; on success st holds every checked section
 * (sw_scene.c). */
sw_status scene_parse(scene_state *st);

/* base_dir/file, or file itself when it is absolute or there is no base. */
sw_status scene_resolve_path(const char *base_dir, const char *file, char out[SCENE_PATH_MAX],
                             sw_error *err);

/* The folder of path (relative part files resolve against it), "" for none. */
sw_status scene_base_dir(const char *path, char out[SCENE_PATH_MAX], sw_error *err);

/* A [view] added to the model's viewpoints, errors at its line. */
sw_status scene_load_view(const scene_state *st, const scene_view *view, sw_model *model,
                          sw_error *err);

/* Adds the file's parts to model, untransformed: the first named name and
 * coloured color, any more (an assembly) as the importer named them. The
 * file is imported on first use (report gets that import's report). */
sw_status scene_cache_place(scene_cache *cache, const char *path, const char *name,
                            const float color[4], const sw_import_options *options,
                            sw_import_report *report, sw_model *model, sw_error *err);

#endif
