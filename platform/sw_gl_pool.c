/* SPDX-License-Identifier: MIT */
#include "sw_gl_pool.h"

#include <GLES2/gl2.h>
#include <stddef.h>
#include <string.h>

/* Zeros written over a buffer's whole store, a block at a time. */
static void write_zeros(GLenum target, size_t bytes)
{
    static const unsigned char zeros[1 << 16];
    for (size_t at = 0; at < bytes; at += sizeof zeros) {
        size_t n = bytes - at < sizeof zeros ? bytes - at : sizeof zeros;
        glBufferSubData(target, (GLintptr)at, (GLsizeiptr)n, zeros);
    }
}

sw_status sw_gl_pool_init(sw_gl_pool *p, uint32_t vertices, uint32_t indices,
                          uint32_t batch_triangles, sw_error *err)
{
    *p = (sw_gl_pool){ .batch_triangles = batch_triangles };
    if (vertices == 0 || indices == 0)
        return sw_error_set(err, SW_ERR_ARG, "GL pool: %u vertices, %u indices, expected > 0",
                            (unsigned)vertices, (unsigned)indices);
    glGenBuffers(1, &p->vertex_buffer);
    glGenBuffers(1, &p->index_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, p->vertex_buffer);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)vertices * (GLsizeiptr)sizeof(sw_vertex), NULL,
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->index_buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)indices * 2, NULL, GL_DYNAMIC_DRAW);
    GLenum code = glGetError();
    /* Written once now: a driver that keeps the store in host memory
     * (llvmpipe) takes its pages as they are first written, which would
     * otherwise be whenever the cache first reaches them, loops into a soak. */
    if (code == GL_NO_ERROR) {
        write_zeros(GL_ARRAY_BUFFER, (size_t)vertices * sizeof(sw_vertex));
        write_zeros(GL_ELEMENT_ARRAY_BUFFER, (size_t)indices * 2);
        code = glGetError();
    }
    if (code != GL_NO_ERROR) {
        sw_gl_pool_destroy(p);
        return sw_error_set(err, SW_ERR_GL, "GL pool: buffers for %u vertices and %u indices "
                            "refused (0x%04x)", (unsigned)vertices, (unsigned)indices,
                            (unsigned)code);
    }
    p->vertices = vertices;
    p->indices = indices;
    return SW_OK;
}

void sw_gl_pool_destroy(sw_gl_pool *p)
{
    if (p->resident_vertices)
        glDeleteBuffers(1, &p->resident_vertices);
    if (p->resident_indices)
        glDeleteBuffers(1, &p->resident_indices);
    p->resident_vertices = p->resident_indices = 0;
    if (p->stream_buffer)
        glDeleteBuffers(1, &p->stream_buffer);
    p->stream_buffer = 0;
    p->merge = 0;
    glDeleteBuffers(1, &p->vertex_buffer);
    glDeleteBuffers(1, &p->index_buffer);
    p->vertex_buffer = p->index_buffer = 0;
}

/* A draw call of triangles counted; past batch_triangles since the last
 * wait, the driver is waited for (SW_GL_POOL_BATCH_TRIANGLES says why). */
static void drawn(sw_gl_pool *p, uint32_t triangles)
{
    p->draw_calls++;
    p->triangles += triangles;
    p->unfinished_triangles += triangles;
    if (p->batch_triangles && p->unfinished_triangles >= p->batch_triangles) {
        glFinish();
        p->unfinished_triangles = 0;
        p->waits++;
    }
}

int sw_gl_pool_upload(sw_gl_pool *p, uint32_t first_vertex, const sw_vertex *verts, uint32_t n,
                      uint32_t first_index, const uint16_t *indices, uint32_t m)
{
    if ((uint64_t)first_vertex + n > p->vertices || (uint64_t)first_index + m > p->indices)
        return 0;
    glBindBuffer(GL_ARRAY_BUFFER, p->vertex_buffer);
    glBufferSubData(GL_ARRAY_BUFFER, (GLintptr)first_vertex * (GLintptr)sizeof(sw_vertex),
                    (GLsizeiptr)n * (GLsizeiptr)sizeof(sw_vertex), verts);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->index_buffer);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)first_index * 2, (GLsizeiptr)m * 2,
                    indices);
    p->bytes_uploaded += (uint64_t)n * sizeof(sw_vertex) + (uint64_t)m * 2;
    return 1;
}

