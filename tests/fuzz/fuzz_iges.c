/* SPDX-License-Identifier: MIT */
/* libFuzzer entry point for the native IGES reader. Besides not crashing,
 * a failed import must explain itself naming the file, and a successful one
 * must have added what its report says. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sw_import_iges.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_model model;
    sw_model_init(&model);
    sw_error err = {0};
    sw_import_report rep;
    sw_status st = sw_import_iges_memory((const char *)data, size, "fuzz.igs", NULL, &model, &rep,
                                         &err);
    if (st != SW_OK && strncmp(err.message, "fuzz.igs:", 9) != 0)
        abort();
    if (st == SW_OK && rep.faces != model.surface_count)
        abort();
    sw_model_free(&model);
    return 0;
}
