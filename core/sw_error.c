/* SPDX-License-Identifier: MIT */
#include "sw_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* msg (of cap bytes) with its control bytes as \xNN, cut to fit: a
 * message may quote a file's bytes (a token, a name, a library's message),
 * and a binary file's escape sequences must not reach the terminal or the
 * journal that prints it. Escaping twice changes nothing. */
static void escape_controls(char *msg, size_t cap)
{
    char out[SW_ERROR_MESSAGE_MAX];
    size_t room = cap < sizeof out ? cap : sizeof out, n = 0;
    for (const char *s = msg; *s; s++) {
        unsigned char c = (unsigned char)*s;
        int control = c < 0x20 || c == 0x7f;
        if (n + (control ? 4 : 1) >= room)   /* the terminator's byte kept */
            break;
        if (control)
            n += (size_t)snprintf(out + n, sizeof out - n, "\\x%02x", c);
        else
            out[n++] = (char)c;
    }
    out[n] = '\0';
    memcpy(msg, out, n + 1);
}

void sw_fput_escaped(FILE *out, const char *s, size_t max)
{
    for (size_t i = 0; i < max && s[i]; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x20 || c == 0x7f)
            fprintf(out, "\\x%02x", c);
        else
            fputc(c, out);
    }
}

sw_status sw_error_set(sw_error *err, sw_status status, const char *fmt, ...)
{
    if (!err)
        return status;
    err->status = status;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    escape_controls(err->message, sizeof err->message);
    return status;
}

void sw_error_prefix(sw_error *err, const char *fmt, ...)
{
    if (!err)
        return;
    char prefix[SW_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, ap);
    va_end(ap);
    /* Truncation is fine: the message stays one readable line either way. */
    char joined[2 * SW_ERROR_MESSAGE_MAX + 2];
    snprintf(joined, sizeof joined, "%s: %s", prefix, err->message);
    memcpy(err->message, joined, sizeof err->message - 1);
    err->message[sizeof err->message - 1] = '\0';
    escape_controls(err->message, sizeof err->message);
}

int sw_usage_error(const char *program, const char *fmt, ...)
{
    char line[SW_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    escape_controls(line, sizeof line);
    fprintf(stderr, "%s: %s\ntry '%s --help'\n", program, line, program);
    return SW_EXIT_USAGE;
}

const char *sw_status_name(sw_status status)
{
    switch (status) {
    case SW_OK: return "ok";
    case SW_ERR_ARG: return "invalid argument";
    case SW_ERR_IO: return "i/o error";
    case SW_ERR_FORMAT: return "format error";
    case SW_ERR_VERSION: return "unsupported version";
    case SW_ERR_CHECKSUM: return "checksum mismatch";
    case SW_ERR_RANGE: return "out of range";
    case SW_ERR_NO_MEMORY: return "out of memory";
    case SW_ERR_UNSUPPORTED: return "unsupported";
    case SW_ERR_GL: return "graphics error";
    }
    return "unknown status";
}
