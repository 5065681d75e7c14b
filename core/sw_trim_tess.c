/* SPDX-License-Identifier: MIT */
/* Trimmed tessellation (paper 004 section 6.3's trimming, on a grid instead
 * of the paper's binary trees). The steps, one file each:
 * - sw_trim_loops.c: the loops oriented and moved a tiny distance into the
 *   trimmed region (the region shrink, SW_TT_SHRINK_REL of the domain), so
 *   no loop runs along a grid line and loops no longer touch; output keeps
 *   every loop point's own (u, v) and position.
 * - sw_trim_grid.c: the conformal tensor grid from the sub-patches' proven
 *   second-derivative bounds (every cell within error, no T-vertex).
 * - sw_trim_bucket.c: loop segments by cell, grid lines added through holes
 *   inside one cell and through very crowded cells.
 * - sw_trim_sweep.c: the row sweep: inside cells as two triangles, crossed
 *   cells clipped (sw_trim_cell.c) and ear clipped, in parts where their
 *   bound exceeds border_error or they hold many loop points.
 * - sw_trim_eval.c: exact evaluation, once per vertex.
 * This file: input checks, the vertex table and output, the entry points.
 * Partial: loops are assumed not to cross each other or themselves (the
 * clipping reports SW_ERR_FORMAT where its walk notices, not always);
 * consecutive loop points with equal (u, v) are merged. */
#include "sw_trim_tess.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "sw_pack_instances.h"
#include "sw_trim_tess_internal.h"

static uint32_t max_vertices_of(const sw_trim_tess_options *opt, uint32_t base)
{
    uint32_t cap = base < 65536u ? 65536u - base : 0;
    uint32_t want = opt && opt->max_vertices ? opt->max_vertices : cap;
    return want < cap ? want : cap;
}

static uint32_t max_depth_of(const sw_trim_tess_options *opt)
{
    uint32_t d = opt && opt->max_depth ? opt->max_depth : SW_TT_DEFAULT_DEPTH;
    return d > SW_TT_MAX_DEPTH ? SW_TT_MAX_DEPTH : d;
}

static uint32_t hash_size(uint32_t max_vertices)
{
    uint32_t h = 16;
    while (h < 2 * (uint64_t)max_vertices)
        h *= 2;
    return h;
}

size_t sw_trim_tess_scratch_bytes(uint32_t patch_count, uint32_t point_count, int max_degree,
                                  const sw_trim_tess_options *opt)
{
    size_t d = (size_t)(max_degree < 1 ? 1 : max_degree > SW_BEZIER_MAX_DEGREE
                                                 ? SW_BEZIER_MAX_DEGREE : max_degree);
    size_t ctrl = sw_tt_ctrl_doubles((int)d, (int)d) * sizeof(double) + 8;
    size_t v = max_vertices_of(opt, 0), n = point_count, np = patch_count;
    /* patches, loops (sw_trim_loops.c) */
    size_t bytes = np * (ctrl + sizeof(sw_bezier_patch) + 8) + 3 * ctrl;
    bytes += n * (sizeof(sw_tt_point) + 2 * sizeof(uint32_t) + 2 * sizeof(double)) +
             (n / 3 + 1) * (sizeof(sw_tt_loop) + sizeof(uint32_t)) + 64; /* + collapsed */
    /* knots, patch table, sub-patch bounds and counts (sw_trim_grid.c) */
    size_t bounds = 3 * (SW_TT_MAX_SUB * SW_TT_MAX_SUB + 1) * sizeof(double); /* subs, whole */
    bytes += np * (4 * sizeof(double) + 1 + bounds + 4 * SW_TT_MAX_SUB * sizeof(double)) +
             (4 * np + 16) * sizeof(uint32_t);
    /* grid lines, each axis at most v + 4 np + SW_TT_MAX_INSERT (lay_lines) */
    size_t lines = v + 4 * np + SW_TT_MAX_INSERT + 2;
    bytes += 2 * lines * (sizeof(double) + sizeof(uint32_t) + 1);
    /* pairs twice, row and column starts (sw_trim_bucket.c) */
    bytes += 2 * (4 * v + 2 * n + 64) * sizeof(tt_pair) + 2 * lines * sizeof(uint32_t);
    /* vertex table */
    bytes += v * (2 * sizeof(double) + 1) + hash_size((uint32_t)v) * sizeof(uint32_t) +
             n * (sizeof(sw_vec3) + 1) + (4 * v + 2 * n + 64);
    /* the sweep: per loop point a mark, a crossing, a segment; per column
     * split flags and two vertex ids; the evaluation cache per knot column */
    bytes += (n + 1) * 16 + lines * (3 + 2 * sizeof(uint32_t)) +
             4 * np * (8 * (d + 1) * sizeof(double) + sizeof(uint32_t));
    /* One cell at a time: per border point (at most 4 SW_TT_MAX_SPLIT) or
     * loop point an item of the walk (56 bytes), a ring vertex and its ring
     * end (36), chain tables (21) and the ear clipping's map, links,
     * triangles and quality (32); rounded up. */
    bytes += SW_TT_BASIS_BYTES;
    size_t cell = 4 * SW_TT_MAX_SPLIT + 3 * n + 8;
    bytes += cell * 168;
    return bytes + 64 * 64; /* alignment of every allocation */
}

