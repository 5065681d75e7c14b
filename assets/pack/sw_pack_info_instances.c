/* SPDX-License-Identifier: MIT */
/* The placed parts' part of `seamwalk-pack info` (sw_pack_info.h): how many
 * prototypes are stored and how often each is placed, what the placed scene
 * holds (what the runtime expands and walks) and the bytes per placed part
 * and patch, so sharing shows in figures. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_info.h"
#include "sw_pack_instances.h"
#include "sw_seam_fronts.h"

/* Control points first .. first + n moved by t, into the box lo .. hi. */
static void add_placed_points(const sw_pack *pack, const float *t, uint32_t first, uint32_t n,
                              float lo[3], float hi[3])
{
    for (uint32_t c = first; c < first + n; c++) {
        float w[3];
        sw_instance_place(t, &pack->control[4 * (size_t)c], w);
        for (int k = 0; k < 3; k++)
            lo[k] = fminf(lo[k], w[k]), hi[k] = fmaxf(hi[k], w[k]);
    }
}

void sw_pack_placed_box(const sw_pack *pack, float lo[3], float hi[3])
{
    if (!pack->instances) {
        for (int k = 0; k < 3; k++)
            lo[k] = pack->meta->box_min[k], hi[k] = pack->meta->box_max[k];
        return;
    }
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    /* The points moved as the runtime moves them, so the box is the one
     * the walk starts from (a turned box's corners would be larger). */
    for (uint32_t i = 0; i < pack->instance_count; i++) {
        const sw_pack_instance *inst = &pack->instances[i];
        const sw_pack_prototype *p = &pack->prototypes[inst->prototype];
        add_placed_points(pack, inst->transform, p->first[SW_SPACE_CONTROL],
                          p->count[SW_SPACE_CONTROL], lo, hi);
    }
    if (lo[0] > hi[0])
        for (int k = 0; k < 3; k++)
            lo[k] = hi[k] = 0;
}

/* How many instances place each prototype (uses[prototype_count]). */
static uint32_t *count_uses(const sw_pack *pack)
{
    uint32_t *uses = calloc((size_t)pack->prototype_count + 1, sizeof *uses);
    for (uint32_t i = 0; uses && i < pack->instance_count; i++)
        uses[pack->instances[i].prototype]++;
    return uses;
}

/* The walk's seam front as it will take it (sw_seam_fronts.h): a front
 * per instance over the prototypes' graphs, or one over the placed graph
 * where that takes fewer bytes; both sizes, so the sharing shows. */
static void print_fronts(FILE *out, const sw_pack *pack)
{
    size_t each = sw_seam_fronts_layout_bytes(pack->prototypes, pack->prototype_count,
                                              pack->instances, pack->instance_count, 1);
    size_t one = sw_seam_fronts_layout_bytes(pack->prototypes, pack->prototype_count,
                                             pack->instances, pack->instance_count, 0);
    fprintf(out, "  %-16s %s: %.1f MiB (%s %.1f MiB)\n", "seam fronts",
            each < one ? "one per instance over its prototype's graph"
                       : "one over the placed graph",
            (each < one ? each : one) / 1048576.0,
            each < one ? "one over the placed graph would take" : "one per instance would take",
            (each < one ? one : each) / 1048576.0);
}

void sw_pack_print_instances_text(FILE *out, const sw_pack *pack)
{
    if (!pack->instances)
        return;
    uint64_t c[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, c);
    fprintf(out, "  %-16s %" PRIu32 " of %" PRIu32 " prototypes; placed: %" PRIu64 " parts, %"
            PRIu64 " patches, %" PRIu64 " surfaces, %" PRIu64 " seam vertices\n", "instances",
            pack->instance_count, pack->prototype_count, c[SW_SPACE_PARTS], c[SW_SPACE_PATCHES],
            c[SW_SPACE_SURFACES], c[SW_SPACE_SEAM_ORIGINALS] + c[SW_SPACE_SEAM_COLLAPSES]);
    fprintf(out, "  %-16s %.0f bytes per placed part, %.1f per placed patch\n", "",
            (double)pack->header->total_size / pack->instance_count,
            c[SW_SPACE_PATCHES] ? (double)pack->header->total_size / c[SW_SPACE_PATCHES] : 0.0);
    if (pack->seam_header)
        print_fronts(out, pack);
    uint32_t *uses = count_uses(pack);
    for (uint32_t k = 0; uses && k < pack->prototype_count && k < 12; k++) {
        const sw_pack_prototype *p = &pack->prototypes[k];
        uint32_t i = 0;
        while (i < pack->instance_count && pack->instances[i].prototype != k)
            i++;
        fprintf(out, "    prototype %-4" PRIu32 " %" PRIu32 " parts, %" PRIu32 " patches, placed %"
                PRIu32 " times%s", k, p->count[SW_SPACE_PARTS], p->count[SW_SPACE_PATCHES],
                uses[k], i < pack->instance_count ? ", first as " : "\n");
        if (i < pack->instance_count) {
            sw_fput_escaped(out, pack->instances[i].name, sizeof pack->instances[i].name);
            fputc('\n', out);
        }
    }
    if (pack->prototype_count > 12)
        fprintf(out, "    ... %" PRIu32 " more prototypes\n", pack->prototype_count - 12);
    free(uses);
}

