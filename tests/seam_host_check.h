/* SPDX-License-Identifier: MIT */
/* The invariants every original Seam Graph (sw_seam_host, before any
 * collapse) must meet, for the sewing tests (test_seam_sew.c,
 * test_seam_sew_repairs.c). */
#ifndef SW_TEST_SEAM_HOST_CHECK_H
#define SW_TEST_SEAM_HOST_CHECK_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "sw_seam_build.h"
#include "sw_test.h"

/* Is vertex v in a slot of a loop other than the one at slots
 * [first, first + n)? */
static inline int host_in_other_loop(const sw_seam_host *h, uint32_t v, uint32_t first, uint32_t n)
{
    const sw_seam_vertex *x = &h->vertices[v];
    for (uint32_t r = 0; r < x->slot_ref_count; r++) {
        uint32_t slot = h->slot_refs[x->first_slot_ref + r];
        if (slot < first || slot >= first + n)
            return 1;
    }
    return 0;
}

/* The largest side of loop lp's (u, v) box. */
static inline double host_loop_extent(const sw_seam_host *h, const sw_seam_loop *lp)
{
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (uint32_t k = lp->first_slot; k < lp->first_slot + lp->slot_count; k++)
        for (int c = 0; c < 2; c++) {
            box[2 * c] = fmin(box[2 * c], h->slots[k].uv[c]);
            box[2 * c + 1] = fmax(box[2 * c + 1], h->slots[k].uv[c]);
        }
    return fmax(box[1] - box[0], box[3] - box[2]);
}

/* One-sided spikes: a loop running x, a, x (runs of one vertex counted
 * once) with a in no other loop goes out to a and back, a on one side of
 * its seam only: a gap point in the drawn seams (the boxed sphere's fillet
 * tip before the T-junction step merged such an a into x). A spike both
 * sides share (a sewn fold, as at the teaspoon's tip) is no gap; nor is a
 * closed face's seam line sewn to itself up to a point (a cone's apex: the
 * loop leaves x and comes back to it a quarter of its extent away in
 * (u, v), up one side of the seam and down the other). */
static inline uint32_t host_spikes(const sw_seam_host *h)
{
    uint32_t spikes = 0;
    for (uint32_t l = 0; l < h->loop_count; l++) {
        const sw_seam_loop *lp = &h->loops[l];
        uint32_t n = lp->slot_count, ring[3] = {SW_SEAM_NONE, SW_SEAM_NONE, SW_SEAM_NONE};
        uint32_t at[3] = {0, 0, 0};   /* the slots of the ring's vertices */
        double across = 0.25 * host_loop_extent(h, lp);
        /* Twice round: the second pass counts, the spikes across the start too. */
        for (uint32_t k = 0; k < 2 * n; k++) {
            uint32_t slot = lp->first_slot + k % n, v = h->slots[slot].vertex;
            if (v == ring[2])
                continue;
            ring[0] = ring[1], ring[1] = ring[2], ring[2] = v;
            at[0] = at[1], at[1] = at[2], at[2] = slot;
            const float *p = h->slots[at[0]].uv, *q = h->slots[at[2]].uv;
            int seam = hypot((double)p[0] - q[0], (double)p[1] - q[1]) > across;
            spikes += k >= n && ring[0] == ring[2] && !seam &&
                      !host_in_other_loop(h, ring[1], lp->first_slot, n);
        }
    }
    return spikes;
}

/* Every invariant of sw_seam_host an original graph must meet. */
static inline void check_host(const sw_seam_host *h)
{
    SW_CHECK(h->collapse_count == 0);
    SW_CHECK(h->vertex_count == h->original_count);
    SW_CHECK(h->slot_ref_count == h->slot_count);
    SW_CHECK(h->tolerance > 0);
    SW_CHECK(h->surface_loops[0] == 0 && h->surface_loops[h->surface_count] == h->loop_count);
    uint32_t slots = 0;
    for (uint32_t s = 0; s < h->surface_count; s++) {
        SW_CHECK(h->surface_loops[s] <= h->surface_loops[s + 1]);
        for (uint32_t l = h->surface_loops[s]; l < h->surface_loops[s + 1]; l++) {
            SW_CHECK(h->loops[l].surface == s);
            SW_CHECK(h->loops[l].first_slot == slots);
            SW_CHECK(h->loops[l].slot_count >= 3);
            slots += h->loops[l].slot_count;
        }
    }
    SW_CHECK(slots == h->slot_count);
    int bad_slot = 0, bad_ref = 0, bad_vertex = 0;
    for (uint32_t k = 0; k < h->slot_count; k++)
        bad_slot += h->slots[k].vertex >= h->vertex_count;
    uint32_t refs = 0;
    for (uint32_t v = 0; v < h->vertex_count; v++) {
        const sw_seam_vertex *x = &h->vertices[v];
        bad_vertex += x->child != SW_SEAM_NONE || x->error != 0 || x->reserved != 0 ||
                      x->slot_ref_count == 0 || x->first_slot_ref != refs;
        for (uint32_t r = 0; r < x->slot_ref_count && !bad_slot; r++)
            bad_ref += h->slots[h->slot_refs[x->first_slot_ref + r]].vertex != v;
        refs += x->slot_ref_count;
    }
    SW_CHECK(bad_slot == 0);
    SW_CHECK(bad_vertex == 0);
    SW_CHECK(bad_ref == 0);
    SW_CHECK(refs == h->slot_count);
    int bad_edge = 0;
    for (uint32_t e = 0; e < h->edge_count; e++) {
        const sw_seam_edge *x = &h->edges[e];
        bad_edge += !(x->a < x->b) || x->b >= h->vertex_count;
        if (e > 0) /* sorted and unique */
            bad_edge += !(h->edges[e - 1].a < x->a ||
                          (h->edges[e - 1].a == x->a && h->edges[e - 1].b < x->b));
    }
    SW_CHECK(bad_edge == 0);
    SW_CHECK(bad_ref == 0 && host_spikes(h) == 0);
}

#endif