void sw_gl_pool_draw(sw_gl_pool *p, const sw_renderer *r, uint32_t first_vertex,
                     uint32_t first_index, uint32_t index_count)
{
    if (index_count < 3)
        return;
    glBindBuffer(GL_ARRAY_BUFFER, p->vertex_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->index_buffer);
    /* No base vertex in GLES2: the layout points at the mesh. */
    sw_renderer_set_layout(r, (size_t)first_vertex * sizeof(sw_vertex));
    glDrawElements(GL_TRIANGLES, (GLsizei)(index_count - index_count % 3), GL_UNSIGNED_SHORT,
                   (const void *)((size_t)first_index * 2));
    drawn(p, index_count / 3);
}

sw_status sw_gl_pool_resident(sw_gl_pool *p, const sw_vertex *verts, uint32_t n,
                              const uint16_t *indices, uint32_t m, sw_error *err)
{
    glGenBuffers(1, &p->resident_vertices);
    glGenBuffers(1, &p->resident_indices);
    glBindBuffer(GL_ARRAY_BUFFER, p->resident_vertices);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)n * (GLsizeiptr)sizeof(sw_vertex), verts,
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->resident_indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)m * 2, indices, GL_STATIC_DRAW);
    GLenum code = glGetError();
    if (code != GL_NO_ERROR) {
        glDeleteBuffers(1, &p->resident_vertices);
        glDeleteBuffers(1, &p->resident_indices);
        p->resident_vertices = p->resident_indices = 0;
        return sw_error_set(err, SW_ERR_GL, "GL pool: resident buffers for %u vertices and %u "
                            "indices refused (0x%04x)", (unsigned)n, (unsigned)m,
                            (unsigned)code);
    }
    p->resident_vertex_count = n, p->resident_index_count = m;
    p->bytes_uploaded += (uint64_t)n * sizeof(sw_vertex) + (uint64_t)m * 2;
    return SW_OK;
}

void sw_gl_pool_draw_resident(sw_gl_pool *p, sw_renderer *r, const float rgba[4],
                              uint32_t first_vertex, uint32_t first_index, uint32_t index_count)
{
    index_count -= index_count % 3;
    if (!p->resident_vertices || index_count == 0 || first_vertex >= p->resident_vertex_count ||
        (uint64_t)first_index + index_count > p->resident_index_count)
        return;
    glBindBuffer(GL_ARRAY_BUFFER, p->resident_vertices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->resident_indices);
    sw_renderer_set_layout(r, (size_t)first_vertex * sizeof(sw_vertex));
    sw_renderer_set_color(r, rgba);
    glDrawElements(GL_TRIANGLES, (GLsizei)index_count, GL_UNSIGNED_SHORT,
                   (const void *)((size_t)first_index * 2));
    drawn(p, index_count / 3);
}

size_t sw_gl_pool_merge_bytes(void)
{
    return 2u * ((size_t)SW_GL_POOL_MERGE_INDICES * sizeof(uint32_t) +
                 (size_t)SW_GL_POOL_MERGE_RUNS * sizeof(sw_gl_run));
}

int sw_gl_pool_merge_start(sw_gl_pool *p, void *staging)
{
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    if (!staging || !ext || !strstr(ext, "GL_OES_element_index_uint"))
        return 0;
    glGenBuffers(1, &p->stream_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->stream_buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(2u * SW_GL_POOL_MERGE_INDICES * 4), NULL,
                 GL_STREAM_DRAW);
    write_zeros(GL_ELEMENT_ARRAY_BUFFER, 2u * SW_GL_POOL_MERGE_INDICES * 4);  /* as the pool */
    if (glGetError() != GL_NO_ERROR) {
        glDeleteBuffers(1, &p->stream_buffer);
        p->stream_buffer = 0;
        return 0;
    }
    sw_gl_run *runs = staging;
    uint32_t *indices = (uint32_t *)(runs + 2u * SW_GL_POOL_MERGE_RUNS);
    for (int q = 0; q < 2; q++)
        p->queues[q] = (sw_gl_queue){ indices + (size_t)q * SW_GL_POOL_MERGE_INDICES,
                                      runs + (size_t)q * SW_GL_POOL_MERGE_RUNS, 0, 0 };
    p->merge = 1;
    return 1;
}

