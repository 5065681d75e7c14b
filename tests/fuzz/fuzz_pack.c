/* SPDX-License-Identifier: MIT */
/* Fuzz target for sw_pack_open_memory. Each input is tried twice: as it is,
 * and with every checksum recomputed, because random mutations almost never
 * keep an XXH3 checksum valid and would otherwise stop at the first
 * checksum, never reaching the record checks behind it. An accepted pack is
 * walked end to end, so a view the validator let out of bounds shows up
 * under AddressSanitizer; the resealed input is opened once more with the
 * checks' parts run backwards, which must give the same answer. The raw
 * signature check a unit runs before the reader goes first. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_border_strip.h"
#include "sw_pack.h"
#include "sw_pack_instances.h"
#include "sw_pack_signature.h"
#include "../parts_backwards.h"
#include "fuzz_reseal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static volatile float sink;

/* Each trimming curve's knots and points, through the loops of each surface,
 * the way a trimming tessellator would reach them. */
static float walk_trims(const sw_pack *pack)
{
    float sum = 0;
    for (uint32_t i = 0; i < pack->surface_count; i++) {
        const sw_pack_surface *s = &pack->surfaces[i];
        sum += pack->parts[s->part].color[1];
        for (uint32_t p = 0; p < s->patch_count; p++)
            sum += pack->patches[s->first_patch + p].box_min[1];
        for (uint32_t l = 0; l < s->loop_count; l++) {
            const sw_pack_trim_loop *loop = &pack->trim_loops[s->first_loop + l];
            for (uint32_t c = 0; c < loop->curve_count; c++) {
                const sw_pack_trim_curve *curve = &pack->trim_curves[loop->first_curve + c];
                size_t n = (size_t)curve->count * 4 + curve->degree + 1;
                for (size_t k = 0; k < n; k++)
                    sum += pack->trim_data[curve->first_float + k];
            }
        }
    }
    for (uint32_t i = 0; pack->patch_domains && i < pack->meta->patch_count; i++) {
        const sw_pack_patch_domain *d = &pack->patch_domains[i];
        sum += pack->surfaces[d->surface].domain[0] + d->domain[1];
        if (d->mask != SW_MASK_NONE)
            sum += (float)pack->trim_masks[d->mask].rows[31];
    }
    return sum;
}

/* Viewpoint names as strings, part transforms by part. */
static float walk_scene(const sw_pack *pack)
{
    float sum = 0;
    for (uint32_t i = 0; i < pack->viewpoint_count; i++)
        sum += (float)strlen(pack->viewpoints[i].name) + pack->viewpoints[i].up[2];
    for (uint32_t i = 0; pack->part_transforms && i < pack->meta->part_count; i++)
        sum += pack->part_transforms[(size_t)i * 16 + 15];
    return sum;
}

/* The Seam Graph the way the runtime walks it: each loop's slots, each
 * slot's vertex up to its root, each vertex's slot references, each
 * surface's loops. The walk to a root is bounded because a validated
 * graph's child links only go to larger indices. */
static float walk_seam(const sw_pack *pack)
{
    const sw_seam_graph *g = &pack->seam;
    float sum = 0;
    for (uint32_t s = 0; g->surface_loops && s < g->surface_count; s++)
        for (uint32_t l = g->surface_loops[s]; l < g->surface_loops[s + 1]; l++) {
            const sw_seam_loop *loop = &g->loops[l];
            sum += pack->surfaces[loop->surface].domain[0];
            for (uint32_t k = 0; k < loop->slot_count; k++) {
                const sw_seam_slot *slot = &g->slots[loop->first_slot + k];
                uint32_t v = slot->vertex;
                while (g->vertices[v].child != SW_SEAM_NONE)
                    v = g->vertices[v].child;
                sum += slot->uv[0] + g->vertices[v].p[1];
            }
        }
    for (uint32_t v = 0; v < g->original_count; v++) {
        const sw_seam_vertex *vx = &g->vertices[v];
        for (uint32_t r = 0; r < vx->slot_ref_count; r++)
            sum += g->slots[g->slot_refs[vx->first_slot_ref + r]].uv[1];
    }
    for (uint32_t k = 0; k < g->collapse_count; k++)
        sum += g->vertices[g->collapses[k].v1].error + g->vertices[g->collapses[k].v2].p[0];
    for (uint32_t e = 0; e < g->edge_count; e++)
        sum += g->vertices[g->edges[e].a].p[2] + g->vertices[g->edges[e].b].p[2];
    return sum;
}

/* The static levels the way the walk draws them: each surface's levels,
 * each level's triangles through its vertices, each of its chains' points
 * (one per loop of the surface) and the border strip of its first chain
 * against itself. */
