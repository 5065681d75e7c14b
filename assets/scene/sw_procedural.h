/* SPDX-License-Identifier: MIT */
/* Procedural trimmed NURBS objects for showrooms and scale tests: plates with
 * circular holes, revolved vases and swept rails, in millimetres, y up,
 * standing on (or floating above) the floor y = 0 around the origin, and
 * deterministic from a seed. Each kind announces its Bezier patch count in
 * advance (sw_proc_patch_count), so the showroom generator can plan a scene of
 * N patches without building it. Scenes (`generate = plate`) and the
 * generator call it. Host only: shapes allocate; sw_proc_shape_free releases.
 *
 *   plate  A horizontal bicubic B-spline plane, size x size, at y = height,
 *          segments x segments spans, normal +y. Control points sit at the
 *          Greville abscissae and the parameters are millimetres, so the
 *          parameter plane maps to the model plane by a translation (and a
 *          flip of v): holes, exact rational circles in parameter space, are
 *          circles of the same radius on the plate. One outer loop (the four
 *          edges) and `holes` inner loops, laid out on a grid from the seed.
 *          Patches: segments^2.
 *   vase   A cubic B-spline profile (radius, height) with `segments` spans,
 *          revolved about the y axis as an exact rational surface (degree 2
 *          around, 4 quarter arcs, weights cos 45 deg), widest diameter about
 *          `size`, `height` tall, normal outward; plus a flat bilinear base
 *          trimmed by an exact circle of the profile's bottom radius.
 *          Patches: 4 * segments + 1.
 *   rail   A channel cross-section (quadratic, 4 spans, `height` tall and
 *          wide) swept along a cubic B-spline path in the floor plane of
 *          `segments` spans and `size` long: the tensor product whose points
 *          are path(u) + section(v). Trimmed by its boundary and `holes`
 *          stadium slots (two exact half ellipses and two lines) on the top.
 *          Patches: 4 * segments. */
#ifndef SW_PROCEDURAL_H
#define SW_PROCEDURAL_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_model.h"
#include "sw_nurbs.h"

typedef enum sw_proc_kind { SW_PROC_PLATE = 1, SW_PROC_VASE, SW_PROC_RAIL } sw_proc_kind;

/* The parameters a kind reads; the others must stay as sw_proc_defaults set
 * them (a scene that gives one is an error). */
enum sw_proc_param_bit {
    SW_PROC_USES_SIZE = 1,
    SW_PROC_USES_HEIGHT = 2,
    SW_PROC_USES_HOLES = 4,
    SW_PROC_USES_SEGMENTS = 8,
    SW_PROC_USES_SEED = 16,
};

typedef struct sw_proc_params {
    sw_proc_kind kind;
    double size_mm;     /* plate: side; vase: widest diameter; rail: length */
    double height_mm;   /* plate: height above the floor; vase: height; rail: section */
    int holes;          /* plate: circular holes; rail: slots; vase: 0 */
    int segments;       /* plate: spans per side; vase: profile spans; rail: path spans */
    uint64_t seed;
} sw_proc_params;

enum {
    SW_PROC_MAX_SEGMENTS = 64,
    SW_PROC_MAX_PLATE_HOLES = 64,
    SW_PROC_MAX_RAIL_SLOTS = 16,
    SW_PROC_RAIL_SECTION_SPANS = 4,
    SW_PROC_MAX_SURFACES = 2,
};
#define SW_PROC_MAX_SIZE_MM 1.0e5

/* "plate", "vase", "rail"; NULL for anything else. */
const char *sw_proc_kind_name(sw_proc_kind kind);
/* 1 and *kind set when name is a kind's name, else 0. */
int sw_proc_kind_from_name(const char *name, sw_proc_kind *kind);

/* The defaults of a kind (seed 1); kind must be valid. */
sw_proc_params sw_proc_defaults(sw_proc_kind kind);
unsigned sw_proc_params_used(sw_proc_kind kind); /* enum sw_proc_param_bit */

/* Checks the ranges: size 1 .. SW_PROC_MAX_SIZE_MM, height 0 .. the same for a
 * plate and 1 .. for the others, segments 1 .. SW_PROC_MAX_SEGMENTS, holes 0
 * .. SW_PROC_MAX_PLATE_HOLES (plate), .. SW_PROC_MAX_RAIL_SLOTS (rail), 0
 * (vase). The message names the parameter as a scene writes it ("holes"). */
sw_status sw_proc_check(const sw_proc_params *params, sw_error *err);

/* The Bezier patches sw_proc_add adds (params must pass sw_proc_check). */
size_t sw_proc_patch_count(const sw_proc_params *params);

/* A built object: surfaces with their trimming loops, ready for
 * sw_model_add_surface, and the curves it was made from (for tests). */
typedef struct sw_proc_shape {
    sw_proc_params params;
    size_t surface_count;
    sw_nurbs_surface surfaces[SW_PROC_MAX_SURFACES];
    size_t first_loop[SW_PROC_MAX_SURFACES], loop_count[SW_PROC_MAX_SURFACES];
    sw_model_loop_input *loops;    /* all surfaces' loops */
    size_t total_loops;
    sw_nurbs_curve *curves;        /* the loops' curves, loop by loop */
    size_t curve_count;
    /* Construction: vase profile (r, y, 0) and rail section (0, y, z) in
     * `profile`, rail path (x, 0, z) in `path`. Plate holes and the vase base
     * circle as (u, v, radius) triples in `circles` (parameters). */
    sw_nurbs_curve profile, path;
    double *circles;
    size_t circle_count;
    void **blocks;                 /* every allocation, for sw_proc_shape_free */
    size_t block_count, block_capacity;
} sw_proc_shape;

/* Builds the object; on failure *shape is freed and zeroed. */
sw_status sw_proc_build(const sw_proc_params *params, sw_proc_shape *shape, sw_error *err);
void sw_proc_shape_free(sw_proc_shape *shape);

/* Builds the object and adds its surfaces (sw_model_add_surface) to the
 * model's current part. */
sw_status sw_proc_add(sw_model *model, const sw_proc_params *params, sw_error *err);

#endif
