/* SPDX-License-Identifier: MIT */
/* Runs of the loops during simplification (sw_seam_runs.h). */
#include "sw_seam_runs.h"

#include <math.h>
#include <stdlib.h>

#include "sw_math.h"

static void push_run(sw_seam_runs *r, uint32_t run)
{
    uint32_t v = r->runs[run].vertex;
    r->link[run] = r->first[v];
    r->first[v] = run;
}

/* One loop's runs, linked in a cycle; returns the runs made. */
static uint32_t loop_runs(sw_seam_runs *r, const sw_seam_host *g, uint32_t l, uint32_t at)
{
    const sw_seam_loop *loop = &g->loops[l];
    uint32_t n = loop->slot_count, start = 0;
    /* start at a slot whose predecessor shows another vertex */
    while (start < n && g->slots[loop->first_slot + start].vertex ==
                            g->slots[loop->first_slot + (start + n - 1) % n].vertex)
        start++;
    if (start == n)
        start = 0;
    uint32_t made = 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t slot = loop->first_slot + (start + i) % n;
        if (made && r->runs[at + made - 1].vertex == g->slots[slot].vertex)
            continue;
        r->runs[at + made] = (sw_seam_run){g->slots[slot].vertex, slot, at + made - 1, at + made + 1};
        r->loop_of[at + made] = l;
        made++;
    }
    r->runs[at].prev = at + made - 1;
    r->runs[at + made - 1].next = at;
    for (uint32_t i = 0; i < made; i++)
        push_run(r, at + i);
    r->loop_runs[l] = made;
    return made;
}

sw_status sw_seam_runs_init(sw_seam_runs *r, const sw_seam_host *g, uint32_t vertex_cap,
                            sw_error *err)
{
    *r = (sw_seam_runs){0};
    r->runs = malloc(((size_t)g->slot_count + 1) * sizeof *r->runs);
    r->link = malloc(((size_t)g->slot_count + 1) * sizeof *r->link);
    r->loop_of = malloc(((size_t)g->slot_count + 1) * sizeof *r->loop_of);
    r->first = malloc(((size_t)vertex_cap + 1) * sizeof *r->first);
    r->loop_runs = malloc(((size_t)g->loop_count + 1) * sizeof *r->loop_runs);
    r->near_cost = malloc(((size_t)vertex_cap + 1) * sizeof *r->near_cost);
    r->near_runs = malloc(((size_t)vertex_cap + 1) * sizeof *r->near_runs);
    r->near_stamp = calloc((size_t)vertex_cap + 1, sizeof *r->near_stamp);
    r->loop_stamp = calloc((size_t)g->loop_count + 1, sizeof *r->loop_stamp);
    r->loop_n1 = malloc(((size_t)g->loop_count + 1) * 3 * sizeof *r->loop_n1);
    if (!r->runs || !r->link || !r->loop_of || !r->first || !r->loop_runs || !r->near_cost ||
        !r->near_runs || !r->near_stamp || !r->loop_stamp || !r->loop_n1) {
        sw_seam_runs_free(r);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "seam simplify: out of memory");
    }
    r->loop_n2 = r->loop_n1 + g->loop_count + 1;
    r->loop_adj = r->loop_n2 + g->loop_count + 1;
    r->loop_count = g->loop_count;
    for (uint32_t v = 0; v < vertex_cap; v++)
        r->first[v] = SW_SEAM_NONE;
    uint32_t at = 0;
    for (uint32_t l = 0; l < g->loop_count; l++)
        at += loop_runs(r, g, l, at);
    sw_status st = sw_seam_runs_grid_init(r, g, at, err);
    if (st != SW_OK)
        sw_seam_runs_free(r);
    return st;
}

