/* SPDX-License-Identifier: MIT */
/* The GLES2 renderer. Lighting is computed per fragment in eye space with two
 * directional lights fixed to the camera: a headlight (from the eye, so what
 * the walker looks at is never dark) and a key light above and to the right
 * (so shapes read as 3D, not flat). Blinn-Phong, no gamma. */
#include "sw_renderer.h"

#include <GLES2/gl2.h>
#include <assert.h>
#include <stddef.h>
#include <string.h>

/* Attribute slots are bound by name before linking (kmscube does the same), so
 * the vertex layout does not depend on the linker's choice. */
enum { ATTRIB_POSITION = 0, ATTRIB_NORMAL = 1 };

static const char *const vertex_source =
    "uniform mat4 u_model_view;\n"
    "uniform mat4 u_projection;\n"
    "attribute vec3 a_position;\n"
    "attribute vec3 a_normal;\n"
    "varying vec3 v_normal;\n"
    "varying vec3 v_eye_pos;\n"
    "void main() {\n"
    "    vec4 eye = u_model_view * vec4(a_position, 1.0);\n"
    "    v_eye_pos = eye.xyz;\n"
    /* The upper 3x3 of the model-view is a valid normal matrix because our
     * model-views are rotations, translations and uniform scales only (camera
     * and part placement); with no non-uniform scale the inverse transpose
     * differs only by a scalar, which the fragment shader normalises away.
     * Built from columns because GLSL ES 1.00 has no mat3(mat4). */
    "    v_normal = mat3(u_model_view[0].xyz, u_model_view[1].xyz, u_model_view[2].xyz)\n"
    "             * a_normal;\n"
    "    gl_Position = u_projection * eye;\n"
    "}\n";

static const char *const fragment_source =
    "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
    "precision highp float;\n"
    "#else\n"
    "precision mediump float;\n"
    "#endif\n"
    "uniform vec4 u_color;\n"
    "uniform vec4 u_back;\n"
    "uniform float u_fill;\n"
    "uniform float u_hide_back;\n"
    "varying vec3 v_normal;\n"
    "varying vec3 v_eye_pos;\n"
    "const vec3 key_dir = vec3(0.408248, 0.816497, 0.408248);\n" /* normalize(1, 2, 1) */
    "const float ambient = 0.1;\n"
    "const float head_diffuse = 0.6;\n"
    "const float key_diffuse = 0.3;\n"
    "const float specular = 0.2;\n"
    "const float shininess = 32.0;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    vec3 view_dir = normalize(-v_eye_pos);\n"
    /* Fill fans (u_fill) have no facing of their own: a sliver between two
     * sides of a seam winds either way once snapped, so it takes the side
     * its normals face, as the surface around it does. */
    "    if (u_fill > 0.5) {\n"
    /* With back faces hidden, a fan's back (by its normals, as its surface
     * faces there) is hidden too. */
    "        if (dot(n, view_dir) < 0.0) {\n"
    "            if (u_hide_back > 0.5) discard;\n"
    "            n = -n;\n"
    "        }\n"
    "    } else if (!gl_FrontFacing) {\n"
    "        if (u_back.a > 0.5) { gl_FragColor = vec4(u_back.rgb, 1.0); return; }\n"
    /* Two-sided: patch soups mix orientations, so light the side we see. */
    "        n = -n;\n"
    "    }\n"
    /* Headlight: light direction equals view direction, so its half vector too. */
    "    float head = max(dot(n, view_dir), 0.0);\n"
    "    float key = max(dot(n, key_dir), 0.0);\n"
    "    vec3 key_half = normalize(key_dir + view_dir);\n"
    "    float spec = specular * (pow(head, shininess) + pow(max(dot(n, key_half), 0.0), shininess));\n"
    "    vec3 lit = u_color.rgb * (ambient + head_diffuse * head + key_diffuse * key) + vec3(spec);\n"
    "    gl_FragColor = vec4(min(lit, vec3(1.0)), u_color.a);\n"
    "}\n";

static sw_status compile_shader(GLenum type, const char *source, GLuint *out, sw_error *err)
{
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[400] = "";
        glGetShaderInfoLog(shader, (GLsizei)sizeof log, NULL, log);
        glDeleteShader(shader);
        return sw_error_set(err, SW_ERR_GL, "renderer: %s shader does not compile: %s",
                            type == GL_VERTEX_SHADER ? "vertex" : "fragment", log);
    }
    *out = shader;
    return SW_OK;
}

