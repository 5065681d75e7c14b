/* SPDX-License-Identifier: MIT */
/* The debounce state machine (sw_debounce.h has the rule). Every input first
 * lets time pass up to its timestamp (step), so an edge that arrives after a
 * quiet gap ends the previous burst before it starts a new one. */
#include "sw_debounce.h"

static int emit(sw_debounce_event *out, int n, sw_debounce_kind kind, int64_t t_ns)
{
    out[n].kind = kind;
    out[n].t_ns = t_ns;
    return n + 1;
}

int sw_debounce_init(sw_debounce *d, const sw_debounce_params *p, int64_t t0_ns, int line_high)
{
    if (p->debounce_ns <= 0 || p->min_press_ns < 0 || p->min_press_ns > p->debounce_ns ||
        p->long_press_ns < 0 || (p->long_press_ns > 0 && p->long_press_ns <= p->debounce_ns))
        return -1;
    int active = p->active_low ? !line_high : !!line_high;
    *d = (sw_debounce){
        .p = *p,
        .now_ns = t0_ns,
        .stable = active,
        .raw = active,
        .held_since_ns = t0_ns,
        .settled_ns = t0_ns,
        .long_fired = active,
        .silent_hold = active,
    };
    return 0;
}

/* The open burst has been quiet for D: decide what it was. */
static int close_burst(sw_debounce *d, sw_debounce_event *out, int n)
{
    int64_t end = d->last_edge_ns + d->p.debounce_ns;
    d->burst_open = 0;
    d->settled_ns = end;
    if (d->raw && !d->stable) {
        d->stable = 1;
        d->held_since_ns = d->burst_start_ns;
        d->long_fired = 0;
        return emit(out, n, SW_DEBOUNCE_PRESS, end);
    }
    if (!d->raw && d->stable) {
        d->stable = 0;
        if (d->silent_hold) {
            d->silent_hold = 0;
            return n;
        }
        n = emit(out, n, SW_DEBOUNCE_RELEASE, end);
        return d->long_fired ? n : emit(out, n, SW_DEBOUNCE_SHORT, end);
    }
    /* Back where it started: from released, a tap shorter than D or a glitch;
     * from pressed, a bounce during the hold. */
    if (!d->stable && d->longest_run_ns >= d->p.min_press_ns) {
        n = emit(out, n, SW_DEBOUNCE_PRESS, end);
        n = emit(out, n, SW_DEBOUNCE_RELEASE, end);
        n = emit(out, n, SW_DEBOUNCE_SHORT, end);
    }
    return n;
}

static int64_t long_press_due(const sw_debounce *d)
{
    if (!d->stable || d->burst_open || d->long_fired || d->p.long_press_ns == 0)
        return INT64_MAX;
    int64_t due = d->held_since_ns + d->p.long_press_ns;
    return due > d->settled_ns ? due : d->settled_ns;
}

/* Lets time pass to t (already clamped to be >= now_ns). */
static int step(sw_debounce *d, int64_t t_ns, sw_debounce_event *out)
{
    int n = 0;
    d->now_ns = t_ns;
    if (d->burst_open && t_ns - d->last_edge_ns >= d->p.debounce_ns)
        n = close_burst(d, out, n);
    int64_t due = long_press_due(d);
    if (due <= t_ns) {
        d->long_fired = 1;
        n = emit(out, n, SW_DEBOUNCE_LONG, due);
    }
    return n;
}

int sw_debounce_edge(sw_debounce *d, int64_t t_ns, int line_high,
                     sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX])
{
    if (t_ns < d->now_ns)
        t_ns = d->now_ns;
    int n = step(d, t_ns, out);
    int level = d->p.active_low ? !line_high : !!line_high;
    if (!d->burst_open) {
        d->burst_open = 1;
        d->burst_start_ns = t_ns;
        d->run_start_ns = t_ns;
        d->longest_run_ns = -1;  /* no complete active run yet */
    }
    if (level != d->raw) {
        if (level) {
            d->run_start_ns = t_ns;
        } else if (t_ns - d->run_start_ns > d->longest_run_ns) {
            d->longest_run_ns = t_ns - d->run_start_ns;
        }
        d->raw = level;
    }
    d->last_edge_ns = t_ns;
    return n;
}

int sw_debounce_tick(sw_debounce *d, int64_t now_ns, sw_debounce_event out[SW_DEBOUNCE_EVENTS_MAX])
{
    if (now_ns < d->now_ns)
        now_ns = d->now_ns;
    return step(d, now_ns, out);
}

int64_t sw_debounce_deadline(const sw_debounce *d)
{
    if (d->burst_open)
        return d->last_edge_ns + d->p.debounce_ns;
    return long_press_due(d);
}
