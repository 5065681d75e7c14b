/* SPDX-License-Identifier: MIT */
#include "sw_seam_surface.h"

#include <float.h>
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

/* ---- loops that touch ---------------------------------------------------- */

/* Segments under one box while points look for the nearest segment of an
 * earlier loop; the box tests a surface may spend on it (points x boxes). */
#define TOUCH_CHUNK 16u
#define TOUCH_TESTS (1u << 26)
/* In shrinks (sw_trim_tess_shrink): a point this near an earlier loop may
 * cross it once both move (each up to four shrinks), and is moved to at
 * least the margin from it; a move past the most is not made. A point a few
 * floats across is a rounding too: the reach adds TOUCH_FLOATS of them. */
#define TOUCH_REACH 12.0
#define TOUCH_MARGIN 16.0
#define TOUCH_MOST 1e6
#define TOUCH_FLOATS 4.0

typedef struct touch_box {
    double box[4];
    uint32_t first, count, loop;
} touch_box;

typedef struct seg2 {
    double au, av, bu, bv;
} seg2;

static seg2 segment(const sw_trim_point *pt, uint32_t a, uint32_t b)
{
    return (seg2){ pt[a].uv[0], pt[a].uv[1], pt[b].uv[0], pt[b].uv[1] };
}

/* Distance from (u, v) to segment s; *t the nearest point's parameter. */
static double seg_distance(const seg2 *s, double u, double v, double *t)
{
    double du = s->bu - s->au, dv = s->bv - s->av, l2 = du * du + dv * dv;
    double k = l2 > 0 ? ((u - s->au) * du + (v - s->av) * dv) / l2 : 0;
    k = k < 0 ? 0 : k > 1 ? 1 : k;
    *t = k;
    double x = s->au + k * du - u, y = s->av + k * dv - v;
    return sqrt(x * x + y * y);
}

/* The unit normal of s toward the region (left when region_left). */
static void region_normal(const seg2 *s, int region_left, double n[2])
{
    double du = s->bu - s->au, dv = s->bv - s->av, l = sqrt(du * du + dv * dv);
    double sign = region_left ? 1.0 : -1.0;
    n[0] = l > 0 ? -sign * dv / l : 0, n[1] = l > 0 ? sign * du / l : 0;
}

/* Point p moved along dir (unit) until it stands at least margin from
 * segments s and s2 (s2 may be s): float steps from the move's size up,
 * doubling; 0 (p kept) when no step up to `most` does. */
static int move_off(sw_trim_point *p, const double dir[2], const seg2 *s, const seg2 *s2,
                    double margin, double most)
{
    double t;
    for (double step = margin; step <= most; step *= 2) {
        float u = (float)(p->uv[0] + dir[0] * step), v = (float)(p->uv[1] + dir[1] * step);
        if (u == p->uv[0] && dir[0] != 0)
            u = nextafterf(u, dir[0] > 0 ? INFINITY : -INFINITY);
        if (v == p->uv[1] && dir[1] != 0)
            v = nextafterf(v, dir[1] > 0 ? INFINITY : -INFINITY);
        if (seg_distance(s, u, v, &t) >= margin && seg_distance(s2, u, v, &t) >= margin) {
            p->uv[0] = u, p->uv[1] = v;
            return 1;
        }
    }
    return 0;
}

static double loop_area2(const sw_trim_point *pt, uint32_t first, uint32_t end)
{
    double sum = 0;
    for (uint32_t k = first; k < end; k++) {
        const sw_trim_point *p = &pt[k], *q = &pt[k + 1 == end ? first : k + 1];
        sum += (double)p->uv[0] * q->uv[1] - (double)q->uv[0] * p->uv[1];
    }
    return sum;
}

/* Boxes of up to TOUCH_CHUNK consecutive segments of every loop, grown by
 * reach. Returns how many. */
static uint32_t touch_boxes(const sw_trim_point *pt, const uint32_t *loop_first,
                            uint32_t loop_count, double reach, touch_box *box)
{
    uint32_t n = 0;
    for (uint32_t l = 0; l < loop_count; l++)
        for (uint32_t a = loop_first[l]; a < loop_first[l + 1]; a += TOUCH_CHUNK, n++) {
            uint32_t end = loop_first[l + 1], count = end - a < TOUCH_CHUNK ? end - a : TOUCH_CHUNK;
            touch_box *b = &box[n];
            *b = (touch_box){ { INFINITY, -INFINITY, INFINITY, -INFINITY }, a, count, l };
            for (uint32_t k = a; k <= a + count; k++) {
                const sw_trim_point *p = &pt[k == end ? loop_first[l] : k];
                double r = reach + 2 * TOUCH_FLOATS * FLT_EPSILON *
                                       fmax(fabs(p->uv[0]), fabs(p->uv[1]));
                b->box[0] = fmin(b->box[0], p->uv[0] - r);
                b->box[1] = fmax(b->box[1], p->uv[0] + r);
                b->box[2] = fmin(b->box[2], p->uv[1] - r);
                b->box[3] = fmax(b->box[3], p->uv[1] + r);
            }
        }
    return n;
}

/* The loops as part_touching sees them: boxes of their segments, and on
 * which side of each the region lies. */
