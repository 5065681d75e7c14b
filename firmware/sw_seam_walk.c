#include "sw_seam_walk.h"

#include <float.h>
#include <math.h>
#include <string.h>
#include <time.h>

#include "sw_seam_surface.h"

enum { SW_SEAM_WALK_TINY = 2 }; /* w->visible: in view, smaller than its bound */

/* Bounds of invisible surfaces: as coarse as the hierarchy goes (their
 * vertices still meet the bounds of visible neighbours that show them). */
#define SW_SEAM_INVISIBLE_BOUND 1e30f

typedef struct surface_sizes {
    uint32_t points, loops, patches;
} surface_sizes;

/* The largest surface in points, loops and patches, each on its own. */
static surface_sizes largest_surface(const sw_pack *pack)
{
    const sw_seam_graph *g = &pack->seam;
    surface_sizes m = { 0, 0, 0 };
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t points = 0, l0 = g->surface_loops[s], l1 = g->surface_loops[s + 1];
        for (uint32_t l = l0; l < l1; l++)
            points += g->loops[l].slot_count;
        const sw_pack_surface *ps = &pack->surfaces[s];
        m.points = points > m.points ? points : m.points;
        m.loops = l1 - l0 > m.loops ? l1 - l0 : m.loops;
        m.patches = ps->patch_count > m.patches ? ps->patch_count : m.patches;
    }
    return m;
}

static size_t scratch_bytes(const surface_sizes *m)
{
    return sw_trim_tess_scratch_bytes(m->patches, m->points, SW_BEZIER_MAX_DEGREE, NULL);
}

size_t sw_seam_walk_arena_bytes(const sw_pack *pack)
{
    surface_sizes m = largest_surface(pack);
    size_t n = pack->seam.surface_count, v = SW_SEAM_WALK_VERTICES, i = SW_SEAM_WALK_INDICES;
    return sw_seam_select_arena_bytes(&pack->seam) + sw_arena_worst_case(n * 17 + 1, 64) +
           sw_arena_worst_case((m.points + 1) * (sizeof(sw_seam_point) + sizeof(sw_trim_point)), 64) +
           sw_arena_worst_case((m.loops + 1) * sizeof(uint32_t), 64) +
           sw_arena_worst_case((m.patches + 1) * sizeof(sw_trim_patch), 64) +
           sw_arena_worst_case(scratch_bytes(&m), 64) +
           sw_arena_worst_case(v * (8 * sizeof(float) + sizeof(uint32_t) + sizeof(sw_vertex)), 64) +
           2 * sw_arena_worst_case(i * sizeof(uint16_t), 64) + 16 * 64;
}

static void *take(sw_arena *a, size_t bytes, int *failed)
{
    void *p = sw_arena_alloc(a, bytes + 1, 64);
    *failed |= p == NULL;
    return p;
}

/* The patch of the surface whose domain holds (u, v) (the nearest one for
 * points an ulp outside), and the point's local parameters in it. */
static const sw_trim_patch *patch_at(const sw_seam_walk *w, uint32_t n, double u, double v,
                                     double *s, double *t)
{
    const sw_trim_patch *best = &w->patches[0];
    double best_out = INFINITY;
    for (uint32_t i = 0; i < n; i++) {
        const float *d = w->patches[i].domain;
        double out = fmax(fmax(d[0] - u, u - d[1]), fmax(d[2] - v, v - d[3]));
        if (out < best_out)
            best_out = out, best = &w->patches[i];
    }
    const float *d = best->domain;
    *s = fmin(fmax((u - d[0]) / (d[1] - d[0]), 0.0), 1.0);
    *t = fmin(fmax((v - d[2]) / (d[3] - d[2]), 0.0), 1.0);
    return best;
}

/* The exact surface (its patches in w->patches) at (u, v). */
static sw_vec3 surface_point(const sw_seam_walk *w, uint32_t patch_count, double u, double v)
{
    double s, t, ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    const sw_trim_patch *tp = patch_at(w, patch_count, u, v, &s, &t);
    sw_bezier_patch exact = sw_bezier_patch_from_float(&tp->patch, ctrl);
    sw_surface_point sp;
    sw_bezier_eval(&exact, s, t, SW_EVAL_POINT, &sp);
    return sp.p;
}

