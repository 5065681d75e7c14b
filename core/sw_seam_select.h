/* SPDX-License-Identifier: MIT */
/* View-dependent level of detail of the Seam Graph (Guthe et al. 2002,
 * sections 5.5 and 6.1): the runtime's front of active vertices over the
 * collapse hierarchy of core/sw_seam_graph.h, moved by vertex splits and edge
 * collapses under El-Sana and Varshney's dependency rule, and the loops'
 * current polylines that the trimmed tessellation draws.
 *
 * The frame loop calls sw_seam_select_update once per frame with an error
 * bound per surface (model units, from the view: paper 6.1), then reads the
 * polylines of the surfaces it tessellates (sw_seam_select_loop) and the
 * surfaces whose loops changed (sw_seam_select_surface_changed). All memory
 * comes from the arena handed to init; nothing here calls malloc. Not
 * thread-safe: one owner.
 *
 * Cost: a split or collapse of v touches every slot of the original vertices
 * under v (their shown vertex changes), so it is O(slots under v), read as
 * contiguous ranges in leaf order (the hierarchy's chains make v's leaves
 * many: read scattered by vertex number, as the first version did, a split
 * near a root cost a cache miss per slot); an update
 * also makes one pass over all vertices and slots to fold the surface bounds
 * into per-vertex bounds (O(vertex_count + slot_count)). */
#ifndef SW_SEAM_SELECT_H
#define SW_SEAM_SELECT_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_seam_graph.h"

/* What a front reads of its graph and never changes: the originals in
 * leaf order and their slots in that order. Built once for a graph; every
 * front over that graph (the instances of one part) can share it. Fields
 * are the module's business. The graph's arrays must outlive it. */
typedef struct sw_seam_topology {
    sw_seam_graph graph;
    uint32_t *leaf_lo;         /* vertex_count: v's originals are leaf_order[leaf_lo[v] .. +leaf_count[v]) */
    uint32_t *leaf_count;      /* vertex_count */
    uint32_t *leaf_order;      /* original_count: originals in depth-first order, v2's side first */
    /* The slots of the originals in leaf order, so that everything a split
     * or collapse of v reads is the contiguous range of v's leaves: */
    uint32_t *leaf_slots;      /* original_count + 1: leaf position p's slots are entries
                                  leaf_slots[p] .. leaf_slots[p + 1] */
    uint32_t *slot_surface;    /* slot_count entries: the surface of the slot's loop */
    uint32_t *slot_prev;       /* slot_count entries: the leaf position of the original at the
                                  slot before it in its loop, and after it (cyclic) */
    uint32_t *slot_next;
} sw_seam_topology;

/* Arena bytes sw_seam_topology_init takes for graph, worst case: 8 bytes
 * per vertex, 8 more per original and 12 per slot. */
size_t sw_seam_topology_arena_bytes(const sw_seam_graph *graph);

/* Builds the topology of graph, which sw_seam_graph_check has passed, from
 * arena (and, for the while, scratch of 4 bytes an original past what it
 * keeps, given back). SW_ERR_RANGE for a graph too large to count,
 * SW_ERR_NO_MEMORY when the arena is too small. */
sw_status sw_seam_topology_init(sw_seam_topology *topology, const sw_seam_graph *graph,
                                sw_arena *arena, sw_error *err);

/* The state. Fields are the module's business; read them through the calls
 * below. The graph's arrays, and the topology's when it was shared, must
 * outlive the state (they are not copied). */
typedef struct sw_seam_select {
    sw_seam_graph graph;
    uint8_t *active;           /* vertex_count: 1 on the front */
    /* The topology's (sw_seam_topology, above): */
    const uint32_t *leaf_lo, *leaf_count, *leaf_order, *leaf_slots;
    const uint32_t *slot_surface, *slot_prev, *slot_next;
    uint32_t *shown;           /* original_count: the active ancestor of the original at each
                                  leaf position (a split fills a contiguous range) */
    float *bound;              /* vertex_count: the smallest surface bound over v's slots (per update) */
    uint32_t *stack, *queue;   /* the scratch's (sw_seam_select_scratch: maybe shared) */
    uint8_t *queued;
    uint8_t *surface_changed;  /* surface_count */
    /* What the next update starts from (sw_seam_select_update.c): */
    float *surface_bound;      /* surface_count: the bounds bound[] was folded from */
    uint32_t *seeds;           /* collapse_count + 1: collapses the next update tries (those
                                  the rule blocked in the last one, and more it adds) */
    uint8_t *seeded;           /* vertex_count: 1 while in seeds */
    uint32_t seed_count;
    int bounds_known;          /* 1: bound[] and seeds[] are the last complete update's and
                                  the front moved only through updates since */
    uint32_t queue_len;
    int queue_largest_first;
    uint32_t active_count;
} sw_seam_select;

