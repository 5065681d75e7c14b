/* SPDX-License-Identifier: MIT */
/* Sewing step 1 (sw_sew.h): every vertex projected onto the edges of other
 * loops within the tolerance, candidates from a 3D uniform grid (paper
 * section 4.1, "a 3D grid is used similar to [13]"). Each edge is entered,
 * in pieces no longer than a cell, into every cell its reach (the
 * tolerance, or twice its own gap) touches; a vertex looks into the cells
 * within twice its own gap. Of a vertex and an edge whose gaps add up to
 * their distance, the one with the wider gap reaches the other, so the
 * grid grows with each trim's own gap, not with the file's widest. An edge
 * or vertex reaching further than WIDE_CELLS cells is not gridded but tried
 * against every vertex or edge. The grid is a sorted array of (cell key,
 * edge): no hash table to size, and a key collision only adds candidates
 * the distance test then drops. Memory and work are capped (SEW_MAX_BYTES,
 * SEW_MAX_WIDE_TESTS): a file whose gaps pass them fails with an error that
 * says so, instead of taking the machine's memory. */
#include "sw_sew_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_grow.h"

enum { WIDE_CELLS = 8 };
/* The most the grid, and the candidate pairs, may each take. */
#define SEW_MAX_BYTES ((size_t)1 << 30)
/* The most projections tried for the wide vertices and edges. */
#define SEW_MAX_WIDE_TESTS 5e8

typedef struct grid_entry {
    uint64_t key;
    uint32_t edge;
} grid_entry;

typedef struct grid {
    double origin[3], cell;
    grid_entry *entries;
    size_t count, capacity;
    uint32_t *wide;           /* edges reaching past WIDE_CELLS cells */
    size_t wide_count, wide_capacity;
} grid;

/* What failed: memory, or one of the caps. */
enum { SEW_OOM = -1, SEW_CAPPED = -2 };

static uint64_t cell_key(int64_t x, int64_t y, int64_t z)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15u ^ (uint64_t)y * 0xC2B2AE3D27D4EB4Fu ^
                 (uint64_t)z * 0x165667B19E3779F9u;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9u;
    return h ^ (h >> 29);
}

static int64_t cell_of(const grid *g, double x, int axis)
{
    double c = floor((x - g->origin[axis]) / g->cell);
    return c > -4e18 ? (c < 4e18 ? (int64_t)c : (int64_t)4e18) : (int64_t)-4e18;
}

static int grid_add(grid *g, uint64_t key, uint32_t edge)
{
    if (g->count + 1 > SEW_MAX_BYTES / sizeof *g->entries)
        return SEW_CAPPED;
    grid_entry *entries = sw_grow(g->entries, &g->capacity, g->count + 1, sizeof *entries);
    if (!entries)
        return SEW_OOM;
    g->entries = entries;
    g->entries[g->count++] = (grid_entry){key, edge};
    return 0;
}

/* Enters edge e (a -> b) in the cells within tol of it. */
static int grid_add_edge(grid *g, const double *a, const double *b, double tol, uint32_t e)
{
    double len = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                      (b[2] - a[2]) * (b[2] - a[2]));
    double pieces = ceil(len / g->cell);
    size_t m = pieces >= 1 ? (pieces < 1e7 ? (size_t)pieces : 10000000u) : 1;
    for (size_t k = 0; k < m; k++) {
        int64_t lo[3], hi[3];
        for (int i = 0; i < 3; i++) {
            double x0 = a[i] + (b[i] - a[i]) * (double)k / (double)m;
            double x1 = a[i] + (b[i] - a[i]) * (double)(k + 1) / (double)m;
            lo[i] = cell_of(g, fmin(x0, x1) - tol, i);
            hi[i] = cell_of(g, fmax(x0, x1) + tol, i);
        }
        for (int64_t x = lo[0]; x <= hi[0]; x++)
            for (int64_t y = lo[1]; y <= hi[1]; y++)
                for (int64_t z = lo[2]; z <= hi[2]; z++) {
                    int st = grid_add(g, cell_key(x, y, z), e);
                    if (st != 0)
                        return st;
                }
    }
    return 0;
}

static int compare_entries(const void *x, const void *y)
{
    const grid_entry *a = x, *b = y;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->edge > b->edge) - (a->edge < b->edge);
}

