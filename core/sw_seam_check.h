/* SPDX-License-Identifier: MIT */
/* Every rule of a Seam Graph (sw_seam_graph.h), checked before anyone
 * indexes into it: the pack reader calls it for a pack's graph (after the
 * SEAM header record, sw_pack_validate_seam), the runtime selection for the
 * graph it is given, the host simplifier for the sewing's output. One pass
 * over the arrays (in parts that may run at once: sw_seam_graph_check_with),
 * no memory, so it runs in the runtime too. The rules are
 * listed in assets/PACK_FORMAT.md; in short:
 * - counts agree (vertex_count == original_count + collapse_count,
 *   slot_ref_count == slot_count), arrays present where their counts are not
 *   zero, finite positions, errors and uv, reserved fields zero;
 * - the hierarchy: collapse k makes vertex original_count + k from two
 *   different older vertices whose child is exactly that vertex and whose
 *   position it copies from v2; every child link is such a collapse (a
 *   forest, links only to larger indices); original errors are 0 and errors
 *   never drop towards the roots;
 * - every slot names an original vertex; every original vertex sits in at
 *   least one slot, and its slot_refs are one run, in vertex order, of the
 *   slots holding it in increasing order (so slot_refs are exactly the
 *   inverse of slots);
 * - surface_loops rises from 0 to loop_count, every loop lies in its
 *   surface's range, has at least three slots, and the loops tile the slots
 *   in order;
 * - edges have a < b < original_count.
 * Not checked (needs scratch memory): whether edges match the loops (the
 * simplifier checks that on the host). */
#ifndef SW_SEAM_CHECK_H
#define SW_SEAM_CHECK_H

#include "sw_error.h"
#include "sw_parts.h"
#include "sw_seam_graph.h"

/* SW_OK, or SW_ERR_FORMAT / SW_ERR_RANGE with the first problem in err. */
sw_status sw_seam_graph_check(const sw_seam_graph *graph, sw_error *err);

/* The same check in parts, run by runner (sw_parts.h; NULL: in order on
 * this thread); the same result and message whatever the runner. */
sw_status sw_seam_graph_check_with(const sw_seam_graph *graph, const sw_parts_runner *runner,
                                   sw_error *err);

#endif
