/* SPDX-License-Identifier: MIT */
/* The GLU baseline of walk_baseline.h: every visible surface handed to
 * GLU's NURBS tessellator every frame, its output (strips, fans, triangles)
 * caught by callbacks as indexed triangles and drawn through the same
 * renderer as seamwalk. GLU samples each surface to the bound seamwalk
 * gives it: the pixel tolerance at the surface's nearest depth, in model
 * units (GLU_OBJECT_PARAMETRIC_ERROR; surface_tolerance says why not GLU's
 * own pixel sampling). The trims are the Seam Graph's loops at full detail,
 * the finest the pack has; GLU has no level of detail for them.
 *
 * GLU's NURBS code breaks on some real surfaces: valgrind shows it reading
 * and writing blocks it has deleted (a showroom plate with eight holes in
 * frame 30 of the aisle walk, all inside libGLU), and malloc's heap then
 * aborts the process. So each frame's tessellation runs in a forked child
 * that writes the meshes into shared memory and publishes them surface by
 * surface; when the child dies, the surface it was on is counted as failed
 * (left out) and a new child carries on after it. The parent draws and
 * measures. The fork (a few ms for this process) is in the frame's time. */
#define _GNU_SOURCE /* MAP_ANONYMOUS, MAP_NORESERVE */
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_glu.h"
#include "trim_glu.h"
#include "walk_baseline.h"

/* What a frame's GLU output may hold in all (shared memory, touched only
 * as far as it is used) and in one mesh (16-bit local indices). A mesh
 * starts anew when fewer than ROOM vertices are left in it: GLU's strips
 * are one row of samples, far fewer. */
#define WB_GLU_VERTICES (24u << 20)
#define WB_GLU_INDICES (72u << 20)
#define WB_GLU_MESHES (1u << 20)
enum { ROOM_VERTICES = 8192 };

typedef struct wb_glu_mesh {
    uint32_t surface, first_vertex, vertex_count, first_index, index_count;
} wb_glu_mesh;

/* The child's output so far, as published after each whole surface (the
 * parent reads it after waitpid, which orders the writes before it). */
typedef struct wb_glu_done {
    uint32_t surfaces;          /* entries of the visible list finished */
    uint32_t meshes, vertices, indices;
    uint32_t failed;            /* surfaces with a GLU error, or whose output did not fit */
    uint64_t triangles;
} wb_glu_done;

typedef struct wb_glu {
    GLUnurbs *nurb;
    trim_glu_surface *surfaces;
    uint8_t *made;              /* per surface: GLU took it */
    wb_walk *w;
    uint32_t *visible;          /* this frame's surfaces, in order */
    float *visible_depth;
    uint32_t visible_count;
    /* shared with the child */
    wb_glu_done *done;
    wb_glu_mesh *meshes;
    sw_vertex *verts;
    float *uvs;
    uint16_t *indices;
    /* the child's working state */
    wb_glu_done cur;            /* counts including the surface in progress */
    wb_glu_mesh *mesh;          /* the mesh being written */
    GLenum type;
    uint32_t prim_first, prim_vertices;
    float uv[2], normal[3];     /* GLU sends them before their vertex */
    int overflow;
    GLenum error;
} wb_glu;

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

static void *shared(size_t bytes)
{
    void *p = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS | MAP_NORESERVE,
                   -1, 0);
    return p == MAP_FAILED ? NULL : p;
}

static int map_shared(wb_glu *g)
{
    g->done = shared(sizeof *g->done);
    g->meshes = shared(WB_GLU_MESHES * sizeof *g->meshes);
    g->verts = shared(WB_GLU_VERTICES * sizeof *g->verts);
    g->uvs = shared(WB_GLU_VERTICES * 2 * sizeof *g->uvs);
    g->indices = shared(WB_GLU_INDICES * sizeof *g->indices);
    return g->done && g->meshes && g->verts && g->uvs && g->indices;
}

/* A new mesh for the current surface at the end of the output. */
static int open_mesh(wb_glu *g, uint32_t surface)
{
    if (g->cur.meshes >= WB_GLU_MESHES)
        return 0;
    g->mesh = &g->meshes[g->cur.meshes++];
    *g->mesh = (wb_glu_mesh){ surface, g->cur.vertices, 0, g->cur.indices, 0 };
    return 1;
}

