/* SPDX-License-Identifier: MIT */
/* seamwalk: the walkthrough runtime. seamwalk_start.c sizes one arena from
 * the pack header and the options, refuses at once if it does not fit
 * --memory-mb, loads and validates the pack into it (on a loader thread,
 * while this thread opens the display); this file then walks the camera
 * path (or an orbit) frame by frame through the pack's Seam Graph
 * (sw_seam_walk.h): select the seams and bounds -> tessellate what changed
 * -> draw -> optional PNG and measurement, and writes the stats.
 * After start-up nothing in our code calls malloc (sw_alloc_count proves it).
 * It draws into the display --display chose (platform/sw_display.h:
 * headless, KMS, an X11 or Wayland window). With --navigate or
 * --input-timeline the camera comes from the input step (sw_kiosk_run.h),
 * one call per frame, for the frame after the one being drawn. The main
 * thread is the GL thread P; with workers, the walk's visibility side V
 * runs on its own thread one frame ahead (sw_seam_visibility.h), and P
 * draws the plans V hands it. */
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "seamwalk_program.h"
#include "sw_alloc_count.h"
#include "sw_heap.h"
#include "sw_message_screen.h"
#include "sw_png.h"
#include "sw_rss.h"

static sw_vec3 vec3_of(const float v[3]) { return sw_v3(v[0], v[1], v[2]); }

static sw_camera_pose pose_at(const sw_program *rt, int frame)
{
    double fovy = rt->opt.fov_deg * SW_PI / 180.0;
    if (rt->kiosk_up)
        return rt->kiosk_pose;
    if (rt->view)
        return (sw_camera_pose){ vec3_of(rt->view->eye), vec3_of(rt->view->target),
                                 sw_v3_normalize(vec3_of(rt->view->up)) };
    if (rt->opt.orbit)
        return sw_camera_orbit_in(&rt->model_box, &rt->frame, fovy,
                                  (double)rt->opt.width / rt->opt.height,
                                  (double)frame / rt->opt.frames);
    double t0 = sw_camera_path_start(&rt->path), t1 = sw_camera_path_end(&rt->path);
    double t = rt->opt.frames > 1 ? t0 + (t1 - t0) * frame / (rt->opt.frames - 1) : t0;
    return sw_camera_path_at(&rt->path, t);
}

static sw_status write_png(sw_program *rt, int frame, sw_error *err)
{
    sw_status st = sw_display_read_rgba(rt->display, rt->pixels, err);
    if (st != SW_OK)
        return st;
    size_t n = (size_t)rt->opt.width * rt->opt.height;
    for (size_t i = 0; i < n; i++) /* RGBA to RGB in place: the alpha is always opaque */
        memmove(rt->pixels + i * 3, rt->pixels + i * 4, 3);
    char name[4096];
    snprintf(name, sizeof name, "%s/frame_%05d.png", rt->opt.png_dir, frame);
    return sw_png_write(name, rt->opt.width, rt->opt.height, 3, rt->pixels,
                        (size_t)rt->opt.width * 3, &rt->readback_arena, err);
}

/* The plan's view with near and far fitted to what the walk selected
 * (sw_seam_depth.h, in the plan), so the depth buffer's bits go where the
 * model is; its projection starts the frame. */
static sw_view begin_frame(sw_program *rt, const sw_seam_plan *plan)
{
    static const float default_background[4] = { 0.93f, 0.94f, 0.96f, 1.0f };
    float background[4] = { rt->opt.background[0], rt->opt.background[1],
                            rt->opt.background[2], 1.0f };
    sw_view view = plan->view;
    if (rt->opt.depth_fit && plan->depth_known)
        view = sw_view_fit_depth(&plan->view, plan->nearest, plan->farthest, rt->depth_bits);
    sw_stats_add_depth_range(&rt->stats, view.near_z, view.far_z);
    float mv[16], proj[16];
    sw_mat4_to_float(&view.view, mv);
    sw_mat4_to_float(&view.proj, proj);
    sw_renderer_begin_frame(&rt->renderer, rt->opt.width, rt->opt.height,
                            rt->opt.background_set ? background : default_background, mv, proj);
    return view;
}

