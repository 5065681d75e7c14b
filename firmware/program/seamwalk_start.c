/* SPDX-License-Identifier: MIT */
/* seamwalk's start-up: from the options to the first frame's threads.
 *
 * Two things take most of a start and need nothing of each other: the
 * display (EGL loading Mesa and LLVM, then the renderer's shaders, which
 * llvmpipe compiles at the first draw) and the pack (read into the arena,
 * validated, and the seam walk's state built from it, then the workers and
 * V started). The pack is loaded on a loader thread while the GL thread
 * opens the display and warms the renderer (the pack's checksums and Seam
 * Graph rules in parts, with a helper thread: sw_parts_threads.h, since
 * the GL thread's core is idle long before the loader ends); the GL
 * thread then waits for the loader (stats: start_ms.load_wait). The GL
 * buffers the loaded cache needs are made once the walk has posted its
 * first view, while V plans that frame (sw_program_start_pool). Nothing
 * the loader touches calls GL, and nothing the GL thread touches before
 * the join is the loader's (the display's size decides only the
 * read-back, taken after it). With
 * --store the display is opened first (start_from_store says why) and the
 * loader overlaps the renderer's start only.
 *
 * Memory: the arena is sized from the pack header and the options alone,
 * so the decision to run is made before any allocation; the frames' block
 * once the pack is loaded, the read-back once the display has its size,
 * the merged draws' staging with the GL buffers; all of them count
 * against --memory-mb. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "seamwalk_program.h"
#include "sw_heap.h"
#include "sw_pack_instances.h"
#include "sw_parts_threads.h"
#include "sw_png.h"
#include "sw_thread_name.h"
#include "sw_up_axis.h"
#include "sw_walk_memory.h"

double sw_program_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The time since *mark_s in ms; *mark_s becomes now, so steps add up. */
static double lap_ms(double *mark_s)
{
    double t = sw_program_now_s(), ms = (t - *mark_s) * 1000.0;
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
static size_t arena_bytes_needed(const sw_program *rt, const sw_pack_header *h,
                                 size_t path_bytes, size_t path_keys)
{
    /* runtime_bytes covers every patch's state and the walk (sw_pack.h,
     * core/sw_walk_memory.h); the pack itself when it is copied, not
     * mapped; the rest depends on the options. */
    size_t bytes = (size_t)h->runtime_bytes + sw_stats_arena_bytes(rt->opt.frames) +
                   sw_seam_drawn_arena_bytes(SW_DRAWN_EDGES, SW_SEAM_WALK_INDICES);
    if (!rt->pack_mapped)
        bytes += (size_t)sw_pack_arena_bytes(h->total_size);
    if (rt->opt.fill_crossings)
        bytes += sw_seam_fill_arena_bytes(SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES);
    if (rt->opt.measure_every > 0)   /* the largest cache's (u, v): the header has no more */
        bytes += sw_seam_cache_uv_bytes(SW_WALK_CACHE_MAX);
    bytes += sw_arena_worst_case(path_bytes + 1, 8) +
             sw_arena_worst_case(path_keys * sizeof(sw_camera_key) + 1, 8);
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

static sw_status load_path(sw_program *rt, size_t path_bytes, sw_error *err)
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
_Static_assert(SW_OPTIONS_MAX_WORKERS <= SW_SEAM_WORKERS_MAX,
               "every worker count the options and the config take, the walk can start");

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
static sw_status start_frames(sw_program *rt, sw_error *err)
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
    /* Not written at start (the kernel zeroes each page as it is first
     * touched: tens of MB on the showroom); made resident with the arena
     * after the first loop (seamwalk_main.c). */
    sw_arena_init(&rt->frame_arena, rt->frame_block, need);
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
                                      rt->gl_thread, &rt->frame_arena, err);
    }
    return st;
}

/* The seam walk, from the same arena: the header's runtime_bytes counted
 * it (the reader checked that against the loaded graph). The drawn-seam
 * check and the crossing fans come from the arena too, counted with the
 * run's other extras (arena_bytes_needed). mark_s: the loader's clock. */
