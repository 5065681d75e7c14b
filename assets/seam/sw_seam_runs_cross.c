/* SPDX-License-Identifier: MIT */
/* Would a collapse make a face's loops cross in (u, v)? (sw_seam_runs.h)
 *
 * A run of v1 that merges into its neighbour v2 drops its (u, v) point: the
 * loop's polyline m, b, o becomes the chord m, o, and the triangle m b o
 * changes sides. The polylines crossed nowhere before (a collapse that
 * made them cross was refused), so a new crossing needs another segment to
 * cut the chord, and that segment cannot leave the triangle through m b or
 * b o: one of its ends lies in the triangle. The test is therefore whether
 * any live run point of the surface lies in the (closed) triangle, found
 * through a grid of each surface's run points. Runs never move in (u, v),
 * they only die, so the grid is built once and dead runs are skipped. */
#include "sw_seam_runs.h"

#include <math.h>
#include <stdlib.h>

/* Cells a side: about four run points a cell, at most this many. */
enum { GRID_MAX_SIDE = 512 };

static uint32_t side_for(uint32_t points)
{
    uint32_t n = (uint32_t)ceil(sqrt(points / 4.0));
    return n < 1 ? 1 : n > GRID_MAX_SIDE ? GRID_MAX_SIDE : n;
}

static uint32_t cell_of(const sw_seam_uv_grid *grid, double x, int axis)
{
    double span = grid->box[2 * axis + 1] - grid->box[2 * axis];
    double t = span > 0 ? (x - grid->box[2 * axis]) / span * grid->side : 0.0;
    return t < 0 ? 0 : t >= grid->side ? grid->side - 1 : (uint32_t)t;
}

static const float *run_uv(const sw_seam_runs *r, const sw_seam_host *g, uint32_t run)
{
    return g->slots[r->runs[run].slot].uv;
}

sw_status sw_seam_runs_grid_init(sw_seam_runs *r, const sw_seam_host *g, uint32_t run_count,
                                 sw_error *err)
{
    uint32_t surfaces = g->surface_count;
    r->grids = calloc((size_t)surfaces + 1, sizeof *r->grids);
    r->cell_runs = malloc(((size_t)run_count + 1) * sizeof *r->cell_runs);
    if (!r->grids || !r->cell_runs)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    for (uint32_t s = 0; s < surfaces; s++)
        r->grids[s].box[0] = r->grids[s].box[2] = INFINITY,
        r->grids[s].box[1] = r->grids[s].box[3] = -INFINITY;
    for (uint32_t k = 0; k < run_count; k++) {
        sw_seam_uv_grid *grid = &r->grids[g->loops[r->loop_of[k]].surface];
        const float *uv = run_uv(r, g, k);
        grid->points++;
        for (int a = 0; a < 2; a++)
            grid->box[2 * a] = fmin(grid->box[2 * a], uv[a]),
            grid->box[2 * a + 1] = fmax(grid->box[2 * a + 1], uv[a]);
    }
    size_t cells = 0;
    for (uint32_t s = 0; s < surfaces; s++) {
        r->grids[s].side = side_for(r->grids[s].points);
        r->grids[s].first_cell = (uint32_t)cells;
        cells += (size_t)r->grids[s].side * r->grids[s].side;
    }
    r->cell_start = calloc(cells + 2, sizeof *r->cell_start);
    if (!r->cell_start)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    uint32_t *cell = malloc(((size_t)run_count + 1) * sizeof *cell);
    if (!cell)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    for (uint32_t k = 0; k < run_count; k++) {
        const sw_seam_uv_grid *grid = &r->grids[g->loops[r->loop_of[k]].surface];
        const float *uv = run_uv(r, g, k);
        cell[k] = grid->first_cell + cell_of(grid, uv[1], 1) * grid->side + cell_of(grid, uv[0], 0);
        r->cell_start[cell[k] + 2]++;
    }
    for (size_t c = 2; c < cells + 2; c++)
        r->cell_start[c] += r->cell_start[c - 1];
    for (uint32_t k = 0; k < run_count; k++)
        r->cell_runs[r->cell_start[cell[k] + 1]++] = k;
    free(cell);
    return SW_OK;
}