/* Each surface's sewing offset: how far its sewn border (the original
 * polylines, at full detail) lies from the surface, at each slot and at the
 * middle of each segment, against the surface at the same (u, v). The
 * sewing moves vertices up to the tolerance to close a file's gaps, and the
 * polylines are flat to half the tolerance, so near views whose bound is
 * finer than that see the border off by up to this much. Once, at init. */
static double border_offset(const sw_seam_walk *w, uint32_t patch_count, const sw_seam_loop *loop)
{
    const sw_seam_graph *g = &w->pack->seam;
    double worst = 0;
    for (uint32_t k = 0; k < loop->slot_count; k++) {
        const sw_seam_slot *a = &g->slots[loop->first_slot + k];
        const sw_seam_slot *b = &g->slots[loop->first_slot + (k + 1) % loop->slot_count];
        const float *p = g->vertices[a->vertex].p, *q = g->vertices[b->vertex].p;
        sw_vec3 at = surface_point(w, patch_count, a->uv[0], a->uv[1]);
        sw_vec3 mid = surface_point(w, patch_count, 0.5 * ((double)a->uv[0] + b->uv[0]),
                                    0.5 * ((double)a->uv[1] + b->uv[1]));
        sw_vec3 chord = sw_v3(0.5 * ((double)p[0] + q[0]), 0.5 * ((double)p[1] + q[1]),
                              0.5 * ((double)p[2] + q[2]));
        worst = fmax(worst, sw_v3_length(sw_v3_sub(at, sw_v3(p[0], p[1], p[2]))));
        worst = fmax(worst, sw_v3_length(sw_v3_sub(mid, chord)));
    }
    return worst;
}

static sw_status measure_sewing(sw_seam_walk *w, sw_error *err)
{
    const sw_seam_graph *g = &w->pack->seam;
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t patch_count = 0;
        sw_status st = sw_trim_patches_from_pack(w->pack, s, w->patches, w->max_patches,
                                                 &patch_count, err);
        if (st != SW_OK)
            return st;
        double worst = 0;
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
            worst = fmax(worst, border_offset(w, patch_count, &g->loops[l]));
        w->sew_offset[s] = (float)worst;
    }
    return SW_OK;
}

sw_status sw_seam_walk_init(sw_seam_walk *w, const sw_pack *pack, sw_arena *arena, double error_px,
                            sw_error *err)
{
    memset(w, 0, sizeof *w);
    if (!pack->seam_header)
        return sw_error_set(err, SW_ERR_ARG, "the pack has no Seam Graph (build it again with "
                            "this seamwalk-pack)");
    w->pack = pack;
    w->error_px = error_px;
    w->bound_floor = 0.1f * pack->seam.tolerance;
    sw_status st = sw_seam_select_init(&w->select, &pack->seam, arena, err);
    if (st != SW_OK)
        return st;
    surface_sizes m = largest_surface(pack);
    w->max_points = m.points, w->max_loops = m.loops, w->max_patches = m.patches;
    size_t n = pack->seam.surface_count, v = SW_SEAM_WALK_VERTICES;
    int failed = 0;
    w->bound = take(arena, n * sizeof(float), &failed);
    w->seam_bound = take(arena, n * sizeof(float), &failed);
    w->visible = take(arena, n, &failed);
    w->sew_offset = take(arena, n * sizeof(float), &failed);
    w->depth = take(arena, n * sizeof(float), &failed);
    w->loop_points = take(arena, (m.points + 1) * sizeof(sw_seam_point), &failed);
    w->points = take(arena, (m.points + 1) * sizeof(sw_trim_point), &failed);
    w->loop_first = take(arena, (m.loops + 1) * sizeof(uint32_t), &failed);
    w->patches = take(arena, (m.patches + 1) * sizeof(sw_trim_patch), &failed);
    void *scratch = take(arena, scratch_bytes(&m), &failed);
    w->positions = take(arena, v * 3 * sizeof(float), &failed);
    w->normals = take(arena, v * 3 * sizeof(float), &failed);
    w->uvs = take(arena, v * 2 * sizeof(float), &failed);
    w->ids = take(arena, v * sizeof(uint32_t), &failed);
    w->indices = take(arena, SW_SEAM_WALK_INDICES * sizeof(uint16_t), &failed);
    w->batch_vertices = take(arena, v * sizeof(sw_vertex), &failed);
    w->batch_indices = take(arena, SW_SEAM_WALK_INDICES * sizeof(uint16_t), &failed);
    if (failed)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the seam walk "
                            "(needs %zu bytes)", sw_seam_walk_arena_bytes(pack));
    sw_arena_init(&w->scratch, scratch, scratch_bytes(&m));
    return measure_sewing(w, err);
}

