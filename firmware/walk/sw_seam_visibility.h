/* SPDX-License-Identifier: MIT */
/* The visibility thread V of paper 000 section 5 (the pipeline V -> T -> P):
 * V culls, bounds, moves the seams, schedules the workers' tessellation,
 * swaps finished batches in and writes the frame's plan (sw_seam_plan.h)
 * for frame i+1 while the GL thread P draws frame i. The plans are the
 * paper's activity list, handed over whole: two of them, V filling one
 * while P draws the other.
 *
 * The hand-over, frame by frame (P's calls):
 *   post(view 0)
 *   frame i: post(view i+1) -> take() waits for plan i -> draw it -> done()
 * so P posts the next frame's view (its camera, its input step) before it
 * draws this one: the input shows one frame later than without V, the
 * price of the overlap. P waits for V only when V's plan is not ready when
 * P has finished the previous frame: V's work is then the frame's bound,
 * and the stats say so (plan_wait_ms). P never waits for the workers.
 * With stand-ins (the pack's static levels) V moves the seams and opens
 * the next batch after it has posted plan i, while P draws it
 * (sw_seam_walk_schedule_deferred), so that move is not in the plan's
 * time.
 *
 * sync (the walk's sync_work, tests): V plans frame i only once P has
 * finished frame i-1, so every retired mesh is free again as in a walk
 * without V, and the frames are the same, bit for bit.
 *
 * Without a thread (threaded 0: no workers, or --visibility-thread 0)
 * take() plans the frame on P's thread: the same calls, in turn.
 *
 * The walk belongs to V between post and take (and P touches only the plan
 * it took and the mesh bytes it names, sw_seam_walk_draw_plan); P's done()
 * hands the controller the frame's time through the plan, which V reads
 * two frames later. Semaphores order the hand-over; threads start at
 * sw_seam_visibility_start, nothing allocates afterwards. */
#ifndef SW_SEAM_VISIBILITY_H
#define SW_SEAM_VISIBILITY_H

#include <pthread.h>
#include <semaphore.h>
#include <stdatomic.h>
#include <stdint.h>

#include "sw_seam_walk.h"

typedef struct sw_seam_visibility {
    sw_seam_walk *walk;
    sw_seam_plan plans[2];        /* frame i's is plans[i & 1] */
    sw_seam_frame frames[2];      /* V's counts of each plan's frame */
    sw_view views[2];             /* posted, frame i's in views[i & 1] */
    uint32_t posted;              /* P's: views posted */
    uint32_t taken;               /* P's: plans taken */
    uint32_t learned;             /* V's: drawn frames the controller has learned */
    _Atomic uint32_t done;        /* frames P has finished (release after drawn_ms) */
    int threaded, sync;
    pthread_t thread, gl_thread;  /* V's, and P's (given at start) */
    sem_t view_ready, plan_ready, frame_done;
    int sems_up, thread_up;
    _Atomic int stop;
    sw_status status;             /* V's: its first error (the walk stops at it) */
    sw_status plan_status[2];     /* each plan's, for P (status changes under P's reads) */
    sw_error error;               /* written once, with the first error */
} sw_seam_visibility;

/* Sets up the plans from arena (sw_seam_walk_init_frames: counted in
 * sw_seam_walk_frame_bytes) and, with
 * threaded, starts V. sync: the walk's sync_work. gl_thread: P, which
 * need not be the caller (seamwalk starts the walk on a loader thread).
 * SW_ERR_IO when the thread or its semaphores cannot be made. */
sw_status sw_seam_visibility_start(sw_seam_visibility *v, sw_seam_walk *walk, int threaded,
                                   int sync, pthread_t gl_thread, sw_arena *arena,
                                   sw_error *err);

/* P: the view of the next frame to plan (views are planned in order). */
void sw_seam_visibility_post(sw_seam_visibility *v, const sw_view *view);

/* P: the next frame's plan and V's counts of it (waits for V, or plans it
 * here without a thread). Requires a view posted for it. SW_OK, or V's
 * error (the walk's select failed): then *plan is NULL. */
sw_status sw_seam_visibility_take(sw_seam_visibility *v, const sw_seam_plan **plan,
                                  sw_seam_frame *frame, sw_error *err);

/* P: the plan taken last is drawn and its frame finished (drawn_ms: the
 * frame's time, measurement excluded; swapped: the plan swapped a batch
 * in). */
void sw_seam_visibility_done(sw_seam_visibility *v, double drawn_ms, int swapped);

/* Stops and joins V (safe when it never started). */
void sw_seam_visibility_stop(sw_seam_visibility *v);

#endif