/* ---- input ----------------------------------------------------------------- */

static sw_status check_patches(tt_ctx *c)
{
    for (uint32_t i = 0; i < c->patch_count; i++) {
        const sw_trim_patch *p = &c->in_patches[i];
        const float *d = p->domain;
        if (!p->patch.ctrl || p->patch.degree_u < 1 || p->patch.degree_u > SW_BEZIER_MAX_DEGREE ||
            p->patch.degree_v < 1 || p->patch.degree_v > SW_BEZIER_MAX_DEGREE)
            return sw_error_set(c->err, SW_ERR_ARG, "trim tess: patch %u: degree %d x %d or no "
                                "control points, expected 1..%d", (unsigned)i, p->patch.degree_u,
                                p->patch.degree_v, SW_BEZIER_MAX_DEGREE);
        if (!(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && isfinite(d[3]) &&
              d[0] < d[1] && d[2] < d[3]))
            return sw_error_set(c->err, SW_ERR_ARG, "trim tess: patch %u: domain [%g, %g] x [%g, "
                                "%g], expected finite, u0 < u1, v0 < v1", (unsigned)i, d[0], d[1],
                                d[2], d[3]);
        if (p->patch.degree_u > c->max_n)
            c->max_n = p->patch.degree_u;
        if (p->patch.degree_v > c->max_m)
            c->max_m = p->patch.degree_v;
    }
    return SW_OK;
}

/* What sw_bezier_second_deriv_bounds would refuse, without its work:
 * non-finite coordinates, weights not finite and > 0. */
static sw_status check_control(tt_ctx *c, uint32_t p)
{
    const sw_bezier_patch *b = &c->patches[p];
    for (int j = 0; j <= b->degree_v; j++)
        for (int i = 0; i <= b->degree_u; i++) {
            const double *x = b->ctrl + ((size_t)j * (size_t)(b->degree_u + 1) + (size_t)i) * 4;
            if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
                return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: patch %u: control point "
                                    "(%d, %d): coordinate not finite", (unsigned)p, i, j);
            if (b->rational && !(x[3] > 0 && isfinite(x[3])))
                return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: patch %u: control point "
                                    "(%d, %d): weight %g, expected finite > 0", (unsigned)p, i,
                                    j, x[3]);
        }
    return SW_OK;
}

