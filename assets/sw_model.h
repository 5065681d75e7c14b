/* The host-side model: parts, each a list of rational Bezier patches in double,
 * the form every importer produces and the pack builder consumes. Host only:
 * it allocates, and sw_model_free releases everything. */
#ifndef SW_MODEL_H
#define SW_MODEL_H

#include <stddef.h>

#include "sw_bezier.h"
#include "sw_error.h"
#include "sw_math.h"

typedef struct sw_model_patch {
    int degree_u, degree_v;
    int rational;
    double *ctrl;      /* owned; sw_bezier_patch layout, 4 doubles per point */
    size_t part;       /* index into parts */
} sw_model_patch;

typedef struct sw_model_part {
    char name[56];
    float color[4];
    size_t first_patch, patch_count;
} sw_model_part;

typedef struct sw_model {
    sw_model_patch *patches;
    size_t patch_count, patch_capacity;
    sw_model_part *parts;
    size_t part_count, part_capacity;
    float model_tolerance;   /* 0 when the sources say nothing */
} sw_model;

void sw_model_init(sw_model *model);
void sw_model_free(sw_model *model);

/* Starts a new part; patches added after it belong to it. The name is
 * truncated to 55 bytes. */
sw_status sw_model_begin_part(sw_model *model, const char *name, const float color[4],
                              sw_error *err);

/* Appends a patch to the current part (a part named after nothing is started
 * if there is none); ctrl is copied. */
sw_status sw_model_add_patch(sw_model *model, int degree_u, int degree_v, int rational,
                             const double *ctrl, sw_error *err);

/* Applies m to every control point of the patches of part (positions only;
 * weights are unchanged, so rational patches stay exact under affine maps). */
void sw_model_transform_part(sw_model *model, size_t part, const sw_mat4 *m);

sw_bezier_patch sw_model_patch_view(const sw_model_patch *patch);
sw_box sw_model_box(const sw_model *model);

#endif
