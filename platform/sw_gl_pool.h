/* SPDX-License-Identifier: MIT */
/* GL buffers that keep meshes across frames (paper 004 section 6.4: a
 * surface's tessellation is uploaded once and drawn until it is redone).
 * One vertex buffer and one index buffer, sized at start (GLES2 has no
 * buffer growth without reallocating and re-uploading everything); the
 * caller decides where each mesh lives (sw_buddy.h) and uploads a mesh's
 * ranges with glBufferSubData when it changes. Indices are local to their
 * mesh: a draw of one mesh points the attributes at its first vertex,
 * since GLES2 has no base-vertex draw; merged draws (below) copy them
 * with the first vertex added. Only the GL thread calls it. */
#ifndef SW_GL_POOL_H
#define SW_GL_POOL_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"
#include "sw_renderer.h"
#include "sw_tess.h"

/* The draws the driver may hold unfinished, in triangles (sw_gl_pool_draw
 * waits for it with glFinish past them). llvmpipe bins draws into scenes of
 * at most 36 MiB of 64 kiB heap blocks and, while its rasteriser threads
 * are behind, opens another scene (up to 64) rather than wait: on the
 * 40,000-patch showroom at 1280x720 the blocks live at once rose in steps
 * of one scene, 4 to 7 scenes' worth (147 to 258 MB), as the machine's load
 * came and went, and the heap kept the most it had reached. At about 600 bytes of scene a triangle there,
 * 32768 triangles keep it to about one scene, at no frame time we could
 * measure (docs/perf/2026-12-05-soak.md). Fencing each batch (EGL_KHR_fence_sync) and
 * waiting for the one before, so the rasteriser works while the next batch
 * is drawn, was not faster there and held more (16384 a batch: 17 to 35 MB
 * more after the first loop, and one run grew 5.6 MB after it). */
#define SW_GL_POOL_BATCH_TRIANGLES 32768

/* llvmpipe's scene a triangle, bytes: the live scene blocks at the most
 * over the triangles of that frame (258 MiB, about 430,000 triangles). */
#define SW_GL_POOL_SCENE_BYTES_PER_TRIANGLE 600

/* Merged draws (sw_gl_pool_queue): indices and runs a region holds
 * before what is queued is drawn; two regions, the meshes' and the fans'. */
#define SW_GL_POOL_MERGE_INDICES (1u << 20)
#define SW_GL_POOL_MERGE_RUNS (1u << 15)

enum { SW_GL_POOL_MESHES = 0, SW_GL_POOL_FANS = 1 };

/* A run of queued indices drawn with one call, in one colour. */
typedef struct sw_gl_run {
    const float *rgba;
    uint32_t first, count;
} sw_gl_run;

/* One region of merged draws: absolute 32-bit indices, staged, and runs. */
typedef struct sw_gl_queue {
    uint32_t *indices;
    sw_gl_run *runs;
    uint32_t count, run_count;
} sw_gl_queue;

typedef struct sw_gl_pool {
    unsigned int vertex_buffer, index_buffer;
    unsigned int stream_buffer;      /* merged draws' indices: both regions, once a flush */
    int merge;                       /* 32-bit indices offered (GL_OES_element_index_uint) */
    sw_gl_queue queues[2];           /* SW_GL_POOL_MESHES, SW_GL_POOL_FANS */
    uint32_t vertices, indices;      /* capacities */
    uint32_t batch_triangles;        /* waits for the driver past these; 0 never */
    uint32_t unfinished_triangles;   /* drawn since the last wait */
    uint64_t bytes_uploaded;         /* since init */
    uint64_t draw_calls, triangles;  /* since init */
    uint64_t waits;                  /* glFinish calls in sw_gl_pool_draw, since init */
    unsigned int resident_vertices, resident_indices;   /* sw_gl_pool_resident; 0: none */
    uint32_t resident_vertex_count, resident_index_count;
} sw_gl_pool;

/* Creates both buffers (GL_DYNAMIC_DRAW) and writes them once, so the
 * driver's pages for them are taken now rather than as meshes first reach
 * them. batch_triangles: see SW_GL_POOL_BATCH_TRIANGLES (0: never wait).
 * SW_ERR_GL when the GL refuses. */
