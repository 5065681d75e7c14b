/* SPDX-License-Identifier: MIT */
/* KMS through libdrm's legacy mode-setting calls and GBM, as kmscube's
 * drm-legacy.c and common.c do it: init_drm (device, connector, mode, CRTC),
 * init_gbm (scan-out surface), init_egl (EGL on GBM), then per frame lock the
 * front buffer, flip to it, wait for the flip event, release the previous one.
 * Run for real on QEMU's virtio-gpu (tests/qemu/kms_in_qemu.sh); untested
 * on a unit's GPU. The failure without a device: tests/test_display.c. */
#include "sw_display_kms.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <errno.h>
#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#include <drm_fourcc.h>

#include "sw_kms_choose.h"

#ifndef EGL_PLATFORM_GBM_KHR
#define EGL_PLATFORM_GBM_KHR 0x31D7
#endif

_Static_assert(sizeof(drmModeModeInfo) <= sizeof(((sw_display_kms *)0)->mode),
               "sw_display_kms.mode must hold a drmModeModeInfo");

enum { MAX_CARDS = 16, MAX_CONNECTORS = 32, MAX_MODES = 64, FLIP_TIMEOUT_MS = 1000 };


/* The connector's choice (sw_kms_choose.h) on libdrm's lists. */
static int pick_connector(int fd, const drmModeRes *res, drmModeConnector **out)
{
    sw_kms_connector_info info[MAX_CONNECTORS] = {{0}};
    drmModeConnector *conn[MAX_CONNECTORS];
    int n = res->count_connectors < MAX_CONNECTORS ? res->count_connectors : MAX_CONNECTORS;
    for (int i = 0; i < n; i++) {
        conn[i] = drmModeGetConnector(fd, res->connectors[i]);
        info[i].connected = conn[i] && conn[i]->connection == DRM_MODE_CONNECTED;
        info[i].mode_count = conn[i] ? conn[i]->count_modes : 0;
    }
    int pick = sw_kms_choose_connector(info, n);
    for (int i = 0; i < n; i++)
        if (i != pick && conn[i])
            drmModeFreeConnector(conn[i]);
    *out = pick >= 0 ? conn[pick] : NULL;
    return pick;
}

static int pick_mode(const drmModeConnector *c, int want_w, int want_h)
{
    sw_kms_mode_info info[MAX_MODES] = {{0}};
    int n = c->count_modes < MAX_MODES ? c->count_modes : MAX_MODES;
    for (int i = 0; i < n; i++) {
        info[i].width = c->modes[i].hdisplay;
        info[i].height = c->modes[i].vdisplay;
        info[i].refresh_hz = (int)c->modes[i].vrefresh;
        info[i].preferred = (c->modes[i].type & DRM_MODE_TYPE_PREFERRED) != 0;
    }
    return sw_kms_choose_mode(info, n, want_w, want_h);
}

/* kmscube's find_crtc_for_connector: the CRTC already driving it, else the
 * first one any of its encoders can drive. 0: none. */
static uint32_t pick_crtc(int fd, const drmModeRes *res, const drmModeConnector *c)
{
    drmModeEncoder *enc = c->encoder_id ? drmModeGetEncoder(fd, c->encoder_id) : NULL;
    uint32_t crtc = enc ? enc->crtc_id : 0;
    if (enc)
        drmModeFreeEncoder(enc);
    for (int e = 0; !crtc && e < c->count_encoders; e++) {
        enc = drmModeGetEncoder(fd, c->encoders[e]);
        for (int i = 0; enc && !crtc && i < res->count_crtcs; i++)
            if (enc->possible_crtcs & (1u << i))
                crtc = res->crtcs[i];
        if (enc)
            drmModeFreeEncoder(enc);
    }
    return crtc;
}

