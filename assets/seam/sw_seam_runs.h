/* SPDX-License-Identifier: MIT */
/* The loops' current polylines while the collapse hierarchy is built
 * (assets/seam/sw_seam_simplify.c), as the runtime will draw them
 * (core/sw_seam_select.h): per loop a cyclic list of runs, each showing one
 * live vertex at the (u, v) of one of its slots. The simplifier asks what a
 * collapse would do in parameter space, which its model-space error cannot
 * see: a border that is straight in space but curved in (u, v) (a planar
 * cut through a helical surface, the screw's ends) loses its curve when
 * collapsed at no model-space cost, and the tessellation, which fills the
 * region inside the (u, v) polyline, then draws the triangles along it far
 * off the surface. */
#ifndef SW_SEAM_RUNS_H
#define SW_SEAM_RUNS_H

#include "sw_seam_build.h"

typedef struct sw_seam_run {
    uint32_t vertex;     /* the live vertex the run shows */
    uint32_t slot;       /* the slot whose (u, v) it is drawn at */
    uint32_t prev, next; /* neighbouring runs of its loop */
} sw_seam_run;

/* The exact surface, where the caller has it: point of surface s at (u, v)
 * in the loops' parameter space. */
typedef struct sw_seam_surface_eval {
    void (*point)(void *ctx, uint32_t surface, double u, double v, double out[3]);
    void *ctx;
} sw_seam_surface_eval;

/* One surface's grid of run points in (u, v) (sw_seam_runs_crosses). */
typedef struct sw_seam_uv_grid {
    double box[4];       /* u0, u1, v0, v1 of its runs */
    uint32_t side;       /* cells a side */
    uint32_t first_cell; /* its cells in cell_start */
    uint32_t points;     /* its runs */
} sw_seam_uv_grid;

typedef struct sw_seam_runs {
    const sw_seam_surface_eval *eval; /* NULL: the cost is estimated (below) */
    sw_seam_run *runs;   /* at most one per slot */
    uint32_t *first;     /* per vertex: its runs are first[v] .. via link */
    uint32_t *link;      /* per run: the vertex's next run, SW_SEAM_NONE at the end */
    uint32_t *loop_runs; /* per loop: how many runs are left */
    uint32_t *loop_of;   /* per run: its loop */
    /* sw_seam_runs_gather's answer, per vertex next to the gathered one:
     * valid where near_stamp equals stamp */
    double *near_cost;   /* the largest cost of the runs next to it */
    uint32_t *near_runs; /* how many of the gathered vertex's runs it is next to */
    uint32_t *near_stamp;
    uint32_t stamp, gathered_runs; /* gathered_runs: all runs of the gathered vertex */
    /* sw_seam_runs_pinch's counts, per loop: valid where loop_stamp is pinch_stamp */
    uint32_t *loop_stamp, *loop_n1, *loop_n2, *loop_adj;
    uint32_t pinch_stamp, loop_count;
    /* per surface, its run points by grid cell: runs cell_runs[cell_start[c]
     * .. cell_start[c + 1]) (dead ones included) */
    sw_seam_uv_grid *grids;
    uint32_t *cell_start, *cell_runs;
} sw_seam_runs;

/* Runs of graph's original loops: consecutive slots of one vertex are one
 * run, at the first slot's (u, v). vertex_cap: the vertices the hierarchy
 * will have (original_count * 2). SW_ERR_NO_MEMORY when malloc fails. */
sw_status sw_seam_runs_init(sw_seam_runs *r, const sw_seam_host *graph, uint32_t vertex_cap,
                            sw_error *err);

/* The parameter-space cost of collapsing v1 into v2, in model units, over
 * the loops where v1 shows. Where its run merges into a neighbouring run of
 * v2: how far the surface along the new (u, v) chord strays from the new
 * model-space chord, sampled at a quarter, half and three quarters of it
 * and where v1's (u, v) projects onto it, when r->eval is set; else
 * estimated as the distance of v1's (u, v) from the chord times the chord's
 * model-space length per unit of (u, v) (blind to a surface whose scale
 * across the chord is larger than along it). Where v2 is not next to it,
 * the run stays at v1's (u, v) but moves to v2's position: |v1 v2|. */
double sw_seam_runs_cost(const sw_seam_runs *r, const sw_seam_host *graph, uint32_t v1,
                         uint32_t v2);

/* A lower bound of sw_seam_runs_cost without evaluating the surface: the
 * same where v2 is not next to v1's run or r->eval is unset, 0 for a run
 * whose cost would be sampled on the surface. */
double sw_seam_runs_cost_bound(const sw_seam_runs *r, const sw_seam_host *graph, uint32_t v1,
                               uint32_t v2);

/* sw_seam_runs_cost (exact 1) or sw_seam_runs_cost_bound (exact 0) of
 * collapsing v1 into each vertex next to one of its runs, in one pass over
 * v1's runs, read back with sw_seam_runs_cost_to. A vertex of many runs and
 * many neighbours (a sewn hub) costs its runs once, not once per neighbour. */
void sw_seam_runs_gather(sw_seam_runs *r, const sw_seam_host *graph, uint32_t v1, int exact);

/* The cost of collapsing the gathered vertex v1 into v2 (the same value as
 * sw_seam_runs_cost or _bound would give). */
double sw_seam_runs_cost_to(const sw_seam_runs *r, const sw_seam_host *graph, uint32_t v1,
                            uint32_t v2);

/* Would collapsing v1 into v2 pinch a loop: leave the new vertex with more
 * runs in some loop than v1 or v2 had there? Two stretches of the loop
 * would meet at one vertex, and the loop's (u, v) polyline, which keeps
 * each run's own (u, v), would fold or cross there at every coarser state
 * (a thin face's two sides, sewn across its width through a neighbour).
 * A vertex that already stood twice in a loop (a periodic seam, a slit)
 * may go on doing so. O(runs of v1 and v2). */
int sw_seam_runs_pinch(sw_seam_runs *r, uint32_t v1, uint32_t v2);

/* Would collapsing v1 into v2 make a loop of some surface cross or touch
 * itself or another of the surface's loops in (u, v)? Where a run of v1
 * merges into v2's, the triangle its point leaves must hold no other run
 * point of the surface (sw_seam_runs_cross.c says why that suffices when
 * nothing crossed before). The runtime tessellates inside these polylines
 * and refuses loops that cross: a zigzag border, simplified, cut across a
 * thin face's other side at every coarser state. */
int sw_seam_runs_crosses(const sw_seam_runs *r, const sw_seam_host *graph, uint32_t v1,
                         uint32_t v2);

/* The grids sw_seam_runs_crosses reads, over the first run_count runs
 * (sw_seam_runs_init calls it). SW_ERR_NO_MEMORY. */
sw_status sw_seam_runs_grid_init(sw_seam_runs *r, const sw_seam_host *graph, uint32_t run_count,
                                 sw_error *err);

/* Applies collapse v1 -> v2 into vn (vn's position is v2's). */
void sw_seam_runs_collapse(sw_seam_runs *r, uint32_t v1, uint32_t v2, uint32_t vn);

void sw_seam_runs_free(sw_seam_runs *r);

#endif
