/* SPDX-License-Identifier: MIT */
/* Fuzz target: the STEP file's quick pass before OpenCASCADE
 * (assets/import/sw_step_scan.c). */
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
    return 0;
}
