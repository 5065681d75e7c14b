/* SPDX-License-Identifier: MIT */
/* Every surface tessellated at every seam state from the finest to the
 * coarsest drawn (sw_pack_verify_tess.h), as firmware/walk/sw_seam_walk.c draws
 * it: its loops from sw_seam_surface_loops (a surface whose outer loop
 * vanished is not drawn); a surface the clipping refuses for crossing loops
 * is tried untangled (sw_seam_surface_untangle), then without its holes;
 * one that needs too many vertices is tried at four times the bound, three
 * times. */
#include "sw_pack_verify_tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_arena.h"
#include "sw_seam_select.h"
#include "sw_seam_surface.h"
#include "sw_trim_tess.h"

enum { ATTEMPTS = 4 };

#define BOUND_OF_BOX 1e-3

typedef struct verifier {
    const sw_pack *pack;
    sw_seam_select sel;
    sw_seam_point *seam_points;
    sw_trim_point *points;
    uint32_t *loop_first;
    sw_trim_patch *patches;
    uint32_t patch_count;   /* the surface's, as tessellate last read them */
    uint32_t max_points, max_patches;
    sw_arena scratch;
    void *scratch_block;
    void *select_block;
    uint8_t *failed;   /* per surface, set when refused (may be NULL) */
} verifier;

static uint32_t surface_slots(const sw_seam_graph *g, uint32_t s)
{
    uint32_t n = 0;
    for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++)
        n += g->loops[l].slot_count;
    return n;
}

static sw_status verifier_open(verifier *v, const sw_pack *pack, sw_error *err)
{
    const sw_seam_graph *g = &pack->seam;
    memset(v, 0, sizeof *v);
    v->pack = pack;
    int degree = 1;
    for (uint32_t i = 0; i < pack->meta->patch_count; i++) {
        const sw_pack_patch *p = &pack->patches[i];
        degree = p->degree_u > degree ? p->degree_u : degree;
        degree = p->degree_v > degree ? p->degree_v : degree;
    }
    for (uint32_t s = 0; s < g->surface_count; s++) {
        uint32_t n = surface_slots(g, s);
        v->max_points = n > v->max_points ? n : v->max_points;
        uint32_t p = pack->surfaces[s].patch_count;
        v->max_patches = p > v->max_patches ? p : v->max_patches;
    }
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    size_t scratch = sw_trim_tess_scratch_bytes(v->max_patches, v->max_points, degree, &opt);
    size_t select = sw_seam_select_arena_bytes(g);
    v->seam_points = malloc(((size_t)v->max_points + 1) * sizeof *v->seam_points);
    v->points = malloc(((size_t)v->max_points + 1) * sizeof *v->points);
    v->loop_first = malloc(((size_t)g->loop_count + 2) * sizeof *v->loop_first);
    v->patches = malloc(((size_t)v->max_patches + 1) * sizeof *v->patches);
    v->scratch_block = malloc(scratch);
    v->select_block = malloc(select);
    if (!v->seam_points || !v->points || !v->loop_first || !v->patches || !v->scratch_block ||
        !v->select_block)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "verify: out of memory for tessellating "
                                                   "%u surfaces", (unsigned)g->surface_count);
    sw_arena_init(&v->scratch, v->scratch_block, scratch);
    sw_arena select_arena;
    sw_arena_init(&select_arena, v->select_block, select);
    return sw_seam_select_init(&v->sel, g, &select_arena, err);
}

static void verifier_close(verifier *v)
{
    free(v->seam_points);
    free(v->points);
    free(v->loop_first);
    free(v->patches);
    free(v->scratch_block);
    free(v->select_block);
}

/* Surface s's current loops into v->points (outer ones first; the steps
 * the seam walk takes, sw_seam_surface.h); *outer gets how many are outer.
 * 0 when the outer loops vanished: the surface is not drawn. */
static int gather_loops(verifier *v, uint32_t s, float pin, sw_trim_loops *loops,
                        uint32_t *outer)
{
    const sw_seam_surface_buffers buf = {v->seam_points, v->points, v->loop_first,
                                         v->max_points};
    return sw_seam_surface_loops(&v->sel, s, pin, &buf, loops, outer);
}

/* The diagonal of the box of surface s's patches' control hulls. */
static double surface_size(const sw_pack *pack, uint32_t s)
{
    return sw_pack_patches_diagonal(pack->patches, pack->surfaces[s].first_patch,
                                    pack->surfaces[s].patch_count);
}

static sw_status tessellate(verifier *v, uint32_t s, const sw_trim_loops *loops, double bound,
                            sw_error *err)
{
    uint32_t patch_count = 0;
    sw_status st = sw_trim_patches_from_pack(v->pack, s, v->patches, v->max_patches,
                                             &patch_count, err);
    v->patch_count = st == SW_OK ? patch_count : 0;
    sw_trim_tess_result result;
    const sw_trim_tess_options opt = sw_seam_surface_tess_options();
    for (int attempt = 0; st == SW_OK && attempt < ATTEMPTS; attempt++, bound *= 4.0) {
        st = sw_trim_tess_sizes(v->patches, patch_count, loops, bound, &opt,
                                &v->scratch, &result, err);
        if (st != SW_ERR_RANGE)
            break;
    }
    return st;
}

/* Surface s at the current state, whose seams may be off by seam_bound:
 * SW_OK when it tessellates or vanished, the tessellator's status otherwise. */