/* How far from edge e (to next) a vertex may lie and be found through the
 * grid: the tolerance, or twice the edge's gap. */
static double edge_reach(const sw_seam_polylines *poly, double tol, uint32_t e, uint32_t next)
{
    return fmax(tol, 2 * fmax(sew_gap(poly, e), sew_gap(poly, next)));
}

static int add_wide(grid *g, uint32_t e)
{
    uint32_t *wide = sw_grow(g->wide, &g->wide_capacity, g->wide_count + 1, sizeof *wide);
    if (!wide)
        return SEW_OOM;
    g->wide = wide;
    g->wide[g->wide_count++] = e;
    return 0;
}

/* Cells as wide as the mean edge (at least twice the tolerance): an edge
 * then touches a few cells and a cell holds a few edges. */
static int grid_build(grid *g, const sw_seam_polylines *poly, double tol)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, total = 0;
    for (size_t v = 0; v < poly->vertex_count; v++)
        for (int i = 0; i < 3; i++)
            lo[i] = fmin(lo[i], poly->p[3 * v + i]);
    for (size_t l = 0; l < poly->loop_count; l++)
        for (size_t v = poly->loop_start[l]; v < poly->loop_start[l + 1]; v++) {
            const double *a = poly->p + 3 * v;
            const double *b = poly->p + 3 * sew_next(poly, (uint32_t)l, (uint32_t)v);
            total += sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                          (b[2] - a[2]) * (b[2] - a[2]));
        }
    memcpy(g->origin, lo, sizeof lo);
    g->cell = fmax(2 * tol, poly->vertex_count ? total / (double)poly->vertex_count : 0);
    for (size_t l = 0; l < poly->loop_count; l++)
        for (size_t v = poly->loop_start[l]; v < poly->loop_start[l + 1]; v++) {
            uint32_t w = sew_next(poly, (uint32_t)l, (uint32_t)v);
            double reach = edge_reach(poly, tol, (uint32_t)v, w);
            int st = reach <= WIDE_CELLS * g->cell
                         ? grid_add_edge(g, poly->p + 3 * v, poly->p + 3 * w, reach, (uint32_t)v)
                         : add_wide(g, (uint32_t)v);
            if (st != 0)
                return st;
        }
    if (g->count > 1)
        qsort(g->entries, g->count, sizeof *g->entries, compare_entries);
    return 0;
}

