/* SPDX-License-Identifier: MIT */
/* The super-surfaces' part of `seamwalk-pack info` (sw_pack_info.h): their
 * count, members, spans and the finest levels' triangles per super-surface,
 * the figures that say whether the clustering's caps and alpha did their
 * job. */
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#include "sw_pack_info.h"

#define DEG_PER_RAD 57.29577951308232

static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Sorts v[0..n) and gives its min, lower median and max. */
static void spread(uint64_t *v, uint32_t n, uint64_t *min, uint64_t *median, uint64_t *max)
{
    qsort(v, n, sizeof *v, compare_u64);
    *min = n ? v[0] : 0;
    *median = n ? v[(n - 1) / 2] : 0;
    *max = n ? v[n - 1] : 0;
}

/* Super-surface k's members' finest levels' triangles together. */
static uint64_t finest_triangles(const sw_pack *pack, const sw_super_surface *k)
{
    const sw_levels *l = &pack->levels;
    uint64_t sum = 0;
    for (uint32_t m = k->first_member; m < k->first_member + k->member_count; m++) {
        uint32_t s = pack->supers.members[m];
        if (l->surface_levels[s] < l->surface_levels[s + 1])
            sum += l->levels[l->surface_levels[s]].index_count / 3;
    }
    return sum;
}

/* The spans (as float bits: non-negative floats sort as their bits). */
static void gather_spans(const sw_pack *pack, uint64_t *v, sw_pack_super_stats *out)
{
    const sw_supers *sp = &pack->supers;
    for (uint32_t k = 0; k < sp->super_count; k++) {
        float span = sp->supers[k].span;
        uint32_t bits;
        memcpy(&bits, &span, sizeof bits);
        v[k] = bits;
        if (span >= SW_SUPER_SPAN_FULL)
            out->no_cone++;
        else if (span > out->span_max_cone)
            out->span_max_cone = span;
    }
    qsort(v, sp->super_count, sizeof *v, compare_u64);
    uint32_t bits = sp->super_count ? (uint32_t)v[(sp->super_count - 1) / 2] : 0;
    memcpy(&out->span_median, &bits, sizeof bits);
}

sw_status sw_pack_gather_super_stats(const sw_pack *pack, sw_pack_super_stats *out,
                                     sw_error *err)
{
    memset(out, 0, sizeof *out);
    const sw_supers *sp = &pack->supers;
    if (!sp->supers)
        return SW_OK;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        uint32_t t = pack->sections[i].type;
        if (t >= SW_SECTION_SUPER_SURFACES && t <= SW_SECTION_SUPER_OF)
            out->bytes += pack->sections[i].size;
    }
    out->supers = sp->super_count;
    uint64_t *v = malloc(((size_t)sp->super_count + 1) * sizeof *v);
    if (!v)
        return sw_error_set(err, SW_ERR_NO_MEMORY, "cannot allocate the figures of %u "
                            "super-surfaces", (unsigned)sp->super_count);
    uint64_t lo, mid, hi;
    for (uint32_t k = 0; k < sp->super_count; k++)
        v[k] = sp->supers[k].member_count;
    spread(v, sp->super_count, &lo, &mid, &hi);
    out->members_min = (uint32_t)lo, out->members_median = (uint32_t)mid;
    out->members_max = (uint32_t)hi;
    gather_spans(pack, v, out);
    out->with_triangles = pack->levels_header != NULL;
    for (uint32_t k = 0; out->with_triangles && k < sp->super_count; k++)
        v[k] = finest_triangles(pack, &sp->supers[k]);
    if (out->with_triangles)
        spread(v, sp->super_count, &out->triangles_min, &out->triangles_median,
               &out->triangles_max);
    free(v);
    return SW_OK;
}

void sw_pack_print_super_text(FILE *out, const sw_pack *pack, const sw_pack_super_stats *s)
{
    if (!pack->supers.supers)
        return;
    fprintf(out, "  %-16s %" PRIu32 " of %" PRIu32 " surfaces, members %" PRIu32 "/%" PRIu32
            "/%" PRIu32 " (min/median/max), %" PRIu64 " bytes\n", "super-surfaces", s->supers,
            pack->surface_count, s->members_min, s->members_median, s->members_max, s->bytes);
    fprintf(out, "    %-14s median %.2f deg, max %.2f deg with a cone, %" PRIu32 " without "
            "(spans of 90 deg or more)\n", "span", s->span_median * DEG_PER_RAD,
            s->span_max_cone * DEG_PER_RAD, s->no_cone);
    if (s->with_triangles)
        fprintf(out, "    %-14s %" PRIu64 "/%" PRIu64 "/%" PRIu64 " (min/median/max) of the "
                "finest levels per super-surface\n", "triangles", s->triangles_min,
                s->triangles_median, s->triangles_max);
}

void sw_pack_print_super_json(FILE *out, const sw_pack *pack, const sw_pack_super_stats *s)
{
    if (!pack->supers.supers) {
        fprintf(out, "  \"super_surfaces\": null,\n");
        return;
    }
    fprintf(out, "  \"super_surfaces\": {\"count\": %" PRIu32 ", \"members\": [%" PRIu32 ", %"
            PRIu32 ", %" PRIu32 "], \"span_median_rad\": %.9g, \"span_max_with_cone_rad\": %.9g, "
            "\"without_cone\": %" PRIu32 ", \"bytes\": %" PRIu64 ",\n                     "
            "\"finest_triangles\": ", s->supers, s->members_min, s->members_median,
            s->members_max, (double)s->span_median, (double)s->span_max_cone, s->no_cone,
            s->bytes);
    if (s->with_triangles)
        fprintf(out, "[%" PRIu64 ", %" PRIu64 ", %" PRIu64 "]},\n", s->triangles_min,
                s->triangles_median, s->triangles_max);
    else
        fprintf(out, "null},\n");
}