/* Arena bytes sw_seam_select_init takes for graph, worst case (alignment
 * included): its topology's and its front's (below), 19 bytes per vertex,
 * 8 more per created vertex, 12 more per original, 12 per slot and 5 per
 * surface (about 82 bytes per original vertex of a sewn graph: 2 slots
 * each, as many created vertices). */
size_t sw_seam_select_arena_bytes(const sw_seam_graph *graph);

/* What an update works in and leaves as it found it (the heap, its flags
 * and the forced-split chain): fronts updated one after another can share
 * one, sized for the largest graph among them. */
typedef struct sw_seam_select_scratch {
    uint32_t *queue;           /* vertex_count: the update's work list (a heap) */
    uint8_t *queued;           /* vertex_count, all 0 between updates */
    uint32_t *stack;           /* collapse_count + 1: the forced-split chain */
    uint32_t vertex_count, collapse_count;
} sw_seam_select_scratch;

/* Arena bytes of a front over a shared topology (sw_seam_select_init_shared):
 * 6 bytes per vertex, 4 more per created vertex, 5 per surface; its shown
 * vertices, 4 bytes per original, when it takes them too; and its scratch,
 * 5 bytes per vertex and 4 per created one, when it is not shared. */
size_t sw_seam_select_front_bytes(const sw_seam_graph *graph);
size_t sw_seam_select_shown_bytes(const sw_seam_graph *graph);
size_t sw_seam_select_scratch_bytes(const sw_seam_graph *graph);

/* Scratch for fronts of graphs up to vertex_count vertices and
 * collapse_count collapses. SW_ERR_NO_MEMORY when the arena is too small. */
sw_status sw_seam_select_scratch_init(sw_seam_select_scratch *scratch, uint32_t vertex_count,
                                      uint32_t collapse_count, sw_arena *arena, sw_error *err);

/* A front over topology (its graph checked already), its own state from
 * arena, at the coarsest front; its shown vertices (original_count) in
 * shown, or from arena when NULL; its scratch scratch (large enough for
 * the graph), or from arena when NULL. SW_ERR_NO_MEMORY when the arena is
 * too small, SW_ERR_ARG for scratch too small. */
sw_status sw_seam_select_init_shared(sw_seam_select *state, const sw_seam_topology *topology,
                                     uint32_t *shown, const sw_seam_select_scratch *scratch,
                                     sw_arena *arena, sw_error *err);

/* Checks graph (sw_seam_graph_check), takes the state's arrays from arena and
 * starts at the coarsest front: the roots of the hierarchy. SW_ERR_FORMAT /
 * SW_ERR_RANGE for a malformed graph, SW_ERR_NO_MEMORY when the arena is too
 * small. The state keeps a copy of graph (the struct, not its arrays). */
sw_status sw_seam_select_init(sw_seam_select *state, const sw_seam_graph *graph, sw_arena *arena,
                              sw_error *err);

/* The dependency rule (El-Sana and Varshney 1999, as Guthe et al. 5.5 use it;
 * the comment in sw_seam_select.c derives it):
 * - split of vn (collapse (v1, v2 -> vn) undone): vn is active and every
 *   active neighbour of vn has a smaller index than vn;
 * - collapse (v1, v2 -> vn): v1 and v2 are active and every active neighbour
 *   w of v1 or v2 (other than v1, v2) has w < vn < child(w), a root's child
 *   counting as infinite.
 * Both keep the front's invariant: any two adjacent active vertices x, y
 * have x < child(y) and y < child(x) (they existed together at some step of
 * the simplification). Neighbours are the vertices next to each other in a
 * loop's current polyline. The can_ calls answer 0 for a vertex out of range
 * or not in the required state. */
/* The same for a graph sw_seam_graph_check has passed already (a loaded
 * pack's: the reader checks it, sw_pack_validate_seam.c); checking it again
 * took a fifth of the 40,000-patch showroom's start. */
sw_status sw_seam_select_init_checked(sw_seam_select *state, const sw_seam_graph *graph,
                                      sw_arena *arena, sw_error *err);

int sw_seam_select_can_split(const sw_seam_select *state, uint32_t vn);
int sw_seam_select_can_collapse(const sw_seam_select *state, uint32_t vn);

/* One step, when the rule allows it; SW_ERR_ARG (state unchanged) when not. */
sw_status sw_seam_select_split(sw_seam_select *state, uint32_t vn, sw_error *err);
sw_status sw_seam_select_collapse(sw_seam_select *state, uint32_t vn, sw_error *err);

/* Splits active vertex v even where the rule forbids it now: first splits,
 * recursively, the neighbours with larger indices that block it (paper 5.5).
 * At most max_ops splits (0: no limit); *splits (may be NULL) gets how many
 * were done. SW_ERR_ARG when v is not an active created vertex; SW_OK with v
 * still active when max_ops ran out (the front is valid after every step). */
sw_status sw_seam_select_force_split(sw_seam_select *state, uint32_t v, uint32_t max_ops,
                                     uint32_t *splits, sw_error *err);