/* Connector, mode and CRTC on an open card. */
static sw_status setup_card(sw_display_kms *k, int want_w, int want_h, int *w, int *h,
                            sw_error *err)
{
    drmModeRes *res = drmModeGetResources(k->fd);
    if (!res)
        return sw_error_set(err, SW_ERR_UNSUPPORTED, "kms display: %s has no mode setting (a "
                            "render-only GPU?): %s", k->path, strerror(errno));
    drmModeConnector *conn = NULL;
    int ok = pick_connector(k->fd, res, &conn) >= 0;
    int m = ok ? pick_mode(conn, want_w, want_h) : -1;
    uint32_t crtc = m >= 0 ? pick_crtc(k->fd, res, conn) : 0;
    sw_status st = SW_OK;
    if (!ok)
        st = sw_error_set(err, SW_ERR_UNSUPPORTED, "kms display: %s: no connected display",
                          k->path);
    else if (!crtc)
        st = sw_error_set(err, SW_ERR_UNSUPPORTED, "kms display: %s: no CRTC can drive "
                          "connector %u", k->path, conn->connector_id);
    if (crtc) {
        memcpy(k->mode, &conn->modes[m], sizeof(drmModeModeInfo));
        k->connector_id = conn->connector_id;
        k->crtc_id = crtc;
        *w = conn->modes[m].hdisplay;
        *h = conn->modes[m].vdisplay;
    }
    if (conn)
        drmModeFreeConnector(conn);
    drmModeFreeResources(res);
    return st;
}

/* Master is needed for mode setting and flips; the first opener of a card
 * gets it, or we ask (logind sessions hand it over on VT switch). */
static sw_status take_master(sw_display_kms *k, sw_error *err)
{
    if (drmIsMaster(k->fd))
        return SW_OK;
    if (drmSetMaster(k->fd) == 0) {
        k->was_master = 1;
        return SW_OK;
    }
    return sw_error_set(err, SW_ERR_UNSUPPORTED, "kms display: %s: cannot become DRM master "
                        "(%s): another program (an X server, a Wayland compositor) is showing "
                        "on it; stop it, or use --display x11 or wayland", k->path,
                        strerror(errno));
}

static sw_status open_card(sw_display_kms *k, const char *device, int want_w, int want_h,
                           int *w, int *h, sw_error *err)
{
    int found = 0;
    sw_status st = SW_OK;
    for (int i = 0; i < (device ? 1 : MAX_CARDS); i++) {
        if (device)
            snprintf(k->path, sizeof k->path, "%s", device);
        else
            snprintf(k->path, sizeof k->path, "/dev/dri/card%d", i);
        k->fd = open(k->path, O_RDWR | O_CLOEXEC);
        if (k->fd < 0 && errno == ENOENT)
            continue;
        found = 1;
        if (k->fd < 0)
            return sw_error_set(err, SW_ERR_IO, "kms display: %s: %s (the user needs the "
                                "video group, or the service's udev rule)", k->path,
                                strerror(errno));
        if ((st = setup_card(k, want_w, want_h, w, h, err)) == SW_OK)
            return take_master(k, err);
        close(k->fd);
        k->fd = -1;
    }
    if (found)
        return st;
    if (device)
        return sw_error_set(err, SW_ERR_IO, "kms display: no DRM device: %s does not exist",
                            device);
    return sw_error_set(err, SW_ERR_IO, "kms display: no DRM device: /dev/dri/card0 .. "
                        "/dev/dri/card%d do not exist (no display driver on this machine); use "
                        "--display headless, x11 or wayland", MAX_CARDS - 1);
}

