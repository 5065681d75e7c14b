/* SPDX-License-Identifier: MIT */
/* The seam front of a placed scene (sw_pack_instances.h) as one front per
 * instance: instance k's front is a sw_seam_select over its prototype's
 * Seam Graph, renumbered from 0 (its positions and errors the prototype's,
 * as stored), and every instance of a prototype shares that graph and its
 * topology (sw_seam_topology). What grows with the placements is then the
 * fronts' own state (sw_seam_select_front_bytes), not the graph, the
 * topology and the state of every copy, as a select over the expanded
 * scene (sw_pack_expand_shared) holds them.
 *
 * Ids in and out are the placed scene's, as sw_pack_expand_shared numbers
 * them: instance k's surfaces, loops, originals and created vertices are
 * its prototype's local ones plus k's first in each space (instance k adds
 * its prototype's counts). An instance's errors are the prototype's, so
 * its bounds are divided by the instance's scale. The placed graph is
 * read only to answer in placed ids where a caller needs its positions.
 *
 * A front of a pack without instances is one front over the pack's own
 * graph. Memory from the arena at init; not thread-safe: one owner, as
 * sw_seam_select (the workers read loops between updates). */
#ifndef SW_SEAM_FRONTS_H
#define SW_SEAM_FRONTS_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_pack.h"
#include "sw_seam_select.h"
#include "sw_seam_surface.h"

/* A prototype's graph renumbered from 0, and its topology. */
typedef struct sw_seam_part_graph {
    sw_seam_graph graph;
    sw_seam_topology topology;
} sw_seam_part_graph;

typedef struct sw_seam_fronts {
    sw_seam_graph placed;          /* the scene's counts (and arrays, when given) */
    uint32_t part_count;           /* prototypes (1 for one front) */
    sw_seam_part_graph *parts;
    sw_seam_select_scratch scratch;/* every front's: they are updated one at a time */
    uint32_t count;                /* fronts: instances (1 for one front) */
    sw_seam_select *front;         /* count */
    uint32_t *part_of;             /* count: its prototype */
    double *scale;                 /* count: its transform's scale */
    /* count + 1 each: instance k's first surface, loop, original and
     * created vertex (an index into the collapses) in the placed scene */
    uint32_t *first_surface, *first_loop, *first_original, *first_created;
    const sw_pack_instance *instances; /* count: where they place the prototypes' graphs
                                      (NULL for one front: the placed graph's own) */
    uint32_t *instance_of;         /* placed surface -> instance (NULL for one front) */
    float *bound;                  /* the largest prototype's surfaces: an instance's bounds
                                      over its scale while it is updated (NULL for one
                                      front) */
    uint32_t *shown;               /* placed originals: every front's shown, instance by
                                      instance (front k's from first_original[k]) */
    uint32_t active_count;         /* on all fronts */
    /* One front's tables, kept here rather than in the arena, so one front
     * takes what one select takes (sw_seam_select_arena_bytes): */
    sw_seam_part_graph one_part;
    sw_seam_select one_front;
    uint32_t one_part_of, one_first[4][2];
    double one_scale;
} sw_seam_fronts;

/* Arena bytes sw_seam_fronts_init takes for a validated pack (with a Seam
 * Graph), worst case. For a pack without instances, one select over its
 * graph. For a placed one, the fewer of: a front per instance (each
 * prototype's graph copied and its topology, each instance's front state
 * and shown vertices, one scratch, the tables) and one front over the
 * placed graph (what a select over the expanded scene takes: a scene
 * that repeats little pays more for the copies than it saves).
 * *per_instance (may be NULL) says which. */
size_t sw_seam_fronts_bytes(const sw_pack_prototype *prototypes, uint32_t prototype_count,
                            const sw_pack_instance *instances, uint32_t instance_count,
                            int *per_instance);
size_t sw_seam_fronts_arena_bytes(const sw_pack *pack);

/* The bytes of one layout: per_instance 1 a front per instance, 0 one
 * front over the placed graph (tests compare the two). */
size_t sw_seam_fronts_layout_bytes(const sw_pack_prototype *prototypes,
                                   uint32_t prototype_count, const sw_pack_instance *instances,
                                   uint32_t instance_count, int per_instance);

/* The fronts of pack (validated, with a Seam Graph), at the coarsest
 * front; placed: the placed scene's graph whose ids callers use (its
 * counts must be those the instances add up to), or the pack's own graph
 * without instances. SW_ERR_NO_MEMORY when the arena is too small,
 * SW_ERR_FORMAT when placed does not match the instances. Not to be moved
 * or copied after (it points into itself). */
