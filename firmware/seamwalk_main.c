/* seamwalk: the walkthrough runtime. Sizes one arena from the pack header and
 * the options, refuses at once if it does not fit --memory-mb, loads and
 * validates the pack into it, then walks the camera path (or an orbit) frame
 * by frame through the pack's Seam Graph (sw_seam_walk.h): select the seams
 * and bounds -> tessellate what changed -> draw -> optional PNG and
 * measurement.
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
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sw_alloc_count.h"
#include "sw_boot.h"
#include "sw_camera_path.h"
#include "sw_display.h"
#include "sw_grow_hook.h"
#include "sw_heap.h"
#include "sw_kiosk_run.h"
#include "sw_message_screen.h"
#include "sw_options.h"
#include "sw_pack.h"
#include "sw_png.h"
#include "sw_renderer.h"
#include "sw_rss.h"
#include "sw_seam_visibility.h"
#include "sw_seam_walk.h"
#include "sw_stats.h"
#include "sw_up_axis.h"

typedef struct runtime {
    sw_options opt;
    sw_arena arena;
    void *block;
    sw_pack pack;
    sw_camera_path path;
    sw_seam_walk seam;
    int workers;              /* tessellation threads (--workers, resolved) */
    void *frame_block;        /* the frames' own buffers (plans, measuring scratch, the
                                 workers'): known only once the pack is loaded (its
                                 largest surface), taken at start like the arena */
    sw_arena frame_arena;
    sw_seam_visibility vis;   /* V, the walk's visibility side (sw_seam_visibility.h) */
    int vis_up;
    size_t walk_bytes;        /* of the arena, what the seam walk took */
    sw_seam_drawn drawn;      /* the seams as drawn, checked in measured frames */
    sw_seam_fill fill;        /* fans over the tessellations' seam crossings */
    sw_stats stats;
    sw_display *display;      /* main's; opened once, kept across --store's slot attempts */
    int depth_bits;           /* the display's depth buffer, as the GL reports it */
    sw_renderer renderer;
    sw_gl_pool pool;          /* the cached tessellations, as rt->seam.cache lays them out */
    int renderer_up, pool_up;
    sw_grow_hook grow;        /* --test-grow-kb */
    uint8_t *pixels;          /* read-back, width * height * 4, only with --png-dir */
    size_t png_scratch;       /* bytes kept free in the arena for sw_png_write */
    sw_box model_box;
    sw_camera_frame frame;           /* the orbit's: up is the pack's up axis */
    const sw_pack_viewpoint *view;   /* with --view */
    double start_s;
    double mark_s;            /* the end of the last start step timed (stats.start_*_ms) */
    double display_ms;        /* the display's start step, kept across sw_stats_init */
    sw_boot boot;             /* with --store: the slot being started, mark-good */
    int loading_slot;         /* with --store: the slot start() loads */
    int no_pack;              /* with --store: no slot started; the message screen runs */
    sw_kiosk_run kiosk;       /* with --navigate or --input-timeline */
    int kiosk_up;
    sw_camera_pose kiosk_pose;   /* this frame's, from the input step */
} runtime;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The time since *mark_s in ms; *mark_s becomes now, so steps add up. */
static double lap_ms(double *mark_s)
{
    double t = now_s(), ms = (t - *mark_s) * 1000.0;
    *mark_s = t;
    return ms;
}

static sw_status file_size(const char *path, size_t *size, sw_error *err)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", path, strerror(errno));
    *size = (size_t)st.st_size;
    return SW_OK;
}

/* Border edges the drawn-seam check holds in a frame. */
#define SW_DRAWN_EDGES (1u << 18)

/* Everything the walk will take from the arena, from the pack header and the
 * options alone, so the decision to run is made before any allocation. */