static sw_status init_seams(sw_program *rt, double *mark_s, sw_error *err)
{
    if (!rt->pack.seam_header)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: the pack has no Seam Graph (build it "
                            "again with this seamwalk-pack)", rt->opt.pack_path);
    size_t before = rt->arena.used;
    rt->stats.seam_active_min = UINT32_MAX;
    sw_status st = sw_seam_walk_init(&rt->seam, &rt->pack, &rt->stored, &rt->arena,
                                     rt->opt.max_error_px, err);
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
    if (st == SW_OK && rt->opt.measure_every > 0)
        st = sw_seam_cache_keep_uvs(&rt->seam.cache, &rt->arena, err);
    rt->seam.drawn = &rt->drawn;
    rt->seam.fill = rt->opt.fill_crossings ? &rt->fill : NULL;
    rt->seam.standin_silhouettes = rt->opt.standin_silhouettes;
    if (st == SW_OK && rt->opt.drop_surface >= 0)
        rt->seam.drop_surface = (uint32_t)rt->opt.drop_surface;
    if (st == SW_OK && rt->opt.cache_vertices > 0)
        sw_seam_walk_shrink_cache(&rt->seam, (uint32_t)rt->opt.cache_vertices);
    rt->seam.no_pressure = !rt->opt.pressure;
    rt->seam.no_standins = !rt->opt.static_levels;
    rt->seam.no_part_levels = !rt->opt.part_levels;
    rt->seam.no_leaner_standins = !rt->opt.leaner_standins;
    rt->seam.part_levels_coarsest = rt->opt.part_levels_coarsest;
    rt->stats.start_walk_init_ms = lap_ms(mark_s);
    if (st == SW_OK)
        st = start_frames(rt, err);
    rt->stats.start_workers_ms = lap_ms(mark_s);
    return st;
}

/* --store: a slot's signature, on its raw bytes, before any is parsed. */
static sw_status check_slot(void *user, const uint8_t *bytes, size_t size, sw_error *err)
{
    const sw_program *rt = user;
    return sw_boot_check_raw(&rt->boot, rt->loading_slot, bytes, size, err);
}

static sw_status size_arena(sw_program *rt, size_t *path_bytes, sw_error *err)
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
    double limit = rt->opt.memory_mb * 1024.0 * 1024.0;
    rt->pack_mapped = sw_pack_file_mappable(rt->opt.pack_path);
    double copied = rt->pack_mapped ? 0.0 : (double)h.total_size;
    /* Checked alone first so a huge header value cannot overflow the sum. */
    size_t need = (double)h.runtime_bytes + copied > limit
                      ? SIZE_MAX
                      : arena_bytes_needed(rt, &h, *path_bytes, keys);
    if (need == SIZE_MAX || (double)need > limit) {
        double asked = need == SIZE_MAX ? (double)h.runtime_bytes + copied : (double)need;
        return sw_program_memory_short(rt, &h, asked, rt->opt.store_dir ? check_slot : NULL,
                                       (void *)rt, err);
    }
    rt->block = sw_heap_take_block(need);
    if (!rt->block)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes for the arena", need);
    sw_arena_init(&rt->arena, rt->block, need);
    /* Not touched here: written whole at start it cost the showroom's
     * start about a second (383 MiB); the walk makes it resident after the
     * first loop instead, with the heap, so no page of it arrives later as
     * caches fill. */
    return SW_OK;
}

static sw_box pack_box(const sw_pack *p)
{
    return (sw_box){ sw_v3(p->meta->box_min[0], p->meta->box_min[1], p->meta->box_min[2]),
                     sw_v3(p->meta->box_max[0], p->meta->box_max[1], p->meta->box_max[2]) };
}

static sw_status find_view(sw_program *rt, sw_error *err)
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

/* Threads beside the loader for the pack's checks (sw_parts_threads.h): a
 * core each, less the GL thread's, at least one and at most three (the
 * Seam Graph's rules are nine parts); the GL thread is idle once its
 * shaders are warm, before the Seam Graph's checks begin. */
static long load_helpers(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return cores > 5 ? 3 : cores > 2 ? cores - 2 : 1;
}

/* The loader's whole job, on its own thread: nothing here calls GL or
 * reads what the GL thread writes before the join (the display's size). */
