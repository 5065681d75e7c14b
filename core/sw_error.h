/* SPDX-License-Identifier: MIT */
/* Errors as values: every fallible seamwalk call returns an sw_status and, when
 * given an sw_error, fills it with one line that names the file, the position and
 * what was expected. Used by every layer. */
#ifndef SW_ERROR_H
#define SW_ERROR_H

#include <stddef.h>
#include <stdio.h>

typedef enum sw_status {
    SW_OK = 0,
    SW_ERR_ARG,         /* the caller passed something invalid */
    SW_ERR_IO,          /* open/read/write/rename failed */
    SW_ERR_FORMAT,      /* input is malformed: truncated, bad magic, bad field */
    SW_ERR_VERSION,     /* a format version this build does not read */
    SW_ERR_CHECKSUM,    /* stored checksum does not match the bytes */
    SW_ERR_RANGE,       /* an index or count out of its valid range */
    SW_ERR_NO_MEMORY,   /* an arena, buffer or malloc is too small */
    SW_ERR_UNSUPPORTED, /* valid input this build cannot handle */
    SW_ERR_GL,          /* EGL or GL reported a failure */
} sw_status;

enum { SW_ERROR_MESSAGE_MAX = 512 };

typedef struct sw_error {
    sw_status status;
    char message[SW_ERROR_MESSAGE_MAX];
} sw_error;

/* Records status and a printf-style message in err (err may be NULL) and
 * returns status, so callers can write `return sw_error_set(err, ...)`.
 * Control bytes in the message (a file's bytes quoted) become \xNN, here
 * and in sw_error_prefix and sw_usage_error, so no caller prints them. */
sw_status sw_error_set(sw_error *err, sw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Prefixes the message already in err with "prefix: " (for example a file name
 * added by an outer layer). Does nothing when err is NULL. */
void sw_error_prefix(sw_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

const char *sw_status_name(sw_status status);

/* Writes s (up to max bytes or its NUL) to out with its control bytes as
 * \xNN, as sw_error_set escapes a message: for text from a file printed
 * outside an sw_error (a pack's part and viewpoint names, a library's
 * words about a file), whose escape sequences must not reach the
 * terminal. */
void sw_fput_escaped(FILE *out, const char *s, size_t max);

/* A command line's usage error as every seamwalk program reports it, on
 * stderr: "PROGRAM: what was wrong" and a line naming PROGRAM --help. The
 * whole usage would bury the one line that says what to fix. Returns the
 * usage exit status, SW_EXIT_USAGE. */
enum { SW_EXIT_USAGE = 2 };
int sw_usage_error(const char *program, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

#endif
