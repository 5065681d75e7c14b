/* SPDX-License-Identifier: MIT */
/* The KMS display (sw_display.h "kms"): full-screen scan-out on a kiosk
 * without X or Wayland, through libdrm and GBM, shaped like kmscube's
 * drm-legacy.c: open /dev/dri/cardN and become DRM master, pick a connected
 * connector and its mode (sw_kms_choose.h), a CRTC its encoders can drive,
 * a GBM surface of XRGB8888 scan-out buffers, EGL on GBM; each present swaps,
 * locks the new front buffer, page-flips to it with an event, waits for the
 * event and releases the previous buffer (sw_kms_flip.h). Destroy puts back
 * the CRTC as it was found (the console) and drops master.
 * Written against the libdrm/GBM documentation and kmscube. Tested without a
 * device (tests/test_display.c) and on QEMU's virtio-gpu
 * (tests/qemu/kms_in_qemu.sh); a real GPU's scan-out only on a unit. */
#ifndef SW_DISPLAY_KMS_H
#define SW_DISPLAY_KMS_H

#include <stdint.h>

#include "sw_egl_window.h"
#include "sw_error.h"
#include "sw_kms_flip.h"

/* Mesa's GBM surfaces cycle through at most 4 buffers; room for twice that. */
enum { SW_KMS_MAX_FBS = 8 };

typedef struct sw_display_kms {
    int fd;                   /* -1 when closed */
    char path[32];            /* /dev/dri/cardN */
    uint32_t connector_id, crtc_id;
    unsigned char mode[96];   /* the drmModeModeInfo chosen (68 bytes in libdrm 2.4) */
    void *saved_crtc;         /* drmModeCrtcPtr as found, restored at exit */
    void *gbm;                /* struct gbm_device * */
    void *surface;            /* struct gbm_surface * */
    sw_egl_window egl;
    sw_kms_flip flip;
    /* The framebuffer of each GBM buffer, added when it first shows up: a
     * table instead of kmscube's gbm_bo_set_user_data with a malloc'd struct,
     * since the frame loop allocates nothing. */
    struct { void *bo; uint32_t fb_id; } fbs[SW_KMS_MAX_FBS];
    int was_master;           /* we set master (and drop it at exit) */
    int flip_done;            /* set by the page-flip event handler */
} sw_display_kms;

/* device NULL tries /dev/dri/card0..card15 and takes the first with a
 * connected display. want_width x want_height > 0 picks that mode when the
 * connector has it. The size shown is written to width, height. */
sw_status sw_display_kms_init(sw_display_kms *k, const char *device, int want_width,
                              int want_height, int *width, int *height, sw_error *err);
sw_status sw_display_kms_present(sw_display_kms *k, sw_error *err);
void sw_display_kms_destroy(sw_display_kms *k);

#endif