static sw_status init_gbm_egl(sw_display_kms *k, int w, int h, sw_error *err)
{
    k->gbm = gbm_create_device(k->fd);
    if (!k->gbm)
        return sw_error_set(err, SW_ERR_GL, "kms display: %s: gbm_create_device failed",
                            k->path);
    k->surface = gbm_surface_create(k->gbm, (uint32_t)w, (uint32_t)h, GBM_FORMAT_XRGB8888,
                                    GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    if (!k->surface)
        return sw_error_set(err, SW_ERR_GL, "kms display: gbm_surface_create %dx%d XRGB8888 "
                            "failed", w, h);
    sw_status st = sw_egl_window_open(&k->egl, "kms display", EGL_PLATFORM_GBM_KHR,
                                      "EGL_KHR_platform_gbm", "EGL_MESA_platform_gbm", k->gbm,
                                      GBM_FORMAT_XRGB8888, err);
    return st != SW_OK ? st : sw_egl_window_attach(&k->egl, k->surface, err);
}

sw_status sw_display_kms_init(sw_display_kms *k, const char *device, int want_width,
                              int want_height, int *width, int *height, sw_error *err)
{
    memset(k, 0, sizeof *k);
    k->fd = -1;
    sw_kms_flip_reset(&k->flip);
    sw_status st = open_card(k, device, want_width, want_height, width, height, err);
    if (st == SW_OK) {
        k->saved_crtc = drmModeGetCrtc(k->fd, k->crtc_id);
        st = init_gbm_egl(k, *width, *height, err);
    }
    if (st != SW_OK)
        sw_display_kms_destroy(k);
    return st;
}

/* The framebuffer of a GBM buffer, added the first time the buffer shows up
 * (kmscube's drm_fb_get_from_bo). 0 with err set on failure. */
static uint32_t fb_for(sw_display_kms *k, struct gbm_bo *bo, sw_error *err)
{
    int free_slot = -1;
    for (int i = 0; i < SW_KMS_MAX_FBS; i++) {
        if (k->fbs[i].bo == bo)
            return k->fbs[i].fb_id;
        if (!k->fbs[i].bo && free_slot < 0)
            free_slot = i;
    }
    if (free_slot < 0) {
        sw_error_set(err, SW_ERR_RANGE, "kms display: GBM gave more than %d buffers",
                     SW_KMS_MAX_FBS);
        return 0;
    }
    uint32_t handles[4] = {gbm_bo_get_handle(bo).u32}, pitches[4] = {gbm_bo_get_stride(bo)};
    uint32_t offsets[4] = {0}, fb = 0;
    if (drmModeAddFB2(k->fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), DRM_FORMAT_XRGB8888,
                      handles, pitches, offsets, &fb, 0) != 0) {
        sw_error_set(err, SW_ERR_IO, "kms display: drmModeAddFB2: %s", strerror(errno));
        return 0;
    }
    k->fbs[free_slot].bo = bo;
    k->fbs[free_slot].fb_id = fb;
    return fb;
}

static void on_page_flip(int fd, unsigned frame, unsigned sec, unsigned usec, void *data)
{
    (void)fd;
    (void)frame;
    (void)sec;
    (void)usec;
    ((sw_display_kms *)data)->flip_done = 1;
}

/* kmscube's loop: poll the card until drmHandleEvent has run our handler. */
static sw_status wait_for_flip(sw_display_kms *k, sw_error *err)
{
    drmEventContext ev = {.version = 2, .page_flip_handler = on_page_flip};
    while (!k->flip_done) {
        struct pollfd p = {.fd = k->fd, .events = POLLIN};
        int n = poll(&p, 1, FLIP_TIMEOUT_MS);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return sw_error_set(err, SW_ERR_IO, "kms display: %s: no page-flip event within "
                                "%d ms%s", k->path, FLIP_TIMEOUT_MS, n < 0 ? strerror(errno) : "");
        if (drmHandleEvent(k->fd, &ev) != 0)
            return sw_error_set(err, SW_ERR_IO, "kms display: drmHandleEvent: %s",
                                strerror(errno));
    }
    return SW_OK;
}

