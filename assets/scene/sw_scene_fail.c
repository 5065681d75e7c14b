/* SPDX-License-Identifier: MIT */
/* The scene loader's one error: the first failure, with file:line, wherever
 * in the parse it happens (sw_scene_internal.h). Below the loader and the
 * key handlers, which both report through it. */
#include <stdarg.h>
#include <stdio.h>

#include "sw_scene_internal.h"

/* Records the first error only (later ones are usually its consequences) and
 * returns 0, inih's "handler failed". */
static int scene_vfail(scene_state *st, long line, sw_status status, const char *fmt,
                       va_list ap)
{
    if (st->error_line)
        return 0;
    char what[SW_ERROR_MESSAGE_MAX];
    vsnprintf(what, sizeof what, fmt, ap);
    if (line < 1)
        line = 1; /* an empty file fails "at line 1"; 0 means "no error" */
    st->error_line = line;
    st->status = status;
    sw_error_set(st->err, status, "%s:%ld: %s", st->file_name, line, what);
    return 0;
}

int scene_fail(scene_state *st, sw_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    scene_vfail(st, st->line, status, fmt, ap);
    va_end(ap);
    return 0;
}

/* At the header of the section that is starting (or the current line). */
int section_fail(scene_state *st, sw_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    scene_vfail(st, st->pending_section ? st->pending_section : st->line, status, fmt, ap);
    va_end(ap);
    return 0;
}

int scene_fail_at(scene_state *st, long line, sw_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    scene_vfail(st, line, status, fmt, ap);
    va_end(ap);
    return 0;
}
