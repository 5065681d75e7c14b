/* SPDX-License-Identifier: MIT */
/* The window half of kmscube's init_egl: platform display, config matched to
 * the native visual, window surface, context. */
#define _GNU_SOURCE /* dl_iterate_phdr, RTLD_NODELETE */
#include "sw_egl_window.h"

#include <dlfcn.h>
#include <link.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <string.h>

int sw_egl_has_extension(const char *list, const char *name)
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

/* As sw_egl_headless.c does, and for the same reason: Mesa unloads its DRI
 * driver in eglTerminate, and blocks its globals still point to then look
 * leaked to LeakSanitizer from an unnamed module. Kept mapped until exit. */
static int pin_dri_driver(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    (void)data;
    if (info->dlpi_name && strstr(info->dlpi_name, "/dri/"))
        dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
}

static sw_status egl_fail(sw_egl_window *w, sw_error *err, const char *step)
{
    EGLint code = eglGetError();
    const char *who = w->who;
    sw_egl_window_destroy(w);
    return sw_error_set(err, SW_ERR_GL, "%s: %s failed (EGL error 0x%04x)", who, step,
                        (unsigned)code);
}

/* A config of the wanted native visual: EGL sorts by its own rules, so the
 * list is searched (kmscube's match_config_to_visual). Depth 24 is asked
 * first (the walk's near/far range), 16 where the driver has no 24. */
static int choose_config(sw_egl_window *w, EGLint depth, int want_visual)
{
    const EGLint attribs[] = {
        EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, depth,
        EGL_NONE,
    };
    EGLConfig configs[64];
    EGLint count = 0;
    if (!eglChooseConfig(w->display, attribs, configs, 64, &count))
        return 0;
    for (EGLint i = 0; i < count; i++) {
        EGLint id = 0;
        eglGetConfigAttrib(w->display, configs[i], EGL_NATIVE_VISUAL_ID, &id);
        if (want_visual == 0 || id == want_visual) {
            w->config = configs[i];
            w->visual_id = id;
            return 1;
        }
    }
    return 0;
}

sw_status sw_egl_window_open(sw_egl_window *w, const char *who, unsigned platform,
                             const char *khr_ext, const char *ext_ext, void *native_display,
                             int want_visual, sw_error *err)
{
    memset(w, 0, sizeof *w);
    w->who = who;
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client || !sw_egl_has_extension(client, "EGL_EXT_platform_base") ||
        (!sw_egl_has_extension(client, khr_ext) && !sw_egl_has_extension(client, ext_ext)))
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "%s: EGL offers neither %s nor %s (its "
                            "client extensions: %s)", who, khr_ext, ext_ext,
                            client ? client : "none");
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_display)
        return egl_fail(w, err, "eglGetProcAddress(eglGetPlatformDisplayEXT)");
    EGLDisplay dpy = get_display((EGLenum)platform, native_display, NULL);
    if (dpy == EGL_NO_DISPLAY)
        return egl_fail(w, err, "eglGetPlatformDisplayEXT");
    EGLint major, minor;
    if (!eglInitialize(dpy, &major, &minor))
        return egl_fail(w, err, "eglInitialize");
    w->display = dpy;
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return egl_fail(w, err, "eglBindAPI(EGL_OPENGL_ES_API)");
    if (!choose_config(w, 24, want_visual) && !choose_config(w, 16, want_visual)) {
        sw_egl_window_destroy(w);
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "%s: no GLES2 window config with RGB8 "
                            "and depth%s", who, want_visual ? " of the scan-out format" : "");
    }
    return SW_OK;
}

sw_status sw_egl_window_attach(sw_egl_window *w, void *native_window, sw_error *err)
{
    PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC create_surface =
        (PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC)eglGetProcAddress(
            "eglCreatePlatformWindowSurfaceEXT");
    if (!create_surface)
        return egl_fail(w, err, "eglGetProcAddress(eglCreatePlatformWindowSurfaceEXT)");
    EGLSurface s = create_surface(w->display, w->config, native_window, NULL);
    if (s == EGL_NO_SURFACE)
        return egl_fail(w, err, "eglCreatePlatformWindowSurfaceEXT");
    w->surface = s;
    const EGLint ctx_attribs[] = { EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE };
    EGLContext ctx = eglCreateContext(w->display, w->config, EGL_NO_CONTEXT, ctx_attribs);
    if (ctx == EGL_NO_CONTEXT)
        return egl_fail(w, err, "eglCreateContext");
    w->context = ctx;
    if (!eglMakeCurrent(w->display, s, s, ctx))
        return egl_fail(w, err, "eglMakeCurrent");
    dl_iterate_phdr(pin_dri_driver, NULL);
    return SW_OK;
}

sw_status sw_egl_window_swap(sw_egl_window *w, sw_error *err)
{
    if (eglSwapBuffers(w->display, w->surface))
        return SW_OK;
    return sw_error_set(err, SW_ERR_GL, "%s: eglSwapBuffers failed (EGL error 0x%04x)", w->who,
                        (unsigned)eglGetError());
}

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

sw_status sw_egl_window_read_rgba(const sw_egl_window *w, int width, int height, uint8_t *rgba,
                                  sw_error *err)
{
    /* GL_RGBA + GL_UNSIGNED_BYTE is the one format GLES2 always reads, from
     * the back buffer of a window surface as from an FBO. */
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    GLenum code = glGetError();
    if (code != GL_NO_ERROR)
        return sw_error_set(err, SW_ERR_GL, "%s: glReadPixels %dx%d failed (0x%04x)", w->who,
                            width, height, (unsigned)code);
    size_t row = (size_t)width * 4;
    for (int y = 0; y < height / 2; y++)
        swap_rows(rgba + (size_t)y * row, rgba + (size_t)(height - 1 - y) * row, row);
    /* A window's alpha may be undefined (XRGB scan-out): the PNG wants it opaque. */
    for (size_t i = 3; i < row * (size_t)height; i += 4)
        rgba[i] = 255;
    return SW_OK;
}

void sw_egl_window_destroy(sw_egl_window *w)
{
    if (w->display) {
        eglMakeCurrent(w->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (w->context)
            eglDestroyContext(w->display, w->context);
        if (w->surface)
            eglDestroySurface(w->display, w->surface);
        eglTerminate(w->display);
        eglReleaseThread();
    }
    const char *who = w->who;
    memset(w, 0, sizeof *w);
    w->who = who;
}