/* The frame's seams as drawn into the stats. */
static void add_drawn(sw_stats *s, sw_seam_drawn *d)
{
    sw_seam_drawn_result r;
    sw_seam_drawn_check(d, &r);
    s->drawn_unchecked_frames += !r.checked;
    s->drawn_points_max = r.points > s->drawn_points_max ? r.points : s->drawn_points_max;
    s->drawn_t_vertices_max = r.t_vertices > s->drawn_t_vertices_max ? r.t_vertices
                                                                     : s->drawn_t_vertices_max;
    s->drawn_gaps_max = r.gaps > s->drawn_gaps_max ? r.gaps : s->drawn_gaps_max;
    s->drawn_free_max = r.free_points > s->drawn_free_max ? r.free_points : s->drawn_free_max;
}

/* Takes the frame's plan (from V), starts the frame and draws it through
 * the Seam Graph; its own measurement. */
static sw_status seam_frame(sw_program *rt, int measuring, uint64_t *triangles, uint32_t *drawn,
                            uint32_t *capped, double *measure_ms, int *swapped, sw_error *err)
{
    sw_seam_frame f;
    const sw_seam_plan *plan;
    sw_status st = sw_seam_visibility_take(&rt->vis, &plan, &f, err);
    if (st != SW_OK)
        return st;
    sw_view view = begin_frame(rt, plan);
    sw_seam_drawn_begin(&rt->drawn);
    sw_seam_walk_draw_plan(&rt->seam, &rt->renderer, &rt->pool, plan, &view,
                           measuring ? &rt->stats : NULL, &f);
    double check_s = sw_program_now_s();
    if (measuring) /* measurement, like the walk's own: not part of the frame's time */
        add_drawn(&rt->stats, &rt->drawn);
    *triangles = f.triangles;
    *swapped = (int)f.batches_committed;
    *drawn = f.drawn_surfaces;
    *capped = f.capped_surfaces;
    *measure_ms = f.measure_ms + (sw_program_now_s() - check_s) * 1000.0;
    sw_stats *s = &rt->stats;
    s->seam_active_min = f.active_vertices < s->seam_active_min ? f.active_vertices
                                                                : s->seam_active_min;
    s->seam_active_max = f.active_vertices > s->seam_active_max ? f.active_vertices
                                                                : s->seam_active_max;
    if (f.vanished_surfaces > s->surfaces_vanished_max)
        s->surfaces_vanished_max = f.vanished_surfaces;
    if (f.failed_surfaces > s->surfaces_failed_max)
        s->surfaces_failed_max = f.failed_surfaces;
    if (f.holes_filled > s->surfaces_holes_filled_max)
        s->surfaces_holes_filled_max = f.holes_filled;
    if (f.untangled > s->surfaces_untangled_max)
        s->surfaces_untangled_max = f.untangled;
    if (f.clamped_surfaces > s->surfaces_clamped_max)
        s->surfaces_clamped_max = f.clamped_surfaces;
    if (f.cracks > s->cracks_max)   /* counted every frame: a refused surface is one */
        s->cracks_max = f.cracks;
    if (f.fill_triangles > s->fill_triangles_max)
        s->fill_triangles_max = f.fill_triangles;
    if (f.crossings > s->seam_crossings_max)
        s->seam_crossings_max = f.crossings;
    sw_stats_add_cache_frame(s, f.retessellated, f.retess_triangles, f.upload_bytes, f.evicted,
                             f.tess_ms);
    sw_stats_add_cache_fill(s, f.cache_used_vertices, f.cache_used_indices,
                            f.cache_drawn_vertices, f.cache_drawn_indices);
    sw_stats_add_cull_frame(s, f.cull_box_tests, f.cone_culled, f.cull_ms);
    if (rt->workers)
        sw_stats_add_threads_frame(s, f.waiting_surfaces, f.behind_surfaces, f.frames_behind,
                                   f.behind_ratio, f.jobs_scheduled, f.jobs_prefetch,
                                   f.batches_committed,
                                   f.seam_ops, f.budget_tris, f.budget_used);
    sw_stats_add_pressure(s, f.pressure);
    if (rt->workers)
        sw_stats_add_standins(s, f.standins, f.standins_made, f.standins_coarser,
                              f.standin_triangles, f.jobs_leaner);
    sw_stats_add_part_levels(s, f.part_levels, f.covered_surfaces, f.part_level_triangles);
    if (rt->workers && f.jobs_scheduled)
        sw_stats_add_update_cap(s, f.updated_tris, f.updated_cap);
    sw_stats_add_visibility_frame(s, f.visibility_ms, f.plan_wait_ms, f.planned_on_gl_thread,
                                  f.plan_overlapped);
    if (measuring) {
        s->seam_error_beyond_sewing_px = fmax(s->seam_error_beyond_sewing_px,
                                              f.error_beyond_sewing_px);
        s->error_behind_beyond_sewing_px = fmax(s->error_behind_beyond_sewing_px,
                                                f.error_behind_beyond_sewing_px);
        s->seam_sewing_offset_px = fmax(s->seam_sewing_offset_px, f.sewing_offset_px);
        s->seam_chord_px_max = fmax(s->seam_chord_px_max, f.seam_chord_px);
    }
    return SW_OK;
}

