/* SPDX-License-Identifier: MIT */
/* Key events from a developer window (X11 key events, Wayland wl_keyboard),
 * kept in a fixed ring inside the display until the input step takes them
 * with sw_display_poll_keys (sw_display.h). No allocation: a full queue drops
 * the oldest event and counts it, so a stalled consumer never blocks the
 * window system. Written and read on the GL thread only (the display pumps
 * its window events there). */
#ifndef SW_KEY_QUEUE_H
#define SW_KEY_QUEUE_H

#include <stdint.h>

/* keysym: an X11/XKB keysym (X11/keysymdef.h, xkbcommon-keysyms.h share the
 * numbers): 0xff1b Escape, 0xff51..0xff54 Left, Up, Right, Down, 'a'..'z'
 * for letters (unshifted), '0'..'9'. pressed: 1 press, 0 release. */
typedef struct sw_key_event {
    uint32_t keysym;
    uint8_t pressed;
} sw_key_event;

enum { SW_KEY_QUEUE_CAPACITY = 64 };

typedef struct sw_key_queue {
    sw_key_event events[SW_KEY_QUEUE_CAPACITY];
    uint32_t head;     /* index of the oldest event */
    uint32_t count;
    uint64_t dropped;  /* events lost to a full queue since init */
} sw_key_queue;

void sw_key_queue_clear(sw_key_queue *q);
/* Appends; on a full queue the oldest event makes room (and is counted). */
void sw_key_queue_push(sw_key_queue *q, uint32_t keysym, int pressed);
/* Moves up to capacity of the oldest events into out, oldest first; returns
 * how many. The rest stay queued. */
int sw_key_queue_take(sw_key_queue *q, sw_key_event *out, int capacity);

#endif
