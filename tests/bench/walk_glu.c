/* The GLU baseline of walk_baseline.h: every visible surface handed to
 * GLU's NURBS tessellator every frame, its output (strips, fans, triangles)
 * caught by callbacks into the batch as indexed triangles and drawn through
 * the same renderer as seamwalk. GLU samples to a tolerance in pixels
 * (GLU_PARAMETRIC_ERROR, the frame's model-view, projection and viewport
 * loaded with gluLoadSamplingMatrices), the same half pixel seamwalk's
 * bound states. The trims are the Seam Graph's loops at full detail, the
 * finest the pack has; GLU has no level of detail for them. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_glu.h"
#include "trim_glu.h"
#include "walk_baseline.h"

/* A primitive starts a new batch when fewer vertices than this are left:
 * GLU's strips are one row of samples, far fewer. */
enum { ROOM_VERTICES = 16384 };

typedef struct wb_glu {
    GLUnurbs *nurb;
    trim_glu_surface *surfaces;
    uint8_t *made;             /* per surface: GLU took it */
    wb_walk *w;
    const sw_view *view;
    uint32_t surface;          /* the one being tessellated, for its measure */
    double depth;
    uint32_t surface_index;    /* its first index in the batch */
    GLenum type;               /* the current primitive */
    uint32_t prim_first, prim_vertices;
    float uv[2], normal[3];    /* GLU sends them before their vertex */
    uint64_t triangles;        /* the current surface's, across batches */
    uint32_t dropped;          /* vertices or triangles the batch could not take */
    GLenum error;
} wb_glu;

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

/* The part of the current surface already in the batch, measured. */
static void measure_part(wb_glu *g)
{
    wb_walk *w = g->w;
    uint32_t s = g->surface;
    if (w->stats && w->batch.index_count > g->surface_index)
        wb_measure(w, g->surface_index, w->patches + w->surface_first[s],
                   w->pack->surfaces[s].patch_count, s, s, g->depth, g->view);
}

static void GLAPIENTRY on_begin(GLenum type, void *data)
{
    wb_glu *g = data;
    if (WB_BATCH_VERTICES - g->w->batch.vertex_count < ROOM_VERTICES) {
        measure_part(g);
        wb_batch_flush(g->w);
        g->surface_index = 0;
    }
    g->type = type;
    g->prim_first = g->w->batch.vertex_count;
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
    wb_batch *b = &g->w->batch;
    if (b->vertex_count >= WB_BATCH_VERTICES) {
        g->dropped++;
        return;
    }
    sw_vertex *v = &b->verts[b->vertex_count];
    memcpy(v->pos, p, sizeof v->pos);
    for (int k = 0; k < 3; k++)
        v->normal[k] = snorm8(g->normal[k]);
    v->normal[3] = 0;
    memcpy(b->uvs + 2 * (size_t)b->vertex_count, g->uv, sizeof g->uv);
    b->vertex_count++;
    g->prim_vertices++;
}

static void GLAPIENTRY on_end(void *data)
{
    wb_glu *g = data;
    wb_batch *b = &g->w->batch;
    uint64_t n = bench_glu_triangles_in(g->type, g->prim_vertices);
    for (uint64_t t = 0; t < n; t++) {
        if (b->index_count + 3 > WB_BATCH_INDICES) {
            g->dropped++;
            return;
        }
        uint64_t v[3];
        bench_glu_triangle_of(g->type, t, v);
        for (int k = 0; k < 3; k++)
            b->indices[b->index_count++] = (uint16_t)(g->prim_first + v[k]);
        g->triangles++;
    }
}

static void GLAPIENTRY on_error(GLenum code, void *data)
{
    wb_glu *g = data;
    g->error = code;
}

static int open_nurb(wb_glu *g, double tolerance_px)
{
    g->nurb = gluNewNurbsRenderer();
    if (!g->nurb)
        return 0;
    gluNurbsProperty(g->nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(g->nurb, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
    gluNurbsProperty(g->nurb, GLU_SAMPLING_METHOD, GLU_PARAMETRIC_ERROR);
    gluNurbsProperty(g->nurb, GLU_PARAMETRIC_TOLERANCE, (GLfloat)tolerance_px);
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
    sw_trim_point *points = malloc((most_points + 1) * sizeof *points);
    uint32_t *loop_first = malloc((most_loops + 2) * sizeof *loop_first);
    if (g) {
        g->w = w;
        g->surfaces = calloc(n + 1, sizeof *g->surfaces);
        g->made = calloc(n + 1, 1);
    }
    w->glu = g;
    if (!g || !points || !loop_first || !g->surfaces || !g->made) {
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
    if (!open_nurb(g, w->error_px)) {
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

static void load_matrices(wb_glu *g, const sw_view *view)
{
    float mv[16], proj[16];
    sw_mat4_to_float(&view->view, mv);
    sw_mat4_to_float(&view->proj, proj);
    const GLint viewport[4] = { 0, 0, view->width, view->height };
    gluLoadSamplingMatrices(g->nurb, mv, proj, viewport);
}

void wb_glu_frame(wb_walk *w, const sw_view *view, wb_frame *out)
{
    wb_glu *g = w->glu;
    const sw_pack *pack = w->pack;
    g->view = view;
    load_matrices(g, view);
    uint32_t part = UINT32_MAX;
    for (uint32_t s = 0; s < pack->seam.surface_count; s++) {
        double depth;
        if (!g->made[s] || !surface_visible(w, s, view, &depth))
            continue;
        if (pack->surfaces[s].part != part) {  /* the colour is a uniform: flush first */
            wb_batch_flush(w);
            part = pack->surfaces[s].part;
            sw_renderer_set_color(w->renderer, pack->parts[part].color);
        }
        g->surface = s, g->depth = depth, g->surface_index = w->batch.index_count;
        g->dropped = 0, g->error = 0, g->triangles = 0;
        trim_glu_draw(&g->surfaces[s], g->nurb, 1);
        out->failed += g->dropped || g->error;
        out->triangles += g->triangles;
        measure_part(g);
        out->drawn++;
    }
    wb_batch_flush(w);
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
    free(g->surfaces), free(g->made), free(g);
    w->glu = NULL;
}
