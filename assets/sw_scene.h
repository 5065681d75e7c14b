/* Showroom scenes: an INI file that places several model files as parts of
 * one sw_model. Host only; called by seamwalk-pack and the fuzz target. Later
 * formats (IGES, STEP) plug into sw_scene_import_file, later section kinds
 * (named viewpoints) into the section table in sw_scene.c.
 *
 *   [part teapot]                ; one section per part; the name is the part's
 *   file = teapot.txt            ; required; relative to the scene's folder
 *   translate = 0 0 0            ; optional, default 0 0 0
 *   rotate = 0 1 0 90            ; optional: axis x y z, angle in degrees
 *   scale = 1                    ; optional: s, or sx sy sz (non-zero)
 *   color = 0.8 0.3 0.2          ; optional: linear RGB in 0..1, optional alpha
 *
 * Transforms apply scale, then rotate, then translate. Comments start with ';'
 * or '#' at the start of a line, or ';' after a blank inside a line. Unknown
 * sections and keys, repeated keys or parts, a section without keys, indented
 * (continuation) lines and lines longer than 198 bytes are errors naming
 * file:line. Part names are at most 44 bytes, because inih keeps only 49 bytes
 * of a section name. */
#ifndef SW_SCENE_H
#define SW_SCENE_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"

/* Loads the scene at path, adding one part per [part] section to model.
 * Relative file names resolve against the scene file's folder. On failure the
 * model may hold the parts loaded before the error; the caller frees it. */
sw_status sw_scene_load(const char *path, sw_model *model, sw_error *err);

/* The same from size bytes of text (need not be NUL-terminated). file_name is
 * used in messages; relative part files resolve against base_dir (NULL or ""
 * for the working directory). */
sw_status sw_scene_load_memory(const char *text, size_t size, const char *file_name,
                               const char *base_dir, sw_model *model, sw_error *err);

/* Imports one model file into the model's current part, chosen by extension
 * (case-insensitive): .txt Newell listing, .bpt Bezier patch text. Other
 * extensions give SW_ERR_UNSUPPORTED. */
sw_status sw_scene_import_file(const char *path, sw_model *model, sw_error *err);

/* 1 when path names a scene (.ini), 0 otherwise. */
int sw_scene_is_scene_path(const char *path);

/* The colour a part gets when nothing says otherwise: a small palette of
 * distinct, muted colours, cycling with index. */
void sw_scene_default_color(size_t index, float out[4]);

#endif