static sw_status copy_patches(tt_ctx *c)
{
    c->patches = sw_arena_alloc(c->arena, sizeof *c->patches * c->patch_count, 8);
    if (!c->patches)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for patches");
    for (uint32_t i = 0; i < c->patch_count; i++) {
        const sw_bezier_patchf *pf = &c->in_patches[i].patch;
        double *ctrl = sw_arena_alloc(c->arena, sizeof(double) *
                                      sw_tt_ctrl_doubles(pf->degree_u, pf->degree_v), 8);
        if (!ctrl)
            return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for patches");
        c->patches[i] = sw_bezier_patch_from_float(pf, ctrl);
        sw_status st = check_control(c, i);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

static void domain_of(const sw_trim_patch *patches, uint32_t count, double dom[4])
{
    dom[0] = dom[2] = INFINITY, dom[1] = dom[3] = -INFINITY;
    for (uint32_t i = 0; i < count; i++) {
        const float *d = patches[i].domain;
        dom[0] = fmin(dom[0], d[0]), dom[1] = fmax(dom[1], d[1]);
        dom[2] = fmin(dom[2], d[2]), dom[3] = fmax(dom[3], d[3]);
    }
}

double sw_tt_shrink_of(const double dom[4])
{
    double big = fmax(fmax(fabs(dom[0]), fabs(dom[1])), fmax(fabs(dom[2]), fabs(dom[3])));
    return fmax(SW_TT_SHRINK_REL * fmax(dom[1] - dom[0], dom[3] - dom[2]),
                1024 * DBL_EPSILON * big);
}

double sw_trim_tess_shrink(const sw_trim_patch *patches, uint32_t patch_count)
{
    double dom[4];
    domain_of(patches, patch_count, dom);
    return patch_count ? sw_tt_shrink_of(dom) : 0;
}

/* ---- output ---------------------------------------------------------------- */

static uint32_t hash_key(double u, double v, uint32_t kind)
{
    uint64_t a, b;
    u = u == 0 ? 0 : u; /* -0 and +0 are one place */
    v = v == 0 ? 0 : v;
    memcpy(&a, &u, sizeof a);
    memcpy(&b, &v, sizeof b);
    uint64_t h = (a * 0x9E3779B97F4A7C15ull) ^ (b * 0xC2B2AE3D27D4EB4Full) ^ kind;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    return (uint32_t)(h ^ (h >> 32));
}

/* The patch whose knot cell holds (u, v): binary search on the knot lines,
 * the nearest patch by a scan where the grid has no patch there. */
uint32_t sw_tt_patch_at(const tt_ctx *c, double u, double v)
{
    const tt_grid *g = &c->grid;
    uint32_t p = SW_TT_NONE;
    if (g->nku >= 2 && g->nkv >= 2) /* else no grid yet: every loop collapsed */
        p = sw_tt_knot_patch(c, sw_tt_interval(g->ku, g->nku, u),
                             sw_tt_interval(g->kv, g->nkv, v));
    if (p != SW_TT_NONE)
        return p;
    uint32_t best = 0;
    double best_d = INFINITY;
    for (uint32_t i = 0; i < c->patch_count; i++) {
        const float *d = c->in_patches[i].domain;
        double du = fmax(fmax(d[0] - u, u - d[1]), 0), dv = fmax(fmax(d[2] - v, v - d[3]), 0);
        if (du + dv < best_d)
            best = i, best_d = du + dv;
    }
    return best;
}

static sw_status new_vertex(tt_ctx *c, uint32_t *index)
{
    if (c->vertex_count >= c->max_vertices)
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: more than %u vertices at error %g:"
                            " coarsen the bound", (unsigned)c->max_vertices, c->error);
    *index = c->vertex_count++;
    return SW_OK;
}

/* Writes vertex i if the caller's buffers hold it. */
static void put_vertex(const tt_ctx *c, uint32_t i, const float p[3], sw_vec3 n, double u,
                       double v, uint32_t id)
{
    const sw_trim_tess_buffers *o = c->out;
    if (!o || i >= o->vertex_capacity)
        return;
    memcpy(o->positions + 3 * (size_t)i, p, 3 * sizeof(float));
    o->normals[3 * (size_t)i] = (float)n.x;
    o->normals[3 * (size_t)i + 1] = (float)n.y;
    o->normals[3 * (size_t)i + 2] = (float)n.z;
    if (o->uvs)
        o->uvs[2 * (size_t)i] = (float)u, o->uvs[2 * (size_t)i + 1] = (float)v;
    if (o->ids)
        o->ids[i] = id;
}

/* A loop point or a crossing: the caller's position, the surface's normal
 * at the loop point's own (u, v). */
static void put_border(tt_ctx *c, uint32_t i, uint32_t src, double u, double v)
{
    const sw_trim_point *tp = &c->in_loops->points[src];
    sw_vec3 *normal = &c->src_normal[src];
    if (!c->src_has_normal[src]) { /* a loop point and its crossings share one */
        sw_vec3 pos;
        sw_tt_eval_at(c, sw_tt_patch_at(c, tp->uv[0], tp->uv[1]), tp->uv[0], tp->uv[1], &pos,
                      normal);
        c->src_has_normal[src] = 1;
    }
    put_vertex(c, i, tp->p, *normal, u, v, tp->id);
}

sw_status sw_tt_new_loop_vertex(tt_ctx *c, uint32_t src, sw_vec3 *normal, uint32_t *out)
{
    sw_status s = new_vertex(c, out);
    if (s != SW_OK)
        return s;
    const sw_trim_point *tp = &c->in_loops->points[src];
    sw_vec3 pos;
    sw_tt_eval_at(c, sw_tt_patch_at(c, tp->uv[0], tp->uv[1]), tp->uv[0], tp->uv[1], &pos, normal);
    put_vertex(c, *out, tp->p, *normal, tp->uv[0], tp->uv[1], tp->id);
    return SW_OK;
}

/* A crossing on its seam segment (crossing_on_segment): the chord point
 * nearest the exact surface point at the crossing's (u, v). Not the point at
 * the crossing's (u, v) fraction of the segment: the border curve's speed in
 * (u, v) is not its speed in space, and that point slides along the chord,
 * away from where the surface puts (u, v) (teaset: 1 px of a 0.5 px bound).
 * Deterministic: the crossing is one vertex of the surface's mesh, evaluated
 * once on the patch patch_at picks for its (u, v). */
static void put_on_segment(tt_ctx *c, uint32_t i, const sw_tt_pv *pv)
{
    const float *a = c->in_loops->points[pv->ref_a].p, *b = c->in_loops->points[pv->ref_b].p;
    sw_surface_point q;
    sw_tt_eval_at(c, sw_tt_patch_at(c, pv->u, pv->v), pv->u, pv->v, &q.p, &q.normal);
    double ab[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
    double aq[3] = {q.p.x - a[0], q.p.y - a[1], q.p.z - a[2]};
    double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    double t = len2 > 0 ? (aq[0] * ab[0] + aq[1] * ab[1] + aq[2] * ab[2]) / len2 : 0.0;
    t = fmin(fmax(t, 0.0), 1.0);
    float p[3];
    for (int k = 0; k < 3; k++)
        p[k] = (float)((double)a[k] + t * ab[k]);
    put_vertex(c, i, p, q.normal, pv->u, pv->v, SW_TRIM_CROSSING);
}

sw_status sw_tt_vertex_for(tt_ctx *c, uint32_t patch, const sw_tt_pv *pv, uint32_t *out)
{
    if (pv->kind == SW_TT_SEAM) {
        uint32_t *slot = &c->seam_out[pv->ref];
        if (*slot == SW_TT_NONE) {
            sw_status s = new_vertex(c, slot);
            if (s != SW_OK)
                return s;
            const sw_trim_point *tp = &c->in_loops->points[c->pts[pv->ref].src];
            put_border(c, *slot, c->pts[pv->ref].src, tp->uv[0], tp->uv[1]);
        }
        *out = *slot;
        return SW_OK;
    }
    if (pv->kind == SW_TT_CROSS) {
        /* A crossing that rounds to an end's own float (u, v) (a grid line a
         * float step from a loop point) is that loop point: both cells at the
         * crossing find the same one, the edge between the two collapses, and
         * no triangle degenerates in the float (u, v) of the output. */
        uint32_t ends[2] = {pv->seg, c->pts[pv->seg].next};
        for (int k = 0; k < 2; k++) {
            const float *uv = c->in_loops->points[c->pts[ends[k]].src].uv;
            if ((float)pv->u == uv[0] && (float)pv->v == uv[1]) {
                sw_tt_pv end = {c->pts[ends[k]].u, c->pts[ends[k]].v, SW_TT_SEAM, ends[k],
                                0, 0, 0, 0};
                return sw_tt_vertex_for(c, patch, &end, out);
            }
        }
    }
    if (c->hashed_count >= c->hash_mask / 2)
        return sw_error_set(c->err, SW_ERR_RANGE, "trim tess: more than %u crossings and part "
                            "corners", (unsigned)c->hash_mask / 2);
    uint32_t h = hash_key(pv->u, pv->v, pv->kind) & c->hash_mask;
    for (; c->hash[h] != SW_TT_NONE; h = (h + 1) & c->hash_mask) {
        uint32_t i = c->hash[h];
        if (c->key_uv[2 * i] == pv->u && c->key_uv[2 * i + 1] == pv->v && c->key_kind[i] == pv->kind) {
            *out = i;
            return SW_OK;
        }
    }
    sw_status s = new_vertex(c, out);
    if (s != SW_OK)
        return s;
    c->hash[h] = *out;
    c->hashed_count++;
    c->key_uv[2 * *out] = pv->u, c->key_uv[2 * *out + 1] = pv->v, c->key_kind[*out] = (uint8_t)pv->kind;
    if (pv->kind == SW_TT_CROSS && c->crossing_on_segment) {
        put_on_segment(c, *out, pv);
    } else if (pv->kind == SW_TT_CROSS) {
        put_border(c, *out, pv->ref, pv->u, pv->v);
    } else {
        sw_vec3 pos, normal;
        sw_tt_eval_at(c, patch, pv->u, pv->v, &pos, &normal);
        float p[3] = {(float)pos.x, (float)pos.y, (float)pos.z};
        put_vertex(c, *out, p, normal, pv->u, pv->v, SW_TRIM_INTERIOR);
    }
    return SW_OK;
}

sw_status sw_tt_new_grid_vertex(tt_ctx *c, uint32_t patch, uint32_t col, uint32_t line,
                                uint32_t *out)
{
    uint32_t *slot = &c->line_ids[line & 1][col];
    sw_status s = new_vertex(c, slot);
    if (s != SW_OK)
        return s;
    sw_vec3 pos, normal;
    sw_tt_eval_grid(c, patch, col, line, &pos, &normal);
    float p[3] = {(float)pos.x, (float)pos.y, (float)pos.z};
    put_vertex(c, *slot, p, normal, c->grid.gu[col], c->grid.gv[line], SW_TRIM_INTERIOR);
    *out = *slot;
    return SW_OK;
}


sw_status sw_tt_init_vertices(tt_ctx *c, uint32_t hashed)
{
    uint32_t hs = hash_size(hashed < c->max_vertices ? hashed : c->max_vertices);
    uint32_t in = c->in_loops->loop_first[c->in_loops->loop_count];
    c->hash_mask = hs - 1;
    c->hash = sw_arena_alloc(c->arena, sizeof(uint32_t) * hs, 4);
    c->key_uv = sw_arena_alloc(c->arena, sizeof(double) * 2 * c->max_vertices, 8);
    c->key_kind = sw_arena_alloc(c->arena, c->max_vertices, 1);
    c->src_normal = sw_arena_alloc(c->arena, sizeof(sw_vec3) * in, 8);
    c->src_has_normal = sw_arena_alloc(c->arena, in, 1);
    if (!c->hash || !c->key_uv || !c->key_kind || !c->src_normal || !c->src_has_normal)
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: arena too small for the "
                            "vertex table (see sw_trim_tess_scratch_bytes)");
    memset(c->hash, 0xFF, sizeof(uint32_t) * hs);
    memset(c->src_has_normal, 0, in);
    return SW_OK;
}

/* ---- entry points ------------------------------------------------------------ */

static sw_status check_call(const sw_trim_patch *patches, uint32_t patch_count,
                            const sw_trim_loops *loops, double error_world, sw_arena *scratch,
                            const sw_trim_tess_buffers *out, sw_error *err)
{
    if (!patches || patch_count == 0 || !loops || !scratch)
        return sw_error_set(err, SW_ERR_ARG, "trim tess: no patches, loops or scratch arena");
    if (!(error_world > 0) || !isfinite(error_world))
        return sw_error_set(err, SW_ERR_ARG, "trim tess: error %g, expected finite > 0",
                            error_world);
    if (out && ((out->vertex_capacity && (!out->positions || !out->normals)) ||
                (out->index_capacity && !out->indices)))
        return sw_error_set(err, SW_ERR_ARG, "trim tess: buffer capacity without a buffer");
    if (out && out->base_vertex >= 65536u)
        return sw_error_set(err, SW_ERR_ARG, "trim tess: base_vertex %u, expected < 65536",
                            (unsigned)out->base_vertex);
    return SW_OK;
}

static sw_status run(tt_ctx *c)
{
    sw_status s = check_patches(c);
    if (s == SW_OK)
        s = copy_patches(c);
    if (s != SW_OK)
        return s;
    double dom[4];
    domain_of(c->in_patches, c->patch_count, dom);
    if ((s = sw_tt_prepare_loops(c, dom)) != SW_OK)
        return s;
    if (c->trims.loop_count > 0 &&
        ((s = sw_tt_build_grid(c)) != SW_OK || (s = sw_tt_bucket(c)) != SW_OK ||
         (s = sw_tt_sweep(c)) != SW_OK))
        return s;
    if ((s = sw_tt_fan_collapsed(c)) != SW_OK)
        return s;
    c->res->vertex_count = c->vertex_count;
    c->res->index_count = c->index_count;
    const sw_trim_tess_buffers *o = c->out;
    if (o && (c->vertex_count > o->vertex_capacity || c->index_count > o->index_capacity))
        return sw_error_set(c->err, SW_ERR_NO_MEMORY, "trim tess: needs %u vertices and %u "
                            "indices, buffers hold %u and %u", (unsigned)c->vertex_count,
                            (unsigned)c->index_count, (unsigned)o->vertex_capacity,
                            (unsigned)o->index_capacity);
    return SW_OK;
}

static sw_status tessellate(const sw_trim_patch *patches, uint32_t patch_count,
                            const sw_trim_loops *loops, double error_world,
                            const sw_trim_tess_options *opt, sw_arena *scratch,
                            const sw_trim_tess_buffers *out, sw_trim_tess_result *result,
                            sw_error *err)
{
    sw_trim_tess_result local;
    sw_trim_tess_result *res = result ? result : &local;
    memset(res, 0, sizeof *res);
    sw_status s = check_call(patches, patch_count, loops, error_world, scratch, out, err);
    if (s != SW_OK)
        return s;
    tt_ctx c;
    memset(&c, 0, sizeof c);
    c.in_patches = patches, c.patch_count = patch_count, c.in_loops = loops;
    c.error = error_world, c.arena = scratch, c.err = err, c.out = out, c.res = res;
    c.max_vertices = max_vertices_of(opt, out ? out->base_vertex : 0);
    c.max_depth = max_depth_of(opt);
    c.crossing_on_segment = opt && opt->crossing_on_segment;
    c.border_error = opt && opt->border_fraction > 0 && opt->border_fraction < 1
                         ? error_world * opt->border_fraction : error_world;
    size_t mark = sw_arena_mark(scratch);
    s = run(&c);
    sw_arena_reset_to(scratch, mark);
    return s;
}

sw_status sw_trim_tess(const sw_trim_patch *patches, uint32_t patch_count,
                       const sw_trim_loops *loops, double error_world,
                       const sw_trim_tess_options *opt, sw_arena *scratch,
                       const sw_trim_tess_buffers *out, sw_trim_tess_result *result,
                       sw_error *err)
{
    if (!out)
        return sw_error_set(err, SW_ERR_ARG, "trim tess: no buffers (sw_trim_tess_sizes "
                            "counts without them)");
    return tessellate(patches, patch_count, loops, error_world, opt, scratch, out, result, err);
}

sw_status sw_trim_tess_sizes(const sw_trim_patch *patches, uint32_t patch_count,
                             const sw_trim_loops *loops, double error_world,
                             const sw_trim_tess_options *opt, sw_arena *scratch,
                             sw_trim_tess_result *result, sw_error *err)
{
    return tessellate(patches, patch_count, loops, error_world, opt, scratch, NULL, result, err);
}

sw_status sw_trim_patches_from_pack(const sw_pack *pack, uint32_t surface, sw_trim_patch *out,
                                    uint32_t capacity, uint32_t *count, sw_error *err)
{
    const sw_trim_patch_room room = { out, capacity, NULL, 0 };
    return sw_trim_patches_placed(pack, surface, &room, count, err);
}

sw_status sw_trim_patches_placed(const sw_pack *pack, uint32_t surface,
                                 const sw_trim_patch_room *room, uint32_t *count, sw_error *err)
{
    sw_trim_patch *out = room->patches;
    float *control = room->control;
    uint32_t capacity = room->capacity, control_capacity = room->control_capacity;
    *count = 0;
    int domains = pack && (pack->patch_domains || pack->stored_domains);
    if (!pack || !pack->surfaces || !domains || surface >= pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "trim tess: surface %u: the pack has %u surfaces"
                            "%s", (unsigned)surface, pack ? (unsigned)pack->surface_count : 0u,
                            pack && pack->surfaces && !domains ? " and no PATCH_DOMAINS" : "");
    const sw_pack_surface *s = &pack->surfaces[surface];
    *count = s->patch_count;
    if (s->patch_count > capacity)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "trim tess: surface %u has %u patches, room "
                            "for %u", (unsigned)surface, (unsigned)s->patch_count,
                            (unsigned)capacity);
    uint32_t used = 0;   /* points of control placed so far */
    for (uint32_t i = 0; i < s->patch_count; i++) {
        uint32_t p = s->first_patch + i;
        const sw_pack_patch *pp = &pack->patches[p];
        uint32_t points = (uint32_t)(pp->degree_u + 1) * (pp->degree_v + 1);
        if (pack->control_local && (!control || points > control_capacity - used))
            return sw_error_set(err, SW_ERR_NO_MEMORY, "trim tess: surface %u: its patches' "
                                "control points are placed as they are read, room for %u "
                                "of them", (unsigned)surface, (unsigned)control_capacity);
        out[i].patch.degree_u = pp->degree_u;
        out[i].patch.degree_v = pp->degree_v;
        out[i].patch.rational = (pp->flags & SW_PATCH_RATIONAL) != 0;
        out[i].patch.ctrl = sw_pack_patch_control(pack, p, control ? control + 4 * (size_t)used
                                                                    : NULL);
        used += pack->control_local ? points : 0;
        memcpy(out[i].domain, sw_pack_domain_of(pack, surface, i)->domain,
               sizeof out[i].domain);
    }
    return SW_OK;
}
