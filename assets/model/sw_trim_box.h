/* SPDX-License-Identifier: MIT */
/* The tight bounding box of a model's trimmed faces, within a given
 * tolerance, for reports and for checking importers against each other. The
 * pack keeps control-hull boxes (cheap and conservative); this is the box of
 * the surface points that are really inside the trims. Host only. */
#ifndef SW_TRIM_BOX_H
#define SW_TRIM_BOX_H

#include "sw_error.h"
#include "sw_model.h"

/* Box of every trimmed face of the model (surfaces first..first+count-1 of
 * the model when count > 0, else all), each side within tolerance_mm of the
 * true extreme (never inside it by more than the trims' own tolerance). */
sw_status sw_model_trimmed_box(const sw_model *model, size_t first_surface, size_t count,
                               double tolerance_mm, sw_box *out, sw_error *err);

#endif
