/* SPDX-License-Identifier: MIT */
/* The frame work of a walk through the Seam Graph (paper 004, sections 5.5,
 * 6.1, 6.3 and 6.4), what `seamwalk` draws: per surface an error bound from
 * the view (half a pixel at the surface's nearest depth, never below a
 * tenth of the sewing tolerance), the view-dependent cut of the seam
 * hierarchy for the seams' share of those bounds (core/sw_seam_select.h),
 * and every visible surface tessellated inside its current loops
 * (core/sw_trim_tess.h), the cells the loops cross to the rest of the bound,
 * its border vertices the seam's own, then drawn. Surfaces whose outer loop
 * has vanished, or whose box fits within their bound, are not drawn: far
 * away whole patches disappear.
 *
 * Tessellate once (paper 6.4): a surface's tessellation is kept in the
 * cache (sw_seam_cache.h, and the same layout in GL buffers, sw_gl_pool.h)
 * with the bound it was made for, t. It stays valid while the view's bound b
 * lies in [t, 1.6 t]: finer than needed by at most 1.6x, never coarser
 * (SW_SEAM_KEEP in the .c says why 1.6). When b
 * leaves that range the surface gets a new t, b rounded down to a power of
 * sqrt 2 (so neighbours at similar depths share levels and their seams do
 * not move every frame), and is tessellated again. The seams are selected
 * for the t of each surface, not for b, so the loops of a surface whose
 * tessellation is still valid do not change unless a neighbour's t does;
 * when they do (sw_seam_select_surface_changed), the surface is tessellated
 * again too. A still camera re-tessellates nothing.
 *
 * Threads (paper 000 section 5): the frame is split into the visibility
 * side V, which selects (culling, bounds, the seam front), schedules the
 * work, swaps finished batches in and writes the frame's plan
 * (sw_seam_walk_select, then sw_seam_walk_plan: sw_seam_plan.h, what to
 * upload and draw), and the GL thread P, which draws a plan
 * (sw_seam_walk_draw_plan) reading nothing else of the walk. With a
 * visibility thread (sw_seam_visibility.h) V plans frame i+1 while P draws
 * frame i; without one P runs both halves in turn. Without workers the
 * tessellation runs in V's half of the frame. With them (sw_seam_walk_start_workers),
 * the walk schedules the work and the workers T (sw_seam_workers.h) make the
 * meshes while P goes on drawing the meshes it has.
 * - Crack-free by versioned batches: the seam front moves only when no
 *   work is in flight, and every job started after a move belongs to that
 *   move's batch, made from the one seam state the move left. The GL thread
 *   swaps a batch in whole, in one frame, once every job of it is
 *   published; until then it draws the previous batch's meshes, all made
 *   from the previous state. A surface whose loops the move changed and
 *   that holds a mesh is always in the batch, visible or not (so no stale
 *   border is ever drawn), so neighbours drawn together always share their
 *   border vertices. Why this and not paper 000's border strips: the Seam
 *   Graph already makes both sides of a seam take the same vertices (its
 *   point), so what must be kept is only that both sides show the same
 *   state; strips would add triangles and a second border to keep right.
 * - Budgets (sw_seam_budget.h): a surface needs work when its view bound
 *   leaves its mesh's valid range; visible ones are ordered by the weight
 *   w, culled ones (out of view with a kept mesh that would not serve the
 *   bound at its box's distance: fetched ahead for when the eye turns to
 *   it) by w' = 1 - 1/w, below every visible one, and only while N lasts;
 *   per frame N new and M updated triangles, set by the controller for
 *   --target-ms. N is a cap (the heaviest surface excepted, so work always
 *   moves); M is spent by the seam update, which cannot stop half-way
 *   without loops that cross, so it is held over two frames: what an
 *   update spends over M comes out of the next frame's N
 *   (sw_seam_budget.h). What the budget does not reach is drawn from the
 *   older, coarser mesh, and a surface passed over keeps its loops: a
 *   mesh remade inside them (its neighbour moved) is made and labelled
 *   for the bound they meet, so the stats say how far behind each drawn
 *   mesh is (frames, bound ratio, its error measured apart) and how much
 *   of the budget was used.
 * - The first frame comes from the coarsest state: its bounds are
 *   SW_SEAM_FIRST_COARSER times the view's, and it is the one frame that
 *   waits for its batch (there is nothing yet to draw instead).
 * - sync_work (tests only): every frame waits for the work it asked for,
 *   with no budget: each frame is then what the walk without workers draws
 *   (the golden images stay deterministic).
 *
 * Memory: taken once from the runtime's arena before the first frame,
 * sw_seam_walk_arena_bytes, which the pack's header counts in its
 * runtime_bytes (core/sw_walk_memory.h), and the frames' own
 * (sw_seam_walk_frame_bytes: the two plans, P's measuring scratch, the
 * workers' buffers) from a second arena sized once the pack is loaded; the
 * frame functions never allocate. */
