/* Structural checks of a Seam Graph (sw_seam_graph.h) before anyone indexes
 * into it: the runtime selection checks a graph from a pack before it builds
 * its state, and the host simplifier checks the sewing's output. No memory:
 * one pass over the arrays, so it runs in the runtime too.
 *
 * What it checks (each failure names the record and the field):
 * - counts agree (vertex_count == original_count + collapse_count), arrays
 *   are present where their counts are not zero, surface_loops has
 *   surface_count + 1 entries from 0 to loop_count, rising, and every loop
 *   lies in the range of its surface;
 * - loops have at least three slots, lie inside slots, and come in slot
 *   order without overlapping (every builder appends loops' slots in loop
 *   order; the runtime relies on each slot having at most one loop);
 * - slots name an original vertex, uv finite;
 * - vertices: finite positions and errors, reserved zero; an original sits in
 *   at least one slot and its slot_refs point back at slots holding it; a
 *   created vertex has no slot_refs; slot_ref_count == slot_count;
 * - the hierarchy: collapse k makes vertex original_count + k from two
 *   different older vertices whose child is exactly that vertex, every child
 *   link is such a collapse (so the links form a forest), errors are finite,
 *   non-negative and monotone (a created vertex's error is at least its
 *   collapse's and its parents');
 * - edges have a < b < original_count; tolerance finite and >= 0.
 * Not checked (needs scratch memory): a slot listed twice in slot_refs, and
 * whether edges match the loops (the simplifier checks that on the host). */
#ifndef SW_SEAM_CHECK_H
#define SW_SEAM_CHECK_H

#include "sw_error.h"
#include "sw_seam_graph.h"

/* SW_OK, or SW_ERR_FORMAT / SW_ERR_RANGE with the first problem in err. */
sw_status sw_seam_graph_check(const sw_seam_graph *graph, sw_error *err);

#endif
