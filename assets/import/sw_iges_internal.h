/* SPDX-License-Identifier: MIT */
/* Shared by the files of the native IGES reader (sw_iges_*.c,
 * sw_import_iges.c), nothing else: the record/section view of the file, the
 * directory, parameter lists, owned NURBS in the reader's working form and the
 * faces collected before they go into the model. Geometry is kept in the
 * file's model units until a face is emitted (then scaled to millimetres), so
 * parameter-space curves are never scaled by mistake. */
#ifndef SW_IGES_INTERNAL_H
#define SW_IGES_INTERNAL_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_import.h"
#include "sw_math.h"
#include "sw_model.h"
#include "sw_pcurve.h"

/* ---- records and sections (sw_iges_records.c) ----------------------- */

enum { IGES_S, IGES_G, IGES_D, IGES_P, IGES_T, IGES_SECTIONS };

/* One record: up to 80 columns of the buffer (not NUL-terminated). */
typedef struct iges_line {
    const char *text;
    int len;
} iges_line;

typedef struct iges_entity {
    int type, form;
    int pointer;        /* 1-based first P line, as written (checked when read) */
    int matrix_de;      /* D pointer of its 124, or 0, as written */
    int subordinate;    /* status digits 3-4: 0 independent, 1/2/3 dependent */
    int used;           /* consumed by a parent that became a face */
    int busy;           /* on the current conversion path: cycle guard */
} iges_entity;

/* Entity references nest (144 -> 142 -> 102 -> 126 -> 124 -> 124 ...);
 * real files go a few levels deep, a cycle would go forever. Shared
 * references could also multiply (a 102 naming another 102 a thousand
 * times, and so on), so the total number of entities entered is bounded by
 * IGES_VISITS_PER_ENTITY per entity in the file. */
enum { IGES_MAX_DEPTH = 32, IGES_VISITS_PER_ENTITY = 64 };

/* The most faces one shell (514) may list: as for STEP's shells
 * (SW_STEP_MAX_SHELL_FACES), far above a real part's and low enough that
 * a file cannot ask for work out of proportion to what it describes. */
enum { IGES_MAX_SHELL_FACES = 100000 };

typedef struct iges_reader {
    const char *file;               /* base name, for messages */
    iges_line *all;                 /* every record; the sections point into it */
    iges_line *lines[IGES_SECTIONS];
    int count[IGES_SECTIONS];
    int first_line[IGES_SECTIONS];  /* 1-based index in the whole file, for messages */
    char pdelim, rdelim;
    double units_to_mm;             /* units and model space scale together */
    double resolution;              /* G 19, model units; 0 if absent */
    double tol;                     /* working tolerance, model units */
    iges_entity *ents;
    int ent_count;
    int depth;
    long visits;                    /* entities entered so far: shared references */
    int unsupported_type;           /* set with SW_ERR_UNSUPPORTED */
    const char *unsupported_why;    /* and, when the type is supported but this entity
                                       could not be used, why (else NULL) */
    const sw_import_options *opt;
    sw_import_report *report;
    sw_error *err;
} iges_reader;

sw_status iges_split_sections(iges_reader *r, const char *text, size_t size);
sw_status iges_read_global(iges_reader *r);
sw_status iges_read_directory(iges_reader *r);
void iges_reader_free(iges_reader *r);

/* ---- parameters (sw_iges_params.c) ------------------------------------ */

typedef struct iges_token {
    int kind;           /* IGES_TOK_* */
    double num;
    int line;           /* 0-based line it starts on */
    int str_line, str_col, str_len;   /* a string's characters, after its nH */
} iges_token;

enum { IGES_TOK_EMPTY, IGES_TOK_NUM, IGES_TOK_STRING };

/* An entity's parameters, the type number (parameter 0) included, read up to
 * the record delimiter (D entries' line counts are not trusted). */
typedef struct iges_params {
    iges_token *tok;
    int count, cap;
    int entity;
    int type;
} iges_params;

sw_status iges_params_read(iges_reader *r, int entity, iges_params *p);
void iges_params_free(iges_params *p);
sw_status iges_param_real(iges_reader *r, const iges_params *p, int i, const char *what,
                          double *out);
sw_status iges_param_real_or(iges_reader *r, const iges_params *p, int i, const char *what,
                             double fallback, double *out);
sw_status iges_param_int(iges_reader *r, const iges_params *p, int i, const char *what,
                         int lo, int hi, int *out);
sw_status iges_param_int_or(iges_reader *r, const iges_params *p, int i, const char *what,
                            int lo, int hi, int fallback, int *out);
/* A D-entry pointer: entity index, or -1 for 0 when allow_null. */
sw_status iges_param_entity(iges_reader *r, const iges_params *p, int i, const char *what,
                            int allow_null, int *out);