static sw_status load(sw_program *rt, sw_error *err)
{
    double mark_s = sw_program_now_s();
    size_t path_bytes;
    sw_status st = size_arena(rt, &path_bytes, err);
    if (st != SW_OK)
        return st;
    double t0 = sw_program_now_s();
    sw_parts_threads threads;
    sw_parts_runner runner = sw_parts_threads_runner(&threads, (uint32_t)load_helpers());
    sw_pack_raw_check check = rt->opt.store_dir ? check_slot : NULL;
    st = rt->pack_mapped ? sw_pack_map_checked(rt->opt.pack_path, &runner, check, rt,
                                               &rt->mapping, &rt->pack, err)
                         : sw_pack_load_checked(rt->opt.pack_path, &rt->arena, &runner, check,
                                                rt, &rt->pack, err);
    /* A pack of placed parts is walked as the scene it places. */
    if (st == SW_OK) {
        rt->stored = rt->pack;
        if ((st = sw_pack_expand_shared(&rt->stored, &rt->arena, &rt->pack, err)) != SW_OK)
            sw_error_prefix(err, "%s", rt->opt.pack_path);
    }
    if (st != SW_OK)
        return st;
    double pack_ms = (sw_program_now_s() - t0) * 1000.0;
    if (rt->pack.meta->patch_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "%s: the pack has no patches to show",
                            rt->opt.pack_path);
    rt->model_box = pack_box(&rt->pack);
    rt->frame = sw_camera_frame_for_up(sw_up_axis_vector(sw_pack_up_axis(&rt->pack)));
    if (rt->opt.path_file && (st = load_path(rt, path_bytes, err)) != SW_OK)
        return st;
    if (rt->opt.view_name && (st = find_view(rt, err)) != SW_OK)
        return st;
    if ((st = sw_stats_init(&rt->stats, &rt->arena, rt->opt.frames, rt->opt.max_error_px, err)))
        return st;
    rt->stats.pack_open_ms = pack_ms;
    rt->stats.start_prepare_ms = lap_ms(&mark_s) - pack_ms;
    return init_seams(rt, &mark_s, err);
}

static void *loader_main(void *arg)
{
    sw_program *rt = arg;
    sw_thread_name("sw-loader");
    rt->load_status = load(rt, &rt->load_err);
    return NULL;
}

static sw_status open_display(sw_program *rt, sw_error *err)
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

/* The GL thread's part while the loader runs: the display (once: kept
 * across --store's slots), the renderer, and its shaders compiled by a
 * draw (sw_renderer_warm_up) instead of in the first frame. */
static sw_status start_gl(sw_program *rt, sw_error *err)
{
    sw_status st = SW_OK;
    if (!rt->display->up) {
        st = open_display(rt, err);
        rt->display_ms = lap_ms(&rt->mark_s);
        if (st != SW_OK)
            return st;
    }
    rt->depth_bits = sw_display_depth_bits(rt->display);
    if ((st = sw_renderer_init(&rt->renderer, SW_SEAM_WALK_VERTICES, SW_SEAM_WALK_INDICES,
                               err)))
        return st;
    rt->renderer_up = 1;
    if (rt->opt.back_flat)
        sw_renderer_set_back_color(&rt->renderer, rt->opt.back_color);
    sw_renderer_set_back_hidden(&rt->renderer, rt->opt.back_hidden);
    sw_renderer_warm_up(&rt->renderer, rt->opt.width, rt->opt.height);
    rt->gl_ms = lap_ms(&rt->mark_s);
    return st;
}

/* The GL buffers the cache lays its meshes out in, and the merged draws'
 * staging (sw_gl_pool.h), held to --memory-mb with the other blocks. The
 * walk makes them once V is planning the first frame (seamwalk_main.c):
 * writing the buffers once (their pages taken now, not in a soak) is the
 * GL thread's longest start step, 112 MB on the showroom. */
