/* SPDX-License-Identifier: MIT */
/* GLU's trimmed NURBS tessellation of the surfaces trim_tess_bench.c gives
 * sw_trim_tess: the same work in GLU's form. A surface's Bezier patches tile
 * its domain on a grid of knot intervals, so GLU gets them as one NURBS
 * surface (gluNurbsSurface: each interior knot repeated degree times, which is
 * exactly that piecewise Bezier surface; rational patches as
 * GL_MAP2_VERTEX_4) and the loops, in the same (u, v), as closed gluPwlCurve
 * trims (GLU_MAP1_TRIM_2), oriented as GLU wants them (outer loops counter-
 * clockwise, holes clockwise; seamwalk takes either). Conversions happen
 * once, outside the timed runs, as a pack would store them.
 *
 * GLU is tuned to seamwalk's measured error: trim_glu_tune searches
 * GLU_PARAMETRIC_TOLERANCE (outside the timed region) for the largest value
 * whose measured error (bench_error.h) is at most a target (within 1%: the
 * seams' own chords, which both sides share, bound both errors from below). Host-side
 * benchmark code: allocates, and frees what it allocates. */
#ifndef TRIM_GLU_H
#define TRIM_GLU_H

#include <stdint.h>

#include "bench_error.h"
#include "bench_glu.h"
#include "sw_trim_tess.h"

typedef struct trim_glu_surface {
    GLint order_u, order_v, count_u, count_v; /* control points along u and v */
    GLfloat *knots_u, *knots_v;               /* count + order each */
    GLenum type;                              /* GL_MAP2_VERTEX_3 or _4 */
    GLint dims;                               /* 3 or 4 (homogeneous x w, y w, z w, w) */
    GLfloat *ctrl;                            /* dims per point, u fastest */
    GLfloat *tex;                             /* the identity map: 2 per point */
    GLfloat *pwl;                             /* loops, (u, v), first point repeated last */
    uint32_t *loop_first;                     /* loop_count + 1 offsets into pwl's points */
    uint32_t loop_count;
    bench_trim_surface exact;                 /* the patches, for measuring */
} trim_glu_surface;

/* Builds GLU's form of the patches and loops. 0 and a message in why (of
 * why_size bytes) when the patches do not tile a knot grid with one degree,
 * or out of memory. */
int trim_glu_make(trim_glu_surface *g, const sw_trim_patch *patches, uint32_t count,
                  const sw_trim_loops *loops, char *why, size_t why_size);
void trim_glu_free(trim_glu_surface *g);

/* The surface handed to nurb between gluBeginSurface and gluEndSurface:
 * the net, with_tex also the identity texture map (the (u, v) for a
 * capturing run), and the trims. */
void trim_glu_draw(const trim_glu_surface *g, GLUnurbs *nurb, int with_tex);

/* What one GLU tessellation emitted: vertices as sent (strips and fans
 * repeat shared ones); from capturing runs also the measured max error and
 * the (u, v) area the triangles cover (to check GLU trimmed what it was
 * given). */
typedef struct trim_glu_output {
    uint64_t triangles, vertices;
    double error, error_nearest, uv_area; /* at the same (u, v), to the nearest point */
} trim_glu_output;

/* GLU's tessellation of the surface at tolerance: measure 0 times repeats
 * counting runs (times into the caller's samples), measure 1 one capturing
 * run. NULL on success, else GLU's problem. */
const char *trim_glu_run(const trim_glu_surface *g, double tolerance, int measure, int repeats,
                         double *samples, trim_glu_output *out);

/* bench_glu_tune on this surface: the tolerance found, the capturing run's
 * output there and the number of tolerances tried. NULL on success, else the
 * problem. */
const char *trim_glu_tune(const trim_glu_surface *g, double start, double target,
                          double *tolerance, trim_glu_output *out, int *tries);

#endif
