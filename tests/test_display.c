/* SPDX-License-Identifier: MIT */
/* The display interface (platform/sw_display.h) on a machine without a DRM
 * device, X server or Wayland compositor: auto's choice over environments
 * built here, --display's words, every missing display failing with one
 * clear line, and the headless display working through the interface. */
#include <EGL/egl.h>
#include <GLES2/gl2.h>
#include <glob.h>
#include <stdlib.h>
#include <string.h>

#include "sw_display.h"
#include "sw_egl_window.h"
#include "sw_test.h"

/* What Debian 12's Mesa offers (eglinfo's client extensions, abridged). */
static const char mesa_ext[] =
    "EGL_EXT_device_base EGL_EXT_client_extensions EGL_EXT_platform_base "
    "EGL_KHR_platform_wayland EGL_EXT_platform_wayland EGL_KHR_platform_gbm "
    "EGL_MESA_platform_gbm EGL_KHR_platform_x11 EGL_EXT_platform_x11 "
    "EGL_MESA_platform_surfaceless";

static sw_display_kind choose(const char *ext, int wayland, int x, int drm)
{
    sw_display_env env = {ext, wayland, x, drm};
    char why[160];
    return sw_display_choose(&env, why, sizeof why);
}

static void auto_prefers_a_session_window_then_kms_then_headless(void)
{
    SW_CHECK(choose(mesa_ext, 1, 1, 1) == SW_DISPLAY_KIND_WAYLAND);
    SW_CHECK(choose(mesa_ext, 0, 1, 1) == SW_DISPLAY_KIND_X11);
    SW_CHECK(choose(mesa_ext, 0, 0, 1) == SW_DISPLAY_KIND_KMS);
    SW_CHECK(choose(mesa_ext, 0, 0, 0) == SW_DISPLAY_KIND_HEADLESS);
}

static void auto_takes_only_what_egl_offers(void)
{
    const char *x11_only = "EGL_EXT_platform_base EGL_EXT_platform_x11 "
                           "EGL_MESA_platform_surfaceless";
    SW_CHECK(choose(x11_only, 1, 1, 1) == SW_DISPLAY_KIND_X11);    /* no Wayland in EGL */
    SW_CHECK(choose(x11_only, 0, 0, 1) == SW_DISPLAY_KIND_HEADLESS);  /* no GBM */
    const char *gbm_mesa = "EGL_EXT_platform_base EGL_MESA_platform_gbm";
    SW_CHECK(choose(gbm_mesa, 0, 0, 1) == SW_DISPLAY_KIND_KMS);
    /* Without EGL_EXT_platform_base no platform display can be asked for. */
    SW_CHECK(choose("EGL_KHR_platform_x11 EGL_KHR_platform_gbm", 0, 1, 1) ==
             SW_DISPLAY_KIND_HEADLESS);
    SW_CHECK(choose(NULL, 1, 1, 1) == SW_DISPLAY_KIND_HEADLESS);   /* EGL 1.4, no client list */
    /* Whole names only: a longer extension is not the one asked for. */
    SW_CHECK(choose("EGL_EXT_platform_base EGL_KHR_platform_x11_ext", 0, 1, 0) ==
             SW_DISPLAY_KIND_HEADLESS);
}

static void auto_says_why(void)
{
    sw_display_env env = {mesa_ext, 0, 1, 0};
    char why[160];
    sw_display_choose(&env, why, sizeof why);
    SW_CHECK_MSG(!strcmp(why, "auto: DISPLAY is set and EGL offers X11"), "%s", why);
}

static void this_machines_egl_offers_surfaceless(void)
{
    sw_display_env env;
    sw_display_probe(&env);
    SW_CHECK(env.client_extensions != NULL);
    SW_CHECK(sw_egl_has_extension(env.client_extensions, "EGL_EXT_platform_base"));
    SW_CHECK(sw_egl_has_extension(env.client_extensions, "EGL_MESA_platform_surfaceless"));
    printf("  EGL client extensions: %s\n", env.client_extensions ? env.client_extensions : "-");
}

