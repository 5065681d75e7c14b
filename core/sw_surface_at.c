/* SPDX-License-Identifier: MIT */
/* The exact surface and the sewing offset (sw_surface_at.h). */
#include "sw_surface_at.h"

#include <math.h>
#include <string.h>

#include "sw_bezier.h"

/* The patch whose domain holds (u, v) (the nearest one for points an ulp
 * outside), and the point's local parameters in it. */
static const sw_trim_patch *patch_at(const sw_trim_patch *patches, uint32_t n, double u,
                                     double v, double *s, double *t)
{
    const sw_trim_patch *best = &patches[0];
    double best_out = INFINITY;
    for (uint32_t i = 0; i < n; i++) {
        const float *d = patches[i].domain;
        double out = sw_max(sw_max(d[0] - u, u - d[1]), sw_max(d[2] - v, v - d[3]));
        if (out < best_out)
            best_out = out, best = &patches[i];
    }
    const float *d = best->domain;
    *s = sw_min(sw_max((u - d[0]) / (d[1] - d[0]), 0.0), 1.0);
    *t = sw_min(sw_max((v - d[2]) / (d[3] - d[2]), 0.0), 1.0);
    return best;
}

/* The exact surface at (u, v). */
sw_vec3 sw_surface_at(const sw_trim_patch *patches, uint32_t n, double u, double v)
{
    double s, t, ctrl[4 * SW_BEZIER_MAX_ORDER * SW_BEZIER_MAX_ORDER];
    const sw_trim_patch *tp = patch_at(patches, n, u, v, &s, &t);
    sw_bezier_patch exact = sw_bezier_patch_from_float(&tp->patch, ctrl);
    sw_surface_point sp;
    sw_bezier_eval(&exact, s, t, SW_EVAL_POINT, &sp);
    return sp.p;
}

/* Does (u, v) lie strictly inside d's domain (no other patch's then, where
 * the domains do not overlap)? */
static int strictly_inside(const float d[4], double u, double v)
{
    return d[0] < u && u < d[1] && d[2] < v && v < d[3];
}

void sw_surface_sampler_init(sw_surface_sampler *s, const sw_trim_patch *patches,
                             uint32_t patch_count)
{
    s->patches = patches, s->patch_count = patch_count, s->last = NULL;
    s->disjoint = patch_count <= SW_SURFACE_SAMPLER_PAIRS;
    for (uint32_t i = 0; s->disjoint && i < patch_count; i++)
        for (uint32_t j = i + 1; j < patch_count; j++) {
            const float *a = patches[i].domain, *b = patches[j].domain;
            if (a[0] < b[1] && b[0] < a[1] && a[2] < b[3] && b[2] < a[3]) {
                s->disjoint = 0;
                break;
            }
        }
}

sw_vec3 sw_surface_sampler_at(sw_surface_sampler *s, double u, double v)
{
    if (!s->disjoint)
        return sw_surface_at(s->patches, s->patch_count, u, v);
    if (!s->last || !strictly_inside(s->last->domain, u, v)) {
        double st[2];
        s->last = patch_at(s->patches, s->patch_count, u, v, &st[0], &st[1]);
        s->exact = sw_bezier_patch_from_float(&s->last->patch, s->ctrl);
    }
    const float *d = s->last->domain;
    double ps = sw_min(sw_max((u - d[0]) / (d[1] - d[0]), 0.0), 1.0);
    double pt = sw_min(sw_max((v - d[2]) / (d[3] - d[2]), 0.0), 1.0);
    sw_surface_point sp;
    sw_bezier_eval(&s->exact, ps, pt, SW_EVAL_POINT, &sp);
    return sp.p;
}

double sw_seam_sewing_offset_of(uint32_t slot_count, sw_sewn_point_fn at, const void *ctx,
                                const sw_trim_patch *patches, uint32_t patch_count)
{
    double worst = 0;
    sw_sewn_point a, b;
    for (uint32_t k = 0; k < slot_count; k++) {
        at(ctx, k, &a);
        if (a.error > 0)
            continue;
        at(ctx, (k + 1) % slot_count, &b);
        const float *p = a.p, *q = b.p;
        sw_vec3 on = sw_surface_at(patches, patch_count, a.uv[0], a.uv[1]);
        worst = fmax(worst, sw_v3_length(sw_v3_sub(on, sw_v3(p[0], p[1], p[2]))));
        if (b.error > 0)
            continue;
        sw_vec3 mid = sw_surface_at(patches, patch_count, 0.5 * ((double)a.uv[0] + b.uv[0]),
                                    0.5 * ((double)a.uv[1] + b.uv[1]));
        sw_vec3 chord = sw_v3(0.5 * ((double)p[0] + q[0]), 0.5 * ((double)p[1] + q[1]),
                              0.5 * ((double)p[2] + q[2]));
        worst = fmax(worst, sw_v3_length(sw_v3_sub(mid, chord)));
    }
    return worst;
}

typedef struct graph_loop {
    const sw_seam_graph *g;
    const sw_seam_loop *loop;
} graph_loop;

static void graph_point(const void *ctx, uint32_t k, sw_sewn_point *out)
{
    const graph_loop *gl = ctx;
    const sw_seam_slot *slot = &gl->g->slots[gl->loop->first_slot + k];
    const sw_seam_vertex *v = &gl->g->vertices[slot->vertex];
    memcpy(out->p, v->p, sizeof out->p);
    memcpy(out->uv, slot->uv, sizeof out->uv);
    out->error = v->error;
}

double sw_seam_sewing_offset(const sw_seam_graph *g, const sw_seam_loop *loop,
                             const sw_trim_patch *patches, uint32_t patch_count)
{
    const graph_loop gl = { g, loop };
    return sw_seam_sewing_offset_of(loop->slot_count, graph_point, &gl, patches, patch_count);
}
