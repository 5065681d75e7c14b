/* SPDX-License-Identifier: MIT */
/* The depth range a frame of the seam walk (sw_seam_walk.h) draws: the
 * nearest and farthest eye-space depths of the boxes of the surfaces it
 * selected for drawing, so the frame loop can fit near and far to them
 * (sw_view_fit_depth) and spend the depth buffer's bits where the model is.
 * Called after sw_seam_walk_select, before the projection is uploaded.
 * Reads the walk; no allocation; GL-free. */
#ifndef SW_SEAM_DEPTH_H
#define SW_SEAM_DEPTH_H

/* Declared here, not included, so the includes run one way: the walk's
 * state (../sw_seam_walk.h), which includes this folder's headers, and the
 * frame's view (sw_view.h), which belongs to the walk's folder. */
struct sw_seam_walk;
struct sw_view;

/* Over the patches in view of every surface the walk will draw: *nearest
 * the smallest depth at which their boxes can be seen (inside the view's
 * sides; at least view's near plane), *farthest their farthest box corner.
 * 0 when nothing is drawn (both left untouched). */
int sw_seam_depth_range(const struct sw_seam_walk *w, const struct sw_view *view, double *nearest,
                        double *farthest);

#endif
