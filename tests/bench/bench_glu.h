/* SPDX-License-Identifier: MIT */
/* GLU's NURBS tessellator as the benchmarks drive it (tess_bench.c,
 * trim_tess_bench.c): GLU_NURBS_TESSELLATOR mode with object-space
 * parametric-error sampling, the output handed to callbacks instead of GL.
 * A counting renderer counts vertices, normals and triangles (what the timed
 * runs do); a capturing one also hands every triangle, with the (u, v) GLU
 * evaluated it at, to the caller for measuring (bench_error.h). GLU gives only
 * positions, so the (u, v) ride along as texture coordinates: the caller adds
 * a GL_MAP2_TEXTURE_COORD_2 map holding the identity (the parameters' own
 * values) to each surface it tessellates in a capturing run. GLU needs a
 * current desktop compatibility context (sw_egl_headless, SW_GL_API_DESKTOP).
 * Host-side benchmark code: capturing allocates a primitive buffer. */
#ifndef BENCH_GLU_H
#define BENCH_GLU_H

#include <GL/gl.h>
#include <GL/glu.h>
#include <stddef.h>
#include <stdint.h>

/* One output triangle: positions and the (u, v) of its three vertices. */
typedef void (*bench_glu_triangle_fn)(void *user, const float p[3][3], const float uv[3][2]);

typedef struct bench_glu {
    GLUnurbs *nurb;
    uint64_t vertices, normals, triangles;
    GLenum error;          /* the last GLU_NURBS_ERROR, 0 if none */
    float sink;            /* touches the data, as a real consumer would */
    GLenum type;           /* the current primitive and its vertex count */
    uint64_t run;
    /* Capturing only: the current primitive's vertices, x y z u v each. */
    bench_glu_triangle_fn on_triangle;
    void *user;
    float pending_uv[2];
    float (*prim)[5];
    size_t prim_cap;
    int out_of_memory;
} bench_glu;

/* A fresh tessellator (no setting or cache carries over from another run)
 * at GLU_PARAMETRIC_TOLERANCE tolerance, culling off, normals generated
 * (GLU's evaluator turns auto-normals on when a normal callback is set).
 * on_triangle NULL: counting only. 0 when GLU cannot make one. */
int bench_glu_open(bench_glu *g, double tolerance, bench_glu_triangle_fn on_triangle, void *user);
void bench_glu_close(bench_glu *g);

/* NULL when the run went well, else what went wrong (a GLU error, normals
 * missing, out of memory while capturing). */
const char *bench_glu_problem(const bench_glu *g);

/* One capturing run at tolerance: the triangles and measured max error
 * (bench_error.h) it gave, NULL on success, else the problem. */
typedef const char *(*bench_glu_measure_fn)(const void *ctx, double tolerance,
                                            uint64_t *triangles, double *error);

/* The largest GLU_PARAMETRIC_TOLERANCE found whose measured error is <=
 * target within 1% (where both sides' error is a floor they share, as the
 * trims' own chords, GLU's float evaluation lands a few 1e-4 off): halving
 * from start until met, doubling until not (or until GLU's output stops
 * changing: its coarsest sampling), then bisecting geometrically to within
 * 10%. GLU's tolerance is not a bound on its measured error, so this is the
 * only way to compare at equal error. *tries: tolerances measured. NULL on
 * success, else the problem (a run's, or no tolerance tried meets target). */
const char *bench_glu_tune(bench_glu_measure_fn measure, const void *ctx, double start,
                           double target, double *tolerance, int *tries);

/* Triangles in a GL primitive of n vertices (0 for points and lines). */
uint64_t bench_glu_triangles_in(GLenum type, uint64_t n);

/* Vertex numbers (from the primitive's first) of triangle t of a primitive,
 * in the order GL draws it. */
void bench_glu_triangle_of(GLenum type, uint64_t t, uint64_t v[3]);

#endif