/* The walk's frame f (counting every loop of --duration) is walked. */
static int walking(const sw_program *rt, uint64_t f, double t0)
{
    if (rt->opt.duration_s > 0)
        return sw_program_now_s() - t0 < rt->opt.duration_s;
    return f < (uint64_t)rt->opt.frames;
}

/* Frame f's view (the input step runs here, with --navigate) posted to V.
 * With --test-stall-workers F the workers stall before V selects frame F. */
static void post_view(sw_program *rt, uint64_t f)
{
    int frame = (int)(f % (uint64_t)rt->opt.frames);
    if (frame == rt->opt.stall_workers_at)
        sw_seam_walk_stall_workers(&rt->seam, 1);
    if (rt->kiosk_up) /* the input step: devices -> actions -> navigation -> pose */
        rt->kiosk_pose = sw_kiosk_run_frame(&rt->kiosk, (int)f);
    sw_camera_pose pose = pose_at(rt, frame);
    sw_view view = sw_view_make_depth(&pose, rt->opt.fov_deg * SW_PI / 180.0, rt->opt.width,
                                      rt->opt.height, &rt->model_box, rt->depth_bits);
    sw_seam_visibility_post(&rt->vis, &view);
}

/* Frame f: the next frame's view to V first (so V selects it while this
 * one is drawn; with --duration it may go unused at the end), then this
 * frame's plan drawn. */