/* Twice the signed area of a b p, from float inputs (exact differences). */
static double orient(const float a[2], const float b[2], const float p[2])
{
    return ((double)b[0] - a[0]) * ((double)p[1] - a[1]) -
           ((double)b[1] - a[1]) * ((double)p[0] - a[0]);
}

static int same_uv(const float a[2], const float b[2])
{
    return a[0] == b[0] && a[1] == b[1];
}

/* p in the closed triangle a b c (which has area). */
static int in_triangle(const float a[2], const float b[2], const float c[2], const float p[2])
{
    double area = orient(a, b, c);
    if (area == 0)
        return 0;
    double s = area > 0 ? 1.0 : -1.0;
    return s * orient(a, b, p) >= 0 && s * orient(b, c, p) >= 0 && s * orient(c, a, p) >= 0;
}

/* Does a live run point of surface s other than the triangle's own runs
 * (tri_runs, count of them) lie in the triangle t? */
static int triangle_holds(const sw_seam_runs *r, const sw_seam_host *g, uint32_t s,
                          const uint32_t *tri_runs, int count, const float *t[3])
{
    if (orient(t[0], t[1], t[2]) == 0)
        return 0;
    const sw_seam_uv_grid *grid = &r->grids[s];
    uint32_t lo[2], hi[2];
    for (int a = 0; a < 2; a++) {
        double x0 = fmin(fmin(t[0][a], t[1][a]), t[2][a]);
        double x1 = fmax(fmax(t[0][a], t[1][a]), t[2][a]);
        lo[a] = cell_of(grid, x0, a), hi[a] = cell_of(grid, x1, a);
    }
    for (uint32_t y = lo[1]; y <= hi[1]; y++)
        for (uint32_t x = lo[0]; x <= hi[0]; x++) {
            uint32_t c = grid->first_cell + y * grid->side + x;
            for (uint32_t e = r->cell_start[c]; e < r->cell_start[c + 1]; e++) {
                uint32_t k = r->cell_runs[e];
                if (r->runs[k].vertex == SW_SEAM_NONE)
                    continue;
                int own = 0;
                for (int i = 0; i < count; i++)
                    own |= k == tri_runs[i];
                const float *p = run_uv(r, g, k);
                if (own || same_uv(p, t[0]) || same_uv(p, t[1]) || same_uv(p, t[2]))
                    continue;
                if (in_triangle(t[0], t[1], t[2], p))
                    return 1;
            }
        }
    return 0;
}

/* Run n of v1 merges into a neighbouring run of v2: do the points it (and,
 * for v2 v1 v2, the second run of v2) drops leave another point on the
 * other side of the new chord? */
static int merge_crosses(const sw_seam_runs *r, const sw_seam_host *g, uint32_t n, uint32_t v2)
{
    const sw_seam_run *run = &r->runs[n];
    uint32_t p = run->prev, q = run->next;
    if (r->loop_runs[r->loop_of[n]] < 4)
        return 0; /* the loop vanishes */
    uint32_t m = r->runs[p].vertex == v2 ? p : q;
    uint32_t poly[4] = {m, n, 0, 0};
    int count = 2;
    if (r->runs[p].vertex == v2 && r->runs[q].vertex == v2 && p != q)
        poly[count++] = q, poly[count++] = r->runs[q].next;
    else
        poly[count++] = m == p ? q : p;
    uint32_t s = g->loops[r->loop_of[n]].surface;
    for (int i = 1; i + 1 < count; i++) {
        const float *t[3] = {run_uv(r, g, poly[0]), run_uv(r, g, poly[i]),
                             run_uv(r, g, poly[i + 1])};
        if (triangle_holds(r, g, s, poly, count, t))
            return 1;
    }
    return 0;
}

int sw_seam_runs_crosses(const sw_seam_runs *r, const sw_seam_host *g, uint32_t v1, uint32_t v2)
{
    if (!r->grids)
        return 0;
    for (uint32_t n = r->first[v1]; n != SW_SEAM_NONE; n = r->link[n]) {
        const sw_seam_run *run = &r->runs[n];
        if (r->runs[run->prev].vertex != v2 && r->runs[run->next].vertex != v2)
            continue;   /* stays at its own (u, v) */
        if (merge_crosses(r, g, n, v2))
            return 1;
    }
    return 0;
}
