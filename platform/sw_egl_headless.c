/* SPDX-License-Identifier: MIT */
/* Headless EGL through Mesa's surfaceless platform. The steps follow kmscube's
 * egl setup, minus the window: platform display, config, context made current
 * without a surface (EGL_KHR_surfaceless_context), then an FBO to draw into.
 * The depth buffer is the FBO's renderbuffer, not the EGL config's (there is
 * no surface), so its bits come from GL_OES_depth24, not EGL_DEPTH_SIZE. */
#define _GNU_SOURCE /* dl_iterate_phdr, RTLD_NODELETE */
#include "sw_egl_headless.h"

#include <dlfcn.h>
#include <link.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <string.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

static const char *egl_error_name(EGLint code)
{
    switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
    }
}

static sw_status egl_fail(sw_egl_headless *egl, sw_error *err, const char *step)
{
    EGLint code = eglGetError();
    sw_egl_headless_destroy(egl);
    return sw_error_set(err, SW_ERR_GL, "egl headless: %s failed: %s (0x%04x)", step,
                        egl_error_name(code), (unsigned)code);
}

/* Whole-word search: "EGL_EXT_platform_base" must not match a longer name. */
static int has_extension(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n) {
        int starts = p == list || p[-1] == ' ';
        int ends = p[n] == '\0' || p[n] == ' ';
        if (starts && ends)
            return 1;
    }
    return 0;
}

static sw_status open_display(sw_egl_headless *egl, sw_error *err)
{
    /* Client extensions are queried on EGL_NO_DISPLAY; NULL means EGL 1.4
     * without EGL_EXT_client_extensions, which cannot offer platforms. */
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client || !has_extension(client, "EGL_EXT_platform_base") ||
        !has_extension(client, "EGL_MESA_platform_surfaceless"))
        return sw_error_set(err, SW_ERR_UNSUPPORTED,
                            "egl headless: client extensions lack EGL_EXT_platform_base or "
                            "EGL_MESA_platform_surfaceless (have: %s)",
                            client ? client : "none");
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display)
        return egl_fail(egl, err, "eglGetProcAddress(eglGetPlatformDisplayEXT)");
    EGLDisplay dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY)
        return egl_fail(egl, err, "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor))
        return egl_fail(egl, err, "eglInitialize");
    egl->display = dpy;
    const char *ext = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!ext || !has_extension(ext, "EGL_KHR_surfaceless_context")) {
        sw_egl_headless_destroy(egl);
        return sw_error_set(err, SW_ERR_UNSUPPORTED,
                            "egl headless: display lacks EGL_KHR_surfaceless_context");
    }
    return SW_OK;
}

