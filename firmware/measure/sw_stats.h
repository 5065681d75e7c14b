/* SPDX-License-Identifier: MIT */
/* Walk statistics: per-frame samples kept in arena arrays sized at start, an
 * error histogram, and the stats JSON (a contract: fields are added, never
 * renamed). The frame loop records; main writes the file after the walk. */
#ifndef SW_STATS_H
#define SW_STATS_H

#include <stdint.h>
#include <stdio.h>

#include "sw_arena.h"
#include "sw_error.h"

/* Histogram of measured per-sample error in pixels: SW_ERROR_BINS bins of
 * width bin_px from 0, plus an overflow count; p99 is read from it as the
 * upper edge of the bin holding the 99th percentile (so it never
 * understates), while max is kept exactly. */
#define SW_ERROR_BINS 4096

/* Loops of a soak whose resident memory at their end is kept. */
#define SW_STATS_RSS_LOOPS 64

typedef struct sw_stats {
    int frame_capacity, frames; /* frames: samples kept, at most frame_capacity */
    float *frame_ms;            /* per frame: tessellate + draw + finish */
    uint32_t *tris;             /* per frame */
    uint32_t *visible;          /* per frame: patches drawn */
    uint32_t patches_total;

    uint64_t *error_bins;       /* SW_ERROR_BINS */
    double error_bin_px;
    uint64_t error_samples, error_overflow;
    double error_max_px;
    /* Samples of meshes drawn coarser than the view asks while their new
     * ones are being made (the threaded walk's first frame and late work,
     * firmware/walk/sw_seam_walk.h): kept apart from error_px, which is then the
     * error of meshes made for their bounds; route_behind is set by the
     * walk around such a mesh's measurement. */
    int route_behind;
    uint64_t error_behind_samples;
    double error_behind_max_px, error_behind_beyond_sewing_px;
    int measured_frames, measure_every;
    double error_bound_px;

    uint64_t cracks_max;
    uint64_t capped_patches_max; /* patches whose grid hit SW_TESS_MAX_SEGMENTS */
    uint32_t seam_active_min, seam_active_max;       /* active seam vertices per frame */
    uint32_t surfaces_vanished_max, surfaces_failed_max, surfaces_holes_filled_max;
    uint32_t surfaces_untangled_max;
    uint32_t surfaces_clamped_max; /* in view, asking finer than the pack's floor */
    uint64_t seam_crossings_max;  /* T-vertices on seam segments, per frame */
    uint64_t seam_arena_bytes, seam_arena_peak_bytes; /* the seam walk's share of the arena:
                                                         its bound, and what it took */
    double seam_error_beyond_sewing_px; /* measured error beyond each surface's sewing offset */
    double seam_sewing_offset_px;       /* largest sewing offset of a drawn surface, pixels */

    /* The seams as drawn (firmware/walk/gl/sw_seam_drawn.h), the most of a measured frame. */
    uint64_t drawn_points_max, drawn_t_vertices_max, drawn_gaps_max, drawn_free_max;
    int drawn_unchecked_frames;
    uint64_t fill_triangles_max; /* zero-area fans over seam crossings drawn in a frame,
                                    beside tris_per_frame (sw_seam_fill.h) */
    double seam_chord_px_max;    /* seam chords against their surfaces, sw_seam_measure.h */  /* measured frames whose borders overflowed the check */

    /* The depth buffer (platform/sw_egl_headless.h) and the planes fitted
     * to each frame's drawn surfaces (firmware/walk/visibility/sw_seam_depth.h). */
    int depth_bits;
    double depth_far_over_near_max;     /* the largest far / near of a frame: the depth
                                           buffer resolves depth^2 * this / (far * 2^bits) */

    /* The tessellation cache (firmware/walk/sw_seam_walk.h), per frame and in all. */
    uint32_t *retess;            /* per frame: surfaces tessellated */
    float *tess_ms;              /* per frame: of frame_ms, tessellating and uploading */
    uint64_t retess_total, retess_triangles_total, retess_triangles_max;
    uint64_t upload_bytes_total, upload_bytes_max, evictions;
    /* Its pools, in vertices and indices: capacity, the most in use when a
     * frame was planned, and the most the drawn meshes' blocks held. */
    uint64_t pool_vertices, pool_indices;
    uint64_t used_vertices_max, used_indices_max, drawn_vertices_max, drawn_indices_max;
    int frames_without_retess;

    /* Culling (core/sw_cull_tree.h, sw_normal_cone.h), per frame. */
    uint32_t *cull_box_tests;    /* boxes tested against the frustum */
    uint32_t *cone_culled;       /* surfaces in the frustum left out facing away */
    float *cull_ms;              /* of frame_ms, spent on those tests */
    const char *cull_method;     /* "tree" or "brute" (--cull) */
    int cone_cull;               /* cone culling was on (--back-faces hidden) */
    double cull_tree_ms, cones_ms; /* start-up: building the tree and the cones */

    /* With workers (firmware/walk/sw_seam_walk.h, "Threads"): how far the work is
     * behind the view and what of the budget it used. */
    int workers, sync_work;
    uint64_t prefetch_total;     /* jobs for surfaces out of view (w', budget left) */
    int visibility_thread;       /* V on its own thread (sw_seam_visibility.h) */
    float *visibility_ms;        /* per frame (ring, as frame_ms): V's half of the frame */
    float *plan_wait_ms;         /* per frame (ring): P waiting for V's plan */
    uint64_t planned_on_gl_thread;  /* frames whose V half ran on P's thread */
    uint64_t plans_overlapped;   /* frames V began while P still drew the one before */
    double target_ms;
    uint32_t waiting_max;        /* visible surfaces with no mesh yet, the most of a frame */
    uint32_t standins_max;       /* drawn from a static level while their mesh is made */
    uint64_t standins_made;      /* stand-ins made (sw_seam_standin.h) */
    uint64_t standins_coarser;   /* of them, from a coarser level than their target's, for
                                    room */
    uint64_t standins_leaner;    /* jobs giving stand-ins finer than needed the walk's own mesh */
    uint64_t standin_triangles;  /* the stand-ins drew, over every frame */
    uint64_t standin_triangles_max; /* of a frame */
    uint32_t part_levels_max;    /* parts drawn whole from a part level, the most of a frame */
    uint32_t covered_max;        /* surfaces in view drawn by their part's level, the most */
    uint64_t part_level_triangles;   /* the part levels drew, over every frame */
    uint64_t part_level_triangles_max; /* of a frame */
    uint32_t behind_max;         /* drawn from a mesh coarser than the view asks */
    uint32_t frames_behind_max;  /* the longest a drawn surface waited for its work */
    double behind_ratio_max;     /* the most a drawn mesh's bound exceeded the view's */
    uint64_t jobs_total, batches_total, seam_ops_total;
    double budget_used_sum, budget_used_max; /* scheduled over N + M, frames that scheduled */
    uint64_t updated_capped_batches; /* batches opened under M (sw_stats_add_update_cap) */
    uint64_t updated_over_batches;   /* of them, the ones whose update spent more than M */
    double updated_over_max;         /* the most spent over M, as a multiple of M */
    int budget_frames;
    double budget_tris_last;     /* N + M at the end */
    uint64_t worker_triangles, worker_steals;
    double worker_busy_ms;

    /* With --store (firmware/store/sw_boot.h): which slot ran and what the boot did. */
    int store;                   /* the fields below are meaningful */
    char store_slot;             /* 'A', 'B', or '-': no slot started, the message screen ran */
    int store_trial;             /* the slot was the pending one on trial */
    int store_marked_good;       /* 1 marked good in this run, -1 failed to, 0 not (yet) */
    const char *store_log;       /* what the boot did, lines; not owned */
    const char *store_message;   /* the message screen's text, or NULL */

    /* A walk longer than the frame arrays (the soak, seamwalk --duration)
     * keeps its last frame_capacity frames in them, as a ring (the
     * percentiles are of those); these cover every frame. */
    uint64_t frames_total;
    double worst_frame_ms;       /* the slowest frame of all, and its number */
    uint64_t worst_frame;
    double duration_s;           /* --duration, or 0: the walk was --frames long */
    uint64_t loops;              /* times the path was walked to its end */
    /* Resident memory (sw_rss.h), kB, -1 unknown: before the first frame,
     * after the first loop (the GL driver's own buffers are taken by then),
     * at the end, and the process's peak. */
    int64_t rss_start_kb, rss_first_loop_kb, rss_end_kb, rss_peak_kb;
    int64_t rss_end_file_kb, rss_end_anon_kb;   /* of the end's: mapped files', the process's own */
    int64_t rss_loop_kb[SW_STATS_RSS_LOOPS]; /* at the end of each of the first loops */
    int heap_resident;           /* the heap and the arena made resident after the first loop
                                    (sw_heap.h); 0 when no loop follows it */
    uint64_t batch_waits;        /* mid-frame waits for the GL driver (--batch-tris) */

    double pack_open_ms, first_frame_ms, walk_s;
    /* first_frame_ms in its steps, each from the end of the one before:
     * the display, the pack (read, checksums, validation: pack_open_ms), the
     * rest of the start before the walk (camera path, statistics), the
     * walk's init (selection, culling tree, cache), the workers' start, the
     * GL's (renderer and its shaders' first draw, buffer pool), and the
     * first frame itself, less its measurement; -1 a step that did not run.
     * The pack's steps (pack_open to workers) run on a loader thread while
     * the GL thread opens the display and starts the renderer, so the
     * steps overlap: load_wait is how long the GL thread then waited for
     * the loader (seamwalk_start.c). */
    double start_display_ms, start_prepare_ms, start_walk_init_ms, start_workers_ms,
        start_gl_ms, start_frame_ms, start_load_wait_ms;
    uint64_t arena_bytes, arena_peak_bytes;  /* the one arena: every byte the walk uses */
    uint64_t runtime_bytes;      /* of it, the pack header's (patch state, walk) */
    uint64_t pack_bytes;         /* the pack's file: mapped, or copied into the arena */
    int pack_mapped;
    double pressure_max;         /* the walk's bound raised by at most this factor */
    uint32_t pressure_frames;    /* in so many frames (sw_seam_walk_pressure) */
    int64_t mallocs_after_init;  /* -1 when the binary could not count */
    int64_t process_mallocs_after_init; /* the whole process's, Mesa's and libc's too, when
                                           tests/process_alloc_shim.so is preloaded; else -1 */
    int width, height;
} sw_stats;

