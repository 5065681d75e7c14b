/* SPDX-License-Identifier: MIT */
/* The trim module (sw_trim.h) applied to faces already in a model: their
 * stored loops as polylines, their trimmed areas. Above both the model and
 * the trim code, so that neither needs the other's whole API. Host only. */
#ifndef SW_MODEL_TRIMS_H
#define SW_MODEL_TRIMS_H

#include <stddef.h>

#include "sw_error.h"
#include "sw_model.h"
#include "sw_trim.h"

/* sw_trim_polyline_build for a surface already in the model (its stored loops). */
sw_status sw_trim_polyline_from_model(const sw_model *model, size_t surface, double tolerance,
                                      sw_trim_polyline *out, sw_error *err);

/* A model surface's trimmed area to about rel_tol (> 0, at least 1e-12): flattens its loops at a
 * tolerance derived from rel_tol and the domain and calls sw_trim_area. */
sw_status sw_trim_model_surface_area(const sw_model *model, size_t surface, double rel_tol,
                                     double *area_out, sw_error *err);

#endif