static sw_status run_frame(sw_program *rt, uint64_t f, sw_error *err)
{
    int frame = (int)(f % (uint64_t)rt->opt.frames);
    if (rt->opt.duration_s > 0 || f + 1 < (uint64_t)rt->opt.frames)
        post_view(rt, f + 1);
    double t0 = sw_program_now_s();
    int measuring = rt->opt.measure_every > 0 && frame % rt->opt.measure_every == 0;
    uint64_t triangles = 0;
    uint32_t drawn = 0, capped = 0;
    double measure_ms = 0;
    int swapped = 0;
    sw_status st = seam_frame(rt, measuring, &triangles, &drawn, &capped, &measure_ms, &swapped,
                              err);
    if (st != SW_OK)
        return st;
    sw_gl_pool_finish(&rt->pool);
    double ms = (sw_program_now_s() - t0) * 1000.0 - measure_ms;
    int first = rt->stats.frames_total == 0;
    sw_stats_add_frame(&rt->stats, ms, (uint32_t)triangles, drawn);
    sw_seam_visibility_done(&rt->vis, ms, swapped);
    if (first) { /* less the measurement, as every frame's time */
        rt->stats.first_frame_ms = (sw_program_now_s() - rt->start_s) * 1000.0 - measure_ms;
        rt->stats.start_frame_ms = (sw_program_now_s() - rt->mark_s) * 1000.0 - measure_ms;
    }
    if (capped > rt->stats.capped_patches_max)
        rt->stats.capped_patches_max = capped;
    if (rt->opt.png_dir && frame % rt->opt.png_every == 0 &&
        (st = write_png(rt, frame, err)) != SW_OK)
        return st;
    if ((st = sw_display_present(rt->display, err)) != SW_OK)
        return st;
    sw_notify_frame(&rt->notify, sw_program_now_s());   /* READY=1 once it is shown */
    return SW_OK;
}

/* The whole process's heap calls when tests/process_alloc_shim.so is
 * preloaded (NULL otherwise): what Mesa and libc do beside our code. */
typedef uint64_t (*process_count_fn)(void);
static process_count_fn process_alloc_counter(void)
{
    void *sym = dlsym(RTLD_DEFAULT, "sw_process_alloc_count");
    process_count_fn fn;
    memcpy(&fn, &sym, sizeof fn);   /* object to function pointer, as POSIX allows */
    return sym ? fn : NULL;
}

/* Resident memory now, kB (-1 unknown); the peak into the stats. */
static int64_t rss_now_kb(sw_stats *s)
{
    sw_rss r;
    sw_rss_read(&r);
    s->rss_peak_kb = r.peak_kb;
    return r.rss_kb;
}

static sw_status walk(sw_program *rt, sw_error *err)
{
    post_view(rt, 0);
    sw_status pool_st = sw_program_start_pool(rt, err);   /* while V plans frame 0 */
    if (pool_st != SW_OK)
        return pool_st;
    rt->mark_s = sw_program_now_s();
    process_count_fn process = process_alloc_counter();
    uint64_t allocs_before = sw_alloc_count_allocs();
    uint64_t process_before = process ? process() : 0;
    sw_stats *s = &rt->stats;
    s->duration_s = rt->opt.duration_s;
    s->rss_start_kb = rss_now_kb(s);
    double t0 = sw_program_now_s();
    for (uint64_t f = 0; walking(rt, f, t0); f++) {
        sw_status st = run_frame(rt, f, err);
        if (st != SW_OK)
            return st;
        if ((f + 1) % (uint64_t)rt->opt.frames == 0 && ++s->loops <= SW_STATS_RSS_LOOPS) {
            sw_grow_hook_step(&rt->grow);
            /* The driver's heap is sized by now: resident from here on, and
             * the arena, the frames' block and the merged draws' staging
             * with it (no allocation; without it, a kernel before 5.14, the
             * soak shows the creep it prevents: a page of the staging is
             * first touched by the first frame that merges that many
             * indices, which may come loops later). Only when another
             * loop follows (--duration): a walk of one loop ends here, and
             * writing its hundred-odd MB then was kernel time spent on
             * nothing. */
            if (s->loops == 1 && rt->opt.duration_s > 0)
                s->heap_resident =
                    sw_heap_populate() && sw_heap_populate_block(rt->block, rt->arena.size) &&
                    sw_heap_populate_block(rt->frame_block, rt->frame_arena.size) &&
                    (!rt->staging_block ||
                     sw_heap_populate_block(rt->staging_block, sw_gl_pool_merge_bytes()));
            s->rss_loop_kb[s->loops - 1] = rss_now_kb(s);
            if (s->loops == 1)
                s->rss_first_loop_kb = s->rss_loop_kb[0];
        }
        if (rt->opt.store_dir && !rt->boot.marked_good) {
            sw_boot_poll_good(&rt->boot, sw_program_now_s() - t0, rt->opt.good_after_s);
            if (rt->boot.marked_good == 1)
                sw_notify_status("slot %c marked good", sw_slot_letter(rt->boot.slot));
        }
        if (rt->display->close_requested)
            break;   /* the window closed, or SIGTERM/SIGINT: end as if the walk were done */
    }
    sw_rss end;
    sw_rss_read(&end);
    s->rss_end_kb = end.rss_kb, s->rss_peak_kb = end.peak_kb;
    s->rss_end_file_kb = end.file_kb, s->rss_end_anon_kb = end.anon_kb;
    s->batch_waits = rt->pool.waits;
    rt->stats.walk_s = sw_program_now_s() - t0;
    rt->stats.mallocs_after_init = sw_alloc_count_active()
                                       ? (int64_t)(sw_alloc_count_allocs() - allocs_before)
                                       : -1;
    rt->stats.process_mallocs_after_init = process ? (int64_t)(process() - process_before) : -1;
    return SW_OK;
}

