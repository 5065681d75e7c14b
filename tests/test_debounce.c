/* SPDX-License-Identifier: MIT */
/* The GPIO button debouncer (firmware/kiosk/sw_debounce.h): scripted edges with
 * exact timestamps in, the exact events out. Times are in microseconds in
 * the scripts for reading; the machine sees nanoseconds. */
#include <stdint.h>
#include <string.h>

#include "sw_debounce.h"
#include "sw_test.h"

#define US 1000LL
#define MS 1000000LL

enum { LOG_MAX = 64 };

typedef struct script {
    sw_debounce d;
    sw_debounce_event ev[LOG_MAX];
    int n;
} script;

static void collect(script *l, const sw_debounce_event *out, int count)
{
    SW_CHECK(count >= 0 && count <= SW_DEBOUNCE_EVENTS_MAX);
    for (int i = 0; i < count && l->n < LOG_MAX; i++)
        l->ev[l->n++] = out[i];
}

static void edge(script *l, int64_t t_ns, int high)
{
    sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX];
    collect(l, out, sw_debounce_edge(&l->d, t_ns, high, out));
}

static void tick(script *l, int64_t t_ns)
{
    sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX];
    collect(l, out, sw_debounce_tick(&l->d, t_ns, out));
}

/* D = 10 ms, G = 2 ms, L = 800 ms, active high, released at t = 0. */
static void start(script *l, int64_t long_press_ns)
{
    memset(l, 0, sizeof *l);
    sw_debounce_params p = {.debounce_ns = 10 * MS, .min_press_ns = 2 * MS,
                            .long_press_ns = long_press_ns};
    SW_CHECK(sw_debounce_init(&l->d, &p, 0, 0) == 0);
}

static void expect(const script *l, int count, const sw_debounce_kind *kinds, const int64_t *times)
{
    SW_CHECK_MSG(l->n == count, "%d events, expected %d", l->n, count);
    for (int i = 0; i < count && i < l->n; i++) {
        SW_CHECK_MSG(l->ev[i].kind == kinds[i], "event %d is kind %d, expected %d", i,
                     (int)l->ev[i].kind, (int)kinds[i]);
        SW_CHECK_MSG(l->ev[i].t_ns == times[i], "event %d at %lld ns, expected %lld", i,
                     (long long)l->ev[i].t_ns, (long long)times[i]);
    }
}

/* 5 bounces within 3 ms on the press, then held; 4 on the release. */
static void bouncing_press_gives_one_press_and_one_release(void)
{
    script l;
    start(&l, 0);
    int64_t t = 100 * MS;
    for (int i = 0; i < 5; i++) {
        edge(&l, t + i * 600 * US, 1);
        edge(&l, t + i * 600 * US + 300 * US, 0);
    }
    edge(&l, t + 3 * MS, 1);                 /* last edge: held from here */
    tick(&l, t + 3 * MS + 10 * MS - 1);      /* one ns before D has passed */
    SW_CHECK(l.n == 0);
    SW_CHECK(sw_debounce_deadline(&l.d) == t + 13 * MS);
    tick(&l, t + 13 * MS);
    tick(&l, t + 200 * MS);
    int64_t r = t + 300 * MS;
    for (int i = 0; i < 4; i++) {
        edge(&l, r + i * 500 * US, 0);
        edge(&l, r + i * 500 * US + 200 * US, 1);
    }
    edge(&l, r + 2 * MS, 0);
    tick(&l, r + 100 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {t + 13 * MS, r + 12 * MS, r + 12 * MS};
    expect(&l, 3, k, times);
}

/* A 1 ms spike is shorter than G = 2 ms: nothing, ever. */
static void glitch_shorter_than_min_press_is_ignored(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 50 * MS, 1);
    edge(&l, 51 * MS, 0);
    tick(&l, 2000 * MS);
    SW_CHECK(l.n == 0);
    SW_CHECK(l.d.stable == 0);
    SW_CHECK(sw_debounce_deadline(&l.d) == INT64_MAX);
}

/* A clean 3 ms tap (shorter than D = 10 ms) after a stable idle is one press:
 * PRESS, RELEASE and SHORT together when the burst ends, D after the release. */
static void clean_tap_shorter_than_debounce_is_one_press(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 50 * MS, 1);
    edge(&l, 53 * MS, 0);
    tick(&l, 62 * MS);
    SW_CHECK(l.n == 0);
    tick(&l, 63 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {63 * MS, 63 * MS, 63 * MS};
    expect(&l, 3, k, times);
    SW_CHECK(l.d.stable == 0);
}