typedef struct touch_ctx {
    sw_trim_point *pt;
    const uint32_t *loop_first;
    const touch_box *box;
    const uint8_t *left;   /* per loop: the region lies left of its segments */
    uint32_t nbox;
    double reach, margin, most;
} touch_ctx;

/* The nearest segment to point i among the boxes of loops before `loop`,
 * within reach (and a few floats): its start in *seg (UINT32_MAX if none),
 * its loop in *seg_loop, the nearest point's parameter on it in *seg_t. */
static void nearest_earlier(const touch_ctx *c, uint32_t loop, uint32_t i, uint32_t *seg,
                            uint32_t *seg_loop, double *seg_t)
{
    double u = c->pt[i].uv[0], v = c->pt[i].uv[1], t;
    double best = c->reach + TOUCH_FLOATS * FLT_EPSILON * fmax(fabs(u), fabs(v));
    *seg = UINT32_MAX;
    for (uint32_t b = 0; b < c->nbox && c->box[b].loop < loop; b++) {
        const touch_box *x = &c->box[b];
        if (u < x->box[0] || u > x->box[1] || v < x->box[2] || v > x->box[3])
            continue;
        uint32_t end = c->loop_first[x->loop + 1];
        for (uint32_t k = x->first; k < x->first + x->count; k++) {
            seg2 s = segment(c->pt, k, k + 1 == end ? c->loop_first[x->loop] : k + 1);
            double d = seg_distance(&s, u, v, &t);
            if (d <= best)
                best = d, *seg = k, *seg_loop = x->loop, *seg_t = t;
        }
    }
}

/* Point i, near segment k of loop m at t, moved into m's region: off the
 * segment along its normal, or, nearest at one of its ends, along the
 * mitre of the two segments there. Returns 1 when moved. */
static int part_point(const touch_ctx *c, uint32_t i, uint32_t m, uint32_t k, double t)
{
    uint32_t f = c->loop_first[m], e = c->loop_first[m + 1];
    seg2 s = segment(c->pt, k, k + 1 == e ? f : k + 1), s2 = s;
    double dir[2], n2[2];
    region_normal(&s, c->left[m], dir);
    if (t == 0 || t == 1) {
        s2 = t == 0 ? segment(c->pt, k == f ? e - 1 : k - 1, k)
                    : segment(c->pt, k + 1 == e ? f : k + 1, k + 2 >= e ? f + (k + 2 - e) : k + 2);
        region_normal(&s2, c->left[m], n2);
        double nu = dir[0] + n2[0], nv = dir[1] + n2[1], nl = sqrt(nu * nu + nv * nv);
        if (nl > 1e-3)
            dir[0] = nu / nl, dir[1] = nv / nl;
    }
    return move_off(&c->pt[i], dir, &s, &s2, c->margin, c->most);
}

/* Where a point of one loop lies on or next to another loop (a hole
 * tangent to the outline, a hole sharing a vertex with it), the
 * tessellator's region shrink moves both into their region, across each
 * other, and the clipping refuses the surface. Each such point of a later
 * loop is moved off the earlier loop into that loop's region side (to the
 * next float and beyond, at least TOUCH_MARGIN shrinks): the region keeps
 * a neck far below a pixel where it was pinched. Border vertices keep
 * their seam position: only the (u, v) the clipping sees moves. Returns
 * the points moved; 0 when the search would pass TOUCH_TESTS. */
static uint32_t part_touching(sw_trim_point *pt, const uint32_t *loop_first, uint32_t loop_count,
                              uint32_t outer, double shrink, sw_arena *scratch)
{
    uint32_t total = loop_first[loop_count], nbox = 0, moved = 0;
    for (uint32_t l = 0; l < loop_count; l++)
        nbox += (loop_first[l + 1] - loop_first[l] + TOUCH_CHUNK - 1) / TOUCH_CHUNK;
    if (loop_count < 2 || !(shrink > 0) || (uint64_t)total * nbox > TOUCH_TESTS)
        return 0;
    size_t mark = sw_arena_mark(scratch);
    touch_box *box = sw_arena_alloc(scratch, sizeof *box * ((size_t)nbox + 1), 8);
    uint8_t *left = sw_arena_alloc(scratch, (size_t)loop_count, 1);
    if (box && left) {
        for (uint32_t l = 0; l < loop_count; l++)
            left[l] = (loop_area2(pt, loop_first[l], loop_first[l + 1]) > 0) == (l < outer);
        touch_ctx c = { pt, loop_first, box, left, 0, TOUCH_REACH * shrink,
                        TOUCH_MARGIN * shrink, TOUCH_MOST * shrink };
        c.nbox = touch_boxes(pt, loop_first, loop_count, c.reach, box);
        for (uint32_t l = 1; l < loop_count; l++)
            for (uint32_t i = loop_first[l]; i < loop_first[l + 1]; i++) {
                uint32_t k, m = 0;
                double t = 0;
                nearest_earlier(&c, l, i, &k, &m, &t);
                moved += k != UINT32_MAX && part_point(&c, i, m, k, t);
            }
    }
    sw_arena_reset_to(scratch, mark);
    return moved;
}

uint32_t sw_seam_surface_untangle(sw_trim_loops *loops, sw_trim_point *points,
                                  uint32_t *loop_first, uint32_t *outer, double shrink,
                                  sw_arena *scratch)
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
    return dropped + part_touching(points, loop_first, loops->loop_count, *outer, shrink, scratch);
}