/* Visible when any of its patches' boxes is; depth the nearest of those.
 * A visible surface whose whole box fits within its bound is too small to
 * draw: leaving it out is within the bound (the paper's vanishing patch,
 * without waiting for its loops to collapse, which takes the seams' share
 * of the bound: a few times farther). */
static void cull_surface(sw_seam_walk *w, const sw_view *view, uint32_t s)
{
    const sw_pack_surface *ps = &w->pack->surfaces[s];
    double depth = INFINITY;
    sw_box all = { sw_v3(INFINITY, INFINITY, INFINITY), sw_v3(-INFINITY, -INFINITY, -INFINITY) };
    for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
        const sw_pack_patch *p = &w->pack->patches[i];
        sw_box box = { sw_v3(p->box_min[0], p->box_min[1], p->box_min[2]),
                       sw_v3(p->box_max[0], p->box_max[1], p->box_max[2]) };
        if (sw_frustum_test_box(&view->frustum, &box) != SW_CULL_OUTSIDE)
            depth = fmin(depth, sw_view_box_min_depth(view, &box));
        all.min = sw_v3(fmin(all.min.x, box.min.x), fmin(all.min.y, box.min.y),
                        fmin(all.min.z, box.min.z));
        all.max = sw_v3(fmax(all.max.x, box.max.x), fmax(all.max.y, box.max.y),
                        fmax(all.max.z, box.max.z));
    }
    w->visible[s] = isfinite(depth);
    w->depth[s] = (float)depth;
    double bound = w->visible[s] ? sw_view_error_world(view, w->error_px, depth) : 0.0;
    if (w->visible[s] && sw_v3_length(sw_v3_sub(all.max, all.min)) <= bound)
        w->visible[s] = SW_SEAM_WALK_TINY;
    w->bound[s] = w->visible[s] != 1 ? SW_SEAM_INVISIBLE_BOUND
                                     : (float)fmax(bound, (double)w->bound_floor);
    w->seam_bound[s] = w->bound[s] * (float)SW_SEAM_SHARE;
}

sw_status sw_seam_walk_select(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame,
                              sw_error *err)
{
    memset(frame, 0, sizeof *frame);
    for (uint32_t s = 0; s < w->pack->seam.surface_count; s++) {
        cull_surface(w, view, s);
        frame->visible_surfaces += w->visible[s] != 0;
    }
    sw_seam_update_result r;
    sw_status st = sw_seam_select_update(&w->select, w->seam_bound, 0, &r, err);
    if (st != SW_OK)
        return st;
    /* The front's own count: sw_seam_select_count would walk every loop. */
    frame->active_vertices = w->select.active_count;
    return SW_OK;
}

/* The surface's current loops as the tessellator takes them, the outer ones
 * first (*outer of them); 0 when its outer loop has vanished (then it is not
 * drawn). */
static int gather_loops(sw_seam_walk *w, uint32_t s, sw_trim_loops *loops, uint32_t *outer)
{
    const sw_seam_surface_buffers buf = { w->loop_points, w->points, w->loop_first,
                                          w->max_points };
    return sw_seam_surface_loops(&w->select, s, w->seam_bound[s], &buf, loops, outer);
}

