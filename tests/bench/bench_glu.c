/* SPDX-License-Identifier: MIT */
/* GLU's NURBS tessellator driven through callbacks: see bench_glu.h. */
#include "bench_glu.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

uint64_t bench_glu_triangles_in(GLenum type, uint64_t n)
{
    switch (type) {
    case GL_TRIANGLES: return n / 3;
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
    case GL_POLYGON: return n >= 3 ? n - 2 : 0;
    case GL_QUAD_STRIP: return n >= 4 ? 2 * ((n - 2) / 2) : 0;
    case GL_QUADS: return 2 * (n / 4);
    default: return 0; /* points and lines (trim curves) are not surface */
    }
}

void bench_glu_triangle_of(GLenum type, uint64_t t, uint64_t v[3])
{
    switch (type) {
    case GL_TRIANGLES: v[0] = 3 * t, v[1] = 3 * t + 1, v[2] = 3 * t + 2; return;
    case GL_TRIANGLE_STRIP: v[0] = t, v[1] = t + 1, v[2] = t + 2; return;
    case GL_QUAD_STRIP: {
        uint64_t q = 2 * (t / 2);
        if (t % 2 == 0)
            v[0] = q, v[1] = q + 1, v[2] = q + 3;
        else
            v[0] = q, v[1] = q + 3, v[2] = q + 2;
        return;
    }
    case GL_QUADS: {
        uint64_t q = 4 * (t / 2);
        if (t % 2 == 0)
            v[0] = q, v[1] = q + 1, v[2] = q + 2;
        else
            v[0] = q, v[1] = q + 2, v[2] = q + 3;
        return;
    }
    default: v[0] = 0, v[1] = t + 1, v[2] = t + 2; return; /* fan, polygon */
    }
}

static void hand_over(bench_glu *g)
{
    uint64_t n = bench_glu_triangles_in(g->type, g->run);
    for (uint64_t t = 0; t < n; t++) {
        uint64_t v[3];
        float p[3][3], uv[3][2];
        bench_glu_triangle_of(g->type, t, v);
        for (int k = 0; k < 3; k++) {
            memcpy(p[k], g->prim[v[k]], sizeof p[k]);
            memcpy(uv[k], g->prim[v[k]] + 3, sizeof uv[k]);
        }
        g->on_triangle(g->user, p, uv);
    }
}

static void keep_vertex(bench_glu *g, const GLfloat *v)
{
    if (g->run >= g->prim_cap) {
        size_t cap = g->prim_cap ? 2 * g->prim_cap : 1024;
        void *grown = realloc(g->prim, cap * sizeof *g->prim);
        if (!grown) {
            g->out_of_memory = 1;
            return;
        }
        g->prim = grown, g->prim_cap = cap;
    }
    float *k = g->prim[g->run];
    k[0] = v[0], k[1] = v[1], k[2] = v[2], k[3] = g->pending_uv[0], k[4] = g->pending_uv[1];
}

static void GLAPIENTRY on_begin(GLenum type, void *data)
{
    bench_glu *g = data;
    g->type = type;
    g->run = 0;
}

static void GLAPIENTRY on_vertex(GLfloat *v, void *data)
{
    bench_glu *g = data;
    if (g->on_triangle && !g->out_of_memory)
        keep_vertex(g, v);
    g->run++;
    g->vertices++;
    g->sink += v[0];
}

static void GLAPIENTRY on_normal(GLfloat *n, void *data)
{
    bench_glu *g = data;
    g->normals++;
    g->sink += n[2];
}

static void GLAPIENTRY on_texcoord(GLfloat *t, void *data)
{
    bench_glu *g = data;
    g->pending_uv[0] = t[0], g->pending_uv[1] = t[1];
}

static void GLAPIENTRY on_end(void *data)
{
    bench_glu *g = data;
    g->triangles += bench_glu_triangles_in(g->type, g->run);
    if (g->on_triangle && !g->out_of_memory)
        hand_over(g);
}

static void GLAPIENTRY on_error(GLenum code, void *data)
{
    bench_glu *g = data;
    g->error = code;
}

int bench_glu_open(bench_glu *g, double tolerance, bench_glu_triangle_fn on_triangle, void *user)
{
    *g = (bench_glu){.on_triangle = on_triangle, .user = user};
    g->nurb = gluNewNurbsRenderer();
    if (!g->nurb)
        return 0;
    gluNurbsProperty(g->nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(g->nurb, GLU_SAMPLING_METHOD, GLU_OBJECT_PARAMETRIC_ERROR);
    gluNurbsProperty(g->nurb, GLU_PARAMETRIC_TOLERANCE, (GLfloat)tolerance);
    /* Object-space sampling already turned GLU_AUTO_LOAD_MATRIX off and the
     * sampling matrix to identity; loading matrices here would rescale it. */
    gluNurbsProperty(g->nurb, GLU_CULLING, GL_FALSE);
    gluNurbsCallbackData(g->nurb, g);
    /* _GLUfuncptr is void (*)(void), which GCC lets any function pointer become. */
    gluNurbsCallback(g->nurb, GLU_NURBS_BEGIN_DATA, (_GLUfuncptr)on_begin);
    gluNurbsCallback(g->nurb, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)on_vertex);
    gluNurbsCallback(g->nurb, GLU_NURBS_NORMAL_DATA, (_GLUfuncptr)on_normal);
    gluNurbsCallback(g->nurb, GLU_NURBS_END_DATA, (_GLUfuncptr)on_end);
    gluNurbsCallback(g->nurb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
    if (on_triangle)
        gluNurbsCallback(g->nurb, GLU_NURBS_TEXTURE_COORD_DATA, (_GLUfuncptr)on_texcoord);
    return 1;
}

void bench_glu_close(bench_glu *g)
{
    if (g->nurb)
        gluDeleteNurbsRenderer(g->nurb);
    free(g->prim);
    g->nurb = NULL, g->prim = NULL, g->prim_cap = 0;
}

const char *bench_glu_problem(const bench_glu *g)
{
    if (g->error)
        return (const char *)gluErrorString(g->error);
    if (g->out_of_memory)
        return "out of memory capturing GLU's triangles";
    if (g->normals != g->vertices)
        return "GLU gave fewer normals than vertices";
    return NULL;
}

enum { MAX_TRIES = 16 };
#define EQUAL_SLACK 0.01

const char *bench_glu_tune(bench_glu_measure_fn measure, const void *ctx, double start,
                           double target, double *tolerance, int *tries)
{
    double ok = 0, bad = 0, t = start;
    uint64_t ok_tris = 0;
    int n = 0;
    while (n < MAX_TRIES) {
        uint64_t tris = 0;
        double e = 0;
        const char *problem = measure(ctx, t, &tris, &e);
        n++;
        if (problem)
            return problem;
        int met = e <= target * (1 + EQUAL_SLACK);
        if (met && bad == 0 && ok > 0 && tris == ok_tris)
            break; /* doubling changed nothing: GLU's coarsest */
        if (met && t > ok)
            ok = t, ok_tris = tris;
        else if (!met && (bad == 0 || t < bad))
            bad = t;
        if (ok == 0)
            t *= 0.5;
        else if (bad == 0)
            t *= 2;
        else if (bad / ok < 1.1)
            break;
        else
            t = sqrt(ok * bad);
    }
    *tries = n;
    if (ok == 0)
        return "no GLU tolerance tried meets seamwalk's measured error";
    *tolerance = ok;
    return NULL;
}