#ifndef SW_SEAM_WALK_H
#define SW_SEAM_WALK_H

#include <stdint.h>

#include "sw_arena.h"
#include "sw_cull_tree.h"
#include "sw_gl_pool.h"
#include "sw_normal_cone.h"
#include "sw_pack.h"
#include "sw_renderer.h"
#include "sw_seam_cache.h"
#include "sw_seam_drawn.h"
#include "sw_seam_budget.h"
#include "sw_seam_fill.h"
#include "sw_seam_make.h"
#include "sw_seam_plan.h"
#include "sw_seam_fronts.h"
#include "sw_seam_select.h"
#include "sw_seam_standin.h"
#include "sw_stats.h"
#include "sw_tess.h"
#include "sw_trim_tess.h"
#include "sw_seam_workers.h"
#include "sw_view.h"
#include "sw_walk_memory.h"

/* The first frame's bounds over the view's (the threaded walk's start).
 * Paper 004 starts from the coarsest state and refines; 2 (as before) made
 * the 40,000-patch showroom's first frame 147k triangles at 1280x720 and
 * 0.8 s, 8 made it 60k and 0.58 s, 32 22k and 0.38 s (same run, loaded
 * 2-core machine). Every surface is remade for the view's bound in the
 * next batches anyway, so what a coarser start costs is only how coarse
 * those few frames look (error_px_behind, threads.behind_ratio_max). */
#define SW_SEAM_FIRST_COARSER 32.0

/* Vertices per tessellated surface: 16-bit indices (core/sw_walk_memory.h). */
#define SW_SEAM_WALK_VERTICES SW_WALK_VERTICES
#define SW_SEAM_WALK_INDICES SW_WALK_INDICES

enum { SW_SEAM_WALK_AWAY = 3 }; /* w->visible: in the frustum, its normal cone facing away */
enum { SW_SEAM_WALK_PART = 4 }; /* w->visible: in view, drawn as its part's level */