static void GLAPIENTRY on_begin(GLenum type, void *data)
{
    wb_glu *g = data;
    if (g->mesh && g->mesh->vertex_count + ROOM_VERTICES > 65536u &&
        !open_mesh(g, g->mesh->surface))
        g->overflow = 1;
    g->type = type;
    g->prim_first = g->mesh ? g->mesh->vertex_count : 0;
    g->prim_vertices = 0;
}

static void GLAPIENTRY on_normal(GLfloat *n, void *data)
{
    wb_glu *g = data;
    memcpy(g->normal, n, sizeof g->normal);
}

static void GLAPIENTRY on_texcoord(GLfloat *t, void *data)
{
    wb_glu *g = data;
    memcpy(g->uv, t, sizeof g->uv);
}

static void GLAPIENTRY on_vertex(GLfloat *p, void *data)
{
    wb_glu *g = data;
    if (g->overflow || g->cur.vertices >= WB_GLU_VERTICES || g->mesh->vertex_count >= 65536u) {
        g->overflow = 1;
        return;
    }
    sw_vertex *v = &g->verts[g->cur.vertices];
    memcpy(v->pos, p, sizeof v->pos);
    for (int k = 0; k < 3; k++)
        v->normal[k] = snorm8(g->normal[k]);
    v->normal[3] = 0;
    memcpy(g->uvs + 2 * (size_t)g->cur.vertices, g->uv, sizeof g->uv);
    g->cur.vertices++;
    g->mesh->vertex_count++;
    g->prim_vertices++;
}

static void GLAPIENTRY on_end(void *data)
{
    wb_glu *g = data;
    uint64_t n = bench_glu_triangles_in(g->type, g->prim_vertices);
    for (uint64_t t = 0; t < n && !g->overflow; t++) {
        if (g->cur.indices + 3 > WB_GLU_INDICES) {
            g->overflow = 1;
            return;
        }
        uint64_t v[3];
        bench_glu_triangle_of(g->type, t, v);
        for (int k = 0; k < 3; k++)
            g->indices[g->cur.indices++] = (uint16_t)(g->prim_first + v[k]);
        g->mesh->index_count += 3;
        g->cur.triangles++;
    }
}

static void GLAPIENTRY on_error(GLenum code, void *data)
{
    wb_glu *g = data;
    g->error = code;
}

