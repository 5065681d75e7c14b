/* SPDX-License-Identifier: MIT */
/* The window key queue (platform/sw_key_queue.h): order, partial takes, and
 * a full queue dropping the oldest. */
#include "sw_key_queue.h"
#include "sw_test.h"

static void keys_come_out_oldest_first(void)
{
    sw_key_queue q;
    sw_key_queue_clear(&q);
    sw_key_queue_push(&q, 'a', 1);
    sw_key_queue_push(&q, 'a', 0);
    sw_key_queue_push(&q, 0xff1b, 1);
    sw_key_event out[8];
    SW_CHECK(sw_key_queue_take(&q, out, 8) == 3);
    SW_CHECK(out[0].keysym == 'a' && out[0].pressed == 1);
    SW_CHECK(out[1].keysym == 'a' && out[1].pressed == 0);
    SW_CHECK(out[2].keysym == 0xff1b && out[2].pressed == 1);
    SW_CHECK(sw_key_queue_take(&q, out, 8) == 0);
}

static void a_small_take_leaves_the_rest(void)
{
    sw_key_queue q;
    sw_key_queue_clear(&q);
    for (uint32_t k = 0; k < 5; k++)
        sw_key_queue_push(&q, '0' + k, 1);
    sw_key_event out[2];
    SW_CHECK(sw_key_queue_take(&q, out, 2) == 2 && out[0].keysym == '0' && out[1].keysym == '1');
    SW_CHECK(sw_key_queue_take(&q, out, 2) == 2 && out[0].keysym == '2' && out[1].keysym == '3');
    SW_CHECK(sw_key_queue_take(&q, out, 2) == 1 && out[0].keysym == '4');
}

static void a_full_queue_drops_the_oldest_and_counts_it(void)
{
    sw_key_queue q;
    sw_key_queue_clear(&q);
    for (uint32_t k = 0; k < SW_KEY_QUEUE_CAPACITY + 3; k++)
        sw_key_queue_push(&q, 1000 + k, k % 2);
    SW_CHECK(q.dropped == 3 && q.count == SW_KEY_QUEUE_CAPACITY);
    sw_key_event out[SW_KEY_QUEUE_CAPACITY + 3];
    SW_CHECK(sw_key_queue_take(&q, out, SW_KEY_QUEUE_CAPACITY + 3) == SW_KEY_QUEUE_CAPACITY);
    SW_CHECK(out[0].keysym == 1003 && out[0].pressed == 1);
    SW_CHECK(out[SW_KEY_QUEUE_CAPACITY - 1].keysym == 1000 + SW_KEY_QUEUE_CAPACITY + 2);
}

int main(void)
{
    SW_RUN(keys_come_out_oldest_first);
    SW_RUN(a_small_take_leaves_the_rest);
    SW_RUN(a_full_queue_drops_the_oldest_and_counts_it);
    return sw_test_finish();
}
