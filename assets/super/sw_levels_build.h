/* SPDX-License-Identifier: MIT */
/* The static levels of detail of a pack's surfaces (core/sw_levels.h), made
 * on the host from the pack itself, so they are made from exactly what the
 * runtime reads (patches, domains, the Seam Graph).
 *
 * Level k of a surface is made at the bound e_k = finest * step^k times the
 * surface's size (its patches' box diagonal): the Seam Graph's front is
 * moved for every surface's seams to within their share of e_k, as the
 * walk moves it (sw_seam_surface.h), and the surface is tessellated inside
 * its loops at e_k by the walk's own tessellator (core/sw_trim_tess.h, an
 * adaptive grid with a proven bound, paper 000 section 4.1's role), without
 * fill fans: the border strip joins the level to the seams instead. Its
 * border is read back as one chain per loop (the mesh's edges used once),
 * each point placed along its loop by slot.
 *
 * The error stored with a level is measured, apart from the tessellator's
 * proof: every triangle is sampled at the points of a barycentric grid and
 * compared with the exact surface at the same (u, v) (sw_surface_at.h); the
 * level's error is the largest distance found beyond the surface's sewing
 * offset (the file's own gaps, which no level removes: the walk's measure
 * subtracts it too), and at least a few float steps of the surface's
 * coordinates (below that, positions differ by rounding alone). A level
 * whose error does not rise above the one
 * before it is not kept (it replaces that one: it is as good and no
 * larger).
 *
 * What is left out is counted in the report: levels the tessellator refused
 * or that need more than one draw's 65536 vertices, borders that are not
 * one chain per loop, and surfaces whose outer loop vanished at a level's
 * state (no coarser level then). Host only: allocates. */
#ifndef SW_LEVELS_BUILD_H
#define SW_LEVELS_BUILD_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_levels.h"
#include "sw_pack.h"
#include "sw_parts.h"

typedef struct sw_levels_options {
    double finest;        /* the finest level's bound over the surface's size (0: 4e-3) */
    double step;          /* each level's bound over the one before (0: 4) */
    uint32_t count;       /* levels tried per surface (0: 4; at most SW_LEVELS_MAX) */
    uint32_t samples;     /* measuring grid: points per triangle side - 1 (0: 8) */
    const sw_parts_runner *runner;   /* makes each rank's surfaces (sw_parts.h), with
                                        scratch for each made at once; NULL: in order
                                        here. The same levels either way */
} sw_levels_options;

typedef struct sw_levels_report {
    uint32_t surfaces;          /* of the pack */
    uint32_t with_levels;       /* surfaces with at least one level */
    uint32_t levels;            /* kept */
    uint32_t refused;           /* tessellations the tessellator refused */
    uint32_t too_large;         /* needed more than 65536 vertices at that bound */
    uint32_t bad_border;        /* border not one closed chain per loop, in slot order */
    uint32_t not_finer;         /* replaced by the next level (its error no larger) */
    uint32_t vanished;          /* surfaces whose outer loop vanished at a level's state */
    uint64_t triangles[SW_LEVELS_MAX];   /* kept, by rank (finest 0) */
    double worst_over_bound;    /* the largest measured error over the bound it was made for */
    double seconds;
} sw_levels_report;

/* Owned arrays, viewed by .view (what the pack writer takes). */
typedef struct sw_levels_built {
    sw_levels view;
    sw_level *levels;
    uint32_t *surface_levels;
    sw_level_vertex *vertices;
    float *uvs;                   /* 2 per vertex: the (u, v) each was made at; not stored in
                                     the pack (for measuring again on the host) */
    uint16_t *indices;
    sw_level_chain *chains;
    sw_strip_point *chain_points;
} sw_levels_built;

/* Makes the levels of every surface of pack (which must hold a Seam Graph;
 * SW_ERR_ARG otherwise). opt may be NULL (defaults). SW_ERR_NO_MEMORY; any
 * other failure of one level is counted in report and leaves that level
 * out. On error *out is empty. */
sw_status sw_levels_build(const sw_pack *pack, const sw_levels_options *opt,
                          sw_levels_built *out, sw_levels_report *report, sw_error *err);

void sw_levels_built_free(sw_levels_built *b);

#endif