static void display_words_parse_and_unknown_ones_are_refused(void)
{
    sw_display_kind k = SW_DISPLAY_KIND_AUTO;
    sw_error err = {0};
    SW_CHECK(sw_display_kind_parse("kms", &k, &err) == SW_OK && k == SW_DISPLAY_KIND_KMS);
    SW_CHECK(sw_display_kind_parse("wayland", &k, &err) == SW_OK && k == SW_DISPLAY_KIND_WAYLAND);
    SW_CHECK(sw_display_kind_parse("auto", &k, &err) == SW_OK && k == SW_DISPLAY_KIND_AUTO);
    SW_CHECK(sw_display_kind_parse("fbdev", &k, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(!strcmp(err.message, "--display expects auto, headless, kms, x11 or wayland, "
                         "got 'fbdev'"), "%s", err.message);
    SW_CHECK(!strcmp(sw_display_kind_name(SW_DISPLAY_KIND_X11), "x11"));
}

static sw_status try_init(sw_display_kind kind, const char *device, sw_display *d, sw_error *err)
{
    sw_display_desc desc = {.kind = kind, .width = 64, .height = 48, .drm_device = device};
    return sw_display_init(d, &desc, err);
}

static int one_line(const char *s) { return strchr(s, '\n') == NULL && *s; }

static void kms_without_a_drm_device_is_one_clear_error(void)
{
    static sw_display d;
    sw_error err = {0};
    glob_t g;
    int cards = glob("/dev/dri/card*", 0, NULL, &g) == 0 && g.gl_pathc > 0;
    globfree(&g);
    if (!cards) {   /* this machine: the scan over card0..card15 finds nothing */
        SW_CHECK(try_init(SW_DISPLAY_KIND_KMS, NULL, &d, &err) == SW_ERR_IO);
        SW_CHECK_MSG(!strcmp(err.message, "kms display: no DRM device: /dev/dri/card0 .. "
                             "/dev/dri/card15 do not exist (no display driver on this machine); "
                             "use --display headless, x11 or wayland"), "%s", err.message);
        SW_CHECK(!d.up);
    }
    SW_CHECK(try_init(SW_DISPLAY_KIND_KMS, "/dev/dri/card-sw-test", &d, &err) == SW_ERR_IO);
    SW_CHECK_MSG(!strcmp(err.message, "kms display: no DRM device: /dev/dri/card-sw-test does "
                         "not exist"), "%s", err.message);
}

static void kms_on_a_file_that_is_no_drm_device_says_so(void)
{
    static sw_display d;
    sw_error err = {0};
    SW_CHECK(try_init(SW_DISPLAY_KIND_KMS, "/dev/null", &d, &err) == SW_ERR_UNSUPPORTED);
    SW_CHECK_MSG(!strncmp(err.message, "kms display: /dev/null has no mode setting", 42) &&
                 one_line(err.message), "%s", err.message);
}

static void x11_without_a_server_is_one_clear_error(void)
{
    static sw_display d;
    sw_error err = {0};
    unsetenv("DISPLAY");
    SW_CHECK(try_init(SW_DISPLAY_KIND_X11, NULL, &d, &err) == SW_ERR_UNSUPPORTED);
    SW_CHECK_MSG(!strcmp(err.message, "x11 display: DISPLAY is not set (no X session; use "
                         "--display headless, kms or wayland)"), "%s", err.message);
    setenv("DISPLAY", ":4242", 1);   /* no server listens there */
    SW_CHECK(try_init(SW_DISPLAY_KIND_X11, NULL, &d, &err) == SW_ERR_IO);
    SW_CHECK_MSG(!strcmp(err.message, "x11 display: cannot open the X display ':4242' (no X "
                         "server there, or no access)"), "%s", err.message);
    unsetenv("DISPLAY");
}

static void wayland_without_a_compositor_is_one_clear_error(void)
{
    static sw_display d;
    sw_error err = {0};
    unsetenv("WAYLAND_DISPLAY");
    SW_CHECK(try_init(SW_DISPLAY_KIND_WAYLAND, NULL, &d, &err) == SW_ERR_UNSUPPORTED);
    SW_CHECK_MSG(!strcmp(err.message, "wayland display: WAYLAND_DISPLAY is not set (no "
                         "Wayland session; use --display headless, kms or x11)"), "%s",
                 err.message);
    setenv("XDG_RUNTIME_DIR", "/tmp", 1);
    setenv("WAYLAND_DISPLAY", "sw-test-no-compositor", 1);
    SW_CHECK(try_init(SW_DISPLAY_KIND_WAYLAND, NULL, &d, &err) == SW_ERR_IO);
    SW_CHECK_MSG(!strncmp(err.message, "wayland display: cannot connect to "
                          "'sw-test-no-compositor'", 58) && one_line(err.message),
                 "%s", err.message);
    /* Chosen by auto, the error says so. */
    SW_CHECK(try_init(SW_DISPLAY_KIND_AUTO, NULL, &d, &err) == SW_ERR_IO);
    SW_CHECK_MSG(!strncmp(err.message, "auto: WAYLAND_DISPLAY is set and EGL offers Wayland: "
                          "wayland display: cannot connect to 'sw-test-no-compositor'", 111),
                 "%s", err.message);
    unsetenv("WAYLAND_DISPLAY");
}

/* A display this build lacks (SW_WITH_KMS, SW_WITH_X11, SW_WITH_WAYLAND
 * off) is refused in one line, by the check and by init, and auto never
 * picks it, even where the session and EGL offer it; one it has passes. */
static void a_display_not_built_is_refused_and_never_chosen(void)
{
    static const struct { sw_display_kind kind; int built; const char *message; } kinds[] = {
        {SW_DISPLAY_KIND_KMS, SW_HAVE_KMS, "built without KMS (SW_WITH_KMS=OFF)"},
        {SW_DISPLAY_KIND_X11, SW_HAVE_X11, "built without X11 (SW_WITH_X11=OFF)"},
        {SW_DISPLAY_KIND_WAYLAND, SW_HAVE_WAYLAND, "built without Wayland (SW_WITH_WAYLAND=OFF)"},
    };
    static sw_display d;
    sw_error err = {0};
    SW_CHECK(sw_display_kind_check_built(SW_DISPLAY_KIND_AUTO, &err) == SW_OK);
    SW_CHECK(sw_display_kind_check_built(SW_DISPLAY_KIND_HEADLESS, &err) == SW_OK);
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
        sw_status st = sw_display_kind_check_built(kinds[i].kind, &err);
        if (kinds[i].built) {
            SW_CHECK(st == SW_OK);
            continue;
        }
        SW_CHECK_MSG(st == SW_ERR_ARG && !strcmp(err.message, kinds[i].message), "%s",
                     err.message);
        SW_CHECK(try_init(kinds[i].kind, NULL, &d, &err) == SW_ERR_ARG && !d.up);
        SW_CHECK_MSG(!strcmp(err.message, kinds[i].message), "%s", err.message);
        SW_CHECK(choose(mesa_ext, 1, 1, 1) != kinds[i].kind);
        SW_CHECK(choose(mesa_ext, kinds[i].kind == SW_DISPLAY_KIND_WAYLAND,
                        kinds[i].kind == SW_DISPLAY_KIND_X11, 1) != kinds[i].kind);
    }
}

static void headless_needs_a_size(void)
{
    static sw_display d;
    sw_error err = {0};
    sw_display_desc desc = {.kind = SW_DISPLAY_KIND_HEADLESS};
    SW_CHECK(sw_display_init(&d, &desc, &err) == SW_ERR_ARG);
    SW_CHECK_MSG(!strcmp(err.message, "headless display (asked for headless) needs a size: "
                         "--headless WxH, --size WxH or [display] size"), "%s", err.message);
}

/* Auto on this machine (no session, no card) is headless, drawn and read
 * back through the interface like any display. */
static void auto_here_is_headless_and_draws(void)
{
    static sw_display d;
    static uint8_t rgba[64 * 48 * 4];
    sw_error err = {0};
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    sw_status st = try_init(SW_DISPLAY_KIND_AUTO, NULL, &d, &err);
    SW_CHECK_MSG(st == SW_OK, "%s", err.message);
    if (st != SW_OK)
        return;
    SW_CHECK(d.kind == SW_DISPLAY_KIND_HEADLESS && d.width == 64 && d.height == 48);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    SW_CHECK(sw_display_read_rgba(&d, rgba, &err) == SW_OK);
    SW_CHECK(rgba[0] == 255 && rgba[1] == 0 && rgba[2] == 0 && rgba[3] == 255);
    SW_CHECK(rgba[sizeof rgba - 4] == 255 && rgba[sizeof rgba - 3] == 0);
    SW_CHECK(sw_display_present(&d, &err) == SW_OK);
    sw_key_event keys[4];
    SW_CHECK(sw_display_poll_keys(&d, keys, 4) == 0 && !d.close_requested);
    sw_display_destroy(&d);
    SW_CHECK(!d.up);
}

int main(void)
{
    if (SW_HAVE_KMS && SW_HAVE_X11 && SW_HAVE_WAYLAND) {   /* auto's order among all three */
        SW_RUN(auto_prefers_a_session_window_then_kms_then_headless);
        SW_RUN(auto_takes_only_what_egl_offers);
        SW_RUN(auto_says_why);
    }
    SW_RUN(this_machines_egl_offers_surfaceless);
    SW_RUN(display_words_parse_and_unknown_ones_are_refused);
    SW_RUN(a_display_not_built_is_refused_and_never_chosen);
    if (SW_HAVE_KMS) {
        SW_RUN(kms_without_a_drm_device_is_one_clear_error);
        SW_RUN(kms_on_a_file_that_is_no_drm_device_says_so);
    }
    if (SW_HAVE_X11)
        SW_RUN(x11_without_a_server_is_one_clear_error);
    if (SW_HAVE_WAYLAND)
        SW_RUN(wayland_without_a_compositor_is_one_clear_error);
    SW_RUN(headless_needs_a_size);
    SW_RUN(auto_here_is_headless_and_draws);
    return sw_test_finish();
}
