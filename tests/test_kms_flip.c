/* SPDX-License-Identifier: MIT */
/* The KMS display's scan-out buffer bookkeeping (platform/sw_kms_flip.h):
 * kmscube's order of lock, flip, wait for the event, release the previous
 * buffer, walked through with three stand-in buffers as GBM hands them out. */
#include "sw_kms_flip.h"
#include "sw_test.h"

static int a, b, c;   /* their addresses are the buffers */

static void the_first_buffer_is_a_mode_set_and_shows_at_once(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    SW_CHECK(sw_kms_flip_submit(&f, &a) == SW_KMS_FLIP_MODESET);
    SW_CHECK(f.front == &a && f.pending == NULL);
}

static void later_buffers_flip_and_release_the_old_front_on_the_event(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    sw_kms_flip_submit(&f, &a);
    SW_CHECK(sw_kms_flip_submit(&f, &b) == SW_KMS_FLIP_PAGE_FLIP);
    SW_CHECK(f.front == &a && f.pending == &b);   /* a is still on screen: kept */
    SW_CHECK(sw_kms_flip_complete(&f) == &a);
    SW_CHECK(f.front == &b && f.pending == NULL);
    SW_CHECK(sw_kms_flip_submit(&f, &c) == SW_KMS_FLIP_PAGE_FLIP);
    SW_CHECK(sw_kms_flip_complete(&f) == &b);
    SW_CHECK(sw_kms_flip_submit(&f, &a) == SW_KMS_FLIP_PAGE_FLIP);  /* GBM reuses a */
    SW_CHECK(sw_kms_flip_complete(&f) == &c);
    SW_CHECK(f.front == &a);
}

static void a_second_flip_before_the_event_is_refused(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    sw_kms_flip_submit(&f, &a);
    sw_kms_flip_submit(&f, &b);
    SW_CHECK(sw_kms_flip_submit(&f, &c) == SW_KMS_FLIP_BUSY);
    SW_CHECK(f.front == &a && f.pending == &b);   /* unchanged; c is still the caller's */
}

static void a_stray_event_releases_nothing(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    SW_CHECK(sw_kms_flip_complete(&f) == NULL);
    sw_kms_flip_submit(&f, &a);
    SW_CHECK(sw_kms_flip_complete(&f) == NULL);
    SW_CHECK(f.front == &a);
}

static void a_refused_flip_gives_the_buffer_back_and_keeps_the_front(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    sw_kms_flip_submit(&f, &a);
    sw_kms_flip_submit(&f, &b);
    SW_CHECK(sw_kms_flip_cancel(&f) == &b);
    SW_CHECK(f.front == &a && f.pending == NULL);
    SW_CHECK(sw_kms_flip_submit(&f, &c) == SW_KMS_FLIP_PAGE_FLIP);
}

static void drain_hands_back_every_held_buffer_once(void)
{
    sw_kms_flip f;
    sw_kms_flip_reset(&f);
    sw_kms_flip_submit(&f, &a);
    sw_kms_flip_submit(&f, &b);   /* exit while a flip is pending */
    void *held[2];
    sw_kms_flip_drain(&f, held);
    SW_CHECK(held[0] == &a && held[1] == &b);
    SW_CHECK(f.front == NULL && f.pending == NULL);
    sw_kms_flip_drain(&f, held);
    SW_CHECK(held[0] == NULL && held[1] == NULL);
    /* After a drain the next buffer is a mode set again (a restarted display). */
    SW_CHECK(sw_kms_flip_submit(&f, &c) == SW_KMS_FLIP_MODESET);
}

int main(void)
{
    SW_RUN(the_first_buffer_is_a_mode_set_and_shows_at_once);
    SW_RUN(later_buffers_flip_and_release_the_old_front_on_the_event);
    SW_RUN(a_second_flip_before_the_event_is_refused);
    SW_RUN(a_stray_event_releases_nothing);
    SW_RUN(a_refused_flip_gives_the_buffer_back_and_keeps_the_front);
    SW_RUN(drain_hands_back_every_held_buffer_once);
    return sw_test_finish();
}