static size_t arena_bytes_needed(const runtime *rt, const sw_pack_header *h, size_t path_bytes,
                                 size_t path_keys)
{
    /* runtime_bytes covers the pack, every patch's state and the walk
     * (sw_pack.h, core/sw_walk_memory.h); the rest depends on the options. */
    size_t bytes = (size_t)h->runtime_bytes + sw_stats_arena_bytes(rt->opt.frames) +
                   sw_seam_drawn_arena_bytes(SW_DRAWN_EDGES, SW_SEAM_WALK_INDICES);
    if (rt->opt.fill_crossings)
        bytes += sw_seam_fill_arena_bytes(SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES);
    bytes += sw_arena_worst_case(path_bytes + 1, 8) +
             sw_arena_worst_case(path_keys * sizeof(sw_camera_key) + 1, 8);
    if (rt->opt.png_dir)
        bytes += sw_arena_worst_case((size_t)rt->opt.width * rt->opt.height * 4, 64) +
                 rt->png_scratch;
    return bytes + 4096;
}

static sw_status read_into_arena(const char *path, sw_arena *a, char **text, size_t size,
                                 sw_error *err)
{
    *text = sw_arena_alloc(a, size + 1, 8);
    FILE *f = fopen(path, "rb");
    size_t got = f && *text ? fread(*text, 1, size, f) : 0;
    if (f)
        fclose(f);
    if (!*text || got != size)
        return sw_error_set(err, SW_ERR_IO, "%s: cannot read %zu bytes", path, size);
    return SW_OK;
}

static sw_status load_path(runtime *rt, size_t path_bytes, sw_error *err)
{
    char *text;
    sw_status st = read_into_arena(rt->opt.path_file, &rt->arena, &text, path_bytes, err);
    if (st != SW_OK)
        return st;
    size_t n = sw_camera_path_count_keys(text, path_bytes);
    sw_camera_key *keys = sw_arena_alloc(&rt->arena, n * sizeof *keys + 1, 8);
    if (!keys)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the camera path");
    return sw_camera_path_parse(text, path_bytes, rt->opt.path_file, keys, n, &rt->path, err);
}

/* --workers: the cores less one, at least one, unless given; none for the
 * --no-cache baseline (it remakes everything in the frame by definition). */
static int workers_wanted(const sw_options *o)
{
    if (o->no_cache)
        return 0;
    if (o->workers >= 0)
        return o->workers;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return cores > 2 ? (int)(cores - 1 > SW_OPTIONS_MAX_WORKERS ? SW_OPTIONS_MAX_WORKERS
                                                                 : cores - 1) : 1;
}

/* The frames' own buffers (the plans, P's measuring scratch and a maker
 * per worker: the pack's largest surface decides their size, so they
 * cannot be counted from the header as the arena is) in a second block
 * taken now, before the walk's allocation count starts, and held to
 * --memory-mb with the arena; then the threads: the workers, and V when
 * there are workers (without them the frame's tessellation is V's, and
 * a thread for it would only move it). */