static int open_nurb(wb_glu *g)
{
    g->nurb = gluNewNurbsRenderer();
    if (!g->nurb)
        return 0;
    gluNurbsProperty(g->nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    /* Object-space sampling turns GLU_AUTO_LOAD_MATRIX off and the sampling
     * matrix to identity; each surface gets its tolerance (surface_tolerance). */
    gluNurbsProperty(g->nurb, GLU_SAMPLING_METHOD, GLU_OBJECT_PARAMETRIC_ERROR);
    gluNurbsProperty(g->nurb, GLU_CULLING, GL_FALSE);  /* culled by us, as for every row */
    gluNurbsCallbackData(g->nurb, g);
    /* _GLUfuncptr is void (*)(void), which GCC lets any function pointer become. */
    gluNurbsCallback(g->nurb, GLU_NURBS_BEGIN_DATA, (_GLUfuncptr)on_begin);
    gluNurbsCallback(g->nurb, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)on_vertex);
    gluNurbsCallback(g->nurb, GLU_NURBS_NORMAL_DATA, (_GLUfuncptr)on_normal);
    gluNurbsCallback(g->nurb, GLU_NURBS_TEXTURE_COORD_DATA, (_GLUfuncptr)on_texcoord);
    gluNurbsCallback(g->nurb, GLU_NURBS_END_DATA, (_GLUfuncptr)on_end);
    gluNurbsCallback(g->nurb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
    return 1;
}

/* Surface s's loops at full detail, as trim_glu_make takes them. */
static int make_surface(wb_glu *g, uint32_t s, sw_trim_point *points, uint32_t *loop_first,
                        char *why, size_t why_size)
{
    const wb_walk *w = g->w;
    const sw_seam_graph *sg = &w->pack->seam;
    uint32_t count = 0, l0 = sg->surface_loops[s], l1 = sg->surface_loops[s + 1];
    loop_first[0] = 0;
    for (uint32_t l = l0; l < l1; l++) {
        const sw_seam_loop *loop = &sg->loops[l];
        for (uint32_t k = 0; k < loop->slot_count; k++) {
            const sw_seam_slot *slot = &sg->slots[loop->first_slot + k];
            sw_trim_point *p = &points[count++];
            memset(p, 0, sizeof *p);
            memcpy(p->uv, slot->uv, sizeof p->uv);
        }
        loop_first[l - l0 + 1] = count;
    }
    const sw_trim_loops loops = { points, loop_first, l1 - l0 };
    return trim_glu_make(&g->surfaces[s], w->patches + w->surface_first[s],
                         w->pack->surfaces[s].patch_count, &loops, why, why_size);
}

int wb_glu_init(wb_walk *w, uint32_t *skipped, char *why, size_t why_size)
{
    const sw_seam_graph *sg = &w->pack->seam;
    uint32_t n = sg->surface_count, most_points = 0, most_loops = 0;
    for (uint32_t s = 0; s < n; s++) {
        uint32_t points = 0;
        for (uint32_t l = sg->surface_loops[s]; l < sg->surface_loops[s + 1]; l++)
            points += sg->loops[l].slot_count;
        most_points = points > most_points ? points : most_points;
        uint32_t loops = sg->surface_loops[s + 1] - sg->surface_loops[s];
        most_loops = loops > most_loops ? loops : most_loops;
    }
    wb_glu *g = calloc(1, sizeof *g);
    if (g && !map_shared(g)) {
        free(g);
        g = NULL;
    }
    sw_trim_point *points = malloc((most_points + 1) * sizeof *points);
    uint32_t *loop_first = malloc((most_loops + 2) * sizeof *loop_first);
    if (g) {
        g->w = w;
        g->surfaces = calloc(n + 1, sizeof *g->surfaces);
        g->made = calloc(n + 1, 1);
        g->visible = calloc(n + 1, sizeof *g->visible);
        g->visible_depth = calloc(n + 1, sizeof *g->visible_depth);
    }
    w->glu = g;
    if (!g || !points || !loop_first || !g->surfaces || !g->made || !g->visible ||
        !g->visible_depth) {
        free(points), free(loop_first);
        snprintf(why, why_size, "out of memory for GLU's surfaces");
        return 0;
    }
    *skipped = 0;
    for (uint32_t s = 0; s < n; s++) {
        char one[256] = "";
        g->made[s] = (uint8_t)make_surface(g, s, points, loop_first, one, sizeof one);
        *skipped += !g->made[s];
    }
    free(points), free(loop_first);
    if (!open_nurb(g)) {
        snprintf(why, why_size, "gluNewNurbsRenderer failed");
        return 0;
    }
    return 1;
}

/* Whether any of surface s's patches is in view, and the nearest depth. */
static int surface_visible(const wb_walk *w, uint32_t s, const sw_view *view, double *depth)
{
    const sw_pack_surface *ps = &w->pack->surfaces[s];
    *depth = INFINITY;
    for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
        double d;
        if (wb_patch_visible(w->pack, i, view, &d))
            *depth = fmin(*depth, d);
    }
    return isfinite(*depth);
}

/* The surface's tolerance in model units: w->error_px pixels at its
 * nearest depth, never below seamwalk's floor (a tenth of the sewing
 * tolerance): the bound seamwalk tessellates the surface for (paper 004,
 * 6.1). GLU's own pixel sampling (GLU_PARAMETRIC_ERROR with the frame's
 * matrices) would project every sample, so a surface reaching behind the
 * eye, as the floor under a walker does, has no sound rate; object space
 * has one everywhere. */
static void surface_tolerance(wb_glu *g, const sw_view *view, double depth)
{
    double t = fmax(sw_view_error_world(view, g->w->error_px, depth), g->w->bound_floor);
    gluNurbsProperty(g->nurb, GLU_PARAMETRIC_TOLERANCE, (GLfloat)t);
}

/* The child: the visible surfaces from entry `from` on, each published
 * when whole (a surface that fails is left out and counted). */
static void tessellate_from(wb_glu *g, const sw_view *view, uint32_t from)
{
    g->cur = *g->done;
    for (uint32_t k = from; k < g->visible_count; k++) {
        uint32_t s = g->visible[k];
        g->overflow = 0, g->error = 0, g->mesh = NULL;
        wb_glu_done before = g->cur;
        if (open_mesh(g, s)) {
            surface_tolerance(g, view, g->visible_depth[k]);
            trim_glu_draw(&g->surfaces[s], g->nurb, 1);
        } else {
            g->overflow = 1;
        }
        if (g->overflow || g->error) {
            g->cur = before;
            g->cur.failed++;
        }
        g->cur.surfaces = k + 1;
        *g->done = g->cur;
    }
}

/* Children until the visible list is done; a child that dies leaves out
 * the surface it was on. */