/* Arena bytes sw_stats_init takes for frames frames. */
size_t sw_stats_arena_bytes(int frames);
sw_status sw_stats_init(sw_stats *s, sw_arena *arena, int frames, double error_bound_px,
                        sw_error *err);

/* One frame; past frame_capacity frames the oldest sample is replaced. */
void sw_stats_add_frame(sw_stats *s, double ms, uint32_t tris, uint32_t visible);
void sw_stats_add_error_px(sw_stats *s, double error_px);
/* The frame's near and far planes. */
void sw_stats_add_depth_range(sw_stats *s, double near_z, double far_z);
/* A batch opened under M (cap > 0) that spent used updated triangles. */
void sw_stats_add_update_cap(sw_stats *s, double used, double cap);

/* The threaded walk's frame: waiting and behind surfaces, frames behind,
 * the bound ratio, jobs and whether a batch was swapped in, the budget. */
/* The threaded walk's stand-ins: drawn this frame, made (coarser of them
 * made from a level coarser than their target's, for room), their
 * triangles, and the jobs scheduled to replace the ones finer than
 * needed. */
void sw_stats_add_standins(sw_stats *s, uint32_t drawn, uint32_t made, uint32_t coarser,
                           uint64_t triangles, uint32_t leaner_jobs);
void sw_stats_add_part_levels(sw_stats *s, uint32_t parts, uint32_t covered, uint64_t triangles);

