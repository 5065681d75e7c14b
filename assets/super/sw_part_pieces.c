/* SPDX-License-Identifier: MIT */
/* Parts cut into pieces by halving at the median (sw_part_pieces.h). */
#include "sw_part_pieces.h"

#include <math.h>
#include <stdlib.h>

typedef struct centre {
    float at[3];              /* the centre of the surface's patches' boxes */
    uint32_t surface;
} centre;

/* qsort has no context: one comparator per axis; ties by surface, so the
 * cut is the same on every machine. */
#define BY_AXIS(k)                                                              \
    static int by_axis_##k(const void *pa, const void *pb)                      \
    {                                                                           \
        const centre *a = pa, *b = pb;                                          \
        if (a->at[k] != b->at[k])                                               \
            return a->at[k] < b->at[k] ? -1 : 1;                                \
        return a->surface < b->surface ? -1 : a->surface > b->surface;          \
    }
BY_AXIS(0)
BY_AXIS(1)
BY_AXIS(2)
static int (*const by_axis[3])(const void *, const void *) = { by_axis_0, by_axis_1, by_axis_2 };

static centre centre_of(const sw_pack *pack, uint32_t s)
{
    const sw_pack_surface *su = &pack->surfaces[s];
    float lo[3], hi[3];
    sw_pack_patches_box(pack->patches, su->first_patch, su->patch_count, lo, hi);
    centre c = { { 0, 0, 0 }, s };
    for (int k = 0; k < 3 && su->patch_count; k++)
        c.at[k] = 0.5f * (lo[k] + hi[k]);
    return c;
}

/* Halves c[0 .. n) until each half has at most max_patches patches (or one
 * surface); each final half gets the next provisional number. */
static void halve(const sw_pack *pack, centre *c, uint32_t n, uint32_t max_patches,
                  uint32_t *piece_of, uint32_t *next)
{
    uint64_t patches = 0;
    float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t i = 0; i < n; i++) {
        patches += pack->surfaces[c[i].surface].patch_count;
        for (int k = 0; k < 3; k++)
            lo[k] = fminf(lo[k], c[i].at[k]), hi[k] = fmaxf(hi[k], c[i].at[k]);
    }
    if (patches <= max_patches || n < 2) {
        for (uint32_t i = 0; i < n; i++)
            piece_of[c[i].surface] = *next;
        (*next)++;
        return;
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        axis = hi[k] - lo[k] > hi[axis] - lo[axis] ? k : axis;
    qsort(c, n, sizeof *c, by_axis[axis]);
    halve(pack, c, n / 2, max_patches, piece_of, next);
    halve(pack, c + n / 2, n - n / 2, max_patches, piece_of, next);
}

/* Numbers the pieces of surfaces [first, end) as their first surfaces
 * come, from *next on; map holds room for the provisional numbers. */
static void renumber(uint32_t *piece_of, uint32_t first, uint32_t end, uint32_t provisional,
                     uint32_t *map, uint32_t *next)
{
    for (uint32_t k = 0; k < provisional; k++)
        map[k] = UINT32_MAX;
    for (uint32_t s = first; s < end; s++) {
        uint32_t *m = &map[piece_of[s]];
        if (*m == UINT32_MAX)
            *m = (*next)++;
        piece_of[s] = *m;
    }
}

sw_status sw_part_pieces(const sw_pack *pack, const sw_part_pieces_options *opt,
                         uint32_t *piece_of, uint32_t *piece_count, sw_error *err)
{
    uint32_t cut = opt && opt->cut_patches ? opt->cut_patches : SW_PART_CUT_PATCHES;
    uint32_t most = opt && opt->piece_patches ? opt->piece_patches : 256;
    uint32_t n = pack->surface_count;
    *piece_count = 0;
    for (uint32_t s = 1; s < n; s++)
        if (pack->surfaces[s].part < pack->surfaces[s - 1].part)
            return sw_error_set(err, SW_ERR_ARG, "part levels: surface %u of part %u comes after "
                                "one of part %u (pieces need the surfaces by part)", (unsigned)s,
                                (unsigned)pack->surfaces[s].part,
                                (unsigned)pack->surfaces[s - 1].part);
    centre *c = malloc(((size_t)n + 1) * sizeof *c);
    uint32_t *map = malloc(((size_t)n + 1) * sizeof *map);
    if (!c || !map) {
        free(c);
        free(map);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "part levels: out of memory for the pieces");
    }
    for (uint32_t s = 0, e; s < n; s = e) {
        uint32_t part = pack->surfaces[s].part, provisional = 0;
        for (e = s; e < n && pack->surfaces[e].part == part; e++)
            c[e - s] = centre_of(pack, e);
        uint32_t max = pack->parts[part].patch_count > cut ? most : UINT32_MAX;
        halve(pack, c, e - s, max, piece_of, &provisional);
        renumber(piece_of, s, e, provisional, map, piece_count);
    }
    free(c);
    free(map);
    return SW_OK;
}

double sw_part_diagonal(const sw_pack *pack, uint32_t p)
{
    return sw_pack_patches_diagonal(pack->patches, pack->parts[p].first_patch,
                                    pack->parts[p].patch_count);
}