static sw_status show(sw_display_kms *k, struct gbm_bo *bo, uint32_t fb, sw_error *err)
{
    switch (sw_kms_flip_submit(&k->flip, bo)) {
    case SW_KMS_FLIP_MODESET: {
        drmModeModeInfo mode;
        memcpy(&mode, k->mode, sizeof mode);
        if (drmModeSetCrtc(k->fd, k->crtc_id, fb, 0, 0, &k->connector_id, 1, &mode) != 0)
            return sw_error_set(err, SW_ERR_IO, "kms display: drmModeSetCrtc %ux%u: %s",
                                mode.hdisplay, mode.vdisplay, strerror(errno));
        return SW_OK;
    }
    case SW_KMS_FLIP_PAGE_FLIP:
        k->flip_done = 0;
        if (drmModePageFlip(k->fd, k->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, k) != 0) {
            gbm_surface_release_buffer(k->surface, sw_kms_flip_cancel(&k->flip));
            return sw_error_set(err, SW_ERR_IO, "kms display: drmModePageFlip: %s",
                                strerror(errno));
        }
        sw_status st = wait_for_flip(k, err);
        if (st != SW_OK)
            return st;   /* the buffer stays pending: destroy releases it */
        struct gbm_bo *old = sw_kms_flip_complete(&k->flip);
        if (old)
            gbm_surface_release_buffer(k->surface, old);
        return SW_OK;
    case SW_KMS_FLIP_BUSY:
    default:
        gbm_surface_release_buffer(k->surface, bo);
        return sw_error_set(err, SW_ERR_ARG, "kms display: a flip is still pending");
    }
}

sw_status sw_display_kms_present(sw_display_kms *k, sw_error *err)
{
    sw_status st = sw_egl_window_swap(&k->egl, err);
    if (st != SW_OK)
        return st;
    struct gbm_bo *bo = gbm_surface_lock_front_buffer(k->surface);
    if (!bo)
        return sw_error_set(err, SW_ERR_GL, "kms display: gbm_surface_lock_front_buffer "
                            "failed");
    uint32_t fb = fb_for(k, bo, err);
    if (!fb) {
        gbm_surface_release_buffer(k->surface, bo);
        return err ? err->status : SW_ERR_IO;
    }
    return show(k, bo, fb, err);
}

/* Puts the console (or whatever was there) back: its framebuffer and mode on
 * the CRTC we took. */
static void restore_crtc(sw_display_kms *k)
{
    drmModeCrtc *saved = k->saved_crtc;
    if (!saved)
        return;
    if (saved->mode_valid)
        drmModeSetCrtc(k->fd, saved->crtc_id, saved->buffer_id, saved->x, saved->y,
                       &k->connector_id, 1, &saved->mode);
    else
        drmModeSetCrtc(k->fd, saved->crtc_id, 0, 0, 0, NULL, 0, NULL);
    drmModeFreeCrtc(saved);
    k->saved_crtc = NULL;
}

void sw_display_kms_destroy(sw_display_kms *k)
{
    if (k->fd >= 0 && k->flip.front)
        restore_crtc(k);
    else if (k->saved_crtc)
        drmModeFreeCrtc(k->saved_crtc);
    k->saved_crtc = NULL;
    void *held[2];
    sw_kms_flip_drain(&k->flip, held);
    for (int i = 0; i < 2; i++)
        if (held[i])
            gbm_surface_release_buffer(k->surface, held[i]);
    for (int i = 0; i < SW_KMS_MAX_FBS; i++)
        if (k->fbs[i].bo)
            drmModeRmFB(k->fd, k->fbs[i].fb_id);
    memset(k->fbs, 0, sizeof k->fbs);
    sw_egl_window_destroy(&k->egl);
    if (k->surface)
        gbm_surface_destroy(k->surface);
    if (k->gbm)
        gbm_device_destroy(k->gbm);
    k->surface = k->gbm = NULL;
    if (k->fd >= 0) {
        if (k->was_master)
            drmDropMaster(k->fd);
        close(k->fd);
    }
    k->fd = -1;
}
