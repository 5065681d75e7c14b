/* Independent measurement of what a frame drew: the screen-space error of the
 * tessellation against the exact surface, and cracks between patches that
 * share a boundary. It re-runs the same deterministic tessellation the frame
 * drew into scratch buffers (so it sees exactly the drawn vertices) and is
 * run every K-th frame because it costs more than drawing. No allocation. */
#ifndef SW_MEASURE_H
#define SW_MEASURE_H

#include <stdint.h>

#include "sw_stats.h"
#include "sw_walk.h"

typedef struct sw_measure {
    sw_vertex *grid_a, *grid_b;   /* SW_BATCH_VERTICES each */
    uint16_t *indices;            /* SW_BATCH_INDICES */
    double crack_tolerance;       /* 1e-6 of the model's box diagonal */
} sw_measure;

size_t sw_measure_arena_bytes(void);
sw_status sw_measure_init(sw_measure *m, sw_arena *arena, const sw_pack *pack, sw_error *err);

/* For every drawn triangle: the exact surface at the parametric centroid and
 * the edge midpoints against the flat triangle at the same barycentric
 * points, projected to pixels at the point's eye-space depth. Every sample
 * goes into the stats' histogram. */
void sw_measure_error(sw_measure *m, const sw_walk *walk, const sw_view *view, sw_stats *stats);

/* For every adjacent pair that is drawn: boundary vertices of either side
 * that do not lie on the other side's tessellated boundary polyline within
 * the crack tolerance. */
uint64_t sw_measure_cracks(sw_measure *m, const sw_walk *walk);

#endif