static sw_status show_message(sw_program *rt, sw_error *err)
{
    double t0 = sw_program_now_s();
    for (int f = 0; f < rt->opt.frames; f++) {
        double f0 = sw_program_now_s();
        sw_message_screen_draw(rt->opt.width, rt->opt.height, "NO VALID PACK");
        sw_status st = sw_display_read_rgba(rt->display, rt->pixels, err);
        if (st != SW_OK)
            return st;
        sw_stats_add_frame(&rt->stats, (sw_program_now_s() - f0) * 1000.0, 0, 0);
        if (rt->opt.png_dir && f % rt->opt.png_every == 0 && (st = write_png(rt, f, err)))
            return st;
        if ((st = sw_display_present(rt->display, err)) != SW_OK)
            return st;
        sw_notify_frame(&rt->notify, sw_program_now_s());
        if (rt->display->close_requested)
            break;
    }
    rt->stats.walk_s = sw_program_now_s() - t0;
    rt->stats.mallocs_after_init = -1; /* not counted: this is no walk */
    return SW_OK;
}

static void store_stats(sw_program *rt)
{
    sw_stats *s = &rt->stats;
    if (rt->boot.trial && !rt->boot.marked_good && !rt->boot.no_picture)
        sw_boot_note(&rt->boot, "slot %c is still pending: it ran %.2f s of the %g s "
                     "(--good-after-s) before it is marked good", sw_slot_letter(rt->boot.slot),
                     s->walk_s, rt->opt.good_after_s);
    s->store = 1;
    s->store_slot = sw_slot_letter(rt->boot.slot);
    s->store_trial = rt->boot.trial;
    s->store_marked_good = rt->boot.marked_good;
    s->store_log = rt->boot.log;
    s->store_message = rt->no_pack ? "NO VALID PACK" : NULL;
}

