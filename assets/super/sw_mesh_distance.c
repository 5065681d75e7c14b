/* SPDX-License-Identifier: MIT */
/* Sampled one-sided distance between two meshes (sw_mesh_distance.h). */
#include "sw_mesh_distance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_math.h"

struct sw_mesh_grid {
    const sw_mesh_view *mesh;
    double lo[3], cell;
    int dim[3];
    uint32_t *first;    /* cells + 1: cell c's triangles are tri[first[c] .. first[c + 1]) */
    uint32_t *tri;      /* triangle numbers */
    float *box;         /* per triangle: its box's low corner, then its high one */
    double *corners;    /* per triangle: its three corners, as doubles (9 a triangle: the
                           distance reads them for every point, gathered once) */
};

static void triangle_box(const sw_mesh_view *m, uint32_t t, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (int c = 0; c < 3; c++) {
        const float *p = m->positions + 3 * (size_t)m->indices[3 * (size_t)t + c];
        for (int k = 0; k < 3; k++)
            lo[k] = sw_min(lo[k], p[k]), hi[k] = sw_max(hi[k], p[k]);
    }
}

static int cell_of(const sw_mesh_grid *g, double x, int k)
{
    int c = (int)floor((x - g->lo[k]) / g->cell);
    return c < 0 ? 0 : c >= g->dim[k] ? g->dim[k] - 1 : c;
}

static size_t cell_index(const sw_mesh_grid *g, int x, int y, int z)
{
    return ((size_t)z * (size_t)g->dim[1] + (size_t)y) * (size_t)g->dim[0] + (size_t)x;
}

/* Calls back for every cell triangle t's box covers: counting (pass 0) or
 * filling (pass 1). */
static void bin(sw_mesh_grid *g, uint32_t t, int pass, uint32_t *fill)
{
    double lo[3], hi[3];
    triangle_box(g->mesh, t, lo, hi);
    int a[3], b[3];
    for (int k = 0; k < 3; k++)
        a[k] = cell_of(g, lo[k], k), b[k] = cell_of(g, hi[k], k);
    for (int z = a[2]; z <= b[2]; z++)
        for (int y = a[1]; y <= b[1]; y++)
            for (int x = a[0]; x <= b[0]; x++) {
                size_t c = cell_index(g, x, y, z);
                if (pass == 0)
                    g->first[c + 1]++;
                else
                    g->tri[fill[c]++] = t;
            }
}

static double mesh_area(const sw_mesh_view *m)
{
    double area = 0;
    for (uint32_t t = 0; t + 2 < m->index_count; t += 3) {
        double e[2][3];
        const float *a = m->positions + 3 * (size_t)m->indices[t];
        for (int j = 0; j < 2; j++)
            for (int k = 0; k < 3; k++)
                e[j][k] = (double)m->positions[3 * (size_t)m->indices[t + 1 + j] + k] - a[k];
        double c[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1],
                        e[0][2] * e[1][0] - e[0][0] * e[1][2],
                        e[0][0] * e[1][1] - e[0][1] * e[1][0] };
        area += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    return area;
}

