/* SPDX-License-Identifier: MIT */
/* Importer for .bpt (Bezier patch text) files: any number of polynomial
 * tensor-product Bezier patches of degree 1..15 in each direction. Host only;
 * called by the scene loader, seamwalk-pack and the fuzz target.
 *
 * Format, line by line:
 *   the patch count (at least 1)
 *   per patch: a line `du dv` (degrees in u and v), then (du+1)*(dv+1) lines
 *   `x y z`, one control point each.
 * The points come row by row with u running fastest: point number
 * j * (du + 1) + i of a patch (counting from 0) is control point (i, j), which
 * is exactly the sw_bezier_patch layout. Blank lines between records are
 * allowed; anything after the last patch is an error. */
#ifndef SW_IMPORT_BPT_H
#define SW_IMPORT_BPT_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"

/* Parses size bytes (need not be NUL-terminated) and appends the patches to
 * the model's current part. file_name is used in messages. On a format error
 * nothing is added; on SW_ERR_NO_MEMORY the model may hold some patches. */
sw_status sw_import_bpt_memory(const char *text, size_t size, const char *file_name,
                               sw_model *model, sw_error *err);

/* Reads the file at path and imports it as above; messages name the path. */
sw_status sw_import_bpt_file(const char *path, sw_model *model, sw_error *err);

#endif
