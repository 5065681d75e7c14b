/* SPDX-License-Identifier: MIT */
#include "sw_kms_flip.h"

#include <stddef.h>

void sw_kms_flip_reset(sw_kms_flip *f) { f->front = f->pending = NULL; }

sw_kms_flip_action sw_kms_flip_submit(sw_kms_flip *f, void *buffer)
{
    if (f->pending)
        return SW_KMS_FLIP_BUSY;
    if (!f->front) {
        f->front = buffer;
        return SW_KMS_FLIP_MODESET;
    }
    f->pending = buffer;
    return SW_KMS_FLIP_PAGE_FLIP;
}

void *sw_kms_flip_complete(sw_kms_flip *f)
{
    if (!f->pending)
        return NULL;
    void *old = f->front;
    f->front = f->pending;
    f->pending = NULL;
    return old;
}

void *sw_kms_flip_cancel(sw_kms_flip *f)
{
    void *b = f->pending;
    f->pending = NULL;
    return b;
}

void sw_kms_flip_drain(sw_kms_flip *f, void *held[2])
{
    held[0] = f->front;
    held[1] = f->pending;
    sw_kms_flip_reset(f);
}