static sw_status write_stats(sw_program *rt, sw_error *err)
{
    sw_stats *s = &rt->stats;
    if (rt->opt.store_dir)
        store_stats(rt);
    s->patches_total = rt->pack.meta ? rt->pack.meta->patch_count : 0;
    s->measure_every = rt->opt.measure_every;
    s->arena_bytes = rt->arena.size + rt->frame_arena.size + rt->readback_arena.size +
                     (rt->staging_block ? sw_gl_pool_merge_bytes() : 0);
    s->arena_peak_bytes = rt->arena.peak + rt->frame_arena.peak + rt->readback_arena.peak;
    if (rt->seam.workers) {
        sw_seam_workers *p = rt->seam.workers;
        s->worker_triangles = atomic_load(&p->made_triangles);
        s->worker_busy_ms = (double)atomic_load(&p->busy_ns) * 1e-6;
        s->worker_steals = atomic_load(&p->steals);
    }
    s->seam_arena_bytes = rt->pack.seam_header ? sw_seam_walk_arena_bytes(&rt->stored) : 0;
    s->seam_arena_peak_bytes = rt->walk_bytes;
    s->runtime_bytes = rt->pack.header ? rt->pack.header->runtime_bytes : 0;
    s->pack_bytes = rt->pack.header ? rt->pack.header->total_size : 0;
    s->pack_mapped = rt->pack_mapped;
    s->width = rt->opt.width;
    s->height = rt->opt.height;
    if (!rt->opt.stats_path)
        return SW_OK;
    /* The JSON in memory first (the walk is over: allocating is allowed),
     * then written whole or not at all: a temporary beside it, fsynced and
     * renamed over it, removed on any failure (a full disk left a 0-byte
     * stats file that readers took for the run's). */
    char *json = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&json, &size);
    if (!f)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "%s: %s", rt->opt.stats_path,
                            strerror(errno));
    sw_status st = sw_stats_write_json(s, f, &rt->arena, err);
    if (fclose(f) != 0 && st == SW_OK)
        st = sw_error_set(err, SW_ERR_NO_MEMORY, "%s: %s", rt->opt.stats_path, strerror(errno));
    if (st == SW_OK && (st = sw_store_write_atomic(rt->opt.stats_path, json, size, err)) != SW_OK)
        sw_error_prefix(err, "stats");
    free(json);
    return st;
}

static void print_summary(const sw_program *rt)
{
    const sw_stats *s = &rt->stats;
    char error[64] = "error not measured (--measure-every 0)";
    if (s->measure_every > 0)
        snprintf(error, sizeof error, "error max %.3f px", s->error_max_px);
    char pack[96];
    snprintf(pack, sizeof pack, "the pack's %.1f MiB %s", s->pack_bytes / 1048576.0,
             s->pack_mapped ? "mapped beside it" : "copied into it");
    printf("seamwalk: %llu frames of %u patches at %dx%d in %.2f s; %s (bound %.2f);"
           " cracks max %llu; undrawn max %u (surfaces in view with no mesh yet, the most in a"
           " frame); bound raised in %u frames, by up to %.2fx (the mesh cache could not hold"
           " the view); clamped max %u (surfaces in view closer than the pack was built for, its"
           " --closest-mm or a tenth of its sewing tolerance, drawn at its finest);"
           " arena %.1f MiB (the pack's runtime_bytes %.1f MiB, %s, the run's"
           " frame stats and pictures the rest); mallocs after init %lld\n",
           (unsigned long long)s->frames_total, s->patches_total, s->width, s->height, s->walk_s, error,
           s->error_bound_px, (unsigned long long)s->cracks_max, s->waiting_max,
           s->pressure_frames, s->pressure_max > 1.0 ? s->pressure_max : 1.0,
           s->surfaces_clamped_max,
           s->arena_bytes / 1048576.0,
           s->runtime_bytes / 1048576.0, pack, (long long)s->mallocs_after_init);
    /* The walk's crack count is its own bookkeeping; the drawn borders are
     * checked apart (sw_seam_drawn.h) on the measured frames. */
    if (s->measure_every > 0)
        printf("seamwalk: drawn borders, checked apart: gaps max %llu, T-vertices max %llu\n",
               (unsigned long long)s->drawn_gaps_max,
               (unsigned long long)s->drawn_t_vertices_max);
    if (s->error_behind_samples)
        printf("seamwalk: meshes drawn coarser while their new ones were made: error max %.3f"
               " px (%llu samples, not in the error max above)\n", s->error_behind_max_px,
               (unsigned long long)s->error_behind_samples);
    if (s->duration_s > 0)
        printf("seamwalk: soak of %.0f s: %llu frames, %llu loops of %d; worst frame %.1f ms"
               " (frame %llu); resident %lld kB at start, %lld after the first loop, %lld at"
               " the end (peak %lld)\n", s->duration_s, (unsigned long long)s->frames_total,
               (unsigned long long)s->loops, rt->opt.frames, s->worst_frame_ms,
               (unsigned long long)s->worst_frame, (long long)s->rss_start_kb,
               (long long)s->rss_first_loop_kb, (long long)s->rss_end_kb,
               (long long)s->rss_peak_kb);
    printf("seamwalk: display %s %dx%d (%s)\n", sw_display_kind_name(rt->display->kind),
           rt->display->width, rt->display->height, rt->display->chosen_why);
    if (rt->opt.png_dir)
        printf("seamwalk: pictures in %s/\n", rt->opt.png_dir);
    if (rt->opt.stats_path)
        printf("seamwalk: stats in %s\n", rt->opt.stats_path);
}

