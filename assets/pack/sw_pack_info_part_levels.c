/* SPDX-License-Identifier: MIT */
/* The part levels' part of `seamwalk-pack info` (sw_pack_info.h): how many
 * pieces have them (and how many parts are cut into pieces), and per front
 * and rank (finest first) the levels, their triangles, their largest
 * measured error and their largest side shaded wrong. */
#include <inttypes.h>
#include <string.h>

#include "sw_pack_info.h"

/* Rows by front and rank; the cut parts' levels of themselves whole last. */
enum { ROWS = SW_PART_LEVELS_MAX * (SW_PART_LEVEL_FRONTS + 1) };

typedef struct part_level_figures {
    uint32_t pieces, cut_parts, cut_pieces, levels[ROWS];
    uint64_t triangles[ROWS], bytes;
    double error_max[ROWS], shading_side_max[ROWS];
} part_level_figures;

/* The row of level i of a piece whose levels start at `first`: its
 * front's block, its rank within the front. */
static uint32_t row_of(const sw_part_levels *pl, uint32_t first, uint32_t i)
{
    uint32_t rank = 0;
    for (uint32_t k = i; k > first && pl->levels[k - 1].front == pl->levels[i].front; k--)
        rank++;
    uint32_t f = pl->levels[i].front == SW_PART_LEVEL_WHOLE ? SW_PART_LEVEL_FRONTS
                                                             : pl->levels[i].front;
    return f * SW_PART_LEVELS_MAX + rank;
}

/* Parts cut into pieces: part by part (a run of surfaces, as the reader
 * checked), its pieces first .. end. */
static void count_cut(const sw_pack *pack, part_level_figures *f)
{
    const sw_part_levels *pl = &pack->part_levels;
    for (uint32_t s = 0, e; s < pl->surface_count; s = e) {
        uint32_t first = pl->piece_of[s], end = first + 1;
        for (e = s; e < pl->surface_count && pack->surfaces[e].part == pack->surfaces[s].part; e++)
            end = pl->piece_of[e] + 1 > end ? pl->piece_of[e] + 1 : end;
        f->cut_parts += end - first > 1;
        f->cut_pieces += end - first > 1 ? end - first : 0;
    }
}

static part_level_figures gather(const sw_pack *pack)
{
    part_level_figures f;
    memset(&f, 0, sizeof f);
    const sw_part_levels *pl = &pack->part_levels;
    for (uint32_t i = 0; i < pack->header->section_count; i++) {
        uint32_t t = pack->sections[i].type;
        if (t >= SW_SECTION_PART_LEVELS && t <= SW_SECTION_PART_LEVEL_PIECE_OF)
            f.bytes += pack->sections[i].size;
    }
    count_cut(pack, &f);
    for (uint32_t g = 0; g < pl->piece_count; g++) {
        uint32_t a = pl->piece_levels[g], b = pl->piece_levels[g + 1];
        f.pieces += b > a;
        for (uint32_t i = a; i < b; i++) {
            uint32_t r = row_of(pl, a, i);
            f.levels[r]++;
            f.triangles[r] += pl->levels[i].index_count / 3;
            if (pl->levels[i].shading_side > f.shading_side_max[r])
                f.shading_side_max[r] = pl->levels[i].shading_side;
            f.error_max[r] = pl->levels[i].error > f.error_max[r] ? pl->levels[i].error
                                                                   : f.error_max[r];
        }
    }
    return f;
}

void sw_pack_print_part_levels_text(FILE *out, const sw_pack *pack)
{
    if (!pack->part_levels.levels)
        return;
    part_level_figures f = gather(pack);
    fprintf(out, "  %-16s %" PRIu32 " of %" PRIu32 " pieces (%" PRIu32 " parts cut into %" PRIu32
            "), %" PRIu32 " levels, %" PRIu64 " bytes\n", "part levels", f.pieces,
            pack->part_levels.piece_count, f.cut_parts, f.cut_pieces,
            pack->part_levels.level_count, f.bytes);
    for (uint32_t r = 0; r < ROWS; r++) {
        if (!f.levels[r])
            continue;
        char front[16] = "whole";
        if (r / SW_PART_LEVELS_MAX < SW_PART_LEVEL_FRONTS)
            snprintf(front, sizeof front, "front %u", (unsigned)(r / SW_PART_LEVELS_MAX));
        fprintf(out, "    %-7s rank %-2" PRIu32 " %" PRIu32 " levels, %" PRIu64 " triangles, "
                "error max %.6g, shading side max %.6g\n", front, r % SW_PART_LEVELS_MAX,
                f.levels[r], f.triangles[r], f.error_max[r], f.shading_side_max[r]);
    }
}

void sw_pack_print_part_levels_json(FILE *out, const sw_pack *pack)
{
    if (!pack->part_levels.levels) {
        fprintf(out, "  \"part_levels\": null,\n");
        return;
    }
    part_level_figures f = gather(pack);
    fprintf(out, "  \"part_levels\": {\"pieces\": %" PRIu32 ", \"pieces_with_levels\": %" PRIu32
            ", \"cut_parts\": %" PRIu32 ", \"cut_pieces\": %" PRIu32 ", \"levels\": %" PRIu32
            ", \"bytes\": %" PRIu64 ", \"ranks\": [", pack->part_levels.piece_count, f.pieces,
            f.cut_parts, f.cut_pieces, pack->part_levels.level_count, f.bytes);
    const char *sep = "";
    for (uint32_t r = 0; r < ROWS; r++) {
        if (!f.levels[r])
            continue;
        fprintf(out, "%s{\"front\": %" PRIu32 ", \"rank\": %" PRIu32 ", \"levels\": %" PRIu32
                ", \"triangles\": %" PRIu64 ", \"error_max\": %.9g, \"shading_side_max\": %.9g}",
                sep, r / SW_PART_LEVELS_MAX < SW_PART_LEVEL_FRONTS ? r / SW_PART_LEVELS_MAX
                                                                  : SW_PART_LEVEL_WHOLE,
                r % SW_PART_LEVELS_MAX, f.levels[r],
                f.triangles[r], f.error_max[r], f.shading_side_max[r]);
        sep = ", ";
    }
    fprintf(out, "]},\n");
}