typedef struct sw_seam_frame {
    uint32_t visible_surfaces, drawn_surfaces, vanished_surfaces;
    uint32_t active_vertices;
    uint32_t failed_surfaces;     /* the tessellator refused them, or the cache could not
                                     hold them (not drawn) */
    uint32_t capped_surfaces;     /* drawn coarser than their bound (over 65536 vertices) */
    uint32_t holes_filled;        /* drawn without their holes: a hole's coarse polyline
                                     crossed another loop, the tessellator refused the whole */
    uint32_t untangled;           /* drawn with a slit cut out of a loop or touching loops
                                     parted: the tessellator refused the loops as they
                                     were (sw_seam_surface.h) */
    uint32_t retessellated;       /* surfaces tessellated this frame */
    uint32_t evicted;             /* meshes the cache gave up for them */
    uint64_t cache_drawn_vertices;/* the drawn meshes' blocks in the cache's pools, */
    uint64_t cache_drawn_indices; /* rounded as the pools hand them out */
    uint64_t cache_used_vertices; /* all blocks in use when the frame was planned */
    uint64_t cache_used_indices;
    uint64_t retess_triangles;    /* triangles those made */
    uint64_t upload_bytes;        /* bytes written into the GL buffers */
    uint64_t triangles;           /* the tessellations', the fill fans not counted: */
    uint64_t fill_triangles;      /* zero-area fans over seam crossings (sw_seam_fill.h) */
    uint64_t cracks;              /* border vertices not bit-identical to their seam vertex,
                                     plus loop points the tessellator dropped off the
                                     border's line (a gap; on it, a crossing), plus every
                                     border point of a visible surface not drawn (a hole) */
    uint64_t crossings;           /* border vertices on a seam segment between its vertices,
                                     and loop points dropped where the border stays on
                                     their line (T-vertices on a straight edge, not gaps) */
    double tess_ms;               /* of the draw, spent tessellating and uploading */
    uint64_t cull_box_tests;      /* of the select: patch and tree boxes tested against the
                                     frustum (sw_cull_tree.h) */
    uint64_t cull_depth_tests;    /* boxes whose depth range it computed */
    double cull_ms;               /* of the select, spent on those */
    uint32_t cone_culled;         /* in the frustum, left out: their cone faces away */
    uint32_t clamped_surfaces;    /* in view, their bound finer than their floor (a view
                                     closer than the pack was built for, --closest-mm):
                                     drawn at the floor, coarser than the view asks */
    double measure_ms;            /* of the draw, spent measuring (not part of the frame) */
    double error_beyond_sewing_px;/* measured: the most a sample's error exceeds its surface's
                                     sewing offset, what the level of detail and the
                                     tessellation add: in pixels at the sample, scaled by
                                     half a pixel over the bound where the bound's floor is
                                     coarser than half a pixel (so <= error_px holds) */
    double error_behind_beyond_sewing_px; /* the same, of meshes drawn coarser than the view
                                     asks while their new ones are made (not in the one above) */
    double sewing_offset_px;      /* measured: the largest sewing offset of a drawn surface, in
                                     pixels at its nearest depth */
    double seam_chord_px;         /* measured: the most a seam chord lies from its surface at
                                     the same (u, v), sw_seam_measure.h */
    /* With workers: */
    uint32_t waiting_surfaces;    /* visible with no mesh yet (not drawn: holes until made) */
    double pressure;              /* the bound's factor this frame (sw_seam_walk_pressure) */
    uint32_t standins;            /* drawn from a static level while their mesh is made */
    uint32_t standins_made;       /* stand-ins made this frame */
    uint32_t standins_coarser;    /* of them, from a level coarser than their target's: the
                                     cache had no room for that one */
    uint64_t standin_triangles;   /* of triangles: those the stand-ins drew */
    uint32_t part_levels;         /* parts drawn whole from a part level */
    uint64_t part_level_triangles;/* of triangles: those the part levels drew */
    uint32_t covered_surfaces;    /* surfaces in view drawn by their part's level */
    uint32_t behind_surfaces;     /* drawn from a mesh coarser than the view's bound */
    uint32_t frames_behind;       /* the longest a drawn surface has waited for its work */
    double behind_ratio;          /* the most a drawn mesh's bound exceeds the view's */
    uint32_t jobs_scheduled;      /* jobs this frame started */
    uint32_t jobs_prefetch;       /* of them, out of view by w' (with budget left) */
    uint32_t jobs_leaner;         /* of them, for stand-ins in view finer than their target
                                     needs (with budget left) */
    uint32_t batches_committed;   /* batches swapped in this frame (0 or 1) */
    double budget_tris;           /* N + M this frame */
    double budget_used;           /* triangles scheduled over N + M */
    uint32_t seam_ops;            /* the seam update's splits and collapses */
    double updated_tris;          /* of the jobs, those whose loops moved (M's share) */
    double updated_cap;           /* M, when the batch opened under it (0: no budget) */
    /* The hand-over (sw_seam_visibility.h): */
    double visibility_ms;         /* V's half of the frame: select, schedule, swap, plan */
    double plan_wait_ms;          /* P waiting for the plan (0 without a visibility thread) */
    uint8_t planned_on_gl_thread; /* V's half ran on P's thread */
    uint8_t plan_overlapped;      /* V began it while P was still drawing the frame before */
} sw_seam_frame;

