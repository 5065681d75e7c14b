/* SPDX-License-Identifier: MIT */
/* A frame's plan: what the GL thread P uploads and draws for one frame of
 * the seam walk, made by whoever runs the walk's visibility side V
 * (sw_seam_walk_plan): the visibility thread when there is one
 * (sw_seam_visibility.h), else P itself just before it draws. It is paper
 * 000 section 5.2's activity list handed over whole, once a frame: P reads
 * only the plan and the mesh bytes it points at, never the walk's state,
 * so V may select the next frame (cull, bound, move seams, schedule, swap
 * batches in) while P draws this one.
 *
 * Why a snapshot and not the walk's arrays: V rewrites the cache entries,
 * visibility and bounds for frame i+1 while P draws frame i. The mesh bytes
 * a plan points at stay put while P may read them: a mesh V replaces is
 * retired with the last frame that draws it (sw_handoff.h), and its blocks
 * are reused only once P has finished that frame.
 *
 * Memory: two plans (V fills one while P draws the other), from the arena
 * the caller gives, sw_seam_plan_bytes each; no allocation afterwards. */
#ifndef SW_SEAM_PLAN_H
#define SW_SEAM_PLAN_H

#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_error.h"
#include "sw_view.h"

/* One surface to draw: where its mesh lies in the cache (and so in the GL
 * buffers, same layout), and what measuring it needs. */
typedef struct sw_seam_draw_item {
    uint32_t surface, part;
    uint32_t first_vertex, first_index;
    uint32_t vertex_count, index_count;  /* index_count: the mesh's and its fans' */
    uint32_t fill_indices;               /* of index_count, the fill fans' (drawn last) */
    float depth;                         /* its nearest depth this frame */
    uint8_t late;                        /* drawn coarser than the view asks (its new mesh
                                            is being made): measured apart */
    uint8_t standin;                     /* a static level standing in (no (u, v) to measure
                                            against the surface: its error is the level's) */
    uint8_t part_level;                  /* a whole part from its part level: first_vertex and
                                            first_index are in the pack's part levels (P's
                                            resident buffers), surface is UINT32_MAX */
} sw_seam_draw_item;

/* One mesh to upload before the frame's first draw. */
typedef struct sw_seam_upload_item {
    uint32_t first_vertex, vertex_count, first_index, index_count;
} sw_seam_upload_item;

typedef struct sw_seam_plan {
    uint32_t number;                  /* the frame, from 0 */
    sw_view view;                     /* the view V selected for (near and far not fitted) */
    int depth_known;                  /* the drawn surfaces' depth range below is set */
    double nearest, farthest;         /* of the drawn (and facing-away) surfaces' boxes */
    sw_seam_draw_item *draws;         /* capacity */
    sw_seam_upload_item *uploads;     /* capacity */
    uint32_t draw_count, upload_count, capacity;
    uint32_t overflow;                /* items refused for capacity: never expected (a
                                         surface is planned and made at most once a frame),
                                         counted as failed surfaces, never silent */
    double visibility_ms;             /* V's time on it: select, schedule, swap, plan */
    uint8_t on_gl_thread;             /* planned on P's thread (no visibility thread) */
    uint8_t overlapped;               /* V began it before P had finished the frame before:
                                         the two halves ran at the same time */
    /* Written by P after drawing it, read by V before it plans the frame
     * two later (the controller's input): */
    double drawn_ms;                  /* P's frame time, measurement excluded */
    int swapped;                      /* the plan swapped a batch in (uploads and all) */
} sw_seam_plan;

/* Arena bytes of one plan for surface_count surfaces. */
size_t sw_seam_plan_bytes(uint32_t surface_count);

sw_status sw_seam_plan_init(sw_seam_plan *p, uint32_t surface_count, sw_arena *arena,
                            sw_error *err);

/* Empties the plan for frame number (keeps its buffers). */
void sw_seam_plan_begin(sw_seam_plan *p, uint32_t number);

/* Appends (at most one item per surface each, so capacity never runs out;
 * past it, counted in overflow). */
void sw_seam_plan_draw(sw_seam_plan *p, const sw_seam_draw_item *item);
void sw_seam_plan_upload(sw_seam_plan *p, uint32_t first_vertex, uint32_t vertex_count,
                         uint32_t first_index, uint32_t index_count);

#endif
