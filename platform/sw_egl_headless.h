/* SPDX-License-Identifier: MIT */
/* A headless EGL display: Mesa's surfaceless platform (EGL_MESA_platform_surfaceless),
 * no window and no /dev/dri needed, with llvmpipe in CI. For GLES2 it renders
 * into an offscreen framebuffer object (RGBA8 texture + a depth renderbuffer
 * of 24 bits with GL_OES_depth24, else core GLES2's 16) of the requested size. The desktop
 * GL variant exists only for the benchmark's GLU reference. One state struct,
 * owned by the caller; only the thread that called init may use it. */
#ifndef SW_EGL_HEADLESS_H
#define SW_EGL_HEADLESS_H

#include <stdint.h>

#include "sw_error.h"

typedef enum sw_gl_api { SW_GL_API_GLES2 = 0, SW_GL_API_DESKTOP = 1 } sw_gl_api;

typedef struct sw_egl_headless {
    void *display;     /* EGLDisplay */
    void *context;     /* EGLContext */
    void *config;      /* EGLConfig */
    sw_gl_api api;
    int width, height;
    unsigned int fbo, color_texture, depth_renderbuffer;  /* GLES2 only */
    char renderer[128];                                   /* GL_RENDERER string */
    int depth_bits;                                       /* the framebuffer's, GLES2 only */
} sw_egl_headless;

/* Creates the display, context (made current) and, for GLES2, the framebuffer.
 * On failure returns non-OK, cleans up, and err says which step failed. */
sw_status sw_egl_headless_init(sw_egl_headless *egl, sw_gl_api api, int width, int height,
                               sw_error *err);
/* The same with at most max_depth_bits of depth (16 or 24; init asks for
 * 24): 24 where GL_OES_depth24 is offered, else 16; egl->depth_bits says
 * which the framebuffer got. */
sw_status sw_egl_headless_init_depth(sw_egl_headless *egl, sw_gl_api api, int width, int height,
                                     int max_depth_bits, sw_error *err);
void sw_egl_headless_destroy(sw_egl_headless *egl);

/* Reads the framebuffer into rgba (width * height * 4 bytes), top row first
 * (GL's bottom-up rows are flipped). Waits for rendering to finish.
 * SW_ERR_UNSUPPORTED for the desktop variant, which has no framebuffer. */
sw_status sw_egl_headless_read_rgba(const sw_egl_headless *egl, uint8_t *rgba, sw_error *err);

#endif