sw_status sw_program_start_pool(sw_program *rt, sw_error *err)
{
    double mark_s = sw_program_now_s();
    uint32_t vertices = rt->seam.cache.vertices, indices = rt->seam.cache.indices;
    rt->stats.pool_vertices = vertices, rt->stats.pool_indices = indices;
    sw_status st = sw_gl_pool_init(&rt->pool, vertices, indices, (uint32_t)rt->opt.batch_tris,
                                   err);
    if (st != SW_OK)
        return st;
    rt->pool_up = 1;
    const sw_part_levels *pl = &rt->pack.part_levels;
    if (rt->opt.part_levels && pl->levels &&
        (st = sw_gl_pool_resident(&rt->pool, (const sw_vertex *)pl->vertices, pl->vertex_count,
                                  pl->indices, pl->index_count, err)) != SW_OK)
        return st;
    if ((rt->staging_block = sw_heap_take_block(sw_gl_pool_merge_bytes())))
        sw_gl_pool_merge_start(&rt->pool, rt->staging_block);   /* else a draw a mesh */
    size_t total = rt->arena.size + rt->frame_arena.size + rt->readback_arena.size +
                   (rt->staging_block ? sw_gl_pool_merge_bytes() : 0);
    if ((double)total > rt->opt.memory_mb * 1024.0 * 1024.0)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "with the %dx%d read-back and the merged "
                            "draws' staging needs %.1f MiB of memory, more than --memory-mb "
                            "%.1f", rt->opt.width, rt->opt.height, total / 1048576.0,
                            rt->opt.memory_mb);
    rt->stats.start_gl_ms += (sw_program_now_s() - mark_s) * 1000.0;
    return SW_OK;
}

/* With --png-dir (or for the message screen, always): the read-back and
 * the PNG writer's scratch, in a block of their own now the size is
 * known, counted against --memory-mb with the rest. */
