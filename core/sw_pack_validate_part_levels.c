/* SPDX-License-Identifier: MIT */
/* The part levels' sections (PART_LEVELS, PART_LEVEL_RECORDS,
 * PART_LEVEL_RANGES, PART_LEVEL_VERTICES, PART_LEVEL_INDICES,
 * PART_LEVEL_PIECE_OF; core/sw_part_levels.h), found, mapped and checked once at load, apart
 * from sw_pack_read.c as the super-surfaces are. Rules: assets/PACK_FORMAT.md,
 * "Part levels". */
#include <math.h>
#include <stddef.h>

#include "sw_pack_validate.h"

_Static_assert(sizeof(sw_part_level) == 32, "sw_part_level");
_Static_assert(sizeof(sw_pack_part_levels) == 16, "sw_pack_part_levels");
_Static_assert(sizeof(sw_level_vertex) == 16, "sw_level_vertex");

enum { GROUP = 6 };
static const uint32_t group_types[GROUP] = {
    SW_SECTION_PART_LEVELS, SW_SECTION_PART_LEVEL_RECORDS, SW_SECTION_PART_LEVEL_RANGES,
    SW_SECTION_PART_LEVEL_VERTICES, SW_SECTION_PART_LEVEL_INDICES,
    SW_SECTION_PART_LEVEL_PIECE_OF };
static const uint64_t group_records[GROUP] = { sizeof(sw_pack_part_levels), sizeof(sw_part_level),
                                               sizeof(uint32_t), sizeof(sw_level_vertex),
                                               sizeof(uint16_t), sizeof(uint32_t) };

/* All six or none, beside SURFACES; the counts record's counts are the
 * sections' sizes. */
static sw_status check_group(const sw_pack *pack, const int32_t index[GROUP], sw_error *err)
{
    int present = 0;
    for (int k = 0; k < GROUP; k++)
        present += index[k] >= 0;
    if (present == 0)
        return SW_OK;
    for (int k = 0; k < GROUP; k++)
        if (index[k] < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section table: no %s section (the part "
                                "levels' six sections appear together)",
                                sw_section_type_name(group_types[k]));
    const sw_pack_section *sec = pack->sections;
    if (sec[index[0]].size != sizeof(sw_pack_part_levels))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (PART_LEVELS): %llu bytes, expected "
                            "%zu", (int)index[0], (unsigned long long)sec[index[0]].size,
                            sizeof(sw_pack_part_levels));
    const sw_pack_part_levels *h = (const sw_pack_part_levels *)(pack->data + sec[index[0]].offset);
    const uint64_t want[GROUP] = { 1, h->level_count, (uint64_t)h->piece_count + 1,
                                   h->vertex_count, h->index_count, pack->surface_count };
    if (!pack->surfaces)
        return sw_error_set(err, SW_ERR_FORMAT, "section table: part levels without a SURFACES "
                            "section (PART_LEVEL_PIECE_OF indexes it)");
    for (int k = 1; k < GROUP; k++)
        if (sec[index[k]].size / group_records[k] != want[k])
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): %llu records, expected "
                                "%llu (PART_LEVELS)", (int)index[k],
                                sw_section_type_name(group_types[k]),
                                (unsigned long long)(sec[index[k]].size / group_records[k]),
                                (unsigned long long)want[k]);
    return SW_OK;
}

/* The fronts piece g's levels may have: a part not cut 0; a piece of a cut
 * part below SW_PART_LEVEL_FRONTS, and its first piece also
 * SW_PART_LEVEL_WHOLE (the part's levels of itself whole). */
static int front_allowed(uint32_t front, int cut, int first)
{
    return cut ? front < SW_PART_LEVEL_FRONTS || (first && front == SW_PART_LEVEL_WHOLE)
               : front == 0;
}

/* Level i of piece g (of a part cut into pieces when cut, its first piece
 * when first), after the level `prev` of the same piece (NULL for its
 * first): its ranges, front and error. */
