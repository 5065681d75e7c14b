/* SPDX-License-Identifier: MIT */
#include "sw_seam_visibility.h"

#include <errno.h>
#include <string.h>
#include <time.h>

#include "sw_seam_walk_internal.h"
#include "sw_thread_name.h"

static void wait_sem(sem_t *s)
{
    while (sem_wait(s) != 0 && errno == EINTR) {
    }
}

/* The controller learns every frame P has finished since V last looked.
 * Frame j's time is in plans[j & 1], which V overwrites only when it plans
 * frame j + 2, after this (P finished j before it posted the view of j+2). */
static void learn(sw_seam_visibility *v)
{
    uint32_t done = atomic_load_explicit(&v->done, memory_order_acquire);
    for (; v->learned < done; v->learned++) {
        const sw_seam_plan *p = &v->plans[v->learned & 1];
        sw_seam_walk_learn(v->walk, p->drawn_ms, p->swapped);
    }
}

/* V's half of frame k: the select for the posted view, then the plan. */
static void plan_frame(sw_seam_visibility *v, uint32_t k)
{
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    uint32_t done = atomic_load_explicit(&v->done, memory_order_acquire);
    learn(v);
    sw_seam_plan *plan = &v->plans[k & 1];
    sw_seam_frame *f = &v->frames[k & 1];
    sw_seam_plan_begin(plan, k);
    plan->on_gl_thread = (uint8_t)(pthread_equal(pthread_self(), v->gl_thread) != 0);
    plan->overlapped = k > 0 && done < k;
    sw_status st = v->status == SW_OK
                       ? sw_seam_walk_select(v->walk, &v->views[k & 1], f, &v->error)
                       : v->status;
    if (st == SW_OK)
        sw_seam_walk_plan(v->walk, &v->views[k & 1], plan, f);
    v->status = st;
    v->plan_status[k & 1] = st;
    plan->visibility_ms = sw_seam_walk_ms_since(&t0);
}

static void *visibility_main(void *arg)
{
    sw_seam_visibility *v = arg;
    sw_thread_name("sw-visibility");
    for (uint32_t k = 0;; k++) {
        wait_sem(&v->view_ready);
        if (atomic_load_explicit(&v->stop, memory_order_acquire))
            break;
        if (v->sync && k > 0)
            wait_sem(&v->frame_done);   /* lockstep: frame k-1 finished first */
        if (atomic_load_explicit(&v->stop, memory_order_acquire))
            break;
        plan_frame(v, k);
        sem_post(&v->plan_ready);
        /* The GL thread draws frame k meanwhile; its error, if any, goes
         * with the next plan (P reads v->error only after that post). */
        if (v->walk->defer_schedule && v->status == SW_OK)
            v->status = sw_seam_walk_schedule_deferred(v->walk, &v->error);
    }
    return NULL;
}

sw_status sw_seam_visibility_start(sw_seam_visibility *v, sw_seam_walk *walk, int threaded,
                                   int sync, pthread_t gl_thread, sw_arena *arena,
                                   sw_error *err)
{
    memset(v, 0, sizeof *v);
    v->walk = walk;
    v->threaded = threaded;
    v->sync = sync;
    v->gl_thread = gl_thread;
    sw_status st = sw_seam_walk_init_frames(walk, v->plans, arena, err);
    if (st != SW_OK || !threaded)
        return st;
    /* With its own thread, workers that run on their own and stand-ins
     * for what they have not made, V moves the front after handing each
     * plan over (sw_seam_walk_schedule_deferred); otherwise a frame's plan
     * must hold the work scheduled for it (sync_work, the first frame
     * without stand-ins). */
    walk->defer_schedule = !sync && sw_seam_walk_async(walk) && walk->standins;
    if (sem_init(&v->view_ready, 0, 0) != 0 || sem_init(&v->plan_ready, 0, 0) != 0 ||
        sem_init(&v->frame_done, 0, 0) != 0)
        return sw_error_set(err, SW_ERR_IO, "visibility thread: cannot make its semaphores");
    v->sems_up = 1;
    if (pthread_create(&v->thread, NULL, visibility_main, v) != 0)
        return sw_error_set(err, SW_ERR_IO, "cannot start the visibility thread");
    v->thread_up = 1;
    return SW_OK;
}

void sw_seam_visibility_post(sw_seam_visibility *v, const sw_view *view)
{
    v->views[v->posted & 1] = *view;
    v->posted++;
    if (v->threaded)
        sem_post(&v->view_ready);
}

sw_status sw_seam_visibility_take(sw_seam_visibility *v, const sw_seam_plan **plan,
                                  sw_seam_frame *frame, sw_error *err)
{
    uint32_t k = v->taken;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if (v->threaded)
        wait_sem(&v->plan_ready);
    else
        plan_frame(v, k);
    double waited = v->threaded ? sw_seam_walk_ms_since(&t0) : 0;
    *plan = NULL;
    sw_status st = v->plan_status[k & 1];
    if (st != SW_OK) {   /* V sets error once and selects nothing after it */
        *err = v->error;
        return st;
    }
    v->taken++;
    *frame = v->frames[k & 1];
    frame->plan_wait_ms = waited;
    frame->visibility_ms = v->plans[k & 1].visibility_ms;
    frame->planned_on_gl_thread = v->plans[k & 1].on_gl_thread;
    frame->plan_overlapped = v->plans[k & 1].overlapped;
    *plan = &v->plans[k & 1];
    return SW_OK;
}

void sw_seam_visibility_done(sw_seam_visibility *v, double drawn_ms, int swapped)
{
    sw_seam_plan *p = &v->plans[(v->taken - 1) & 1];
    p->drawn_ms = drawn_ms;
    p->swapped = swapped;
    sw_seam_walk_finished(v->walk, p->number);
    atomic_store_explicit(&v->done, v->taken, memory_order_release);
    if (v->threaded && v->sync)
        sem_post(&v->frame_done);
}

void sw_seam_visibility_stop(sw_seam_visibility *v)
{
    if (v->thread_up) {
        atomic_store_explicit(&v->stop, 1, memory_order_release);
        sem_post(&v->view_ready);
        sem_post(&v->frame_done);
        pthread_join(v->thread, NULL);
        v->thread_up = 0;
    }
    if (v->sems_up) {
        sem_destroy(&v->view_ready);
        sem_destroy(&v->plan_ready);
        sem_destroy(&v->frame_done);
        v->sems_up = 0;
    }
}