typedef struct sw_seam_update_result {
    uint32_t splits;          /* all splits, the forced ones included */
    uint32_t forced_splits;   /* splits of vertices that met their bound, made for a neighbour */
    uint32_t collapses;
    int complete;             /* 0 when max_ops stopped the update early */
} sw_seam_update_result;

/* Moves the front for one frame. surface_bound[s] (model units, finite,
 * >= 0) is the error surface s accepts; a vertex's bound is the smallest
 * over the surfaces whose loops hold its originals' slots, which are the
 * surfaces whose loops show it whenever it is active. Afterwards every
 * active vertex's error is <= its bound (refined where needed, with forced
 * splits), and no collapse is left whose vertex would meet its bound and
 * the rule allows (coarse where it can). max_ops caps splits + collapses
 * (paper 6.4's load balancing; 0: no cap): when it stops the update early,
 * result->complete is 0 and the bound may not hold yet; the next update goes
 * on from there. Refinement comes first, so a capped update spends its
 * operations on errors that are too large before saving vertices.
 * SW_ERR_ARG for a missing, NaN, infinite or negative bound. */
sw_status sw_seam_select_update(sw_seam_select *state, const float *surface_bound,
                                uint32_t max_ops, sw_seam_update_result *result, sw_error *err);

/* The next update works from every surface's bound, as the first one does,
 * not from those that changed since the last (tests compare the two). */
void sw_seam_select_forget_bounds(sw_seam_select *state);

/* One point of a loop's current polyline: the active vertex shown and the
 * (u, v) to use for it in the loop's surface. */
typedef struct sw_seam_point {
    uint32_t vertex;
    float uv[2];
} sw_seam_point;

/* Loop's current polyline (closed: the last point joins the first) into
 * points[0 .. *count). A run of slots showing one vertex gives one point; its
 * (u, v) comes from the run's slot whose original the vertex's position
 * descends from most directly: at each collapse on the way down, v2's side
 * when the run holds a slot of it, else v1's (so a vertex sewn in the loop
 * keeps its own parameters, and vn takes v1's where v2 is not in the loop).
 * With pin > 0 (model units) a run instead gives a point per slot whose
 * original lies within pin of the vertex, in slot order, repeats of one
 * (u, v) dropped, all at the vertex: so a degenerate side of the domain (a
 * pole, one model-space point along a whole side in (u, v)) keeps its corners.
 * The rule above still applies to a run with no such slot. The caller passes
 * the surface's error bound, within which the vertex may stand for them.
 * The polyline starts at the first slot (in slot order) that begins a run.
 * *vanished is 1 when the polyline has fewer than three distinct vertices.
 * At most the loop's slot_count points; SW_ERR_NO_MEMORY with *count set to
 * the points needed when capacity is smaller; SW_ERR_RANGE for a bad loop. */
sw_status sw_seam_select_loop(const sw_seam_select *state, uint32_t loop, float pin,
                              sw_seam_point *points, uint32_t capacity, uint32_t *count,
                              int *vanished, sw_error *err);

/* Is slot k of loop (0 .. slot_count - 1 from its first) on a degenerate
 * side of its surface's domain (a pole: one of its two segments far
 * shorter in model space than its (u, v) length predicts), where the pin
 * above keeps the slot's own point? Static: the original slots only. */
int sw_seam_slot_degenerate(const sw_seam_graph *graph, uint32_t loop, uint32_t k);

/* The same, and each point's slot in the loop (0 .. slot_count - 1 from
 * the loop's first) into slots (capacity entries, may be NULL): where the
 * point stands along the loop, whatever the front (sw_border_strip.h's t). */
sw_status sw_seam_select_loop_slots(const sw_seam_select *state, uint32_t loop, float pin,
                                    sw_seam_point *points, uint32_t *slots, uint32_t capacity,
                                    uint32_t *count, int *vanished, sw_error *err);

typedef struct sw_seam_select_stats {
    uint32_t active_vertices;
    uint32_t loops_vanished;
    uint32_t surfaces_vanished;   /* surfaces whose outer loop vanished: not drawn */
} sw_seam_select_stats;

/* Counts over the whole graph: O(slot_count) (the loops are walked). */
sw_seam_select_stats sw_seam_select_count(const sw_seam_select *state);

/* The surfaces whose loops original o sits in, one for each of its slots
 * (a surface twice where two of its loops, or one loop twice, meet there):
 * *surfaces points at them in the state (valid while it lives); returns
 * how many, 0 for a vertex that is not original. */
uint32_t sw_seam_select_surfaces_at(const sw_seam_select *state, uint32_t o,
                                    const uint32_t **surfaces);

/* 1 when v is on the front. */
int sw_seam_select_is_active(const sw_seam_select *state, uint32_t v);

/* Surfaces with a loop whose polyline may have changed since the last
 * clear: set by every split and collapse for the surfaces of the slots it
 * touched. The tessellation reads and clears them. */
int sw_seam_select_surface_changed(const sw_seam_select *state, uint32_t surface);
void sw_seam_select_clear_changed(sw_seam_select *state);

#endif