static sw_status start_frames(runtime *rt, sw_error *err)
{
    rt->workers = workers_wanted(&rt->opt);
    rt->stats.workers = rt->workers;
    rt->stats.sync_work = rt->opt.sync_work;
    rt->stats.target_ms = rt->opt.target_ms;
    size_t need = sw_seam_walk_frame_bytes(&rt->pack, (uint32_t)rt->workers,
                                           rt->opt.fill_crossings) + 4096;
    double limit = rt->opt.memory_mb * 1024.0 * 1024.0;
    if ((double)(rt->arena.size + need) > limit)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "with --workers %d needs %.1f MiB of memory "
                            "(the arena %.1f and the frames' and workers' %.1f), more than "
                            "--memory-mb %.1f", rt->workers,
                            (rt->arena.size + need) / 1048576.0, rt->arena.size / 1048576.0,
                            need / 1048576.0, rt->opt.memory_mb);
    if (!(rt->frame_block = sw_heap_take_block(need)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes for the frames", need);
    sw_arena_init(&rt->frame_arena, rt->frame_block, need);
    sw_arena_touch(&rt->frame_arena);   /* resident from the start, as the arena */
    rt->seam.sync_work = rt->opt.sync_work;
    sw_status st = SW_OK;
    if (rt->workers > 0) {
        st = sw_seam_walk_start_workers(&rt->seam, (uint32_t)rt->workers, rt->opt.target_ms,
                                        &rt->arena, &rt->frame_arena, err);
        sw_seam_walk_slow_workers(&rt->seam, rt->opt.slow_workers_ms);
    }
    int threaded = rt->workers > 0 && rt->opt.visibility_thread;
    rt->stats.visibility_thread = threaded;
    if (st == SW_OK) {
        rt->vis_up = 1;
        st = sw_seam_visibility_start(&rt->vis, &rt->seam, threaded, rt->opt.sync_work,
                                      &rt->frame_arena, err);
    }
    return st;
}

/* The seam walk, from the same arena: the header's runtime_bytes counted
 * it (the reader checked that against the loaded graph). The drawn-seam
 * check and the crossing fans come from the arena too, counted with the
 * run's other extras (arena_bytes_needed). */
static sw_status init_seams(runtime *rt, sw_error *err)
{
    if (!rt->pack.seam_header)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: the pack has no Seam Graph (build it "
                            "again with this seamwalk-pack)", rt->opt.pack_path);
    size_t before = rt->arena.used;
    rt->stats.seam_active_min = UINT32_MAX;
    sw_status st = sw_seam_walk_init(&rt->seam, &rt->pack, &rt->arena, rt->opt.max_error_px, err);
    rt->walk_bytes = rt->arena.used - before;
    rt->seam.no_cache = rt->opt.no_cache;
    rt->seam.cull_brute = rt->opt.cull_brute;
    /* Cone culling removes only what the renderer would not draw: back
     * faces, when they are hidden (sw_renderer_set_back_hidden). */
    if (st == SW_OK && rt->opt.back_hidden && rt->opt.cone_cull)
        st = sw_seam_walk_enable_cones(&rt->seam, &rt->arena, err);
    rt->stats.cull_method = rt->opt.cull_brute ? "brute" : "tree";
    rt->stats.cone_cull = rt->seam.cone_cull;
    rt->stats.cull_tree_ms = rt->seam.cull_tree_ms;
    rt->stats.cones_ms = rt->seam.cones_ms;
    if (st == SW_OK)
        st = sw_seam_drawn_init(&rt->drawn, &rt->model_box, rt->pack.seam.tolerance,
                                SW_DRAWN_EDGES, SW_SEAM_WALK_INDICES, &rt->arena, err);
    if (st == SW_OK && rt->opt.fill_crossings)
        st = sw_seam_fill_init(&rt->fill, SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES,
                               &rt->arena, err);
    rt->seam.drawn = &rt->drawn;
    rt->seam.fill = rt->opt.fill_crossings ? &rt->fill : NULL;
    rt->stats.start_walk_init_ms = lap_ms(&rt->mark_s);
    if (st == SW_OK)
        st = start_frames(rt, err);
    rt->stats.start_workers_ms = lap_ms(&rt->mark_s);
    return st;
}

static sw_status size_arena(runtime *rt, size_t *path_bytes, sw_error *err)
{
    sw_pack_header h;
    sw_status st = sw_pack_read_header(rt->opt.pack_path, &h, err);
    if (st != SW_OK)
        return st;
    size_t keys = 0;
    *path_bytes = 0;
    if (rt->opt.path_file) {
        if ((st = file_size(rt->opt.path_file, path_bytes, err)) != SW_OK)
            return st;
        keys = *path_bytes / 20 + 1; /* a key line has at least 10 numbers and 10 separators */
    }
    if (rt->opt.png_dir)
        rt->png_scratch = sw_png_scratch_bytes(rt->opt.width, rt->opt.height, 3);
    double limit = rt->opt.memory_mb * 1024.0 * 1024.0;
    /* Checked alone first so a huge header value cannot overflow the sum. */
    size_t need = (double)h.runtime_bytes > limit ? SIZE_MAX
                                                  : arena_bytes_needed(rt, &h, *path_bytes, keys);
    if (need == SIZE_MAX)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "the pack alone needs %.1f MiB, more than --memory-mb %.1f",
                            h.runtime_bytes / (1024.0 * 1024.0), rt->opt.memory_mb);
    if ((double)need > limit)
        return sw_error_set(err, SW_ERR_NO_MEMORY,
                            "needs %.1f MiB of memory (%zu bytes), more than --memory-mb %.1f",
                            need / (1024.0 * 1024.0), need, rt->opt.memory_mb);
    rt->block = sw_heap_take_block(need);
    if (!rt->block)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes for the arena", need);
    sw_arena_init(&rt->arena, rt->block, need);
    /* Not touched here: written whole at start it cost the showroom's
     * start about a second (383 MiB); walk() makes it resident after the
     * first loop instead, with the heap, so no page of it arrives later as
     * caches fill. */
    return SW_OK;
}

