/* SPDX-License-Identifier: MIT */
#include "sw_seam_surface.h"

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
