/* SPDX-License-Identifier: MIT */
/* Cutting surfaces whose loops are too long for one draw (sw_seam_split.h).
 *
 * The lines are chosen from the sewn loops' points: k pieces of about the
 * target each, at the points' quantiles along u or along v, midway between
 * two neighbouring points so that no line runs through one. Of the two
 * directions the one whose largest piece, with the points its cut lines
 * add (their length on the surface at the loops' density), is smaller
 * wins: a spring is cut across its wire, not along it. A line the cut
 * refuses (it grazes a curve's end) is moved by a few points. */
#include "sw_seam_split.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_model_split.h"

enum { MAX_PIECES = 32, TRIES = 8, ISO_SAMPLES = 64 };

typedef struct long_surface {
    uint32_t surface, points;
    double *coords[2];   /* the loop points' u and v, sorted */
    double length;       /* the loops' length in model space */
} long_surface;

static int by_value(const void *a, const void *b)
{
    double p = *(const double *)a, q = *(const double *)b;
    return (p > q) - (p < q);
}

static double dist(const float a[3], const float b[3])
{
    double d[3] = {(double)a[0] - b[0], (double)a[1] - b[1], (double)a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static sw_status gather(const sw_seam_host *g, uint32_t s, long_surface *ls, sw_error *err)
{
    ls->surface = s;
    for (int a = 0; a < 2; a++)
        ls->coords[a] = malloc(((size_t)ls->points + 1) * sizeof *ls->coords[a]);
    if (!ls->coords[0] || !ls->coords[1])
        return sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory cutting surface %u", s);
    size_t n = 0;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        for (uint32_t i = 0; i < loop->slot_count; i++) {
            const sw_seam_slot *a = &g->slots[loop->first_slot + i];
            const sw_seam_slot *b = &g->slots[loop->first_slot + (i + 1) % loop->slot_count];
            ls->coords[0][n] = a->uv[0], ls->coords[1][n] = a->uv[1], n++;
            ls->length += dist(g->vertices[a->vertex].p, g->vertices[b->vertex].p);
        }
    }
    for (int a = 0; a < 2; a++)
        qsort(ls->coords[a], n, sizeof *ls->coords[a], by_value);
    return SW_OK;
}

/* The model-space length of the line where coordinate axis is at, across
 * the surface's whole domain (a bound of the cut inside the face). */
static double line_length(const sw_model_surface *s, int axis, double at)
{
    sw_nurbs_surface view = sw_model_surface_view(s);
    double lo = s->domain[2 * (1 - axis)], hi = s->domain[2 * (1 - axis) + 1], length = 0;
    sw_vec3 prev = {0, 0, 0};
    for (int i = 0; i <= ISO_SAMPLES; i++) {
        double t = lo + (hi - lo) * i / ISO_SAMPLES;
        sw_vec3 p = axis == 0 ? sw_nurbs_surface_point(&view, at, t)
                              : sw_nurbs_surface_point(&view, t, at);
        if (i)
            length += sw_v3_length(sw_v3_sub(p, prev));
        prev = p;
    }
    return length;
}

/* k - 1 lines along axis at the points' quantiles, each moved by shift
 * points; 0 when the points leave no room between two of them. */
static int choose_lines(const long_surface *ls, const sw_model_surface *s, int axis, int k,
                        int shift, double *at)
{
    const double *c = ls->coords[axis];
    size_t n = ls->points;
    for (int i = 1; i < k; i++) {
        long idx = (long)((double)i * (double)n / k) + shift;
        if (idx < 1)
            idx = 1;
        while ((size_t)idx < n && c[idx] == c[idx - 1])
            idx++;
        if ((size_t)idx >= n)
            return 0;
        at[i - 1] = 0.5 * (c[idx - 1] + c[idx]);
        if ((i > 1 && !(at[i - 1] > at[i - 2])) || !(at[i - 1] > s->domain[2 * axis]) ||
            !(at[i - 1] < s->domain[2 * axis + 1]))
            return 0;
    }
    return 1;
}

/* The largest piece's points, with those the lines add. */
static double score(const long_surface *ls, const sw_model_surface *s, int axis, int k,
                    const double *at)
{
    const double *c = ls->coords[axis];
    double density = ls->length > 0 ? ls->points / ls->length : 0, worst = 0;
    size_t from = 0;
    for (int i = 0; i < k; i++) {
        size_t to = from;
        while (to < ls->points && (i == k - 1 || c[to] < at[i]))
            to++;
        double added = 0;
        if (i > 0)
            added += density * line_length(s, axis, at[i - 1]);
        if (i < k - 1)
            added += density * line_length(s, axis, at[i]);
        worst = fmax(worst, (double)(to - from) + added);
        from = to;
    }
    return worst;
}

/* The pieces of one long surface (pieces: MAX_PIECES); 0 pieces when no
 * line could cut it. */
static sw_status cut_one(const sw_model *model, const long_surface *ls, sw_trim_set *pieces,
                         size_t *count, sw_error *err)
{
    const sw_model_surface *s = &model->surfaces[ls->surface];
    int k = (int)((ls->points + SW_SEAM_SPLIT_TARGET - 1) / SW_SEAM_SPLIT_TARGET);
    k = k < 2 ? 2 : k > MAX_PIECES ? MAX_PIECES : k;
    *count = 0;
    double at[2][MAX_PIECES];
    int ok[2], axis = -1;
    double best = INFINITY;
    for (int a = 0; a < 2; a++) {
        ok[a] = choose_lines(ls, s, a, k, 0, at[a]);
        double sc = ok[a] ? score(ls, s, a, k, at[a]) : INFINITY;
        if (sc < best)
            best = sc, axis = a;
    }
    if (axis < 0)
        return SW_OK;
    int step = (int)(ls->points / (8u * (uint32_t)k)) + 1;
    for (int t = 0; t < TRIES; t++) {
        int shift = (t + 1) / 2 * (t % 2 ? 1 : -1) * step;
        double lines[MAX_PIECES];
        if (!choose_lines(ls, s, axis, k, shift, lines))
            continue;
        memset(pieces, 0, (size_t)k * sizeof *pieces);
        sw_status st = sw_model_cut_surface(model, ls->surface, axis, lines, (size_t)k - 1,
                                            pieces, err);
        if (st == SW_OK) {
            *count = (size_t)k;
            return SW_OK;
        }
        if (st != SW_ERR_RANGE)
            return st;
    }
    return SW_OK;
}

static uint32_t surface_points(const sw_seam_host *g, uint32_t s)
{
    uint32_t n = 0;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        n += g->loops[l].slot_count;
    return n;
}

sw_status sw_seam_split_long(const sw_model *model, const sw_seam_host *seams, sw_model *out,
                             sw_seam_split_report *report, sw_error *err)
{
    memset(report, 0, sizeof *report);
    uint32_t surfaces = seams->surface_count < model->surface_count
                            ? seams->surface_count : (uint32_t)model->surface_count;
    size_t longs = 0;
    for (uint32_t s = 0; s < surfaces; s++)
        longs += surface_points(seams, s) > SW_SEAM_SPLIT_POINTS;
    if (longs == 0)
        return SW_OK;
    sw_model_cut *cuts = calloc(longs, sizeof *cuts);
    sw_trim_set *sets = calloc(longs * MAX_PIECES, sizeof *sets);
    sw_status st = cuts && sets ? SW_OK
                                : sw_error_set(err, SW_ERR_NO_MEMORY, "out of memory cutting "
                                               "%zu surfaces", longs);
    size_t n = 0;
    for (uint32_t s = 0, i = 0; st == SW_OK && s < surfaces; s++) {
        uint32_t points = surface_points(seams, s);
        if (points <= SW_SEAM_SPLIT_POINTS)
            continue;
        long_surface ls = {.points = points};
        size_t count = 0;
        st = gather(seams, s, &ls, err);
        if (st == SW_OK)
            st = cut_one(model, &ls, sets + (size_t)i * MAX_PIECES, &count, err);
        free(ls.coords[0]);
        free(ls.coords[1]);
        if (st == SW_OK && count == 0)
            report->uncut++;
        if (st != SW_OK || count == 0)
            continue;
        cuts[n++] = (sw_model_cut){s, sets + (size_t)i * MAX_PIECES, count};
        report->cut++;
        report->pieces += (uint32_t)count;
        i++;
    }
    if (st == SW_OK && n > 0)
        st = sw_model_split(model, cuts, n, out, err);
    for (size_t i = 0; sets && i < longs * MAX_PIECES; i++)
        sw_trim_set_free(&sets[i]);
    free(sets);
    free(cuts);
    if (st != SW_OK)
        report->cut = 0;
    return st;
}
