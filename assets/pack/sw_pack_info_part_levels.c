/* SPDX-License-Identifier: MIT */
/* The part levels' part of `seamwalk-pack info` (sw_pack_info.h): how many
 * parts have them, and per rank (finest first) the levels, their
 * triangles, their largest measured error and their largest side shaded
 * wrong. */
#include <inttypes.h>
#include <string.h>

#include "sw_pack_info.h"

typedef struct part_level_figures {
    uint32_t parts, levels[SW_PART_LEVELS_MAX];
    uint64_t triangles[SW_PART_LEVELS_MAX], bytes;
    double error_max[SW_PART_LEVELS_MAX], shading_side_max[SW_PART_LEVELS_MAX];
    uint32_t ranks;
} part_level_figures;

static part_level_figures gather(const sw_pack *pack)
{
    part_level_figures f;
    memset(&f, 0, sizeof f);
    const sw_part_levels *pl = &pack->part_levels;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        uint32_t t = pack->sections[i].type;
        if (t >= SW_SECTION_PART_LEVELS && t <= SW_SECTION_PART_LEVEL_INDICES)
            f.bytes += pack->sections[i].size;
    }
    for (uint32_t p = 0; p < pl->part_count; p++) {
        uint32_t a = pl->part_levels[p], b = pl->part_levels[p + 1];
        f.parts += b > a;
        for (uint32_t i = a; i < b; i++) {
            uint32_t r = i - a;
            f.levels[r]++;
            f.triangles[r] += pl->levels[i].index_count / 3;
            if (pl->levels[i].shading_side > f.shading_side_max[r])
                f.shading_side_max[r] = pl->levels[i].shading_side;
            f.error_max[r] = pl->levels[i].error > f.error_max[r] ? pl->levels[i].error
                                                                   : f.error_max[r];
            f.ranks = r + 1 > f.ranks ? r + 1 : f.ranks;
        }
    }
    return f;
}

void sw_pack_print_part_levels_text(FILE *out, const sw_pack *pack)
{
    if (!pack->part_levels.levels)
        return;
    part_level_figures f = gather(pack);
    fprintf(out, "  %-16s %" PRIu32 " of %" PRIu32 " parts, %" PRIu32 " levels, %" PRIu64
            " bytes\n", "part levels", f.parts, pack->part_levels.part_count,
            pack->part_levels.level_count, f.bytes);
    for (uint32_t r = 0; r < f.ranks; r++)
        fprintf(out, "    rank %-9" PRIu32 " %" PRIu32 " levels, %" PRIu64 " triangles, error "
                "max %.6g, shading side max %.6g\n", r, f.levels[r], f.triangles[r],
                f.error_max[r], f.shading_side_max[r]);
}

void sw_pack_print_part_levels_json(FILE *out, const sw_pack *pack)
{
    if (!pack->part_levels.levels) {
        fprintf(out, "  \"part_levels\": null,\n");
        return;
    }
    part_level_figures f = gather(pack);
    fprintf(out, "  \"part_levels\": {\"parts\": %" PRIu32 ", \"levels\": %" PRIu32
            ", \"bytes\": %" PRIu64 ", \"ranks\": [", f.parts, pack->part_levels.level_count,
            f.bytes);
    for (uint32_t r = 0; r < f.ranks; r++)
        fprintf(out, "%s{\"levels\": %" PRIu32 ", \"triangles\": %" PRIu64
                ", \"error_max\": %.9g, \"shading_side_max\": %.9g}", r ? ", " : "",
                f.levels[r], f.triangles[r], f.error_max[r], f.shading_side_max[r]);
    fprintf(out, "]},\n");
}