static double dist3(const float a[3], const float b[3])
{
    double dx = (double)a[0] - b[0], dy = (double)a[1] - b[1], dz = (double)a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Distance in (u, v) from p to the segment a-b; *len gets |a b|, *t the
 * segment parameter of the nearest point. */
static double uv_seg_dist(const float p[2], const float a[2], const float b[2], double *len,
                          double *t)
{
    double ab[2] = {(double)b[0] - a[0], (double)b[1] - a[1]};
    double ap[2] = {(double)p[0] - a[0], (double)p[1] - a[1]};
    double len2 = ab[0] * ab[0] + ab[1] * ab[1];
    *t = len2 > 0 ? fmin(fmax((ap[0] * ab[0] + ap[1] * ab[1]) / len2, 0.0), 1.0) : 0.0;
    *len = sqrt(len2);
    return hypot(ap[0] - *t * ab[0], ap[1] - *t * ab[1]);
}

/* Distance from p to the model-space segment a-b. */
static double seg_dist3(const double p[3], const float a[3], const float b[3])
{
    return sw_v3_segment_distance(sw_v3(p[0], p[1], p[2]), sw_v3(a[0], a[1], a[2]),
                                  sw_v3(b[0], b[1], b[2]));
}

/* The surface along the (u, v) chord a-b against the model-space chord
 * pa-pb, at the quarters and at t. */
static double chord_stray(const sw_seam_runs *r, uint32_t surface, const float a[2],
                          const float b[2], const float pa[3], const float pb[3], double t)
{
    const double at[4] = {0.25, 0.5, 0.75, t};
    double worst = 0;
    for (int i = 0; i < 4; i++) {
        double q[3];
        r->eval->point(r->eval->ctx, surface, a[0] + at[i] * ((double)b[0] - a[0]),
                       a[1] + at[i] * ((double)b[1] - a[1]), q);
        worst = fmax(worst, seg_dist3(q, pa, pb));
    }
    return worst;
}

/* The cost at one run of v1 (see the header); with bound set, 0 where the
 * surface would be sampled (a lower bound: the stray is a distance). */
static double run_cost(const sw_seam_runs *r, const sw_seam_host *g, uint32_t n, uint32_t v2,
                       int bound)
{
    const sw_seam_run *run = &r->runs[n], *p = &r->runs[run->prev], *q = &r->runs[run->next];
    const sw_seam_vertex *vx = g->vertices;
    if (p->vertex != v2 && q->vertex != v2)
        return dist3(vx[run->vertex].p, vx[v2].p);
    if (r->loop_runs[r->loop_of[n]] < 4)
        return 0.0; /* the loop vanishes: nothing left to stray */
    /* merged: the run it joins and the other side's run span the new chord */
    const sw_seam_run *m = p->vertex == v2 ? p : q;
    const sw_seam_run *o = p->vertex == v2 ? (q->vertex == v2 ? &r->runs[q->next] : q) : p;
    if (r->eval && bound)
        return 0.0;
    const float *uv_m = g->slots[m->slot].uv, *uv_o = g->slots[o->slot].uv;
    double len, t, off = uv_seg_dist(g->slots[run->slot].uv, uv_m, uv_o, &len, &t);
    if (r->eval)
        return chord_stray(r, g->loops[r->loop_of[n]].surface, uv_m, uv_o, vx[v2].p,
                           vx[o->vertex].p, t);
    return len > 0 ? off * dist3(vx[v2].p, vx[o->vertex].p) / len : 0.0;
}

static double runs_cost(const sw_seam_runs *r, const sw_seam_host *g, uint32_t v1, uint32_t v2,
                        int bound)
{
    double cost = 0.0;
    for (uint32_t n = r->first[v1]; n != SW_SEAM_NONE; n = r->link[n])
        cost = fmax(cost, run_cost(r, g, n, v2, bound));
    return cost;
}

double sw_seam_runs_cost(const sw_seam_runs *r, const sw_seam_host *g, uint32_t v1, uint32_t v2)
{
    return runs_cost(r, g, v1, v2, 0);
}

double sw_seam_runs_cost_bound(const sw_seam_runs *r, const sw_seam_host *g, uint32_t v1,
                               uint32_t v2)
{
    return runs_cost(r, g, v1, v2, 1);
}

/* Counts run n (of the gathered vertex) next to x, at cost c. */
static void near_add(sw_seam_runs *r, uint32_t x, double c)
{
    if (r->near_stamp[x] != r->stamp) {
        r->near_stamp[x] = r->stamp;
        r->near_runs[x] = 0;
        r->near_cost[x] = 0.0;
    }
    r->near_runs[x]++;
    r->near_cost[x] = fmax(r->near_cost[x], c);
}

void sw_seam_runs_gather(sw_seam_runs *r, const sw_seam_host *g, uint32_t v1, int exact)
{
    if (++r->stamp == 0) { /* wrapped: no stale stamp may read as current */
        for (uint32_t v = 0; v < g->vertex_count; v++)
            r->near_stamp[v] = 0;
        r->stamp = 1;
    }
    r->gathered_runs = 0;
    for (uint32_t n = r->first[v1]; n != SW_SEAM_NONE; n = r->link[n]) {
        uint32_t p = r->runs[r->runs[n].prev].vertex, q = r->runs[r->runs[n].next].vertex;
        r->gathered_runs++;
        near_add(r, p, run_cost(r, g, n, p, !exact));
        if (q != p)
            near_add(r, q, run_cost(r, g, n, q, !exact));
    }
}

double sw_seam_runs_cost_to(const sw_seam_runs *r, const sw_seam_host *g, uint32_t v1,
                            uint32_t v2)
{
    int near = r->near_stamp[v2] == r->stamp;
    uint32_t next_to = near ? r->near_runs[v2] : 0;
    /* the runs not next to v2 stay at v1's (u, v) and move by |v1 v2| */
    double cost = next_to < r->gathered_runs ? dist3(g->vertices[v1].p, g->vertices[v2].p) : 0.0;
    return near ? fmax(cost, r->near_cost[v2]) : cost;
}

int sw_seam_runs_pinch(sw_seam_runs *r, uint32_t v1, uint32_t v2)
{
    if (++r->pinch_stamp == 0) { /* wrapped: no stale stamp may read as current */
        for (uint32_t l = 0; l < r->loop_count; l++)
            r->loop_stamp[l] = 0;
        r->pinch_stamp = 1;
    }
    const uint32_t s = r->pinch_stamp;
    for (uint32_t n = r->first[v1]; n != SW_SEAM_NONE; n = r->link[n]) {
        uint32_t l = r->loop_of[n];
        if (r->loop_stamp[l] != s)
            r->loop_stamp[l] = s, r->loop_n1[l] = r->loop_n2[l] = r->loop_adj[l] = 0;
        r->loop_n1[l]++;
    }
    for (uint32_t m = r->first[v2]; m != SW_SEAM_NONE; m = r->link[m]) {
        uint32_t l = r->loop_of[m], p = r->runs[m].prev, q = r->runs[m].next;
        if (r->loop_stamp[l] != s)
            continue;   /* v1 is not in this loop: nothing to meet */
        r->loop_n2[l]++;
        r->loop_adj[l] += (r->runs[p].vertex == v1) + (q != p && r->runs[q].vertex == v1);
    }
    for (uint32_t m = r->first[v2]; m != SW_SEAM_NONE; m = r->link[m]) {
        uint32_t l = r->loop_of[m];
        if (r->loop_stamp[l] != s)
            continue;
        uint32_t n1 = r->loop_n1[l], n2 = r->loop_n2[l], adj = r->loop_adj[l];
        uint32_t after = n1 + n2 > adj ? n1 + n2 - adj : 0;
        if (after > (n1 > n2 ? n1 : n2))
            return 1;
    }
    return 0;
}

static void unlink_run(sw_seam_runs *r, uint32_t n)
{
    sw_seam_run *run = &r->runs[n];
    r->runs[run->prev].next = run->next;
    r->runs[run->next].prev = run->prev;
    r->loop_runs[r->loop_of[n]]--;
    run->vertex = SW_SEAM_NONE;
}

void sw_seam_runs_collapse(sw_seam_runs *r, uint32_t v1, uint32_t v2, uint32_t vn)
{
    /* v1's runs next to a run of v2 join it (v2's (u, v) wins, as at run
     * time); the rest of v1's and all of v2's now show vn */
    for (uint32_t n = r->first[v1]; n != SW_SEAM_NONE; n = r->link[n]) {
        sw_seam_run *run = &r->runs[n];
        uint32_t p = run->prev, q = run->next;
        if (r->runs[p].vertex != v2 && r->runs[q].vertex != v2)
            continue;
        unlink_run(r, n);
        if (r->runs[p].vertex == v2 && r->runs[q].vertex == v2 && p != q)
            unlink_run(r, q); /* v2, v1, v2: one run, at the first's (u, v) */
    }
    uint32_t list = SW_SEAM_NONE;
    for (int side = 0; side < 2; side++)
        for (uint32_t n = r->first[side ? v2 : v1], next; n != SW_SEAM_NONE; n = next) {
            next = r->link[n];
            if (r->runs[n].vertex == SW_SEAM_NONE)
                continue;
            r->runs[n].vertex = vn;
            r->link[n] = list;
            list = n;
        }
    r->first[v1] = r->first[v2] = SW_SEAM_NONE;
    r->first[vn] = list;
}

void sw_seam_runs_free(sw_seam_runs *r)
{
    free(r->runs);
    free(r->link);
    free(r->loop_of);
    free(r->first);
    free(r->loop_runs);
    free(r->near_cost);
    free(r->near_runs);
    free(r->near_stamp);
    free(r->loop_stamp);
    free(r->loop_n1);
    free(r->grids);
    free(r->cell_start);
    free(r->cell_runs);
    *r = (sw_seam_runs){0};
}
