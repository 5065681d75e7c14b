/* The invariants every original Seam Graph (sw_seam_host, before any
 * collapse) must meet, for the sewing tests (test_seam_sew.c,
 * test_seam_sew_repairs.c). */
#ifndef SW_TEST_SEAM_HOST_CHECK_H
#define SW_TEST_SEAM_HOST_CHECK_H

#include <stdint.h>
#include <stdlib.h>

#include "sw_seam_build.h"
#include "sw_test.h"

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
}

#endif