static sw_status link_program(sw_renderer *r, sw_error *err)
{
    GLuint vs = 0, fs = 0;
    sw_status st = compile_shader(GL_VERTEX_SHADER, vertex_source, &vs, err);
    if (st == SW_OK)
        st = compile_shader(GL_FRAGMENT_SHADER, fragment_source, &fs, err);
    if (st != SW_OK) {
        glDeleteShader(vs);
        return st;
    }
    GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glBindAttribLocation(prog, ATTRIB_POSITION, "a_position");
    glBindAttribLocation(prog, ATTRIB_NORMAL, "a_normal");
    glLinkProgram(prog);
    /* Flagged for deletion; they go when the program does. */
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[400] = "";
        glGetProgramInfoLog(prog, (GLsizei)sizeof log, NULL, log);
        glDeleteProgram(prog);
        return sw_error_set(err, SW_ERR_GL, "renderer: program does not link: %s", log);
    }
    r->program = prog;
    r->a_position = ATTRIB_POSITION;
    r->a_normal = ATTRIB_NORMAL;
    r->u_model_view = glGetUniformLocation(prog, "u_model_view");
    r->u_projection = glGetUniformLocation(prog, "u_projection");
    r->u_color = glGetUniformLocation(prog, "u_color");
    r->u_back = glGetUniformLocation(prog, "u_back");
    r->u_fill = glGetUniformLocation(prog, "u_fill");
    r->u_hide_back = glGetUniformLocation(prog, "u_hide_back");
    return SW_OK;
}

sw_status sw_renderer_init(sw_renderer *r, uint32_t max_vertices, uint32_t max_indices,
                           sw_error *err)
{
    *r = (sw_renderer){ .u_model_view = -1, .u_projection = -1, .u_color = -1, .u_back = -1,
                        .u_fill = -1, .u_hide_back = -1 };
    if (max_vertices < 1 || max_vertices > 65536 || max_indices < 3)
        return sw_error_set(err, SW_ERR_ARG,
                            "renderer: max_vertices %u must be 1..65536 (16-bit indices) and "
                            "max_indices %u at least 3",
                            max_vertices, max_indices);
    sw_status st = link_program(r, err);
    if (st != SW_OK)
        return st;
    r->max_vertices = max_vertices;
    r->max_indices = max_indices;
    glGenBuffers(1, &r->vertex_buffer);
    glGenBuffers(1, &r->index_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, r->vertex_buffer);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)max_vertices * (GLsizeiptr)sizeof(sw_vertex), NULL,
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->index_buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)max_indices * 2, NULL, GL_STREAM_DRAW);
    GLenum code = glGetError();
    if (code != GL_NO_ERROR) {
        sw_renderer_destroy(r);
        return sw_error_set(err, SW_ERR_GL,
                            "renderer: creating buffers for %u vertices, %u indices failed "
                            "(0x%04x)",
                            max_vertices, max_indices, (unsigned)code);
    }
    return SW_OK;
}

void sw_renderer_destroy(sw_renderer *r)
{
    glDeleteBuffers(1, &r->vertex_buffer);
    glDeleteBuffers(1, &r->index_buffer);
    glDeleteProgram(r->program);
    r->vertex_buffer = r->index_buffer = r->program = 0;
}

void sw_renderer_begin_frame(sw_renderer *r, int width, int height, const float clear_rgba[4],
                             const float model_view[16], const float projection[16])
{
    glViewport(0, 0, width, height);
    glClearColor(clear_rgba[0], clear_rgba[1], clear_rgba[2], clear_rgba[3]);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    /* Patch soups have no consistent orientation; the shader is two-sided
     * unless back faces were asked hidden. */
    if (r->back_hidden) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glUseProgram(r->program);
    glUniformMatrix4fv(r->u_model_view, 1, GL_FALSE, model_view);
    glUniformMatrix4fv(r->u_projection, 1, GL_FALSE, projection);
    memcpy(r->view, model_view, sizeof r->view);
}

void sw_renderer_set_model(sw_renderer *r, const float model[16])
{
    float mv[16];
    for (int c = 0; model && c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double x = 0;
            for (int k = 0; k < 4; k++)
                x += (double)r->view[4 * k + row] * model[4 * c + k];
            mv[4 * c + row] = (float)x;
        }
    glUseProgram(r->program);
    glUniformMatrix4fv(r->u_model_view, 1, GL_FALSE, model ? mv : r->view);
}