static sw_status check_level(const sw_part_levels *v, uint32_t i, uint32_t g, int cut, int first,
                             const sw_part_level *prev, sw_error *err)
{
    const sw_part_level *l = &v->levels[i];
    if (l->piece != g)
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RECORDS[%u].piece: %u, expected %u "
                            "(PART_LEVEL_RANGES gives it to that piece)", (unsigned)i,
                            (unsigned)l->piece, (unsigned)g);
    if (!front_allowed(l->front, cut, first) || (prev && l->front < prev->front))
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RECORDS[%u].front: %u, expected "
                            "below %u (%s) and not below the piece's level before it",
                            (unsigned)i, (unsigned)l->front,
                            cut ? (unsigned)SW_PART_LEVEL_FRONTS : 1u,
                            cut ? (first ? "or 255, its part is cut and this is its first piece"
                                         : "its part is cut into pieces")
                                : "a part not cut has one");
    int same = prev && prev->front == l->front;
    if (!isfinite(l->error) || !(l->error > 0) || (same && !(l->error > prev->error)))
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RECORDS[%u].error: %g, expected "
                            "finite, > 0 and above the piece's level before it at its front",
                            (unsigned)i, (double)l->error);
    if (l->vertex_count < 3 || l->vertex_count > 65536 ||
        (uint64_t)l->first_vertex + l->vertex_count > v->vertex_count)
        return sw_error_set(err, SW_ERR_RANGE, "PART_LEVEL_RECORDS[%u]: vertices %u + %u, "
                            "expected 3 to 65536 within PART_LEVEL_VERTICES (%u)", (unsigned)i,
                            (unsigned)l->first_vertex, (unsigned)l->vertex_count,
                            (unsigned)v->vertex_count);
    if (l->index_count == 0 || l->index_count % 3 != 0 ||
        (uint64_t)l->first_index + l->index_count > v->index_count)
        return sw_error_set(err, SW_ERR_RANGE, "PART_LEVEL_RECORDS[%u]: indices %u + %u, "
                            "expected a positive multiple of 3 within PART_LEVEL_INDICES (%u)",
                            (unsigned)i, (unsigned)l->first_index, (unsigned)l->index_count,
                            (unsigned)v->index_count);
    if (!isfinite(l->shading_side) || !(l->shading_side >= 0))
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RECORDS[%u].shading_side: %g, "
                            "expected finite and >= 0", (unsigned)i, (double)l->shading_side);
    for (uint32_t k = 0; k < l->index_count; k++)
        if (v->indices[l->first_index + k] >= l->vertex_count)
            return sw_error_set(err, SW_ERR_RANGE, "PART_LEVEL_INDICES[%u]: %u, expected < %u "
                                "(PART_LEVEL_RECORDS[%u].vertex_count)",
                                (unsigned)(l->first_index + k),
                                (unsigned)v->indices[l->first_index + k],
                                (unsigned)l->vertex_count, (unsigned)i);
    return SW_OK;
}

/* PART_LEVEL_PIECE_OF: the surfaces come part by part (each part's run of
 * surfaces after the last's), a part's pieces are new numbers counted up
 * from the last part's, each first met in the order of their numbers, and
 * no piece is empty; so pieces never span parts and follow them. */
static sw_status check_pieces(const sw_pack *pack, const sw_part_levels *v, sw_error *err)
{
    uint32_t next = 0, run_first = 0;
    for (uint32_t s = 0; s < v->surface_count; s++) {
        uint32_t g = v->piece_of[s], p = pack->surfaces[s].part;
        int run = s == 0 || p != pack->surfaces[s - 1].part;
        if (run && s > 0 && p < pack->surfaces[s - 1].part)
            return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_PIECE_OF: surface %u of part %u "
                                "after one of part %u (part levels need the surfaces by part)",
                                (unsigned)s, (unsigned)p, (unsigned)pack->surfaces[s - 1].part);
        if (run)
            run_first = next;
        if (g < run_first || g > next || g >= v->piece_count || (run && g != next))
            return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_PIECE_OF[%u]: %u, expected %u "
                                "to %u (a part's own pieces, numbered as they come)",
                                (unsigned)s, (unsigned)g, (unsigned)(run ? next : run_first),
                                (unsigned)(next < v->piece_count ? next : v->piece_count - 1));
        next += g == next;
    }
    if (next != v->piece_count)
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_PIECE_OF: %u pieces have surfaces, "
                            "expected all %u", (unsigned)next, (unsigned)v->piece_count);
    return SW_OK;
}