static sw_status take_readback(sw_program *rt, int always, sw_error *err)
{
    if (!rt->opt.png_dir && !always)
        return SW_OK;
    size_t pixels = (size_t)rt->opt.width * rt->opt.height * 4;
    size_t scratch = rt->opt.png_dir ? sw_png_scratch_bytes(rt->opt.width, rt->opt.height, 3)
                                     : 0;
    size_t need = sw_arena_worst_case(pixels, 64) + scratch + 4096;
    if (!(rt->readback_block = sw_heap_take_block(need)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes for the read-back",
                            need);
    sw_arena_init(&rt->readback_arena, rt->readback_block, need);
    rt->pixels = sw_arena_alloc(&rt->readback_arena, pixels, 64);
    if (rt->opt.png_dir && mkdir(rt->opt.png_dir, 0777) != 0 && errno != EEXIST)
        return sw_error_set(err, SW_ERR_IO, "%s: %s", rt->opt.png_dir, strerror(errno));
    return SW_OK;
}

static sw_status start_kiosk(sw_program *rt, sw_error *err)
{
    rt->kiosk_up = 1;
    sw_kiosk_run_desc desc = {&rt->opt.config.kiosk, rt->opt.input_timeline, rt->opt.pose_log};
    return sw_kiosk_run_start(&rt->kiosk, &desc, rt->display, &rt->frame, &rt->model_box,
                              rt->pack.viewpoints, rt->pack.viewpoint_count,
                              rt->opt.fov_deg * SW_PI / 180.0,
                              (double)rt->opt.width / rt->opt.height, err);
}

/* After the join, on the GL thread: what needs both the pack and the
 * display. The stats' start steps are set here, sw_stats_init having
 * cleared them. */
static sw_status finish_start(sw_program *rt, sw_error *err)
{
    rt->stats.start_display_ms = rt->display_ms;
    rt->stats.start_load_wait_ms = rt->load_wait_ms;
    rt->stats.depth_bits = rt->depth_bits;
    sw_status st = SW_OK;
    if ((rt->opt.navigate || rt->opt.input_timeline) && (st = start_kiosk(rt, err)) != SW_OK)
        return st;
    if ((st = take_readback(rt, 0, err)) != SW_OK)
        return st;
    rt->stats.start_gl_ms = rt->gl_ms;
    return sw_grow_hook_init(&rt->grow, (size_t)rt->opt.test_grow_kb * 1024, SW_STATS_RSS_LOOPS,
                             err);
}

/* One pack (--pack, or a store slot): the loader started, the GL thread's
 * part meanwhile, the join, the rest. A display that fails is said first,
 * as when it was opened before anything else; then the loader's error. */
static sw_status start_pack(sw_program *rt, sw_error *err)
{
    rt->gl_thread = pthread_self();
    int threaded = pthread_create(&rt->loader, NULL, loader_main, rt) == 0;
    if (!threaded)   /* no thread to be had: the same steps, one after the other */
        loader_main(rt);
    sw_status st = start_gl(rt, err);
    if (threaded)
        pthread_join(rt->loader, NULL);
    rt->load_wait_ms = lap_ms(&rt->mark_s);
    if (st != SW_OK)
        return st;
    if (rt->load_status != SW_OK) {
        *err = rt->load_err;
        return rt->load_status;
    }
    return finish_start(rt, err);
}

/* ---- --store: the unit's pack store (sw_boot.h) ---------------------------- */

/* Back to before start, keeping the options, the boot and the display,
 * so the next slot can be tried from scratch (a display that works is not
 * the slot's fault). */
static void reset_program(sw_program *rt)
{
    sw_program_stop(rt);
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
 * screen (sw_message_screen.h), on the display already open. */
static sw_status start_message(sw_program *rt, sw_error *err)
{
    rt->no_pack = 1;
    size_t need = sw_stats_arena_bytes(rt->opt.frames) + 4096;
    if (!(rt->block = sw_heap_take_block(need)))
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot take %zu bytes", need);
    sw_arena_init(&rt->arena, rt->block, need);
    sw_status st = sw_stats_init(&rt->stats, &rt->arena, rt->opt.frames, rt->opt.max_error_px,
                                 err);
    return st != SW_OK ? st : take_readback(rt, 1, err);
}

/* The display first, before the store is touched: a unit whose display
 * does not come up must not spend its pending slot's boot attempts (the
 * loader then overlaps only the renderer's start). Then the pending slot
 * on trial (its attempt counted by sw_boot_begin), then the good one; a
 * slot that does not load or verify is logged and the next tried. */
static sw_status start_from_store(sw_program *rt, sw_error *err)
{
    sw_status st = open_display(rt, err);
    rt->display_ms = lap_ms(&rt->mark_s);
    if (st != SW_OK)
        return st;
    sw_boot_begin(&rt->boot, rt->opt.store_dir, rt->opt.keys_path,
                  (uint32_t)rt->opt.boot_attempts);
    int slots[2], n = sw_boot_candidates(&rt->boot, slots);
    for (int i = 0; i < n; i++) {
        rt->loading_slot = slots[i];
        rt->opt.pack_path = sw_boot_prepare(&rt->boot, slots[i]);
        sw_error slot_err = { 0 };
        if (start_pack(rt, &slot_err) == SW_OK) {
            sw_boot_started(&rt->boot, slots[i]);
            if (rt->display->kind == SW_DISPLAY_KIND_HEADLESS)
                sw_boot_no_picture(&rt->boot, "the display is headless (no screen shows it)");
            return SW_OK;
        }
        sw_boot_note(&rt->boot, "slot %c does not start: %s", sw_slot_letter(slots[i]),
                     slot_err.message);
        reset_program(rt);
    }
    sw_boot_note(&rt->boot, "no valid pack in %s: showing the message screen",
                 rt->opt.store_dir);
    return start_message(rt, err);
}

sw_status sw_program_start(sw_program *rt, sw_error *err)
{
    rt->mark_s = rt->start_s;
    return rt->opt.store_dir ? start_from_store(rt, err) : start_pack(rt, err);
}

void sw_program_stop(sw_program *rt)
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
    sw_heap_give_block(rt->readback_block, rt->readback_arena.size);
    rt->readback_block = NULL;
    if (rt->pool_up)
        sw_gl_pool_destroy(&rt->pool);
    sw_heap_give_block(rt->staging_block, sw_gl_pool_merge_bytes());
    rt->staging_block = NULL;
    if (rt->renderer_up)
        sw_renderer_destroy(&rt->renderer);
    rt->pool_up = rt->renderer_up = 0;
    sw_grow_hook_destroy(&rt->grow);
    sw_heap_give_block(rt->block, rt->arena.size);
    rt->block = NULL;
    sw_pack_unmap(&rt->mapping);   /* after everything that read the pack */
}