sw_status sw_gl_pool_init(sw_gl_pool *p, uint32_t vertices, uint32_t indices,
                          uint32_t batch_triangles, sw_error *err);
void sw_gl_pool_destroy(sw_gl_pool *p);

/* Writes a mesh: n vertices at first_vertex, m indices at first_index
 * (ranges within the capacities; out-of-range writes are refused, 0). */
int sw_gl_pool_upload(sw_gl_pool *p, uint32_t first_vertex, const sw_vertex *verts, uint32_t n,
                      uint32_t first_index, const uint16_t *indices, uint32_t m);

/* Draws index_count indices from first_index, their vertices counted from
 * first_vertex, with r's program (its camera and colour as set); then waits
 * for the driver (glFinish) when batch_triangles or more were drawn since
 * the last wait. */
void sw_gl_pool_draw(sw_gl_pool *p, const sw_renderer *r, uint32_t first_vertex,
                     uint32_t first_index, uint32_t index_count);

/* Meshes written once and kept for the whole walk (the pack's part
 * levels), in buffers of their own (GL_STATIC_DRAW). SW_ERR_GL when the GL
 * refuses; the pool's own buffers are left as they are. */
sw_status sw_gl_pool_resident(sw_gl_pool *p, const sw_vertex *verts, uint32_t n,
                              const uint16_t *indices, uint32_t m, sw_error *err);

/* Draws index_count of the resident indices from first_index, their
 * vertices counted from first_vertex, in rgba; at once, not merged (one
 * call a mesh: the resident meshes are whole parts). Ranges outside what
 * was written are not drawn. */
void sw_gl_pool_draw_resident(sw_gl_pool *p, sw_renderer *r, const float rgba[4],
                              uint32_t first_vertex, uint32_t first_index, uint32_t index_count);

/* Merged draws. In GLES2 a mesh's draw has to point the attributes at
 * its first vertex (16-bit indices local to the mesh, no base-vertex
 * draw), so a frame was one draw call a surface: 13,000 a frame on the
 * 40,000-patch showroom. Where the GL offers 32-bit indices the meshes are
 * queued instead, their indices copied with their first vertex added;
 * sw_gl_pool_flush then writes the queued indices to one stream buffer
 * with one call and draws each run (consecutive meshes of one colour) with
 * one call from the pool's vertex buffer at offset 0. The stream buffer is
 * made once, its size fixed: orphaning a buffer a draw made the driver
 * take (and the kernel zero) fresh memory for each. Bytes of staging the
 * caller gives sw_gl_pool_merge_start: */
size_t sw_gl_pool_merge_bytes(void);

/* Turns merging on when the GL offers GL_OES_element_index_uint: staging
 * (sw_gl_pool_merge_bytes, 8-aligned) is the caller's and must outlive
 * the pool. Returns 1 when merging is on, 0 when draws stay one a mesh. */
int sw_gl_pool_merge_start(sw_gl_pool *p, void *staging);

/* Queues index_count of a mesh's indices (local to the mesh, as the cache
 * keeps them) into queue (SW_GL_POOL_MESHES or SW_GL_POOL_FANS), to be
 * drawn in rgba (kept by pointer until the flush), flushing first when a
 * region is full. Without merging, draws them at once (sw_gl_pool_draw;
 * the fans with r's fill state). */
void sw_gl_pool_queue(sw_gl_pool *p, sw_renderer *r, int queue, const float rgba[4],
                      uint32_t first_vertex, uint32_t first_index, const uint16_t *indices,
                      uint32_t index_count);

/* Draws what is queued: the meshes' runs, then the fans' (lit as their
 * surfaces, sw_renderer_set_fill), each run in its colour; waits for the
 * driver past batch_triangles as sw_gl_pool_draw does. The frame's end
 * calls it. */
void sw_gl_pool_flush(sw_gl_pool *p, sw_renderer *r);

/* The frame's end: waits for the driver (glFinish) and starts the next
 * batch from zero. */
void sw_gl_pool_finish(sw_gl_pool *p);

#endif
