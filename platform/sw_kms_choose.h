/* SPDX-License-Identifier: MIT */
/* The KMS display's choices as pure functions over plain lists, so they are
 * tested without a DRM device (tests/test_kms_choose.c): which connector,
 * which of its modes. sw_display_kms.c fills the lists from libdrm. */
#ifndef SW_KMS_CHOOSE_H
#define SW_KMS_CHOOSE_H

typedef struct sw_kms_connector_info {
    int connected;    /* DRM_MODE_CONNECTED */
    int mode_count;
} sw_kms_connector_info;

typedef struct sw_kms_mode_info {
    int width, height;
    int refresh_hz;
    int preferred;    /* DRM_MODE_TYPE_PREFERRED */
} sw_kms_mode_info;

/* The first connected connector with at least one mode (kmscube's rule: the
 * order is the driver's, which lists the built-in panel first); -1: none. */
int sw_kms_choose_connector(const sw_kms_connector_info *connectors, int count);

/* With want_width and want_height > 0, the first mode of exactly that size
 * (the highest refresh among them); else, or when none has it, the
 * preferred mode; without one the largest by area, then refresh. -1 when
 * count is 0. */
int sw_kms_choose_mode(const sw_kms_mode_info *modes, int count, int want_width,
                       int want_height);

#endif
