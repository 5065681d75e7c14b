/* SPDX-License-Identifier: MIT */
/* Shared between the steps of sewing (sw_sew.h): the driver
 * (sw_sew_polylines.c), projections (sw_sew_project.c), intervals
 * (sw_sew_intervals.c) and the merge into an sw_seam_host (sw_sew_merge.c). */
#ifndef SW_SEW_INTERNAL_H
#define SW_SEW_INTERNAL_H

#include <stdint.h>

#include "sw_sew.h"

/* Vertex v projected onto the edge starting at vertex e (of another loop),
 * its foot at parameter t along the edge (0 or 1: the end vertex itself). */
typedef struct sew_match {
    uint32_t v, e;
    uint32_t lv, le;   /* their loops; le is loop_count + the loop when e is on v's own
                          loop (a closed surface meeting itself: sewn as a pair of the
                          loop with a copy of it, see sew_project) */
    double t, dist;
    int used;
} sew_match;

/* A merge decided by an interval: vertex v with the foot of its match. */
typedef struct sew_join {
    uint32_t v, e;
    double t;
} sew_join;

typedef struct sew_state {
    const sw_seam_polylines *poly;
    double tol;              /* the sewing tolerance; a pair of vertices may be as far apart
                                as it or as both their gaps (sew_gap), whichever is more */
    double max_gap;          /* the largest sew_gap */
    uint32_t *vertex_loop;   /* per vertex */
    double *arc;             /* per vertex: arc length along its loop from the loop's start */
    sew_match *matches;
    size_t match_count, match_capacity;
    sew_join *joins;
    size_t join_count, join_capacity;
    size_t intervals;
    sw_error *err;
} sew_state;

/* The real loop of a match's loop id (sew_match.le). */
static inline uint32_t sew_real_loop(const sw_seam_polylines *poly, uint32_t loop)
{
    return loop >= poly->loop_count ? loop - (uint32_t)poly->loop_count : loop;
}

/* How far vertex v's border may stray from the file's edge (0 without gaps). */
static inline double sew_gap(const sw_seam_polylines *poly, uint32_t v)
{
    return poly->gap ? (double)poly->gap[v] : 0.0;
}

static inline uint32_t sew_next(const sw_seam_polylines *poly, uint32_t loop, uint32_t v)
{
    return v + 1 < poly->loop_start[loop + 1] ? v + 1 : (uint32_t)poly->loop_start[loop];
}

/* Step 1: fills matches. */
sw_status sew_project(sew_state *s);

/* Step 2: fills joins from the matches' intervals. */
sw_status sew_intervals(sew_state *s);

/* Step 3: the host arrays from the joins. */
sw_status sew_merge(sew_state *s, sw_seam_host *out, sw_sew_counts *counts);

/* Step 3b (sw_sew_tjunctions.c, called by sew_merge on its loops before the
 * vertices are numbered): T-junctions the intervals left open; *inserted
 * gets how many vertices went into other loops' edges or, where that would
 * have made a spike, merged into their neighbour. */
sw_status sew_insert_tjunctions(sew_state *s, sw_seam_host *h, size_t *inserted);

#endif
