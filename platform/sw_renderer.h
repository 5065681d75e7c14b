/* SPDX-License-Identifier: MIT */
/* The GLES2 renderer: one shader program with per-fragment lighting (a
 * headlight plus a key light, two-sided so soups of patches with mixed
 * orientation still shade), depth test, 16-bit indices, streaming vertex and
 * index buffers. No VAOs, no extensions. Only the GL thread calls it. */
#ifndef SW_RENDERER_H
#define SW_RENDERER_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_tess.h"

typedef struct sw_renderer {
    unsigned int program;
    int u_model_view, u_projection, u_color, u_back, u_fill, u_hide_back;
    int a_position, a_normal;
    unsigned int vertex_buffer, index_buffer;
    uint32_t max_vertices, max_indices;
    uint64_t draw_calls, triangles;   /* since init, for the stats */
    int back_hidden;                  /* sw_renderer_set_back_hidden */
    float view[16];                   /* this frame's camera, for sw_renderer_set_model */
} sw_renderer;

/* Compiles the program and creates buffers for batches of up to max_vertices
 * (<= 65536) vertices and max_indices indices. */
sw_status sw_renderer_init(sw_renderer *r, uint32_t max_vertices, uint32_t max_indices,
                           sw_error *err);
void sw_renderer_destroy(sw_renderer *r);

/* Sets viewport, clears colour and depth, loads the camera matrices
 * (column-major float, as sw_mat4_to_float writes them). */
void sw_renderer_begin_frame(sw_renderer *r, int width, int height, const float clear_rgba[4],
                             const float model_view[16], const float projection[16]);
void sw_renderer_set_color(sw_renderer *r, const float rgba[4]);

/* Draws that follow place their vertices by model (column-major, a
 * similarity: rotation, uniform scale, translation) before the frame's
 * camera; NULL: the camera alone again. */
void sw_renderer_set_model(sw_renderer *r, const float model[16]);

/* With rgb, back faces (clockwise on screen) are drawn flat in rgb instead
 * of lit: in a colour of their own, the inside of a closed solid showing
 * through a crack can be told from its outside (tests/test_image_holes.sh).
 * NULL, the default: both sides lit. */
void sw_renderer_set_back_color(sw_renderer *r, const float rgb[3]);

/* hidden 1: back faces (clockwise on screen) are not drawn at all
 * (GL_CULL_FACE), for closed solids whose faces all point out; the seam
 * walk's cone culling leaves out whole surfaces only in this mode (it
 * removes what this would not draw anyway). Fill fans wind either way, so
 * they are not culled by winding but by their normals: a fan fragment
 * whose normal faces away is discarded, as its surface faces away there.
 * 0, the default: both sides drawn. */
void sw_renderer_set_back_hidden(sw_renderer *r, int hidden);

/* Draws that follow, until set again, are fill fans over seam crossings
 * (firmware/walk/workers/sw_seam_fill.h): lit on the side their normals face, whatever
 * way the sliver winds, never flat like a back face. */
void sw_renderer_set_fill(sw_renderer *r, int fill);

/* Uploads one batch (buffer orphaning, then glBufferSubData) and draws it as
 * GL_TRIANGLES. vertex_count <= max_vertices, index_count <= max_indices. */
void sw_renderer_draw(sw_renderer *r, const sw_vertex *verts, uint32_t vertex_count,
                      const uint16_t *indices, uint32_t index_count);

/* Points the position and normal attributes at the bound vertex buffer's
 * sw_vertex array starting base bytes in, and enables them (no VAOs in
 * GLES2: every draw sets its layout). */
void sw_renderer_set_layout(const sw_renderer *r, size_t base);

/* Draws one small triangle the way frames draw (the state begin_frame
 * sets, the same vertex layout) into a cleared width x height frame and
 * waits for it: llvmpipe compiles a shader's machine code at its first
 * draw (LLVM, tens of ms), which would otherwise fall into the first frame.
 * The start calls it while the pack is still loading. The next
 * begin_frame clears what it drew. */
void sw_renderer_warm_up(sw_renderer *r, int width, int height);

/* Waits for the GL to finish (glFinish), so frame times include the rendering. */
void sw_renderer_finish(sw_renderer *r);

#endif
