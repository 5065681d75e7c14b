/* SPDX-License-Identifier: MIT */
#include "sw_seam_border.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static int compare_pairs(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return a < b ? -1 : a > b;
}

static double distance(const sw_seam_graph *g, uint32_t a, uint32_t b)
{
    const float *p = g->vertices[a].p, *q = g->vertices[b].p;
    double dx = (double)p[0] - q[0], dy = (double)p[1] - q[1], dz = (double)p[2] - q[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

sw_status sw_seam_border_measure(const sw_seam_graph *g, sw_seam_border *out, sw_error *err)
{
    *out = (sw_seam_border){0};
    uint64_t *pairs = malloc(((size_t)g->slot_count + 1) * sizeof *pairs);
    if (!pairs)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "border length: out of memory for %u slots",
                            (unsigned)g->slot_count);
    size_t n = 0;
    for (uint32_t l = 0; l < g->loop_count; l++) {
        const sw_seam_loop *loop = &g->loops[l];
        for (uint32_t i = 0; i < loop->slot_count; i++) {
            uint32_t a = g->slots[loop->first_slot + i].vertex;
            uint32_t b = g->slots[loop->first_slot + (i + 1) % loop->slot_count].vertex;
            if (a == b)
                continue;
            uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
            pairs[n++] = (uint64_t)lo << 32 | hi;
        }
    }
    qsort(pairs, n, sizeof *pairs, compare_pairs);
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && pairs[j] == pairs[i])
            j++;
        double len = distance(g, (uint32_t)(pairs[i] >> 32), (uint32_t)pairs[i]);
        out->length += len * (double)(j - i);
        out->edge_uses += j - i;
        if (j - i == 1) {
            out->free_length += len;
            out->free_edges++;
        }
        i = j;
    }
    free(pairs);
    return SW_OK;
}
