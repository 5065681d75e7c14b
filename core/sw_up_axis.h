/* SPDX-License-Identifier: MIT */
/* The up axis of a model: which of its coordinate axes points up in the
 * world it was drawn in. Mechanical CAD (STEP, IGES) is z-up by convention,
 * the runtime's default camera is y-up; the pack says which (its ORIENTATION
 * section, assets/PACK_FORMAT.md) so the runtime can stand a model upright
 * by turning its camera instead of its geometry. Used by the pack reader,
 * seamwalk-pack (--up, scene up_axis, info) and the runtime's orbit. */
#ifndef SW_UP_AXIS_H
#define SW_UP_AXIS_H

#include <stdint.h>

#include "sw_error.h"
#include "sw_math.h"
#include "sw_pack.h"

/* The stored value: the axis number (1 x, 2 y, 3 z), negative for the
 * opposite direction. 0 is no axis (callers use it for "not given"). */
enum sw_up_axis {
    SW_UP_NEG_Z = -3, SW_UP_NEG_Y = -2, SW_UP_NEG_X = -1,
    SW_UP_POS_X = 1, SW_UP_POS_Y = 2, SW_UP_POS_Z = 3,
};

/* What a pack without an ORIENTATION section means (every pack before it). */
#define SW_UP_DEFAULT SW_UP_POS_Y

/* 1 when axis is one of the six values above. */
int sw_up_axis_valid(int32_t axis);

/* "+x", "-x", "+y", "-y", "+z", "-z"; "invalid" for anything else. */
const char *sw_up_axis_name(int32_t axis);

/* Reads "x", "y", "z", "+x", ..., "-z" (lower case, nothing around it) into
 * *out; 0 (and *out untouched) for anything else. */
int sw_up_axis_parse(const char *text, int32_t *out);

/* The unit vector of a valid axis ((0, 1, 0) for +y); +y for an invalid one. */
sw_vec3 sw_up_axis_vector(int32_t axis);

/* The pack's up axis: its ORIENTATION record's, SW_UP_DEFAULT without one. */
int32_t sw_pack_up_axis(const sw_pack *pack);

/* For sw_pack_open_memory, after the table and checksums are checked: finds
 * the ORIENTATION section (at most one, exactly 16 bytes, a valid axis,
 * reserved zero) and sets out->orientation, NULL when there is none. */
sw_status sw_pack_map_orientation(const uint8_t *data, sw_pack *out, sw_error *err);

#endif
