/* SPDX-License-Identifier: MIT */
/* A face's trimming loops cut in two along a parameter line (u = at or
 * v = at): the loops of the region on each side, the cut closing them. The
 * model splits a surface whose border is longer than one draw can show
 * (sw_model_split.h) with it. Curves crossing the line are split there
 * exactly (knot insertion); the loops are oriented first (outer ones
 * counter-clockwise, holes clockwise) so that the crossings pair up along
 * the line. Host only (malloc). */
#ifndef SW_TRIM_CLIP_H
#define SW_TRIM_CLIP_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"

/* Loops with their own curves: loops[l] names curves[first_curve ..
 * first_curve + curve_count). Owned; zero-initialise, free with
 * sw_trim_set_free. */
typedef struct sw_trim_set {
    sw_model_trim_curve *curves;
    size_t curve_count, curve_capacity;
    sw_model_loop *loops;
    size_t loop_count, loop_capacity;
} sw_trim_set;

void sw_trim_set_free(sw_trim_set *set);

/* Copies a model surface's loops into out (empty); a surface without loops
 * (its whole domain) gets one outer loop of four lines around its domain. */
sw_status sw_trim_set_of_surface(const sw_model *model, size_t surface, sw_trim_set *out,
                                 sw_error *err);

/* The regions of in where coordinate axis (0: u, 1: v) is below at (low)
 * and above it (high), each as loops (low and high empty on entry). A loop
 * the line misses goes whole to its side. SW_ERR_RANGE when the line
 * passes within tol of a curve's end or touches a curve without crossing
 * it, or the crossings do not pair up (loops that cross each other): the
 * caller tries another line. SW_ERR_NO_MEMORY. */
sw_status sw_trim_clip(const sw_trim_set *in, int axis, double at, double tol, sw_trim_set *low,
                       sw_trim_set *high, sw_error *err);

#endif