static sw_status create_context(sw_egl_headless *egl, sw_error *err)
{
    int gles = egl->api == SW_GL_API_GLES2;
    /* Surface type 0: we never create a surface, and Mesa's surfaceless
     * configs carry only EGL_PBUFFER_BIT, so asking for a window would fail. */
    const EGLint config_attribs[] = {
        EGL_SURFACE_TYPE, 0,
        EGL_RENDERABLE_TYPE, gles ? EGL_OPENGL_ES2_BIT : EGL_OPENGL_BIT,
        EGL_NONE,
    };
    EGLConfig config = NULL;
    EGLint count = 0;
    if (!eglChooseConfig(egl->display, config_attribs, &config, 1, &count))
        return egl_fail(egl, err, "eglChooseConfig");
    if (count < 1) {
        sw_egl_headless_destroy(egl);
        return sw_error_set(err, SW_ERR_UNSUPPORTED,
                            "egl headless: eglChooseConfig found no %s config",
                            gles ? "EGL_OPENGL_ES2_BIT" : "EGL_OPENGL_BIT");
    }
    egl->config = config;
    if (!eglBindAPI(gles ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
        return egl_fail(egl, err, gles ? "eglBindAPI(EGL_OPENGL_ES_API)" : "eglBindAPI(EGL_OPENGL_API)");
    /* Desktop: no attributes asks for version 1.0, which EGL serves with a
     * compatibility profile of whatever version the driver has (GLU needs one). */
    const EGLint gles_attribs[] = { EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE };
    const EGLint desktop_attribs[] = { EGL_NONE };
    EGLContext ctx = eglCreateContext(egl->display, config, EGL_NO_CONTEXT,
                                      gles ? gles_attribs : desktop_attribs);
    if (ctx == EGL_NO_CONTEXT)
        return egl_fail(egl, err, "eglCreateContext");
    egl->context = ctx;
    if (!eglMakeCurrent(egl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
        return egl_fail(egl, err, "eglMakeCurrent(EGL_NO_SURFACE)");
    return SW_OK;
}

static sw_status fbo_fail(sw_egl_headless *egl, sw_error *err, const char *what, unsigned code)
{
    sw_egl_headless_destroy(egl);
    return sw_error_set(err, SW_ERR_GL, "egl headless: framebuffer %dx%d: %s (0x%04x)",
                        egl->width, egl->height, what, code);
}

#ifndef GL_DEPTH_COMPONENT24_OES
#define GL_DEPTH_COMPONENT24_OES 0x81A6
#endif

/* The depth renderbuffer: 24 bits where GL_OES_depth24 offers them and
 * max_bits allows (16 bits show z-fighting on close faces, a claw's or a
 * chamfer's), else core GLES2's 16. The bits the framebuffer really has
 * are read back, not assumed. 0 when the framebuffer is incomplete. */
static int attach_depth(sw_egl_headless *egl, int max_bits)
{
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    int offer24 = max_bits >= 24 && has_extension(ext, "GL_OES_depth24");
    for (int bits = offer24 ? 24 : 16; bits >= 16; bits -= 8) {
        glBindRenderbuffer(GL_RENDERBUFFER, egl->depth_renderbuffer);
        glRenderbufferStorage(GL_RENDERBUFFER,
                              bits == 24 ? GL_DEPTH_COMPONENT24_OES : GL_DEPTH_COMPONENT16,
                              egl->width, egl->height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  egl->depth_renderbuffer);
        if (glGetError() == GL_NO_ERROR &&
            glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
            GLint got = 0;
            glGetIntegerv(GL_DEPTH_BITS, &got);
            egl->depth_bits = got > 0 ? got : bits;
            return 1;
        }
    }
    return 0;
}

static sw_status create_framebuffer(sw_egl_headless *egl, int max_depth_bits, sw_error *err)
{
    GLint max_tex = 0, max_rb = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
    if (egl->width > max_tex || egl->height > max_tex || egl->width > max_rb ||
        egl->height > max_rb)
        return fbo_fail(egl, err, "larger than GL_MAX_TEXTURE_SIZE / GL_MAX_RENDERBUFFER_SIZE",
                        (unsigned)(max_tex < max_rb ? max_tex : max_rb));
    glGenTextures(1, &egl->color_texture);
    glBindTexture(GL_TEXTURE_2D, egl->color_texture);
    /* Non-power-of-two sizes are legal in GLES2 only with clamping and no mipmaps. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, egl->width, egl->height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
    glGenRenderbuffers(1, &egl->depth_renderbuffer);
    glGenFramebuffers(1, &egl->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, egl->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                           egl->color_texture, 0);
    if (!attach_depth(egl, max_depth_bits))
        return fbo_fail(egl, err, "glCheckFramebufferStatus is not GL_FRAMEBUFFER_COMPLETE",
                        glCheckFramebufferStatus(GL_FRAMEBUFFER));
    GLenum gl_err = glGetError();
    if (gl_err != GL_NO_ERROR)
        return fbo_fail(egl, err, "glGetError after creating the attachments", gl_err);
    glViewport(0, 0, egl->width, egl->height);
    return SW_OK;
}

static void record_renderer(sw_egl_headless *egl)
{
    /* glvnd dispatches glGetString to the current context, desktop or ES. */
    const char *name = (const char *)glGetString(GL_RENDERER);
    size_t n = name ? strlen(name) : 0;
    if (n >= sizeof egl->renderer)
        n = sizeof egl->renderer - 1;
    if (name)
        memcpy(egl->renderer, name, n);
    egl->renderer[n] = '\0';
}

/* Mesa dlcloses its DRI driver in eglTerminate. Blocks the driver still
 * points to from its own globals then look leaked to LeakSanitizer, in an
 * "<unknown module>" no suppression can name (the driver is unmapped by the
 * time of the check). Keeping the driver mapped until exit, as a program
 * that never calls eglTerminate would, keeps them reachable; leaks of ours
 * still show. It costs nothing: nothing here loads a driver twice. */
static int pin_dri_driver(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    (void)data;
    if (info->dlpi_name && strstr(info->dlpi_name, "/dri/"))
        dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
}

sw_status sw_egl_headless_init(sw_egl_headless *egl, sw_gl_api api, int width, int height,
                               sw_error *err)
{
    return sw_egl_headless_init_depth(egl, api, width, height, 24, err);
}

sw_status sw_egl_headless_init_depth(sw_egl_headless *egl, sw_gl_api api, int width, int height,
                                     int max_depth_bits, sw_error *err)
{
    memset(egl, 0, sizeof *egl);
    egl->api = api;
    egl->width = width;
    egl->height = height;
    if (api != SW_GL_API_GLES2 && api != SW_GL_API_DESKTOP)
        return sw_error_set(err, SW_ERR_ARG, "egl headless: unknown API %d", (int)api);
    if (width < 1 || height < 1)
        return sw_error_set(err, SW_ERR_ARG, "egl headless: size %dx%d must be at least 1x1",
                            width, height);
    sw_status st = open_display(egl, err);
    if (st == SW_OK)
        st = create_context(egl, err);
    if (st != SW_OK)
        return st;
    record_renderer(egl);
    dl_iterate_phdr(pin_dri_driver, NULL);
    if (api == SW_GL_API_GLES2)
        return create_framebuffer(egl, max_depth_bits, err);
    return SW_OK;
}

void sw_egl_headless_destroy(sw_egl_headless *egl)
{
    if (egl->context && egl->api == SW_GL_API_GLES2) {
        /* Names are 0 when never created; deleting 0 is ignored by GL. */
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &egl->fbo);
        glDeleteRenderbuffers(1, &egl->depth_renderbuffer);
        glDeleteTextures(1, &egl->color_texture);
    }
    if (egl->display) {
        eglMakeCurrent(egl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (egl->context)
            eglDestroyContext(egl->display, egl->context);
        eglTerminate(egl->display);
        /* Per-thread EGL state (the bound API, the last error) otherwise
         * outlives the display and shows up as a leak at exit. */
        eglReleaseThread();
    }
    egl->fbo = egl->depth_renderbuffer = egl->color_texture = 0;
    egl->context = NULL;
    egl->display = NULL;
    egl->config = NULL;
}

/* Swaps rows a and b in chunks through a small stack buffer (no allocation). */
static void swap_rows(uint8_t *a, uint8_t *b, size_t bytes)
{
    uint8_t tmp[256];
    while (bytes) {
        size_t n = bytes < sizeof tmp ? bytes : sizeof tmp;
        memcpy(tmp, a, n);
        memcpy(a, b, n);
        memcpy(b, tmp, n);
        a += n;
        b += n;
        bytes -= n;
    }
}

sw_status sw_egl_headless_read_rgba(const sw_egl_headless *egl, uint8_t *rgba, sw_error *err)
{
    if (!egl->context || egl->api != SW_GL_API_GLES2)
        return sw_error_set(err, SW_ERR_UNSUPPORTED,
                            "egl headless: read_rgba needs an initialised GLES2 display");
    /* Rows of width * 4 bytes are always 4-aligned, the GLES2 default. */
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, egl->width, egl->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    GLenum code = glGetError();
    if (code != GL_NO_ERROR)
        return sw_error_set(err, SW_ERR_GL, "egl headless: glReadPixels %dx%d failed (0x%04x)",
                            egl->width, egl->height, (unsigned)code);
    /* GL's first row is the bottom one; callers (PNG, tests) want the top first. */
    size_t row = (size_t)egl->width * 4;
    for (int y = 0; y < egl->height / 2; y++)
        swap_rows(rgba + (size_t)y * row, rgba + (size_t)(egl->height - 1 - y) * row, row);
    return SW_OK;
}