/* A region's runs, one draw call each, from where its indices lie in the
 * stream buffer. */
static void draw_runs(sw_gl_pool *p, sw_renderer *r, sw_gl_queue *q, size_t at)
{
    for (uint32_t k = 0; k < q->run_count; k++) {
        const sw_gl_run *run = &q->runs[k];
        sw_renderer_set_color(r, run->rgba);
        glDrawElements(GL_TRIANGLES, (GLsizei)run->count, GL_UNSIGNED_INT,
                       (const void *)(at + (size_t)run->first * 4));
        drawn(p, run->count / 3);
    }
    q->count = q->run_count = 0;
}

void sw_gl_pool_flush(sw_gl_pool *p, sw_renderer *r)
{
    sw_gl_queue *meshes = &p->queues[SW_GL_POOL_MESHES], *fans = &p->queues[SW_GL_POOL_FANS];
    if (!p->merge || (meshes->run_count == 0 && fans->run_count == 0))
        return;
    /* Both regions in one buffer (the fans' after the meshes'), written
     * before any draw reads it: no draw of this flush is in flight. */
    size_t fans_at = (size_t)meshes->count * 4;
    glBindBuffer(GL_ARRAY_BUFFER, p->vertex_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p->stream_buffer);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, (GLsizeiptr)fans_at, meshes->indices);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)fans_at, (GLsizeiptr)fans->count * 4,
                    fans->indices);
    sw_renderer_set_layout(r, 0);
    draw_runs(p, r, meshes, 0);
    if (fans->run_count) {
        sw_renderer_set_fill(r, 1);
        draw_runs(p, r, fans, fans_at);
        sw_renderer_set_fill(r, 0);
    }
}

void sw_gl_pool_queue(sw_gl_pool *p, sw_renderer *r, int queue, const float rgba[4],
                      uint32_t first_vertex, uint32_t first_index, const uint16_t *indices,
                      uint32_t index_count)
{
    index_count -= index_count % 3;
    if (index_count == 0)
        return;
    if (!p->merge || index_count > SW_GL_POOL_MERGE_INDICES) {  /* one draw, at once */
        sw_gl_pool_flush(p, r);
        sw_renderer_set_color(r, rgba);
        if (queue == SW_GL_POOL_FANS)
            sw_renderer_set_fill(r, 1);
        sw_gl_pool_draw(p, r, first_vertex, first_index, index_count);
        if (queue == SW_GL_POOL_FANS)
            sw_renderer_set_fill(r, 0);
        return;
    }
    sw_gl_queue *q = &p->queues[queue];
    /* One run while the colour stays the same, whichever part it is
     * (the showroom gives each of its 625 parts a colour of its own: its
     * first frame's 2,676 meshes made 302 runs, one a visible part). */
    const float *last = q->run_count ? q->runs[q->run_count - 1].rgba : NULL;
    int same = last && (last == rgba || !memcmp(last, rgba, 4 * sizeof *rgba));
    if (q->count + index_count > SW_GL_POOL_MERGE_INDICES ||
        (!same && q->run_count == SW_GL_POOL_MERGE_RUNS)) {
        sw_gl_pool_flush(p, r);
        same = 0;
    }
    if (!same)
        q->runs[q->run_count++] = (sw_gl_run){ rgba, q->count, 0 };
    uint32_t *out = q->indices + q->count;
    for (uint32_t i = 0; i < index_count; i++)
        out[i] = first_vertex + indices[i];
    q->count += index_count;
    q->runs[q->run_count - 1].count += index_count;
}

void sw_gl_pool_finish(sw_gl_pool *p)
{
    glFinish();
    p->unfinished_triangles = 0;
}