/* The same tap with bounces on both edges: one of its active runs lasts
 * 2.5 ms >= G, so it is still one press; the 0.2 ms runs are not. */
static void bouncy_tap_with_a_long_enough_run_is_one_press(void)
{
    script l;
    start(&l, 0);
    edge(&l, 50 * MS, 1);
    edge(&l, 50 * MS + 200 * US, 0);
    edge(&l, 50 * MS + 400 * US, 1);
    edge(&l, 52 * MS + 900 * US, 0);
    edge(&l, 53 * MS, 1);
    edge(&l, 53 * MS + 200 * US, 0);
    tick(&l, 100 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t e = 63 * MS + 200 * US;
    const int64_t times[] = {e, e, e};
    expect(&l, 3, k, times);
}

/* Many sub-G spikes in one burst are still noise. */
static void train_of_short_spikes_is_ignored(void)
{
    script l;
    start(&l, 0);
    for (int i = 0; i < 20; i++) {
        edge(&l, 10 * MS + i * 3 * MS, 1);
        edge(&l, 10 * MS + i * 3 * MS + 1500 * US, 0);
    }
    tick(&l, 500 * MS);
    SW_CHECK(l.n == 0);
}

/* Held: LONG exactly once at press burst start + L, and the release after it
 * gives RELEASE but no SHORT. */
static void long_press_fires_once_and_release_gives_no_short(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 100 * MS, 1);
    edge(&l, 100 * MS + 500 * US, 0);
    edge(&l, 101 * MS, 1);
    tick(&l, 200 * MS);
    SW_CHECK(sw_debounce_deadline(&l.d) == 900 * MS);
    tick(&l, 900 * MS - 1);
    SW_CHECK(l.n == 1);
    tick(&l, 900 * MS);
    tick(&l, 950 * MS);
    tick(&l, 5000 * MS);
    SW_CHECK(sw_debounce_deadline(&l.d) == INT64_MAX);
    edge(&l, 6000 * MS, 0);
    tick(&l, 6100 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_LONG,
                                         SW_DEBOUNCE_RELEASE};
    const int64_t times[] = {111 * MS, 900 * MS, 6010 * MS};
    expect(&l, 3, k, times);
}

/* A tick that comes late still dates LONG at its threshold. */
static void late_tick_dates_long_press_at_threshold(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 100 * MS, 1);
    tick(&l, 3000 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_LONG};
    const int64_t times[] = {110 * MS, 900 * MS};
    expect(&l, 2, k, times);
}

/* Released before L: RELEASE then SHORT, no LONG. */
static void release_before_long_press_gives_short(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 100 * MS, 1);
    edge(&l, 500 * MS, 0);
    tick(&l, 2000 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {110 * MS, 510 * MS, 510 * MS};
    expect(&l, 3, k, times);
}

/* A release bounce across the threshold that comes back pressed is a bounce:
 * LONG waits for the burst's end instead of firing during it. */
static void bounce_during_hold_delays_long_press(void)
{
    script l;
    start(&l, 800 * MS);
    edge(&l, 100 * MS, 1);
    edge(&l, 898 * MS, 0);
    edge(&l, 899 * MS, 1);
    tick(&l, 905 * MS);
    SW_CHECK(l.n == 1);
    tick(&l, 909 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_LONG};
    const int64_t times[] = {110 * MS, 909 * MS};
    expect(&l, 2, k, times);
}

