/* SPDX-License-Identifier: MIT */
/* A quick pass over a STEP (ISO 10303-21) file before OpenCASCADE reads it:
 * counts the entity instances and reads every CLOSED_SHELL and OPEN_SHELL's
 * list of faces, so a file that would keep OpenCASCADE busy for minutes is
 * refused at once with the line and what was wrong (a shell listing one
 * face many times kept OpenCASCADE's reader busy for minutes).
 * It checks only these limits; everything else about the file is left to
 * OpenCASCADE. Called by the STEP importer (sw_import_occt.cpp) on the
 * file's bytes; host only, allocates (and frees) a shell's list. */
#ifndef SW_STEP_SCAN_H
#define SW_STEP_SCAN_H

#include <stddef.h>
#include <stdint.h>

#include "sw_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Entity instances in one file; a STEP file of a few hundred MB has a few
 * million. */
#define SW_STEP_MAX_ENTITIES 20000000L
/* Faces listed by one shell. */
#define SW_STEP_MAX_SHELL_FACES 100000L

typedef struct sw_step_scan_result {
    long entities;       /* "#N = ..." instances */
    long shells;         /* CLOSED_SHELL and OPEN_SHELL instances read */
    long faces_max;      /* the most faces one shell lists */
} sw_step_scan_result;

/* Limits other than the defaults; a field of 0 keeps its default. Small
 * ones let a test or a fuzzer reach a limit without millions of lines. */
typedef struct sw_step_scan_limits {
    long entities;       /* default SW_STEP_MAX_ENTITIES */
    long shell_faces;    /* default SW_STEP_MAX_SHELL_FACES */
} sw_step_scan_limits;

/* SW_ERR_RANGE past a limit, SW_ERR_FORMAT for a shell that lists a face
 * twice, with "file:line: #N CLOSED_SHELL ..." in err. SW_OK otherwise,
 * whatever else the file holds. */
sw_status sw_step_scan(const char *text, size_t size, const char *file,
                       sw_step_scan_result *out, sw_error *err);

/* The same within other limits (NULL: the defaults). */
sw_status sw_step_scan_within(const char *text, size_t size, const char *file,
                              const sw_step_scan_limits *limits, sw_step_scan_result *out,
                              sw_error *err);

/* The same on a file read whole (SW_ERR_IO when it cannot be). */
sw_status sw_step_scan_file(const char *path, sw_step_scan_result *out, sw_error *err);

#ifdef __cplusplus
}
#endif

#endif