sw_mesh_grid *sw_mesh_grid_make(const sw_mesh_view *b)
{
    uint32_t n = b->index_count / 3;
    if (n == 0)
        return NULL;
    sw_mesh_grid *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    g->mesh = b;
    double hi[3] = { -INFINITY, -INFINITY, -INFINITY }, extent = 0;
    for (int k = 0; k < 3; k++)
        g->lo[k] = INFINITY;
    g->box = malloc(6 * (size_t)n * sizeof *g->box);
    g->corners = malloc(9 * (size_t)n * sizeof *g->corners);
    if (!g->box || !g->corners) {
        sw_mesh_grid_free(g);
        return NULL;
    }
    for (uint32_t t = 0; t < n; t++) {
        double tl[3], th[3];
        triangle_box(b, t, tl, th);
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                g->corners[9 * (size_t)t + 3 * c + k] =
                    b->positions[3 * (size_t)b->indices[3 * (size_t)t + c] + k];
        for (int k = 0; k < 3; k++) {
            g->lo[k] = fmin(g->lo[k], tl[k]), hi[k] = fmax(hi[k], th[k]);
            g->box[6 * (size_t)t + k] = (float)tl[k], g->box[6 * (size_t)t + 3 + k] = (float)th[k];
        }
    }
    for (int k = 0; k < 3; k++)
        extent = fmax(extent, hi[k] - g->lo[k]);
    /* Cells about as wide as a triangle (a mesh is a surface: cells sized
     * by the box's volume over the triangles held tens of them each, most
     * of the time spent measuring), at most 96 a side. */
    g->cell = fmax(sqrt(2.0 * mesh_area(b) / n), extent / 96.0) + 1e-30;
    size_t cells = 1;
    for (int k = 0; k < 3; k++) {
        g->dim[k] = (int)fmin(96, floor((hi[k] - g->lo[k]) / g->cell) + 1);
        cells *= (size_t)g->dim[k];
    }
    g->first = calloc(cells + 1, sizeof *g->first);
    uint32_t *fill = malloc((cells + 1) * sizeof *fill);
    if (!g->first || !fill) {
        free(fill);
        sw_mesh_grid_free(g);
        return NULL;
    }
    for (uint32_t t = 0; t < n; t++)
        bin(g, t, 0, NULL);
    for (size_t c = 0; c < cells; c++)
        g->first[c + 1] += g->first[c];
    g->tri = malloc(((size_t)g->first[cells] + 1) * sizeof *g->tri);
    if (!g->tri) {
        free(fill);
        sw_mesh_grid_free(g);
        return NULL;
    }
    memcpy(fill, g->first, cells * sizeof *fill);
    for (uint32_t t = 0; t < n; t++)
        bin(g, t, 1, fill);
    free(fill);
    return g;
}

void sw_mesh_grid_free(sw_mesh_grid *g)
{
    if (!g)
        return;
    free(g->first);
    free(g->tri);
    free(g->box);
    free(g->corners);
    free(g);
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Squared distance from p to triangle abc (the closest point by regions,
 * as in Ericson, Real-Time Collision Detection, 5.1.5); w gets the closest
 * point's barycentric weights of a, b and c. */
static double triangle_distance2(const double p[3], const double a[3], const double b[3],
                                 const double c[3], double w3[3])
{
    double ab[3], ac[3], ap[3], q[3];
    for (int k = 0; k < 3; k++)
        ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = p[k] - a[k];
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    double bp[3], cp[3];
    for (int k = 0; k < 3; k++)
        bp[k] = p[k] - b[k], cp[k] = p[k] - c[k];
    double d3 = dot3(ab, bp), d4 = dot3(ac, bp), d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    double v = 0, w = 0;   /* q = a + v ab + w ac */
    if (d1 <= 0 && d2 <= 0)
        v = 0, w = 0;
    else if (d3 >= 0 && d4 <= d3)
        v = 1, w = 0;
    else if (d6 >= 0 && d5 <= d6)
        v = 0, w = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
        v = d1 / (d1 - d3), w = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
        v = 0, w = d2 / (d2 - d6);
    else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6)), v = 1 - w;
    else {
        double den = va + vb + vc;
        v = den != 0 ? vb / den : 0, w = den != 0 ? vc / den : 0;
    }
    for (int k = 0; k < 3; k++)
        q[k] = a[k] + ab[k] * v + ac[k] * w;
    w3[0] = 1 - v - w, w3[1] = v, w3[2] = w;
    double d[3] = { p[0] - q[0], p[1] - q[1], p[2] - q[2] };
    return dot3(d, d);
}

/* The squared distance from p to the box lo .. hi. */
static double box_distance2(const double p[3], const float lo[3], const float hi[3])
{
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double d = p[k] < lo[k] ? lo[k] - p[k] : p[k] > hi[k] ? p[k] - hi[k] : 0;
        d2 += d * d;
    }
    return d2;
}

/* The squared distance from p to cell (x, y, z) of the grid. */
static double cell_distance2(const sw_mesh_grid *g, const double p[3], const int c[3])
{
    float lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        /* a box a little larger than the cell: triangles' boxes are
         * rounded to float, and cell_of clamps what lies outside */
        double a = g->lo[k] + c[k] * g->cell, b = a + g->cell;
        lo[k] = c[k] == 0 ? -INFINITY : (float)(a - 1e-6 * g->cell);
        hi[k] = c[k] == g->dim[k] - 1 ? INFINITY : (float)(b + 1e-6 * g->cell);
    }
    return box_distance2(p, lo, hi);
}

/* each(ctx, at, squared distance) for p's nearest point on every triangle
 * binned in cell c whose box lies within sqrt(*reach2) of p, until it
 * returns nonzero; returns whether it did. *reach2 is read again after
 * each call: the nearest search narrows it. */
