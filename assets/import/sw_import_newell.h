/* SPDX-License-Identifier: MIT */
/* Importer for Martin Newell's Bezier patch listings (the teaset: teapot,
 * teacup, teaspoon), as distributed with freeglut. Host only; called by the
 * scene loader, seamwalk-pack and the fuzz target.
 *
 * Format, line by line:
 *   1   a title (ignored)
 *   2   four counts: vertices, objects, patch lines, and a fourth number
 *       (28 for the teapot, 16 for the spoon, 14 of 26 for the two-object cup:
 *       apparently the first object's patches). Only vertices and patch lines
 *       are used; the other two must be non-negative integers.
 *   then one line per vertex, `index x y z`, index counting 1, 2, 3, ...
 *   then one line per patch, 16 vertex indices counting from 1; the first is
 *   written with a leading '-' (accepted with or without it).
 * Blank lines between records are allowed; anything after the last patch is
 * an error.
 *
 * Control point order: the listing gives the 16 indices as four groups of
 * four, and the index inside a group runs along v. So listing position
 * g * 4 + k becomes control point (i = g, j = k), stored at ctrl[(k * 4 + g) * 4]
 * in sw_bezier_patch layout. With this choice cross(F_u, F_v) points out of the
 * teapot's body, as a renderer culling back faces expects. */
#ifndef SW_IMPORT_NEWELL_H
#define SW_IMPORT_NEWELL_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"

/* Parses size bytes of text (need not be NUL-terminated) and appends every
 * patch as a polynomial bicubic to the model's current part. file_name is
 * used in messages ("teapot.txt:42: ..."). On a format error nothing is added;
 * on SW_ERR_NO_MEMORY the model may hold some of the file's patches. */
sw_status sw_import_newell_memory(const char *text, size_t size, const char *file_name,
                                  sw_model *model, sw_error *err);

/* Reads the file at path and imports it as above; messages name the path. */
sw_status sw_import_newell_file(const char *path, sw_model *model, sw_error *err);

#endif
