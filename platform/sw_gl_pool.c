#include "sw_gl_pool.h"

#include <GLES2/gl2.h>
#include <stddef.h>

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
    /* Not written over here: llvmpipe zeroes a buffer's store when it is
     * made, so its pages are resident from now on (the 40,000-patch
     * showroom's resident memory at the walk's start was 398.9 MB with
     * zeros written over the 112 MB and without; writing them cost the
     * start a copy of it). A driver that takes its pages lazily would
     * show it in the soak's check (tests/soak.sh). */
    GLenum code = glGetError();
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
    glDeleteBuffers(1, &p->vertex_buffer);
    glDeleteBuffers(1, &p->index_buffer);
    p->vertex_buffer = p->index_buffer = 0;
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
    size_t base = (size_t)first_vertex * sizeof(sw_vertex);
    /* No VAOs and no base vertex in GLES2: the layout points at the mesh. */
    glVertexAttribPointer((GLuint)r->a_position, 3, GL_FLOAT, GL_FALSE, sizeof(sw_vertex),
                          (const void *)(base + offsetof(sw_vertex, pos)));
    glVertexAttribPointer((GLuint)r->a_normal, 3, GL_BYTE, GL_TRUE, sizeof(sw_vertex),
                          (const void *)(base + offsetof(sw_vertex, normal)));
    glEnableVertexAttribArray((GLuint)r->a_position);
    glEnableVertexAttribArray((GLuint)r->a_normal);
    glDrawElements(GL_TRIANGLES, (GLsizei)(index_count - index_count % 3), GL_UNSIGNED_SHORT,
                   (const void *)((size_t)first_index * 2));
    p->draw_calls++;
    p->triangles += index_count / 3;
    p->unfinished_triangles += index_count / 3;
    if (p->batch_triangles && p->unfinished_triangles >= p->batch_triangles) {
        glFinish();
        p->unfinished_triangles = 0;
        p->waits++;
    }
}

void sw_gl_pool_finish(sw_gl_pool *p)
{
    glFinish();
    p->unfinished_triangles = 0;
}