/* The first entry with key >= key. */
static size_t grid_find(const grid *g, uint64_t key)
{
    size_t lo = 0, hi = g->count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (g->entries[mid].key < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static int add_match(sew_state *s, const sew_match *m)
{
    if (s->match_count + 1 > SEW_MAX_BYTES / sizeof *s->matches)
        return SEW_CAPPED;
    sew_match *matches = sw_grow(s->matches, &s->match_capacity, s->match_count + 1,
                                 sizeof *matches);
    if (!matches)
        return SEW_OOM;
    s->matches = matches;
    s->matches[s->match_count++] = *m;
    return 0;
}

/* Does one of v's edges run within 60 degrees of direction d (either way)?
 * Edges no longer than twice the tolerance say nothing about direction and
 * count as agreeing. Without this, where several loops meet at an angle (a
 * pole, a corner of high valence) the vertices near the junction on one
 * loop's side lie within the tolerance of another side leaving it and get
 * sewn across the corner. */
static int directions_agree(const sew_state *s, uint32_t v, const double d[3], double dlen)
{
    const sw_seam_polylines *poly = s->poly;
    uint32_t l = s->vertex_loop[v];
    uint32_t prev = v > poly->loop_start[l] ? v - 1 : (uint32_t)poly->loop_start[l + 1] - 1;
    uint32_t ends[2] = {prev, sew_next(poly, l, v)};
    if (dlen <= 2 * s->tol)
        return 1;
    for (int k = 0; k < 2; k++) {
        const double *a = poly->p + 3 * (size_t)v, *b = poly->p + 3 * (size_t)ends[k];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double elen = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (elen <= 2 * s->tol || fabs(e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) >= 0.5 * elen * dlen)
            return 1;
    }
    return 0;
}

/* Does the file's topology let vertex v sew onto edge e? Where both are
 * uses of shared edges (sw_seam_polylines.edge), only of the same one: v
 * lies on the edges of its segments to either side (two at a corner). The
 * two long sides of a sliver face narrower than the tolerance each belong
 * with their own neighbour; by position alone either side was sewn to both
 * (the Fly Gemini DIN mount), and the sliver's loop zigzagged between them. */
static int edges_agree(const sew_state *s, uint32_t v, uint32_t e)
{
    const sw_seam_polylines *poly = s->poly;
    if (!poly->edge || poly->edge[e] == 0)
        return 1;
    uint32_t l = s->vertex_loop[v];
    uint32_t prev = v > poly->loop_start[l] ? v - 1 : (uint32_t)poly->loop_start[l + 1] - 1;
    uint32_t out = poly->edge[v], in = poly->edge[prev];
    return out == 0 || in == 0 || out == poly->edge[e] || in == poly->edge[e];
}

/* Projects vertex v onto edge e; keeps it within the tolerance, or within
 * both sides' gaps where they add up to more: each border lies within its
 * gap of the edge the file meant (OpenCASCADE's sewing takes the edges' own
 * tolerances the same way). */
static int project(sew_state *s, uint32_t v, uint32_t e)
{
    const sw_seam_polylines *poly = s->poly;
    uint32_t le = s->vertex_loop[e];
    const double *p = poly->p + 3 * (size_t)v, *a = poly->p + 3 * (size_t)e;
    uint32_t next = sew_next(poly, le, e);
    const double *b = poly->p + 3 * (size_t)next;
    double reach = fmax(s->tol, sew_gap(poly, v) + fmax(sew_gap(poly, e), sew_gap(poly, next)));
    double d[3], len2 = 0, t = 0, dist2 = 0;
    for (int i = 0; i < 3; i++) {
        d[i] = b[i] - a[i];
        len2 += d[i] * d[i];
        t += (p[i] - a[i]) * d[i];
    }
    double len = sqrt(len2), snap = 0.25 * fmin(s->tol, len);
    t = len2 > 0 ? t / len2 : 0;
    /* Only feet on the edge count (paper, figure 2: projections onto the
     * edge). A point beyond an end is that end's business, through the edge
     * on the other side of it, unless it is within the snap distance: a
     * clamped projection would let every vertex near a vertex of the other
     * polyline map onto it, and a dense run of vertices collapse into one. */
    if (t < 0 ? -t * len > snap : t > 1 ? (t - 1) * len > snap : 0)
        return 0;
    t = fmin(fmax(t, 0.0), 1.0);
    for (int i = 0; i < 3; i++)
        dist2 += (p[i] - a[i] - t * d[i]) * (p[i] - a[i] - t * d[i]);
    if (!(dist2 <= reach * reach))
        return 0;
    if (!directions_agree(s, v, d, len) || !edges_agree(s, v, e))
        return 0;
    /* A foot this close to an end is that end: no sliver edges. */
    if (t * len <= snap)
        t = 0;
    else if ((1 - t) * len <= snap)
        t = 1;
    /* on v's own loop: a copy of it, so the pair code sees two loops */
    uint32_t pair = le == s->vertex_loop[v] ? le + (uint32_t)poly->loop_count : le;
    sew_match m = {v, e, s->vertex_loop[v], pair, t, sqrt(dist2), 0};
    return add_match(s, &m);
}

/* Are vertex v and edge e of its own loop far apart along the loop (more
 * than ten tolerances either way)? Then they may be sewn: a closed surface
 * meets itself there (a cylinder's two sides along its seam line), and left
 * unsewn each side would be simplified on its own. Nearer, they are
 * neighbours on one border, which must not be sewn to itself. */
static int far_along(const sew_state *s, uint32_t v, uint32_t e)
{
    const sw_seam_polylines *poly = s->poly;
    uint32_t l = s->vertex_loop[v];
    uint32_t first = (uint32_t)poly->loop_start[l], last = (uint32_t)poly->loop_start[l + 1] - 1;
    const double *a = poly->p + 3 * (size_t)first, *b = poly->p + 3 * (size_t)last;
    double closing = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                          (a[2] - b[2]) * (a[2] - b[2]));
    double length = s->arc[last] + closing, limit = 10 * s->tol;
    uint32_t ends[2] = {e, sew_next(poly, l, e)};
    for (int k = 0; k < 2; k++) {
        double d = fabs(s->arc[ends[k]] - s->arc[v]);
        if (fmin(d, length - d) <= limit)
            return 0;
    }
    return 1;
}

/* Tries edge e for vertex v once (seen[e] == v after), unless e is a
 * neighbour of v on v's own loop. */
static int visit(sew_state *s, uint32_t *seen, uint32_t v, uint32_t e)
{
    if (seen[e] == v || (s->vertex_loop[e] == s->vertex_loop[v] && !far_along(s, v, e)))
        return 0;
    seen[e] = v;
    return project(s, v, e);
}

/* Every candidate edge of vertex v: those in the cells within twice its gap
 * (every edge when that passes WIDE_CELLS cells), and the wide edges. */
static int query_vertex(sew_state *s, const grid *g, uint32_t *seen, uint32_t v)
{
    const double *p = s->poly->p + 3 * (size_t)v;
    double r = 2 * sew_gap(s->poly, v);
    int st = 0;
    if (!(r <= WIDE_CELLS * g->cell)) {
        for (uint32_t e = 0; st == 0 && e < s->poly->vertex_count; e++)
            st = visit(s, seen, v, e);
        return st;
    }
    int64_t lo[3], hi[3];
    for (int i = 0; i < 3; i++)
        lo[i] = cell_of(g, p[i] - r, i), hi[i] = cell_of(g, p[i] + r, i);
    for (int64_t x = lo[0]; x <= hi[0]; x++)
        for (int64_t y = lo[1]; y <= hi[1]; y++)
            for (int64_t z = lo[2]; z <= hi[2]; z++) {
                uint64_t key = cell_key(x, y, z);
                for (size_t k = grid_find(g, key); st == 0 && k < g->count &&
                                                   g->entries[k].key == key; k++)
                    st = visit(s, seen, v, g->entries[k].edge);
            }
    for (size_t k = 0; st == 0 && k < g->wide_count; k++)
        st = visit(s, seen, v, g->wide[k]);
    return st;
}

/* The projections the wide vertices and edges cost: each is tried against
 * every edge or vertex. */
static double wide_tests(const sew_state *s, const grid *g)
{
    size_t wide_vertices = 0;
    for (uint32_t v = 0; v < s->poly->vertex_count; v++)
        wide_vertices += !(2 * sew_gap(s->poly, v) <= WIDE_CELLS * g->cell);
    return ((double)wide_vertices + (double)g->wide_count) * (double)s->poly->vertex_count;
}

static sw_status capped(const sew_state *s, const grid *g, const char *what)
{
    return sw_error_set(s->err, SW_ERR_RANGE, "sewing: %s (%zu trim vertices; gaps up to %g "
                        "beside a mean edge of %g and a tolerance of %g): the trims' gaps are too "
                        "wide for the sewing to search", what, s->poly->vertex_count, s->max_gap,
                        g->cell, s->tol);
}

sw_status sew_project(sew_state *s)
{
    const sw_seam_polylines *poly = s->poly;
    grid g = {0};
    uint32_t *seen = malloc((poly->vertex_count + 1) * sizeof *seen);
    int st = seen ? grid_build(&g, poly, s->tol) : SEW_OOM;
    const char *cap = st == SEW_CAPPED ? "a search grid of more than 1 GiB" : NULL;
    if (st == 0 && wide_tests(s, &g) > SEW_MAX_WIDE_TESTS)
        st = SEW_CAPPED, cap = "more than 5e8 projections for the widest gaps";
    for (size_t e = 0; seen && e < poly->vertex_count; e++)
        seen[e] = UINT32_MAX;
    for (uint32_t v = 0; st == 0 && v < poly->vertex_count; v++)
        st = query_vertex(s, &g, seen, v);
    if (st == SEW_CAPPED && !cap)
        cap = "more than 1 GiB of candidate pairs";
    sw_status out = SW_OK;
    if (cap)
        out = capped(s, &g, cap);
    else if (st != 0)
        out = sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory projecting %zu "
                           "vertices", poly->vertex_count);
    free(g.entries);
    free(g.wide);
    free(seen);
    return out;
}
