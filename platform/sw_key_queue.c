/* SPDX-License-Identifier: MIT */
#include "sw_key_queue.h"

#include <string.h>

void sw_key_queue_clear(sw_key_queue *q) { memset(q, 0, sizeof *q); }

void sw_key_queue_push(sw_key_queue *q, uint32_t keysym, int pressed)
{
    if (q->count == SW_KEY_QUEUE_CAPACITY) {
        /* The newest keys matter most to a person at the keyboard. */
        q->head = (q->head + 1) % SW_KEY_QUEUE_CAPACITY;
        q->count--;
        q->dropped++;
    }
    sw_key_event *e = &q->events[(q->head + q->count) % SW_KEY_QUEUE_CAPACITY];
    e->keysym = keysym;
    e->pressed = pressed ? 1 : 0;
    q->count++;
}

int sw_key_queue_take(sw_key_queue *q, sw_key_event *out, int capacity)
{
    int n = 0;
    while (n < capacity && q->count > 0) {
        out[n++] = q->events[q->head];
        q->head = (q->head + 1) % SW_KEY_QUEUE_CAPACITY;
        q->count--;
    }
    return n;
}