/* Piece g's levels; cut: its part has other pieces; first: g is its
 * part's first. */
static sw_status check_piece(const sw_part_levels *v, uint32_t g, int cut, int first,
                             sw_error *err)
{
    uint32_t a = v->piece_levels[g], b = v->piece_levels[g + 1];
    if (b < a || b > v->level_count || b - a > SW_PART_LEVELS_MAX * (SW_PART_LEVEL_FRONTS + 1))
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RANGES[%u]: %u to %u, expected "
                            "rising by at most %u within the %u levels", (unsigned)g,
                            (unsigned)a, (unsigned)b,
                            (unsigned)(SW_PART_LEVELS_MAX * (SW_PART_LEVEL_FRONTS + 1)),
                            (unsigned)v->level_count);
    for (uint32_t i = a; i < b; i++) {
        sw_status st = check_level(v, i, g, cut, first, i > a ? &v->levels[i - 1] : NULL, err);
        if (st != SW_OK)
            return st;
    }
    return SW_OK;
}

static sw_status check_records(const sw_pack *pack, const sw_part_levels *v, sw_error *err)
{
    sw_status st = check_pieces(pack, v, err);
    if (st != SW_OK)
        return st;
    if (v->piece_levels[0] != 0 || v->piece_levels[v->piece_count] != v->level_count)
        return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_RANGES: runs from %u to %u, expected "
                            "0 to %u (the level count)", (unsigned)v->piece_levels[0],
                            (unsigned)v->piece_levels[v->piece_count], (unsigned)v->level_count);
    /* Part by part (its run of surfaces): its pieces are first .. end. */
    for (uint32_t s = 0, e; st == SW_OK && s < v->surface_count; s = e) {
        uint32_t first = v->piece_of[s], end = first + 1;
        for (e = s; e < v->surface_count && pack->surfaces[e].part == pack->surfaces[s].part; e++)
            end = v->piece_of[e] + 1 > end ? v->piece_of[e] + 1 : end;
        for (uint32_t g = first; st == SW_OK && g < end; g++)
            st = check_piece(v, g, end - first > 1, g == first, err);
    }
    if (st != SW_OK)
        return st;
    for (uint32_t i = 0; i < v->vertex_count; i++) {
        const sw_level_vertex *x = &v->vertices[i];
        if (!isfinite(x->p[0]) || !isfinite(x->p[1]) || !isfinite(x->p[2]) || x->normal[3])
            return sw_error_set(err, SW_ERR_FORMAT, "PART_LEVEL_VERTICES[%u]: expected finite "
                                "coordinates and a zero fourth normal byte", (unsigned)i);
    }
    return SW_OK;
}

sw_status sw_pack_map_part_levels(const uint8_t *data, sw_pack *out, sw_error *err)
{
    int32_t index[GROUP];
    out->part_levels = (sw_part_levels){ 0 };
    sw_status st = sw_pack_find_group(out, group_types, group_records, GROUP, index, err);
    if (st == SW_OK)
        st = check_group(out, index, err);
    if (st != SW_OK || index[0] < 0)
        return st;
    const sw_pack_section *sec = out->sections;
    const sw_pack_part_levels *h = (const sw_pack_part_levels *)(data + sec[index[0]].offset);
    sw_part_levels v = {
        .levels = (const sw_part_level *)(data + sec[index[1]].offset),
        .piece_levels = (const uint32_t *)(data + sec[index[2]].offset),
        .piece_of = (const uint32_t *)(data + sec[index[5]].offset),
        .vertices = (const sw_level_vertex *)(data + sec[index[3]].offset),
        .indices = (const uint16_t *)(data + sec[index[4]].offset),
        .level_count = h->level_count, .vertex_count = h->vertex_count,
        .index_count = h->index_count, .piece_count = h->piece_count,
        .surface_count = out->surface_count };
    st = check_records(out, &v, err);
    if (st == SW_OK)
        out->part_levels = v;
    return st;
}