/* Tessellates surface s at its bound, coarsening (x4, three times) when it
 * would need more than 65536 vertices. */
static sw_status tessellate(sw_seam_walk *w, uint32_t s, const sw_trim_loops *loops,
                            sw_trim_tess_result *result, uint32_t *patch_count)
{
    sw_status st = sw_trim_patches_from_pack(w->pack, s, w->patches, w->max_patches, patch_count,
                                             NULL);
    if (st != SW_OK)
        return st;
    sw_trim_tess_buffers out = { w->positions, w->normals, w->uvs, w->ids, w->indices,
                                 SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES, 0 };
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    double bound = w->bound[s];
    for (int attempt = 0; attempt < 4; attempt++, bound *= 4.0) {
        st = sw_trim_tess(w->patches, *patch_count, loops, bound, &opt, &w->scratch, &out,
                          result, NULL);
        if (st != SW_ERR_RANGE)
            break;
    }
    return st;
}

static void flush(sw_seam_walk *w, sw_renderer *r)
{
    if (w->batch_index_count)
        sw_renderer_draw(r, w->batch_vertices, w->batch_vertex_count, w->batch_indices,
                         w->batch_index_count);
    w->batch_vertex_count = 0;
    w->batch_index_count = 0;
}

static int8_t snorm8(float x)
{
    float c = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
    return (int8_t)lrintf(c * 127.0f);
}

static void append(sw_seam_walk *w, sw_renderer *r, const sw_trim_tess_result *t)
{
    if (w->batch_vertex_count + t->vertex_count > SW_SEAM_WALK_VERTICES ||
        w->batch_index_count + t->index_count > SW_SEAM_WALK_INDICES)
        flush(w, r);
    uint32_t base = w->batch_vertex_count;
    for (uint32_t i = 0; i < t->vertex_count; i++) {
        sw_vertex *v = &w->batch_vertices[base + i];
        memcpy(v->pos, w->positions + 3 * i, sizeof v->pos);
        for (int k = 0; k < 3; k++)
            v->normal[k] = snorm8(w->normals[3 * i + k]);
        v->normal[3] = 0;
    }
    for (uint32_t i = 0; i < t->index_count; i++)
        w->batch_indices[w->batch_index_count + i] = (uint16_t)(w->indices[i] + base);
    w->batch_vertex_count += t->vertex_count;
    w->batch_index_count += t->index_count;
}

/* Border vertices must be their seam vertex's position bit for bit (the
 * neighbour across the seam draws the same float), and every loop point must
 * be in the mesh: each violation is a crack. */
static uint64_t count_cracks(const sw_seam_walk *w, const sw_trim_tess_result *t,
                             uint64_t *crossings)
{
    uint64_t cracks = t->dropped_points;
    for (uint32_t i = 0; i < t->vertex_count; i++) {
        *crossings += w->ids[i] == SW_TRIM_CROSSING;
        if (w->ids[i] == SW_TRIM_INTERIOR || w->ids[i] == SW_TRIM_CROSSING)
            continue;
        const float *p = w->pack->seam.vertices[w->ids[i]].p;
        cracks += memcmp(p, w->positions + 3 * i, 3 * sizeof(float)) != 0;
    }
    return cracks;
}

/* One sample: the flat triangle's point at barycentric weights b against the
 * exact surface at the same interpolated (u, v), in pixels at its depth;
 * also what it exceeds the surface's sewing offset by, against the bound. */
