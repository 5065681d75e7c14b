/* SPDX-License-Identifier: MIT */
/* A face's trimming loop as curves in its surface's parameter space: what
 * importers hand to the model (sw_model_add_surface) and what the trim
 * flattener (sw_trim.h) takes. Its own header so that the trim code, below
 * the model, needs nothing else of it. Host only. */
#ifndef SW_TRIM_LOOP_H
#define SW_TRIM_LOOP_H

#include <stddef.h>
#include <stdint.h>

#include "sw_nurbs.h"

/* One trimming loop as the importer gives it: curves in the surface's
 * parameter space (sw_nurbs_curve with points u, v, 0, w), head to tail. */
typedef struct sw_model_loop_input {
    const sw_nurbs_curve *curves;
    const int *computed;     /* per curve, may be NULL: 1 when made by point inversion */
    size_t curve_count;
    int outer;
    const double *gaps;      /* per curve, may be NULL (all 0): sw_model_trim_curve.gap */
    const uint32_t *edges;   /* per curve, may be NULL (all 0): sw_model_trim_curve.edge */
} sw_model_loop_input;

#endif
