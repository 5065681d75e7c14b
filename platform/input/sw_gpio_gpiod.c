/* SPDX-License-Identifier: MIT */
/* The GPIO button backend on libgpiod v1 (sw_input_backend.h; Debian 12
 * ships 1.6). Only a unit with buttons exercises it; tests use
 * sw_input_fake.h. v1 has no debounce, so lines are requested for both
 * edges with no active-low flag (the debouncer applies active_low to the
 * physical level) and every edge goes to sw_debounce with the kernel's
 * timestamp. The chip is found by gpiod_chip_open_lookup (a name such as
 * gpiochip0, a path, a label or a number); the line by offset or name. */
#include <gpiod.h>
#include <string.h>

#include "sw_input_backend.h"

enum { LINES_MAX = SW_GPIO_LINES_MAX };

static struct { struct gpiod_chip *chip; struct gpiod_line *line; } lines[LINES_MAX];

static int bias_flags(sw_gpio_bias bias)
{
    switch (bias) {
    case SW_GPIO_BIAS_DISABLE: return GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
    case SW_GPIO_BIAS_PULL_UP: return GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    case SW_GPIO_BIAS_PULL_DOWN: return GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    default: return 0;
    }
}

static int fail(struct gpiod_chip *chip, sw_error *err, const sw_gpio_line *g, const char *what)
{
    if (chip)
        gpiod_chip_close(chip);
    if (g->line_name[0])
        sw_error_set(err, SW_ERR_IO, "%s line %s: %s", g->chip, g->line_name, what);
    else
        sw_error_set(err, SW_ERR_IO, "%s line %d: %s", g->chip, g->line_offset, what);
    return -1;
}

static int gpiod_open(void *ctx, const sw_gpio_line *g, int *high, sw_error *err)
{
    (void)ctx;
    int slot = -1;
    for (int i = 0; i < LINES_MAX && slot < 0; i++)
        if (!lines[i].chip)
            slot = i;
    if (slot < 0)
        return fail(NULL, err, g, "too many lines");
    struct gpiod_chip *chip = gpiod_chip_open_lookup(g->chip);
    if (!chip)
        return fail(NULL, err, g, "no such GPIO chip");
    struct gpiod_line *line = g->line_name[0] ? gpiod_chip_find_line(chip, g->line_name)
                                              : gpiod_chip_get_line(chip, (unsigned)g->line_offset);
    if (!line)
        return fail(chip, err, g, "no such line on the chip");
    if (gpiod_line_request_both_edges_events_flags(line, "seamwalk", bias_flags(g->bias)) != 0)
        return fail(chip, err, g, "cannot request it (in use, or bias unsupported)");
    int v = gpiod_line_get_value(line);
    *high = v > 0;
    lines[slot].chip = chip;
    lines[slot].line = line;
    return slot;
}

static int gpiod_read(void *ctx, int handle, sw_gpio_edge *edge)
{
    (void)ctx;
    struct gpiod_line *line = lines[handle].line;
    const struct timespec zero = {0, 0};
    struct gpiod_line_event ev;
    if (gpiod_line_event_wait(line, &zero) != 1 || gpiod_line_event_read(line, &ev) != 0)
        return 0;
    edge->t_ns = (int64_t)ev.ts.tv_sec * 1000000000 + ev.ts.tv_nsec;
    edge->high = ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE;
    return 1;
}

static void gpiod_close(void *ctx, int handle)
{
    (void)ctx;
    gpiod_line_release(lines[handle].line);
    gpiod_chip_close(lines[handle].chip);
    memset(&lines[handle], 0, sizeof lines[handle]);
}

sw_gpio_backend sw_gpio_gpiod_backend(void)
{
    return (sw_gpio_backend){NULL, gpiod_open, gpiod_read, gpiod_close};
}
