/* SPDX-License-Identifier: MIT */
/* Collapsed loops: a loop whose points lie on one line in (u, v) bounds no
 * region there, yet its points (the Seam Graph's vertices) may span a
 * triangle in space. That happens at coarse seam states, where a face
 * smaller than the bound keeps three corners whose (u, v) came to lie on a
 * line. The neighbours across its seams still draw their borders through
 * those points, so leaving the loop out opens a hole of its size; the paper
 * (Guthe et al. 2002) lets a surface vanish only when its seams collapse.
 * Here such a loop is drawn as a fan over its points' positions, every
 * border edge matching the neighbours' edge for edge, turned so its normal
 * agrees with the surface's at those points. Its error is the face's own
 * size, within the bound that chose this seam state. */
#include <float.h>
#include <math.h>

#include "sw_trim_tess_internal.h"

static double dist2(const float *a, const float *b)
{
    double d = 0;
    for (int k = 0; k < 3; k++)
        d += ((double)a[k] - b[k]) * ((double)a[k] - b[k]);
    return d;
}

/* The index in [first, end) of the point farthest from p. */
static uint32_t farthest(const sw_trim_point *pts, uint32_t first, uint32_t end, const float *p)
{
    uint32_t best = first;
    double best_d = -1;
    for (uint32_t i = first; i < end; i++) {
        double d = dist2(pts[i].p, p);
        if (d > best_d)
            best = i, best_d = d;
    }
    return best;
}

int sw_tt_loop_spans_space(const sw_trim_loops *l, uint32_t k)
{
    uint32_t first = l->loop_first[k], end = l->loop_first[k + 1];
    if (end - first < 3)
        return 0;
    /* The line through two far-apart points (the farthest from the first,
     * then the farthest from that), and every point's distance from it. */
    uint32_t a = farthest(l->points, first, end, l->points[first].p);
    uint32_t b = farthest(l->points, first, end, l->points[a].p);
    const float *pa = l->points[a].p, *pb = l->points[b].p;
    double big = 0;
    for (uint32_t i = first; i < end; i++)
        for (int j = 0; j < 3; j++)
            big = fmax(big, fabs((double)l->points[i].p[j]));
    double tol = 8.0 * FLT_EPSILON * big; /* float rounding, as the drawn-seam check's */
    double ab[3] = {(double)pb[0] - pa[0], (double)pb[1] - pa[1], (double)pb[2] - pa[2]};
    double len = sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
    if (len <= tol)
        return 0; /* all on one point */
    for (uint32_t i = first; i < end; i++) {
        const float *q = l->points[i].p;
        double aq[3] = {(double)q[0] - pa[0], (double)q[1] - pa[1], (double)q[2] - pa[2]};
        double x = ab[1] * aq[2] - ab[2] * aq[1], y = ab[2] * aq[0] - ab[0] * aq[2];
        double z = ab[0] * aq[1] - ab[1] * aq[0];
        if (sqrt(x * x + y * y + z * z) / len > tol)
            return 1;
    }
    return 0;
}

/* Loop k's points, a repeat of the same vertex (id) counted once, the
 * closing repeat of the first left out: into c's output, *count of them
 * from *first_vertex on; *turn gets the sum of the surface's normals. */
static sw_status fan_vertices(tt_ctx *c, uint32_t k, uint32_t *first_vertex, uint32_t *count,
                              sw_vec3 *turn)
{
    const sw_trim_loops *l = c->in_loops;
    uint32_t first = l->loop_first[k], end = l->loop_first[k + 1];
    while (end > first + 1 && l->points[end - 1].id == l->points[first].id)
        end--;
    *first_vertex = c->vertex_count;
    *count = 0;
    *turn = sw_v3(0, 0, 0);
    for (uint32_t i = first; i < end; i++) {
        if (i > first && l->points[i].id == l->points[i - 1].id)
            continue;
        sw_vec3 n;
        uint32_t v;
        sw_status s = sw_tt_new_loop_vertex(c, i, &n, &v);
        if (s != SW_OK)
            return s;
        *turn = sw_v3_add(*turn, n);
        (*count)++;
    }
    return SW_OK;
}

/* The polygon's normal (Newell's sum) over the output positions of loop
 * k's points; from the caller's points, so also without buffers. */
static sw_vec3 polygon_normal(const tt_ctx *c, uint32_t k)
{
    const sw_trim_loops *l = c->in_loops;
    uint32_t first = l->loop_first[k], n = l->loop_first[k + 1] - first;
    double s[3] = {0, 0, 0};
    for (uint32_t i = 0; i < n; i++) {
        const float *a = l->points[first + i].p, *b = l->points[first + (i + 1) % n].p;
        for (int j = 0; j < 3; j++) {
            int y = (j + 1) % 3, z = (j + 2) % 3;
            s[j] += ((double)a[y] - b[y]) * ((double)a[z] + b[z]);
        }
    }
    return sw_v3(s[0], s[1], s[2]);
}

sw_status sw_tt_fan_collapsed(tt_ctx *c)
{
    for (uint32_t i = 0; i < c->collapsed_count; i++) {
        uint32_t k = c->collapsed[i], v0 = 0, count = 0;
        sw_vec3 turn;
        sw_status s = fan_vertices(c, k, &v0, &count, &turn);
        if (s != SW_OK)
            return s;
        /* CCW about the surface's normal, as the sweep's triangles are. */
        int flip = sw_v3_dot(polygon_normal(c, k), turn) < 0;
        for (uint32_t j = 1; j + 1 < count; j++) {
            if (flip)
                sw_tt_put_triangle(c, v0, v0 + j + 1, v0 + j);
            else
                sw_tt_put_triangle(c, v0, v0 + j, v0 + j + 1);
        }
        c->res->fanned_loops++;
    }
    return SW_OK;
}
