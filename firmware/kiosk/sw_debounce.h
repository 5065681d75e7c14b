/* SPDX-License-Identifier: MIT */
/* Debouncing one GPIO button line, the logic only: the
 * device layer (libgpiod v1, which has no debounce of its own) feeds each
 * both-edge event with its kernel timestamp, and ticks the machine with the
 * current time so that confirmations and long presses fire while the line is
 * quiet. Deterministic: no clock reads, no allocation; time comes in.
 *
 * The rule, with D = debounce, G = min_press, L = long_press:
 *  - A burst starts with the first edge after the line was settled and ends
 *    once no edge came for D. Edges inside it are bounces.
 *  - When a burst ends at the other level than the settled one, the level
 *    changes: PRESS (or RELEASE) at the burst's last edge + D.
 *  - When a burst that started from released ends released again, it was a
 *    short press if the line stayed active for at least G without a break
 *    somewhere inside it; then PRESS, RELEASE and SHORT all at the burst's
 *    end. Shorter pulses are glitches and give nothing. So a tap shorter than
 *    D is not lost, and a 1 ms spike with G = 2 ms is ignored.
 *  - A burst that starts and ends pressed is a bounce during a hold: nothing.
 *  - LONG fires once when the line has been pressed for L since its press
 *    burst began and no release burst is open (a release bounce that comes
 *    back pressed delays it to the burst's end). L = 0: no long presses.
 *  - RELEASE is followed by SHORT unless LONG fired for that press, so a
 *    button with two actions runs the short one on SHORT and the long one on
 *    LONG; a button with one action may run it on PRESS for a quicker answer.
 *  - A line that is active at init is taken as settled pressed without a
 *    PRESS, and its release is silent (no RELEASE, no SHORT, no LONG): a
 *    button stuck at boot does nothing until released and pressed again.
 *  - Time never goes backwards inside the machine: an edge or tick earlier
 *    than the latest time seen is taken to happen at that latest time (the
 *    kernel's per-line timestamps are monotonic; this only guards a caller
 *    mixing clocks), so events come out in non-decreasing time order.
 *  - Two edges of the same level in a row (an event lost in between) count
 *    as activity that restarts the quiet time, not as a level change. */
#ifndef SW_DEBOUNCE_H
#define SW_DEBOUNCE_H

#include <stdint.h>

typedef enum sw_debounce_kind {
    SW_DEBOUNCE_PRESS = 1,
    SW_DEBOUNCE_RELEASE,
    SW_DEBOUNCE_SHORT,  /* after RELEASE, when LONG did not fire for that press */
    SW_DEBOUNCE_LONG,
} sw_debounce_kind;

typedef struct sw_debounce_event {
    sw_debounce_kind kind;
    int64_t t_ns;       /* when the machine decided it, in the caller's clock */
} sw_debounce_event;

/* The most events one sw_debounce_edge or sw_debounce_tick call writes. */
enum { SW_DEBOUNCE_EVENTS_MAX = 4 };

typedef struct sw_debounce_params {
    int64_t debounce_ns;    /* D: quiet time that ends a burst; > 0 */
    int64_t min_press_ns;   /* G: shortest pulse that is a press, 0 <= G <= D */
    int64_t long_press_ns;  /* L: 0 = no long press, else > D */
    int active_low;         /* 1: a low line (falling edge) is the press */
} sw_debounce_params;

typedef struct sw_debounce {
    sw_debounce_params p;
    int64_t now_ns;         /* latest time seen */
    int stable;             /* settled level: 1 pressed */
    int raw;                /* the line's latest level, 1 active */
    int burst_open;
    int64_t burst_start_ns, last_edge_ns;
    int64_t run_start_ns;   /* start of the current active run in the burst */
    int64_t longest_run_ns; /* longest complete active run in the burst */
    int64_t held_since_ns;  /* start of the press burst, for LONG */
    int64_t settled_ns;     /* when the latest burst ended */
    int long_fired;
    int silent_hold;        /* pressed since init: its release is not reported */
} sw_debounce;

/* Checks params; SW_OK or -1 with nothing changed (the config layer checks
 * the same ranges with file:line messages, so -1 is a programmer error). */
int sw_debounce_init(sw_debounce *d, const sw_debounce_params *p, int64_t t0_ns,
                     int line_high);

/* An edge: line_high is the physical level after it (1: rising). Writes up to
 * SW_DEBOUNCE_EVENTS_MAX events into out and returns how many. */
int sw_debounce_edge(sw_debounce *d, int64_t t_ns, int line_high,
                     sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX]);

/* Time passes with no edge. Same output as sw_debounce_edge. */
int sw_debounce_tick(sw_debounce *d, int64_t now_ns, sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX]);

/* The earliest time a tick could emit something (end of the open burst or
 * the long press), or INT64_MAX when only an edge can: the device layer's
 * poll timeout. */
int64_t sw_debounce_deadline(const sw_debounce *d);

#endif