/* Checks that parameters first..first+n-1 exist ("expected 12 knots, found 9"). */
sw_status iges_param_need(iges_reader *r, const iges_params *p, int first, int n,
                          const char *what);
/* n reals from parameter first on, all required. */
sw_status iges_param_reals(iges_reader *r, const iges_params *p, int first, int n,
                           const char *what, double *out);
/* An error at parameter i (its P line), or at the entity when i < 0. */
sw_status iges_fail(iges_reader *r, const iges_params *p, int i, sw_status st, const char *fmt,
                    ...) __attribute__((format(printf, 5, 6)));
/* An error naming only the entity (D line, type). */
sw_status iges_fail_entity(iges_reader *r, int entity, sw_status st, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* The 1-based D line of an entity: what files and messages call it. */
static inline int iges_de(int entity) { return 2 * entity + 1; }

/* ---- owned NURBS and their operations (sw_iges_nurbs.c) -------------- */

/* Control points x, y, z, w with x, y, z Cartesian, as sw_nurbs. Knots need
 * not be clamped until iges_nurbs_clamp. */
typedef struct iges_curve {
    int degree, count;
    double *knots, *ctrl;
    double gap;   /* a trim's: how far its image may lie from the file's model-space
                     curve, model units (sw_model_trim_curve.gap); 0 otherwise */
} iges_curve;

typedef struct iges_curves {
    iges_curve *items;
    int count, cap;
} iges_curves;

typedef struct iges_surface {
    int degree_u, degree_v, count_u, count_v;
    double *knots_u, *knots_v, *ctrl;
    /* The entity's own parameter space (trims are written in it) to ours:
     * u' = map_u[0] + map_u[1] * u, same for v, unless angle_v (120: v is
     * an angle, mapped through the rational arc pieces). */
    double map_u[2], map_v[2];
    int angle_v;
    double angle_start, angle_end;
    int flipped;     /* a mirroring transform reversed its normal */
} iges_surface;

sw_status iges_curve_alloc(iges_reader *r, iges_curve *c, int degree, int count);
void iges_curve_free(iges_curve *c);
sw_status iges_curves_push(iges_reader *r, iges_curves *list, iges_curve *c);
sw_status iges_curves_append(iges_reader *r, iges_curves *dst, iges_curves *src);
void iges_curves_free(iges_curves *list);
sw_status iges_surface_alloc(iges_reader *r, iges_surface *s, int du, int dv, int cu, int cv);
void iges_surface_free(iges_surface *s);
sw_nurbs_curve iges_curve_view(const iges_curve *c);
sw_nurbs_surface iges_surface_view(const iges_surface *s);

/* Cuts the curve to [a, b] and clamps its knots there by knot insertion
 * (periodic and unclamped IGES splines; parameters are kept). */
sw_status iges_curve_clamp(iges_reader *r, iges_curve *c, double a, double b);
sw_status iges_surface_clamp(iges_reader *r, iges_surface *s, double u0, double u1, double v0,
                             double v1);
void iges_curve_reverse(iges_curve *c);
void iges_curve_transform(iges_curve *c, const sw_mat4 *m);
void iges_surface_transform(iges_surface *s, const sw_mat4 *m);
/* The pieces as one curve of their highest degree, parameters concatenated
 * (Bezier segments degree-elevated and joined on knots of multiplicity
 * degree). */
sw_status iges_curves_join(iges_reader *r, const iges_curves *list, iges_curve *out);
/* A line segment (degree 1) from a to b over [t0, t1]. */
sw_status iges_curve_line(iges_reader *r, iges_curve *c, sw_vec3 a, sw_vec3 b, double t0,
                          double t1);
/* Rational quadratic circular arc around centre in the plane of unit axes x,
 * y, from angle a0 to a1 (a1 > a0), split into pieces of at most 90 degrees;
 * parameter = piece index (knots 0, 1, ..., n). */
sw_status iges_curve_arc(iges_reader *r, iges_curve *c, sw_vec3 centre, sw_vec3 x, sw_vec3 y,
                         double radius, double a0, double a1);
int iges_arc_pieces(double sweep);
/* Parameter of the point at angle a on such an arc (exact inverse of the
 * rational quadratic's angle map). */
double iges_arc_param(double a0, double a1, double a);

/* ---- entities ---------------------------------------------------------- */

/* The 124 chain of an entity (its D entry's matrix pointer), identity if
 * none (sw_iges_refs.c). */
sw_status iges_entity_matrix(iges_reader *r, int entity, sw_mat4 *out);
/* Any curve entity as NURBS pieces, head to tail, in model units with its
 * own transform applied (sw_iges_curves.c). */
sw_status iges_read_curve(iges_reader *r, int entity, iges_curves *out);
int iges_is_curve(int type);
/* Any surface entity as one NURBS surface, clamped, transform applied
 * (sw_iges_surfaces.c). */
sw_status iges_read_surface(iges_reader *r, int entity, iges_surface *out);
int iges_is_surface(int type);

/* ---- faces (sw_iges_trims.c, sw_iges_brep.c) ------------------------- */

typedef struct iges_loop {
    iges_curves curves;     /* (u, v, 0, w) */
    int *computed;          /* per curve */
    int outer;
} iges_loop;

typedef struct iges_face {
    iges_surface surface;
    iges_loop *loops;
    int loop_count, loop_cap;
    int reversed;
    int entity;              /* where it came from, for messages */
    sw_pcurve_surface ps;    /* made on first need (inversion, mapped trims) */
    int ps_ready;
} iges_face;

typedef struct iges_faces {
    iges_face *items;
    int count, cap;
} iges_faces;

void iges_face_free(iges_face *f);
void iges_faces_free(iges_faces *list);
sw_status iges_faces_push(iges_reader *r, iges_faces *list, iges_face *f);
/* Appends a loop (takes the curves; computed may be NULL), closing small
 * parameter-space gaps between consecutive curves with lines. */
sw_status iges_face_add_loop(iges_reader *r, iges_face *f, iges_curves *curves,
                             const int *computed, int outer);
/* The natural boundary of the surface's domain as a loop. */
sw_status iges_face_add_domain_loop(iges_reader *r, iges_face *f);
/* Parameter-space curves for model-space curves on the face's surface, by
 * point inversion and fitting within r->tol; counted in the report. */
sw_status iges_compute_pcurves(iges_reader *r, iges_face *f, const iges_curves *model,
                               iges_curves *out, int entity);
/* Parameter-space curves as read (x, y of the entity's own parameter space)
 * made into ours: z dropped, mapped through the surface's map (refitted for
 * the angle of a 120). */
sw_status iges_map_trims(iges_reader *r, iges_face *f, iges_curves *trims, int entity);

/* A loop under construction: its curves and each curve's computed flag. */
typedef struct iges_loop_build {
    iges_curves curves;
    int *flags;
    int cap;
} iges_loop_build;

/* Moves a group of curves into the loop (freed on failure). */
sw_status iges_loop_take(iges_reader *r, iges_loop_build *lb, iges_curves *group, int computed);
/* Adds the loop to the face when st is SW_OK; frees the builder either way. */
sw_status iges_loop_finish(iges_reader *r, iges_face *f, iges_loop_build *lb, sw_status st,
                           int outer);
/* Reverses the order of the curves and each curve. */
void iges_reverse_group(iges_curves *g);
/* A model-space curve entity, transformed by outer, made parameter curves. */
sw_status iges_computed_group(iges_reader *r, iges_face *f, int curve, const sw_mat4 *outer,
                              int owner, iges_curves *out);
/* Parameter-space curves as written, mapped; SW_ERR_UNSUPPORTED lets the
 * caller fall back on the model-space curve. */
sw_status iges_written_group(iges_reader *r, iges_face *f, int curve, int owner,
                             iges_curves *out);
/* The face's surface with its owner's transform applied. */
sw_status iges_face_surface(iges_reader *r, int owner, int surface, iges_face *f, sw_mat4 *m);
/* Sets every trim's gap in uv (parameter curves as written for face f) to
 * how far their image on the surface strays from the model-space curve
 * entity (under m) the same boundary names; a curve that cannot be read
 * leaves the gaps as they are. */
sw_status iges_measure_gap(iges_reader *r, iges_face *f, int model_curve, const sw_mat4 *m,
                           iges_curves *uv);

sw_status iges_read_trimmed(iges_reader *r, int entity, iges_faces *out);  /* 144 */
sw_status iges_read_bounded(iges_reader *r, int entity, iges_faces *out);  /* 143 */
sw_status iges_read_untrimmed(iges_reader *r, int entity, iges_faces *out);
sw_status iges_read_brep(iges_reader *r, int entity, iges_faces *out);     /* 186, 514, 510 */

/* Records that an entity of an unsupported type was met (SW_ERR_UNSUPPORTED,
 * its type kept for the report): faces that need it are skipped. The guards
 * and the matrices are in sw_iges_refs.c. */
sw_status iges_unsupported(iges_reader *r, int entity, const char *expected);

/* Marks an entity as entered (cycle and depth guard); leave undoes it. */
sw_status iges_enter(iges_reader *r, int entity);
void iges_leave(iges_reader *r, int entity);

#endif