static sw_box pack_box(const sw_pack *p)
{
    return (sw_box){ sw_v3(p->meta->box_min[0], p->meta->box_min[1], p->meta->box_min[2]),
                     sw_v3(p->meta->box_max[0], p->meta->box_max[1], p->meta->box_max[2]) };
}

static sw_status find_view(runtime *rt, sw_error *err)
{
    for (uint32_t i = 0; i < rt->pack.viewpoint_count; i++)
        if (!strcmp(rt->pack.viewpoints[i].name, rt->opt.view_name)) {
            rt->view = &rt->pack.viewpoints[i];
            if (rt->view->fov_deg > 0)
                rt->opt.fov_deg = rt->view->fov_deg;
            return SW_OK;
        }
    return sw_error_set(err, SW_ERR_ARG, "%s has no viewpoint named '%s' (it has %u%s)",
                        rt->opt.pack_path, rt->opt.view_name, rt->pack.viewpoint_count,
                        rt->pack.viewpoint_count ? ": see seamwalk-pack info" : "");
}

static sw_status start_kiosk(runtime *rt, sw_error *err)
{
    rt->kiosk_up = 1;
    return sw_kiosk_run_start(&rt->kiosk, &rt->opt, rt->display, &rt->frame, &rt->model_box,
                              rt->pack.viewpoints, rt->pack.viewpoint_count,
                              rt->opt.fov_deg * SW_PI / 180.0,
                              (double)rt->opt.width / rt->opt.height, err);
}

static sw_status start(runtime *rt, sw_error *err)
{
    size_t path_bytes;
    sw_status st = size_arena(rt, &path_bytes, err);
    if (st != SW_OK)
        return st;
    double t0 = now_s();
    if ((st = sw_pack_load(rt->opt.pack_path, &rt->arena, &rt->pack, err)) != SW_OK)
        return st;
    if (rt->opt.store_dir &&
        (st = sw_boot_check_loaded(&rt->boot, rt->loading_slot, &rt->pack, err)) != SW_OK)
        return st;
    rt->stats.pack_open_ms = (now_s() - t0) * 1000.0;
    if (rt->pack.meta->patch_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: the pack has no patches to show",
                            rt->opt.pack_path);
    rt->model_box = pack_box(&rt->pack);
    rt->frame = sw_camera_frame_for_up(sw_up_axis_vector(sw_pack_up_axis(&rt->pack)));
    if (rt->opt.path_file && (st = load_path(rt, path_bytes, err)) != SW_OK)
        return st;
    if (rt->opt.view_name && (st = find_view(rt, err)) != SW_OK)
        return st;
    if ((rt->opt.navigate || rt->opt.input_timeline) && (st = start_kiosk(rt, err)) != SW_OK)
        return st;
    double pack_ms = rt->stats.pack_open_ms;
    if ((st = sw_stats_init(&rt->stats, &rt->arena, rt->opt.frames, rt->opt.max_error_px, err)))
        return st;
    rt->stats.pack_open_ms = pack_ms;
    rt->stats.start_display_ms = rt->display_ms;
    rt->stats.start_prepare_ms = lap_ms(&rt->mark_s) - pack_ms;
    if ((st = init_seams(rt, err)) != SW_OK)
        return st;
    if (rt->opt.png_dir) {
        rt->pixels = sw_arena_alloc(&rt->arena, (size_t)rt->opt.width * rt->opt.height * 4, 64);
        if (!rt->pixels)
            return sw_error_set(err, SW_ERR_NO_MEMORY, "arena too small for the read-back");
        if (mkdir(rt->opt.png_dir, 0777) != 0 && errno != EEXIST)
            return sw_error_set(err, SW_ERR_IO, "%s: %s", rt->opt.png_dir, strerror(errno));
    }
    rt->depth_bits = sw_display_depth_bits(rt->display);
    rt->stats.depth_bits = rt->depth_bits;
    if (rt->opt.drop_surface >= 0)
        rt->seam.drop_surface = (uint32_t)rt->opt.drop_surface;
    if ((st = sw_renderer_init(&rt->renderer, SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES,
                                 err)))
        return st;
    rt->renderer_up = 1;
    if (rt->opt.back_flat)
        sw_renderer_set_back_color(&rt->renderer, rt->opt.back_color);
    sw_renderer_set_back_hidden(&rt->renderer, rt->opt.back_hidden);
    if ((st = sw_gl_pool_init(&rt->pool, rt->seam.cache.vertices, rt->seam.cache.indices,
                              (uint32_t)rt->opt.batch_tris, err)))
        return st;
    rt->pool_up = 1;
    rt->stats.start_gl_ms = lap_ms(&rt->mark_s);
    return sw_grow_hook_init(&rt->grow, (size_t)rt->opt.test_grow_kb * 1024, SW_STATS_RSS_LOOPS,
                             err);
}