/* The factor the walk raised its bound by this frame (1: not raised). */
void sw_stats_add_pressure(sw_stats *s, double pressure);

void sw_stats_add_threads_frame(sw_stats *s, uint32_t waiting, uint32_t behind,
                                uint32_t frames_behind, double behind_ratio, uint32_t jobs,
                                uint32_t prefetch, uint32_t batches, uint32_t seam_ops,
                                double budget_tris, double budget_used);

/* The hand-over in the frame sw_stats_add_frame records next: V's time
 * on the frame's plan and P's wait for it. */
void sw_stats_add_visibility_frame(sw_stats *s, double visibility_ms, double plan_wait_ms,
                                   int on_gl_thread, int overlapped);

/* The cache's work in the frame sw_stats_add_frame records next. */
void sw_stats_add_cache_frame(sw_stats *s, uint32_t surfaces, uint64_t triangles,
                              uint64_t upload_bytes, uint32_t evictions, double tess_ms);

/* The cache's pools in a frame: in use, and held by the drawn meshes. */
void sw_stats_add_cache_fill(sw_stats *s, uint64_t used_vertices, uint64_t used_indices,
                             uint64_t drawn_vertices, uint64_t drawn_indices);

/* The culling's work in the frame sw_stats_add_frame records next. */
void sw_stats_add_cull_frame(sw_stats *s, uint64_t box_tests, uint32_t cone_culled,
                             double cull_ms);

typedef struct sw_percentiles { double p50, p90, p99, max; } sw_percentiles;
/* Nearest-rank percentiles; sorts values in place. */
sw_percentiles sw_percentiles_of(float *values, int count);
double sw_stats_error_p99(const sw_stats *s);

/* Writes the JSON object. Uses scratch (9 * frames * 4 bytes) to sort. */
sw_status sw_stats_write_json(const sw_stats *s, FILE *out, sw_arena *scratch, sw_error *err);

#endif
