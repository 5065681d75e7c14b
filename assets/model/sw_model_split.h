/* SPDX-License-Identifier: MIT */
/* Copies of a model's surfaces into another model, whole or cut into
 * pieces along parameter lines (sw_trim_clip.h). A surface whose border
 * has more points than one draw's 65536 vertices can show (a spring's
 * wire swept along many turns of a helix) is drawn as pieces, each with
 * the same geometry and the part of the face its loops bound: the
 * tessellation and the patches follow the loops (sw_model_add_surface
 * drops the patches a piece does not touch). Host only (malloc). */
#ifndef SW_MODEL_SPLIT_H
#define SW_MODEL_SPLIT_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"
#include "sw_trim_clip.h"

/* Appends surface s of from to the current part of to, as it is (loops,
 * orientation, patches). */
sw_status sw_model_copy_surface(const sw_model *from, size_t s, sw_model *to, sw_error *err);

/* The pieces of surface s cut where coordinate axis (0: u, 1: v) equals
 * each of at[0 .. count) (ascending, inside its domain): pieces[0 ..
 * count] (empty on entry) get each piece's loops, lowest first.
 * SW_ERR_RANGE naming the line when a cut is refused (sw_trim_clip): the
 * caller may try others; the pieces are then freed. */
sw_status sw_model_cut_surface(const sw_model *model, size_t s, int axis, const double *at,
                               size_t count, sw_trim_set *pieces, sw_error *err);

/* A surface to replace by pieces, in sw_model_split. */
typedef struct sw_model_cut {
    size_t surface;
    const sw_trim_set *pieces;
    size_t piece_count;
} sw_model_cut;

/* out (initialised, empty): in with every surface of cuts (ascending by
 * surface) replaced by one surface per piece, in place; parts, their
 * names, colours and transforms, the viewpoints and the tolerance as in
 * in. */
sw_status sw_model_split(const sw_model *in, const sw_model_cut *cuts, size_t cut_count,
                         sw_model *out, sw_error *err);

#endif
