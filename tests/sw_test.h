/* SPDX-License-Identifier: MIT */
/* A minimal test harness: each check prints file:line and the failed
 * expression with the values, and the program exits non-zero at the end if
 * any check failed. Tests read as specifications: one behaviour per function. */
#ifndef SW_TEST_H
#define SW_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int sw_test_failures;
static int sw_test_checks;

#define SW_CHECK(cond)                                                                    \
    do {                                                                                  \
        sw_test_checks++;                                                                 \
        if (!(cond)) {                                                                    \
            sw_test_failures++;                                                           \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);      \
        }                                                                                 \
    } while (0)

#define SW_CHECK_MSG(cond, ...)                                                           \
    do {                                                                                  \
        sw_test_checks++;                                                                 \
        if (!(cond)) {                                                                    \
            sw_test_failures++;                                                           \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);      \
            fprintf(stderr, __VA_ARGS__);                                                 \
            fputc('\n', stderr);                                                          \
        }                                                                                 \
    } while (0)

#define SW_CHECK_NEAR(a, b, tol)                                                          \
    do {                                                                                  \
        double sw_a_ = (a), sw_b_ = (b), sw_t_ = (tol);                                   \
        sw_test_checks++;                                                                 \
        if (!(fabs(sw_a_ - sw_b_) <= sw_t_)) {                                            \
            sw_test_failures++;                                                           \
            fprintf(stderr, "%s:%d: %s = %.17g, %s = %.17g, differ by more than %g\n",    \
                    __FILE__, __LINE__, #a, sw_a_, #b, sw_b_, sw_t_);                     \
        }                                                                                 \
    } while (0)

#define SW_RUN(test_fn)                                                                   \
    do {                                                                                  \
        int sw_before_ = sw_test_failures;                                                \
        test_fn();                                                                        \
        printf("%s %s\n", sw_test_failures == sw_before_ ? "ok  " : "FAIL", #test_fn);    \
    } while (0)

/* Ends main: a summary line and the exit status. A program that checked
 * nothing fails, so a test cannot pass by not running. */
static inline int sw_test_finish(void)
{
    printf("%d checks, %d failed\n", sw_test_checks, sw_test_failures);
    if (sw_test_checks == 0)
        return 1;
    return sw_test_failures ? 1 : 0;
}

/* The bytes of the file at path (malloc'd: aligned enough for the pack
 * reader), *size its length; NULL, a failed check, when it cannot be read. */
static inline unsigned char *sw_test_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    SW_CHECK_MSG(f != NULL, "cannot open %s", path);
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *bytes = n >= 0 ? (unsigned char *)malloc((size_t)n + 1) : NULL;
    int read = bytes && fread(bytes, 1, (size_t)n, f) == (size_t)n;
    fclose(f);
    SW_CHECK_MSG(read, "cannot read %s", path);
    if (!read) {
        free(bytes);
        return NULL;
    }
    *size = (size_t)n;
    return bytes;
}

/* Deterministic random numbers for tests (xorshift64*), seedable. */
static unsigned long long sw_test_rng_state = 0x9E3779B97F4A7C15ull;
static inline double sw_test_random(void)
{
    unsigned long long x = sw_test_rng_state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    sw_test_rng_state = x;
    return (double)((x * 2685821657736338717ull) >> 11) * (1.0 / 9007199254740992.0);
}

#endif
