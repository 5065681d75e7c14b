/* SPDX-License-Identifier: MIT */
/* A one-line progress bar for seamwalk-pack's long builds: stage, percent
 * and rate ("importing bearing.iges  42%  1800 faces/s") on standard error,
 * redrawn in place with \r at most ten times a second and cleared at the end.
 * Only on a terminal: when the stream is a pipe or a file, or the user asked
 * for --quiet, nothing is ever written, so logs and scripts see clean output.
 * Host only; the importers and the pack writer report through
 * sw_progress_fn callbacks (sw_import.h) that the CLI points here. */
#ifndef SW_PROGRESS_H
#define SW_PROGRESS_H

#include <stddef.h>
#include <stdio.h>

enum { SW_PROGRESS_WIDTH = 79 }; /* longest line drawn, so it fits 80 columns */

typedef struct sw_progress {
    FILE *out;
    int enabled;                /* out is a terminal and not quiet */
    double (*clock_s)(void);    /* monotonic seconds; tests may replace it */
    double min_interval_s;      /* between redraws: 0.1 */
    double last_draw_s;         /* < 0: nothing drawn since the last stage change */
    double stage_start_s;
    char stage[64];
    size_t drawn;               /* characters on the line now, to erase */
} sw_progress;

/* Sets p up to draw on out when out is a terminal (isatty) and quiet is 0. */
void sw_progress_init(sw_progress *p, FILE *out, int quiet);

/* Reports fraction (clamped to [0, 1]) of stage done, and count items of
 * unit ("faces") so far in this stage for the rate; count < 0 or unit NULL:
 * no rate. A new stage name restarts the rate's clock and draws at once;
 * otherwise the line is redrawn only if min_interval_s has passed. */
void sw_progress_update(sw_progress *p, const char *stage, double fraction, double count,
                        const char *unit);

/* Erases the line (if anything is drawn) so the next output starts clean. */
void sw_progress_clear(sw_progress *p);

/* The line itself, for tests and for sw_progress_update: "STAGE  PP%" and,
 * when count > 0 and elapsed_s > 0, "  RATE UNIT/s"; cut to
 * SW_PROGRESS_WIDTH characters (the stage is shortened first). Returns the
 * length written (cap must be > SW_PROGRESS_WIDTH). */
size_t sw_progress_format(char *buf, size_t cap, const char *stage, double fraction,
                          double count, const char *unit, double elapsed_s);

#endif
