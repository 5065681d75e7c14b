/* SPDX-License-Identifier: MIT */
/* seamwalk-pack's progress line: what one line says, that it is drawn only
 * on a terminal (checked on a pseudo-terminal and on a file), at most every
 * 0.1 s, and erased at the end. */
#define _XOPEN_SOURCE 700 /* posix_openpt, grantpt, unlockpt, ptsname */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sw_test.h"
#include "sw_progress.h"

static double fake_now;
static double fake_clock(void) { return fake_now; }

static void test_format_stage_percent_rate(void)
{
    char line[128];
    size_t n = sw_progress_format(line, sizeof line, "importing bearing.iges", 0.42, 1800, "faces",
                                  1.0);
    SW_CHECK_MSG(strcmp(line, "importing bearing.iges   42%  1800 faces/s") == 0, "%s", line);
    SW_CHECK(n == strlen(line));
    sw_progress_format(line, sizeof line, "writing pack", 1.0, -1, NULL, 2.0);
    SW_CHECK_MSG(strcmp(line, "writing pack  100%") == 0, "%s", line);
    sw_progress_format(line, sizeof line, "adjacency", 0.05, 3, "patches", 4.0);
    SW_CHECK_MSG(strcmp(line, "adjacency    5%  0.8 patches/s") == 0, "%s", line);
}

static void test_format_clamps_fraction_and_skips_empty_rate(void)
{
    char line[128];
    sw_progress_format(line, sizeof line, "s", NAN, 10, "faces", 1.0);
    SW_CHECK_MSG(strcmp(line, "s    0%  10 faces/s") == 0, "%s", line);
    sw_progress_format(line, sizeof line, "s", 7.5, 0, "faces", 1.0); /* nothing counted yet */
    SW_CHECK_MSG(strcmp(line, "s  100%") == 0, "%s", line);
    sw_progress_format(line, sizeof line, "s", -1, 10, "faces", 0.0); /* no time passed */
    SW_CHECK_MSG(strcmp(line, "s    0%") == 0, "%s", line);
}

static void test_format_fits_80_columns_without_splitting_characters(void)
{
    char stage[300] = "importing ";
    for (int i = 0; i < 60; i++)
        strcat(stage, "\xc3\xa9"); /* e-acute, two bytes */
    char line[128];
    size_t n = sw_progress_format(line, sizeof line, stage, 0.5, 100, "faces", 1.0);
    SW_CHECK_MSG(n <= SW_PROGRESS_WIDTH && n == strlen(line), "%zu: %s", n, line);
    const char *tail = "...   50%  100 faces/s";
    SW_CHECK_MSG(n > strlen(tail) && strcmp(line + n - strlen(tail), tail) == 0, "%s", line);
    /* The cut lands between characters: the byte before "..." ends one. */
    const char *dots = strstr(line, "...");
    SW_CHECK(dots && (unsigned char)dots[-1] == 0xa9);
}

static void test_nothing_is_written_to_a_file(void)
{
    FILE *f = tmpfile();
    SW_CHECK(f != NULL);
    if (!f)
        return;
    sw_progress p;
    sw_progress_init(&p, f, 0);
    SW_CHECK(p.enabled == 0);
    sw_progress_update(&p, "importing x.iges", 0.5, 10, "faces");
    sw_progress_clear(&p);
    SW_CHECK(ftell(f) == 0);
    fclose(f);
}

/* Bytes the pseudo-terminal's master has to read now, as a string. */
static size_t drain(int master, char *buf, size_t cap)
{
    size_t got = 0;
    for (;;) {
        ssize_t r = read(master, buf + got, cap - 1 - got);
        if (r <= 0)
            break;
        got += (size_t)r;
    }
    buf[got] = '\0';
    return got;
}

/* A pseudo-terminal pair: *master (non-blocking) and a FILE on the slave. */
static FILE *open_terminal(int *master)
{
    *master = posix_openpt(O_RDWR | O_NOCTTY);
    if (*master < 0 || grantpt(*master) != 0 || unlockpt(*master) != 0)
        return NULL;
    const char *name = ptsname(*master);
    int slave = name ? open(name, O_RDWR | O_NOCTTY) : -1;
    fcntl(*master, F_SETFL, O_NONBLOCK);
    return slave >= 0 ? fdopen(slave, "w") : NULL;
}

static void test_terminal_gets_throttled_redraws_and_a_clean_end(void)
{
    int master = -1;
    FILE *tty = open_terminal(&master);
    if (!tty) {
        printf("     skipped: no pseudo-terminal (%s)\n", strerror(errno));
        if (master >= 0)
            close(master);
        return;
    }
    sw_progress p;
    sw_progress_init(&p, tty, 0);
    SW_CHECK(p.enabled == 1);
    p.clock_s = fake_clock;
    char buf[1024];
    fake_now = 100.0;
    sw_progress_update(&p, "importing hammer.iges", 0.0, 0, "faces");
    drain(master, buf, sizeof buf);
    SW_CHECK_MSG(strcmp(buf, "\rimporting hammer.iges    0%") == 0, "%s", buf);
    fake_now = 100.05; /* too soon: not redrawn */
    sw_progress_update(&p, "importing hammer.iges", 0.3, 30, "faces");
    SW_CHECK(drain(master, buf, sizeof buf) == 0);
    fake_now = 102.0;
    sw_progress_update(&p, "importing hammer.iges", 0.6, 60, "faces");
    drain(master, buf, sizeof buf);
    SW_CHECK_MSG(strcmp(buf, "\rimporting hammer.iges   60%  30 faces/s") == 0, "%s", buf);
    fake_now = 102.01; /* a new stage draws at once, padding over the longer line */
    sw_progress_update(&p, "writing pack", 0.0, -1, NULL);
    drain(master, buf, sizeof buf);
    SW_CHECK_MSG(strncmp(buf, "\rwriting pack    0%       ", 26) == 0 &&
                 strlen(buf) == 1 + strlen("importing hammer.iges   60%  30 faces/s"), "%s", buf);
    sw_progress_clear(&p);
    drain(master, buf, sizeof buf);
    SW_CHECK(buf[0] == '\r' && buf[strlen(buf) - 1] == '\r' &&
             strspn(buf + 1, " ") == strlen("writing pack    0%"));
    sw_progress_clear(&p); /* nothing drawn: nothing written */
    SW_CHECK(drain(master, buf, sizeof buf) == 0);
    fclose(tty);
    close(master);
}

static void test_quiet_silences_a_terminal(void)
{
    int master = -1;
    FILE *tty = open_terminal(&master);
    if (!tty) {
        printf("     skipped: no pseudo-terminal\n");
        if (master >= 0)
            close(master);
        return;
    }
    sw_progress p;
    sw_progress_init(&p, tty, 1);
    SW_CHECK(p.enabled == 0);
    sw_progress_update(&p, "importing x", 0.5, 1, "faces");
    char buf[256];
    SW_CHECK(drain(master, buf, sizeof buf) == 0);
    fclose(tty);
    close(master);
}

int main(void)
{
    SW_RUN(test_format_stage_percent_rate);
    SW_RUN(test_format_clamps_fraction_and_skips_empty_rate);
    SW_RUN(test_format_fits_80_columns_without_splitting_characters);
    SW_RUN(test_nothing_is_written_to_a_file);
    SW_RUN(test_terminal_gets_throttled_redraws_and_a_clean_end);
    SW_RUN(test_quiet_silences_a_terminal);
    return sw_test_finish();
}