sw_status sw_seam_fronts_init(sw_seam_fronts *f, const sw_pack *pack, const sw_seam_graph *placed,
                              sw_arena *arena, sw_error *err);

/* The same in the layout per_instance says (sw_seam_fronts_layout_bytes);
 * SW_ERR_ARG for a front per instance of a pack without instances. */
sw_status sw_seam_fronts_init_layout(sw_seam_fronts *f, const sw_pack *pack,
                                     const sw_seam_graph *placed, int per_instance,
                                     sw_arena *arena, sw_error *err);

/* Moves every front for the placed surfaces' bounds (sw_seam_select_update
 * with no cap, instance by instance); *result (may be NULL) the sums. */
sw_status sw_seam_fronts_update(sw_seam_fronts *f, const float *surface_bound,
                                sw_seam_update_result *result, sw_error *err);

/* Placed surface s's loops changed since the last clear. */
int sw_seam_fronts_surface_changed(const sw_seam_fronts *f, uint32_t s);
void sw_seam_fronts_clear_changed(sw_seam_fronts *f);

/* The instance of placed surface s and of placed original o. */
uint32_t sw_seam_fronts_instance_of(const sw_seam_fronts *f, uint32_t s);
uint32_t sw_seam_fronts_instance_at(const sw_seam_fronts *f, uint32_t o);

/* A vertex of instance k: its placed id from its local one, and back. */
uint32_t sw_seam_fronts_placed(const sw_seam_fronts *f, uint32_t k, uint32_t local);
uint32_t sw_seam_fronts_local(const sw_seam_fronts *f, uint32_t k, uint32_t placed);

/* Placed surface s's loops at its front, as sw_seam_surface_loops gives
 * them (pin in the scene's units), each point's id and position the
 * placed scene's vertex (f->placed's arrays). */
int sw_seam_fronts_surface_loops(const sw_seam_fronts *f, uint32_t s, float pin,
                                 const sw_seam_surface_buffers *buf, sw_trim_loops *loops,
                                 uint32_t *outer);

/* The placed surfaces whose loops placed original o sits in, as
 * sw_seam_select_surfaces_at: *surfaces local to o's instance, to which
 * *first (its first surface) is added. */
uint32_t sw_seam_fronts_surfaces_at(const sw_seam_fronts *f, uint32_t o,
                                    const uint32_t **surfaces, uint32_t *first);

/* The vertex placed original o shows, placed: in the fronts (shown NULL),
 * or in a copy of f->shown (placed originals, as the fronts lay it out). */
uint32_t sw_seam_fronts_shown(const sw_seam_fronts *f, const uint32_t *shown, uint32_t o);

/* Placed vertex v as the placed scene has it, whether or not its arrays
 * hold it (sw_pack_expand_shared leaves them to the fronts): its position
 * (the prototype's placed by the instance, sw_instance_place) and its
 * error (the prototype's times the instance's scale). The same floats as
 * the expansion's copy. */
void sw_seam_fronts_position(const sw_seam_fronts *f, uint32_t v, float out[3]);
float sw_seam_fronts_error(const sw_seam_fronts *f, uint32_t v);

/* Placed vertex v's highest ancestor whose error is within (v itself
 * when its child's is not), placed, with one look for v's instance. */
uint32_t sw_seam_fronts_ancestor_within(const sw_seam_fronts *f, uint32_t v, float within);

/* The largest error of the originals placed surface s's loops start at
 * (placed: times the instance's scale), 0 for none. */
float sw_seam_fronts_loop_error(const sw_seam_fronts *f, uint32_t s);

/* The original sewn at slot k (0 .. slot_count - 1) of placed loop l. */
uint32_t sw_seam_fronts_slot_vertex(const sw_seam_fronts *f, uint32_t l, uint32_t k);

/* Placed surface s's sewing offset (sw_seam_sewing_offset) against its
 * placed patches. */
double sw_seam_fronts_sewing_offset(const sw_seam_fronts *f, uint32_t s,
                                    const sw_trim_patch *patches, uint32_t patch_count);

/* In such a copy: o shows placed vertex v (o's or an ancestor of it). */
void sw_seam_fronts_set_shown(const sw_seam_fronts *f, uint32_t *shown, uint32_t o, uint32_t v);

/* Placed loop l's polyline as sw_seam_select_loop_slots gives it (pin in
 * the scene's units), its fronts' shown vertices, or those of a copy of
 * f->shown; the points' vertices placed. */
sw_status sw_seam_fronts_loop_slots(const sw_seam_fronts *f, const uint32_t *shown, uint32_t l,
                                    float pin, sw_seam_point *points, uint32_t *slots,
                                    uint32_t capacity, uint32_t *count, int *vanished,
                                    sw_error *err);

#endif