/* What runs, for `systemctl status` (READY=1 follows with the first frame). */
static void say_status(const sw_program *rt)
{
    const char *display = sw_display_kind_name(rt->display->kind);
    if (rt->no_pack)
        sw_notify_status("NO VALID PACK on %s (journalctl -u seamwalk says why)", display);
    else if (rt->opt.store_dir)
        sw_notify_status("walking slot %c (%s) on %s %dx%d", sw_slot_letter(rt->boot.slot),
                         rt->boot.trial ? "pending, on trial" : "good", display,
                         rt->display->width, rt->display->height);
    else
        sw_notify_status("walking %s (unsigned, --pack) on %s %dx%d", rt->opt.pack_path,
                         display, rt->display->width, rt->display->height);
}

int main(int argc, char **argv)
{
    static sw_program rt;
    static sw_display display;   /* stays put: window listeners point into it */
    sw_error err = { SW_OK, "" };
    rt.display = &display;
    sw_heap_huge_pages(argv, sw_program_now_s());   /* returns when it did not run again */
    rt.start_s = sw_heap_started_s(sw_program_now_s());
    sw_status st = sw_options_parse(argc, argv, &rt.opt, &err);
    if (st != SW_OK)
        return sw_usage_error("seamwalk", "%s", err.message);
    if (rt.opt.help || rt.opt.help_test) {
        if (rt.opt.help_test)
            sw_options_print_test_usage(stdout);
        else
            sw_options_print_usage(stdout, argv[0]);
        return fflush(stdout) == 0 ? 0 : 1;
    }
    if (rt.opt.version) {
        puts("seamwalk " SW_VERSION);
        return fflush(stdout) == 0 ? 0 : 1;
    }
    /* A service stop (SIGTERM) or Ctrl-C ends the walk after the frame, so
     * the stats are written and a KMS display gives the screen back. */
    struct sigaction stop_walk_on = {.sa_handler = sw_display_close_on_signal};
    sigaction(SIGTERM, &stop_walk_on, NULL);
    sigaction(SIGINT, &stop_walk_on, NULL);
    /* A batch's worth of scene (sw_gl_pool.h) as the heap's steps. */
    sw_heap_keep((size_t)rt.opt.batch_tris * SW_GL_POOL_SCENE_BYTES_PER_TRIANGLE);
    sw_notify_status("starting");
    st = sw_program_start(&rt, &err);
    sw_notify_init(&rt.notify);
    if (st == SW_OK)
        say_status(&rt);
    if (st == SW_OK)
        st = rt.no_pack ? show_message(&rt, &err) : walk(&rt, &err);
    if (st == SW_OK)
        st = write_stats(&rt, &err);
    if (st == SW_OK && !rt.no_pack)
        print_summary(&rt);
    else if (st != SW_OK)
        fprintf(stderr, "seamwalk: %s\n", err.message);
    sw_program_stop(&rt);
    if (display.up)
        sw_display_destroy(&display);
    /* 3: the unit had no pack to show and showed the message screen instead. */
    return st != SW_OK ? 1 : rt.no_pack ? 3 : 0;
}