static sw_vec3 vec3_of(const float v[3]) { return sw_v3(v[0], v[1], v[2]); }

static sw_camera_pose pose_at(const runtime *rt, int frame)
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

static sw_status write_png(runtime *rt, int frame, sw_error *err)
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
                        (size_t)rt->opt.width * 3, &rt->arena, err);
}

/* The plan's view with near and far fitted to what the walk selected
 * (sw_seam_depth.h, in the plan), so the depth buffer's bits go where the
 * model is; its projection starts the frame. */
static sw_view begin_frame(runtime *rt, const sw_seam_plan *plan)
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
static sw_status seam_frame(runtime *rt, int measuring, uint64_t *triangles, uint32_t *drawn,
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
    double check_s = now_s();
    if (measuring) /* measurement, like the walk's own: not part of the frame's time */
        add_drawn(&rt->stats, &rt->drawn);
    *triangles = f.triangles;
    *swapped = (int)f.batches_committed;
    *drawn = f.drawn_surfaces;
    *capped = f.capped_surfaces;
    *measure_ms = f.measure_ms + (now_s() - check_s) * 1000.0;
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
    if (f.cracks > s->cracks_max)   /* counted every frame: a refused surface is one */
        s->cracks_max = f.cracks;
    if (f.fill_triangles > s->fill_triangles_max)
        s->fill_triangles_max = f.fill_triangles;
    if (f.crossings > s->seam_crossings_max)
        s->seam_crossings_max = f.crossings;
    sw_stats_add_cache_frame(s, f.retessellated, f.retess_triangles, f.upload_bytes, f.evicted,
                             f.tess_ms);
    sw_stats_add_cull_frame(s, f.cull_box_tests, f.cone_culled, f.cull_ms);
    if (rt->workers)
        sw_stats_add_threads_frame(s, f.waiting_surfaces, f.behind_surfaces, f.frames_behind,
                                   f.behind_ratio, f.jobs_scheduled, f.jobs_prefetch,
                                   f.batches_committed,
                                   f.seam_ops, f.budget_tris, f.budget_used);
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
static int walking(const runtime *rt, uint64_t f, double t0)
{
    if (rt->opt.duration_s > 0)
        return now_s() - t0 < rt->opt.duration_s;
    return f < (uint64_t)rt->opt.frames;
}

/* Frame f's view (the input step runs here, with --navigate) posted to V.
 * With --test-stall-workers F the workers stall before V selects frame F. */
static void post_view(runtime *rt, uint64_t f)
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
static sw_status run_frame(runtime *rt, uint64_t f, sw_error *err)
{
    int frame = (int)(f % (uint64_t)rt->opt.frames);
    if (rt->opt.duration_s > 0 || f + 1 < (uint64_t)rt->opt.frames)
        post_view(rt, f + 1);
    double t0 = now_s();
    int measuring = frame % rt->opt.measure_every == 0;
    uint64_t triangles = 0;
    uint32_t drawn = 0, capped = 0;
    double measure_ms = 0;
    int swapped = 0;
    sw_status st = seam_frame(rt, measuring, &triangles, &drawn, &capped, &measure_ms, &swapped,
                              err);
    if (st != SW_OK)
        return st;
    sw_gl_pool_finish(&rt->pool);
    double ms = (now_s() - t0) * 1000.0 - measure_ms;
    int first = rt->stats.frames_total == 0;
    sw_stats_add_frame(&rt->stats, ms, (uint32_t)triangles, drawn);
    sw_seam_visibility_done(&rt->vis, ms, swapped);
    if (first) { /* less the measurement, as every frame's time */
        rt->stats.first_frame_ms = (now_s() - rt->start_s) * 1000.0 - measure_ms;
        rt->stats.start_frame_ms = lap_ms(&rt->mark_s) - measure_ms;
    }
    if (capped > rt->stats.capped_patches_max)
        rt->stats.capped_patches_max = capped;
    if (rt->opt.png_dir && frame % rt->opt.png_every == 0 &&
        (st = write_png(rt, frame, err)) != SW_OK)
        return st;
    return sw_display_present(rt->display, err);
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

static sw_status walk(runtime *rt, sw_error *err)
{
    process_count_fn process = process_alloc_counter();
    uint64_t allocs_before = sw_alloc_count_allocs();
    uint64_t process_before = process ? process() : 0;
    sw_stats *s = &rt->stats;
    s->duration_s = rt->opt.duration_s;
    s->rss_start_kb = rss_now_kb(s);
    double t0 = now_s();
    post_view(rt, 0);
    for (uint64_t f = 0; walking(rt, f, t0); f++) {
        sw_status st = run_frame(rt, f, err);
        if (st != SW_OK)
            return st;
        if ((f + 1) % (uint64_t)rt->opt.frames == 0 && ++s->loops <= SW_STATS_RSS_LOOPS) {
            sw_grow_hook_step(&rt->grow);
            /* The driver's heap is sized by now: resident from here on, and
             * the arena with it (no allocation; without it, a kernel before
             * 5.14, the soak shows the creep it prevents). */
            if (s->loops == 1)
                s->heap_resident = sw_heap_populate() &&
                                   sw_heap_populate_block(rt->block, rt->arena.size);
            s->rss_loop_kb[s->loops - 1] = rss_now_kb(s);
            if (s->loops == 1)
                s->rss_first_loop_kb = s->rss_loop_kb[0];
        }
        if (rt->opt.store_dir)
            sw_boot_poll_good(&rt->boot, now_s() - t0, rt->opt.good_after_s);
        if (rt->display->close_requested)
            break;   /* the window closed, or SIGTERM/SIGINT: end as if the walk were done */
    }
    s->rss_end_kb = rss_now_kb(s);
    s->batch_waits = rt->pool.waits;
    rt->stats.walk_s = now_s() - t0;
    rt->stats.mallocs_after_init = sw_alloc_count_active()
                                       ? (int64_t)(sw_alloc_count_allocs() - allocs_before)
                                       : -1;
    rt->stats.process_mallocs_after_init = process ? (int64_t)(process() - process_before) : -1;
    return SW_OK;
}

/* ---- --store: the unit's pack store (sw_boot.h) ---------------------------- */

/* Back to before start(), keeping the options, the boot and the display,
 * so the next slot can be tried from scratch (a display that works is not
 * the slot's fault). */
static void stop_walk(runtime *rt);
static void reset_runtime(runtime *rt)
{
    stop_walk(rt);
    sw_options opt = rt->opt;
    double start_s = rt->start_s, mark_s = rt->mark_s, display_ms = rt->display_ms;
    sw_boot boot = rt->boot;
    sw_display *display = rt->display;
    memset(rt, 0, sizeof *rt);
    rt->opt = opt;
    rt->start_s = start_s;
    rt->mark_s = mark_s;
    rt->display_ms = display_ms;
    rt->boot = boot;
    rt->display = display;
}

/* No slot starts: a block for the stats and the read-back of the message
 * screen (sw_message_screen.h), on the display main opened. */
static sw_status start_message(runtime *rt, sw_error *err)
{
    rt->no_pack = 1;
    size_t pixels = (size_t)rt->opt.width * rt->opt.height * 4;
    rt->png_scratch = rt->opt.png_dir ? sw_png_scratch_bytes(rt->opt.width, rt->opt.height, 3) : 0;
    size_t need = sw_stats_arena_bytes(rt->opt.frames) + sw_arena_worst_case(pixels, 64) +
                  rt->png_scratch + 4096;
    if (!(rt->block = sw_heap_take_block(need)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes", need);
    sw_arena_init(&rt->arena, rt->block, need);
    sw_status st = sw_stats_init(&rt->stats, &rt->arena, rt->opt.frames, rt->opt.max_error_px, err);
    if (st != SW_OK)
        return st;
    rt->pixels = sw_arena_alloc(&rt->arena, pixels, 64);
    if (rt->opt.png_dir && mkdir(rt->opt.png_dir, 0777) != 0 && errno != EEXIST)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", rt->opt.png_dir, strerror(errno));
    return SW_OK;
}

/* The pending slot on trial (its attempt already counted), then the good
 * one; a slot that does not load or verify is logged and the next tried. */
static sw_status start_from_store(runtime *rt, sw_error *err)
{
    sw_boot_begin(&rt->boot, rt->opt.store_dir, rt->opt.keys_path,
                  (uint32_t)rt->opt.boot_attempts);
    int slots[2], n = sw_boot_candidates(&rt->boot, slots);
    for (int i = 0; i < n; i++) {
        rt->loading_slot = slots[i];
        rt->opt.pack_path = sw_boot_prepare(&rt->boot, slots[i]);
        sw_error slot_err = { 0 };
        if (start(rt, &slot_err) == SW_OK) {
            sw_boot_started(&rt->boot, slots[i]);
            return SW_OK;
        }
        sw_boot_note(&rt->boot, "slot %c does not start: %s", sw_slot_letter(slots[i]),
                     slot_err.message);
        reset_runtime(rt);
    }
    sw_boot_note(&rt->boot, "no valid pack in %s: showing the message screen",
                 rt->opt.store_dir);
    return start_message(rt, err);
}

/* The message screen for --frames frames, read back like a walk's. */
static sw_status show_message(runtime *rt, sw_error *err)
{
    double t0 = now_s();
    for (int f = 0; f < rt->opt.frames; f++) {
        double f0 = now_s();
        sw_message_screen_draw(rt->opt.width, rt->opt.height, "NO VALID PACK");
        sw_status st = sw_display_read_rgba(rt->display, rt->pixels, err);
        if (st != SW_OK)
            return st;
        sw_stats_add_frame(&rt->stats, (now_s() - f0) * 1000.0, 0, 0);
        if (rt->opt.png_dir && f % rt->opt.png_every == 0 && (st = write_png(rt, f, err)))
            return st;
        if ((st = sw_display_present(rt->display, err)) != SW_OK)
            return st;
        if (rt->display->close_requested)
            break;
    }
    rt->stats.walk_s = now_s() - t0;
    rt->stats.mallocs_after_init = -1; /* not counted: this is no walk */
    return SW_OK;
}

static void store_stats(runtime *rt)
{
    sw_stats *s = &rt->stats;
    if (rt->boot.trial && !rt->boot.marked_good)
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

static sw_status write_stats(runtime *rt, sw_error *err)
{
    sw_stats *s = &rt->stats;
    if (rt->opt.store_dir)
        store_stats(rt);
    s->patches_total = rt->pack.meta ? rt->pack.meta->patch_count : 0;
    s->measure_every = rt->opt.measure_every;
    s->arena_bytes = rt->arena.size + rt->frame_arena.size;
    s->arena_peak_bytes = rt->arena.peak + rt->frame_arena.peak;
    if (rt->seam.workers) {
        sw_seam_workers *p = rt->seam.workers;
        s->worker_triangles = atomic_load(&p->made_triangles);
        s->worker_busy_ms = (double)atomic_load(&p->busy_ns) * 1e-6;
        s->worker_steals = atomic_load(&p->steals);
    }
    s->seam_arena_bytes = rt->pack.seam_header ? sw_seam_walk_arena_bytes(&rt->pack) : 0;
    s->seam_arena_peak_bytes = rt->walk_bytes;
    s->runtime_bytes = rt->pack.header ? rt->pack.header->runtime_bytes : 0;
    s->width = rt->opt.width;
    s->height = rt->opt.height;
    if (!rt->opt.stats_path)
        return SW_OK;
    FILE *f = fopen(rt->opt.stats_path, "w");
    if (!f)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", rt->opt.stats_path, strerror(errno));
    sw_status st = sw_stats_write_json(s, f, &rt->arena, err);
    if (fclose(f) != 0 && st == SW_OK)
        st = sw_error_set(err, SW_ERR_IO, "%s: %s", rt->opt.stats_path, strerror(errno));
    return st;
}

static void stop_walk(runtime *rt)
{
    if (rt->kiosk_up)
        sw_kiosk_run_stop(&rt->kiosk);
    rt->kiosk_up = 0;
    if (rt->vis_up)   /* V first: it may be waiting for the workers' first batch */
        sw_seam_visibility_stop(&rt->vis);
    rt->vis_up = 0;
    sw_seam_walk_stop_workers(&rt->seam);
    sw_heap_give_block(rt->frame_block, rt->frame_arena.size);
    rt->frame_block = NULL;
    if (rt->pool_up)
        sw_gl_pool_destroy(&rt->pool);
    if (rt->renderer_up)
        sw_renderer_destroy(&rt->renderer);
    rt->pool_up = rt->renderer_up = 0;
    sw_grow_hook_destroy(&rt->grow);
    sw_heap_give_block(rt->block, rt->arena.size);
    rt->block = NULL;
}

/* Before anything else, because a KMS display decides the size (its mode)
 * that the arena's read-back and the view are made for. */
static sw_status open_display(runtime *rt, sw_error *err)
{
    sw_display_desc desc = {.kind = rt->opt.display, .width = rt->opt.width,
                            .height = rt->opt.height, .max_depth_bits = rt->opt.depth_bits};
    sw_status st = sw_display_init(rt->display, &desc, err);
    if (st != SW_OK)
        return st;
    rt->opt.width = rt->display->width;
    rt->opt.height = rt->display->height;
    return SW_OK;
}

static void print_summary(const runtime *rt)
{
    const sw_stats *s = &rt->stats;
    printf("seamwalk: %llu frames of %u patches at %dx%d in %.2f s; error max %.3f px (bound %.2f);"
           " cracks max %llu; arena %.1f MiB (the pack's runtime_bytes %.1f MiB, the run's"
           " frame stats and pictures the rest); mallocs after init %lld\n",
           (unsigned long long)s->frames_total, s->patches_total, s->width, s->height, s->walk_s, s->error_max_px,
           s->error_bound_px, (unsigned long long)s->cracks_max, s->arena_bytes / 1048576.0,
           s->runtime_bytes / 1048576.0, (long long)s->mallocs_after_init);
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

int main(int argc, char **argv)
{
    static runtime rt;
    static sw_display display;   /* stays put: window listeners point into it */
    sw_error err = { SW_OK, "" };
    rt.display = &display;
    rt.start_s = now_s();
    sw_status st = sw_options_parse(argc, argv, &rt.opt, &err);
    if (st != SW_OK || rt.opt.help) {
        if (st != SW_OK)
            fprintf(stderr, "seamwalk: %s\n", err.message);
        sw_options_print_usage(argv[0]);
        return st != SW_OK ? 2 : 0;
    }
    /* A service stop (SIGTERM) or Ctrl-C ends the walk after the frame, so
     * the stats are written and a KMS display gives the screen back. */
    struct sigaction stop_walk_on = {.sa_handler = sw_display_close_on_signal};
    sigaction(SIGTERM, &stop_walk_on, NULL);
    sigaction(SIGINT, &stop_walk_on, NULL);
    rt.mark_s = rt.start_s;
    /* A batch's worth of scene (sw_gl_pool.h) as the heap's steps. */
    sw_heap_keep((size_t)rt.opt.batch_tris * SW_GL_POOL_SCENE_BYTES_PER_TRIANGLE);
    st = open_display(&rt, &err);
    rt.display_ms = lap_ms(&rt.mark_s);
    if (st == SW_OK)
        st = rt.opt.store_dir ? start_from_store(&rt, &err) : start(&rt, &err);
    if (st == SW_OK)
        st = rt.no_pack ? show_message(&rt, &err) : walk(&rt, &err);
    if (st == SW_OK)
        st = write_stats(&rt, &err);
    if (st == SW_OK && !rt.no_pack)
        print_summary(&rt);
    else if (st != SW_OK)
        fprintf(stderr, "seamwalk: %s\n", err.message);
    stop_walk(&rt);
    if (display.up)
        sw_display_destroy(&display);
    /* 3: the unit had no pack to show and showed the message screen instead. */
    return st != SW_OK ? 1 : rt.no_pack ? 3 : 0;
}