void sw_pack_print_instances_json(FILE *out, const sw_pack *pack)
{
    if (!pack->instances) {
        fprintf(out, "  \"prototype_count\": 0,\n  \"instance_count\": 0,\n");
        return;
    }
    uint64_t c[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, c);
    fprintf(out, "  \"prototype_count\": %" PRIu32 ",\n  \"instance_count\": %" PRIu32 ",\n",
            pack->prototype_count, pack->instance_count);
    fprintf(out, "  \"placed\": {\"parts\": %" PRIu64 ", \"patches\": %" PRIu64 ", \"surfaces\": %"
            PRIu64 ", \"seam_vertices\": %" PRIu64 ", \"level_vertices\": %" PRIu64
            ", \"part_level_vertices\": %" PRIu64 "},\n", c[SW_SPACE_PARTS],
            c[SW_SPACE_PATCHES], c[SW_SPACE_SURFACES],
            c[SW_SPACE_SEAM_ORIGINALS] + c[SW_SPACE_SEAM_COLLAPSES], c[SW_SPACE_LEVEL_VERTICES],
            c[SW_SPACE_PART_LEVEL_VERTICES]);
    if (pack->seam_header)
        fprintf(out, "  \"seam_fronts\": {\"per_instance_bytes\": %zu, \"one_bytes\": %zu},\n",
                sw_seam_fronts_layout_bytes(pack->prototypes, pack->prototype_count,
                                            pack->instances, pack->instance_count, 1),
                sw_seam_fronts_layout_bytes(pack->prototypes, pack->prototype_count,
                                            pack->instances, pack->instance_count, 0));
    uint32_t *uses = count_uses(pack);
    fprintf(out, "  \"prototypes\": [");
    for (uint32_t k = 0; uses && k < pack->prototype_count; k++) {
        const sw_pack_prototype *p = &pack->prototypes[k];
        fprintf(out, "%s\n    {\"first_part\": %" PRIu32 ", \"parts\": %" PRIu32 ", \"patches\": %"
                PRIu32 ", \"seam_vertices\": %" PRIu64 ", \"instances\": %" PRIu32 "}",
                k ? "," : "", p->first[SW_SPACE_PARTS], p->count[SW_SPACE_PARTS],
                p->count[SW_SPACE_PATCHES],
                (uint64_t)p->count[SW_SPACE_SEAM_ORIGINALS] + p->count[SW_SPACE_SEAM_COLLAPSES],
                uses[k]);
    }
    fprintf(out, "\n  ],\n  \"instances\": [");
    for (uint32_t i = 0; i < pack->instance_count; i++) {
        const sw_pack_instance *inst = &pack->instances[i];
        fprintf(out, "%s\n    {\"prototype\": %" PRIu32 ", \"name\": ", i ? "," : "",
                inst->prototype);
        sw_pack_json_string(out, inst->name, sizeof inst->name);
        fprintf(out, ", \"scale\": %.9g, \"translation\": [%.9g, %.9g, %.9g]}",
                sw_instance_scale(inst->transform), inst->transform[12], inst->transform[13],
                inst->transform[14]);
    }
    fprintf(out, "\n  ],\n");
    free(uses);
}

/* The box stored part p's patches are placed in by transform t. */
static void placed_part_box(const sw_pack *pack, const sw_pack_part *p, const float *t,
                            float lo[3], float hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (uint32_t i = p->first_patch; i < p->first_patch + p->patch_count; i++) {
        const sw_pack_patch *q = &pack->patches[i];
        add_placed_points(pack, t, q->first_control,
                          (uint32_t)(q->degree_u + 1) * (q->degree_v + 1), lo, hi);
    }
    if (lo[0] > hi[0])
        for (int k = 0; k < 3; k++)
            lo[k] = hi[k] = 0;
}

sw_status sw_pack_place_parts(const sw_pack *pack, const sw_pack_part_stats *stored,
                              sw_pack_placed_parts *out, sw_error *err)
{
    memset(out, 0, sizeof *out);
    uint64_t c[SW_SPACE_COUNT];
    sw_pack_placed_counts(pack->prototypes, pack->instances, pack->instance_count, c);
    size_t n = (size_t)c[SW_SPACE_PARTS];
    out->parts = calloc(n + 1, sizeof *out->parts);
    out->transforms = calloc(16 * n + 1, sizeof *out->transforms);
    out->stats = calloc(n + 1, sizeof *out->stats);
    if (!out->parts || !out->transforms || !out->stats) {
        sw_pack_placed_parts_free(out);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot allocate %zu placed parts", n);
    }
    uint32_t at = 0, patches = 0;
    for (uint32_t i = 0; i < pack->instance_count; i++) {
        const sw_pack_instance *inst = &pack->instances[i];
        const sw_pack_prototype *p = &pack->prototypes[inst->prototype];
        uint32_t first = p->first[SW_SPACE_PARTS], count = p->count[SW_SPACE_PARTS];
        for (uint32_t k = 0; k < count; k++, at++) {
            const sw_pack_part *from = &pack->parts[first + k];
            sw_pack_part *to = &out->parts[at];
            *to = *from;
            to->first_patch = patches + from->first_patch - p->first[SW_SPACE_PATCHES];
            memcpy(to->color, inst->color, sizeof to->color);
            sw_instance_part_name(inst->name, from->name, to->name);
            memcpy(&out->transforms[16 * (size_t)at], inst->transform, sizeof inst->transform);
            out->stats[at] = stored[first + k];
            placed_part_box(pack, from, inst->transform, out->stats[at].box_min,
                            out->stats[at].box_max);
            sw_pack_stats_add(&out->total, &out->stats[at]);
        }
        patches += p->count[SW_SPACE_PATCHES];
    }
    out->count = at;
    return SW_OK;
}

void sw_pack_placed_parts_free(sw_pack_placed_parts *p)
{
    free(p->parts);
    free(p->transforms);
    free(p->stats);
    memset(p, 0, sizeof *p);
}