static int cell_visit(const sw_mesh_grid *g, const double p[3], const int c[3],
                      const double *reach2,
                      int (*each)(void *ctx, const sw_mesh_point *at, double d2), void *ctx)
{
    size_t cell = cell_index(g, c[0], c[1], c[2]);
    for (uint32_t i = g->first[cell]; i < g->first[cell + 1]; i++) {
        uint32_t tri = g->tri[i];
        const float *box = g->box + 6 * (size_t)tri;
        if (box_distance2(p, box, box + 3) > *reach2)
            continue;
        const double *v = g->corners + 9 * (size_t)tri;
        sw_mesh_point at = { tri, { 0, 0, 0 } };
        double d2 = triangle_distance2(p, v, v + 3, v + 6, at.weights);
        if (each(ctx, &at, d2))
            return 1;
    }
    return 0;
}

typedef struct nearest {
    double d2;
    sw_mesh_point at;
    double enough2;   /* a triangle this close ends the search */
} nearest;

/* Keeps the nearest, the lowest-numbered of equals: the answer does not
 * depend on the order cells are visited in. */
static int keep_nearest(void *ctx, const sw_mesh_point *at, double d2)
{
    nearest *n = ctx;
    if (d2 < n->d2 || (d2 == n->d2 && at->triangle < n->at.triangle))
        n->d2 = d2, n->at = *at;
    return n->d2 <= n->enough2;
}

/* A lower bound on the distance from p to any cell k or more cells from
 * its own cell c (in the largest of the three index differences); INFINITY
 * when there is no such cell. */
static double ring_distance(const sw_mesh_grid *g, const double p[3], const int c[3], int k)
{
    double d = INFINITY;
    for (int a = 0; a < 3; a++) {
        if (c[a] - k >= 0)   /* the far side of cell c - k + 1 */
            d = sw_min(d, sw_max(0, p[a] - (g->lo[a] + (c[a] - k + 1) * g->cell)));
        if (c[a] + k < g->dim[a])
            d = sw_min(d, sw_max(0, g->lo[a] + (c[a] + k) * g->cell - p[a]));
    }
    return d;
}

/* Visits ring k of cells around c (those whose largest index difference
 * from c is k) that lie within the nearest found, as cell_visit; returns
 * whether a visit ended the search. */
static int ring_visit(const sw_mesh_grid *g, const double p[3], const int c[3], int k, nearest *n)
{
    int lo[3], hi[3], q[3];
    for (int a = 0; a < 3; a++)
        lo[a] = c[a] - k < 0 ? 0 : c[a] - k, hi[a] = c[a] + k >= g->dim[a] ? g->dim[a] - 1 : c[a] + k;
    for (q[2] = lo[2]; q[2] <= hi[2]; q[2]++)
        for (q[1] = lo[1]; q[1] <= hi[1]; q[1]++) {
            int edge = abs(q[2] - c[2]) == k || abs(q[1] - c[1]) == k;
            /* inside the ring's faces in y and z, only its two x sides */
            int step = edge || k == 0 ? 1 : 2 * k;
            for (q[0] = edge || k == 0 ? lo[0] : c[0] - k; q[0] <= hi[0]; q[0] += step) {
                if (q[0] < 0 || cell_distance2(g, p, q) > n->d2)
                    continue;
                if (cell_visit(g, p, q, &n->d2, keep_nearest, n))
                    return 1;
            }
        }
    return 0;
}

/* The distance from p to the grid's mesh and where, or (when something
 * is within `enough` of p; never when it is negative) the distance to some
 * triangle within it. */
static double nearest_within(const sw_mesh_grid *g, const double p[3], double enough,
                             sw_mesh_point *at)
{
    /* Rings of cells outward from p's, until the next ring lies farther
     * than the nearest found. */
    nearest n = { INFINITY, { UINT32_MAX, { 1, 0, 0 } }, enough < 0 ? -1 : enough * enough };
    int c[3];
    for (int k = 0; k < 3; k++)
        c[k] = cell_of(g, p[k], k);
    for (int k = 0;; k++) {
        double r = ring_distance(g, p, c, k);
        if (r == INFINITY || r * r > n.d2 || ring_visit(g, p, c, k, &n))
            break;
    }
    n.at.triangle = n.at.triangle == UINT32_MAX ? 0 : n.at.triangle;
    *at = n.at;
    return sqrt(n.d2);
}

double sw_mesh_grid_distance(const sw_mesh_grid *g, const double p[3])
{
    sw_mesh_point at;
    return sw_mesh_grid_nearest(g, p, &at);
}

