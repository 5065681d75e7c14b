/* SPDX-License-Identifier: MIT */
/* Which display "auto" means (sw_display.h), and the names of the kinds. */
#include "sw_display.h"

#include <EGL/egl.h>
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_egl_window.h"

static const char *const kind_names[] = {"auto", "headless", "kms", "x11", "wayland"};

const char *sw_display_kind_name(sw_display_kind kind)
{
    return (unsigned)kind < sizeof kind_names / sizeof kind_names[0] ? kind_names[kind] : "?";
}

sw_status sw_display_kind_parse(const char *name, sw_display_kind *kind, sw_error *err)
{
    for (unsigned i = 0; i < sizeof kind_names / sizeof kind_names[0]; i++)
        if (name && !strcmp(name, kind_names[i])) {
            *kind = (sw_display_kind)i;
            return SW_OK;
        }
    return sw_error_set(err, SW_ERR_ARG, "--display expects auto, headless, kms, x11 or "
                        "wayland, got '%s'", name ? name : "");
}

sw_status sw_display_kind_check_built(sw_display_kind kind, sw_error *err)
{
    switch (kind) {
    case SW_DISPLAY_KIND_KMS:
        return SW_HAVE_KMS ? SW_OK
                           : sw_error_set(err, SW_ERR_ARG, "built without KMS (SW_WITH_KMS=OFF)");
    case SW_DISPLAY_KIND_X11:
        return SW_HAVE_X11 ? SW_OK
                           : sw_error_set(err, SW_ERR_ARG, "built without X11 (SW_WITH_X11=OFF)");
    case SW_DISPLAY_KIND_WAYLAND:
        return SW_HAVE_WAYLAND ? SW_OK : sw_error_set(err, SW_ERR_ARG, "built without Wayland "
                                                      "(SW_WITH_WAYLAND=OFF)");
    default:
        return SW_OK;
    }
}

static int env_set(const char *name)
{
    const char *v = getenv(name);
    return v && *v;
}

void sw_display_probe(sw_display_env *env)
{
    env->client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    env->wayland_display_set = env_set("WAYLAND_DISPLAY");
    env->x_display_set = env_set("DISPLAY");
    glob_t g;
    env->drm_card_present = glob("/dev/dri/card*", 0, NULL, &g) == 0 && g.gl_pathc > 0;
    globfree(&g);
}

static int offers(const sw_display_env *env, const char *a, const char *b)
{
    const char *c = env->client_extensions;
    return c && sw_egl_has_extension(c, "EGL_EXT_platform_base") &&
           (sw_egl_has_extension(c, a) || sw_egl_has_extension(c, b));
}

sw_display_kind sw_display_choose(const sw_display_env *env, char *why, size_t why_size)
{
    if (SW_HAVE_WAYLAND && env->wayland_display_set &&
        offers(env, "EGL_KHR_platform_wayland", "EGL_EXT_platform_wayland")) {
        snprintf(why, why_size, "auto: WAYLAND_DISPLAY is set and EGL offers Wayland");
        return SW_DISPLAY_KIND_WAYLAND;
    }
    if (SW_HAVE_X11 && env->x_display_set &&
        offers(env, "EGL_KHR_platform_x11", "EGL_EXT_platform_x11")) {
        snprintf(why, why_size, "auto: DISPLAY is set and EGL offers X11");
        return SW_DISPLAY_KIND_X11;
    }
    if (SW_HAVE_KMS && env->drm_card_present &&
        offers(env, "EGL_KHR_platform_gbm", "EGL_MESA_platform_gbm")) {
        snprintf(why, why_size, "auto: /dev/dri/card* exists and EGL offers GBM");
        return SW_DISPLAY_KIND_KMS;
    }
    snprintf(why, why_size, "auto: no window session or DRM device that EGL can use");
    return SW_DISPLAY_KIND_HEADLESS;
}