static float walk_levels(const sw_pack *pack)
{
    const sw_levels *l = &pack->levels;
    float sum = 0;
    static uint32_t tris[3 * 2 * 64];
    for (uint32_t s = 0; l->levels && s < l->surface_count; s++) {
        uint32_t first, end;
        sw_pack_surface_levels(pack, s, &first, &end);   /* shared where the runtime's */
        for (uint32_t k = first; k < end; k++) {
            const sw_level placed = sw_pack_level(pack, s, k);
            const sw_level *lv = &placed;
            sum += lv->error;
            const sw_level_vertex *v = &l->vertices[lv->first_vertex];
            for (uint32_t i = 0; i < lv->index_count; i++)
                sum += v[l->indices[lv->first_index + i]].p[0];
            uint32_t first_loop = pack->seam.surface_loops[s];
            for (uint32_t i = 0; first_loop + i < pack->seam.surface_loops[s + 1]; i++) {
                const sw_level_chain *c = &l->chains[lv->first_chain + i];
                const sw_strip_point *pts = &l->chain_points[c->first_point];
                for (uint32_t p = 0; p < c->point_count; p++)
                    sum += v[pts[p].vertex].p[1] + pts[p].t;
                float period = (float)pack->seam.loops[first_loop + i].slot_count;
                if (c->point_count > 0 && c->point_count <= 64)
                    sum += (float)sw_border_strip(pts, c->point_count, pts, c->point_count,
                                                  period, tris);
            }
        }
    }
    return sum;
}

static void walk(const sw_pack *pack)
{
    float sum = 0;
    for (uint32_t i = 0; i < pack->meta->patch_count; i++) {
        const sw_pack_patch *p = &pack->patches[i];
        size_t n = (size_t)(p->degree_u + 1) * (size_t)(p->degree_v + 1);
        const float *c = &pack->control[(size_t)p->first_control * 4];
        for (size_t k = 0; k < n * 4; k++)
            sum += c[k];
        sum += pack->parts[p->part].color[0];
    }
    for (uint32_t i = 0; i < pack->meta->part_count; i++)
        sum += (float)strlen(pack->parts[i].name);
    for (uint32_t i = 0; i < pack->meta->adjacency_count; i++)
        sum += pack->patches[pack->adjacency[i].patch_a].box_min[0] +
               pack->patches[pack->adjacency[i].patch_b].box_max[0];
    sink = sum + walk_trims(pack) + walk_scene(pack) + walk_seam(pack) + walk_levels(pack);
}

/* A pack of placed parts: walked as stored, then expanded as the runtime
 * expands it (when the placed scene is small enough to hold) and walked
 * again, so an expansion the checks let out of bounds shows up too. */
static void walk_placed(const sw_pack *pack)
{
    walk(pack);
    if (!pack->instances)
        return;
    uint64_t counts[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, counts);
    /* Both expansions: the tools' (every position copied) and the
     * runtime's (the static levels' vertices shared with the prototypes). */
    for (int shared = 0; shared < 2; shared++) {
        uint64_t bytes = shared ? sw_pack_expand_shared_bytes(counts) : sw_pack_expand_bytes(counts);
        if (bytes > (64u << 20))
            return;
        void *block = malloc((size_t)bytes);
        if (!block)
            return;
        sw_arena arena;
        sw_arena_init(&arena, block, (size_t)bytes);
        sw_pack placed;
        sw_error err;
        sw_status st = shared ? sw_pack_expand_shared(pack, &arena, &placed, &err)
                              : sw_pack_expand(pack, &arena, &placed, &err);
        if (st != SW_OK)
            abort();   /* the bytes were counted: expansion cannot run short */
        walk(&placed);
        free(block);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *buf = fuzz_copy(data, size);
    if (!buf)
        return 0;
    sw_pack pack;
    sw_error err;
    /* A unit checks the signature on the raw bytes before any parser runs
     * (sw_pack_check_signature_raw): it must stay inside them too. */
    sw_pack_signature sig;
    (void)sw_pack_check_signature_raw(buf, size, NULL, &sig, &err);
    if (sw_pack_open_memory(buf, size, &pack, &err) == SW_OK)
        walk_placed(&pack);
    if (size >= sizeof(sw_pack_header)) {
        reseal(buf, size);
        sw_status st = sw_pack_open_memory(buf, size, &pack, &err);
        if (st == SW_OK)
            walk_placed(&pack);
        sw_error again;   /* order-free: the loader's threads run the checks in any order */
        if (!sw_opens_the_same_backwards(buf, size, st, err.message, &again))
            abort();   /* reported by the fuzzer as a crash */
    }
    free(buf);
    return 0;
}