static void sample(const sw_seam_walk *w, uint32_t s, uint32_t n, const uint16_t idx[3],
                   const double b[3], const sw_view *view, sw_stats *stats, sw_seam_frame *frame)
{
    double flat[3] = { 0, 0, 0 }, uv[2] = { 0, 0 };
    for (int k = 0; k < 3; k++) {
        for (int c = 0; c < 3; c++)
            flat[c] += b[k] * w->positions[3 * idx[k] + c];
        for (int c = 0; c < 2; c++)
            uv[c] += b[k] * w->uvs[2 * idx[k] + c];
    }
    sw_vec3 q = surface_point(w, n, uv[0], uv[1]);
    double px = view->px_per_unit / fmax(sw_view_depth(view, q), view->near_z);
    double d = sw_v3_length(sw_v3_sub(q, sw_v3(flat[0], flat[1], flat[2])));
    sw_stats_add_error_px(stats, d * px);
    /* in pixels where the bound is half a pixel; scaled down where the
     * bound's floor (a tenth of the sewing tolerance) is coarser */
    double allowed = fmax(w->error_px / px, (double)w->bound_floor);
    frame->error_beyond_sewing_px = fmax(frame->error_beyond_sewing_px,
                                         (d - (double)w->sew_offset[s]) / allowed * w->error_px);
}

/* Every triangle at its centroid and edge midpoints. */
static void measure_surface(const sw_seam_walk *w, uint32_t s, uint32_t patch_count,
                            const sw_trim_tess_result *t, const sw_view *view, sw_stats *stats,
                            sw_seam_frame *frame)
{
    static const double weights[4][3] = { { 1 / 3.0, 1 / 3.0, 1 / 3.0 }, { 0.5, 0.5, 0 },
                                          { 0, 0.5, 0.5 }, { 0.5, 0, 0.5 } };
    for (uint32_t i = 0; i + 2 < t->index_count; i += 3)
        for (int k = 0; k < 4; k++)
            sample(w, s, patch_count, w->indices + i, weights[k], view, stats, frame);
    double depth = fmax((double)w->depth[s], view->near_z);
    frame->sewing_offset_px = fmax(frame->sewing_offset_px,
                                   w->sew_offset[s] * view->px_per_unit / depth);
}

void sw_seam_walk_draw(sw_seam_walk *w, sw_renderer *r, const sw_view *view, sw_stats *stats,
                       sw_seam_frame *frame)
{
    const sw_pack *pack = w->pack;
    uint32_t part = UINT32_MAX;
    if (stats)
        stats->measured_frames++;
    for (uint32_t s = 0; s < pack->seam.surface_count; s++) {
        if (!w->visible[s])
            continue;
        if (w->visible[s] == SW_SEAM_WALK_TINY) {
            frame->vanished_surfaces++;
            continue;
        }
        sw_trim_loops loops;
        uint32_t outer = 0;
        if (!gather_loops(w, s, &loops, &outer)) {
            frame->vanished_surfaces++;
            continue;
        }
        sw_trim_tess_result t;
        uint32_t patch_count = 0;
        sw_status st = tessellate(w, s, &loops, &t, &patch_count);
        if (st == SW_ERR_FORMAT && outer < loops.loop_count) {
            /* A hole's coarse polyline crosses another loop (both are within
             * the bound of where they belong, and so of each other): drawn
             * without its holes rather than not at all. */
            loops.loop_count = outer;
            st = tessellate(w, s, &loops, &t, &patch_count);
            frame->holes_filled += st == SW_OK;
        }
        if (st != SW_OK) {
            /* A visible surface left out is a hole: every point of its
             * border has nothing on this side, so each counts as a crack. */
            frame->failed_surfaces++;
            frame->cracks += loops.loop_first[loops.loop_count] - loops.loop_first[0];
            continue;
        }
        if (pack->surfaces[s].part != part) {
            flush(w, r);
            part = pack->surfaces[s].part;
            sw_renderer_set_color(r, pack->parts[part].color);
        }
        append(w, r, &t);
        frame->drawn_surfaces++;
        frame->triangles += t.index_count / 3;
        frame->cracks += count_cracks(w, &t, &frame->crossings);
        if (stats) {
            struct timespec a, b;
            clock_gettime(CLOCK_MONOTONIC, &a);
            measure_surface(w, s, patch_count, &t, view, stats, frame);
            clock_gettime(CLOCK_MONOTONIC, &b);
            frame->measure_ms += (double)(b.tv_sec - a.tv_sec) * 1e3 + (b.tv_nsec - a.tv_nsec) * 1e-6;
        }
    }
    flush(w, r);
}