static sw_status check_surface(verifier *v, uint32_t s, double seam_bound,
                               sw_pack_tess_report *out, int *drawn, sw_error *err)
{
    sw_trim_loops loops;
    uint32_t outer = 0;
    *drawn = 0;
    /* Poles pinned within the seams' bound, as the runtime pins them. */
    if (!gather_loops(v, s, (float)seam_bound, &loops, &outer))
        return SW_OK;
    *drawn = 1;
    /* The runtime's surface bound is the seams' over their share. What is
     * proved here is the loops (inside the domain, not crossing), which do
     * not depend on it: at least a thousandth of the surface keeps every
     * tessellation within one draw's 65536 vertices. */
    double bound = fmax(seam_bound / SW_SEAM_SHARE, BOUND_OF_BOX * surface_size(v->pack, s));
    if (!(bound > 0))
        bound = 1.0;
    sw_status st = tessellate(v, s, &loops, bound, err);
    if (st == SW_ERR_FORMAT &&
        sw_seam_surface_untangle(&loops, v->points, v->loop_first, &outer,
                                 sw_trim_tess_shrink(v->patches, v->patch_count),
                                 &v->scratch) > 0) {
        out->untangled++;
        st = tessellate(v, s, &loops, bound, err);
    }
    if (st == SW_ERR_FORMAT && outer < loops.loop_count) {
        loops.loop_count = outer;
        st = tessellate(v, s, &loops, bound, err);
        out->holes_filled += st == SW_OK;
    }
    return st;
}

/* Every created vertex split: the front on the original vertices. */
static sw_status go_finest(verifier *v, sw_error *err)
{
    const sw_seam_graph *g = &v->pack->seam;
    for (uint32_t i = g->vertex_count; i-- > g->original_count;) {
        if (!sw_seam_select_is_active(&v->sel, i))
            continue;
        sw_status st = sw_seam_select_force_split(&v->sel, i, 0, NULL, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

/* Every surface at the current state; the first failure into err. *drawn
 * gets how many were drawn (not vanished). */
static sw_status check_state(verifier *v, double seam_bound, sw_pack_tess_report *out,
                             uint32_t *drawn, sw_error *err)
{
    sw_status first = SW_OK;
    *drawn = 0;
    for (uint32_t s = 0; s < v->pack->seam.surface_count; s++) {
        sw_error why = {0};
        int shown = 0;
        sw_status st = check_surface(v, s, seam_bound, out, &shown, &why);
        *drawn += (uint32_t)shown;
        out->checks += (uint32_t)shown;
        if (st == SW_OK)
            continue;
        out->failed++;
        if (v->failed)
            v->failed[s] = 1;
        if (out->first_failed == UINT32_MAX)
            out->first_failed = s;
        if (first == SW_OK)
            first = sw_error_set(err, SW_ERR_FORMAT, "surface %u does not tessellate with its "
                                 "seams within %g: %s", (unsigned)s, seam_bound,
                                 why.message[0] ? why.message : "refused");
    }
    return first;
}

/* The front for seams within bound everywhere. */
static sw_status go_to(verifier *v, double bound, sw_error *err)
{
    uint32_t n = v->pack->seam.surface_count;
    float *bounds = malloc(((size_t)n + 1) * sizeof *bounds);
    if (!bounds)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "verify: out of memory for %u bounds",
                            (unsigned)n);
    for (uint32_t s = 0; s < n; s++)
        bounds[s] = (float)bound;
    sw_seam_update_result r;
    sw_status st = sw_seam_select_update(&v->sel, bounds, 0, &r, err);
    free(bounds);
    return st;
}

sw_status sw_pack_verify_tessellation(const sw_pack *pack, sw_pack_tess_report *out,
                                      sw_error *err)
{
    return sw_pack_verify_tessellation_marks(pack, NULL, out, err);
}

sw_status sw_pack_verify_tessellation_marks(const sw_pack *pack, uint8_t *failed,
                                            sw_pack_tess_report *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    out->first_failed = UINT32_MAX;
    if (!pack->seam_header || pack->seam.surface_count == 0)
        return SW_OK;
    verifier v;
    sw_status st = verifier_open(&v, pack, err);
    v.failed = failed;
    sw_status first = SW_OK;
    sw_error why = {0};
    out->surfaces = pack->seam.surface_count;
    if (st == SW_OK)
        st = go_finest(&v, err);
    double size = sqrt((double)(pack->meta->box_max[0] - pack->meta->box_min[0]) *
                           (pack->meta->box_max[0] - pack->meta->box_min[0]) +
                       (double)(pack->meta->box_max[1] - pack->meta->box_min[1]) *
                           (pack->meta->box_max[1] - pack->meta->box_min[1]) +
                       (double)(pack->meta->box_max[2] - pack->meta->box_min[2]) *
                           (pack->meta->box_max[2] - pack->meta->box_min[2]));
    /* The finest state, then seams within 1, 4, 16, ... sewing tolerances,
     * until nothing is drawn or the bound passes the model's size. */
    double bound = 0, step = fmax((double)pack->seam.tolerance, 1e-9 * size);
    for (int level = 0; st == SW_OK && level < 40; level++) {
        if (level > 0)
            st = go_to(&v, bound, err);
        uint32_t drawn = 0;
        sw_status got = st == SW_OK ? check_state(&v, bound, out, &drawn, &why) : st;
        if (first == SW_OK && got != SW_OK)
            first = got;
        out->states++;
        if (drawn == 0 || bound > size)
            break;
        bound = level == 0 ? step : bound * 4;
    }
    verifier_close(&v);
    if (st == SW_OK && first != SW_OK) {
        st = first;
        if (err)
            *err = why;
    }
    return st;
}
