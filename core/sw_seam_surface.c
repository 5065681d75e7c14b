/* SPDX-License-Identifier: MIT */
#include "sw_seam_surface.h"

#include <math.h>
#include <string.h>

sw_trim_tess_options sw_seam_surface_tess_options(void)
{
    return (sw_trim_tess_options){ .crossing_on_segment = 1,
                                   .border_fraction = 1.0 - SW_SEAM_SHARE };
}

int sw_seam_surface_loops(const sw_seam_select *state, uint32_t surface, float pin,
                          const sw_seam_surface_buffers *buf, sw_trim_loops *loops,
                          uint32_t *outer)
{
    const sw_seam_graph *g = &state->graph;
    uint32_t total = 0, k = 0;
    buf->loop_first[0] = 0;
    *outer = 0;
    for (int holes = 0; holes < 2; holes++) {
        if (holes)
            *outer = k;
        for (uint32_t l = g->surface_loops[surface]; l < g->surface_loops[surface + 1]; l++) {
            if ((!(g->loops[l].flags & SW_SEAM_LOOP_OUTER)) != holes)
                continue;
            uint32_t count = 0;
            int vanished = 0;
            /* Cannot fail: l is in range and the buffer holds the surface's slots. */
            sw_seam_select_loop(state, l, pin, buf->seam_points + total, buf->capacity - total,
                                &count, &vanished, NULL);
            if (vanished && !holes)
                return 0;
            if (vanished)
                continue;
            for (uint32_t i = 0; i < count; i++) {
                const sw_seam_point *sp = &buf->seam_points[total + i];
                sw_trim_point *tp = &buf->points[total + i];
                memcpy(tp->uv, sp->uv, sizeof tp->uv);
                memcpy(tp->p, g->vertices[sp->vertex].p, sizeof tp->p);
                tp->id = sp->vertex;
            }
            total += count;
            buf->loop_first[++k] = total;
        }
    }
    *loops = (sw_trim_loops){ buf->points, buf->loop_first, k };
    return k > 0;
}

/* ---- untangling --------------------------------------------------------- */

/* Is the excursion from points[a] out and back to points[b] (a < b, the
 * same vertex) thin: chord and area small against its reach? */
static int thin_excursion(const sw_trim_point *pt, uint32_t a, uint32_t b)
{
    double u0 = pt[a].uv[0], v0 = pt[a].uv[1], reach = 0, area = 0;
    for (uint32_t k = a + 1; k <= b; k++) {
        double du = pt[k].uv[0] - u0, dv = pt[k].uv[1] - v0;
        reach = fmax(reach, sqrt(du * du + dv * dv));
        double pu = pt[k - 1].uv[0] - u0, pv = pt[k - 1].uv[1] - v0;
        area += pu * dv - pv * du;
    }
    double cu = pt[b].uv[0] - u0, cv = pt[b].uv[1] - v0;
    double chord = sqrt(cu * cu + cv * cv);
    return reach > 0 && chord <= SW_SEAM_THIN * reach &&
           fabs(0.5 * area) <= SW_SEAM_THIN * reach * reach;
}

/* Points an excursion test may read, per point of the loop: a loop that
 * comes back to its vertices over and over (a printer bed's outline, 54
 * slots a vertex) would otherwise cost its length squared. */
#define EXCURSION_READS 64u

/* Loop [first, first + n): marks drop[k] for the points of thin excursions,
 * found through an open-addressing table of each vertex's last position
 * (table: at least 2n entries; the loop's own power of two of them is
 * used, so a surface of many small holes clears little of it). */
static uint32_t mark_loop(const sw_trim_point *pt, uint32_t first, uint32_t n, uint8_t *drop,
                          uint32_t *table)
{
    uint32_t marked = 0, mask = 1;
    while (mask < 2 * n)
        mask <<= 1;
    mask -= 1;
    uint64_t reads = 0, budget = (uint64_t)EXCURSION_READS * n;
    for (uint32_t i = 0; i <= mask; i++)
        table[i] = UINT32_MAX;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t id = pt[first + i].id, h = (id * 2654435761u) & mask;
        while (table[h] != UINT32_MAX && pt[first + table[h]].id != id)
            h = (h + 1) & mask;
        uint32_t last = table[h];
        table[h] = i;
        if (last == UINT32_MAX || i - last < 2 || drop[first + last] ||
            (reads += i - last) > budget || !thin_excursion(pt, first + last, first + i))
            continue;
        for (uint32_t k = last + 1; k <= i; k++)
            marked += !drop[first + k], drop[first + k] = 1;
        table[h] = last;   /* the vertex stands where it first stood */
    }
    return marked;
}

/* Crossing lobes: rounds per loop, and the most points a loop may have for
 * its segments to be tried pair by pair. */
#define LOBE_ROUNDS 4u
#define LOBE_POINTS 2048u