/* Active low: the falling edge is the press. */
static void active_low_presses_on_falling_edge(void)
{
    script l;
    memset(&l, 0, sizeof l);
    sw_debounce_params p = {.debounce_ns = 5 * MS, .min_press_ns = 1 * MS, .active_low = 1};
    SW_CHECK(sw_debounce_init(&l.d, &p, 0, 1) == 0);
    edge(&l, 10 * MS, 0);
    tick(&l, 20 * MS);
    edge(&l, 30 * MS, 1);
    tick(&l, 40 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {15 * MS, 35 * MS, 35 * MS};
    expect(&l, 3, k, times);
}

/* A button held at init neither presses nor reports its release. */
static void button_held_at_init_is_silent_until_pressed_again(void)
{
    script l;
    memset(&l, 0, sizeof l);
    sw_debounce_params p = {.debounce_ns = 10 * MS, .min_press_ns = 2 * MS,
                            .long_press_ns = 800 * MS};
    SW_CHECK(sw_debounce_init(&l.d, &p, 0, 1) == 0);
    tick(&l, 2000 * MS);
    edge(&l, 2100 * MS, 0);
    tick(&l, 2200 * MS);
    SW_CHECK(l.n == 0);
    edge(&l, 3000 * MS, 1);
    edge(&l, 3100 * MS, 0);
    tick(&l, 3200 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {3010 * MS, 3110 * MS, 3110 * MS};
    expect(&l, 3, k, times);
}

/* Timestamps going backwards are taken at the latest time seen: an edge
 * "before" the last one extends the burst from there, and events never go
 * back in time. */
static void backward_timestamps_are_clamped_to_latest(void)
{
    script l;
    start(&l, 0);
    edge(&l, 100 * MS, 1);
    edge(&l, 90 * MS, 0);    /* earlier than the press edge: taken at 100 ms */
    tick(&l, 105 * MS);
    tick(&l, 50 * MS);       /* a stale tick changes nothing */
    SW_CHECK(l.d.now_ns == 105 * MS);
    tick(&l, 110 * MS);
    SW_CHECK(l.n == 0);      /* a zero-length pulse is under G: nothing */
    edge(&l, 200 * MS, 1);
    tick(&l, 300 * MS);
    edge(&l, 250 * MS, 0);   /* release dated before the tick: at 300 ms */
    tick(&l, 400 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS, SW_DEBOUNCE_RELEASE,
                                         SW_DEBOUNCE_SHORT};
    const int64_t times[] = {210 * MS, 310 * MS, 310 * MS};
    expect(&l, 3, k, times);
    for (int i = 1; i < l.n; i++)
        SW_CHECK(l.ev[i].t_ns >= l.ev[i - 1].t_ns);
}

/* A lost event (two rising edges) restarts the quiet time, no double press. */
static void repeated_level_restarts_quiet_time(void)
{
    script l;
    start(&l, 0);
    edge(&l, 100 * MS, 1);
    edge(&l, 108 * MS, 1);
    tick(&l, 117 * MS);
    SW_CHECK(l.n == 0);
    tick(&l, 118 * MS);
    static const sw_debounce_kind k[] = {SW_DEBOUNCE_PRESS};
    const int64_t times[] = {118 * MS};
    expect(&l, 1, k, times);
}

/* An edge after a quiet gap ends the previous burst before starting its own:
 * both events come from the edge call itself, with no tick in between. */
static void edge_after_quiet_gap_confirms_previous_burst(void)
{
    script l;
    start(&l, 0);
    edge(&l, 100 * MS, 1);
    edge(&l, 300 * MS, 0);
    SW_CHECK(l.n == 1 && l.ev[0].kind == SW_DEBOUNCE_PRESS && l.ev[0].t_ns == 110 * MS);
}

static void bad_params_are_refused(void)
{
    sw_debounce d;
    sw_debounce_params zero = {0};
    SW_CHECK(sw_debounce_init(&d, &zero, 0, 0) == -1);
    sw_debounce_params g = {.debounce_ns = 5 * MS, .min_press_ns = 6 * MS};
    SW_CHECK(sw_debounce_init(&d, &g, 0, 0) == -1);
    sw_debounce_params lp = {.debounce_ns = 5 * MS, .long_press_ns = 5 * MS};
    SW_CHECK(sw_debounce_init(&d, &lp, 0, 0) == -1);
    sw_debounce_params ok = {.debounce_ns = 5 * MS, .min_press_ns = 5 * MS,
                             .long_press_ns = 5 * MS + 1};
    SW_CHECK(sw_debounce_init(&d, &ok, 0, 0) == 0);
}

int main(void)
{
    SW_RUN(bouncing_press_gives_one_press_and_one_release);
    SW_RUN(glitch_shorter_than_min_press_is_ignored);
    SW_RUN(clean_tap_shorter_than_debounce_is_one_press);
    SW_RUN(bouncy_tap_with_a_long_enough_run_is_one_press);
    SW_RUN(train_of_short_spikes_is_ignored);
    SW_RUN(long_press_fires_once_and_release_gives_no_short);
    SW_RUN(late_tick_dates_long_press_at_threshold);
    SW_RUN(release_before_long_press_gives_short);
    SW_RUN(bounce_during_hold_delays_long_press);
    SW_RUN(active_low_presses_on_falling_edge);
    SW_RUN(button_held_at_init_is_silent_until_pressed_again);
    SW_RUN(backward_timestamps_are_clamped_to_latest);
    SW_RUN(repeated_level_restarts_quiet_time);
    SW_RUN(edge_after_quiet_gap_confirms_previous_burst);
    SW_RUN(bad_params_are_refused);
    return sw_test_finish();
}