double sw_mesh_grid_nearest(const sw_mesh_grid *g, const double p[3], sw_mesh_point *at)
{
    return nearest_within(g, p, -1, at);
}

/* The squared distance from p to triangle t of the grid's mesh. */
static double distance2_to(const sw_mesh_grid *g, const double p[3], uint32_t t)
{
    const double *v = g->corners + 9 * (size_t)t;
    double w[3];
    return triangle_distance2(p, v, v + 3, v + 6, w);
}

/* max(worst, the distance from p to the grid's mesh), searching no further
 * once a triangle within worst is found: most points of a level lie closer
 * to its source than the largest distance found so far. *hint is the
 * triangle that ended the last search (UINT32_MAX: none), tried first:
 * points are measured in order along a mesh, so the last one's triangle
 * is most often within worst of the next, and any triangle within worst
 * gives the same answer. */
static double farther(const sw_mesh_grid *g, const double p[3], double worst, uint32_t *hint)
{
    if (*hint != UINT32_MAX && distance2_to(g, p, *hint) <= worst * worst)
        return worst;
    sw_mesh_point at;
    double d = nearest_within(g, p, worst, &at);
    *hint = at.triangle;
    return sw_max(worst, d);
}

typedef struct within {
    double r2;
    int (*visit)(void *ctx, const sw_mesh_point *at);
    void *ctx;
} within;

static int visit_within(void *ctx, const sw_mesh_point *at, double d2)
{
    within *w = ctx;
    return d2 <= w->r2 && w->visit(w->ctx, at);
}

int sw_mesh_grid_within(const sw_mesh_grid *g, const double p[3], double r,
                        int (*visit)(void *ctx, const sw_mesh_point *at), void *ctx)
{
    int a[3], b[3], q[3];
    for (int k = 0; k < 3; k++)
        a[k] = cell_of(g, p[k] - r, k), b[k] = cell_of(g, p[k] + r, k);
    within w = { r * r, visit, ctx };
    for (q[2] = a[2]; q[2] <= b[2]; q[2]++)
        for (q[1] = a[1]; q[1] <= b[1]; q[1]++)
            for (q[0] = a[0]; q[0] <= b[0]; q[0]++)
                if (cell_distance2(g, p, q) <= w.r2 &&
                    cell_visit(g, p, q, &w.r2, visit_within, &w))
                    return 1;
    return 0;
}

double sw_mesh_distance(const sw_mesh_view *a, const sw_mesh_grid *g, double spacing)
{
    /* A triangle sampled at its corners alone shares them with its
     * neighbours: those vertices are measured once each, afterwards. */
    uint8_t *corner = calloc((size_t)a->vertex_count + 1, 1);
    double worst = 0;
    uint32_t hint = UINT32_MAX;
    for (uint32_t t = 0; t + 2 < a->index_count; t += 3) {
        double v[3][3], longest = 0;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                v[j][k] = a->positions[3 * (size_t)a->indices[t + j] + k];
        for (int j = 0; j < 3; j++) {
            double d[3] = { v[j][0] - v[(j + 1) % 3][0], v[j][1] - v[(j + 1) % 3][1],
                            v[j][2] - v[(j + 1) % 3][2] };
            longest = sw_max(longest, sqrt(dot3(d, d)));
        }
        int n = spacing > 0 ? (int)fmin(SW_MESH_DISTANCE_MAX_SIDE, ceil(longest / spacing)) : 1;
        if (n <= 1 && corner) {
            for (int j = 0; j < 3; j++)
                corner[a->indices[t + j]] = 1;
            continue;
        }
        n = n < 1 ? 1 : n;
        for (int i = 0; i <= n; i++)
            for (int j = 0; i + j <= n; j++) {
                double w0 = (double)i / n, w1 = (double)j / n, w2 = 1 - w0 - w1, p[3];
                for (int k = 0; k < 3; k++)
                    p[k] = w0 * v[0][k] + w1 * v[1][k] + w2 * v[2][k];
                worst = farther(g, p, worst, &hint);
            }
    }
    for (uint32_t i = 0; corner && i < a->vertex_count; i++)
        if (corner[i]) {
            const double p[3] = { a->positions[3 * (size_t)i], a->positions[3 * (size_t)i + 1],
                                  a->positions[3 * (size_t)i + 2] };
            worst = farther(g, p, worst, &hint);
        }
    free(corner);
    return worst;
}