void sw_renderer_set_back_color(sw_renderer *r, const float rgb[3])
{
    const float off[4] = { 0, 0, 0, 0 };
    const float on[4] = { rgb ? rgb[0] : 0, rgb ? rgb[1] : 0, rgb ? rgb[2] : 0, 1 };
    glUseProgram(r->program);
    glUniform4fv(r->u_back, 1, rgb ? on : off);
}

void sw_renderer_set_back_hidden(sw_renderer *r, int hidden)
{
    r->back_hidden = hidden;
    glUseProgram(r->program);
    glUniform1f(r->u_hide_back, hidden ? 1.0f : 0.0f);
}

void sw_renderer_set_fill(sw_renderer *r, int fill)
{
    /* A fan winds either way; culled by its winding it would reopen the
     * pinhole it closes. */
    if (r->back_hidden && fill)
        glDisable(GL_CULL_FACE);
    else if (r->back_hidden)
        glEnable(GL_CULL_FACE);
    glUseProgram(r->program);
    glUniform1f(r->u_fill, fill ? 1.0f : 0.0f);
}

void sw_renderer_set_color(sw_renderer *r, const float rgba[4])
{
    glUseProgram(r->program);
    glUniform4fv(r->u_color, 1, rgba);
}

void sw_renderer_draw(sw_renderer *r, const sw_vertex *verts, uint32_t vertex_count,
                      const uint16_t *indices, uint32_t index_count)
{
    assert(vertex_count <= r->max_vertices && index_count <= r->max_indices);
    if (vertex_count == 0 || index_count < 3)
        return;
    /* Orphaning: a fresh store of the same size lets the driver keep the old
     * one for draws still in flight instead of stalling on them. */
    glBindBuffer(GL_ARRAY_BUFFER, r->vertex_buffer);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)r->max_vertices * (GLsizeiptr)sizeof(sw_vertex),
                 NULL, GL_STREAM_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)vertex_count * (GLsizeiptr)sizeof(sw_vertex),
                    verts);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->index_buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)r->max_indices * 2, NULL, GL_STREAM_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, (GLsizeiptr)index_count * 2, indices);

    sw_renderer_set_layout(r, 0);
    glDrawElements(GL_TRIANGLES, (GLsizei)(index_count - index_count % 3), GL_UNSIGNED_SHORT, 0);
    r->draw_calls++;
    r->triangles += index_count / 3;
}

void sw_renderer_set_layout(const sw_renderer *r, size_t base)
{
    glVertexAttribPointer((GLuint)r->a_position, 3, GL_FLOAT, GL_FALSE, sizeof(sw_vertex),
                          (const void *)(base + offsetof(sw_vertex, pos)));
    glVertexAttribPointer((GLuint)r->a_normal, 3, GL_BYTE, GL_TRUE, sizeof(sw_vertex),
                          (const void *)(base + offsetof(sw_vertex, normal)));
    glEnableVertexAttribArray((GLuint)r->a_position);
    glEnableVertexAttribArray((GLuint)r->a_normal);
}

void sw_renderer_warm_up(sw_renderer *r, int width, int height)
{
    static const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    static const float clear[4] = { 0, 0, 0, 1 }, grey[4] = { 0.5f, 0.5f, 0.5f, 1 };
    /* Counter-clockwise, facing the eye: drawn with back faces hidden too. */
    const sw_vertex tri[3] = {
        { { -0.5f, -0.5f, 0.0f }, { 0, 0, 127, 0 } },
        { { 0.5f, -0.5f, 0.0f }, { 0, 0, 127, 0 } },
        { { 0.0f, 0.5f, 0.0f }, { 0, 0, 127, 0 } },
    };
    static const uint16_t idx[3] = { 0, 1, 2 };
    uint64_t calls = r->draw_calls, tris = r->triangles;
    sw_renderer_begin_frame(r, width, height, clear, identity, identity);
    sw_renderer_set_color(r, grey);
    sw_renderer_draw(r, tri, 3, idx, 3);
    glFinish();
    r->draw_calls = calls;   /* not the walk's */
    r->triangles = tris;
}

void sw_renderer_finish(sw_renderer *r)
{
    (void)r;
    glFinish();
}
