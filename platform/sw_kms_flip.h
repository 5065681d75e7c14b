/* SPDX-License-Identifier: MIT */
/* The KMS display's scan-out buffer bookkeeping as a pure state machine
 * (kmscube's loop: lock the new front buffer, flip to it, wait for the flip
 * event, release the previous one), so the order is tested without a DRM
 * device (tests/test_kms_flip.c). Buffers are opaque handles (struct gbm_bo
 * pointers in sw_display_kms.c). The screen shows `front`; `pending` has
 * been queued by a page flip whose event has not come yet. A buffer goes
 * back to the GBM surface only when the screen no longer scans it out. */
#ifndef SW_KMS_FLIP_H
#define SW_KMS_FLIP_H

typedef struct sw_kms_flip {
    void *front;     /* scanned out now; NULL before the first mode set */
    void *pending;   /* queued by drmModePageFlip, waiting for its event */
} sw_kms_flip;

typedef enum sw_kms_flip_action {
    SW_KMS_FLIP_MODESET,     /* first frame: drmModeSetCrtc with it; it is the front at once */
    SW_KMS_FLIP_PAGE_FLIP,   /* drmModePageFlip with an event, then wait for the event */
    SW_KMS_FLIP_BUSY,        /* a flip is still pending: wait for its event first */
} sw_kms_flip_action;

void sw_kms_flip_reset(sw_kms_flip *f);

/* A newly locked buffer: what to do with it. On MODESET it becomes the front
 * (nothing to release); on PAGE_FLIP it is pending; on BUSY nothing changed
 * and the caller still owns it. */
sw_kms_flip_action sw_kms_flip_submit(sw_kms_flip *f, void *buffer);

/* The pending flip's event came: the pending buffer is the front now.
 * Returns the buffer to release (the old front), or NULL when no flip was
 * pending (a stray event is ignored). */
void *sw_kms_flip_complete(sw_kms_flip *f);

/* The flip was refused (drmModePageFlip failed): the pending buffer goes
 * back to the caller, who releases it; the front stays. */
void *sw_kms_flip_cancel(sw_kms_flip *f);

/* At exit, after the CRTC was restored: the buffers still held, front first
 * (NULLs where none); the state is reset. */
void sw_kms_flip_drain(sw_kms_flip *f, void *held[2]);

#endif