typedef struct sw_seam_walk {
    const sw_pack *pack;
    sw_seam_fronts fronts;        /* the seam front, one per instance where that takes less
                                     memory (core/sw_seam_fronts.h) */
    sw_seam_cache cache;
    float *target;                /* surface_count: the bound its tessellation is (to be) made
                                     for, model units; huge for surfaces without one */
    float *seam_bound;            /* surface_count: its seams' share of the target */
    uint8_t *visible;             /* surface_count: 0 out of view, 1 drawn, 2 too small to
                                     draw (its box within its bound), SW_SEAM_WALK_AWAY in
                                     view but facing away (cone culling: not drawn) */
    uint8_t *evictable;           /* surface_count: not drawn this frame */
    uint8_t *dirty;               /* surface_count: its loops changed since it was made */
    sw_seam_maker maker;          /* V's buffers (tessellating in the frame, helping the
                                     workers, cone culling's sewing offsets) */
    sw_walk_sizes largest;        /* the pack's largest surface */
    float *sew_offset;            /* surface_count: its border's largest distance from the
                                     surface, model units (sewing joins faces across the
                                     file's gaps; no level of detail makes that smaller);
                                     -1 until V first needs it (cone culling) */
    /* P's own, for measuring what it draws (sw_seam_walk_init_frames): */
    sw_trim_patch_room measure;   /* the largest surface's patches */
    float *measure_sew_offset;    /* surface_count: as sew_offset, P's copy */
    float *depth;                 /* surface_count: this frame's nearest depth */
    sw_cull_tree cull_tree;       /* over the surfaces and their patches, built at init */
    double *cull_near, *cull_far; /* surface_count: this frame's nearest and farthest depth
                                     of its patch boxes in view (+inf, -inf: none) */
    int cull_brute;               /* every patch box tested on its own instead of the tree:
                                     the benchmarks' "before" (same answers) */
    sw_normal_cone *cones;        /* surface_count: the union of its patches' normal cones
                                     (sw_normal_cone.h), made by sw_seam_walk_enable_cones */
    double cull_tree_ms, cones_ms;/* time building the tree (init) and the cones */
    int cone_cull;                /* surfaces whose cone faces away over their box are not
                                     drawn (set by sw_seam_walk_enable_cones; 0: off) */
    sw_vec3 eye;                  /* this frame's (select): which stand-ins may show a
                                     silhouette */
    double error_px;
    double pressure;              /* V: the bound's factor while the cache cannot hold the
                                     view at error_px (1: none; sw_seam_walk_pressure) */
    uint32_t pressure_raised;     /* the frame it last rose */
    uint32_t pressure_calm;       /* frames with room since it last moved */
    int no_pressure;              /* a test's mutant: never raised */
    float bound_floor;            /* a tenth of the sewing tolerance */
    float *floor;                 /* surface_count: the finest bound it is drawn at: the
                                     above, or the largest error its seam vertices start
                                     at where the pack's hierarchy was cut at a floor
                                     (assets/seam/sw_seam_reroot.h) */
    uint32_t frame;               /* frames selected so far */
    int no_cache;                 /* every visible surface remade every frame at its exact
                                     bound: the benchmarks' baseline */
    sw_seam_drawn *drawn;         /* with it, measuring also hands it every drawn mesh (the
                                     caller begins and checks it); NULL: not */
    sw_seam_fill *fill;           /* with it, every tessellation's crossings get fill fans
                                     (no T-junction pinholes); NULL: drawn as made */
    uint32_t drop_surface;        /* a mutation for the image tests: this surface is never
                                     drawn, and nothing counts it (UINT32_MAX: none) */
    /* Threads (all on the walk's own thread except inside workers). */
    sw_seam_workers *workers;     /* NULL: tessellate in the frame */
    int sync_work;                /* tests: each frame waits for its work, no budget */
    sw_seam_budget budget;
    float *want;                  /* surface_count: this frame's bound from the view; out of
                                     view (async), the bound at its box's distance for a
                                     kept mesh (the prefetch by w'), else 0 */
    uint8_t *busy;                /* surface_count: a job in flight */
    uint32_t *need_since;         /* surface_count: the frame it first needed work
                                     (UINT32_MAX: it does not) */
    uint32_t *batch;              /* surface_count: the surfaces with a job in the batch */
    uint32_t batch_count, batch_pushed;
    uint32_t room_retries;        /* of the batch: rounds its jobs went again for room */
    int room_tight;               /* the last batch went again for room: no prefetch */
    sw_seam_candidate *candidates;/* surface_count */
    /* Stand-ins (sw_seam_standin.h), with workers and a pack with static
     * levels; NULL otherwise (a surface in view waits for its mesh). */
    sw_seam_standin *standins;
    int no_standins;              /* set before the workers start: none even with levels */
    int no_leaner_standins;       /* stand-ins finer than needed stay (no leaner jobs) */
    /* Part levels (core/sw_part_levels.h; visibility/sw_seam_part_levels.c),
     * V's; NULL when the pack has none or no_part_levels was set before
     * sw_seam_walk_init_frames: */
    const sw_part_levels *part_levels;
    int no_part_levels;
    int part_levels_coarsest;     /* tests' mutant: each piece from its coarsest level */
    uint32_t *part_level;         /* piece_count: the level drawn this frame, UINT32_MAX none */
    double *part_depth;           /* piece_count: its surfaces' nearest depth in view */
    uint32_t *part_pieces;        /* part_count + 1: part p's pieces are
                                     [part_pieces[p], part_pieces[p + 1]) */
    uint32_t *piece_part;         /* piece_count: its part */
    int standin_silhouettes;      /* 1: where a silhouette may cross a stand-in its level is
                                     chosen by the bound it was made for
                                     (sw_seam_standin_worth); 0 by its error alone (tests) */
    uint32_t standin_evicted;     /* the frame stand-ins last gave meshes up for room */
    uint32_t standin_evict_rounds;/* and how many times in it (UINT32_MAX: none was left) */
    uint32_t standin_searches;    /* region searches for stand-ins in that frame */
    uint8_t *standin;             /* surface_count: its cache entry is a stand-in */
    uint8_t *restitch;            /* surface_count: a stand-in to make again after the swap */
    float *standin_error;         /* surface_count: the error of the level its stand-in
                                     shows, as its neighbours were joined to it (INFINITY:
                                     none) */
    float *standin_border;        /* surface_count: the error its stand-in's loops may
                                     show, as announced with that level (INFINITY: none) */
    uint32_t *drawn_shown;        /* original_count: the front's shown vertices as the drawn
                                     meshes have them, kept while a batch is in flight */
    uint32_t *mixed_shown;        /* original_count: a stand-in's front (sw_seam_walk_plan.c) */
    uint64_t batch_tris;          /* of the frame's schedule: triangles estimated */
    int defer_schedule;           /* V runs the schedule after handing the plan over
                                     (sw_seam_walk_schedule_deferred) */
    sw_seam_frame deferred;       /* that schedule's counts, for the next frame's stats */
} sw_seam_walk;