static double orient(const sw_trim_point *a, const sw_trim_point *b, const sw_trim_point *c)
{
    return ((double)b->uv[0] - a->uv[0]) * ((double)c->uv[1] - a->uv[1]) -
           ((double)b->uv[1] - a->uv[1]) * ((double)c->uv[0] - a->uv[0]);
}

/* Do segments a-b and c-d cross, each strictly between the other's ends? */
static int cross(const sw_trim_point *a, const sw_trim_point *b, const sw_trim_point *c,
                 const sw_trim_point *d)
{
    double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

/* Twice the signed area of the polygon idx[a .. b] (closed). */
static double area2(const sw_trim_point *pt, const uint32_t *idx, uint32_t a, uint32_t b)
{
    double sum = 0;
    for (uint32_t k = a; k <= b; k++) {
        const sw_trim_point *p = &pt[idx[k]], *q = &pt[idx[k == b ? a : k + 1]];
        sum += (double)p->uv[0] * q->uv[1] - (double)q->uv[0] * p->uv[1];
    }
    return sum;
}

/* The first crossing of two segments a < b of the kept points idx[0 .. m)
 * whose lobe idx[a + 1 .. b] is thin against the whole loop; 0 if none. */
static int thin_lobe(const sw_trim_point *pt, const uint32_t *idx, uint32_t m, uint32_t *lo,
                     uint32_t *hi)
{
    double whole = fabs(area2(pt, idx, 0, m - 1));
    for (uint32_t a = 0; a + 2 < m; a++)
        for (uint32_t b = a + 2; b < m; b++) {
            if ((a == 0 && b == m - 1) ||
                !cross(&pt[idx[a]], &pt[idx[a + 1]], &pt[idx[b]], &pt[idx[(b + 1) % m]]))
                continue;
            if (2 * (b - a) < m && fabs(area2(pt, idx, a + 1, b)) <= SW_SEAM_THIN * whole) {
                *lo = a + 1, *hi = b;
                return 1;
            }
        }
    return 0;
}

/* Loop [first, first + n): where two of its segments cross and the lobe
 * between them encloses next to nothing against the loop (a needle's two
 * sides, the same curve's (u, v) twice, crossing short of its tip), the
 * lobe's points are marked. idx: scratch for the loop's kept points. */
static uint32_t mark_lobes(const sw_trim_point *pt, uint32_t first, uint32_t n, uint8_t *drop,
                           uint32_t *idx)
{
    uint32_t marked = 0;
    for (uint32_t round = 0; round < LOBE_ROUNDS; round++) {
        uint32_t m = 0, lo, hi;
        for (uint32_t k = first; k < first + n; k++)
            if (!drop[k])
                idx[m++] = k;
        if (m < 4 || m > LOBE_POINTS || !thin_lobe(pt, idx, m, &lo, &hi))
            break;
        for (uint32_t k = lo; k <= hi; k++)
            drop[idx[k]] = 1, marked++;
    }
    return marked;
}

uint32_t sw_seam_surface_untangle(sw_trim_loops *loops, sw_trim_point *points,
                                  uint32_t *loop_first, uint32_t *outer, sw_arena *scratch)
{
    uint32_t total = loop_first[loops->loop_count], table_size = 1;   /* the largest loop's */
    for (uint32_t l = 0; l < loops->loop_count; l++)
        while (table_size < 2 * (loop_first[l + 1] - loop_first[l]))
            table_size <<= 1;
    size_t mark = sw_arena_mark(scratch);
    uint8_t *drop = sw_arena_alloc(scratch, (size_t)total + 1, 1);
    uint32_t *table = sw_arena_alloc(scratch, sizeof *table * (size_t)table_size, 4);
    uint32_t *idx = sw_arena_alloc(scratch, sizeof *idx * ((size_t)total + 1), 4);
    uint32_t dropped = 0;
    if (drop && table && idx) {
        memset(drop, 0, (size_t)total + 1);
        for (uint32_t l = 0; l < loops->loop_count; l++) {
            uint32_t first = loop_first[l], n = loop_first[l + 1] - first;
            dropped += mark_loop(points, first, n, drop, table);
            dropped += mark_lobes(points, first, n, drop, idx);
        }
    }
    if (dropped > 0) {
        uint32_t out = 0, k = 0, outer_kept = 0;
        for (uint32_t l = 0; l < loops->loop_count; l++) {
            uint32_t start = out;
            for (uint32_t i = loop_first[l]; i < loop_first[l + 1]; i++)
                if (!drop[i])
                    points[out++] = points[i];
            if (out - start < 3) {
                out = start;   /* nothing left to bound */
                continue;
            }
            loop_first[++k] = out;
            outer_kept += l < *outer;
        }
        loops->loop_count = k;
        *outer = outer_kept;
    }
    sw_arena_reset_to(scratch, mark);
    return dropped;
}