static void tessellate_frame(wb_glu *g, const sw_view *view)
{
    *g->done = (wb_glu_done){ 0, 0, 0, 0, 0, 0 };
    while (g->done->surfaces < g->visible_count) {
        uint32_t from = g->done->surfaces;
        fflush(NULL);
        pid_t child = fork();
        if (child == 0) {
            tessellate_from(g, view, from);
            _exit(0);
        }
        int status = 0;
        if (child < 0 || waitpid(child, &status, 0) != child)
            return;   /* no child: the rest is not drawn, and not counted as drawn */
        if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
            g->done->failed++;
            g->done->surfaces++;   /* the one it died on */
        }
    }
}

static void cull(wb_glu *g, const sw_view *view)
{
    const sw_pack *pack = g->w->pack;
    g->visible_count = 0;
    for (uint32_t s = 0; s < pack->seam.surface_count; s++) {
        double depth;
        if (g->made[s] && surface_visible(g->w, s, view, &depth)) {
            g->visible_depth[g->visible_count] = (float)depth;
            g->visible[g->visible_count++] = s;
        }
    }
}

/* Mesh m into the batch (indices made batch-relative), drawn in the colour
 * of its part, measured as its surface. */
static void draw_mesh(wb_glu *g, const wb_glu_mesh *m, double depth, const sw_view *view,
                      uint32_t *part)
{
    wb_walk *w = g->w;
    wb_batch *b = &w->batch;
    const sw_pack *pack = w->pack;
    if (pack->surfaces[m->surface].part != *part) {  /* the colour is a uniform: flush first */
        wb_batch_flush(w);
        *part = pack->surfaces[m->surface].part;
        sw_renderer_set_color(w->renderer, pack->parts[*part].color);
    }
    if (b->vertex_count + m->vertex_count > WB_BATCH_VERTICES ||
        b->index_count + m->index_count > WB_BATCH_INDICES)
        wb_batch_flush(w);
    uint32_t v0 = b->vertex_count, i0 = b->index_count;
    memcpy(b->verts + v0, g->verts + m->first_vertex, m->vertex_count * sizeof *b->verts);
    memcpy(b->uvs + 2 * (size_t)v0, g->uvs + 2 * (size_t)m->first_vertex,
           2 * sizeof(float) * m->vertex_count);
    for (uint32_t i = 0; i < m->index_count; i++)
        b->indices[i0 + i] = (uint16_t)(v0 + g->indices[m->first_index + i]);
    b->vertex_count += m->vertex_count;
    b->index_count += m->index_count;
    wb_measure(w, i0, w->patches + w->surface_first[m->surface],
               pack->surfaces[m->surface].patch_count, m->surface, m->surface, depth, view);
}

void wb_glu_frame(wb_walk *w, const sw_view *view, wb_frame *out)
{
    wb_glu *g = w->glu;
    cull(g, view);
    tessellate_frame(g, view);
    uint32_t part = UINT32_MAX, k = 0, last = UINT32_MAX;
    for (uint32_t i = 0; i < g->done->meshes; i++) {
        const wb_glu_mesh *m = &g->meshes[i];
        while (k < g->visible_count && g->visible[k] != m->surface)
            k++;   /* meshes follow the visible list's order */
        draw_mesh(g, m, k < g->visible_count ? g->visible_depth[k] : view->near_z, view, &part);
        out->drawn += m->surface != last;
        last = m->surface;
    }
    wb_batch_flush(w);
    out->triangles += g->done->triangles;
    out->failed += g->done->failed;
}

void wb_glu_free(wb_walk *w)
{
    wb_glu *g = w->glu;
    if (!g)
        return;
    if (g->nurb)
        gluDeleteNurbsRenderer(g->nurb);
    for (uint32_t s = 0; g->surfaces && s < w->pack->seam.surface_count; s++)
        if (g->made[s])
            trim_glu_free(&g->surfaces[s]);
    munmap(g->done, sizeof *g->done);
    munmap(g->meshes, WB_GLU_MESHES * sizeof *g->meshes);
    munmap(g->verts, WB_GLU_VERTICES * sizeof *g->verts);
    munmap(g->uvs, WB_GLU_VERTICES * 2 * sizeof *g->uvs);
    munmap(g->indices, WB_GLU_INDICES * sizeof *g->indices);
    free(g->surfaces), free(g->made), free(g->visible), free(g->visible_depth), free(g);
    w->glu = NULL;
}