/* Bytes sw_seam_walk_init takes from its arena for this validated pack
 * as read (which must hold a Seam Graph: pack->seam_header; placed or
 * not). */
size_t sw_seam_walk_arena_bytes(const sw_pack *stored);

/* The walk of pack: the scene the walk draws (a placed pack's expanded,
 * sw_pack_expand_shared), and stored, the pack as read (the same for a
 * pack without instances): its instances' fronts share their
 * prototypes' graphs (sw_seam_fronts.h). Both must outlive the walk. */
sw_status sw_seam_walk_init(sw_seam_walk *w, const sw_pack *pack, const sw_pack *stored,
                            sw_arena *arena, double error_px, sw_error *err);

/* A test's smaller cache: the pools cut to about vertices vertices and 6
 * x as many indices (never more than they have), so every share of them
 * the walk keeps or reads is of that size. Before the workers start.
 * (Holding the rest in blocks no surface owned left the shares of the
 * whole pool, which the pressure and the room kept read.) */
void sw_seam_walk_shrink_cache(sw_seam_walk *w, uint32_t vertices);

/* Makes every surface's normal cone (its scratch from arena, given back:
 * counted in the walk's bytes) and turns cone culling on: surfaces in view
 * whose cone faces away from the eye over their whole box are then
 * tessellated and cached as usual but not drawn. Only for a renderer that
 * does not draw back faces (sw_renderer_set_back_hidden): it leaves out
 * only what that would not draw. Not at init: the cones of the 40,000-patch
 * showroom take about 0.2 s, which a walk drawing back faces never needs. */
