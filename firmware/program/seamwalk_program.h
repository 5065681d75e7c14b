/* SPDX-License-Identifier: MIT */
/* The seamwalk program's state, shared by its two files: the start-up
 * (seamwalk_start.c: memory, the pack, the display, the GL, the threads)
 * and the walk (seamwalk_main.c: the frame loop, the stats). Not a library
 * module: one program owns one of these, in main. */
#ifndef SEAMWALK_PROGRAM_H
#define SEAMWALK_PROGRAM_H

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>

#include "sw_arena.h"
#include "sw_boot.h"
#include "sw_notify.h"
#include "sw_camera_path.h"
#include "sw_display.h"
#include "sw_error.h"
#include "sw_gl_pool.h"
#include "sw_grow_hook.h"
#include "sw_kiosk_run.h"
#include "sw_options.h"
#include "sw_pack.h"
#include "sw_renderer.h"
#include "sw_seam_drawn.h"
#include "sw_seam_fill.h"
#include "sw_seam_visibility.h"
#include "sw_seam_walk.h"
#include "sw_stats.h"

typedef struct sw_program {
    sw_options opt;
    sw_arena arena;
    void *block;
    sw_pack pack;             /* the scene walked: a placed pack's expanded */
    sw_pack stored;           /* the pack as read (pack itself without instances) */
    int pack_mapped;          /* the pack file mapped (sw_pack_file_mappable), else copied
                                 into the arena */
    sw_pack_mapping mapping;
    sw_camera_path path;
    sw_seam_walk seam;
    int workers;              /* tessellation threads (--workers, resolved) */
    void *frame_block;        /* the frames' own buffers (plans, measuring scratch, the
                                 workers'): known only once the pack is loaded (its
                                 largest surface), taken at start like the arena */
    sw_arena frame_arena;
    void *readback_block;     /* with --png-dir: the read-back and the PNG writer's
                                 scratch, sized once the display has its size */
    sw_arena readback_arena;
    void *staging_block;      /* the GL pool's merged draws' staging (sw_gl_pool_merge_bytes) */
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
    sw_box model_box;
    sw_camera_frame frame;           /* the orbit's: up is the pack's up axis */
    const sw_pack_viewpoint *view;   /* with --view */
    double start_s;
    double mark_s;            /* the GL thread's start steps: the end of the last one timed */
    double display_ms, gl_ms, load_wait_ms;   /* its steps, kept across sw_stats_init */
    sw_boot boot;             /* with --store: the slot being started, mark-good */
    sw_notify notify;         /* systemd's READY, WATCHDOG and STATUS (sw_notify.h) */
    int loading_slot;         /* with --store: the slot start() loads */
    int no_pack;              /* with --store: no slot started; the message screen runs */
    sw_kiosk_run kiosk;       /* with --navigate or --input-timeline */
    int kiosk_up;
    sw_camera_pose kiosk_pose;   /* this frame's, from the input step */
    /* The loader thread (seamwalk_start.c): the pack and everything made
     * from it without the GL, while the GL thread opens the display. */
    pthread_t loader, gl_thread;
    sw_status load_status;
    sw_error load_err;
} sw_program;

/* Seconds on the monotonic clock. */
double sw_program_now_s(void);

/* Everything before the first frame: the display, and the pack (or, with
 * --store, the first slot that starts, else the message screen) loaded on
 * a thread of its own meanwhile. main opens nothing itself. */
sw_status sw_program_start(sw_program *rt, sw_error *err);

/* The GL buffers for the cache (and the merged draws' staging): the walk
 * calls it once, after posting the first frame's view to V, so writing
 * them overlaps V's planning of that frame. */
sw_status sw_program_start_pool(sw_program *rt, sw_error *err);

/* The refusal of a pack whose arena (need bytes, from its header h) is
 * more than --memory-mb: by how much, and the pack's largest pools
 * (seamwalk_memory_short.c; the pack read again with check on its raw
 * bytes, as the loader reads it). Always SW_ERR_NO_MEMORY. */
sw_status sw_program_memory_short(const sw_program *rt, const sw_pack_header *h, double need,
                                  sw_pack_raw_check check, void *user, sw_error *err);

/* Ends the threads and gives back every block and GL object start took
 * (the display stays: main closes it). Safe after a failed start. */
void sw_program_stop(sw_program *rt);

#endif
