/* SPDX-License-Identifier: MIT */
/* The host-side model: parts made of trimmed NURBS surfaces (a soup: no
 * adjacency assumed), each split into rational Bezier patches by knot
 * insertion, the form every importer produces and the pack builder consumes.
 * Bezier inputs (Newell, .bpt) are surfaces of one patch each, untrimmed.
 * Host only: it allocates, and sw_model_free releases everything.
 *
 * Units: all geometry is in millimetres once imported. Importers of files
 * that declare units (IGES, STEP) convert; unitless inputs (Newell, .bpt) are
 * taken as millimetres unless a scene part says otherwise (`units =`). */
#ifndef SW_MODEL_H
#define SW_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "sw_bezier.h"
#include "sw_error.h"
#include "sw_math.h"
#include "sw_nurbs.h"
#include "sw_trim_loop.h"

typedef struct sw_model_patch {
    int degree_u, degree_v;
    int rational;
    double *ctrl;      /* owned; sw_bezier_patch layout, 4 doubles per point */
    size_t part;       /* index into parts */
    size_t surface;    /* index into surfaces */
    double domain[4];  /* u0, u1, v0, v1: the part of the surface's domain it covers */
    /* Trimmed surfaces: which of 32 x 32 equal cells of domain touch the face
     * (bit i of mask[j]: cell i along u, row j along v; conservative, as
     * sw_pack_trim_mask). masked 0: every cell touches the face (the whole
     * domain is inside, or the trims only run along its border): mask unused. */
    uint32_t mask[32];
    int masked;
} sw_model_patch;

/* A trimming curve: a clamped rational B-spline in the surface's (u, v)
 * parameter space, stored as an sw_nurbs_curve whose points are (u, v, 0, w). */
typedef struct sw_model_trim_curve {
    int degree, count;
    double *knots;     /* owned; count + degree + 1 */
    double *ctrl;      /* owned; count * 4: u, v, 0, w */
    int computed;      /* 1: computed by point inversion from a model-space curve */
    double gap;        /* model units: how far the curve's image on the surface may lie
                          from the edge the file meant (its edge tolerance, or the fit's
                          distance from a model-space curve); 0 when the file says none */
    uint32_t edge;     /* the file's edge this trim is a use of, where the part's topology
                          shares that edge between faces: an id unique in the part (from
                          1); 0 when not shared or not known. The sewing pairs a shared
                          edge's trims with each other (sw_seam_flatten.h) */
} sw_model_trim_curve;

/* A closed loop of trimming curves, head to tail. Outer loops bound the
 * face; inner loops cut holes. Inside is decided by the even-odd rule over
 * all loops of the surface, so loop orientation does not matter. */
typedef struct sw_model_loop {
    size_t first_curve, curve_count;   /* into curves */
    int outer;
} sw_model_loop;

typedef struct sw_model_surface {
    int degree_u, degree_v, count_u, count_v;
    int rational;
    double *knots_u, *knots_v;         /* owned; clamped */
    double *ctrl;                      /* owned; sw_nurbs_surface layout */
    size_t part;
    size_t first_loop, loop_count;     /* into loops; 0 loops: the whole domain */
    size_t first_patch, patch_count;   /* the Bezier patches split from it */
    double domain[4];                  /* u0, u1, v0, v1 */
    int reversed;                      /* 1: u was mirrored to flip the normal */
} sw_model_surface;

typedef struct sw_model_part {
    char name[56];
    float color[4];
    double transform[16];   /* sw_mat4 layout: how the part was placed (already applied) */
    size_t first_patch, patch_count;
    size_t first_surface, surface_count;
} sw_model_part;

/* A named camera of a showroom scene. */
typedef struct sw_model_viewpoint {
    char name[48];
    double eye[3], target[3], up[3];
    double fov_deg;          /* 0: the runtime's default */
} sw_model_viewpoint;

typedef struct sw_model {
    sw_model_patch *patches;
    size_t patch_count, patch_capacity;
    sw_model_surface *surfaces;
    size_t surface_count, surface_capacity;
    sw_model_loop *loops;
    size_t loop_count, loop_capacity;
    sw_model_trim_curve *curves;
    size_t curve_count, curve_capacity;
    sw_model_part *parts;
    size_t part_count, part_capacity;
    sw_model_viewpoint *viewpoints;
    size_t viewpoint_count, viewpoint_capacity;
    float model_tolerance;   /* millimetres; 0 when the sources say nothing */
    int32_t up_axis;         /* sw_up_axis.h: a scene's up_axis, then the build's; 0: not said */
} sw_model;

void sw_model_init(sw_model *model);
void sw_model_free(sw_model *model);

/* Starts a new part; surfaces added after it belong to it. The name is
 * truncated to 55 bytes. The transform starts as the identity. */
sw_status sw_model_begin_part(sw_model *model, const char *name, const float color[4],
                              sw_error *err);

/* Appends a Bezier patch to the current part, as an untrimmed surface of one
 * patch on [0,1]^2 (a part named after nothing is started if there is none);
 * ctrl is copied. */
sw_status sw_model_add_patch(sw_model *model, int degree_u, int degree_v, int rational,
                             const double *ctrl, sw_error *err);

/* Appends a trimmed NURBS surface to the current part: checks it
 * (sw_nurbs_surface_check, sw_nurbs_curve_check on every trim), copies it and
 * its loops, and splits it into Bezier patches. reversed: the face's normal is
 * opposite to the surface's; the surface is reparameterised (u mirrored, the
 * trims with it) so every patch's du x dv points out of the face.
 * loop_count 0: untrimmed. Trimmed: patches that do not touch the face are
 * dropped, the others shrunk to the trims' parameter box (sw_bezier_subpatch)
 * and given a trim mask (sw_trim_mask). Every loop must close within 1% of the
 * domain's size; trims that leave no patch are an error (SW_ERR_FORMAT). On
 * failure the model is unchanged. */
sw_status sw_model_add_surface(sw_model *model, const sw_nurbs_surface *surface, int reversed,
                               const sw_model_loop_input *loops, size_t loop_count,
                               sw_error *err);

/* Applies m to every control point of the part's surfaces and patches
 * (positions only; weights unchanged, so rational geometry stays exact under
 * affine maps) and records it: part.transform = m * part.transform. */
void sw_model_transform_part(sw_model *model, size_t part, const sw_mat4 *m);

/* Appends a named viewpoint (name truncated to 47 bytes); names are unique:
 * SW_ERR_FORMAT when one is repeated. */
sw_status sw_model_add_viewpoint(sw_model *model, const sw_model_viewpoint *view, sw_error *err);

sw_bezier_patch sw_model_patch_view(const sw_model_patch *patch);
sw_nurbs_surface sw_model_surface_view(const sw_model_surface *surface);
sw_nurbs_curve sw_model_curve_view(const sw_model_trim_curve *curve);
sw_box sw_model_box(const sw_model *model);

#endif
