/* SPDX-License-Identifier: MIT */
/* Fuzz target: the STEP file's quick pass before OpenCASCADE
 * (assets/import/sw_step_scan.c): an accepted input keeps the limits, the
 * defaults and small ones that an input of a few kB reaches. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "sw_step_scan.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_step_scan_result r;
    sw_error err = {0};
    if (sw_step_scan((const char *)data, size, "fuzz", &r, &err) == SW_OK &&
        (r.faces_max > SW_STEP_MAX_SHELL_FACES || r.entities > SW_STEP_MAX_ENTITIES))
        abort();
    /* Again within small limits, which an input of a few kB can reach. */
    static const sw_step_scan_limits small = {.entities = 64, .shell_faces = 16};
    if (sw_step_scan_within((const char *)data, size, "fuzz", &small, &r, &err) == SW_OK &&
        (r.faces_max > small.shell_faces || r.entities > small.entities))
        abort();
    return 0;
}
