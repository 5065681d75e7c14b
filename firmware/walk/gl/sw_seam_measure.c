/* SPDX-License-Identifier: MIT */
#include "sw_seam_measure.h"

#include <math.h>

#include "sw_surface_at.h"
#include "sw_view.h"

/* The point p on screen, in pixels from the viewport's corner; 0 when it is
 * behind the near plane, beyond the far one or outside the viewport (not
 * on screen: no pixel shows it). */
static int on_screen(const sw_view *view, sw_vec3 p, double xy[2])
{
    sw_vec4 c = sw_mat4_mul_v4(&view->view_proj, (sw_vec4){ p.x, p.y, p.z, 1.0 });
    if (!(c.w >= view->near_z) || fabs(c.x) > c.w || fabs(c.y) > c.w || fabs(c.z) > c.w)
        return 0;
    xy[0] = (c.x / c.w + 1.0) * 0.5 * view->width;
    xy[1] = (c.y / c.w + 1.0) * 0.5 * view->height;
    return 1;
}

/* One sample: the flat triangle's point at barycentric weights b and the
 * exact surface at the same interpolated (u, v), both projected to the
 * screen; their distance in pixels, counted only when both are on screen.
 * Also what it exceeds the surface's sewing offset by, against the bound.
 * Samples of a zero-area triangle (chord) go to acc->chord_px alone. */
static void sample(const sw_seam_mesh *m, const sw_seam_exact *e, const uint16_t idx[3],
                   const double b[3], int chord, const sw_view *view, sw_stats *stats,
                   sw_seam_error *acc)
{
    double flat[3] = { 0, 0, 0 }, uv[2] = { 0, 0 };
    for (int k = 0; k < 3; k++) {
        for (int c = 0; c < 3; c++)
            flat[c] += b[k] * m->verts[idx[k]].pos[c];
        for (int c = 0; c < 2; c++)
            uv[c] += b[k] * m->uvs[2 * idx[k] + c];
    }
    sw_vec3 q = sw_surface_at(e->patches, e->patch_count, uv[0], uv[1]);
    sw_vec3 p = sw_v3(flat[0], flat[1], flat[2]);
    double sq[2], sp[2];
    if (!on_screen(view, q, sq) || !on_screen(view, p, sp))
        return;
    double error_px = hypot(sq[0] - sp[0], sq[1] - sp[1]);
    if (chord) {
        acc->chord_px = fmax(acc->chord_px, error_px);
        return;
    }
    sw_stats_add_error_px(stats, error_px);
    double d = sw_v3_length(sw_v3_sub(q, p));
    if (d <= e->sew_offset || error_px == 0)
        return;
    /* px: this displacement's pixels per model unit, as projected. The
     * walk's bound is half a pixel at the surface's depth; where its floor
     * (a tenth of the sewing tolerance) is coarser, the excess is scaled by
     * half a pixel over the floor, so <= error_px still states the bound. */
    double px = error_px / d;
    double allowed = fmax(e->error_px / px, e->bound_floor);
    acc->beyond_sewing_px = fmax(acc->beyond_sewing_px, (d - e->sew_offset) / allowed * e->error_px);
}

/* A triangle whose corners lie on one line (to 1e-5 of its edges): the
 * fill fans over seam crossings (sw_seam_fill.h), which cover no area and
 * lie on a seam's chord. */
static int collinear(const sw_seam_mesh *m, const uint16_t idx[3])
{
    const float *a = m->verts[idx[0]].pos, *b = m->verts[idx[1]].pos, *c = m->verts[idx[2]].pos;
    sw_vec3 ab = sw_v3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    sw_vec3 ac = sw_v3(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    sw_vec3 n = sw_v3(ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z,
                      ab.x * ac.y - ab.y * ac.x);
    return sw_v3_length(n) <= 1e-5 * sw_v3_length(ab) * sw_v3_length(ac);
}

void sw_seam_measure_mesh(const sw_seam_mesh *mesh, const sw_seam_exact *exact,
                          const sw_view *view, sw_stats *stats, sw_seam_error *acc)
{
    /* the vertices (where the flat and exact surfaces should meet, and
     * where a wrong (u, v) shows first), the centroid and the edge midpoints */
    static const double weights[7][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
                                          { 1 / 3.0, 1 / 3.0, 1 / 3.0 }, { 0.5, 0.5, 0 },
                                          { 0, 0.5, 0.5 }, { 0.5, 0, 0.5 } };
    for (uint32_t i = 0; i + 2 < mesh->index_count; i += 3) {
        int chord = collinear(mesh, mesh->indices + i);
        for (int k = 0; k < 7; k++)
            sample(mesh, exact, mesh->indices + i, weights[k], chord, view, stats, acc);
    }
    double depth = fmax(exact->depth, view->near_z);
    acc->sewing_offset_px = fmax(acc->sewing_offset_px,
                                 exact->sew_offset * view->px_per_unit / depth);
}