sw_status sw_seam_walk_enable_cones(sw_seam_walk *w, sw_arena *arena, sw_error *err);

/* Culls surfaces, sets their bounds and moves the seam front to meet them. */
sw_status sw_seam_walk_select(sw_seam_walk *w, const sw_view *view, sw_seam_frame *frame,
                              sw_error *err);

/* V, after the select: the batch swapped in when whole (with workers) or
 * the meshes the frame needs made (without), then the plan: the meshes to
 * upload, every visible surface to draw from the cache (one colour per
 * part), the depth range of what is drawn, and the frame's counts. */
void sw_seam_walk_plan(sw_seam_walk *w, const sw_view *view, sw_seam_plan *plan,
                       sw_seam_frame *frame);

/* P (GL thread only): uploads and draws the plan; with stats, also
 * measures every drawn triangle against the exact surface
 * (sw_seam_measure.h) and hands the meshes to w->drawn. view: the plan's
 * with near and far as drawn. Reads of the walk: the plan, the mesh bytes
 * it names, P's scratch, the pack. */
void sw_seam_walk_draw_plan(sw_seam_walk *w, sw_renderer *r, sw_gl_pool *pool,
                            const sw_seam_plan *plan, const sw_view *view, sw_stats *stats,
                            sw_seam_frame *frame);

/* Bytes of the frames' own arena (sw_seam_walk_init_frames, then
 * sw_seam_walk_start_workers with workers > 0), fill as the walk has it. */
size_t sw_seam_walk_frame_bytes(const sw_pack *pack, uint32_t workers, int fill);

/* The two plans and P's measuring scratch, from arena (after init). */
sw_status sw_seam_walk_init_frames(sw_seam_walk *w, sw_seam_plan plans[2], sw_arena *arena,
                                   sw_error *err);

/* Arena bytes of count workers for this pack (on top of
 * sw_seam_walk_arena_bytes), fill as the walk will have it. */
size_t sw_seam_walk_worker_bytes(const sw_pack *pack, uint32_t count, int fill);

/* Starts count tessellation workers (after init, fill and drawn set):
 * from then on the walk is threaded. target_ms: the controller's frame
 * time. shared: the walk's arena (the pack's runtime_bytes counts what the
 * workers share); arena: sw_seam_walk_worker_bytes for their own buffers.
 * Errors as sw_seam_workers_init. */
sw_status sw_seam_walk_start_workers(sw_seam_walk *w, uint32_t count, double target_ms,
                                     sw_arena *shared, sw_arena *arena, sw_error *err);

/* Stops the workers (safe without them). */
void sw_seam_walk_stop_workers(sw_seam_walk *w);

/* Test hook: while stalled the workers take no job (frames go on drawing
 * the meshes they have). */
void sw_seam_walk_stall_workers(sw_seam_walk *w, int stalled);

/* Test hook: every job waits ms before it is published (batches then take
 * many frames: a batch swapped in before it is whole would show). */
void sw_seam_walk_slow_workers(sw_seam_walk *w, int ms);

/* P, after it has drawn plan number: meshes that plan drew may be reused
 * (the retire ring's epoch; safe from any thread, an atomic store). */
void sw_seam_walk_finished(sw_seam_walk *w, uint32_t number);

/* V: the controller learns a drawn frame's time (swapped: its plan swapped
 * a batch in). */
void sw_seam_walk_learn(sw_seam_walk *w, double frame_ms, int swapped);

#endif
