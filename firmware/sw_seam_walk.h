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
 * Memory: taken once from the runtime's arena before the first frame,
 * sw_seam_walk_arena_bytes, which the pack's header counts in its
 * runtime_bytes (core/sw_walk_memory.h); the frame functions never
 * allocate. Single-threaded: tessellation runs in the frame (threads
 * and budgets are issue 10). */
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
#include "sw_seam_fill.h"
#include "sw_seam_select.h"
#include "sw_stats.h"
#include "sw_tess.h"
#include "sw_trim_tess.h"
#include "sw_view.h"
#include "sw_walk_memory.h"

/* Vertices per tessellated surface: 16-bit indices (core/sw_walk_memory.h). */
#define SW_SEAM_WALK_VERTICES SW_WALK_VERTICES
#define SW_SEAM_WALK_INDICES SW_WALK_INDICES

enum { SW_SEAM_WALK_AWAY = 3 }; /* w->visible: in the frustum, its normal cone facing away */

typedef struct sw_seam_walk {
    const sw_pack *pack;
    sw_seam_select select;
    sw_seam_cache cache;
    float *target;                /* surface_count: the bound its tessellation is (to be) made
                                     for, model units; huge for surfaces without one */
    float *seam_bound;            /* surface_count: its seams' share of the target */
    uint8_t *visible;             /* surface_count: 0 out of view, 1 drawn, 2 too small to
                                     draw (its box within its bound), SW_SEAM_WALK_AWAY in
                                     view but facing away (cone culling: not drawn) */
    uint8_t *evictable;           /* surface_count: not drawn this frame */
    uint8_t *dirty;               /* surface_count: its loops changed since it was made */
    sw_seam_point *loop_points;   /* the largest surface's slots */
    sw_trim_point *points;        /* the same, as the tessellator takes them */
    uint32_t *loop_first;         /* the most loops of a surface, + 1 */
    sw_trim_patch *patches;       /* the most patches of a surface */
    uint32_t max_points, max_loops, max_patches;
    sw_arena scratch;             /* the tessellator's */
    float *positions, *normals, *uvs;
    uint32_t *ids;
    uint16_t *indices;            /* one surface's, as the tessellator writes it */
    float *sew_offset;            /* surface_count: its border's largest distance from the
                                     surface, model units (sewing joins faces across the
                                     file's gaps; no level of detail makes that smaller) */
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
    double error_px;
    float bound_floor;            /* a tenth of the sewing tolerance */
    uint32_t frame;               /* frames selected so far */
    int no_cache;                 /* every visible surface remade every frame at its exact
                                     bound: the benchmarks' baseline */
    sw_seam_drawn *drawn;         /* with it, measuring also hands it every drawn mesh (the
                                     caller begins and checks it); NULL: not */
    sw_seam_fill *fill;           /* with it, every tessellation's crossings get fill fans
                                     (no T-junction pinholes); NULL: drawn as made */
    uint32_t drop_surface;        /* a mutation for the image tests: this surface is never
                                     drawn, and nothing counts it (UINT32_MAX: none) */
} sw_seam_walk;

typedef struct sw_seam_frame {
    uint32_t visible_surfaces, drawn_surfaces, vanished_surfaces;
    uint32_t active_vertices;
    uint32_t failed_surfaces;     /* the tessellator refused them, or the cache could not
                                     hold them (not drawn) */
    uint32_t capped_surfaces;     /* drawn coarser than their bound (over 65536 vertices) */
    uint32_t holes_filled;        /* drawn without their holes: a hole's coarse polyline
                                     crossed another loop, the tessellator refused the whole */
    uint32_t retessellated;       /* surfaces tessellated this frame */
    uint32_t evicted;             /* meshes the cache gave up for them */
    uint64_t retess_triangles;    /* triangles those made */
    uint64_t upload_bytes;        /* bytes written into the GL buffers */
    uint64_t triangles;           /* the tessellations', the fill fans not counted: */
    uint64_t fill_triangles;      /* zero-area fans over seam crossings (sw_seam_fill.h) */
    uint64_t cracks;              /* border vertices not bit-identical to their seam vertex,
                                     plus loop points the tessellator dropped, plus every
                                     border point of a visible surface not drawn (a hole) */
    uint64_t crossings;           /* border vertices on a seam segment between its vertices
                                     (T-vertices on a straight edge, not gaps) */
    double tess_ms;               /* of the draw, spent tessellating and uploading */
    uint64_t cull_box_tests;      /* of the select: patch and tree boxes tested against the
                                     frustum (sw_cull_tree.h) */
    uint64_t cull_depth_tests;    /* boxes whose depth range it computed */
    double cull_ms;               /* of the select, spent on those */
    uint32_t cone_culled;         /* in the frustum, left out: their cone faces away */
    double measure_ms;            /* of the draw, spent measuring (not part of the frame) */
    double error_beyond_sewing_px;/* measured: the most a sample's error exceeds its surface's
                                     sewing offset, what the level of detail and the
                                     tessellation add: in pixels at the sample, scaled by
                                     half a pixel over the bound where the bound's floor is
                                     coarser than half a pixel (so <= error_px holds) */
    double sewing_offset_px;      /* measured: the largest sewing offset of a drawn surface, in
                                     pixels at its nearest depth */
    double seam_chord_px;         /* measured: the most a seam chord lies from its surface at
                                     the same (u, v), sw_seam_measure.h */
} sw_seam_frame;

/* Bytes sw_seam_walk_init takes from its arena for this validated pack
 * (which must hold a Seam Graph: pack->seam_header). */
size_t sw_seam_walk_arena_bytes(const sw_pack *pack);
sw_status sw_seam_walk_init(sw_seam_walk *w, const sw_pack *pack, sw_arena *arena, double error_px,
                            sw_error *err);

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

/* Tessellates the visible surfaces whose tessellation is missing or no
 * longer valid, uploads them into pool (same layout as w->cache: created
 * with w->cache.vertices and w->cache.indices), and draws every visible
 * surface from it, one colour per part. With stats, also measures every
 * drawn triangle against the exact surface (sw_seam_measure.h). GL thread
 * only. */
void sw_seam_walk_draw(sw_seam_walk *w, sw_renderer *r, sw_gl_pool *pool, const sw_view *view,
                       sw_stats *stats, sw_seam_frame *frame);

#endif
